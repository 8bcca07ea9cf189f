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
    // pymodbus's RTU client cannot frame a FIFO queue's answer: 24 is left out here (the
    // gateway passes it in tests/cli/protocol).
    let on_the_line = run(&[
        "--framer",
        "rtu",
        "--serial",
        &direct.b.display().to_string(),
        "--skip",
        "fifo",
    ]);
    assert_eq!(on_the_line["holding"], serde_json::json!([555, 0, 100]));
    let Some(bridged) = PtyPair::new() else {
        return;
    };
    let (_slave, gateway) = gateway_to_serve(&bridged, &[], &["-q"]);
    let port = gateway.port.to_string();
    assert_eq!(run(&["--tcp", &port, "--skip", "fifo"]), on_the_line);

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

mod faults;
