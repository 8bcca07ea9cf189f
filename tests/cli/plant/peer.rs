//! The same devices read by `mbtool poll` and by pymodbus, as a Telegraf-style
//! configuration of the same points describes them: the same values.

use std::io::Write;
use std::process::{Command as Process, Stdio};

use super::json_rows;
use crate::support::{command_exists, peer_available, serve_tcp};

#[test]
fn a_plant_reads_as_pymodbus_reads_the_same_devices() {
    let found = command_exists("python3")
        && Process::new("python3")
            .args(["-c", "import pymodbus"])
            .status()
            .is_ok_and(|s| s.success());
    if !peer_available("pymodbus", found) {
        return eprintln!("skipped: pymodbus is not installed");
    }
    let dir = tempfile::tempdir().unwrap();
    let data = |name: &str, text: &str| {
        let path = dir.path().join(name);
        std::fs::write(&path, text).unwrap();
        path.display().to_string()
    };
    let first = data(
        "first.txt",
        "400001 = 1234\n400002 = -7 i16\n400003 = 229.01 f32 CDAB\n400005 = 3000000000 u32\n",
    );
    let second = data(
        "second.txt",
        "400001 = 65535\n400002 = -32768 i16\n400003 = -0.5 f32 CDAB\n400005 = 7 u32\n",
    );
    let (_one, _, one) = serve_tcp(&["--data", &first, "--slave", "3"]);
    let (_two, _, two) = serve_tcp(&["--data", &second, "--slave", "9"]);
    let points = "    points:\n      - {name: volts, ref: 400001, scale: 0.1, unit: V}\n      - {name: delta, ref: 400002, type: i16}\n      - {name: power, ref: 400003, type: f32, order: CDAB}\n      - {name: energy, ref: 400005, type: u32}\n";
    let plant = dir.path().join("plant.yaml");
    std::fs::write(
        &plant,
        format!(
            "devices:\n  - name: one\n    port: tcp://127.0.0.1:{one}\n    slave: 3\n    every: 100ms\n{points}  - name: two\n    port: tcp://127.0.0.1:{two}\n    slave: 9\n    every: 100ms\n{points}"
        ),
    )
    .unwrap();
    let (code, rows, stderr) = json_rows(&[plant.to_str().unwrap(), "--for", "150ms"]);
    assert_eq!(code, 0, "{stderr}");

    let field = |name: &str, address: u16, data_type: &str, byte_order: &str, scale: f64| serde_json::json!({"name": name, "address": address, "data_type": data_type, "byte_order": byte_order, "scale": scale});
    let fields = [
        field("volts", 0, "UINT16", "ABCD", 0.1),
        field("delta", 1, "INT16", "ABCD", 1.0),
        field("power", 2, "FLOAT32", "CDAB", 1.0),
        field("energy", 4, "UINT32", "ABCD", 1.0),
    ];
    let config = serde_json::json!([
        {"name": "one", "port": one, "slave": 3, "fields": fields},
        {"name": "two", "port": two, "slave": 9, "fields": fields},
    ]);
    let mut reader = Process::new("python3")
        .arg(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/peers/plant_reader.py"
        ))
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    reader
        .stdin
        .take()
        .unwrap()
        .write_all(config.to_string().as_bytes())
        .unwrap();
    let read = reader.wait_with_output().unwrap();
    assert!(
        read.status.success(),
        "{}",
        String::from_utf8_lossy(&read.stderr)
    );
    let peer: serde_json::Value = serde_json::from_slice(&read.stdout).unwrap();

    for device in ["one", "two"] {
        let row = rows.iter().find(|row| row["device"] == device).unwrap();
        for name in ["volts", "delta", "power", "energy"] {
            let ours = row["values"][name].as_f64().unwrap();
            let theirs = peer[device][name].as_f64().unwrap();
            // Shown as f32 and as the scale's decimals: as close as those allow.
            assert!(
                (ours - theirs).abs() <= 1e-6 * theirs.abs().max(1.0),
                "{device} {name}: {ours} against pymodbus's {theirs}"
            );
        }
    }
    let one = &rows.iter().find(|row| row["device"] == "one").unwrap()["values"];
    assert_eq!(
        (
            one["volts"].as_f64(),
            one["delta"].as_i64(),
            one["energy"].as_u64()
        ),
        (Some(123.4), Some(-7), Some(3_000_000_000))
    );
}
