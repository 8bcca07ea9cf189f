//! `mbtool serve` finding its requests as a real slave must: on a shared RS-485 line among
//! other slaves' traffic, noise and cut frames; from a slow ASCII sender; over TCP however
//! a client's bytes are segmented; and with clients that hog connections or never read.

use std::io::{Read, Write};
use std::net::TcpStream;
use std::thread;
use std::time::Duration;

use crate::support::{
    free_port, random_request, read_frame, serve, values_of, wait_for_listener, write_all, Pty,
};
use mbtool_core::codec::framing::{Event, Framer};
use mbtool_core::codec::{Direction, Frame, Mode, Pdu, Request};
use mbtool_core::slave::{DataModel, Slave};

const SERVED: u8 = 17;

/// Well above 3.5 characters at the default 19200 baud (1.75 ms): the silence a real bus
/// leaves between frames.
const SILENCE: Duration = Duration::from_millis(8);

fn encode(mode: Mode, slave: u8, transaction: u16, pdu: Pdu) -> Vec<u8> {
    Frame {
        mode,
        slave,
        transaction,
        pdu,
    }
    .encode()
    .expect("the test's frames keep the limits")
}

/// What other stations put on the line: another slave's request or answer, a noise burst,
/// or a frame cut short.
fn bus_traffic(rng: &mut fastrand::Rng, others: &mut Slave) -> Vec<u8> {
    let other = [5u8, 9, 200][rng.usize(..3)];
    let asked = random_request(rng);
    let answer = others
        .handle(other, &asked)
        .expect("the other slave answers");
    match rng.u8(..4) {
        0 => encode(Mode::Rtu, other, 0, Pdu::Request(asked)),
        1 => encode(Mode::Rtu, other, 0, answer),
        2 => (0..rng.usize(1..=20)).map(|_| rng.u8(..)).collect(),
        _ => {
            let whole = encode(Mode::Rtu, other, 0, answer);
            whole[..rng.usize(1..whole.len())].to_vec()
        }
    }
}

/// `mbtool serve --slave 17` on a pty; the test's end of the line.
fn serve_on_pty(extra: &[&str]) -> (crate::support::Stopped, Pty) {
    let pty = Pty::new();
    let mut args = vec!["--port", pty.path.as_str(), "--slave", "17"];
    args.extend_from_slice(extra);
    (serve(&args), pty)
}

/// Sends requests to the served slave, each after (or glued to) what `before` puts on the
/// line, and checks every answer against a slave of our own given the same requests.
fn every_request_answered(before: impl Fn(&mut fastrand::Rng, &mut Slave) -> (Vec<u8>, bool)) {
    let (_server, pty) = serve_on_pty(&[]);
    let mut line = pty.master.try_clone_native().unwrap();
    let mut rng = fastrand::Rng::with_seed(11);
    let mut mirror = Slave::new(&[SERVED], DataModel::manual_examples());
    let mut others = Slave::new(&[5, 9, 200], DataModel::manual_examples());
    // The server is up once it answers.
    let probe = encode(
        Mode::Rtu,
        SERVED,
        0,
        Pdu::Request(Request::ReadHoldingRegisters {
            address: 107,
            quantity: 1,
        }),
    );
    let mut up = false;
    for _ in 0..100 {
        write_all(&mut line, &probe);
        if read_frame(
            &mut line,
            Mode::Rtu,
            Direction::Response,
            Duration::from_millis(100),
        )
        .is_some()
        {
            up = true;
            break;
        }
    }
    assert!(up, "serve never answered");
    thread::sleep(Duration::from_millis(200));
    for i in 0..100 {
        let (traffic, glued) = before(&mut rng, &mut others);
        let asked = random_request(&mut rng);
        let expected = encode(
            Mode::Rtu,
            SERVED,
            0,
            mirror.handle(SERVED, &asked).expect("slave 17 answers"),
        );
        let frame = encode(Mode::Rtu, SERVED, 0, Pdu::Request(asked));
        if glued {
            write_all(&mut line, &[traffic.as_slice(), &frame].concat());
        } else {
            write_all(&mut line, &traffic);
            thread::sleep(SILENCE);
            write_all(&mut line, &frame);
        }
        let answer = read_frame(
            &mut line,
            Mode::Rtu,
            Direction::Response,
            Duration::from_secs(3),
        )
        .map(|(_, bytes)| bytes);
        assert_eq!(
            answer.as_deref(),
            Some(expected.as_slice()),
            "request {i} ({}) after {}",
            hex::encode_upper(&frame),
            hex::encode_upper(&traffic)
        );
        thread::sleep(SILENCE);
    }
}

#[test]
fn on_a_busy_rtu_line_every_request_to_the_served_id_is_answered() {
    every_request_answered(|rng, others| (bus_traffic(rng, others), false));
}

#[test]
fn noise_glued_to_the_front_of_a_request_costs_nothing() {
    every_request_answered(|rng, _| ((0..rng.usize(1..=20)).map(|_| rng.u8(..)).collect(), true));
}

#[test]
fn requests_in_pieces_with_pauses_are_answered_and_so_is_every_one_after() {
    // A request written a byte at a time 5 ms apart, one in halves 20 ms apart (a USB
    // adapter), then requests with noise glued in front: each is answered, at once.
    let (_server, pty) = serve_on_pty(&[]);
    let mut line = pty.master.try_clone_native().unwrap();
    thread::sleep(Duration::from_millis(300));
    let request = crate::support::WORKED_FRAMES[4].clone();
    let bytes: Vec<Vec<u8>> = request.chunks(1).map(<[u8]>::to_vec).collect();
    let halves = vec![request[..3].to_vec(), request[3..].to_vec()];
    let glued = vec![[&[0x13, 0x37][..], &request].concat()];
    for (pause, pieces) in [(5, bytes), (20, halves), (0, glued.clone()), (0, glued)] {
        for piece in pieces {
            write_all(&mut line, &piece);
            thread::sleep(Duration::from_millis(pause));
        }
        let answer = read_frame(
            &mut line,
            Mode::Rtu,
            Direction::Response,
            Duration::from_secs(1),
        );
        assert!(answer.is_some(), "no answer after pieces {pause} ms apart");
        thread::sleep(Duration::from_millis(20));
    }
}

#[test]
fn an_ascii_request_with_half_a_second_between_characters_is_answered() {
    let (_server, pty) = serve_on_pty(&["--mode", "ascii"]);
    let mut line = pty.master.try_clone_native().unwrap();
    thread::sleep(Duration::from_millis(500));
    for byte in b":1103006B00037E\r\n" {
        write_all(&mut line, &[*byte]);
        thread::sleep(Duration::from_millis(500));
    }
    let (frame, _) = read_frame(
        &mut line,
        Mode::Ascii,
        Direction::Response,
        Duration::from_secs(3),
    )
    .expect("an answer");
    let mut mirror = Slave::new(&[SERVED], DataModel::manual_examples());
    let read = Request::ReadHoldingRegisters {
        address: 107,
        quantity: 3,
    };
    assert_eq!(
        frame.encode().unwrap(),
        encode(
            Mode::Ascii,
            SERVED,
            0,
            mirror.handle(SERVED, &read).unwrap()
        )
    );
}

/// `mbtool serve` on 127.0.0.1; the `--port` options for a master, and the TCP port.
fn serve_on_tcp() -> (crate::support::Stopped, Vec<String>, u16) {
    let port = free_port();
    let address = format!("tcp://127.0.0.1:{port}");
    let server = serve(&["--port", &address, "--slave", "17"]);
    assert!(
        wait_for_listener(port, Duration::from_secs(10)),
        "serve did not listen"
    );
    (server, vec!["--port".into(), address], port)
}

/// Reads `count` Modbus TCP frames from `stream`.
fn tcp_answers(stream: &mut TcpStream, count: usize) -> Vec<Vec<u8>> {
    stream
        .set_read_timeout(Some(Duration::from_secs(10)))
        .unwrap();
    let mut framer = Framer::new(Mode::Tcp, 0.0, 0);
    let mut events = Vec::new();
    let mut answers = Vec::new();
    let mut chunk = [0u8; 4096];
    while answers.len() < count {
        let n = stream.read(&mut chunk).expect("the answers come");
        assert!(n > 0, "the server closed the connection");
        framer.push(&chunk[..n], &mut events);
        for event in events.drain(..) {
            match event {
                Event::Frame(found) => answers.push(found.bytes.to_vec()),
                Event::Noise(noise) => panic!("not Modbus TCP: {:02X?}", noise.kept),
            }
        }
    }
    answers
}

#[test]
fn a_tcp_request_split_byte_by_byte_with_300_ms_between_bytes_is_answered() {
    let (_server, _, port) = serve_on_tcp();
    let mut client = TcpStream::connect(("127.0.0.1", port)).unwrap();
    client.set_nodelay(true).unwrap();
    let read = Request::ReadHoldingRegisters {
        address: 107,
        quantity: 3,
    };
    for byte in encode(Mode::Tcp, SERVED, 7, Pdu::Request(read.clone())) {
        client.write_all(&[byte]).unwrap();
        thread::sleep(Duration::from_millis(300));
    }
    let mut mirror = Slave::new(&[SERVED], DataModel::manual_examples());
    let expected = encode(Mode::Tcp, SERVED, 7, mirror.handle(SERVED, &read).unwrap());
    assert_eq!(tcp_answers(&mut client, 1), [expected]);
}

#[test]
fn a_hundred_tcp_requests_in_one_write_are_all_answered_in_order() {
    let (_server, _, port) = serve_on_tcp();
    let mut client = TcpStream::connect(("127.0.0.1", port)).unwrap();
    let mut rng = fastrand::Rng::with_seed(12);
    let mut mirror = Slave::new(&[SERVED], DataModel::manual_examples());
    let mut requests = Vec::new();
    let mut expected = Vec::new();
    for transaction in 1..=100u16 {
        let asked = random_request(&mut rng);
        expected.push(encode(
            Mode::Tcp,
            SERVED,
            transaction,
            mirror.handle(SERVED, &asked).unwrap(),
        ));
        requests.extend(encode(Mode::Tcp, SERVED, transaction, Pdu::Request(asked)));
    }
    client.write_all(&requests).unwrap();
    assert_eq!(tcp_answers(&mut client, 100), expected);
}

#[test]
fn with_a_hundred_idle_connections_open_a_new_client_is_served() {
    let (_server, master, port) = serve_on_tcp();
    let idle: Vec<TcpStream> = (0..100)
        .map(|_| TcpStream::connect(("127.0.0.1", port)).unwrap())
        .collect();
    // Within the master's own timeout (2 s), not after the idle clients time out.
    assert_eq!(
        values_of(&master, "read-holding 17 400108 3"),
        ["555", "0", "100"]
    );
    drop(idle);
}

#[test]
fn a_client_that_pipelines_and_never_reads_does_not_stop_another() {
    let (_server, master, port) = serve_on_tcp();
    let mut hog = TcpStream::connect(("127.0.0.1", port)).unwrap();
    let read = Pdu::Request(Request::ReadHoldingRegisters {
        address: 0,
        quantity: 125,
    });
    let pipeline: Vec<u8> = (0..10_000u16)
        .flat_map(|t| encode(Mode::Tcp, SERVED, t, read.clone()))
        .collect();
    // The hog writes until its buffers and the server's are full, and never reads.
    hog.set_write_timeout(Some(Duration::from_secs(3))).unwrap();
    let writer = thread::spawn(move || {
        let _ = hog.write_all(&pipeline);
        hog
    });
    thread::sleep(Duration::from_secs(1));
    assert_eq!(
        values_of(&master, "read-holding 17 400108 3"),
        ["555", "0", "100"]
    );
    drop(writer.join().unwrap());
}

#[test]
fn over_rtu_tcp_a_request_that_breaks_its_layout_gets_its_exception() {
    let port = free_port();
    let address = format!("rtu+tcp://127.0.0.1:{port}");
    let _server = serve(&["--port", &address, "--slave", "17"]);
    assert!(wait_for_listener(port, Duration::from_secs(10)));
    let mut client = TcpStream::connect(("127.0.0.1", port)).unwrap();
    client
        .set_read_timeout(Some(Duration::from_secs(5)))
        .unwrap();
    // Read 0 holding registers: the CRC holds, the quantity does not.
    client
        .write_all(&crate::support::rtu(&[17, 0x03, 0x00, 0x6B, 0x00, 0x00]))
        .unwrap();
    let mut answer = [0u8; 5];
    client.read_exact(&mut answer).expect("an answer");
    assert_eq!(answer.to_vec(), crate::support::rtu(&[17, 0x83, 0x03]));
}

/// `clients` Modbus TCP clients, all connected before any sends, each then reading
/// 400108-400110 `requests` times back to back; how many got every answer right, and the
/// first failures.
fn busy_clients(port: u16, clients: usize, requests: u16) -> (usize, Vec<String>) {
    let barrier = std::sync::Arc::new(std::sync::Barrier::new(clients));
    let workers: Vec<_> = (0..clients)
        .map(|_| {
            let barrier = barrier.clone();
            thread::spawn(move || -> Result<(), String> {
                let mut client =
                    TcpStream::connect(("127.0.0.1", port)).map_err(|e| e.to_string())?;
                client
                    .set_read_timeout(Some(Duration::from_secs(30)))
                    .map_err(|e| e.to_string())?;
                barrier.wait();
                let read = Pdu::Request(Request::ReadHoldingRegisters {
                    address: 107,
                    quantity: 3,
                });
                for transaction in 0..requests {
                    client
                        .write_all(&encode(Mode::Tcp, SERVED, transaction, read.clone()))
                        .map_err(|e| format!("request {transaction}: {e}"))?;
                    let mut answer = [0u8; 15];
                    client
                        .read_exact(&mut answer)
                        .map_err(|e| format!("answer {transaction}: {e}"))?;
                    if answer[..2] != transaction.to_be_bytes()
                        || answer[9..] != [2, 43, 0, 0, 0, 100]
                    {
                        return Err(format!("answer {transaction}: {answer:02X?}"));
                    }
                }
                Ok(())
            })
        })
        .collect();
    let mut done = 0;
    let mut failures = Vec::new();
    for worker in workers {
        match worker.join().unwrap() {
            Ok(()) => done += 1,
            Err(failure) => failures.push(failure),
        }
    }
    failures.truncate(3);
    (done, failures)
}

/// `mbtool serve` on TCP with at most `descriptors` open files, its stderr kept.
fn serve_limited(
    descriptors: u32,
    port: u16,
) -> (crate::support::Stopped, tempfile::NamedTempFile) {
    let stderr = tempfile::NamedTempFile::new().unwrap();
    let child = std::process::Command::new("sh")
        .arg("-c")
        .arg(format!(
            "ulimit -n {descriptors} && exec {} serve --port tcp://127.0.0.1:{port}",
            assert_cmd::cargo::cargo_bin("mbtool").display()
        ))
        .stdout(std::process::Stdio::null())
        .stderr(stderr.reopen().unwrap())
        .spawn()
        .unwrap();
    let server = crate::support::Stopped(child);
    assert!(wait_for_listener(port, Duration::from_secs(10)));
    (server, stderr)
}

#[test]
fn hundreds_of_busy_clients_are_all_served_to_the_end() {
    let port = free_port();
    let (_server, stderr) = serve_limited(4096, port);
    let (done, failures) = busy_clients(port, 400, 25);
    assert_eq!((done, failures), (400, vec![]));
    // None was closed to make room: every one was busy.
    let said = std::fs::read_to_string(stderr.path()).unwrap();
    assert!(!said.contains("make room"), "{said}");
}

#[test]
fn out_of_file_descriptors_new_clients_wait_their_turn_and_it_is_said_once() {
    let port = free_port();
    let (_server, stderr) = serve_limited(40, port);
    let (done, failures) = busy_clients(port, 120, 25);
    assert_eq!((done, failures), (120, vec![]));
    let said = std::fs::read_to_string(stderr.path()).unwrap();
    let told: Vec<&str> = said
        .lines()
        .filter(|line| line.contains("file descriptor"))
        .collect();
    assert_eq!(told.len(), 1, "{said}");
    assert!(
        told[0].starts_with("mbtool: no file descriptor left for another client (")
            && told[0].ends_with("new clients wait until one leaves; 'ulimit -n' raises the limit"),
        "{said}"
    );
}
