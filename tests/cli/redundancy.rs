//! Two paths to one device: a poll that changes to the secondary when the primary fails,
//! and back when the secondary fails, with `--switch-when any` and `all`.

use std::io::BufRead;
use std::process::Stdio;
use std::time::{Duration, Instant};

use serde_json::Value;

use crate::support::*;

/// `mbtool serve` of slave 17 on 127.0.0.1:`port`, its 400108 holding `value`, with
/// `faults`; returns once it listens.
fn device(port: u16, value: u16, faults: &[&str], dir: &std::path::Path) -> Stopped {
    let data = dir.join(format!("device-{port}-{value}.txt"));
    std::fs::write(&data, format!("400108 = {value}\n")).unwrap();
    let address = format!("tcp://127.0.0.1:{port}");
    let data = data.display().to_string();
    let mut args = vec!["--port", address.as_str(), "--data", data.as_str()];
    args.extend_from_slice(faults);
    let server = serve(&args);
    assert!(
        wait_for_listener(port, Duration::from_secs(10)),
        "serve did not listen on {port}"
    );
    server
}

/// The read every test polls, its rows as JSON, then `--poll`'s interval.
const POLLED: [&str; 6] = ["read-holding", "17", "400108", "-o", "json", "--poll"];

/// The JSON rows a poll printed.
fn rows_of(stdout: &[u8]) -> Vec<Value> {
    String::from_utf8_lossy(stdout)
        .lines()
        .map(|line| serde_json::from_str(line).expect("a JSON row"))
        .collect()
}

/// A poll running in the background, its JSON rows read as they come.
struct Poller {
    child: Stopped,
    rows: std::sync::mpsc::Receiver<Value>,
}

impl Poller {
    fn start(args: &[String]) -> Poller {
        let mut child = mbtool_process()
            .args(POLLED)
            .arg("100ms")
            .args(args)
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        let stdout = child.stdout.take().unwrap();
        let (send, rows) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            for line in std::io::BufReader::new(stdout).lines() {
                let Ok(line) = line else { break };
                let row = serde_json::from_str(&line).expect("a JSON row");
                if send.send(row).is_err() {
                    break;
                }
            }
        });
        Poller {
            child: Stopped(child),
            rows,
        }
    }

    /// The rows that come until one satisfies `wanted` (included), within `within`.
    fn until(&self, within: Duration, wanted: impl Fn(&Value) -> bool) -> Vec<Value> {
        let deadline = Instant::now() + within;
        let mut seen = Vec::new();
        while let Some(left) = deadline.checked_duration_since(Instant::now()) {
            let Ok(row) = self.rows.recv_timeout(left) else {
                break;
            };
            let done = wanted(&row);
            seen.push(row);
            if done {
                return seen;
            }
        }
        panic!("not seen within {within:?}; rows: {seen:#?}");
    }
}

/// The first row that tells a change of path.
fn switch_row(rows: &[Value]) -> &Value {
    rows.iter()
        .find(|row| row.get("switched").is_some())
        .unwrap_or_else(|| panic!("no switch row among {rows:#?}"))
}

fn value_of(row: &Value) -> Option<u64> {
    row["values"][0]["value"].as_u64()
}

#[test]
fn a_poll_changes_to_the_secondary_and_back_and_the_rows_keep_coming() {
    let dir = tempfile::tempdir().unwrap();
    let (primary_port, secondary_port) = (free_port(), free_port());
    let primary = device(primary_port, 555, &[], dir.path());
    let secondary = device(secondary_port, 777, &[], dir.path());
    let log = dir.path().join("poll.jsonl");
    let poller = Poller::start(&[
        format!("--port=tcp://127.0.0.1:{primary_port}"),
        format!("--secondary-port=tcp://127.0.0.1:{secondary_port}"),
        "--timeout=300ms".into(),
        format!("--log={}", log.display()),
    ]);
    poller.until(Duration::from_secs(5), |row| value_of(row) == Some(555));
    drop(primary);
    let rows = poller.until(Duration::from_secs(5), |row| value_of(row) == Some(777));
    let switch = switch_row(&rows);
    assert_eq!(switch["switched"], "secondary");
    assert!(
        switch["why"].as_str().unwrap().starts_with("disconnected"),
        "{switch}"
    );
    // No value of the primary's is shown after the switch, and no poll is lost to it.
    assert!(
        rows.iter().all(|row| row.get("error").is_none()),
        "{rows:#?}"
    );
    let _primary = device(primary_port, 555, &[], dir.path());
    poller.until(Duration::from_secs(3), |row| value_of(row) == Some(777));
    drop(secondary);
    let rows = poller.until(Duration::from_secs(5), |row| value_of(row) == Some(555));
    let back = switch_row(&rows);
    assert_eq!(back["switched"], "primary");
    drop(poller.child);
    // The log holds the same rows, the switches among them.
    let logged = std::fs::read_to_string(&log).unwrap();
    let switches: Vec<Value> = logged
        .lines()
        .map(|line| serde_json::from_str::<Value>(line).unwrap())
        .filter(|row| row.get("switched").is_some())
        .collect();
    assert_eq!(switches.len(), 2, "{logged}");
    assert_eq!(switches[0]["switched"], "secondary");
    assert_eq!(switches[1]["switched"], "primary");
}

/// The rows of `count` polls of a primary with `faults` and a healthy secondary, with the
/// switch options `switch`.
fn poll_with(faults: &[&str], switch: &[&str], count: u32) -> Vec<Value> {
    let dir = tempfile::tempdir().unwrap();
    let (primary_port, secondary_port) = (free_port(), free_port());
    let _primary = device(primary_port, 555, faults, dir.path());
    let _secondary = device(secondary_port, 777, &[], dir.path());
    let output = mbtool()
        .args(POLLED)
        .arg("10ms")
        .arg(format!("--count={count}"))
        .arg(format!("--port=tcp://127.0.0.1:{primary_port}"))
        .arg(format!("--secondary-port=tcp://127.0.0.1:{secondary_port}"))
        .args(["--timeout", "100ms"])
        .args(switch)
        .output()
        .unwrap();
    rows_of(&output.stdout)
}

#[test]
fn any_switches_on_the_first_condition_and_all_waits_for_every_one() {
    // Never answered: two timeouts are enough for any.
    let rows = poll_with(
        &["--drop", "1"],
        &[
            "--switch-on",
            "timeout:2,exception:0B",
            "--switch-when",
            "any",
        ],
        5,
    );
    let switch = rows
        .iter()
        .position(|r| r.get("switched").is_some())
        .unwrap();
    assert_eq!(rows[switch]["why"], "2 timeouts", "{rows:#?}");
    assert_eq!(rows.iter().filter(|r| r.get("error").is_some()).count(), 1);
    assert_eq!(value_of(&rows[switch + 1]), Some(777));
    // Timeouts alone are not all the conditions: the poll stays on the primary.
    let rows = poll_with(
        &["--drop", "1"],
        &[
            "--switch-on",
            "timeout:2,exception:0B",
            "--switch-when",
            "all",
        ],
        5,
    );
    assert!(
        rows.iter().all(|r| r.get("switched").is_none()),
        "{rows:#?}"
    );
    assert_eq!(rows.iter().filter(|r| r.get("error").is_some()).count(), 5);
    // Timeouts and the gateway's exception 0B since the last good answer: all hold.
    let rows = poll_with(
        &["--drop", "0.5", "--exception", "11", "--seed", "7"],
        &[
            "--switch-on",
            "timeout:2,exception:0B",
            "--switch-when",
            "all",
        ],
        12,
    );
    let switch = switch_row(&rows);
    let why = switch["why"].as_str().unwrap();
    assert!(why.contains("timeouts and exception 0B"), "{why}");
    assert_eq!(value_of(rows.last().unwrap()), Some(777));
}

#[test]
fn redundancy_options_are_checked_before_anything_is_sent() {
    let cases: [(&[&str], &str); 5] = [
        (
            &["--port", "sim", "--switch-on", "timeout:3"],
            "mbtool: --switch-on needs --secondary-port: the other path to the device",
        ),
        (
            &["--port", "sim", "--secondary-port="],
            "mbtool: --secondary-port is empty: give the other path to the device, or leave it out",
        ),
        (
            &["--port", "sim", "--secondary-port", "sim", "--switch-on", "timeout:0"],
            "mbtool: invalid value 'timeout:0' for '--switch-on <CONDITIONS>': timeout takes a count from 1 up: timeout:3",
        ),
        (
            &["--port", "sim", "--secondary-port", "sim", "--switch-on", "exception:0x99"],
            "mbtool: invalid value 'exception:0x99' for '--switch-on <CONDITIONS>': exception takes a code in hex, 01 to 7F",
        ),
        (
            &["--port", "sim", "--secondary-port", "tcp://127.0.0.1:1", "--secondary-mode", "rtu"],
            "mbtool: --secondary-port tcp://127.0.0.1:1: tcp:// carries Modbus TCP frames",
        ),
    ];
    for (args, message) in cases {
        assert_refused(&[&["read-holding", "17", "400108"], args].concat(), message);
    }
    // A primary that cannot be opened gives way to the secondary at once.
    let output = mbtool()
        .args(["read-holding", "17", "400108", "-o", "values"])
        .args(["--port", "tcp://127.0.0.1:1", "--secondary-port", "sim"])
        .output()
        .unwrap();
    assert_eq!(String::from_utf8_lossy(&output.stdout), "555\n");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.starts_with(
            "mbtool: switched to the secondary path (sim): the primary path cannot be opened"
        ),
        "{stderr}"
    );
}

#[test]
fn a_dump_goes_on_through_the_secondary() {
    let dir = tempfile::tempdir().unwrap();
    let (primary_port, secondary_port) = (free_port(), free_port());
    // The primary stops answering part way: the gateway's line is cut, say.
    let _primary = device(primary_port, 555, &["--drop", "1"], dir.path());
    let _secondary = device(secondary_port, 777, &[], dir.path());
    let file = dir.path().join("backup.txt");
    let output = mbtool()
        .args(["dump", "17", "400108"])
        .arg(format!("--port=tcp://127.0.0.1:{primary_port}"))
        .arg(format!("--secondary-port=tcp://127.0.0.1:{secondary_port}"))
        .args(["--timeout", "100ms", "-o"])
        .arg(&file)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(0), "{stderr}");
    assert!(
        stderr.contains(&format!(
            "mbtool: switched to the secondary path (tcp://127.0.0.1:{secondary_port}): 3 timeouts"
        )),
        "{stderr}"
    );
    let saved = std::fs::read_to_string(&file).unwrap();
    assert!(saved.contains("400108 = 777"), "{saved}");
    // A single read, which ends at a failure too, asks until the rule decides.
    let output = mbtool()
        .args(["read-holding", "17", "400108", "-o", "values"])
        .arg(format!("--port=tcp://127.0.0.1:{primary_port}"))
        .arg(format!("--secondary-port=tcp://127.0.0.1:{secondary_port}"))
        .args(["--timeout", "100ms", "--switch-on", "timeout:2"])
        .output()
        .unwrap();
    assert_eq!(String::from_utf8_lossy(&output.stdout), "777\n");
    // With all of the conditions needed and one of them never holding, it gives up as
    // a single path would, after asking as often as the rule counts.
    let started = Instant::now();
    let output = mbtool()
        .args(["read-holding", "17", "400108", "-o", "values"])
        .arg(format!("--port=tcp://127.0.0.1:{primary_port}"))
        .arg(format!("--secondary-port=tcp://127.0.0.1:{secondary_port}"))
        .args([
            "--timeout",
            "100ms",
            "--switch-on",
            "timeout:2,exception:0B",
            "--switch-when",
            "all",
        ])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(3));
    assert!(started.elapsed() < Duration::from_secs(2));
}

#[test]
fn with_both_paths_down_the_poll_waits_and_tells_which_one_came_back() {
    let dir = tempfile::tempdir().unwrap();
    let (primary_port, secondary_port) = (free_port(), free_port());
    let secondary = device(secondary_port, 777, &[], dir.path());
    let poller = Poller::start(&[
        format!("--port=tcp://127.0.0.1:{primary_port}"),
        format!("--secondary-port=tcp://127.0.0.1:{secondary_port}"),
        "--timeout=300ms".into(),
    ]);
    // The primary is not there: the poll starts on the secondary, and says so.
    let rows = poller.until(Duration::from_secs(5), |row| value_of(row) == Some(777));
    let first = switch_row(&rows);
    assert_eq!(first["switched"], "secondary");
    assert!(
        first["why"]
            .as_str()
            .unwrap()
            .starts_with("the primary path cannot be opened"),
        "{first}"
    );
    drop(secondary);
    poller.until(Duration::from_secs(5), |row| row.get("error").is_some());
    let _primary = device(primary_port, 555, &[], dir.path());
    let rows = poller.until(Duration::from_secs(10), |row| value_of(row) == Some(555));
    let back = switch_row(&rows);
    assert_eq!(back["switched"], "primary", "{rows:#?}");
}

#[test]
fn a_device_that_closes_idle_connections_is_no_failure_of_its_path() {
    // Each answer, then the connection closed, as a gateway closes idle ones.
    let closing = scripted_tcp_device(|_, _| Act::AnswerThenClose(vec![0x03, 0x02, 0x02, 0x2B]));
    let dir = tempfile::tempdir().unwrap();
    let secondary_port = free_port();
    let _secondary = device(secondary_port, 777, &[], dir.path());
    for secondary in [
        vec![],
        vec![format!("--secondary-port=tcp://127.0.0.1:{secondary_port}")],
    ] {
        let output = mbtool()
            .args(POLLED)
            .args(["20ms", "--count", "4"])
            .arg(format!("--port=tcp://127.0.0.1:{closing}"))
            .args(["--timeout", "5s"])
            .args(&secondary)
            .timeout(Duration::from_secs(20))
            .output()
            .unwrap();
        let rows = rows_of(&output.stdout);
        assert_eq!(rows.len(), 4, "{secondary:?}: {rows:#?}");
        assert!(
            rows.iter().all(|row| value_of(row) == Some(555)),
            "{rows:#?}"
        );
        assert_eq!(output.status.code(), Some(0));
    }
}

#[test]
fn each_path_is_told_by_its_own_port_and_line() {
    let silent = Pty::new();
    // No answer on the secondary: the timeout names the secondary and its line.
    let output = mbtool()
        .args(["read-holding", "17", "400108", "--timeout", "100ms"])
        .args([
            "--port",
            "tcp://127.0.0.1:1",
            "--secondary-port",
            &silent.path,
        ])
        .args(["--secondary-baud", "9600", "--secondary-parity", "odd"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(3));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains(&format!(
            "no answer from slave 17 within 100.00 ms on {} (RTU, 9600 baud, odd parity",
            silent.path
        )),
        "{stderr}"
    );
    // --rs485 is for the path that is a serial line, the other being TCP.
    let output = mbtool()
        .args(["read-holding", "17", "400108", "--rs485"])
        .args([
            "--port",
            "tcp://127.0.0.1:1",
            "--secondary-port",
            &silent.path,
        ])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains(&format!("{} does not support RS-485 mode", silent.path)),
        "{stderr}"
    );
    // A serial primary that refuses the RS-485 mode is a setting to correct, not a path
    // that is down: told as without a second path, nothing read through the other.
    let (_device, port, _) = serve_tcp(&[]);
    let output = mbtool()
        .args(["read-holding", "17", "400108", "--port", &silent.path])
        .args(["--secondary-port", &port[1]])
        .env("MBTOOL_RS485", "1")
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(1));
    assert_eq!(
        String::from_utf8_lossy(&output.stderr),
        format!(
            "mbtool: {} does not support RS-485 mode: try --rts-toggle\n",
            silent.path
        )
    );
    // A secondary that is not there is told when the poll starts, not when it is needed.
    let output = mbtool()
        .args(&port)
        .args([
            "read-holding",
            "17",
            "400108",
            "--poll",
            "10ms",
            "--count",
            "2",
        ])
        .args(["--secondary-port", "tcp://127.0.0.1:1", "-o", "values"])
        .output()
        .unwrap();
    assert_eq!(String::from_utf8_lossy(&output.stdout), "555\n555\n");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.starts_with("mbtool: warning: the secondary path cannot be opened now"),
        "{stderr}"
    );
}

#[test]
fn the_summary_counts_the_failure_that_made_the_change() {
    let dir = tempfile::tempdir().unwrap();
    let (primary_port, secondary_port) = (free_port(), free_port());
    let _primary = device(primary_port, 555, &["--drop", "1"], dir.path());
    let _secondary = device(secondary_port, 777, &[], dir.path());
    let output = mbtool()
        .args(POLLED)
        .args(["10ms", "--count", "3", "--timeout", "100ms"])
        .arg(format!("--port=tcp://127.0.0.1:{primary_port}"))
        .arg(format!("--secondary-port=tcp://127.0.0.1:{secondary_port}"))
        .args(["--switch-on", "timeout:2"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    // The rows say 2 timeouts before the change; so does the tally.
    assert!(
        stderr.contains("mbtool: 3 requests, 2 answers, 2 timeouts, 0 bad frames, 0 exceptions, 1 change of path;"),
        "{stderr}"
    );
}
