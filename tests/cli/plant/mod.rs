//! `mbtool poll PLANT`: many devices kept read, each at its rate, against `serve` over
//! TCP and on a pseudo-terminal line, with a device that is not there.

mod faults;
mod influx;
mod mqtt;
mod peer;
mod prometheus;

use std::process::{Command as Process, Stdio};
use std::time::{Duration, Instant};

use crate::support::{free_port, mbtool, serve_pty, serve_tcp, PtyPair};

/// A register map of three of the example slave's registers.
const MAP: &str =
    "name,ref,type,unit\nspeed,400108,u16,rpm\nlevel,400109,u16,\nflow,400110,u16,m3/h\n";

/// A folder holding `map.csv` and `plant.yaml` with `devices` (the YAML of each device).
fn plant(devices: &[String]) -> (tempfile::TempDir, String) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("map.csv"), MAP).unwrap();
    let path = dir.path().join("plant.yaml");
    std::fs::write(&path, format!("devices:\n{}", devices.concat())).unwrap();
    (dir, path.display().to_string())
}

fn device(name: &str, port: &str, slave: u8, every: &str) -> String {
    format!("  - name: {name}\n    port: {port}\n    slave: {slave}\n    map: map.csv\n    every: {every}\n")
}

/// The JSON rows of a poll of `args`, with its exit status and stderr.
fn json_rows(args: &[&str]) -> (i32, Vec<serde_json::Value>, String) {
    let output = mbtool()
        .arg("poll")
        .args(args)
        .args(["-o", "json"])
        .output()
        .unwrap();
    let rows = String::from_utf8_lossy(&output.stdout)
        .lines()
        .map(|line| serde_json::from_str(line).unwrap_or_else(|e| panic!("{line}: {e}")))
        .collect();
    (
        output.status.code().unwrap_or(-1),
        rows,
        String::from_utf8_lossy(&output.stderr).into_owned(),
    )
}

fn rows_of<'a>(rows: &'a [serde_json::Value], device: &str) -> Vec<&'a serde_json::Value> {
    rows.iter().filter(|row| row["device"] == device).collect()
}

#[test]
fn each_device_keeps_its_rate_and_a_dead_one_holds_back_no_other() {
    let (_fast_device, _, fast) = serve_tcp(&[]);
    let (_slow_device, _, slow) = serve_tcp(&[]);
    let nowhere = free_port();
    let (_dir, path) = plant(&[
        device("fast", &format!("tcp://127.0.0.1:{fast}"), 17, "100ms"),
        device("slow", &format!("tcp://127.0.0.1:{slow}"), 17, "400ms"),
        device("dead", &format!("tcp://127.0.0.1:{nowhere}"), 17, "100ms"),
    ]);
    let started = Instant::now();
    let (code, rows, stderr) = json_rows(&[&path, "--for", "2s"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        started.elapsed() < Duration::from_secs(4),
        "{:?}",
        started.elapsed()
    );
    let (fast, slow, dead) = (
        rows_of(&rows, "fast"),
        rows_of(&rows, "slow"),
        rows_of(&rows, "dead"),
    );
    // At their rates, whatever the dead device does: 20 and 5 in 2 s, give or take a
    // loaded machine.
    assert!((14..=21).contains(&fast.len()), "fast: {}", fast.len());
    assert!((4..=6).contains(&slow.len()), "slow: {}", slow.len());
    for row in fast.iter().chain(&slow) {
        assert_eq!(row["values"]["speed"], 555, "{row}");
        assert_eq!(row["values"]["flow"], 100, "{row}");
        assert!(chrono::DateTime::parse_from_rfc3339(row["time"].as_str().unwrap()).is_ok());
    }
    // The dead device: rows without values that say why, asked less often after three.
    assert!(
        !dead.is_empty() && dead.len() < fast.len(),
        "dead: {}",
        dead.len()
    );
    for row in &dead {
        assert_eq!(row["values"], serde_json::json!({}), "{row}");
        assert!(
            row["error"].as_str().unwrap().contains("not connected"),
            "{row}"
        );
    }
    // A summary per device on stderr.
    for name in ["fast", "slow", "dead"] {
        assert!(stderr.contains(&format!("mbtool: {name}: ")), "{stderr}");
    }
}

#[test]
fn the_devices_of_one_serial_line_are_polled_in_turn() {
    let Some(pair) = PtyPair::new() else { return };
    let (_line, port) = serve_pty(&pair, &["--slave", "17", "--slave", "18"]);
    let (_dir, path) = plant(&[
        device("a", &port[1], 17, "200ms"),
        device("b", &port[1], 18, "200ms"),
        device("c", &port[1], 19, "200ms"),
    ]);
    let (code, rows, stderr) = json_rows(&[&path, "--for", "2s", "--timeout", "100ms"]);
    assert_eq!(code, 0, "{stderr}");
    for name in ["a", "b"] {
        let rows = rows_of(&rows, name);
        assert!(rows.len() >= 6, "{name}: {}", rows.len());
        assert!(
            rows.iter().all(|row| row["values"]["speed"] == 555),
            "{rows:?}"
        );
    }
    // Slave 19 is not on the line: its timeouts are its rows alone.
    let absent = rows_of(&rows, "c");
    assert!(!absent.is_empty());
    assert!(
        absent
            .iter()
            .all(|row| row["values"] == serde_json::json!({})),
        "{absent:?}"
    );
}

#[test]
fn csv_and_influx_rows_name_every_device_and_point() {
    let (_dir, path) = plant(&[
        device("pump", "sim", 17, "100ms"),
        device("meter", "sim", 17, "100ms"),
    ]);
    let output = mbtool()
        .args(["poll", &path, "--for", "350ms", "-o", "csv"])
        .output()
        .unwrap();
    let csv = String::from_utf8_lossy(&output.stdout);
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some("time,device,speed,level,flow,error"));
    let rows: Vec<&str> = lines.collect();
    assert!(rows.len() >= 4, "{csv}");
    assert!(rows.iter().all(|row| row.ends_with(",555,0,100,")), "{csv}");
    let output = mbtool()
        .args(["poll", &path, "--for", "250ms", "-o", "influx"])
        .output()
        .unwrap();
    let now = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .unwrap()
        .as_nanos();
    let text = String::from_utf8_lossy(&output.stdout);
    for line in text.lines() {
        let (head, time) = line.rsplit_once(' ').unwrap();
        assert!(
            head == "modbus,device=pump,slave=17 speed=555i,level=0i,flow=100i"
                || head == "modbus,device=meter,slave=17 speed=555i,level=0i,flow=100i",
            "{line}"
        );
        let time: u128 = time.parse().unwrap();
        assert!(now - time < 5_000_000_000, "{line}");
    }
    assert!(text.lines().count() >= 4, "{text}");
}

#[test]
fn every_fault_of_the_plant_is_told_at_once_and_nothing_is_polled() {
    let listening = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    let port = listening.local_addr().unwrap().port();
    let (dir, path) = plant(&[
        device("a", &format!("tcp://127.0.0.1:{port}"), 17, "fast"),
        "  - name: b\n    slave: 300\n    map: none.csv\n    every: 1s\n".to_string(),
        device("c", "nope://x", 17, "1s"),
        device("a", &format!("tcp://127.0.0.1:{port}"), 17, "1s"),
        // One line at two speeds.
        device("d", "/dev/ttyNOPE0", 1, "1s"),
        "  - name: e\n    port: /dev/ttyNOPE0\n    baud: 9600\n    slave: 2\n    map: map.csv\n    every: 1s\n".to_string(),
    ]);
    let output = mbtool().args(["poll", &path]).output().unwrap();
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&output.stderr);
    let file = dir.path().join("plant.yaml").display().to_string();
    for said in [
        format!("{file}:6: a: every:"),
        format!("{file}:7: b has no port"),
        format!("{file}:8: b: slave"),
        format!("{file}:16: the name 'a' is taken already, on line 2"),
        format!("{file}:11: c: 'nope://x'"),
        format!("{file}:26: e: /dev/ttyNOPE0 is RTU 19200 baud, parity even, 8 data bits, 1 stop bits for d (line 21), and RTU 9600 baud"),
    ] {
        assert!(stderr.contains(&said), "{said}:\n{stderr}");
    }
    assert!(
        stderr.lines().all(|line| line.starts_with("mbtool: ")),
        "{stderr}"
    );
    listening.set_nonblocking(true).unwrap();
    assert!(listening.accept().is_err(), "a connection was made");
}

#[test]
fn sigterm_ends_the_poll_with_its_summary() {
    let (_dir, path) = plant(&[device("pump", "sim", 17, "100ms")]);
    let child = Process::new(assert_cmd::cargo::cargo_bin("mbtool"))
        .args(["poll", &path])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    std::thread::sleep(Duration::from_millis(500));
    let stopped = Instant::now();
    send_signal(child.id(), "TERM");
    let output = child.wait_with_output().unwrap();
    assert!(
        stopped.elapsed() < Duration::from_secs(1),
        "{:?}",
        stopped.elapsed()
    );
    assert_eq!(output.status.code(), Some(143));
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(stdout.lines().count() >= 3, "{stdout}");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("mbtool: pump: "), "{stderr}");
}

/// Sends a signal with kill(1).
fn send_signal(pid: u32, signal: &str) {
    let status = Process::new("kill")
        .args([&format!("-{signal}"), &pid.to_string()])
        .status()
        .unwrap();
    assert!(status.success());
}

/// A Home Assistant configuration as it stands is a plant: its hub a device per slave and
/// per `scan_interval` (15 s where not given), an entity it does not poll left out.
#[test]
fn a_home_assistant_configuration_is_polled_as_home_assistant_polls_it() {
    let (_device, _, port) = serve_tcp(&["--slave", "17", "--slave", "18"]);
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("configuration.yaml");
    std::fs::write(
        &path,
        format!(
            "modbus:\n  - name: station\n    type: tcp\n    host: 127.0.0.1\n    port: {port}\n    sensors:\n      - {{name: speed, slave: 17, address: 107, scan_interval: 1}}\n      - {{name: flow, slave: 17, address: 109, scan_interval: 1}}\n      - {{name: other, slave: 18, address: 107, scan_interval: 2}}\n      - {{name: never, slave: 18, address: 108, scan_interval: 0}}\n      - {{name: level, slave: 18, address: 108}}\n"
        ),
    )
    .unwrap();
    let (code, rows, stderr) = json_rows(&[path.to_str().unwrap(), "--for", "2500ms"]);
    assert_eq!(code, 0, "{stderr}");
    let counted = |device: &str| rows_of(&rows, device).len();
    assert!((2..=4).contains(&counted("station/17")), "{rows:?}");
    assert!((1..=2).contains(&counted("station/18/2s")), "{rows:?}");
    assert_eq!(counted("station/18/15s"), 1, "{rows:?}");
    let first = rows_of(&rows, "station/17")[0];
    assert_eq!(
        first["values"],
        serde_json::json!({"speed": 555, "flow": 100})
    );
    assert_eq!(
        rows_of(&rows, "station/18/15s")[0]["values"],
        serde_json::json!({"level": 0})
    );
    assert!(
        rows.iter().all(|row| row["values"].get("never").is_none()),
        "{rows:?}"
    );
}

/// A register map given as a plant, or a plant with nothing to poll, is refused at once
/// rather than polled for ever.
#[test]
fn a_map_or_an_empty_plant_is_refused() {
    let (dir, _) = plant(&[]);
    let path = dir.path().join("empty.yaml");
    std::fs::write(&path, "devices: []\n").unwrap();
    let path = path.display().to_string();
    for (file, said) in [
        (
            "examples/sim.csv",
            "mbtool: examples/sim.csv is a register map, not a plant",
        ),
        (path.as_str(), "mbtool: the plant has no device to poll"),
    ] {
        let started = Instant::now();
        let output = mbtool().args(["poll", file]).output().unwrap();
        assert!(started.elapsed() < Duration::from_secs(5));
        assert_eq!(output.status.code(), Some(2), "{file}");
        assert!(
            String::from_utf8_lossy(&output.stderr).starts_with(said),
            "{output:?}"
        );
    }
}

/// The systemd unit of docs/ is one systemd reads without a fault (where
/// systemd-analyze is), and its command line one mbtool takes: run on a plant that is not
/// there, it is told so, not refused as a usage.
#[test]
fn the_systemd_unit_of_the_docs_is_sound() {
    let unit = std::fs::read_to_string("docs/systemd/mbtool-poll.service").unwrap();
    let binary = assert_cmd::cargo::cargo_bin("mbtool");
    let command: String = unit
        .split("ExecStart=")
        .nth(1)
        .unwrap()
        .split("\nEnvironmentFile")
        .next()
        .unwrap()
        .replace("\\\n", " ");
    let words: Vec<&str> = command.split_whitespace().collect();
    assert_eq!(words[..2], ["/usr/local/bin/mbtool", "poll"]);
    let output = mbtool()
        .args(&words[1..])
        .env_remove("MBTOOL_MQTT_PASSWORD")
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&output.stderr),
        "mbtool: cannot read /etc/mbtool/plant.yaml: No such file or directory (os error 2)\n"
    );
    if !crate::support::command_exists("systemd-analyze") {
        return eprintln!("skipped: systemd-analyze is not installed");
    }
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("mbtool-poll.service");
    let here = unit.replace("/usr/local/bin/mbtool", &binary.display().to_string());
    std::fs::write(&path, here).unwrap();
    let verified = Process::new("systemd-analyze")
        .args(["verify", "--man=no"])
        .arg(&path)
        .output()
        .unwrap();
    assert!(
        verified.status.success() && verified.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&verified.stderr)
    );
}

/// `--log` appends the rows to several files at once, CSV and JSON Lines, the same rows as
/// standard output; a CSV appended to keeps its columns; a file that cannot be written
/// (a full disk) is told once, its rows counted, and the polling goes on.
#[test]
fn rows_are_logged_to_several_files_and_a_full_disk_stops_no_poll() {
    let (dir, path) = plant(&[device("pump", "sim", 17, "100ms")]);
    let csv = dir.path().join("rows.csv");
    let jsonl = dir.path().join("rows.jsonl");
    let logs = [
        "--log",
        csv.to_str().unwrap(),
        "--log",
        jsonl.to_str().unwrap(),
    ];
    let (code, rows, stderr) = json_rows(&[&[path.as_str(), "--for", "450ms"][..], &logs].concat());
    assert_eq!(code, 0, "{stderr}");
    let logged: Vec<serde_json::Value> = std::fs::read_to_string(&jsonl)
        .unwrap()
        .lines()
        .map(|line| serde_json::from_str(line).unwrap())
        .collect();
    assert_eq!(logged, rows);
    let (code, more, _) = json_rows(&[&[path.as_str(), "--for", "250ms"][..], &logs].concat());
    assert_eq!(code, 0);
    let csv_text = std::fs::read_to_string(&csv).unwrap();
    let lines: Vec<&str> = csv_text.lines().collect();
    assert_eq!(lines[0], "time,device,speed,level,flow,error");
    assert_eq!(lines.len(), 1 + rows.len() + more.len(), "{csv_text}");
    for (line, row) in lines[1..].iter().zip(rows.iter().chain(&more)) {
        assert_eq!(
            *line,
            format!("{},pump,555,0,100,", row["time"].as_str().unwrap())
        );
    }
    // A CSV of other columns is not appended to.
    std::fs::write(&csv, "time,device,volts,error\n").unwrap();
    let output = mbtool()
        .args(["poll", &path, "--log"])
        .arg(&csv)
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&output.stderr).contains("has other columns (time,device,volts,error) than this plant's (time,device,speed,level,flow,error): give a new file to --log"));
    if !std::path::Path::new("/dev/full").exists() {
        return eprintln!("skipped: no /dev/full on this system");
    }
    let (code, rows, stderr) = json_rows(&[
        &path,
        "--for",
        "450ms",
        "--log",
        "/dev/full",
        "--log",
        jsonl.to_str().unwrap(),
    ]);
    assert!(rows.len() >= 4, "{stderr}");
    assert_eq!(code, 1, "{stderr}");
    assert_eq!(
        stderr
            .matches("cannot write /dev/full: No space left on device")
            .count(),
        1,
        "{stderr}"
    );
    assert!(
        stderr.contains(&format!("mbtool: /dev/full: {} rows not saved", rows.len())),
        "{stderr}"
    );
}

/// The faults of several files at once: a device whose name another file has, even with
/// faults of its own; a file given twice; a device with an empty list of points.
#[test]
fn the_faults_of_several_files_are_told_together() {
    let (dir, first) = plant(&[device("b", "sim", 17, "1s")]);
    let second = dir.path().join("more.toml");
    std::fs::write(
        &second,
        "[[devices]]\nname = \"b\"\nport = \"sim\"\nslave = 1\nevery = \"1s\"\npoints = [{ name = \"x\", ref = \"400001\", access = \"rwx\" }]\n\n[[devices]]\nname = \"e\"\nport = \"sim\"\nslave = 1\nevery = \"1s\"\npoints = []\n",
    )
    .unwrap();
    let second = second.display().to_string();
    let output = mbtool()
        .args(["poll", &first, &second, &first])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&output.stderr),
        format!(
            "mbtool: {second}:6: access 'rwx': give r or rw\nmbtool: {second}:13: e: points: give at least one point\nmbtool: {second}:1: the name 'b' is taken already, by a device of {first}:2\nmbtool: {first} is given twice: give each plant file once\n"
        )
    );
}
