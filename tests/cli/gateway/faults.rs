//! The gateway at its edges: clients that leave, broadcasts, lines that fail, slaves that stall, thousands of clients

use super::*;

#[test]
fn a_client_that_leaves_mid_transaction_does_not_put_the_line_out_of_step() {
    let Some(pair) = PtyPair::new() else { return };
    // Not through `serve_pty`, whose first reads would leave late answers on the line.
    let _slave = serve(&["--port", pair.a.to_str().unwrap(), "--delay", "300ms"]);
    std::thread::sleep(Duration::from_millis(300));
    let gateway = Gateway::start(&["--port", pair.b.to_str().unwrap(), "-o", "json"]);
    let mut leaving = gateway.client();
    leaving
        .write_all(&mbap(1, 17, &read_holding(107, 1)))
        .unwrap();
    std::thread::sleep(Duration::from_millis(100));
    drop(leaving);
    let mut staying = gateway.client();
    for id in 0..3 {
        assert_eq!(
            ask(&mut staying, id, 17, &read_holding(108, 1)).1,
            [3, 2, 0, 0]
        );
    }
    let (_, stdout, _) = gateway.stop();
    let rows = rows(&stdout);
    // Its answer was read off the line (and written to a socket no one reads).
    assert_eq!(rows[0]["outcome"], "answer", "{stdout}");
    assert!(rows[1..].iter().all(|row| row["outcome"] == "answer"));
}

#[test]
fn a_client_that_closes_its_sending_side_still_gets_its_answers() {
    let Some(pair) = PtyPair::new() else { return };
    let (_slave, gateway) = gateway_to_serve(&pair, &[], &["-q"]);
    let mut client = gateway.client();
    let asked: Vec<u8> = (0..3u16)
        .flat_map(|id| mbap(id, 17, &read_holding(107 + id, 1)))
        .collect();
    // As `nc -N` or a script's `shutdown(SHUT_WR)` does.
    client.write_all(&asked).unwrap();
    client.shutdown(std::net::Shutdown::Write).unwrap();
    let answers: Vec<_> = std::iter::from_fn(|| answer(&mut client)).collect();
    assert_eq!(
        answers,
        [
            (0, 17, vec![3, 2, 2, 0x2B]),
            (1, 17, vec![3, 2, 0, 0]),
            (2, 17, vec![3, 2, 0, 0x64]),
        ]
    );
}

#[test]
fn a_broadcast_is_carried_out_and_answered_only_when_asked_to() {
    let Some(pair) = PtyPair::new() else { return };
    let (_slave, gateway) = gateway_to_serve(&pair, &[], &["-q"]);
    let mut client = gateway.client();
    client
        .set_read_timeout(Some(Duration::from_millis(500)))
        .unwrap();
    client
        .write_all(&mbap(1, 0, &write_register(3, 4711)))
        .unwrap();
    assert!(answer(&mut client).is_none(), "a broadcast got an answer");
    assert_eq!(values_of(&gateway.master(), "read-holding 17 3"), ["4711"]);
    drop(gateway);

    let Some(pair) = PtyPair::new() else { return };
    let (_slave, gateway) = gateway_to_serve(&pair, &[], &["-q", "--broadcast-reply"]);
    let mut client = gateway.client();
    assert_eq!(
        ask(&mut client, 2, 0, &write_register(3, 42)),
        (0, write_register(3, 42))
    );
    // No slave may answer a read sent to all: refused, not sent.
    assert_eq!(
        ask(&mut client, 3, 0, &read_holding(3, 1)),
        (0, vec![0x83, 1])
    );
    assert_eq!(values_of(&gateway.master(), "read-holding 17 3"), ["42"]);
}

#[test]
fn an_answer_there_at_once_is_passed_on_at_once() {
    let Some(pair) = PtyPair::new() else { return };
    let (_slave, gateway) = gateway_to_serve(&pair, &[], &["-q", "--timeout", "5s"]);
    let mut client = gateway.client();
    for id in 0..5 {
        let asked = Instant::now();
        assert_eq!(
            ask(&mut client, id, 17, &read_holding(107, 1)).1,
            [3, 2, 2, 0x2B]
        );
        assert!(
            asked.elapsed() < Duration::from_secs(1),
            "{:?}",
            asked.elapsed()
        );
    }
}

#[test]
fn a_line_that_cannot_be_opened_gives_0a_and_says_why() {
    let gateway = Gateway::start(&["--port", "/dev/ttyNOSUCH0", "-q"]);
    let mut client = gateway.client();
    let asked = Instant::now();
    assert_eq!(ask(&mut client, 1, 17, &read_holding(0, 1)).1, [0x83, 0x0A]);
    assert!(asked.elapsed() < Duration::from_secs(1));
    let (status, _, messages) = gateway.stop();
    assert_eq!(status, 0);
    assert!(
        messages.contains("line down: cannot open /dev/ttyNOSUCH0"),
        "{messages}"
    );
}

#[test]
fn a_gateway_to_a_tcp_server_listens_twice_shows_the_traffic_and_logs_it() {
    let (_server, port, _) = crate::support::serve_tcp(&[]);
    let (second, dir) = (free_port(), tempfile::tempdir().unwrap());
    let log = dir.path().join("gateway.csv");
    let also = format!("tcp://127.0.0.1:{second}");
    let gateway = Gateway::start(&[
        &port[0],
        &port[1],
        "-o",
        "csv",
        "--listen",
        &also,
        "--log",
        log.to_str().unwrap(),
    ]);
    assert_eq!(
        values_of(&gateway.master(), "read-holding 17 400108 3"),
        ["555", "0", "100"]
    );
    let through_second = ["--port".to_string(), format!("127.0.0.1:{second}")];
    assert_eq!(
        values_of(&through_second, "read-holding 17 400110"),
        ["100"]
    );
    let (status, stdout, _) = gateway.stop();
    assert_eq!(status, 0);
    let lines: Vec<&str> = stdout.lines().collect();
    assert!(
        lines[0].starts_with("time,client,unit,slave,transaction,function,request,answer"),
        "{stdout}"
    );
    assert!(
        lines[1].contains(",17,17,") && lines[1].contains("400108 = 555 0 100"),
        "{stdout}"
    );
    assert_eq!(lines.len(), 3, "{stdout}");
    // The log holds the same rows as the screen, its header once.
    assert_eq!(std::fs::read_to_string(&log).unwrap(), stdout);
}

#[test]
fn the_command_line_is_checked_before_anything_listens() {
    let refused = |args: &[&str], message: &str| {
        let output = mbtool_process().arg("gateway").args(args).output().unwrap();
        assert_eq!(output.status.code(), Some(2), "{args:?}");
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(stderr.contains(message), "{args:?}: {stderr}");
    };
    refused(&["--port", "/dev/ttyUSB0"], "--listen");
    refused(&["--listen", "tcp://127.0.0.1:0"], "gateway needs --port");
    refused(
        &[
            "--listen",
            "rtu+tcp://127.0.0.1:1502",
            "--port",
            "/dev/ttyUSB0",
        ],
        "give tcp://ADDRESS[:PORT]",
    );
    refused(
        &[
            "--listen",
            "tcp://127.0.0.1:0",
            "--port",
            "/dev/x",
            "--unit-map",
            "1=300",
        ],
        "the slave id is 0-255",
    );
}

#[test]
fn a_slave_that_stalls_never_hands_a_client_another_requests_answer() {
    let Some(pair) = PtyPair::new() else { return };
    let (slave, gateway) = gateway_to_serve(&pair, &[], &["-q", "--timeout", "150ms"]);
    // The slave stops for 300 ms of every 600 and then answers everything it missed, late:
    // answers to requests the gateway has given up on, of the same shape as the next.
    let pid = slave.0.id().to_string();
    let until = Instant::now() + Duration::from_secs(4);
    let staller = std::thread::spawn(move || {
        while Instant::now() < until {
            std::thread::sleep(Duration::from_millis(300));
            Process::new("kill").args(["-STOP", &pid]).status().unwrap();
            std::thread::sleep(Duration::from_millis(300));
            Process::new("kill").args(["-CONT", &pid]).status().unwrap();
        }
    });
    // Three clients read one register each, of the same shape: 555, 0 and 100.
    let clients: Vec<_> = [(107u16, 555u16), (108, 0), (109, 100)]
        .into_iter()
        .map(|(address, value)| {
            let mut client = gateway.client();
            std::thread::spawn(move || {
                let (mut right, mut wrong, mut refused) = (0, 0, 0);
                let mut id = 0u16;
                while Instant::now() < until {
                    id = id.wrapping_add(1);
                    match ask(&mut client, id, 17, &read_holding(address, 1)).1[..] {
                        [3, 2, high, low] if u16::from_be_bytes([high, low]) == value => right += 1,
                        [0x83, 0x0B] => refused += 1,
                        ref other => {
                            wrong += 1;
                            eprintln!("{address}: {other:02X?}");
                        }
                    }
                }
                (right, wrong, refused)
            })
        })
        .collect();
    let counts: Vec<(u32, u32, u32)> = clients.into_iter().map(|c| c.join().unwrap()).collect();
    staller.join().unwrap();
    let wrong: u32 = counts.iter().map(|c| c.1).sum();
    assert_eq!(wrong, 0, "answers that were not the request's: {counts:?}");
    // The stalls cost time, not service: every client got its own values in between.
    assert!(counts.iter().all(|c| c.0 >= 10), "{counts:?}");
    assert!(
        counts.iter().any(|c| c.2 > 0),
        "no stall was seen: {counts:?}"
    );
}

#[test]
fn thousands_of_clients_come_and_go_and_nothing_grows() {
    if !std::path::Path::new("/proc/self/status").exists() {
        eprintln!("skipped: no /proc to read a process's memory and descriptors from");
        return;
    }
    let gateway = Gateway::start(&["--port", "sim", "-o", "json"]);
    let samples = churn(&gateway, 6, 500);
    let (first, last) = (samples[1], samples[samples.len() - 1]);
    // Memory settles after the first rounds; 2,000 more clients leave it where it was.
    assert!(
        last.0 <= first.0 + 1024,
        "resident memory grew from {} KiB to {} KiB: {samples:?}",
        first.0,
        last.0
    );
    // Every client's descriptor and thread are given back.
    assert!(last.1 <= first.1, "descriptors: {samples:?}");
    assert!(last.2 <= first.2, "threads: {samples:?}");
    let (_, stdout, _) = gateway.stop();
    let summary: Vec<serde_json::Value> = stdout
        .lines()
        .filter(|line| line.contains("\"summary\""))
        .map(|line| serde_json::from_str(line).unwrap())
        .collect();
    // A row for each of the last 32 clients and one for the rest, and the unit's: all
    // 3,000 requests counted.
    assert_eq!(summary.len(), 32 + 1 + 1, "{stdout}");
    let earlier = summary
        .iter()
        .find(|row| row["summary"] == "earlier_clients")
        .unwrap();
    assert_eq!(earlier["clients"], 3000 - 32);
    let unit = summary.iter().find(|row| row["summary"] == "unit").unwrap();
    assert_eq!(unit["requests"], 3000);
}

#[test]
fn a_first_request_whose_transaction_id_reads_as_a_tls_record_is_answered() {
    let gateway = Gateway::start(&["--port", "sim", "-q"]);
    // 0x1503 and 0x1603 begin a TLS alert and handshake record; MBAP's protocol id 00 00
    // after them is no TLS version.
    for id in [0x1503, 0x1603] {
        let mut client = gateway.client();
        assert_eq!(
            ask(&mut client, id, 17, &read_holding(107, 1)).1,
            [3, 2, 2, 0x2B]
        );
    }
    let (_, _, messages) = gateway.stop();
    assert!(!messages.contains("speaks TLS"), "{messages}");
}

/// `scan` through a gateway that waits longer for an id it lacks than the scan does: the
/// device behind it is found, and the scan says it waited as long as the gateway; mbpoll,
/// waiting its own 1 s, gets the gateway's 0B for a silent id; the start line says the
/// line's settings.
#[test]
fn a_scan_through_a_slow_gateway_finds_the_device_behind_it() {
    let Some(pair) = PtyPair::new() else { return };
    let (_slave, gateway) = gateway_to_serve(&pair, &["--slave", "17", "--slave", "5"], &["-q"]);
    assert!(
        gateway.messages().contains(" to the line on ") && gateway.messages().contains(" baud, "),
        "{}",
        gateway.messages()
    );
    let output = crate::support::mbtool()
        .args(gateway.master())
        .args(["scan", "--ids", "1-6", "-o", "json"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(0), "{stderr}");
    let found: Vec<u64> = String::from_utf8_lossy(&output.stdout)
        .lines()
        .filter_map(|line| serde_json::from_str::<serde_json::Value>(line).ok()?["slave"].as_u64())
        .collect();
    assert_eq!(found, [5], "{stderr}");
    assert!(
        stderr.contains("answers came after the timeout"),
        "{stderr}"
    );
    if peer_available("mbpoll", command_exists("mbpoll")) {
        let port = gateway.port.to_string();
        let output = Process::new("mbpoll")
            .args([
                "-m",
                "tcp",
                "-p",
                &port,
                "-a",
                "9",
                "-r",
                "1",
                "-c",
                "1",
                "-1",
                "127.0.0.1",
            ])
            .output()
            .unwrap();
        let said = format!(
            "{}{}",
            String::from_utf8_lossy(&output.stdout),
            String::from_utf8_lossy(&output.stderr)
        );
        assert!(
            said.to_ascii_lowercase()
                .contains("target device failed to respond"),
            "{said}"
        );
    }
}
