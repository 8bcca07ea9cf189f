//! The master over Modbus TCP against a scripted server on 127.0.0.1 that plays exact
//! bytes: a server that never answers, answers with another transaction id, answers twice,
//! or puts two answers in one segment. The MBAP length frames, whatever the segments.

use std::io::{Read, Write};
use std::net::TcpListener;
use std::thread;
use std::time::Duration;

use crate::support::mbtool;
use mbtool_core::codec::framing::{Event, Framer};
use mbtool_core::codec::{Direction, Frame, Mode, Pdu, Request};
use mbtool_core::master::{Master, MasterOptions, Reply};
use mbtool_core::slave::{DataModel, Slave};
use mbtool_core::transport::tcp::Tcp;

/// What the server does with a request: the bytes it writes back, in one segment, made
/// from the request's transaction id and its true answer.
type Act = fn(u16, &[u8]) -> Vec<u8>;

fn answer_with(transaction: u16, request: &Frame) -> Vec<u8> {
    let Pdu::Request(asked) = &request.pdu else {
        panic!("a request came")
    };
    let mut slave = Slave::new(&[17], DataModel::manual_examples());
    Frame {
        mode: Mode::Tcp,
        slave: 17,
        transaction,
        pdu: slave.handle(17, asked).expect("slave 17 answers"),
    }
    .encode()
    .unwrap()
}

/// A server that accepts one client and plays `acts`, one per request; the port.
fn scripted(acts: Vec<Act>) -> (u16, thread::JoinHandle<()>) {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let port = listener.local_addr().unwrap().port();
    let server = thread::spawn(move || {
        let (mut client, _) = listener.accept().unwrap();
        client
            .set_read_timeout(Some(Duration::from_secs(5)))
            .unwrap();
        let mut framer = Framer::new(Mode::Tcp, 0.0, 0);
        let mut events = Vec::new();
        let mut chunk = [0u8; 512];
        for act in acts {
            let request = loop {
                if let Some(Event::Frame(found)) = events.pop() {
                    break Frame::decode(Mode::Tcp, &found.bytes, Direction::Request).unwrap();
                }
                match client.read(&mut chunk) {
                    Ok(n) if n > 0 => framer.push(&chunk[..n], &mut events),
                    _ => return,
                }
            };
            let answer = answer_with(request.transaction, &request);
            let _ = client.write_all(&act(request.transaction, &answer));
        }
        // Hold the connection until the master is done.
        let _ = client.read(&mut chunk);
    });
    (port, server)
}

/// The answer with another transaction id.
fn stale(transaction: u16, answer: &[u8]) -> Vec<u8> {
    let mut stale = answer.to_vec();
    stale[..2].copy_from_slice(&transaction.wrapping_add(1).to_be_bytes());
    stale
}

fn read_17(port: u16, extra: &[&str]) -> assert_cmd::assert::Assert {
    mbtool()
        .args(["--port", &format!("tcp://127.0.0.1:{port}")])
        .args(["read-holding", "17", "400108", "3", "-o", "values"])
        .args(extra)
        // A guard against a hang, not a measure of speed.
        .timeout(Duration::from_secs(20))
        .assert()
}

#[test]
fn a_timeout_under_a_millisecond_against_a_silent_server_is_no_answer() {
    let (port, _server) = scripted(vec![|_, _| Vec::new()]);
    read_17(port, &["--timeout", "1us"])
        .code(3)
        .stderr(predicates::str::contains("no answer from slave 17"));
}

#[test]
fn an_answer_with_another_transaction_id_then_silence_is_no_answer() {
    let (port, _server) = scripted(vec![stale]);
    read_17(port, &["--timeout", "300ms"])
        .code(3)
        .stderr(predicates::str::contains("no answer from slave 17"));
}

#[test]
fn a_stale_answer_and_the_right_one_in_one_segment() {
    let (port, _server) = scripted(vec![|transaction, answer| {
        [stale(transaction, answer), answer.to_vec()].concat()
    }]);
    read_17(port, &["--timeout", "1s"])
        .code(0)
        .stdout("555\n0\n100\n");
}

#[test]
fn a_duplicated_answer_is_skipped_by_the_next_transaction() {
    let (port, _server) = scripted(vec![|_, answer| [answer, answer].concat(), |_, answer| {
        answer.to_vec()
    }]);
    let transport = Tcp::connect("127.0.0.1", port, Duration::from_secs(2), false).unwrap();
    let mut master = Master::new(
        Box::new(transport),
        MasterOptions {
            mode: Mode::Tcp,
            timeout: Duration::from_secs(2),
            retries: 0,
            retry_non_idempotent: false,
            frame_gap: Duration::ZERO,
            character: Duration::ZERO,
            silence: Duration::ZERO,
            turnaround: Duration::ZERO,
        },
    );
    let reads = [
        Request::ReadHoldingRegisters {
            address: 107,
            quantity: 3,
        },
        Request::ReadHoldingRegisters {
            address: 108,
            quantity: 2,
        },
    ];
    let mut slave = Slave::new(&[17], DataModel::manual_examples());
    for read in reads {
        let Some(Pdu::Response(expected)) = slave.handle(17, &read) else {
            panic!("slave 17 answers")
        };
        let reply = master.transact(17, &read).expect("the right answer");
        assert_eq!(reply, Reply::Response(expected));
    }
}

#[test]
fn a_server_that_resets_the_connection_is_named_in_the_message() {
    // A server that stops (or restarts) as the request comes: closing with the request
    // unread makes its kernel reset the connection.
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let port = listener.local_addr().unwrap().port();
    let server = thread::spawn(move || {
        let (client, _) = listener.accept().unwrap();
        let mut request = [0u8; 12];
        let _ = client.peek(&mut request);
        drop(client);
    });
    let output = read_17(port, &["--timeout", "5s"]).get_output().clone();
    server.join().unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.starts_with(&format!(
            "mbtool: 127.0.0.1:{port} dropped the connection (it closed or restarted)"
        )),
        "{stderr}"
    );
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
}
