//! A capture of a plant's day holds hundreds of thousands of short connections: what the
//! session keeps must not grow with them once they are closed. Told by the memory the
//! process holds (Linux), in a test binary of its own so that no other test allocates
//! meanwhile.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use etherparse::PacketBuilder;

use mbtool_core::codec::Mode;
use mbtool_core::sniff::capture::Packet;
use mbtool_core::sniff::session::Filter;
use mbtool_core::sniff::tcp::TcpSession;

/// The memory the process holds, in bytes (its resident set).
fn resident() -> usize {
    let status = std::fs::read_to_string("/proc/self/status").unwrap();
    let line = status
        .lines()
        .find(|line| line.starts_with("VmRSS:"))
        .unwrap();
    let kilobytes: usize = line.split_whitespace().nth(1).unwrap().parse().unwrap();
    kilobytes * 1024
}

/// One packet of connection `n`, from the client (`to_server`) or the server.
fn segment(n: u32, to_server: bool, sequence: u32, ack: u32, fin: bool, payload: &[u8]) -> Vec<u8> {
    let client = [10, 1, (n >> 16) as u8, (n >> 8) as u8];
    let server = [10, 0, 0, 2];
    let client_port = 20_000 + (n & 0xFF) as u16;
    let (a, b, source, destination) = match to_server {
        true => (client, server, client_port, 502),
        false => (server, client, 502, client_port),
    };
    let builder = PacketBuilder::ethernet2([1; 6], [2; 6])
        .ipv4(a, b, 64)
        .tcp(source, destination, sequence, 1024)
        .ack(ack);
    let builder = if fin { builder.fin() } else { builder };
    let mut bytes = Vec::new();
    builder.write(&mut bytes, payload).unwrap();
    bytes
}

/// Connection `n`: a read and its answer, FINs both ways, the client's last ACK.
fn connection(n: u32) -> Vec<Vec<u8>> {
    let request = [0, 1, 0, 0, 0, 6, 17, 3, 0, 0, 0, 2];
    let answer = [0, 1, 0, 0, 0, 7, 17, 3, 4, 0, 1, 0, 2];
    let (c, s) = (1000, 5000);
    let (c_end, s_end) = (c + request.len() as u32, s + answer.len() as u32);
    vec![
        segment(n, true, c, s, false, &request),
        segment(n, false, s, c_end, false, &answer),
        segment(n, true, c_end, s_end, true, &[]),
        segment(n, false, s_end, c_end + 1, true, &[]),
        segment(n, true, c_end + 1, s_end + 1, false, &[]),
    ]
}

#[test]
fn connections_closed_leave_nothing_behind() {
    let mut session = TcpSession::new(Mode::Tcp, vec![502], Filter::default());
    let mut records = Vec::new();
    let mut number = 0;
    let mut held_after = |connections: std::ops::Range<u32>, session: &mut TcpSession| {
        for n in connections {
            for data in connection(n) {
                number += 1;
                let packet = Packet {
                    number,
                    time_us: 1_700_000_000_000_000 + number * 100,
                    link: 1,
                    data: &data,
                    original_len: data.len() as u32,
                };
                session.packet(&packet, &mut records);
                records.clear();
            }
        }
        resident()
    };
    let after_few = held_after(0..5_000, &mut session);
    let after_many = held_after(5_000..50_000, &mut session);
    // Nine times as many connections again: the memory held may differ by what a few
    // connections hold, and by the bounded memory of those closed lately; each left
    // behind would hold kilobytes.
    assert!(
        after_many < after_few + (8 << 20),
        "{after_few} bytes held after 5,000 connections, {after_many} after 50,000"
    );
    assert_eq!(session.counts().requests, 50_000);
    assert_eq!(session.counts().answers, 50_000);
}
