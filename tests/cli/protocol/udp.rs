//! Modbus over UDP under the faults of a real network: datagrams lost, repeated, late, or
//! from another host; RTU in datagrams; and a capture of Modbus/UDP read as tshark reads it.

use std::net::{SocketAddr, UdpSocket};
use std::sync::{Arc, Mutex};

use std::time::{Duration, Instant};

use super::{serve_udp, udp_port};
use crate::support::{command_exists, mbtool, peer_available, values_of, Stopped};

/// What the scripted device does with one request.
#[derive(Clone, Copy, Debug)]
enum Udp {
    /// Answers at once.
    Answer,
    /// Says nothing: the request, or its answer, was lost.
    Lose,
    /// Answers twice.
    Twice,
    /// First an answer to the transaction before, then the answer.
    EarlierFirst,
    /// First an answer from another socket (another host, to the master), then the answer.
    StrangerFirst,
    /// First a datagram of the answer with other values and two bytes after it, then the
    /// answer.
    TrailingFirst,
}

/// A Modbus/UDP device on 127.0.0.1 that answers reads of holding registers with each
/// register's address as its value, as `script` says request after request (then
/// answering every one); returns its port and the requests it received.
fn scripted_udp_device(script: Vec<Udp>) -> (u16, Arc<Mutex<Vec<Vec<u8>>>>) {
    let socket = UdpSocket::bind("127.0.0.1:0").unwrap();
    let stranger = UdpSocket::bind("127.0.0.1:0").unwrap();
    let port = socket.local_addr().unwrap().port();
    let received = Arc::new(Mutex::new(Vec::new()));
    let seen = Arc::clone(&received);
    std::thread::spawn(move || {
        let mut script = script.into_iter();
        let mut datagram = [0u8; 512];
        while let Ok((len, from)) = socket.recv_from(&mut datagram) {
            let request = datagram[..len].to_vec();
            seen.lock().unwrap().push(request.clone());
            let answer = |transaction: u16| answer_to(&request, transaction);
            let transaction = u16::from_be_bytes([request[0], request[1]]);
            let send = |socket: &UdpSocket, bytes: &[u8], to: SocketAddr| {
                socket.send_to(bytes, to).unwrap();
            };
            match script.next().unwrap_or(Udp::Answer) {
                Udp::Answer => send(&socket, &answer(transaction), from),
                Udp::Lose => {}
                Udp::Twice => {
                    send(&socket, &answer(transaction), from);
                    send(&socket, &answer(transaction), from);
                }
                Udp::EarlierFirst => {
                    let mut wrong = answer(transaction.wrapping_sub(1));
                    // Other values, that a master taking it would show.
                    *wrong.last_mut().unwrap() ^= 0xFF;
                    send(&socket, &wrong, from);
                    send(&socket, &answer(transaction), from);
                }
                Udp::TrailingFirst => {
                    let mut wrong = answer(transaction);
                    *wrong.last_mut().unwrap() ^= 0xFF;
                    wrong.extend_from_slice(&[0, 0]);
                    send(&socket, &wrong, from);
                    send(&socket, &answer(transaction), from);
                }
                Udp::StrangerFirst => {
                    let mut wrong = answer(transaction);
                    *wrong.last_mut().unwrap() ^= 0xFF;
                    send(&stranger, &wrong, from);
                    std::thread::sleep(Duration::from_millis(20));
                    send(&socket, &answer(transaction), from);
                }
            }
        }
    });
    (port, received)
}

/// The answer to an MBAP read of holding registers, with `transaction`.
fn answer_to(request: &[u8], transaction: u16) -> Vec<u8> {
    let address = u16::from_be_bytes([request[8], request[9]]);
    let quantity = u16::from_be_bytes([request[10], request[11]]);
    let mut pdu = vec![0x03, (quantity * 2) as u8];
    for register in address..address + quantity {
        pdu.extend_from_slice(&register.to_be_bytes());
    }
    let mut frame = transaction.to_be_bytes().to_vec();
    frame.extend_from_slice(&[0, 0]);
    frame.extend_from_slice(&((pdu.len() + 1) as u16).to_be_bytes());
    frame.push(request[6]);
    frame.extend_from_slice(&pdu);
    frame
}

/// mbtool reading `count` registers from 400001 of the scripted device with `timeout`: its
/// values, its stderr, and how long it took.
fn read(port: u16, count: u16, timeout: &str) -> (Vec<u16>, String, Duration) {
    let started = Instant::now();
    let output = mbtool()
        .args([
            "--port",
            &format!("udp://127.0.0.1:{port}"),
            "--timeout",
            timeout,
        ])
        .args([
            "read-holding",
            "1",
            "400001",
            &count.to_string(),
            "-o",
            "values",
        ])
        .output()
        .unwrap();
    let took = started.elapsed();
    assert!(output.status.success(), "{output:?}");
    let values = String::from_utf8_lossy(&output.stdout)
        .lines()
        .map(|l| l.parse().unwrap())
        .collect();
    (
        values,
        String::from_utf8_lossy(&output.stderr).into_owned(),
        took,
    )
}

#[test]
fn answers_at_once_are_read_at_once_and_duplicates_and_earlier_ones_are_passed_over() {
    let expected: Vec<u16> = (0..200).collect();
    // 200 registers: two requests, the first answered twice. The repeat is not taken for
    // the second's answer, and nothing waits on the 5 s timeout.
    let (port, received) = scripted_udp_device(vec![Udp::Twice, Udp::Answer]);
    let (values, stderr, took) = read(port, 200, "5s");
    assert_eq!(values, expected, "{stderr}");
    assert!(took < Duration::from_secs(1), "{took:?}");
    assert_eq!(received.lock().unwrap().len(), 2);
    // An answer to the transaction before comes first.
    let (port, _) = scripted_udp_device(vec![Udp::Answer, Udp::EarlierFirst]);
    let (values, stderr, took) = read(port, 200, "5s");
    assert_eq!(values, expected, "{stderr}");
    assert!(took < Duration::from_secs(1), "{took:?}");
    // A datagram that is more than one frame is no answer, whatever it starts with.
    let (port, _) = scripted_udp_device(vec![Udp::TrailingFirst]);
    let (values, stderr, took) = read(port, 3, "5s");
    assert_eq!(values, [0, 1, 2], "{stderr}");
    assert!(took < Duration::from_secs(1), "{took:?}");
}

#[test]
fn a_datagram_from_another_host_is_passed_over_and_counted() {
    let (port, _) = scripted_udp_device(vec![Udp::StrangerFirst]);
    let (values, stderr, took) = read(port, 3, "5s");
    assert_eq!(values, [0, 1, 2]);
    assert!(took < Duration::from_secs(1), "{took:?}");
    assert!(stderr.contains("1 datagram from 127.0.0.1:"), "{stderr}");
    assert!(
        stderr.contains(&format!(
            "not the device asked (127.0.0.1:{port}), was passed over"
        )),
        "{stderr}"
    );
    // A poll tells them at its end too.
    let (port, _) = scripted_udp_device(vec![Udp::StrangerFirst, Udp::Answer, Udp::StrangerFirst]);
    let output = mbtool()
        .args(["--port", &format!("udp://127.0.0.1:{port}")])
        .args([
            "read-holding",
            "1",
            "400001",
            "--poll",
            "50ms",
            "--count",
            "3",
            "-o",
            "csv",
        ])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("2 datagrams from 127.0.0.1:"), "{stderr}");
}

/// RTU in datagrams is the stream a serial server packs: an answer cut across two
/// datagrams is read whole.
#[test]
fn an_rtu_answer_cut_across_two_datagrams_is_read_whole() {
    let socket = UdpSocket::bind("127.0.0.1:0").unwrap();
    let port = socket.local_addr().unwrap().port();
    std::thread::spawn(move || {
        let mut datagram = [0u8; 256];
        while let Ok((_, from)) = socket.recv_from(&mut datagram) {
            let answer = crate::support::rtu(&[0x11, 0x03, 0x04, 0x03, 0xE8, 0x03, 0xE9]);
            for piece in [&answer[..3], &answer[3..]] {
                socket.send_to(piece, from).unwrap();
                std::thread::sleep(Duration::from_millis(5));
            }
        }
    });
    let port = vec!["--port".to_string(), format!("rtu+udp://127.0.0.1:{port}")];
    assert_eq!(
        values_of(&port, "read-holding 17 400001 2"),
        ["1000", "1001"]
    );
}

#[test]
fn a_lost_datagram_is_asked_again_and_retries_can_be_turned_off() {
    let (port, received) = scripted_udp_device(vec![Udp::Lose]);
    let (values, _, took) = read(port, 3, "300ms");
    assert_eq!(values, [0, 1, 2]);
    assert!(
        took >= Duration::from_millis(300) && took < Duration::from_secs(2),
        "{took:?}"
    );
    assert_eq!(received.lock().unwrap().len(), 2);
    // --retries 0: the loss is a timeout (exit status 3).
    let (port, _) = scripted_udp_device(vec![Udp::Lose]);
    let output = mbtool()
        .args(["--port", &format!("udp://127.0.0.1:{port}")])
        .args([
            "--timeout",
            "200ms",
            "--retries",
            "0",
            "read-holding",
            "1",
            "400001",
        ])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(3), "{output:?}");
    // A mask write lost is not sent twice unless asked: the device may have done it.
    let (port, received) = scripted_udp_device(vec![Udp::Lose, Udp::Lose, Udp::Lose]);
    let output = mbtool()
        .args(["--port", &format!("udp://127.0.0.1:{port}")])
        .args(["--timeout", "200ms", "mask-write", "1", "400001.01=1"])
        .output()
        .unwrap();
    assert_ne!(output.status.code(), Some(0), "{output:?}");
    assert_eq!(received.lock().unwrap().len(), 1);
}

/// `serve` over UDP in both framings, every command of the rest of the protocol through it.
#[test]
fn serve_answers_over_udp_in_mbap_and_in_rtu() {
    for scheme in ["udp://", "rtu+udp://"] {
        let (_server, port) = serve_udp(scheme, &[]);
        assert_eq!(
            values_of(&port, "read-holding 17 400108 3"),
            ["555", "0", "100"]
        );
        assert_eq!(
            values_of(&port, "read-file 17 4:1 2 3:9 2"),
            ["3582", "32", "13261", "64"]
        );
        assert_eq!(values_of(&port, "read-fifo 17 401247"), ["440", "4740"]);
        assert_eq!(values_of(&port, "read-write 17 400108 1 400108 9"), ["9"]);
    }
}

/// A capture of Modbus/UDP, taken by tcpdump while mbtool talks to pymodbus, read by
/// `sniff` as tshark reads it: the same frames, transactions and units, each answer paired.
#[test]
fn a_capture_of_modbus_udp_is_read_as_tshark_reads_it() {
    if !peer_available("tshark", command_exists("tshark"))
        || !peer_available("tcpdump", command_exists("tcpdump"))
    {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let capture = dir.path().join("udp.pcap");
    let (_server, port) = serve_udp("udp://", &[]);
    let udp: u16 = port[1].rsplit(':').next().unwrap().parse().unwrap();
    let tcpdump = std::process::Command::new("tcpdump")
        .args(["-i", "lo", "-U", "-w"])
        .arg(&capture)
        .arg(format!("udp port {udp}"))
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let tcpdump = Stopped(tcpdump);
    std::thread::sleep(Duration::from_millis(1500));
    if std::fs::metadata(&capture).is_err() {
        // Capturing needs the right to: none here.
        assert!(
            std::env::var_os("CI").is_none(),
            "tcpdump cannot capture on lo"
        );
        eprintln!("skipping: tcpdump cannot capture on lo here");
        return;
    }
    for command in [
        "read-holding 17 400108 3",
        "read-file 17 4:1 2 3:9 2",
        "read-fifo 17 401247",
        "mask-write 17 400108.01=1",
        "read-write 17 400108 2 400110 9",
        "read-fifo 17 400001",
    ] {
        crate::support::run_against(&port, command);
    }
    std::thread::sleep(Duration::from_millis(500));
    // SIGINT: tcpdump writes what it holds.
    let pid = tcpdump.0.id().to_string();
    std::process::Command::new("kill")
        .args(["-INT", &pid])
        .status()
        .unwrap();
    std::thread::sleep(Duration::from_millis(500));
    drop(tcpdump);
    let theirs = std::process::Command::new("tshark")
        .arg("-r")
        .arg(&capture)
        .args(["-d", &format!("udp.port=={udp},mbudp")])
        .args([
            "-T",
            "fields",
            "-e",
            "frame.number",
            "-e",
            "mbtcp.trans_id",
            "-e",
            "mbtcp.unit_id",
            "-e",
            "modbus.func_code",
        ])
        .output()
        .unwrap();
    let theirs: Vec<(u64, u64, u64, u64)> = String::from_utf8_lossy(&theirs.stdout)
        .lines()
        .map(|line| {
            let f: Vec<u64> = line.split('\t').map(|v| v.parse().unwrap()).collect();
            (f[0], f[1], f[2], f[3])
        })
        .collect();
    assert_eq!(theirs.len(), 12, "{theirs:?}");
    let ours = mbtool()
        .args([
            "sniff",
            "--tcp-port",
            &udp.to_string(),
            "-o",
            "json",
            "--input",
        ])
        .arg(&capture)
        .output()
        .unwrap();
    let records: Vec<serde_json::Value> = String::from_utf8_lossy(&ours.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .filter(|r: &serde_json::Value| r["type"] == "frame")
        .collect();
    let ours: Vec<(u64, u64, u64, u64)> = records
        .iter()
        .map(|r| {
            let field = |name: &str| r[name].as_u64().unwrap();
            // tshark gives an exception's function without its 0x80 flag.
            (
                field("packet"),
                field("transaction"),
                field("slave"),
                field("function") & 0x7F,
            )
        })
        .collect();
    assert_eq!(ours, theirs);
    // Each frame says it came over UDP.
    assert!(records.iter().all(|r| r["transport"] == "udp"));
    // Every answer is paired with its request; the file record answer names its files.
    assert!(records
        .iter()
        .filter(|r| r["kind"] != "request")
        .all(|r| r["paired"] == true));
    let files = records
        .iter()
        .find(|r| r["function"] == 20 && r["kind"] == "response")
        .unwrap();
    assert_eq!(files["files"][1]["file"], 3);
}

/// `mbtool gateway` to `line`, listening for Modbus/UDP on a port of its own, its rows as
/// JSON: the guard and the port.
fn json_gateway(line: &[String]) -> (Stopped, u16) {
    let listen = udp_port();
    let gateway = std::process::Command::new(assert_cmd::cargo::cargo_bin("mbtool"))
        .arg("gateway")
        .args(line)
        .args([
            "--listen",
            &format!("udp://127.0.0.1:{listen}"),
            "-o",
            "json",
        ])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    std::thread::sleep(Duration::from_millis(500));
    (Stopped(gateway), listen)
}

/// Ends a gateway as Ctrl-C does and reads what it printed: its rows and its summary.
fn rows_of(mut gateway: Stopped) -> String {
    let pid = gateway.0.id().to_string();
    std::process::Command::new("kill")
        .args(["-INT", &pid])
        .status()
        .unwrap();
    let gateway = std::mem::replace(
        &mut gateway.0,
        std::process::Command::new("true").spawn().unwrap(),
    );
    let output = gateway.wait_with_output().unwrap();
    String::from_utf8_lossy(&output.stdout).into_owned()
}

/// `gateway --listen udp://` with a datagram that is no Modbus: passed over, counted, and
/// the next request answered; its rows show a read/write's read and a file record read's
/// records, and records that are no place in a file go to the device, which says 02.
#[test]
fn a_gateway_passes_over_datagrams_that_are_no_modbus_and_shows_what_it_passes() {
    let (_server, line) = serve_udp("udp://", &[]);
    let (gateway, listen) = json_gateway(&line);
    let port = vec!["--port".to_string(), format!("udp://127.0.0.1:{listen}")];
    let junk = UdpSocket::bind("127.0.0.1:0").unwrap();
    junk.send_to(b"not modbus at all", ("127.0.0.1", listen))
        .unwrap();
    assert_eq!(
        values_of(&port, "read-holding 17 400108 3"),
        ["555", "0", "100"]
    );
    assert_eq!(
        values_of(&port, "read-write 17 400108 2 400110 7"),
        ["555", "0"]
    );
    assert_eq!(values_of(&port, "read-file 17 4:1 2"), ["3582", "32"]);
    let (_, out) = crate::support::run_against(&port, "raw 17 14 07 06 00 00 00 01 00 01");
    assert!(out.contains("exception") && out.contains("02"), "{out}");
    std::thread::sleep(Duration::from_millis(200));
    let text = rows_of(gateway);
    assert!(
        text.contains(r#"{"passed_over":1,"summary":"bad_datagrams"}"#),
        "{text}"
    );
    let rows: Vec<serde_json::Value> = text
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .filter(|r: &serde_json::Value| r.get("transaction").is_some())
        .collect();
    let answers = |function: u64| -> Vec<&serde_json::Value> {
        rows.iter()
            .filter(|r| r["function"] == function)
            .map(|r| &r["answer"])
            .collect()
    };
    assert_eq!(answers(23)[0]["ref"], "400108", "{text}");
    assert_eq!(answers(20)[0]["files"][0]["file"], 4, "{text}");
    assert_eq!(answers(20)[0]["files"][0]["record"], 1, "{text}");
    // File 0 went to the line, and its device answered 02.
    assert_eq!(answers(20)[1]["exception"], 2, "{text}");
}

/// A request the network repeats reaches the line once: repeats while it is under way are
/// dropped, and one after its answer gets that answer again.
#[test]
fn a_gateway_carries_out_a_repeated_datagram_once() {
    let (_server, line) = serve_udp("udp://", &["--delay", "50ms"]);
    let (gateway, listen) = json_gateway(&line);
    let client = UdpSocket::bind("127.0.0.1:0").unwrap();
    client
        .set_read_timeout(Some(Duration::from_millis(400)))
        .unwrap();
    // Mask write of 400005, transaction 4242, three times 5 ms apart.
    let request = [0x10, 0x92, 0, 0, 0, 8, 17, 0x16, 0, 4, 0, 0xF2, 0, 0x25];
    for _ in 0..3 {
        client.send_to(&request, ("127.0.0.1", listen)).unwrap();
        std::thread::sleep(Duration::from_millis(5));
    }
    let mut answer = [0u8; 64];
    let (len, _) = client.recv_from(&mut answer).unwrap();
    assert_eq!(answer[..len], request);
    assert!(
        client.recv_from(&mut answer).is_err(),
        "a second answer came"
    );
    // Its answer lost, the client asks again: the same answer, from the gateway.
    client.send_to(&request, ("127.0.0.1", listen)).unwrap();
    let (len, _) = client.recv_from(&mut answer).unwrap();
    assert_eq!(answer[..len], request);
    let text = rows_of(gateway);
    let on_the_line = text
        .lines()
        .filter(|l| l.contains(r#""function":22"#))
        .count();
    assert_eq!(on_the_line, 1, "{text}");
}
