//! Peers we did not write that implement functions 20-24 and Modbus/UDP: pymodbus as client
//! and server, and libmodbus for 22 and 23.

use std::process::{Command as Process, Stdio};
use std::time::{Duration, Instant};

use super::{serve_udp, udp_port};
use crate::support::{
    command_exists, peer_available, python_has, run_against, serve_tcp, values_of, Stopped,
};

const MASTER: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/peers/pymodbus_master.py"
);
const SLAVE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/peers/pymodbus_slave.py");
const LIBMODBUS_PEER: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/peers/libmodbus_peer.c");

fn pymodbus() -> bool {
    peer_available("pymodbus (Python)", python_has("pymodbus"))
}

/// pymodbus's client through functions 20-24 (`--records`) against `transport` PORT.
fn pymodbus_client(transport: &str, port: &str) -> serde_json::Value {
    let output = Process::new("python3")
        .args([MASTER, transport, port, "--records"])
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    serde_json::from_slice(&output.stdout).unwrap()
}

/// pymodbus's client reads and writes files, the FIFO queue, masks and read/write of
/// `serve` as the specification's examples say, over TCP and over UDP.
#[test]
fn pymodbus_s_client_gets_the_specification_s_answers_from_serve() {
    if !pymodbus() {
        return;
    }
    let expected = serde_json::json!({
        "file_records": ["0dfe0020", "33cd0040"],
        "file_write": {"status": 1},
        "file_written": ["06af04be100d"],
        "file_zero": {"exception": 2},
        "fifo": {"status": 1, "values": [440, 4740]},
        "fifo_missing": {"exception": 2},
        "mask_write": {"status": 1},
        "after_mask": [0x17],
        "read_write": {"status": 1, "registers": [0, 0x17, 0, 0, 0, 0]},
    });
    let (_tcp, _, tcp) = serve_tcp(&[]);
    assert_eq!(pymodbus_client("--tcp", &tcp.to_string()), expected);
    let (_udp, port) = serve_udp("udp://", &[]);
    let udp = port[1].rsplit(':').next().unwrap().to_string();
    assert_eq!(pymodbus_client("--udp", &udp), expected);
}

/// mbtool against pymodbus's UDP server: reads and writes, 22 and 23 on its data, 24 and
/// 20 as pymodbus answers them (a fixed queue 0 1 2 3; ten registers of the text "SERVER
/// DUMMY RECORD." whatever is asked, which mbtool refuses when fewer were asked).
#[test]
fn mbtool_against_pymodbus_over_udp() {
    if !pymodbus() {
        return;
    }
    let udp = udp_port();
    let _slave = Stopped(
        Process::new("python3")
            .args([SLAVE, "--framer", "socket", "--udp", &udp.to_string()])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap(),
    );
    let port = vec!["--port".to_string(), format!("udp://127.0.0.1:{udp}")];
    let deadline = Instant::now() + Duration::from_secs(15);
    while run_against(&port, "read-holding 17 400001 --timeout 300ms").0 != 0 {
        assert!(
            Instant::now() < deadline,
            "pymodbus never answered over UDP"
        );
    }
    crate::support::writes_read_back(&port);
    assert_eq!(run_against(&port, "write 17 400005 0x12").0, 0);
    assert_eq!(run_against(&port, "mask-write 17 400005 0xF2 0x25").0, 0);
    assert_eq!(values_of(&port, "read-holding 17 400005"), ["23"]);
    assert_eq!(
        values_of(&port, "read-write 17 400004 3 400015 7 8 9"),
        ["0", "23", "0"]
    );
    assert_eq!(
        values_of(&port, "read-holding 17 400015 3"),
        ["7", "8", "9"]
    );
    assert_eq!(
        values_of(&port, "read-fifo 17 400001"),
        ["0", "1", "2", "3"]
    );
    assert_eq!(
        values_of(&port, "read-file 17 1:0 10 --type ascii"),
        ["SERVER DUMMY RECORD."]
    );
    let (code, out) = run_against(&port, "read-file 17 1:0 2");
    assert_eq!(code, 4, "{out}");
    assert!(
        out.contains("answer carries records: 10, the request asked for 2"),
        "{out}"
    );
}

/// libmodbus's mask write and write-and-read against `serve`, and mbtool's against a
/// libmodbus server: the specification's example both ways (register 4 holding 0012, AND
/// 00F2, OR 0025, gives 0017).
#[test]
fn libmodbus_mask_write_and_read_write_both_ways() {
    if !peer_available(
        "cc and libmodbus",
        command_exists("cc") && command_exists("pkg-config"),
    ) {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let peer = dir.path().join("libmodbus_peer");
    let flags = Process::new("pkg-config")
        .args(["--cflags", "--libs", "libmodbus"])
        .output()
        .unwrap();
    if !peer_available("libmodbus-dev", flags.status.success()) {
        return;
    }
    let flags = String::from_utf8(flags.stdout).unwrap();
    let built = Process::new("cc")
        .arg("-o")
        .arg(&peer)
        .arg(LIBMODBUS_PEER)
        .args(flags.split_whitespace())
        .status()
        .unwrap();
    assert!(built.success());
    // libmodbus's client against serve.
    let data = super::data_file("400001-400004 = 0 1 2 3\n400005 = 0x12\n400006-400020 = 5\n");
    let path = data.path().display().to_string();
    let (_server, _, port) = serve_tcp(&["--data", &path]);
    let output = Process::new(&peer)
        .args(["client", &port.to_string()])
        .output()
        .unwrap();
    assert!(output.status.success(), "{output:?}");
    assert_eq!(
        String::from_utf8_lossy(&output.stdout),
        "mask 0017\nread 3 23 5 5 5 5\n"
    );
    // mbtool against libmodbus's server.
    let port = crate::support::free_port();
    let _server = Stopped(
        Process::new(&peer)
            .args(["server", &port.to_string()])
            .stdout(Stdio::null())
            .spawn()
            .unwrap(),
    );
    assert!(crate::support::wait_for_listener(
        port,
        Duration::from_secs(5)
    ));
    // libmodbus serves one client at a time and this check was one: it is let go first.
    std::thread::sleep(Duration::from_millis(200));
    let master = vec!["--port".to_string(), format!("127.0.0.1:{port}")];
    assert_eq!(run_against(&master, "mask-write 17 400005 0xF2 0x25").0, 0);
    assert_eq!(values_of(&master, "read-holding 17 400005"), ["23"]);
    assert_eq!(
        values_of(&master, "read-write 17 400004 6 400015 255 255 255"),
        ["3", "23", "5", "6", "7", "8"]
    );
    assert_eq!(
        values_of(&master, "read-holding 17 400015 3"),
        ["255", "255", "255"]
    );
    assert_eq!(run_against(&master, "mask-write 17 400005.03=1").0, 0);
    assert_eq!(values_of(&master, "read-holding 17 400005"), ["31"]);
}
