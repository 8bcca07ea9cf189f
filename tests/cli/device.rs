//! `info` and `diag` against devices: `serve` on TCP and on a pseudo-terminal, pymodbus
//! with an identity of its own, and a scripted TCP device that lacks function 43.

use std::io::Write;
use std::time::Duration;

use crate::support::{
    mbtool, pymodbus_tcp, scripted_tcp_device, serve_pty, serve_tcp, Act, PtyPair,
};

/// Runs mbtool against `port` with `args` and `--json`; (exit status, the JSON, stderr).
fn json_of(port: &[String], args: &[&str]) -> (i32, serde_json::Value, String) {
    let output = mbtool()
        .args(port)
        .args(args)
        .arg("--json")
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    let json = serde_json::from_str(stdout.trim()).unwrap_or(serde_json::Value::Null);
    (
        output.status.code().unwrap_or(-1),
        json,
        String::from_utf8_lossy(&output.stderr).into_owned(),
    )
}

#[test]
fn info_reads_objects_that_need_several_requests() {
    let url = format!("VendorUrl=https://{}.example", "u".repeat(180));
    let name = format!("ProductName={}", "P".repeat(200));
    let private = format!("0x80={}", "x".repeat(200));
    let (_server, port, _) = serve_tcp(&[
        "--vendor",
        "ACME",
        "--identity",
        &url,
        "--identity",
        &name,
        "--identity",
        &private,
        "--identity",
        "ModelName=PX7-400",
    ]);
    let (code, json, stderr) = json_of(&port, &["info", "17"]);
    assert_eq!(code, 0, "{stderr}");
    let objects = &json["identification"];
    assert_eq!(objects["VendorName"], "ACME");
    assert_eq!(objects["ProductCode"], "mbtool-sim");
    assert_eq!(objects["VendorUrl"], url.split_once('=').unwrap().1);
    assert_eq!(objects["ProductName"], "P".repeat(200));
    assert_eq!(objects["ModelName"], "PX7-400");
    assert_eq!(objects["0x80"], "x".repeat(200));
    // 600 bytes of objects do not fit one answer: the extended stream takes three.
    assert!(json["requests"].as_u64().unwrap() >= 4, "{json}");
    assert_eq!(json["conformity"], 0x83);
    assert_eq!(json["server_id"]["id"], 17);
    assert_eq!(json["server_id"]["running"], true);
    let version = env!("CARGO_PKG_VERSION");
    assert_eq!(
        json["server_id"]["data"],
        format!("ACME mbtool-sim {version}")
    );
}

#[test]
fn info_shows_what_pymodbus_says_it_is() {
    let identity = [
        ("VendorName", "Pumps & Co"),
        ("ProductCode", "PX-7"),
        ("MajorMinorRevision", "2.1"),
        ("VendorUrl", "https://pumps.example"),
        ("ProductName", "Booster pump"),
        ("ModelName", "PX7-400"),
    ];
    let args: Vec<String> = identity
        .iter()
        .flat_map(|(name, value)| ["--identity".to_string(), format!("{name}={value}")])
        .collect();
    let Some((_slave, port)) = pymodbus_tcp(&args) else {
        return;
    };
    let (code, json, stderr) = json_of(&port, &["info", "17"]);
    assert_eq!(code, 0, "{stderr}");
    for (name, value) in identity {
        assert_eq!(json["identification"][name], value, "{json}");
    }
    // pymodbus answers 17 with its text id and the run indicator last.
    assert_eq!(json["server_id"]["running"], true, "{json}");
    assert!(
        json["server_id"]["data"].as_str().unwrap().contains("PX-7"),
        "{json}"
    );
}

/// A TCP device that answers report server id (17) with `answer_17` (or ignores it, for
/// an empty one) and refuses every other function with exception 01.
fn device_without_43(answer_17: &'static [u8]) -> Vec<String> {
    let tcp = scripted_tcp_device(move |_, pdu| match pdu.first() {
        Some(0x11) if answer_17.is_empty() => Act::Silent,
        Some(0x11) => Act::Answer([&[0x11, answer_17.len() as u8][..], answer_17].concat()),
        Some(function) => Act::Answer(vec![function | 0x80, 0x01]),
        None => Act::Close,
    });
    vec!["--port".to_string(), format!("127.0.0.1:{tcp}")]
}

#[test]
fn info_without_43_falls_back_to_17_and_says_so() {
    let port = device_without_43(&[0x2A, 0xFF, b'P', b'L', b'C', b'-', b'5']);
    let output = mbtool().args(&port).args(["info", "42"]).output().unwrap();
    let table = String::from_utf8_lossy(&output.stdout);
    assert_eq!(output.status.code(), Some(0), "{output:?}");
    assert!(
        table.contains("identification (43/14) ┆ not supported (exception 01 illegal function)"),
        "{table}"
    );
    assert!(
        table.contains("server id              ┆ 42 (0x2A)"),
        "{table}"
    );
    assert!(table.contains("run status             ┆ ON"), "{table}");
    assert!(table.contains("server data            ┆ PLC-5"), "{table}");
}

#[test]
fn info_escapes_what_a_device_sends_and_shows_binary_as_hex() {
    let port = device_without_43(&[0x07, 0x00, 0x1B, b'[', b'2', b'J', 0x01]);
    let (code, json, _) = json_of(&port, &["info", "7"]);
    assert_eq!(code, 0);
    assert_eq!(json["identification"]["exception"], 1);
    assert_eq!(json["server_id"]["running"], false);
    assert_eq!(json["server_id"]["data"], "1B 5B 32 4A 01");
}

#[test]
fn a_device_that_refuses_43_and_ignores_17_gives_its_refusal() {
    let port = device_without_43(&[]);
    let output = mbtool()
        .args(&port)
        .args(["--timeout", "200ms", "info", "9"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(11), "{output:?}");
    assert_eq!(
        String::from_utf8_lossy(&output.stderr),
        "mbtool: slave 9 answered exception 01 illegal function to function 43 (Encapsulated Interface Transport)\n"
    );
}

#[test]
fn diag_of_a_unit_id_a_gateway_lacks_is_the_gateway_s_answer() {
    let (_server, port, _) = serve_tcp(&["--slave", "3"]);
    let output = mbtool().args(&port).args(["diag", "5"]).output().unwrap();
    // serve answers 0B for unit ids it lacks, as a gateway does: 10 + 0x0B.
    assert_eq!(output.status.code(), Some(21), "{output:?}");
    assert_eq!(output.stdout, b"");
}

#[test]
fn a_bad_slave_is_refused_before_the_port_is_opened() {
    for command in ["info", "diag", "dump"] {
        let output = mbtool()
            .args(["--port", "tcp://127.0.0.1:1", command, "abc"])
            .args(if command == "dump" {
                &["400001"][..]
            } else {
                &[][..]
            })
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(2), "{command}: {output:?}");
    }
}

/// The counters of `diag --json`, by name.
fn counters(port: &[String], extra: &[&str]) -> serde_json::Value {
    let (code, json, stderr) = json_of(port, &[&["diag", "17"][..], extra].concat());
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(json["round_trips"]["answered"], 5, "{json}");
    assert_eq!(json["round_trips"]["intact"], true, "{json}");
    json["counters"].clone()
}

#[test]
fn diag_counters_count_what_happened_on_the_line() {
    let Some(pair) = PtyPair::new() else { return };
    let (_server, port) = serve_pty(&pair, &[]);
    let before = counters(&port, &[]);
    let reads = 7;
    for _ in 0..reads {
        let status = mbtool()
            .args(&port)
            .args(["read-holding", "17", "400108", "3"])
            .output()
            .unwrap()
            .status;
        assert!(status.success());
    }
    // Two frames whose CRC fails, written on the line by a third party.
    let mut line = std::fs::OpenOptions::new()
        .write(true)
        .open(&pair.b)
        .unwrap();
    for _ in 0..2 {
        line.write_all(&[0x11, 0x03, 0x00, 0x6B, 0x00, 0x03, 0x76, 0x88])
            .unwrap();
        line.flush().unwrap();
        std::thread::sleep(Duration::from_millis(50));
    }
    drop(line);
    let after = counters(&port, &[]);
    let grown = |name: &str| after[name].as_u64().unwrap() - before[name].as_u64().unwrap();
    // The reads, and diag's own requests between the two readings of 0B: the seven
    // counters after it and 07 in the first run, five round trips and 0B in the second.
    assert_eq!(grown("bus_messages"), reads + 8 + 6, "{before} {after}");
    assert_eq!(grown("bus_communication_errors"), 2, "{before} {after}");
    assert_eq!(after["slave_nak"], 0);

    // --clear zeroes them: what a diag counts next is only itself.
    counters(&port, &["--clear"]);
    let cleared = counters(&port, &[]);
    assert_eq!(cleared["bus_messages"], 6, "{cleared}");
    assert_eq!(cleared["bus_communication_errors"], 0, "{cleared}");
}

#[test]
fn a_device_that_does_not_answer_exits_3() {
    for command in ["info", "diag"] {
        let output = mbtool()
            .args(["--port", "sim", "--timeout", "100ms", command, "5"])
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(3), "{command}: {output:?}");
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(
            stderr.starts_with("mbtool: no answer from slave 5 within 100.00 ms"),
            "{stderr}"
        );
    }
}

#[test]
fn diag_shows_the_counters_a_device_lacks_as_such() {
    // Echoes 08/00, keeps only the bus message counter (08/0B), refuses the others and 07.
    let tcp = scripted_tcp_device(|_, pdu| match pdu {
        [0x08, 0x00, 0x00, ..] => Act::Answer(pdu.to_vec()),
        [0x08, 0x00, 0x0B, ..] => Act::Answer(vec![0x08, 0x00, 0x0B, 0x01, 0x2C]),
        [function, ..] => Act::Answer(vec![function | 0x80, 0x01]),
        [] => Act::Close,
    });
    let port = vec!["--port".to_string(), format!("127.0.0.1:{tcp}")];
    let (code, json, stderr) = json_of(&port, &["diag", "1", "--count", "3"]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(json["round_trips"]["answered"], 3);
    assert_eq!(json["counters"]["bus_messages"], 300);
    assert_eq!(json["counters"]["slave_busy"]["exception"], 1);
    assert_eq!(json["exception_status"]["exception"], 1);
    let table = mbtool().args(&port).args(["diag", "1"]).output().unwrap();
    let table = String::from_utf8_lossy(&table.stdout);
    assert!(
        table.contains(
            "slave busy (08/11)               ┆ not supported (exception 01 illegal function)"
        ),
        "{table}"
    );
}

/// With a long `--timeout`, every command that asks a slave that answers at once is done at
/// once: none of them waits out its timeout (or a multiple of it) once the answers are in.
#[test]
fn with_a_long_timeout_every_command_is_done_as_soon_as_it_is_answered() {
    let Some(pair) = PtyPair::new() else { return };
    let pump = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/pump3.txt");
    let map = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/pump3.csv");
    // The pump's data, and the register serve_pty asks to see that it is up.
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("pump.txt");
    std::fs::write(
        &data,
        std::fs::read_to_string(pump).unwrap() + "400108 = 0\n",
    )
    .unwrap();
    let (_server, port) = serve_pty(&pair, &["--data", data.to_str().unwrap()]);
    for args in [
        "read-holding 17 400001",
        "read-holding 17 400001 3",
        "read-coils 17 000001",
        "read-input-registers 17 300001",
        "write-register 17 400020 10",
        "write-coil 17 000001 1",
        "raw 17 03 00 00 00 01",
        "info 17",
        "diag 17 --count 1",
        "dump 17 400001-400003",
        "scan --ids 17",
        "scan --ids 16-17",
        &format!("read 17 --map {map}"),
    ] {
        let mut words: Vec<&str> = vec!["--timeout", "5s"];
        words.extend(args.split(' '));
        let started = std::time::Instant::now();
        let output = mbtool().args(&port).args(&words).output().unwrap();
        let took = started.elapsed();
        assert!(output.status.success(), "{words:?}: {output:?}");
        // scan --ids 16-17 waits out 16's timeout once, and no more.
        let bound = if args.contains("16-17") { 6 } else { 1 };
        assert!(
            took < std::time::Duration::from_secs(bound),
            "{words:?} took {took:?}"
        );
    }
}
