//! `read --layouts` and `read --expect`: registers read as every type and order, and the
//! layout that gives a value the user knows, ranked first, for values that pymodbus wrote
//! in every type and order.

use std::process::Command as Process;

use crate::support::{mbtool, peer_available, python_has, serve_tcp};

const WRITER: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/peers/pymodbus_layouts.py"
);

#[test]
fn a_value_pymodbus_wrote_in_any_layout_ranks_that_layout_first() {
    if !peer_available("pymodbus (Python)", python_has("pymodbus")) {
        return;
    }
    let (_server, port, tcp) = serve_tcp(&[]);
    let written = Process::new("python3")
        .args([WRITER, &tcp.to_string()])
        .output()
        .unwrap();
    assert!(
        written.status.success(),
        "{}",
        String::from_utf8_lossy(&written.stderr)
    );
    let written: Vec<serde_json::Value> = String::from_utf8_lossy(&written.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(written.len(), 2 * 2 + 6 * 4);
    for layout in written {
        let address = layout["address"].as_u64().unwrap();
        let value = layout["value"].as_str().unwrap();
        // The register after is read too, as a user reading a block from the point does.
        let reference = format!("4{:05}", address + 1);
        let count = (layout["registers"].as_u64().unwrap() + 1).to_string();
        let output = mbtool()
            .args(&port)
            .args([
                "read", "17", &reference, &count, "--expect", value, "-o", "json",
            ])
            .output()
            .unwrap();
        assert!(output.status.success(), "{layout}: {output:?}");
        let best: serde_json::Value = serde_json::from_str(
            String::from_utf8_lossy(&output.stdout)
                .lines()
                .next()
                .unwrap(),
        )
        .unwrap();
        let at = format!("4{:05}", address + 1);
        assert_eq!(
            (&best["ref"], &best["type"], &best["order"]),
            (&at.as_str().into(), &layout["type"], &layout["order"]),
            "{layout}"
        );
        let told = String::from_utf8_lossy(&output.stderr);
        let line = format!(
            "value,{at},{},{}",
            layout["type"].as_str().unwrap(),
            layout["order"].as_str().unwrap()
        );
        assert!(told.contains(&line), "{told}");
    }
}

#[test]
fn layouts_show_every_type_and_order_and_refuse_what_they_cannot_read() {
    let output = mbtool()
        .args([
            "--port",
            "sim",
            "read",
            "17",
            "400108",
            "2",
            "--layouts",
            "-o",
            "csv",
        ])
        .output()
        .unwrap();
    let csv = String::from_utf8_lossy(&output.stdout);
    assert!(
        csv.starts_with("ref,type,order,hex,value\n400108,u16,ABCD,022B,555\n"),
        "{csv}"
    );
    assert!(
        csv.contains("400108,u32,ABCD,022B 0000,36372480\n"),
        "{csv}"
    );
    assert!(csv.contains("400108,u32,CDAB,022B 0000,555\n"), "{csv}");
    assert_eq!(csv.lines().count(), 1 + 2 + 2 + 4 + 4 + 4 + 2);
    for (args, message) in [
        (
            "read 17 000020 --layouts",
            "mbtool: --layouts and --expect read registers",
        ),
        (
            "read 17 400108 2 --layouts --type f32",
            "mbtool: --layouts and --expect read every type",
        ),
        (
            "read 17 400108 2 --expect volts",
            "mbtool: --expect volts: give a number",
        ),
        (
            "read 17 400108 2 --expect 5..1",
            "mbtool: --expect 5..1: the lower end",
        ),
    ] {
        let output = mbtool()
            .args(["--port", "sim"])
            .args(args.split_whitespace())
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(2), "{args}: {output:?}");
        assert!(
            String::from_utf8_lossy(&output.stderr).starts_with(message),
            "{args}: {output:?}"
        );
    }
    // Nothing gives it: said, exit status 1.
    let output = mbtool()
        .args([
            "--port", "sim", "read", "17", "400108", "3", "--expect", "12345.6",
        ])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&output.stderr)
        .contains("no type or order of the 3 registers read gives 12345.6"));
}

#[test]
fn a_small_value_a_wider_type_gives_as_well_is_told_as_open() {
    let (_server, port, _) = serve_tcp(&[]);
    let wrote = mbtool()
        .args(&port)
        .args(["write", "17", "400001", "229", "0"])
        .output()
        .unwrap();
    assert!(wrote.status.success(), "{wrote:?}");
    let output = mbtool()
        .args(&port)
        .args(["read", "17", "400001", "2", "--expect", "229"])
        .output()
        .unwrap();
    assert!(output.status.success(), "{output:?}");
    let told = String::from_utf8_lossy(&output.stderr);
    assert!(
        told.contains("value,400001,u16,ABCD\n")
            && told.contains("mbtool: 400001,u32,CDAB gives it as well; read again when the value is larger to tell them apart"),
        "{told}"
    );
}
