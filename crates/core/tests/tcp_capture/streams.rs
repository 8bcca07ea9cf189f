//! pcapng files, RTU over TCP, and transactions lost, cut or completed out of order

use super::*;

#[test]
fn a_record_larger_than_the_buffer_is_read_and_a_giant_length_is_refused() {
    // A loopback packet larger than the buffer: requests the kernel coalesced.
    let (request, answer) = exchange(1, 1);
    let payload = request.repeat(65_480 / request.len());
    let mut big = pcap(1, &[(0, packet(Link::Ipv6, true, 1, 1, &payload), None)]);
    assert!(big.len() > 65_536 + 24);
    let (records, read) = sniff(&big);
    assert_eq!(read, Ok(1));
    assert_eq!(frames(&records).len(), payload.len() / request.len());
    // A record that says it holds 4 GB: damaged, said at once, nothing of that size kept.
    big[32..36].copy_from_slice(&0xFFFF_FFF0u32.to_le_bytes());
    let started = std::time::Instant::now();
    let (_, read) = sniff(&big);
    assert!(
        matches!(
            read,
            Err(CaptureError::Damaged(0) | CaptureError::Truncated(0))
        ),
        "{read:?}"
    );
    assert!(started.elapsed() < std::time::Duration::from_secs(2));
    let _ = answer;
}

/// What `sniff --interface --save` writes reads back as the packets it was given.
#[test]
fn a_pcapng_written_reads_back_packet_for_packet() {
    use mbtool_core::sniff::pcap::PcapNgWriter;
    let exchanges: Vec<_> = (1..=3).map(|t| exchange(t, t as u8)).collect();
    let packets = timed(conversation(Link::Ethernet, &exchanges));
    let mut file = Vec::new();
    let mut writer = PcapNgWriter::new(&mut file, 1).unwrap();
    for (time, bytes, _) in &packets {
        writer.packet(*time, bytes, bytes.len() as u32).unwrap();
    }
    writer.flush().unwrap();
    let mut read = Vec::new();
    read_packets(&file[..], |packet| {
        read.push((packet.time_us, packet.data.to_vec(), packet.link));
        true
    })
    .unwrap();
    let given: Vec<_> = packets.iter().map(|(t, b, _)| (*t, b.clone(), 1)).collect();
    assert_eq!(read, given);
    assert_eq!(frames(&sniff(&file).0).len(), 6);
}

/// RTU frames through a transparent gateway (`--mode rtu --tcp-port`): framed by their
/// layout and CRC, paired by unit and function, oldest first.
#[test]
fn rtu_over_tcp_is_framed_by_the_rtu_framer() {
    let request = hex("11 03 00 6B 00 03 76 87");
    let answer = hex("11 03 06 02 2B 00 00 00 64 C8 BA");
    let packets = vec![
        packet(Link::Ethernet, true, 1, 1, &request),
        packet(Link::Ethernet, false, 1, 9, &answer),
        // Both again, glued in one segment each way with a second request.
        packet(
            Link::Ethernet,
            true,
            9,
            12,
            &[request.clone(), request.clone()].concat(),
        ),
        packet(
            Link::Ethernet,
            false,
            12,
            25,
            &[answer.clone(), answer.clone()].concat(),
        ),
    ];
    let (_, records, _) = session_of(Mode::Rtu, &pcap(1, &timed(packets)));
    let found = frames(&records);
    assert_eq!(found.len(), 6, "{found:?}");
    assert!(found.iter().all(|(_, _, valid, _)| *valid));
    // Each answer paired. The last frame of a glued pair is taken once what follows
    // supports it (here the end of the capture), as on a serial line without timing.
    let answers: Vec<_> = found
        .iter()
        .filter(|f| f.1 == Kind::Response)
        .map(|f| f.3)
        .collect();
    assert_eq!(answers.len(), 3);
    assert!(answers.iter().all(Option::is_some), "{answers:?}");
    assert_eq!(answers[..2], [Some(1), Some(3)]);
}

/// pcapng with several interfaces, each with its own link type and time units
/// (`if_tsresol`: microseconds by default, nanoseconds, 2^-20 s): each packet is timed by
/// its own interface's units.
#[test]
fn pcapng_interfaces_keep_their_own_time_units() {
    fn block(kind: u32, body: &[u8]) -> Vec<u8> {
        let total = u32::try_from(12 + body.len()).unwrap();
        [
            &kind.to_le_bytes()[..],
            &total.to_le_bytes(),
            body,
            &total.to_le_bytes(),
        ]
        .concat()
    }
    fn interface(link: u16, tsresol: Option<u8>) -> Vec<u8> {
        let mut body = [&link.to_le_bytes()[..], &[0, 0], &65535u32.to_le_bytes()].concat();
        if let Some(resolution) = tsresol {
            body.extend([9, 0, 1, 0, resolution, 0, 0, 0, 0, 0, 0, 0]);
        }
        block(1, &body)
    }
    fn enhanced(interface: u32, units: u64, data: &[u8]) -> Vec<u8> {
        let len = u32::try_from(data.len()).unwrap();
        let mut body = [
            &interface.to_le_bytes()[..],
            &((units >> 32) as u32).to_le_bytes(),
            &(units as u32).to_le_bytes(),
            &len.to_le_bytes(),
            &len.to_le_bytes(),
            data,
        ]
        .concat();
        body.resize(body.len().div_ceil(4) * 4, 0);
        block(6, &body)
    }
    let section = block(
        0x0A0D_0D0A,
        &[&0x1A2B_3C4Du32.to_le_bytes()[..], &[1, 0, 0, 0], &[0xFF; 8]].concat(),
    );
    let (request, answer) = exchange(1, 1);
    let second = 1_700_000_000u64;
    let cooked = |to_server, sequence, ack, payload: &[u8]| {
        packet(Link::CookedV2, to_server, sequence, ack, payload)
    };
    let file = [
        section,
        interface(1, None),
        interface(276, Some(9)),
        interface(1, Some(0x94)),
        enhanced(
            0,
            second * 1_000_000 + 250,
            &packet(Link::Ethernet, true, 1, 1, &request),
        ),
        enhanced(
            1,
            second * 1_000_000_000 + 500_000,
            &cooked(false, 1, 13, &answer),
        ),
        enhanced(2, (second + 1) << 20, &[0; 20]),
    ]
    .concat();
    let mut times = Vec::new();
    let read = read_packets(&file[..], |packet| {
        times.push((packet.link, packet.time_us));
        true
    });
    assert_eq!(read, Ok(3));
    assert_eq!(
        times,
        [
            (1, second * 1_000_000 + 250),
            (276, second * 1_000_000 + 500),
            (1, (second + 1) * 1_000_000)
        ]
    );
    let (records, _) = sniff(&file);
    assert_eq!(
        frames(&records),
        [
            (1, Kind::Request, true, None),
            (1, Kind::Response, true, Some(1))
        ]
    );
}

/// Found by an outside trial: a transaction lost both ways (request and answer), the
/// others acknowledged as sent. The next request comes before its answer, paired, and
/// nothing is called unanswered.
#[test]
fn a_transaction_lost_both_ways_leaves_the_next_one_paired() {
    let exchanges: Vec<_> = (1..=5).map(|t| exchange(t, 3)).collect();
    let mut packets = conversation(Link::Ethernet, &exchanges);
    packets.drain(4..6);
    let (records, _) = sniff(&pcap(1, &timed(packets)));
    let found = frames(&records);
    assert_eq!(
        found,
        [
            (1, Kind::Request, true, None),
            (1, Kind::Response, true, Some(1)),
            (2, Kind::Request, true, None),
            (2, Kind::Response, true, Some(3)),
            (4, Kind::Request, true, None),
            (4, Kind::Response, true, Some(5)),
            (5, Kind::Request, true, None),
            (5, Kind::Response, true, Some(7)),
        ]
    );
    assert!(!records
        .iter()
        .any(|r| matches!(r, Record::Unanswered { .. })));
}

/// Every packet cut by a short snap length just after the function code: each frame is
/// shown cut, none is turned into noise, and no request is called unanswered.
#[test]
fn every_packet_cut_short_shows_every_frame_cut() {
    let exchanges: Vec<_> = (1..=4).map(|t| exchange(t, 10)).collect();
    let packets: Vec<_> = timed(conversation(Link::Ethernet, &exchanges))
        .into_iter()
        .map(|(time, mut bytes, _)| {
            let whole = bytes.len() as u32;
            bytes.truncate(14 + 20 + 20 + 8);
            (time, bytes, Some(whole))
        })
        .collect();
    let (records, _) = sniff(&pcap(1, &packets));
    let found = frames(&records);
    assert_eq!(found.len(), 8, "{found:?}");
    assert!(found.iter().all(|(_, _, valid, _)| !valid), "{found:?}");
    let transactions: Vec<u16> = found.iter().map(|f| f.0).collect();
    assert_eq!(transactions, [1, 1, 2, 2, 3, 3, 4, 4]);
    assert!(!records
        .iter()
        .any(|r| matches!(r, Record::Unanswered { .. })));
}

/// A request whose tail came before its head: it is complete, and timed, in the packet of
/// its head, and its answer's response time counts from there.
#[test]
fn a_request_completed_out_of_order_is_timed_from_its_last_packet() {
    let (request, answer) = exchange(1, 1);
    let mut syn = Vec::new();
    PacketBuilder::ethernet2([1; 6], [2; 6])
        .ipv4(CLIENT, SERVER, 64)
        .tcp(CLIENT_PORT, 502, 0, 1024)
        .syn()
        .write(&mut syn, &[])
        .unwrap();
    let packets = vec![
        (999_000, syn, None),
        (
            1_000_000,
            packet(Link::Ethernet, true, 1 + 5, 1, &request[5..]),
            None,
        ),
        (
            1_002_000,
            packet(Link::Ethernet, true, 1, 1, &request[..5]),
            None,
        ),
        (
            1_003_000,
            packet(Link::Ethernet, false, 1, 1 + request.len() as u32, &answer),
            None,
        ),
    ];
    let (records, _) = sniff(&pcap(1, &packets));
    let places: Vec<_> = records
        .iter()
        .filter_map(|r| match r {
            Record::Frame(frame) => frame
                .tcp
                .map(|p| (p.packet, p.request_packet, p.response_time)),
            _ => None,
        })
        .collect();
    assert_eq!(places, [(3, None, None), (4, Some(3), Some(1000))]);
}

/// A big-endian pcapng (as a big-endian machine writes it) whose interface has an
/// `if_tsoffset`: its times are those of the same file in little-endian.
#[test]
fn a_big_endian_pcapng_with_a_time_offset_reads_as_the_little_endian_one() {
    fn file(big: bool) -> Vec<u8> {
        let u32s = |v: u32| {
            if big {
                v.to_be_bytes()
            } else {
                v.to_le_bytes()
            }
        };
        let u16s = |v: u16| {
            if big {
                v.to_be_bytes()
            } else {
                v.to_le_bytes()
            }
        };
        let block = |kind: u32, body: &[u8]| {
            let total = u32::try_from(12 + body.len()).unwrap();
            [&u32s(kind)[..], &u32s(total), body, &u32s(total)].concat()
        };
        let section = block(
            0x0A0D_0D0A,
            &[&u32s(0x1A2B_3C4D)[..], &u16s(1), &u16s(0), &[0xFF; 8]].concat(),
        );
        let offset = if big {
            5i64.to_be_bytes()
        } else {
            5i64.to_le_bytes()
        };
        let interface = block(
            1,
            &[
                &u16s(1)[..],
                &[0, 0],
                &u32s(65535),
                &u16s(14),
                &u16s(8),
                &offset,
                &[0; 4],
            ]
            .concat(),
        );
        let (request, _) = exchange(1, 1);
        let data = packet(Link::Ethernet, true, 1, 1, &request);
        let mut body = [
            &u32s(0)[..],
            &u32s(0),
            &u32s(2_500_000),
            &u32s(data.len() as u32),
            &u32s(data.len() as u32),
            &data,
        ]
        .concat();
        body.resize(body.len().div_ceil(4) * 4, 0);
        [section, interface, block(6, &body)].concat()
    }
    let times = |file: &[u8]| {
        let mut times = Vec::new();
        read_packets(file, |packet| {
            times.push(packet.time_us);
            true
        })
        .unwrap();
        times
    };
    assert_eq!(times(&file(false)), [7_500_000]);
    assert_eq!(times(&file(true)), [7_500_000]);
}

/// A request whose answer the capture does not hold: while its connection is still open at
/// the end of the capture, the capture may be why; once the connection closed, the server
/// never answered.
#[test]
fn a_request_left_waiting_tells_whether_the_capture_ended_or_the_connection_closed() {
    let exchanges: Vec<_> = (1..=2).map(|t| exchange(t, 2)).collect();
    let mut packets = conversation(Link::Ethernet, &exchanges);
    packets.pop();
    let unanswered = |packets: Vec<Vec<u8>>| -> Vec<(bool, Option<u64>)> {
        let (records, _) = sniff(&pcap(1, &timed(packets)));
        records
            .into_iter()
            .filter_map(|r| match r {
                Record::Unanswered {
                    capture_ended,
                    waited,
                    ..
                } => Some((capture_ended, waited)),
                _ => None,
            })
            .collect()
    };
    // The request is the capture's last packet: it waited no time the capture shows.
    assert_eq!(unanswered(packets.clone()), [(true, None)]);
    let sent: u32 = exchanges.iter().map(|(r, _)| r.len() as u32).sum();
    let answered = exchanges[0].1.len() as u32;
    packets.push(fin(false, 5000 + answered, 1000 + sent));
    packets.push(fin(true, 1000 + sent, 5000 + answered + 1));
    assert_eq!(unanswered(packets), [(false, Some(2000))]);
}
