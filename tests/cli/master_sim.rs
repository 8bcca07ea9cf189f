//! Every request command against `--port sim`, the built-in slave: it holds the manuals'
//! example values, and each run of mbtool starts from them.

use crate::support::{mbtool, run_against};

fn sim() -> Vec<String> {
    vec!["--port".into(), "sim".into()]
}

fn run(args: &str) -> (i32, String) {
    run_against(&sim(), args)
}

#[test]
fn reads_give_the_manual_values() {
    assert_eq!(
        run("read-holding 17 400108 3 -o values"),
        (0, "555\n0\n100\n".into())
    );
    assert_eq!(run("read 17 300009 -o values"), (0, "10\n".into()));
    let (code, coils) = run("read-coils 17 000020 8 -o values");
    assert_eq!((code, coils.as_str()), (0, "1\n0\n1\n1\n0\n0\n1\n1\n"));
    let (code, inputs) = run("read-inputs 17 100197 8 -o values");
    assert_eq!((code, inputs.as_str()), (0, "0\n0\n1\n1\n0\n1\n0\n1\n"));
    let (code, table) = run("read-holding 17 400108 3");
    assert_eq!(code, 0);
    for text in ["400108", "400110", "022B", "555"] {
        assert!(table.contains(text), "{table}");
    }
}

#[test]
fn reads_past_one_request_are_put_together() {
    let (code, out) = run("read-holding 17 400001 300 -o values");
    assert_eq!(code, 0);
    let values: Vec<&str> = out.lines().collect();
    assert_eq!(values.len(), 300);
    assert_eq!(values[107..110], ["555", "0", "100"]);
}

#[test]
fn writes_are_confirmed() {
    for (args, says) in [
        ("write-coil 17 000173 on", "wrote 1 value from 000173"),
        ("write-coils 17 000020 10110", "wrote 5 values from 000020"),
        (
            "write-register 17 400002 3",
            "function 6 Write Single Register",
        ),
        (
            "write-registers 17 400002 10 258",
            "function 16 Write Multiple Registers",
        ),
        (
            "write 17 400001 3.14 --type f32",
            "wrote 1 value from 400001",
        ),
    ] {
        let (code, out) = run(args);
        assert_eq!(code, 0, "{args}: {out}");
        assert!(out.contains(says), "{args}: {out}");
    }
    let (code, out) = run("write-register 17 400002 3 --json");
    let json: serde_json::Value = serde_json::from_str(out.trim()).unwrap();
    assert_eq!(
        (code, json["function"].as_u64(), json["ref"].as_str()),
        (0, Some(6), Some("400002"))
    );
}

#[test]
fn raw_requests_and_exceptions() {
    let (code, out) = run("raw 17 2B 0E 01 00 --json");
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("\"VendorName\""), "{out}");
    let (code, out) = run("raw 17 41");
    assert_eq!(code, 11, "{out}");
    assert!(out.contains("illegal function"), "{out}");
    // A known function with a bad quantity: exception 03, as a device answers it.
    let (code, out) = run("raw 17 03 00 00 00 00");
    assert_eq!(code, 13, "{out}");
    let (code, out) = run("raw 17 08 00 00 12 34 --json");
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("\"data\":\"12 34\""), "{out}");
}

#[test]
fn another_slave_id_is_silent() {
    let (code, out) = run("read-holding 18 400108 --timeout 100ms");
    assert_eq!(code, 3, "{out}");
    assert!(out.contains("no answer from slave 18"), "{out}");
}

#[test]
fn polling_counts_and_summarises() {
    let output = mbtool()
        .args([
            "--port",
            "sim",
            "read-holding",
            "17",
            "400108",
            "3",
            "--poll",
            "0",
            "--count",
            "5",
            "--json",
        ])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(0));
    assert_eq!(String::from_utf8_lossy(&output.stdout).lines().count(), 5);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.starts_with("mbtool: 5 requests, 5 answers, 0 timeouts"),
        "{stderr}"
    );
    assert!(stderr.contains("response time min"), "{stderr}");
}

#[test]
fn wide_values_carry_their_registers_in_json_and_csv() {
    // 400108-400109 hold 555 and 0: as a u32 (ABCD) that is 555 << 16.
    let (code, out) = run("read-holding 17 400108 --type u32 --json");
    assert_eq!(code, 0, "{out}");
    let json: serde_json::Value = serde_json::from_str(out.trim()).unwrap();
    assert_eq!(
        json["values"][0],
        serde_json::json!({"address": 107, "ref": "400108", "value": 555u64 << 16, "registers": [555, 0]})
    );
    // 16-bit values carry no registers key.
    let (_, out) = run("read-holding 17 400108 --json");
    assert!(!out.contains("registers"), "{out}");
    let (code, out) = run("read-holding 17 400108 2 -o csv");
    assert_eq!(code, 0);
    assert_eq!(
        out,
        "ref,address,hex,value\n400108,107,022B,555\n400109,108,0000,0\n"
    );
}
