//! Captures of Modbus TCP written here, packet by packet, with the faults a real capture
//! has: segments out of order, retransmitted and lost, a capture that starts
//! mid-connection, VLAN tags, IPv6, Linux cooked headers, packets a snap length cut, a
//! stream on port 502 that is no Modbus, a giant MBAP length, a file cut off. The frames
//! after each fault are found, and nothing is invented.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use etherparse::{PacketBuilder, VlanId};

use mbtool_core::codec::Mode;

use mbtool_core::describe::Kind;

use mbtool_core::sniff::capture::{is_capture, read_packets, CaptureError};

use mbtool_core::sniff::session::{Filter, Record};

use mbtool_core::sniff::tcp::TcpSession;

use proptest::prelude::*;

const CLIENT: [u8; 4] = [10, 0, 0, 1];

const SERVER: [u8; 4] = [10, 0, 0, 2];

const CLIENT_PORT: u16 = 40000;

/// An MBAP ADU to unit 17.
fn mbap(transaction: u16, pdu: &[u8]) -> Vec<u8> {
    let mut adu = transaction.to_be_bytes().to_vec();
    adu.extend([0, 0]);
    adu.extend(u16::try_from(pdu.len() + 1).unwrap().to_be_bytes());
    adu.push(17);
    adu.extend_from_slice(pdu);
    adu
}

/// The request to read `n` holding registers from 0, and its answer (values 1..=n).
fn exchange(transaction: u16, n: u8) -> (Vec<u8>, Vec<u8>) {
    let request = mbap(transaction, &[3, 0, 0, 0, n]);
    let mut answer = vec![3, 2 * n];
    for value in 1..=n {
        answer.extend([0, value]);
    }
    (request, mbap(transaction, &answer))
}

/// How a packet is wrapped.
#[derive(Clone, Copy)]
enum Link {
    Ethernet,
    Vlan,
    Ipv6,
    CookedV2,
}

/// A TCP segment from the client (`to_server`) or the server, as a packet of `link`.
fn packet(link: Link, to_server: bool, sequence: u32, ack: u32, payload: &[u8]) -> Vec<u8> {
    let (source, destination) = match to_server {
        true => (CLIENT_PORT, 502),
        false => (502, CLIENT_PORT),
    };
    let (a, b) = match to_server {
        true => (CLIENT, SERVER),
        false => (SERVER, CLIENT),
    };
    let mut bytes = Vec::new();
    let v6 = |ip: [u8; 4]| {
        let mut address = [0u8; 16];
        address[12..].copy_from_slice(&ip);
        address
    };
    match link {
        Link::Ethernet => PacketBuilder::ethernet2([1; 6], [2; 6])
            .ipv4(a, b, 64)
            .tcp(source, destination, sequence, 1024)
            .ack(ack)
            .write(&mut bytes, payload)
            .unwrap(),
        Link::Vlan => PacketBuilder::ethernet2([1; 6], [2; 6])
            .single_vlan(VlanId::try_new(42).unwrap())
            .ipv4(a, b, 64)
            .tcp(source, destination, sequence, 1024)
            .ack(ack)
            .write(&mut bytes, payload)
            .unwrap(),
        Link::Ipv6 => PacketBuilder::ethernet2([1; 6], [2; 6])
            .ipv6(v6(a), v6(b), 64)
            .tcp(source, destination, sequence, 1024)
            .ack(ack)
            .write(&mut bytes, payload)
            .unwrap(),
        Link::CookedV2 => {
            // Protocol, reserved, interface index, ARPHRD, packet type, address length, address.
            bytes.extend([
                0x08, 0x00, 0, 0, 0, 0, 0, 1, 0, 1, 4, 6, 1, 1, 1, 1, 1, 1, 0, 0,
            ]);
            PacketBuilder::ipv4(a, b, 64)
                .tcp(source, destination, sequence, 1024)
                .ack(ack)
                .write(&mut bytes, payload)
                .unwrap();
        }
    }
    bytes
}

/// A pcap file of `link_type` holding `packets`, each (time in us, bytes, length on the
/// wire when longer).
fn pcap(link_type: u32, packets: &[(u64, Vec<u8>, Option<u32>)]) -> Vec<u8> {
    let mut file = Vec::new();
    file.extend(0xA1B2_C3D4u32.to_le_bytes());
    file.extend(2u16.to_le_bytes());
    file.extend(4u16.to_le_bytes());
    file.extend([0; 8]);
    file.extend(65535u32.to_le_bytes());
    file.extend(link_type.to_le_bytes());
    for (time, bytes, wire) in packets {
        file.extend(u32::try_from(time / 1_000_000).unwrap().to_le_bytes());
        file.extend(u32::try_from(time % 1_000_000).unwrap().to_le_bytes());
        let len = u32::try_from(bytes.len()).unwrap();
        file.extend(len.to_le_bytes());
        file.extend(wire.unwrap_or(len).to_le_bytes());
        file.extend(bytes);
    }
    file
}

/// What sniff makes of a capture: its records, and how reading it ended.
fn sniff(file: &[u8]) -> (Vec<Record>, Result<u64, CaptureError>) {
    let (_, records, read) = session_of(Mode::Tcp, file);
    (records, read)
}

/// A session of `mode` run over a capture on port 502, with what it found.
fn session_of(mode: Mode, file: &[u8]) -> (TcpSession, Vec<Record>, Result<u64, CaptureError>) {
    let mut session = TcpSession::new(mode, vec![502], Filter::default());
    let mut records = Vec::new();
    let read = read_packets(file, |packet| {
        session.packet(&packet, &mut records);
        true
    });
    session.finish(&mut records);
    (session, records, read)
}

/// The frames found: (transaction, kind, valid, the request's packet for an answer).
fn frames(records: &[Record]) -> Vec<(u16, Kind, bool, Option<u64>)> {
    records
        .iter()
        .filter_map(|record| match record {
            Record::Frame(frame) => Some((
                frame.report().transaction.unwrap_or_default(),
                frame.report().kind,
                frame.report().valid,
                frame.tcp.and_then(|place| place.request_packet),
            )),
            _ => None,
        })
        .collect()
}

/// A conversation of `exchanges` read/answer pairs, client and server segments in turn,
/// with the sequence numbers of each side.
fn conversation(link: Link, exchanges: &[(Vec<u8>, Vec<u8>)]) -> Vec<Vec<u8>> {
    let (mut client, mut server) = (1000u32, 5000u32);
    let mut packets = Vec::new();
    for (request, answer) in exchanges {
        packets.push(packet(link, true, client, server, request));
        client += u32::try_from(request.len()).unwrap();
        packets.push(packet(link, false, server, client, answer));
        server += u32::try_from(answer.len()).unwrap();
    }
    packets
}

fn timed(packets: Vec<Vec<u8>>) -> Vec<(u64, Vec<u8>, Option<u32>)> {
    packets
        .into_iter()
        .enumerate()
        .map(|(i, bytes)| (1_000_000 + 1000 * i as u64, bytes, None))
        .collect()
}

#[test]
fn every_link_gives_the_same_frames_paired() {
    let exchanges: Vec<_> = (1..=3).map(|t| exchange(t, t as u8)).collect();
    let expected = vec![
        (1, Kind::Request, true, None),
        (1, Kind::Response, true, Some(1)),
        (2, Kind::Request, true, None),
        (2, Kind::Response, true, Some(3)),
        (3, Kind::Request, true, None),
        (3, Kind::Response, true, Some(5)),
    ];
    for (link, link_type) in [
        (Link::Ethernet, 1),
        (Link::Vlan, 1),
        (Link::Ipv6, 1),
        (Link::CookedV2, 276),
    ] {
        let file = pcap(link_type, &timed(conversation(link, &exchanges)));
        let (records, read) = sniff(&file);
        assert_eq!(read, Ok(6));
        assert_eq!(frames(&records), expected, "link type {link_type}");
    }
}

/// A FIN with no payload, client to server or back.
fn fin(to_server: bool, sequence: u32, ack: u32) -> Vec<u8> {
    let (source, destination) = if to_server {
        (CLIENT_PORT, 502)
    } else {
        (502, CLIENT_PORT)
    };
    let (a, b) = if to_server {
        (CLIENT, SERVER)
    } else {
        (SERVER, CLIENT)
    };
    let mut bytes = Vec::new();
    PacketBuilder::ethernet2([1; 6], [2; 6])
        .ipv4(a, b, 64)
        .tcp(source, destination, sequence, 1024)
        .fin()
        .ack(ack)
        .write(&mut bytes, &[])
        .unwrap();
    bytes
}

#[test]
fn a_fin_acknowledged_is_no_byte_missing() {
    let exchanges: Vec<_> = (1..=2).map(|t| exchange(t, 2)).collect();
    let mut packets = conversation(Link::Ethernet, &exchanges);
    let sent: u32 = exchanges.iter().map(|(r, _)| r.len() as u32).sum();
    let answered: u32 = exchanges.iter().map(|(_, a)| a.len() as u32).sum();
    packets.push(fin(true, 1000 + sent, 5000 + answered));
    packets.push(fin(false, 5000 + answered, 1000 + sent + 1));
    packets.push(packet(
        Link::Ethernet,
        true,
        1000 + sent + 1,
        5000 + answered + 1,
        &[],
    ));
    let (session, records, _) = session_of(Mode::Tcp, &pcap(1, &timed(packets)));
    assert_eq!(session.packet_counts().missing_bytes, 0);
    assert_eq!(frames(&records).len(), 4);
}

#[test]
fn segments_out_of_order_and_repeated_are_read_once_in_order() {
    let exchanges: Vec<_> = (1..=3).map(|t| exchange(t, 2)).collect();
    let mut packets = conversation(Link::Ethernet, &exchanges);
    // The second request split in two, its halves swapped, then both sent again.
    let (request, _) = &exchanges[1];
    let second = packets.remove(2);
    let sequence = 1000 + u32::try_from(exchanges[0].0.len()).unwrap();
    let head = packet(Link::Ethernet, true, sequence, 5000, &request[..5]);
    let tail = packet(Link::Ethernet, true, sequence + 5, 5000, &request[5..]);
    packets.splice(2..2, [tail.clone(), head, second, tail]);
    let (records, _) = sniff(&pcap(1, &timed(packets)));
    let found = frames(&records);
    assert_eq!(found.len(), 6, "{found:?}");
    assert!(found.iter().all(|(_, _, valid, _)| *valid), "{found:?}");
    let transactions: Vec<u16> = found.iter().map(|f| f.0).collect();
    assert_eq!(transactions, [1, 1, 2, 2, 3, 3]);
}

#[test]
fn after_a_lost_segment_the_next_frames_are_found_and_none_invented() {
    let exchanges: Vec<_> = (1..=4).map(|t| exchange(t, 3)).collect();
    let mut packets = conversation(Link::Ethernet, &exchanges);
    // The second request never reached the capture; its answer did.
    packets.remove(2);
    let (records, _) = sniff(&pcap(1, &timed(packets)));
    let found = frames(&records);
    assert_eq!(
        found,
        [
            (1, Kind::Request, true, None),
            (1, Kind::Response, true, Some(1)),
            (2, Kind::Response, true, None),
            (3, Kind::Request, true, None),
            (3, Kind::Response, true, Some(4)),
            (4, Kind::Request, true, None),
            (4, Kind::Response, true, Some(6)),
        ]
    );
}

#[test]
fn a_capture_that_starts_mid_connection_picks_up_at_the_first_header_that_reads() {
    let (first, first_answer) = exchange(1, 4);
    let (second, second_answer) = exchange(2, 1);
    // The capture begins with the last 5 bytes of a request, glued to the next one.
    let mut bytes = first[first.len() - 5..].to_vec();
    bytes.extend(&second);
    let packets = vec![
        packet(Link::Ethernet, true, 7777, 100, &bytes),
        packet(
            Link::Ethernet,
            false,
            100,
            7777 + bytes.len() as u32,
            &second_answer,
        ),
    ];
    let (records, _) = sniff(&pcap(1, &timed(packets)));
    assert_eq!(
        frames(&records),
        [
            (2, Kind::Request, true, None),
            (2, Kind::Response, true, Some(1))
        ]
    );
    let _ = first_answer;
}

#[test]
fn a_stream_on_port_502_that_is_no_modbus_gives_no_frame() {
    let text = b"GET / HTTP/1.1\r\nHost: plc\r\n\r\n".to_vec();
    let giant = {
        let mut adu = mbap(9, &[3, 0, 0, 0, 1]);
        adu[4..6].copy_from_slice(&[0xFF, 0xFF]);
        adu
    };
    let (request, answer) = exchange(5, 1);
    let mut bytes = text.clone();
    bytes.extend(&giant);
    let packets = vec![
        packet(Link::Ethernet, true, 1, 1, &bytes),
        packet(Link::Ethernet, true, 1 + bytes.len() as u32, 1, &request),
        packet(
            Link::Ethernet,
            false,
            1,
            1 + (bytes.len() + request.len()) as u32,
            &answer,
        ),
    ];
    let (records, _) = sniff(&pcap(1, &timed(packets)));
    assert_eq!(
        frames(&records),
        [
            (5, Kind::Request, true, None),
            (5, Kind::Response, true, Some(2))
        ]
    );
}

#[test]
fn a_packet_cut_by_the_snap_length_shows_its_frame_as_cut() {
    let exchanges: Vec<_> = (1..=2).map(|t| exchange(t, 40)).collect();
    let mut packets = timed(conversation(Link::Ethernet, &exchanges));
    // The first answer captured up to 70 bytes only: 16 of its 89.
    let whole = packets[1].1.len() as u32;
    packets[1].1.truncate(70);
    packets[1].2 = Some(whole);
    let (records, read) = sniff(&pcap(1, &packets));
    assert_eq!(read, Ok(4));
    assert_eq!(
        frames(&records),
        [
            (1, Kind::Request, true, None),
            (1, Kind::Response, false, None),
            (2, Kind::Request, true, None),
            (2, Kind::Response, true, Some(3)),
        ]
    );
}

#[test]
fn a_file_cut_off_or_of_another_kind_is_said_so() {
    let exchanges: Vec<_> = (1..=2).map(|t| exchange(t, 2)).collect();
    let file = pcap(1, &timed(conversation(Link::Ethernet, &exchanges)));
    let (records, read) = sniff(&file[..file.len() - 10]);
    assert_eq!(read, Err(CaptureError::Truncated(3)));
    assert_eq!(frames(&records).len(), 3);
    assert!(!is_capture(b"\x11\x03\x00\x6B"));
    assert_eq!(sniff(b"").1, Err(CaptureError::Empty));
    assert_eq!(
        sniff(b"not a capture at all").1,
        Err(CaptureError::NotACapture)
    );
}

proptest! {
    #[test]
    fn arbitrary_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..2000)) {
        let _ = sniff(&bytes);
        // Behind a pcap header, as packets of every link type.
        for link_type in [0, 1, 101, 113, 276] {
            let mut file = pcap(link_type, &[]);
            file.extend(&bytes);
            let _ = sniff(&file);
            let _ = sniff(&pcap(link_type, &[(0, bytes.clone(), None)]));
        }
    }

    #[test]
    fn any_payload_on_port_502_never_panics(
        payloads in proptest::collection::vec(proptest::collection::vec(any::<u8>(), 0..300), 1..8)
    ) {
        let mut sequence = 1u32;
        let packets: Vec<_> = payloads
            .iter()
            .map(|p| {
                let bytes = packet(Link::Ethernet, true, sequence, 1, p);
                sequence = sequence.wrapping_add(p.len() as u32);
                bytes
            })
            .collect();
        let _ = sniff(&pcap(1, &timed(packets)));
    }

    /// However a stream of frames is cut into segments, the same frames come out.
    #[test]
    fn segments_of_any_size_give_the_frames_of_one_segment(
        cuts in proptest::collection::vec(1usize..40, 1..20)
    ) {
        let stream: Vec<u8> = (1..=5).flat_map(|t| exchange(t, t as u8).0).collect();
        let whole = sniff(&pcap(1, &timed(vec![packet(Link::Ethernet, true, 1, 1, &stream)]))).0;
        let mut packets = Vec::new();
        let mut at = 0;
        for cut in cuts.iter().cycle() {
            if at >= stream.len() {
                break;
            }
            let end = (at + cut).min(stream.len());
            packets.push(packet(Link::Ethernet, true, 1 + at as u32, 1, &stream[at..end]));
            at = end;
        }
        let parts = sniff(&pcap(1, &timed(packets))).0;
        let kinds = |records: &[Record]| frames(records).iter().map(|f| (f.0, f.1, f.2)).collect::<Vec<_>>();
        prop_assert_eq!(kinds(&parts), kinds(&whole));
        prop_assert_eq!(kinds(&whole).len(), 5);
    }
}

fn hex(spaced: &str) -> Vec<u8> {
    spaced
        .split(' ')
        .map(|b| u8::from_str_radix(b, 16).unwrap())
        .collect()
}

mod streams;
