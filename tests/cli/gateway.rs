//! `gateway`: Modbus TCP clients bridged to a line, checked with peers we did not write
//! (mbpoll, pymodbus) and with raw MBAP clients that misbehave, on pseudo-terminals and
//! 127.0.0.1 only.

use std::io::{Read, Write};
use std::net::TcpStream;
use std::path::PathBuf;
use std::process::{Command as Process, Stdio};
use std::time::{Duration, Instant};

use crate::support::{
    command_exists, free_port, mbtool_process, peer_available, python_has, serve, serve_pty,
    values_of, wait_for_listener, PtyPair, Stopped,
};

/// A running gateway: its port, and its rows and messages in files read at the end.
struct Gateway {
    process: Stopped,
    port: u16,
    stdout: PathBuf,
    stderr: PathBuf,
    _dir: tempfile::TempDir,
}

impl Gateway {
    /// `mbtool gateway` listening on a free port of 127.0.0.1, with `args` (the line).
    fn start(args: &[&str]) -> Gateway {
        let port = free_port();
        let dir = tempfile::tempdir().unwrap();
        let (stdout, stderr) = (dir.path().join("rows"), dir.path().join("messages"));
        let child = mbtool_process()
            .args(["gateway", "--listen", &format!("tcp://127.0.0.1:{port}")])
            .args(args)
            .stdout(std::fs::File::create(&stdout).unwrap())
            .stderr(std::fs::File::create(&stderr).unwrap())
            .spawn()
            .expect("mbtool gateway starts");
        let process = Stopped(child);
        assert!(
            wait_for_listener(port, Duration::from_secs(10)),
            "the gateway did not listen"
        );
        Gateway {
            process,
            port,
            stdout,
            stderr,
            _dir: dir,
        }
    }

    /// The connection options of a master that goes through the gateway.
    fn master(&self) -> Vec<String> {
        vec!["--port".into(), format!("127.0.0.1:{}", self.port)]
    }

    fn client(&self) -> TcpStream {
        let stream = TcpStream::connect(("127.0.0.1", self.port)).unwrap();
        stream
            .set_read_timeout(Some(Duration::from_secs(10)))
            .unwrap();
        stream
    }

    fn messages(&self) -> String {
        std::fs::read_to_string(&self.stderr).unwrap()
    }

    /// Ends it with SIGTERM: (exit status, rows, messages).
    fn stop(mut self) -> (i32, String, String) {
        let pid = self.process.0.id().to_string();
        assert!(Process::new("kill")
            .args(["-TERM", &pid])
            .status()
            .unwrap()
            .success());
        let deadline = Instant::now() + Duration::from_secs(5);
        let status = loop {
            if let Some(status) = self.process.0.try_wait().unwrap() {
                break status;
            }
            assert!(Instant::now() < deadline, "SIGTERM did not end the gateway");
            std::thread::sleep(Duration::from_millis(20));
        };
        (
            status.code().unwrap_or(-1),
            std::fs::read_to_string(&self.stdout).unwrap(),
            self.messages(),
        )
    }
}

/// Sends one MBAP request and returns the answer's unit id and PDU.
fn ask(stream: &mut TcpStream, transaction: u16, unit: u8, pdu: &[u8]) -> (u8, Vec<u8>) {
    stream.write_all(&mbap(transaction, unit, pdu)).unwrap();
    let (id, unit, pdu) = answer(stream).expect("an answer");
    assert_eq!(id, transaction);
    (unit, pdu)
}

fn mbap(transaction: u16, unit: u8, pdu: &[u8]) -> Vec<u8> {
    let mut frame = transaction.to_be_bytes().to_vec();
    frame.extend([0, 0]);
    frame.extend(((pdu.len() + 1) as u16).to_be_bytes());
    frame.push(unit);
    frame.extend(pdu);
    frame
}

/// The next MBAP answer on `stream`: (transaction id, unit id, PDU); `None` when the
/// connection closed or nothing came.
fn answer(stream: &mut TcpStream) -> Option<(u16, u8, Vec<u8>)> {
    let mut header = [0u8; 7];
    stream.read_exact(&mut header).ok()?;
    let length = usize::from(u16::from_be_bytes([header[4], header[5]]));
    let mut pdu = vec![0u8; length.checked_sub(1)?];
    stream.read_exact(&mut pdu).ok()?;
    Some((u16::from_be_bytes([header[0], header[1]]), header[6], pdu))
}

/// Read holding registers: the PDU.
fn read_holding(address: u16, count: u16) -> Vec<u8> {
    let mut pdu = vec![0x03];
    pdu.extend(address.to_be_bytes());
    pdu.extend(count.to_be_bytes());
    pdu
}

fn write_register(address: u16, value: u16) -> Vec<u8> {
    let mut pdu = vec![0x06];
    pdu.extend(address.to_be_bytes());
    pdu.extend(value.to_be_bytes());
    pdu
}

/// `mbtool serve` on one end of a pty pair, and a gateway on the other end with `args`.
fn gateway_to_serve(pair: &PtyPair, serve_args: &[&str], args: &[&str]) -> (Stopped, Gateway) {
    let (server, _) = serve_pty(pair, serve_args);
    let line = pair.b.display().to_string();
    let gateway = Gateway::start(&[&["--port", line.as_str()], args].concat());
    (server, gateway)
}

/// The JSON rows the gateway printed.
fn rows(stdout: &str) -> Vec<serde_json::Value> {
    stdout
        .lines()
        .filter(|line| !line.contains("\"summary\""))
        .map(|line| serde_json::from_str(line).unwrap_or_else(|e| panic!("{e}: {line}")))
        .collect()
}

#[test]
fn pymodbus_reads_and_writes_every_function_through_it_as_on_the_line() {
    if !peer_available("pymodbus (Python)", python_has("pymodbus")) {
        return;
    }
    let script = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/peers/pymodbus_master.py"
    );
    // pymodbus's own RTU server leaves function 24 unanswered, where the gateway says 0B.
    let run = |args: &[&str]| {
        let output = Process::new("python3")
            .arg(script)
            .args(args)
            .arg("--every-function")
            .output()
            .unwrap();
        assert!(
            output.status.success(),
            "{}",
            String::from_utf8_lossy(&output.stderr)
        );
        serde_json::from_slice::<serde_json::Value>(&output.stdout).unwrap()
    };
    // The same script directly on a line, and through the gateway to a twin slave:
    // first mbtool serve, then pymodbus's own RTU server.
    let Some(direct) = PtyPair::new() else { return };
    let (_direct_slave, _) = serve_pty(&direct, &[]);
    let on_the_line = run(&[
        "--framer",
        "rtu",
        "--serial",
        &direct.b.display().to_string(),
    ]);
    assert_eq!(on_the_line["holding"], serde_json::json!([555, 0, 100]));
    assert_eq!(
        on_the_line["missing_function"],
        serde_json::json!({"exception": 1})
    );
    let Some(bridged) = PtyPair::new() else {
        return;
    };
    let (_slave, gateway) = gateway_to_serve(&bridged, &[], &["-q"]);
    let port = gateway.port.to_string();
    assert_eq!(run(&["--tcp", &port]), on_the_line);

    let slave_script = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/peers/pymodbus_slave.py");
    let pymodbus_slave = |pair: &PtyPair| {
        let slave = Stopped(
            Process::new("python3")
                .args([slave_script, "--framer", "rtu", "--serial"])
                .arg(&pair.a)
                .stdout(Stdio::null())
                .stderr(Stdio::null())
                .spawn()
                .unwrap(),
        );
        std::thread::sleep(Duration::from_millis(1500));
        slave
    };
    let Some(direct) = PtyPair::new() else { return };
    let _direct_slave = pymodbus_slave(&direct);
    let direct = direct.b.display().to_string();
    let on_the_line = run(&["--framer", "rtu", "--serial", &direct, "--skip", "fifo"]);
    assert_eq!(on_the_line["holding"], serde_json::json!([0, 0, 0]));
    let Some(bridged) = PtyPair::new() else {
        return;
    };
    let _slave = pymodbus_slave(&bridged);
    let line = bridged.b.display().to_string();
    let gateway = Gateway::start(&["--port", &line, "-q"]);
    let port = gateway.port.to_string();
    assert_eq!(run(&["--tcp", &port, "--skip", "fifo"]), on_the_line);
}

#[test]
fn mbpoll_reads_and_writes_through_it() {
    if !peer_available("mbpoll", command_exists("mbpoll")) {
        return;
    }
    let Some(pair) = PtyPair::new() else { return };
    let (_slave, gateway) = gateway_to_serve(&pair, &[], &["-q"]);
    let port = gateway.port.to_string();
    crate::serve::mbpoll_exercise(&["-m", "tcp", "-p", &port, "127.0.0.1"], &gateway.master());
}

#[test]
fn fifty_clients_at_once_each_get_their_own_answers_and_every_write_lands_once() {
    let Some(pair) = PtyPair::new() else { return };
    let (_slave, gateway) = gateway_to_serve(&pair, &[], &["-q"]);
    let clients: Vec<_> = (0..50u16)
        .map(|client| {
            let mut stream = gateway.client();
            std::thread::spawn(move || {
                // Each client counts in a register of its own and reads it back, with
                // reads of the manual's registers in between.
                let register = 1000 + client;
                for n in 0..200u16 {
                    let id = n.wrapping_mul(7).wrapping_add(client);
                    if n % 2 == 0 {
                        let (_, pdu) = ask(&mut stream, id, 17, &write_register(register, n));
                        assert_eq!(pdu, write_register(register, n), "client {client}");
                    } else {
                        let (_, pdu) = ask(&mut stream, id, 17, &read_holding(register, 1));
                        let [hi, lo] = (n - 1).to_be_bytes();
                        assert_eq!(pdu, [3, 2, hi, lo], "client {client}, request {n}");
                        let (_, pdu) = ask(&mut stream, id, 17, &read_holding(107, 3));
                        assert_eq!(pdu, [3, 6, 2, 0x2B, 0, 0, 0, 0x64]);
                    }
                }
            })
        })
        .collect();
    for client in clients {
        client.join().unwrap();
    }
    let last: Vec<String> = (0..50).map(|_| "198".to_string()).collect();
    assert_eq!(
        values_of(&gateway.master(), "read-holding 17 1000 50"),
        last
    );
    let (status, _, messages) = gateway.stop();
    assert_eq!(status, 0);
    // 50 clients x 200 requests (half of them two), and the read above.
    assert!(messages.contains("│ unit 17 "), "{messages}");
    let unit_row = messages.lines().find(|l| l.contains("unit 17")).unwrap();
    let cells: Vec<&str> = unit_row.split('┆').map(str::trim).collect();
    assert_eq!(cells[1], "15001", "{unit_row}");
    assert_eq!(cells[2], "15001", "{unit_row}");
}

#[test]
fn a_hundred_and_twenty_clients_connected_at_once_are_all_served() {
    let Some(pair) = PtyPair::new() else { return };
    let (_slave, gateway) = gateway_to_serve(&pair, &[], &["-q"]);
    let mut clients: Vec<TcpStream> = (0..120).map(|_| gateway.client()).collect();
    for (id, client) in clients.iter_mut().enumerate() {
        client
            .write_all(&mbap(id as u16, 17, &read_holding(107, 1)))
            .unwrap();
    }
    for (id, client) in clients.iter_mut().enumerate() {
        assert_eq!(
            answer(client),
            Some((id as u16, 17, vec![3, 2, 2, 0x2B])),
            "client {id}"
        );
    }
}

#[test]
fn a_client_that_pipelines_a_thousand_requests_does_not_starve_another() {
    let Some(pair) = PtyPair::new() else { return };
    let (_slave, gateway) = gateway_to_serve(&pair, &[], &["-o", "json", "--frame-gap", "0"]);
    let mut greedy = gateway.client();
    let pipelined: Vec<u8> = (1..=1000u16)
        .flat_map(|id| mbap(id, 17, &read_holding(id % 100, 1)))
        .collect();
    greedy.write_all(&pipelined).unwrap();
    let answered = std::sync::Arc::new(std::sync::atomic::AtomicU16::new(0));
    let reader = {
        let answered = std::sync::Arc::clone(&answered);
        let mut greedy = greedy.try_clone().unwrap();
        std::thread::spawn(move || {
            // Answered in the order asked.
            for id in 1..=1000u16 {
                let (got, _, pdu) = answer(&mut greedy).expect("an answer");
                assert_eq!(got, id);
                assert_eq!(pdu.len(), 4);
                answered.store(id, std::sync::atomic::Ordering::SeqCst);
            }
        })
    };
    while answered.load(std::sync::atomic::Ordering::SeqCst) < 50 {
        std::thread::sleep(Duration::from_millis(1));
    }
    let mut modest = gateway.client();
    let (_, pdu) = ask(&mut modest, 9999, 17, &read_holding(107, 1));
    assert_eq!(pdu, [3, 2, 2, 0x2B]);
    reader.join().unwrap();
    // Judged by the gateway's own clock, which a busy test machine does not skew: the
    // single request waited for the greedy client's request on the line at most, not for
    // the hundreds it still had queued.
    let (_, stdout, _) = gateway.stop();
    let rows = rows(&stdout);
    let number = |row: &serde_json::Value, key: &str| row[key].as_u64().unwrap();
    let modest = rows
        .iter()
        .find(|row| number(row, "transaction") == 9999)
        .unwrap();
    let longest = rows
        .iter()
        .map(|row| number(row, "response_time_us"))
        .max()
        .unwrap();
    let queued = number(modest, "queued_us");
    assert!(
        queued <= 2 * longest + 20_000,
        "waited {queued} us; a transaction took at most {longest} us"
    );
}

#[test]
fn a_silent_slave_gets_0b_after_the_retries_and_the_next_client_is_served() {
    let Some(pair) = PtyPair::new() else { return };
    let (_slave, gateway) = gateway_to_serve(
        &pair,
        &[],
        &["--timeout", "200ms", "--retries", "2", "-o", "json"],
    );
    let mut first = gateway.client();
    let mut second = gateway.client();
    let started = Instant::now();
    // Slave 5 is not on the line.
    first.write_all(&mbap(1, 5, &read_holding(0, 1))).unwrap();
    std::thread::sleep(Duration::from_millis(50));
    let (_, pdu) = ask(&mut second, 2, 17, &read_holding(107, 1));
    let answered_after = started.elapsed();
    assert_eq!(pdu, [3, 2, 2, 0x2B]);
    let (id, unit, pdu) = answer(&mut first).unwrap();
    assert_eq!((id, unit, pdu), (1, 5, vec![0x83, 0x0B]));
    // Three tries of 200 ms, then the second client's turn.
    assert!(
        answered_after >= Duration::from_millis(600),
        "{answered_after:?}"
    );
    assert!(
        answered_after < Duration::from_secs(2),
        "{answered_after:?}"
    );
    let (status, stdout, _) = gateway.stop();
    assert_eq!(status, 0);
    let rows = rows(&stdout);
    assert_eq!(rows[0]["outcome"], "timeout");
    assert_eq!(rows[0]["tries"], 3);
    assert_eq!(rows[0]["answer"]["exception"], 11);
    assert_eq!(rows[1]["outcome"], "answer");
}

#[test]
fn corrupted_answers_are_retried_or_told_as_bad_frames() {
    let Some(pair) = PtyPair::new() else { return };
    let corrupt = ["--corrupt", "20%", "--seed", "7"];
    let (_slave, gateway) = gateway_to_serve(&pair, &corrupt, &["--retries", "3", "-q"]);
    let mut client = gateway.client();
    for id in 0..100 {
        let (_, pdu) = ask(&mut client, id, 17, &read_holding(107, 3));
        assert_eq!(pdu, [3, 6, 2, 0x2B, 0, 0, 0, 0x64], "request {id}");
    }
    drop(gateway);
    let Some(pair) = PtyPair::new() else { return };
    let (_slave, gateway) = gateway_to_serve(&pair, &corrupt, &["-o", "json"]);
    let mut client = gateway.client();
    let mut failed = 0;
    for id in 0..100 {
        match ask(&mut client, id, 17, &read_holding(107, 3)).1.as_slice() {
            [3, 6, 2, 0x2B, 0, 0, 0, 0x64] => {}
            [0x83, 0x0B] => failed += 1,
            other => panic!("request {id}: {other:02X?}"),
        }
    }
    assert!((5..=40).contains(&failed), "{failed} of 100 failed");
    let (_, stdout, _) = gateway.stop();
    let bad: Vec<_> = rows(&stdout)
        .into_iter()
        .filter(|row| row["outcome"] == "bad-frame")
        .collect();
    assert_eq!(bad.len(), failed);
    // A corrupted CRC is told as such; a corrupted function code leaves bytes that make
    // no frame, waited out to the timeout in case the answer follows them.
    let crc = bad
        .iter()
        .filter(|row| row["why"].as_str().unwrap().contains("CRC mismatch"))
        .count();
    assert!(crc * 2 >= bad.len(), "{bad:?}");
}

#[test]
fn a_port_taken_away_gives_0a_at_once_and_answers_again_when_it_is_back() {
    if !peer_available("socat", command_exists("socat")) {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a"), dir.path().join("b"));
    let link = || {
        let socat = Stopped(
            Process::new("socat")
                .arg(format!("pty,raw,echo=0,link={}", a.display()))
                .arg(format!("pty,raw,echo=0,link={}", b.display()))
                .spawn()
                .unwrap(),
        );
        while !(a.exists() && b.exists()) {
            std::thread::sleep(Duration::from_millis(10));
        }
        let slave = serve(&["--port", a.to_str().unwrap()]);
        std::thread::sleep(Duration::from_millis(300));
        (socat, slave)
    };
    let line = link();
    let gateway = Gateway::start(&["--port", b.to_str().unwrap(), "-o", "json"]);
    let mut client = gateway.client();
    assert_eq!(
        ask(&mut client, 1, 17, &read_holding(107, 1)).1,
        [3, 2, 2, 0x2B]
    );
    // The adapter is unplugged: the port and the slave behind it go away.
    drop(line);
    while b.exists() {
        std::thread::sleep(Duration::from_millis(10));
    }
    let mut gone = Vec::new();
    for id in 2..12 {
        let asked = Instant::now();
        gone.push(ask(&mut client, id, 17, &read_holding(107, 1)).1);
        assert!(
            asked.elapsed() < Duration::from_millis(1500),
            "{:?}",
            asked.elapsed()
        );
    }
    // The first may fail as the line goes; the rest are 0A at once.
    assert!(
        gone[1..].iter().all(|pdu| pdu == &[0x83, 0x0A]),
        "{gone:02X?}"
    );
    let _line = link();
    let deadline = Instant::now() + Duration::from_secs(10);
    let mut id = 100;
    loop {
        id += 1;
        let (_, pdu) = ask(&mut client, id, 17, &read_holding(107, 1));
        if pdu == [3, 2, 2, 0x2B] {
            break;
        }
        assert_eq!(pdu, [0x83, 0x0A]);
        assert!(Instant::now() < deadline, "the line never came back");
        std::thread::sleep(Duration::from_millis(100));
    }
    let messages = gateway.messages();
    assert!(messages.contains("line down"), "{messages}");
    assert!(messages.contains("line up again"), "{messages}");
    let (status, stdout, _) = gateway.stop();
    assert_eq!(status, 0);
    assert!(rows(&stdout)
        .iter()
        .any(|row| row["outcome"] == "line-down"));
}

#[test]
fn each_transaction_is_one_json_row_saying_what_was_asked_and_answered() {
    let Some(pair) = PtyPair::new() else { return };
    let (_slave, gateway) = gateway_to_serve(
        &pair,
        &["--exception", "2@400150-400160"],
        &["-o", "json", "--unit-map", "1=17"],
    );
    let mut client = gateway.client();
    let address = client.local_addr().unwrap().to_string();
    assert_eq!(
        ask(&mut client, 0x1234, 1, &read_holding(107, 3)),
        (1, vec![3, 6, 2, 0x2B, 0, 0, 0, 0x64])
    );
    assert_eq!(
        ask(&mut client, 7, 17, &write_register(1, 99)).1,
        write_register(1, 99)
    );
    // An exception from the slave.
    assert_eq!(ask(&mut client, 8, 17, &read_holding(149, 2)).1, [0x83, 2]);
    // A function code that is no request, and a quantity of 0: the gateway answers.
    assert_eq!(ask(&mut client, 9, 17, &[0x83, 0, 0]).1, [0x83, 1]);
    assert_eq!(ask(&mut client, 10, 17, &read_holding(0, 0)).1, [0x83, 3]);
    let (status, stdout, _) = gateway.stop();
    assert_eq!(status, 0);
    let rows = rows(&stdout);
    assert_eq!(rows.len(), 5, "{stdout}");
    let first = &rows[0];
    assert_eq!(first["client"], address.as_str());
    assert_eq!(
        (first["unit"].as_u64(), first["slave"].as_u64()),
        (Some(1), Some(17))
    );
    assert_eq!(first["transaction"], 0x1234);
    assert_eq!(first["function"], 3);
    assert_eq!(first["request"]["ref"], "400108");
    assert_eq!(first["request"]["count"], 3);
    assert_eq!(first["answer"]["values"], serde_json::json!([555, 0, 100]));
    assert_eq!(
        (first["tries"].as_u64(), first["outcome"].as_str()),
        (Some(1), Some("answer"))
    );
    assert!(first["response_time_us"].as_u64().unwrap() > 0);
    assert!(chrono::DateTime::parse_from_rfc3339(first["time"].as_str().unwrap()).is_ok());
    assert_eq!(rows[1]["request"]["values"], serde_json::json!([99]));
    assert_eq!(first["answer"]["ref"], "400108");
    assert_eq!(rows[2]["outcome"], "exception");
    assert_eq!(rows[2]["answer"]["exception"], 2);
    for row in &rows[3..] {
        assert_eq!(row["outcome"], "exception");
        assert_eq!(row["tries"], 0, "{row}");
    }
}

#[test]
fn bad_clients_are_closed_and_counted_while_the_others_go_on() {
    let Some(pair) = PtyPair::new() else { return };
    let (_slave, gateway) = gateway_to_serve(&pair, &[], &["-q"]);
    let mut good = gateway.client();
    let mut length_300 = mbap(1, 17, &read_holding(0, 1));
    length_300[4..6].copy_from_slice(&300u16.to_be_bytes());
    let mut protocol_1 = mbap(1, 17, &read_holding(0, 1));
    protocol_1[3] = 1;
    let bad: [&[u8]; 4] = [
        b"GET / HTTP/1.1\r\nHost: plc\r\n\r\n",
        &[0, 1, 0, 0, 0, 0, 17, 3, 0, 0, 0, 1],
        &length_300,
        &protocol_1,
    ];
    for bytes in bad {
        let mut stream = gateway.client();
        stream.write_all(bytes).unwrap();
        let mut rest = Vec::new();
        // Closed by the gateway, with no answer.
        assert!(
            matches!(stream.read_to_end(&mut rest), Ok(0)),
            "{bytes:02X?}"
        );
        assert_eq!(
            ask(&mut good, 5, 17, &read_holding(107, 1)).1,
            [3, 2, 2, 0x2B]
        );
    }
    let (status, _, messages) = gateway.stop();
    assert_eq!(status, 0);
    assert!(
        messages.contains("4 clients closed for sending what is not Modbus TCP"),
        "{messages}"
    );
    assert_eq!(
        messages.matches("sent what is not Modbus TCP").count(),
        4,
        "{messages}"
    );
}

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

/// What a process holds now: resident memory in KiB, open descriptors and threads.
fn holds(pid: u32) -> (u64, usize, u64) {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).unwrap();
    let field = |name: &str| {
        status
            .lines()
            .find_map(|line| line.strip_prefix(name))
            .and_then(|rest| rest.split_whitespace().next())
            .and_then(|n| n.parse::<u64>().ok())
            .unwrap()
    };
    let descriptors = std::fs::read_dir(format!("/proc/{pid}/fd"))
        .unwrap()
        .count();
    (field("VmRSS:"), descriptors, field("Threads:"))
}

/// `rounds` rounds of `per_round` clients that each connect, read once and leave.
fn churn(gateway: &Gateway, rounds: usize, per_round: usize) -> Vec<(u64, usize, u64)> {
    let pid = gateway.process.0.id();
    let mut samples = Vec::new();
    for _ in 0..rounds {
        for id in 0..per_round {
            let mut client = gateway.client();
            assert_eq!(
                ask(&mut client, id as u16, 17, &read_holding(107, 1)).1,
                [3, 2, 2, 0x2B]
            );
        }
        // The clients' threads end once they see the close.
        std::thread::sleep(Duration::from_millis(200));
        samples.push(holds(pid));
    }
    samples
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
