//! Bits of registers (`400010.03`): read as 1/0, written with function 22, and on a slave
//! without 22 with a read (03) and a write (06), said on stderr.

use std::sync::{Arc, Mutex};

use crate::support::{mbtool, scripted_tcp_device, serve_tcp, values_of, Act};

#[test]
fn a_bit_is_set_alone_with_function_22() {
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("data.txt");
    std::fs::write(&data, "400010 = 0x00F0\n").unwrap();
    let (_slave, port, _) = serve_tcp(&["--data", &data.display().to_string()]);
    let output = mbtool()
        .args(&port)
        .args(["write", "17", "400010.03", "1", "-v"])
        .output()
        .unwrap();
    assert!(output.status.success(), "{output:?}");
    // The frame on the wire: function 22, AND mask FFF7, OR mask 0008.
    let trace = String::from_utf8_lossy(&output.stderr);
    assert!(
        trace.contains("> 00 01 00 00 00 08 11 16 00 09 FF F7 00 08"),
        "{trace}"
    );
    assert_eq!(
        String::from_utf8_lossy(&output.stdout),
        "wrote 1 value from 400010.03 (slave 17, function 22 Mask Write Register)\n"
    );
    assert_eq!(
        values_of(&port, "read-holding 17 400010 --type hex"),
        ["0x00F8"]
    );
    // Read back as bits: 400010.03 and the three above it.
    assert_eq!(
        values_of(&port, "read 17 400010.03 4"),
        ["1", "1", "1", "1"]
    );
    assert_eq!(values_of(&port, "read-holding 17 400010.02 2"), ["0", "1"]);
}

#[test]
fn without_function_22_the_register_is_read_and_written_whole() {
    let register = Arc::new(Mutex::new(0x00F0u16));
    let seen = Arc::new(Mutex::new(Vec::new()));
    let (device_register, device_seen) = (register.clone(), seen.clone());
    let tcp = scripted_tcp_device(move |_, pdu| {
        let (Ok(mut value), Ok(mut seen)) = (device_register.lock(), device_seen.lock()) else {
            return Act::Close;
        };
        seen.push(pdu[0]);
        Act::Answer(match pdu {
            [0x03, 0x00, 0x09, 0x00, 0x01] => [&[0x03, 0x02][..], &value.to_be_bytes()].concat(),
            [0x06, 0x00, 0x09, high, low] => {
                *value = u16::from_be_bytes([*high, *low]);
                pdu.to_vec()
            }
            [function, ..] => vec![function | 0x80, 0x01],
            [] => vec![0x80, 0x01],
        })
    });
    let output = mbtool()
        .args(["--port", &format!("127.0.0.1:{tcp}")])
        .args(["write", "17", "400010.03", "on"])
        .output()
        .unwrap();
    assert!(output.status.success(), "{output:?}");
    assert_eq!(*register.lock().unwrap(), 0x00F8);
    assert_eq!(*seen.lock().unwrap(), [0x16, 0x03, 0x06]);
    assert_eq!(
        String::from_utf8_lossy(&output.stderr),
        "mbtool: slave 17 does not do function 22 (mask write register): 400010.03 was set \
         by reading the register (03) and writing it whole (06)\n"
    );
}

#[test]
fn bit_references_that_name_no_bit_of_a_register_are_refused() {
    for (args, says) in [
        (
            "read-coils 17 000020.01",
            "coils and discrete inputs are bits already",
        ),
        (
            "write 17 400001.16 1",
            "'400001.16' names no bit of a register",
        ),
        (
            "write 17 400001.01 1 0",
            "a bit of a register takes one value",
        ),
        (
            "read 17 400001.00-400001.07",
            "give the first bit and a count",
        ),
        ("write 17 300009.01 1", "that table is read-only"),
    ] {
        let output = mbtool()
            .args(["--port", "127.0.0.1:9"])
            .args(args.split_whitespace())
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{args}: {stderr}");
        assert!(stderr.contains(says), "{args}: {stderr}");
    }
}
