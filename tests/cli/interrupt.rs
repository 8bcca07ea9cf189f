//! Long commands ended by Ctrl-C, SIGINT, SIGTERM or SIGHUP end with what they have: scan
//! shows the slaves found so far, dump writes its file whole or not at all, and each exits
//! as a shell reports a command the signal killed, 128 + N (130, 143, 129). In a
//! real terminal (tmux) and in the background of a script, where SIGINT is ignored unless
//! the program catches it.

use std::process::{Command as Process, Output, Stdio};
use std::time::{Duration, Instant};

use crate::support::{serve_pty, PtyPair, Terminal};

/// Runs mbtool in the background of a non-interactive shell, as a script would (`&`, then
/// `wait`), sends it `signal` after `after`, and returns its output and how long it took
/// to end once signalled.
fn signalled(args: &[String], after: Duration, signal: &str) -> (Output, Duration) {
    let dir = tempfile::tempdir().unwrap();
    let pid_file = dir.path().join("pid");
    let mut child = Process::new("sh")
        .arg("-c")
        .arg(r#""$@" & echo $! > "$PID_FILE"; wait $!"#)
        .arg("sh")
        .arg(assert_cmd::cargo::cargo_bin("mbtool"))
        .args(args)
        .env("PID_FILE", &pid_file)
        .env("NO_COLOR", "1")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    std::thread::sleep(after);
    let pid = std::fs::read_to_string(&pid_file).unwrap();
    let sent = Instant::now();
    let killed = Process::new("kill")
        .args([&format!("-{signal}"), pid.trim()])
        .status()
        .unwrap();
    assert!(killed.success());
    let output = loop {
        if let Some(_status) = child.try_wait().unwrap() {
            break child.wait_with_output().unwrap();
        }
        if sent.elapsed() > Duration::from_secs(10) {
            let _ = child.kill();
            panic!("mbtool did not end on SIG{signal}");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    (output, sent.elapsed())
}

fn words(port: &[String], args: &str) -> Vec<String> {
    port.iter()
        .cloned()
        .chain(args.split(' ').map(String::from))
        .collect()
}

#[test]
fn an_interrupted_scan_shows_the_slaves_found_so_far_and_exits_128_and_the_signal() {
    let Some(pair) = PtyPair::new() else { return };
    let (_server, port) = serve_pty(&pair, &["--slave", "3", "--slave", "17"]);
    for (signal, status) in [("INT", 130), ("TERM", 143), ("HUP", 129)] {
        // 247 ids at 100 ms take 25 s; by 3 s ids 3 and 17 have been asked.
        let args = words(&port, "scan --ids 1-247 --timeout 100ms --json");
        let (output, took) = signalled(&args, Duration::from_secs(3), signal);
        let stdout = String::from_utf8_lossy(&output.stdout);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(status), "SIG{signal}: {stderr}");
        assert!(
            took < Duration::from_secs(1),
            "SIG{signal}: ended {took:?} after"
        );
        let found: Vec<u64> = stdout
            .lines()
            .map(|line| {
                serde_json::from_str::<serde_json::Value>(line).unwrap()["slave"]
                    .as_u64()
                    .unwrap()
            })
            .collect();
        assert_eq!(found, [3, 17], "SIG{signal}: {stdout}");
        assert!(
            stderr.contains("mbtool: scan interrupted; so far 2 slaves found: 3, 17"),
            "SIG{signal}: {stderr}"
        );
    }
}

#[test]
fn an_interrupted_dump_writes_no_file_and_leaves_an_older_one_as_it_was() {
    let Some(pair) = PtyPair::new() else { return };
    let (_server, port) = serve_pty(&pair, &["--delay", "50ms"]);
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("pump.txt");
    // 100 requests of 10 registers, 50 ms each: interrupted after about 20.
    let args = words(
        &port,
        &format!(
            "dump 17 400001-401000 --max-per-request 10 -o {}",
            file.display()
        ),
    );
    let (output, took) = signalled(&args, Duration::from_secs(1), "INT");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(130), "{stderr}");
    assert!(took < Duration::from_secs(1), "ended {took:?} after");
    assert!(
        stderr.contains("mbtool: dump interrupted after reading")
            && stderr.contains("nothing was written"),
        "{stderr}"
    );
    assert!(
        !file.exists(),
        "an interrupted dump left {}",
        file.display()
    );
    assert_eq!(
        std::fs::read_dir(dir.path()).unwrap().count(),
        0,
        "a partial file was left"
    );
    // A dump that was there stays whole.
    std::fs::write(&file, "# an older dump\n400001 = 7\n").unwrap();
    let (output, _) = signalled(&args, Duration::from_secs(1), "TERM");
    assert_eq!(output.status.code(), Some(143));
    assert_eq!(
        std::fs::read_to_string(&file).unwrap(),
        "# an older dump\n400001 = 7\n"
    );
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
}

#[test]
fn a_dump_or_a_restore_waiting_for_a_tcp_answer_ends_on_a_signal_not_at_its_timeout() {
    // A Modbus TCP server that takes every request and answers none, and a long timeout.
    // (On a serial line the wait goes on to its timeout: an answer still on its way would
    // be taken by the next command for its own.)
    let listener = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    let address = listener.local_addr().unwrap();
    std::thread::spawn(move || {
        for client in listener.incoming().flatten() {
            std::thread::spawn(move || {
                let mut client = client;
                let mut sink = [0u8; 256];
                while std::io::Read::read(&mut client, &mut sink).is_ok_and(|n| n > 0) {}
            });
        }
    });
    let port = vec!["--port".to_string(), format!("tcp://{address}")];
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("pump.txt");
    let args = words(
        &port,
        &format!("--timeout 5s dump 17 400001-400200 -o {}", file.display()),
    );
    for (signal, status) in [("INT", 130), ("TERM", 143)] {
        let (output, took) = signalled(&args, Duration::from_millis(500), signal);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(status), "SIG{signal}: {stderr}");
        assert!(
            took < Duration::from_secs(1),
            "SIG{signal}: ended {took:?} after"
        );
        assert!(stderr.contains("mbtool: dump interrupted"), "{stderr}");
        assert!(!file.exists());
    }
    // A restore too, its write waiting: the device may or may not have taken it.
    std::fs::write(&file, "400001 = 1 2 3\n").unwrap();
    let args = words(
        &port,
        &format!("--timeout 5s restore 17 {}", file.display()),
    );
    let (output, took) = signalled(&args, Duration::from_millis(500), "HUP");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(129), "{stderr}");
    assert!(took < Duration::from_secs(1), "ended {took:?} after");
    assert!(
        stderr.contains("mbtool: restore interrupted while request 1 of 1 waited for its answer"),
        "{stderr}"
    );
}

#[test]
fn ctrl_c_in_a_terminal_ends_a_scan_with_what_it_found() {
    let Some(pair) = PtyPair::new() else { return };
    let (_server, port) = serve_pty(&pair, &["--slave", "5", "--slave", "17"]);
    let args = format!("{} scan --ids 1-247 --timeout 100ms", port.join(" "));
    let Some(terminal) = Terminal::run(&args, 100, 30) else {
        return;
    };
    // By 3 s ids 5 and 17 have been asked, and 30 more ids are to go at the least.
    std::thread::sleep(Duration::from_secs(3));
    terminal.keys(&["C-c"]);
    let screen = terminal.wait_for(Duration::from_secs(10), |_| terminal.done());
    assert_eq!(terminal.status(), Some(130), "{screen:#?}");
    assert!(
        screen.iter().any(|line| line.contains("│ 5 ")),
        "{screen:#?}"
    );
    assert!(
        screen
            .iter()
            .any(|line| line.contains("scan interrupted; so far 2 slaves found: 5, 17")),
        "{screen:#?}"
    );
}

/// A range full of holes is halved down to them in many requests: a signal ends that too,
/// between two requests, not once the range is done.
#[test]
fn a_dump_halving_a_range_down_to_its_holes_ends_on_a_signal() {
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("sparse.txt");
    // Every other register exists: each run of 120 is halved down to single addresses.
    let lines: String = (0..120)
        .map(|i| format!("4{:05} = {i}\n", 2 * i + 1))
        .collect();
    std::fs::write(&data, lines).unwrap();
    let (_server, port, _) =
        crate::support::serve_tcp(&["--delay", "20ms", "--data", data.to_str().unwrap()]);
    let file = dir.path().join("dump.txt");
    let args = words(
        &port,
        &format!("dump 17 400001-400240 -o {}", file.display()),
    );
    let (output, took) = signalled(&args, Duration::from_secs(1), "INT");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(130), "{stderr}");
    assert!(took < Duration::from_secs(1), "ended {took:?} after");
    assert!(!file.exists());
}

/// restore stopped by a signal between two writes says how far it got and that the device
/// holds part of the file, and exits 130.
#[test]
fn an_interrupted_restore_says_the_device_holds_part_of_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("plant.txt");
    std::fs::write(&data, "400001-400040 = 7\n").unwrap();
    let (_server, port, _) = crate::support::serve_tcp(&["--delay", "50ms"]);
    let args = words(
        &port,
        &format!("--max-per-request 1 restore 17 {}", data.display()),
    );
    let (output, took) = signalled(&args, Duration::from_millis(700), "INT");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(130), "{stderr}");
    assert!(took < Duration::from_secs(1), "ended {took:?} after");
    assert!(
        stderr.contains("restore interrupted after")
            && stderr.contains("of 40")
            && stderr.contains("holds part of"),
        "{stderr}"
    );
}

/// serve in the background of a script, where SIGINT is ignored unless caught, ends on it
/// at once, exit 0: a stand-in device holds nothing to save.
#[test]
fn serve_in_the_background_ends_on_sigint() {
    let port = crate::support::free_port();
    let args = vec![
        "--port".to_string(),
        format!("tcp://127.0.0.1:{port}"),
        "serve".to_string(),
    ];
    let (output, took) = signalled(&args, Duration::from_millis(500), "INT");
    assert_eq!(output.status.code(), Some(0));
    assert!(took < Duration::from_secs(1), "ended {took:?} after");
}

#[test]
fn an_interrupted_host_sweep_shows_the_units_found_so_far() {
    let port = crate::support::free_port();
    let _server = crate::support::serve(&[
        "--port",
        &format!("tcp://127.0.4.2:{port}"),
        "--slave",
        "1",
        "--quiet",
    ]);
    crate::hosts::listening("127.0.4.2", port);
    for (signal, status) in [("INT", 130), ("TERM", 143)] {
        // 249 ids with 50 ms between two take 12 s on the first host; by 2 s its units
        // 0, 1 and 255 have answered, and the second host is not asked yet.
        let args = words(
            &[],
            &format!(
                "scan --hosts 127.0.4.2,127.0.4.3 --tcp-port {port} --parallel 1 --ids 2-246 --pause 50ms -o json"
            ),
        );
        let (output, took) = signalled(&args, Duration::from_secs(2), signal);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(status), "SIG{signal}: {stderr}");
        assert!(
            took < Duration::from_secs(1),
            "SIG{signal}: ended {took:?} after"
        );
        assert!(
            stderr.contains(
                "sweep stopped: 0 of 2 hosts asked, 1 host port asked in part (marked interrupted)"
            ),
            "{stderr}"
        );
        let rows: Vec<serde_json::Value> = String::from_utf8_lossy(&output.stdout)
            .lines()
            .map(|line| serde_json::from_str(line).unwrap())
            .collect();
        assert_eq!(rows.len(), 1, "{rows:?}");
        let units: Vec<u64> = rows[0]["units"]
            .as_array()
            .unwrap()
            .iter()
            .map(|u| u["unit"].as_u64().unwrap())
            .collect();
        assert_eq!(units, [0, 1, 255], "SIG{signal}");
        assert_eq!(rows[0]["interrupted"], true);
    }
}

#[test]
fn a_signal_ends_a_host_sweep_waiting_on_a_silent_host_at_once() {
    let dir = tempfile::tempdir().unwrap();
    let port = crate::support::free_port();
    let listener = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/peers/counting_listener.py"
    );
    let _silent = crate::support::Stopped(
        Process::new("python3")
            .args([listener, "127.0.4.9", &port.to_string()])
            .arg(dir.path().join("report.json"))
            .stdout(Stdio::null())
            .spawn()
            .unwrap(),
    );
    crate::hosts::listening("127.0.4.9", port);
    let args = words(
        &[],
        &format!("scan --hosts 127.0.4.9 --tcp-port {port} --timeout 5s -o json"),
    );
    let (output, took) = signalled(&args, Duration::from_secs(1), "INT");
    assert_eq!(output.status.code(), Some(130), "{output:?}");
    assert!(took < Duration::from_secs(1), "ended {took:?} after");
    let row: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(
        (&row["modbus"], &row["interrupted"]),
        (&false.into(), &true.into())
    );
}
