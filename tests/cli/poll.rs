//! `--poll` as a logger: rows with their time, failures as rows, and a connection that
//! drops opened again, against a `serve` that is stopped and started again.

use std::process::{Command as Process, Stdio};
use std::time::Duration;

use crate::support::{free_port, mbtool, serve, wait_for_listener};

/// The rows of a CSV poll log of 400108: (time, value, error).
fn rows(text: &str) -> Vec<(chrono::DateTime<chrono::FixedOffset>, String, String)> {
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("time,400108,error"), "{text}");
    lines
        .map(|line| {
            let fields: Vec<&str> = line.splitn(3, ',').collect();
            let time = chrono::DateTime::parse_from_rfc3339(fields[0])
                .unwrap_or_else(|e| panic!("{line}: {e}"));
            assert_eq!(
                fields[0].split('.').nth(1).map(|f| f.len()),
                Some(9),
                "{line}: milliseconds and offset"
            );
            (time, fields[1].to_string(), fields[2].to_string())
        })
        .collect()
}

/// mbtool polling in the background, its rows piped for the test to read.
fn polling<S: AsRef<std::ffi::OsStr>>(args: &[S]) -> crate::support::Stopped {
    crate::support::Stopped(
        Process::new(assert_cmd::cargo::cargo_bin("mbtool"))
            .args(args)
            .env("NO_COLOR", "1")
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .unwrap(),
    )
}

#[test]
fn a_poll_goes_on_through_a_device_that_restarts() {
    let tcp = free_port();
    let address = format!("tcp://127.0.0.1:{tcp}");
    let first = serve(&["--port", &address]);
    assert!(wait_for_listener(tcp, Duration::from_secs(10)));
    let dir = tempfile::tempdir().unwrap();
    let log = dir.path().join("poll.csv");
    let port = format!("127.0.0.1:{tcp}");
    let log_path = log.to_str().unwrap();
    let mut poller = polling(&[
        "--port",
        &port,
        "read-holding",
        "17",
        "400108",
        "--poll",
        "100ms",
        "--count",
        "55",
        "-o",
        "csv",
        "--log",
        log_path,
    ]);
    std::thread::sleep(Duration::from_millis(1500));
    drop(first);
    std::thread::sleep(Duration::from_secs(2));
    let _second = serve(&["--port", &address]);
    let status = poller.0.wait().unwrap();
    let text = std::fs::read_to_string(&log).unwrap();
    let rows = rows(&text);
    assert_eq!(rows.len(), 55, "{text}");
    // Times in order.
    assert!(rows.windows(2).all(|w| w[0].0 <= w[1].0), "{text}");
    // Values, then errors while serve was down, then values again.
    let kinds: Vec<&str> = rows
        .iter()
        .map(
            |(_, value, error)| match (value.as_str(), error.is_empty()) {
                ("555", true) => "value",
                ("", false) => "error",
                other => panic!("{other:?}"),
            },
        )
        .collect();
    let mut phases = kinds.clone();
    phases.dedup();
    assert_eq!(phases, ["value", "error", "value"], "{text}");
    assert!(
        kinds.iter().filter(|k| **k == "error").count() >= 10,
        "{text}"
    );
    // The screen showed the same rows; the last read succeeded.
    assert!(status.success(), "{status}");
    let mut screen = String::new();
    std::io::Read::read_to_string(poller.0.stdout.as_mut().unwrap(), &mut screen).unwrap();
    assert_eq!(screen, text);
}

#[test]
fn log_without_poll_is_refused() {
    let output = mbtool()
        .args(["--port", "sim", "read-holding", "17", "1", "--log", "x.csv"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&output.stderr),
        "mbtool: --log keeps the rows of a --poll: give --poll INTERVAL too\n"
    );
}

/// socat joining two pseudo-terminals at `a` and `b`, stopped when dropped.
fn socat(a: &std::path::Path, b: &std::path::Path) -> crate::support::Stopped {
    let child = Process::new("socat")
        .arg(format!("pty,raw,echo=0,link={}", a.display()))
        .arg(format!("pty,raw,echo=0,link={}", b.display()))
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let deadline = std::time::Instant::now() + Duration::from_secs(5);
    while !(a.exists() && b.exists()) && std::time::Instant::now() < deadline {
        std::thread::sleep(Duration::from_millis(20));
    }
    crate::support::Stopped(child)
}

#[test]
fn a_poll_goes_on_through_a_serial_port_that_goes_away_and_comes_back() {
    if !crate::support::peer_available("socat", crate::support::command_exists("socat")) {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a"), dir.path().join("b"));
    let line = socat(&a, &b);
    let slave = serve(&["--port", &a.display().to_string()]);
    let log = dir.path().join("poll.csv");
    let mut poller = crate::support::Stopped(
        Process::new(assert_cmd::cargo::cargo_bin("mbtool"))
            .args([
                "--port",
                &b.display().to_string(),
                "read-holding",
                "17",
                "400108",
            ])
            .args([
                "--poll",
                "100ms",
                "--count",
                "45",
                "-o",
                "csv",
                "--timeout",
                "50ms",
                "--log",
            ])
            .arg(&log)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap(),
    );
    std::thread::sleep(Duration::from_millis(1200));
    // The adapter is unplugged: the port and the slave behind it go away.
    drop(slave);
    drop(line);
    std::thread::sleep(Duration::from_millis(1500));
    let _line = socat(&a, &b);
    let _slave = serve(&["--port", &a.display().to_string()]);
    assert!(poller.0.wait().unwrap().success());
    let text = std::fs::read_to_string(&log).unwrap();
    let mut phases: Vec<bool> = rows(&text)
        .iter()
        .map(|(_, _, error)| error.is_empty())
        .collect();
    phases.dedup();
    assert_eq!(phases, [true, false, true], "{text}");
}

#[test]
fn a_map_polled_is_logged_point_by_point_and_failures_are_rows() {
    let map = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/pump3.csv");
    let data = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/pump3.txt");
    let (_device, port, _) = crate::support::serve_tcp(&["--data", data]);
    let dir = tempfile::tempdir().unwrap();
    let log = dir.path().join("pump.jsonl");
    let output = mbtool()
        .args(&port)
        .args([
            "read", "17", "--map", map, "speed", "flow", "--poll", "50ms", "--count", "3", "--log",
        ])
        .arg(&log)
        .output()
        .unwrap();
    assert!(output.status.success(), "{output:?}");
    let lines: Vec<serde_json::Value> = std::fs::read_to_string(&log)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(lines.len(), 3);
    for line in &lines {
        assert!(chrono::DateTime::parse_from_rfc3339(line["time"].as_str().unwrap()).is_ok());
        assert_eq!(line["points"][0]["name"], "speed");
        assert_eq!(line["points"][1]["value"], 4.5);
    }
    // Nobody there: every poll is an error row, and the exit status is the last one's.
    let nowhere = format!("127.0.0.1:{}", free_port());
    let output = mbtool()
        .args([
            "--port", &nowhere, "read", "17", "--map", map, "--poll", "50ms", "--count", "3", "-o",
            "csv",
        ])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(1));
    let csv = String::from_utf8_lossy(&output.stdout);
    let mut lines = csv.lines();
    assert_eq!(
        lines.next(),
        Some("time,voltage,speed,pressure_max,running,flow,error")
    );
    assert!(
        lines.all(|l| l.contains(",,,,,,") && l.contains("127.0.0.1")),
        "{csv}"
    );
}

#[test]
fn a_log_appended_to_keeps_one_header_and_timeouts_say_what_was_tried() {
    let dir = tempfile::tempdir().unwrap();
    let log = dir.path().join("run.csv");
    for _ in 0..2 {
        let output = mbtool()
            .args([
                "--port",
                "sim",
                "read-holding",
                "17",
                "400108",
                "--poll",
                "10ms",
                "--count",
                "2",
                "--log",
            ])
            .arg(&log)
            .output()
            .unwrap();
        assert!(output.status.success(), "{output:?}");
    }
    let text = std::fs::read_to_string(&log).unwrap();
    assert_eq!(
        text.lines().filter(|l| l.starts_with("time,")).count(),
        1,
        "{text}"
    );
    assert_eq!(text.lines().count(), 5, "{text}");
    let output = mbtool()
        .args([
            "--port",
            "sim",
            "--timeout",
            "20ms",
            "read-holding",
            "5",
            "400108",
            "--poll",
            "10ms",
            "--count",
            "1",
        ])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(3));
    assert!(
        String::from_utf8_lossy(&output.stderr)
            .contains("from the built-in slave (sim): it answers as slave 17 only"),
        "{output:?}"
    );
}

/// A poll's output for `args` against `port`: (exit status, stdout).
fn polled(port: &[String], args: &str) -> (i32, String) {
    let output = mbtool()
        .args(port)
        .args(args.split_whitespace())
        .args(["--poll", "100ms", "--count", "1"])
        .output()
        .expect("mbtool runs");
    (
        output.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&output.stdout).into_owned(),
    )
}

/// The (ref, value, error) of each value of a poll's one-line CSV: a hole has no value,
/// and the error column names it.
fn cells(csv: &str) -> Vec<(String, String, String)> {
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap_or_default().split(',').collect();
    let row: Vec<&str> = lines.next().unwrap_or_default().split(',').collect();
    assert_eq!(header.len(), row.len(), "{csv}");
    let columns = 1..header.len() - 1;
    // The error column names the first hole.
    let first_hole = (1..header.len() - 1).find(|i| row[*i].is_empty());
    let said = first_hole.map(|i| format!("{}: no such address", header[i]));
    assert_eq!(row[header.len() - 1], said.unwrap_or_default(), "{csv}");
    header[columns.clone()]
        .iter()
        .zip(&row[columns])
        .map(|(reference, value)| {
            let hole = value.is_empty().then(|| "no such address".to_string());
            (
                reference.to_string(),
                value.to_string(),
                hole.unwrap_or_default(),
            )
        })
        .collect()
}

/// A poll of a range with holes reads around them, as watch does, against pymodbus (whose
/// sparse block refuses a hole with exception 02) and against serve with a data file: the
/// addresses that exist show their values, each hole says so, and a wide type is never cut
/// in two.
#[test]
fn a_poll_of_a_range_reads_around_its_holes() {
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("holes.txt");
    std::fs::write(
        &data,
        "400003-400004 = 3 4\n400006-400011 = 6 7 8 9 10 11\n",
    )
    .unwrap();
    let (_serve, serve_port, _) = crate::support::serve_tcp(&["--data", data.to_str().unwrap()]);
    let holding = "--holding=2=3,3=4,5=6,6=7,7=8,8=9,9=10,10=11".to_string();
    let peers = crate::support::pymodbus_tcp(&[holding]);
    let mut ports = vec![serve_port];
    ports.extend(peers.as_ref().map(|(_, port)| port.clone()));
    let row = |r: &str, v: &str| (r.to_string(), v.to_string(), String::new());
    let hole = |r: &str| (r.to_string(), String::new(), "no such address".to_string());
    for port in &ports {
        let (code, csv) = polled(port, "read-holding 17 400003 5 -o csv");
        assert_eq!(code, 0, "{csv}");
        assert_eq!(
            cells(&csv),
            [
                row("400003", "3"),
                row("400004", "4"),
                hole("400005"),
                row("400006", "6"),
                row("400007", "7")
            ],
            "{port:?}"
        );
        // Two requests of at most 2 each; the hole in the first is found all the same.
        let (_, csv) = polled(port, "read-holding 17 400004 4 --max-per-request 2 -o csv");
        assert_eq!(
            cells(&csv),
            [
                row("400004", "4"),
                hole("400005"),
                row("400006", "6"),
                row("400007", "7")
            ],
            "{port:?}"
        );
        // A u32 that would take the hole is the hole; the next one is whole.
        let (_, csv) = polled(port, "read-holding 17 400003 3 -t u32 -o csv");
        assert_eq!(
            cells(&csv),
            [
                row("400003", "196612"),
                hole("400005"),
                row("400007", "458760")
            ],
            "{port:?}"
        );
        let (_, values) = polled(port, "read-holding 17 400004 3 -o values");
        assert_eq!(values, "4\n-\n6\n", "{port:?}");
        let (_, json) = polled(port, "read-holding 17 400005 2 --json");
        let json: serde_json::Value = serde_json::from_str(json.trim()).unwrap();
        assert_eq!(json["values"][0]["error"], "no such address", "{json}");
        assert_eq!(json["values"][0].get("value"), None, "{json}");
        assert_eq!(json["values"][1]["value"], 6, "{json}");
        // Nothing of the range there: the device's answer stands.
        let (code, csv) = polled(port, "read-holding 17 400012 3 -o csv");
        assert_eq!(code, 12, "{csv}");
        assert!(csv.contains("exception 02"), "{csv}");
    }
}

/// On the screen a poll is one line under one header: its time of day, a column a value,
/// a value that changed marked, and a poll that read nothing a line of `-`, never the last
/// values again.
#[test]
fn the_table_of_a_poll_grows_by_a_line_a_poll() {
    let (_device, port, _) = crate::support::serve_tcp(&[]);
    let mut args: Vec<&str> = port.iter().map(String::as_str).collect();
    args.extend(["read-holding", "17", "400108", "2", "--poll", "200ms"]);
    args.extend(["--count", "8", "--timeout", "100ms"]);
    let mut poller = polling(&args);
    std::thread::sleep(Duration::from_millis(700));
    write_42(&port);
    poller.0.wait().unwrap();
    let mut screen = String::new();
    std::io::Read::read_to_string(poller.0.stdout.as_mut().unwrap(), &mut screen).unwrap();
    let lines: Vec<Vec<&str>> = screen
        .lines()
        .map(|l| l.split_whitespace().collect())
        .collect();
    assert_eq!(lines[0], ["time", "400108", "400109"], "{screen}");
    assert_eq!(lines.len(), 9, "{screen}");
    let values: Vec<&[&str]> = lines[1..].iter().map(|l| &l[1..]).collect();
    // 555 throughout; 400109 from 0 to 42, marked once, when it changed.
    let changed = values
        .iter()
        .position(|v| v[1] == "42*")
        .expect("a change marked");
    assert!(changed > 0, "{screen}");
    assert!(
        values[..changed].iter().all(|v| *v == ["555", "0"]),
        "{screen}"
    );
    assert!(
        values[changed + 1..].iter().all(|v| *v == ["555", "42"]),
        "{screen}"
    );
    // Each line starts with the time of day, milliseconds included.
    for line in &lines[1..] {
        let time = chrono::NaiveTime::parse_from_str(line[0], "%H:%M:%S%.3f");
        assert!(time.is_ok(), "{screen}");
    }
    // Nobody there: a line of `-` a poll.
    let nowhere = format!("127.0.0.1:{}", free_port());
    let output = mbtool()
        .args(["--port", &nowhere, "read-holding", "17", "400108", "2"])
        .args(["--poll", "50ms", "--count", "2"])
        .env("NO_COLOR", "1")
        .output()
        .unwrap();
    let screen = String::from_utf8_lossy(&output.stdout);
    let lines: Vec<Vec<&str>> = screen
        .lines()
        .map(|l| l.split_whitespace().collect())
        .collect();
    assert_eq!(lines.len(), 3, "{screen}");
    assert!(lines[1..].iter().all(|l| l[1..] == ["-", "-"]), "{screen}");
}

/// In a terminal a value that changed since the last poll is yellow, on its poll's line
/// only.
#[test]
fn in_a_terminal_a_changed_value_is_yellow() {
    let (_device, port, _) = crate::support::serve_tcp(&[]);
    let args = format!(
        "{} read-holding 17 400108 2 --poll 300ms --count 6",
        port.join(" ")
    );
    let Some(terminal) = crate::support::Terminal::run_in_colour(&args, 100, 12) else {
        return;
    };
    std::thread::sleep(Duration::from_millis(800));
    write_42(&port);
    terminal.wait_for(Duration::from_secs(10), |_| terminal.done());
    let screen = terminal.screen_in_colour();
    let yellow = "\u{1b}[33m42";
    let coloured: Vec<&String> = screen.iter().filter(|l| l.contains(yellow)).collect();
    assert_eq!(coloured.len(), 1, "{screen:#?}");
    let after = screen.iter().skip_while(|l| !l.contains(yellow)).nth(1);
    assert!(
        after.is_some_and(|l| l.contains("42") && !l.contains("\u{1b}[33m")),
        "{screen:#?}"
    );
}

/// Writes 42 to 400109 of slave 17 at `port`, as another master would.
fn write_42(port: &[String]) {
    let wrote = mbtool()
        .args(port)
        .args(["write-register", "17", "400109", "42"])
        .output()
        .unwrap();
    assert!(wrote.status.success(), "{wrote:?}");
}
