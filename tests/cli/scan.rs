//! `mbtool scan` finding slaves: `serve` with several ids on a pseudo-terminal and on TCP,
//! a slave that answers only at its own serial settings, a bus heard without a byte
//! sent, and a TCP device that answers every unit id.

use std::io::{BufRead, BufReader, Read, Write};
use std::process::{Command as Process, Stdio};
use std::time::Duration;

use crate::support::{
    command_exists, mbtool, peer_available, pymodbus_tcp, scripted_tcp_device, serve_pty,
    serve_tcp, Act, PtyPair, Stopped, Terminal,
};

struct Scan {
    code: i32,
    stdout: String,
    stderr: String,
}

fn scan(port: &[String], args: &[&str]) -> Scan {
    let output = mbtool().args(port).arg("scan").args(args).output().unwrap();
    Scan {
        code: output.status.code().unwrap_or(-1),
        stdout: String::from_utf8_lossy(&output.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&output.stderr).into_owned(),
    }
}

fn json_lines(text: &str) -> Vec<serde_json::Value> {
    text.lines()
        .map(|line| serde_json::from_str(line).unwrap())
        .collect()
}

#[test]
fn scan_finds_every_slave_on_a_serial_line() {
    let Some(pair) = PtyPair::new() else { return };
    let (_server, port) = serve_pty(&pair, &["--slave", "3", "--slave", "17", "--slave", "200"]);
    let run = scan(&port, &["--timeout", "20ms", "--json"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let found: Vec<(u64, bool)> = json_lines(&run.stdout)
        .iter()
        .map(|line| {
            assert_eq!(line["answer"], "ok", "{line}");
            assert_eq!(
                (line["baud"].as_u64(), line["parity"].as_str()),
                (Some(19200), Some("even"))
            );
            (line["slave"].as_u64().unwrap(), line["confirmed"] == true)
        })
        .collect();
    assert_eq!(found, [(3, true), (17, true), (200, true)]);
    // A pty carries any setting: what answered was tried, not found, and that is said.
    assert!(
        run.stderr.contains(
            "is a pseudo-terminal, which carries any baud and parity: the settings shown were tried, not found"
        ),
        "{}",
        run.stderr
    );
    assert!(
        run.stderr
            .contains("3 slaves found: 3, 17, 200 at 19200 baud, even parity; 1 setting tried"),
        "{}",
        run.stderr
    );

    let table = scan(&port, &["--timeout", "20ms", "--ids", "1-20"]);
    assert_eq!(table.code, 0);
    let row: Vec<&str> = table
        .stdout
        .lines()
        .find(|line| line.contains(" 17 "))
        .map(|line| line.split(['│', '┆']).map(str::trim).collect())
        .unwrap_or_default();
    assert_eq!(
        row,
        ["", "17", "19200 baud, even parity", "ok", "yes", ""],
        "{}",
        table.stdout
    );
    // 200 is past --ids.
    assert!(!table.stdout.contains("│ 200 "), "{}", table.stdout);
}

#[test]
fn scan_finds_nothing_and_exits_3() {
    let Some(pair) = PtyPair::new() else { return };
    let (_server, port) = serve_pty(&pair, &[]);
    let run = scan(&port, &["--timeout", "20ms", "--ids", "1-5,18"]);
    assert_eq!(run.code, 3, "{}", run.stderr);
    assert_eq!(run.stdout, "");
    assert!(
        run.stderr
            .contains("no slave found; 1 setting tried, 6 requests"),
        "{}",
        run.stderr
    );
}

#[test]
fn scan_over_tcp_finds_the_unit_ids_served() {
    let (_server, port, _) = serve_tcp(&["--slave", "5", "--slave", "9"]);
    let run = scan(&port, &["--json"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let slaves: Vec<u64> = json_lines(&run.stdout)
        .iter()
        .map(|line| line["slave"].as_u64().unwrap())
        .collect();
    // The other ids get exception 0B, a gateway's "no such device": absent.
    assert_eq!(slaves, [5, 9]);
}

/// A TCP device that answers a read of one register for the unit ids `answers` says yes
/// to, and closes the connection on the others.
fn scripted_device(answers: fn(u8) -> bool) -> u16 {
    scripted_tcp_device(move |unit, _| match answers(unit) {
        true => Act::Answer(vec![0x03, 2, 0, 42]),
        false => Act::Close,
    })
}

#[test]
fn a_device_that_answers_every_unit_id_is_one_device() {
    let tcp = scripted_device(|_| true);
    let port = vec!["--port".to_string(), format!("127.0.0.1:{tcp}")];
    let run = scan(&port, &["--ids", "1-10"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(
        run.stdout,
        "every id answered (ok): the device does not tell unit ids apart\n"
    );
    let json = scan(&port, &["--ids", "1-10", "--json"]);
    assert_eq!(json_lines(&json.stdout)[0]["ignores_unit_id"], true);
    // Whatever the range, the whole of it included, and whatever values it returns.
    let counting = std::sync::atomic::AtomicU16::new(0);
    let tcp = scripted_tcp_device(move |unit, _| {
        let value = counting.fetch_add(unit.into(), std::sync::atomic::Ordering::SeqCst);
        let [hi, lo] = value.to_be_bytes();
        Act::Answer(vec![0x03, 2, hi, lo])
    });
    let counting_port = vec!["--port".to_string(), format!("127.0.0.1:{tcp}")];
    for (port, range) in [
        (&port, None),
        (&port, Some("0-255")),
        (&port, Some("1-254")),
        (&counting_port, None),
        (&counting_port, Some("200-247")),
    ] {
        let args: Vec<&str> = match range {
            Some(range) => vec!["--ids", range],
            None => vec![],
        };
        let run = scan(port, &args);
        assert_eq!(run.code, 0, "{range:?}: {}", run.stderr);
        assert_eq!(
            run.stdout, "every id answered (ok): the device does not tell unit ids apart\n",
            "{range:?}"
        );
        assert!(
            run.stderr
                .contains("one device, answering every unit id alike"),
            "{range:?}: {}",
            run.stderr
        );
    }
    // Two slaves that both exist are two slaves: an id outside the scan tells them apart.
    let (_server, served, _) = serve_tcp(&["--slave", "3", "--slave", "17"]);
    let both = scan(&served, &["--ids", "3,17", "-o", "values"]);
    assert_eq!(both.stdout, "3\n17\n");
}

#[test]
fn a_device_that_closes_on_an_unknown_unit_id_is_scanned_to_the_end() {
    let tcp = scripted_device(|id| id == 4);
    let port = vec!["--port".to_string(), format!("127.0.0.1:{tcp}")];
    let run = scan(&port, &["--ids", "1-6", "-o", "values"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(run.stdout, "4\n");
    assert!(
        run.stderr
            .contains("the device closed the connection after unit id 1 (5 times in all)"),
        "{}",
        run.stderr
    );
}

#[test]
fn pymodbus_answering_every_unit_id_is_one_device_with_one_real_id() {
    let Some((_slave, port)) = pymodbus_tcp(&[]) else {
        return;
    };
    // pymodbus refuses the unit ids it lacks with exception 04 rather than staying
    // silent: only slave 17 answers otherwise.
    let run = scan(&port, &["--ids", "1-30", "--json"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let lines = json_lines(&run.stdout);
    assert_eq!(lines.len(), 2, "{}", run.stdout);
    assert_eq!(lines[0]["ignores_unit_id"], true);
    assert_eq!(lines[0]["exception"], 4);
    assert_eq!(
        (&lines[1]["slave"], &lines[1]["answer"]),
        (&serde_json::json!(17), &serde_json::json!("ok"))
    );
}

#[test]
fn the_sweep_finds_the_settings_a_slave_answers_at() {
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/peers/picky_slave.py");
    let mut child = Process::new("python3")
        .args([script, "--id", "17", "--baud", "38400", "--parity", "odd"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let stdout = child.stdout.take().unwrap();
    let _slave = Stopped(child);
    let mut path = String::new();
    BufReader::new(stdout).read_line(&mut path).unwrap();
    let port = vec!["--port".to_string(), path.trim().to_string()];
    let run = scan(
        &port,
        &[
            "--baud",
            "9600,19200,38400",
            "--parity",
            "none,even,odd",
            "--ids",
            "16-18",
            "--timeout",
            "30ms",
            "--json",
        ],
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    let found = json_lines(&run.stdout);
    assert_eq!(found.len(), 1, "{}", run.stdout);
    assert_eq!(
        (&found[0]["slave"], &found[0]["baud"], &found[0]["parity"]),
        (
            &serde_json::json!(17),
            &serde_json::json!(38400),
            &serde_json::json!("odd")
        )
    );
    // 38400 odd comes last of the nine: every setting was tried, and it stopped there.
    assert!(run.stderr.contains("9 settings tried"), "{}", run.stderr);
}

#[test]
fn listening_finds_the_slaves_of_a_busy_bus_without_a_byte_sent() {
    let Some(pair) = PtyPair::new() else { return };
    let capture = std::fs::read(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/captures/brainchild-io-16do.bin"
    ))
    .unwrap();
    let mut bus = serialport::new(pair.a.display().to_string(), 19200)
        .timeout(Duration::from_millis(300))
        .open_native()
        .unwrap();
    let writer = std::thread::spawn(move || {
        std::thread::sleep(Duration::from_millis(300));
        // The capture as the line carried it: in pieces, with pauses between them.
        for piece in capture.chunks(8) {
            bus.write_all(piece).unwrap();
            std::thread::sleep(Duration::from_millis(4));
        }
        bus
    });
    let output = mbtool()
        .args(["--port", &pair.b.display().to_string()])
        .args(["scan", "--listen", "1500ms", "--json"])
        .timeout(Duration::from_secs(60))
        .output()
        .unwrap();
    let mut bus = writer.join().unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert_eq!(output.status.code(), Some(0), "{output:?}");
    let found = json_lines(&stdout);
    assert_eq!(found.len(), 1, "{stdout}");
    assert_eq!(found[0]["slave"], 1);
    assert_eq!(found[0]["answer"], "heard");
    // Nothing came back on the bus.
    let mut sent = [0u8; 64];
    let read = bus.read(&mut sent);
    assert!(
        matches!(&read, Err(e) if e.kind() == std::io::ErrorKind::TimedOut),
        "the scan sent {read:?}"
    );
}

#[test]
fn a_terminal_shows_the_scan_progress() {
    let Some(pair) = PtyPair::new() else { return };
    let (_server, port) = serve_pty(&pair, &[]);
    let args = format!("{} scan --timeout 40ms", port.join(" "));
    let Some(terminal) = Terminal::run(&args, 100, 20) else {
        return;
    };
    // While it runs: ids asked of 247, the slave found, the time left.
    let screen = terminal.wait_for(Duration::from_secs(20), |screen| {
        screen
            .iter()
            .any(|line| line.contains("ids asked, 1 found"))
    });
    let bar = screen
        .iter()
        .find(|line| line.contains("ids asked"))
        .unwrap_or_else(|| panic!("no progress bar: {screen:#?}"));
    assert!(bar.contains("/247 ids asked, 1 found, "), "{bar}");
    assert!(bar.trim_end().ends_with(" left"), "{bar}");
    // At the end the bar is gone and the table and the summary stay.
    let screen = terminal.wait_for(Duration::from_secs(30), |_| terminal.done());
    assert!(
        !screen.iter().any(|line| line.contains("ids asked")),
        "{screen:#?}"
    );
    assert!(
        screen
            .iter()
            .any(|line| line.contains("1 slave found: 17 at 19200 baud")),
        "{screen:#?}"
    );
}

#[test]
fn listening_over_tcp_is_refused_before_anything_is_sent() {
    let output = mbtool()
        .args(["--port", "tcp://127.0.0.1:1", "scan", "--listen", "1s"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&output.stderr)
        .starts_with("mbtool: --listen hears other masters on a serial line"));
}

#[test]
fn bytes_that_are_no_answer_are_something_at_other_settings() {
    // Unit id 2 answers a read of holding registers as if it were one of input registers.
    let tcp = scripted_tcp_device(|unit, _| match unit {
        2 => Act::Answer(vec![0x04, 2, 0, 1]),
        _ => Act::Answer(vec![0x83, 0x0B]),
    });
    let port = vec!["--port".to_string(), format!("127.0.0.1:{tcp}")];
    let run = scan(&port, &["--ids", "1-3"]);
    assert_eq!(run.code, 3, "{}", run.stderr);
    assert!(
        run.stderr
            .contains("mbtool: id 2 at TCP: something answered, maybe at other settings (answer is for function 04, the request was 03)"),
        "{}",
        run.stderr
    );
}

/// `tests/peers/busy_line.py` playing `slaves` on a pty; the port options for it.
fn busy_line(slaves: &[&str]) -> Option<(Stopped, Vec<String>)> {
    if !peer_available("python3", command_exists("python3")) {
        return None;
    }
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/peers/busy_line.py");
    let mut child = Process::new("python3")
        .arg(script)
        .args(slaves)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let stdout = child.stdout.take().unwrap();
    let line = Stopped(child);
    let mut path = String::new();
    BufReader::new(stdout).read_line(&mut path).unwrap();
    Some((line, vec!["--port".to_string(), path.trim().to_string()]))
}

#[test]
fn a_late_answer_is_its_own_slave_and_never_another_ids() {
    // The late slave's answer lands while the next id, or the one after, is asked, or
    // after the last id; another answers with a broken CRC at first; one says 02.
    for late in ["late:150", "late:300"] {
        let nine = format!("9={late}");
        let last = format!("16={late}");
        let slaves = ["3=now", &nine, "12=badcrc:1", "14=exception:2", &last];
        let Some((_line, port)) = busy_line(&slaves) else {
            return;
        };
        let run = scan(&port, &["--ids", "1-16", "--json"]);
        assert_eq!(run.code, 0, "{}", run.stderr);
        let found: Vec<(u64, String, bool, bool)> = json_lines(&run.stdout)
            .iter()
            .map(|line| {
                (
                    line["slave"].as_u64().unwrap(),
                    line["answer"].as_str().unwrap().to_string(),
                    line["confirmed"].as_bool().unwrap(),
                    line["late"].as_bool().unwrap(),
                )
            })
            .collect();
        let mut ids: Vec<u64> = found.iter().map(|hit| hit.0).collect();
        ids.sort_unstable();
        assert_eq!(
            ids,
            [3, 9, 12, 14, 16],
            "{late}: {}{}",
            run.stdout,
            run.stderr
        );
        for (slave, answer, confirmed, is_late) in found {
            assert!(confirmed, "{slave}: {}", run.stdout);
            assert_eq!(
                is_late,
                slave == 9 || slave == 16,
                "{slave}: {}",
                run.stdout
            );
            let expected = if slave == 14 { "exception" } else { "ok" };
            assert_eq!(answer, expected, "{slave}");
        }
        // Nothing is blamed on an id that did not answer.
        assert!(!run.stderr.contains("something answered"), "{}", run.stderr);
        assert!(
            run.stderr
                .contains("mbtool: slaves 9, 16 answered after the scan's timeout of"),
            "{}",
            run.stderr
        );
    }
}

/// The last id of a scan answering well after a short timeout is still found, as late.
#[test]
fn the_last_ids_late_answer_is_heard_after_a_short_timeout() {
    let Some((_line, port)) = busy_line(&["30=late:450"]) else {
        return;
    };
    let run = scan(&port, &["--ids", "25-30", "--timeout", "50ms", "--json"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let found: Vec<(u64, bool)> = json_lines(&run.stdout)
        .iter()
        .map(|line| (line["slave"].as_u64().unwrap(), line["late"] == true))
        .collect();
    assert_eq!(found, [(30, true)], "{}", run.stderr);
}
