//! Properties of the codec: every frame we encode decodes back to itself in all three ADUs,
//! a stream decodes the same fed byte by byte or all at once, and no input panics.
#![allow(clippy::unwrap_used, clippy::expect_used)] // a test stops at what it did not expect

use mbtool_core::codec::framing::{Event, Framer};
use mbtool_core::codec::{DeviceIdentification, DeviceObject, FileRecords, FileSpan};
use mbtool_core::codec::{
    Direction, Envelope, Exception, ExceptionCode, Frame, Mode, Pdu, Reading, Request, Response,
    Ways,
};
use mbtool_core::describe::describe_frame;
use mbtool_core::input::hexinput::read_line;
use proptest::collection::vec;
use proptest::prelude::*;

/// An address and a quantity 1..=max that stay inside the 65536 addresses.
fn span(max: u16) -> impl Strategy<Value = (u16, u16)> {
    (1..=max).prop_flat_map(|quantity| {
        (0..=(65536 - u32::from(quantity)) as u16).prop_map(move |address| (address, quantity))
    })
}

fn registers(max: usize) -> impl Strategy<Value = Vec<u16>> {
    vec(any::<u16>(), 1..=max)
}

/// Function codes that have no layout of their own: kept as opaque PDUs.
fn opaque_function() -> impl Strategy<Value = u8> {
    (1u8..0x80).prop_filter("typed function", |f| {
        !matches!(
            f,
            0x01..=0x08 | 0x0F | 0x10 | 0x11 | 0x14 | 0x15 | 0x16 | 0x17 | 0x18 | 0x2B
        )
    })
}

/// A run of records inside a file: file 1-65535, records 0-9999, at most `most` of them.
fn file_place(most: u16) -> impl Strategy<Value = (u16, u16, u16)> {
    (1u16..=u16::MAX, 1..=most).prop_flat_map(|(file, count)| {
        (0..=(10000 - count)).prop_map(move |record| (file, record, count))
    })
}

/// Read File Record groups whose answer fits one PDU: up to 35 groups (7 bytes each in
/// 245), their answers' groups within 245 bytes.
fn file_spans() -> impl Strategy<Value = Vec<FileSpan>> {
    vec(file_place(121), 1..=35)
        .prop_map(|places| {
            let mut answer = 0;
            places
                .into_iter()
                .map(|(file, record, count)| FileSpan {
                    file,
                    record,
                    count,
                })
                .take_while(|span| {
                    answer += 2 + 2 * usize::from(span.count);
                    answer <= 245
                })
                .collect::<Vec<_>>()
        })
        .prop_filter("at least one group", |spans| !spans.is_empty())
}

/// Write File Record groups within 251 bytes of groups.
fn file_writes() -> impl Strategy<Value = Vec<FileRecords>> {
    vec(file_place(20), 1..=8).prop_flat_map(|places| {
        let mut bytes = 0;
        let places: Vec<_> = places
            .into_iter()
            .take_while(|(_, _, count)| {
                bytes += 7 + 2 * usize::from(*count);
                bytes <= 251
            })
            .collect();
        places
            .into_iter()
            .map(|(file, record, count)| {
                vec(any::<u16>(), usize::from(count)).prop_map(move |values| FileRecords {
                    file,
                    record,
                    values,
                })
            })
            .collect::<Vec<_>>()
    })
}

fn request(diagnostic_data: std::ops::RangeInclusive<usize>) -> impl Strategy<Value = Request> {
    prop_oneof![
        span(2000).prop_map(|(address, quantity)| Request::ReadCoils { address, quantity }),
        span(2000)
            .prop_map(|(address, quantity)| Request::ReadDiscreteInputs { address, quantity }),
        span(125)
            .prop_map(|(address, quantity)| Request::ReadHoldingRegisters { address, quantity }),
        span(125).prop_map(|(address, quantity)| Request::ReadInputRegisters { address, quantity }),
        (any::<u16>(), any::<bool>())
            .prop_map(|(address, value)| Request::WriteSingleCoil { address, value }),
        (any::<u16>(), any::<u16>())
            .prop_map(|(address, value)| Request::WriteSingleRegister { address, value }),
        Just(Request::ReadExceptionStatus),
        (any::<u16>(), vec(any::<u8>(), diagnostic_data))
            .prop_map(|(sub_function, data)| Request::Diagnostics { sub_function, data }),
        span(1968).prop_flat_map(|(address, quantity)| {
            vec(any::<bool>(), usize::from(quantity))
                .prop_map(move |values| Request::WriteMultipleCoils { address, values })
        }),
        span(123).prop_flat_map(|(address, quantity)| {
            vec(any::<u16>(), usize::from(quantity))
                .prop_map(move |values| Request::WriteMultipleRegisters { address, values })
        }),
        Just(Request::ReportServerId),
        (any::<u16>(), any::<u16>(), any::<u16>()).prop_map(|(address, and_mask, or_mask)| {
            Request::MaskWriteRegister {
                address,
                and_mask,
                or_mask,
            }
        }),
        (span(125), span(121)).prop_flat_map(
            |((read_address, read_quantity), (write_address, n))| {
                vec(any::<u16>(), usize::from(n)).prop_map(move |values| {
                    Request::ReadWriteMultipleRegisters {
                        read_address,
                        read_quantity,
                        write_address,
                        values,
                    }
                })
            }
        ),
        (any::<u8>(), any::<u8>()).prop_map(|(read_code, object_id)| {
            Request::ReadDeviceIdentification {
                read_code,
                object_id,
            }
        }),
        file_spans().prop_map(|groups| Request::ReadFileRecord { groups }),
        file_writes().prop_map(|groups| Request::WriteFileRecord { groups }),
        any::<u16>().prop_map(|address| Request::ReadFifoQueue { address }),
    ]
}

/// Kept byte for byte, with a length its layout allows where it has one (11, 12): the
/// codec decodes no other (it encodes any, so that `raw` can send a malformed
/// request on purpose).
fn opaque_request() -> impl Strategy<Value = Request> {
    (opaque_function(), vec(any::<u8>(), 0..=252))
        .prop_map(|(function, data)| Request::Other { function, data })
        .prop_filter("a length its layout allows", |r| {
            let mut pdu = Vec::new();
            r.encode(&mut pdu).is_ok() && Request::decode(&pdu).is_ok()
        })
}

fn device_identification() -> impl Strategy<Value = Response> {
    (
        any::<u8>(),
        any::<u8>(),
        any::<bool>(),
        any::<u8>(),
        vec((any::<u8>(), vec(any::<u8>(), 0..40)), 0..5),
    )
        .prop_map(
            |(read_code, conformity, more_follows, next_object_id, objects)| {
                Response::ReadDeviceIdentification(DeviceIdentification {
                    read_code,
                    conformity,
                    more_follows,
                    next_object_id,
                    objects: objects
                        .into_iter()
                        .map(|(id, value)| DeviceObject { id, value })
                        .collect(),
                })
            },
        )
}

fn response(diagnostic_data: std::ops::RangeInclusive<usize>) -> impl Strategy<Value = Response> {
    prop_oneof![
        vec(any::<u8>(), 1..=250).prop_map(|packed| Response::ReadCoils { packed }),
        vec(any::<u8>(), 1..=250).prop_map(|packed| Response::ReadDiscreteInputs { packed }),
        registers(125).prop_map(|values| Response::ReadHoldingRegisters { values }),
        registers(125).prop_map(|values| Response::ReadInputRegisters { values }),
        (any::<u16>(), any::<bool>())
            .prop_map(|(address, value)| Response::WriteSingleCoil { address, value }),
        (any::<u16>(), any::<u16>())
            .prop_map(|(address, value)| Response::WriteSingleRegister { address, value }),
        any::<u8>().prop_map(|status| Response::ReadExceptionStatus { status }),
        (any::<u16>(), vec(any::<u8>(), diagnostic_data))
            .prop_map(|(sub_function, data)| Response::Diagnostics { sub_function, data }),
        span(1968)
            .prop_map(|(address, quantity)| Response::WriteMultipleCoils { address, quantity }),
        span(123)
            .prop_map(|(address, quantity)| Response::WriteMultipleRegisters { address, quantity }),
        vec(any::<u8>(), 0..=251).prop_map(|data| Response::ReportServerId { data }),
        (any::<u16>(), any::<u16>(), any::<u16>()).prop_map(|(address, and_mask, or_mask)| {
            Response::MaskWriteRegister {
                address,
                and_mask,
                or_mask,
            }
        }),
        registers(125).prop_map(|values| Response::ReadWriteMultipleRegisters { values }),
        device_identification(),
        vec(registers(20), 1..=10)
            .prop_filter("within 245 bytes", |groups| {
                groups.iter().map(|g| 2 + 2 * g.len()).sum::<usize>() <= 245
            })
            .prop_map(|groups| Response::ReadFileRecord { groups }),
        file_writes().prop_map(|groups| Response::WriteFileRecord { groups }),
        vec(any::<u16>(), 0..=31).prop_map(|values| Response::ReadFifoQueue { values }),
    ]
}

fn opaque_response() -> impl Strategy<Value = Response> {
    (opaque_function(), vec(any::<u8>(), 0..=252))
        .prop_map(|(function, data)| Response::Other { function, data })
        .prop_filter("a length its layout allows", |r| {
            let mut pdu = Vec::new();
            r.encode(&mut pdu).is_ok() && Response::decode(&pdu).is_ok()
        })
}

fn exception() -> impl Strategy<Value = Exception> {
    (1u8..0x80, any::<u8>()).prop_map(|(function, code)| Exception {
        function,
        code: ExceptionCode(code),
    })
}

fn mode() -> impl Strategy<Value = Mode> {
    prop_oneof![Just(Mode::Rtu), Just(Mode::Ascii), Just(Mode::Tcp)]
}

/// A frame in any mode; the transaction id exists only over TCP.
fn frame(pdu: impl Strategy<Value = Pdu>) -> impl Strategy<Value = Frame> {
    (mode(), any::<u8>(), any::<u16>(), pdu).prop_map(|(mode, slave, transaction, pdu)| Frame {
        mode,
        slave,
        transaction: if mode == Mode::Tcp { transaction } else { 0 },
        pdu,
    })
}

fn any_pdu() -> impl Strategy<Value = Pdu> {
    prop_oneof![
        request(0..=250).prop_map(Pdu::Request),
        opaque_request().prop_map(Pdu::Request),
        response(0..=250).prop_map(Pdu::Response),
        opaque_response().prop_map(Pdu::Response),
        exception().prop_map(Pdu::Exception),
    ]
}

/// PDUs whose length the stream decoder can tell from their first bytes (diagnostics
/// carry the usual two data bytes).
fn framed_pdu() -> impl Strategy<Value = Pdu> {
    prop_oneof![
        request(2..=2).prop_map(Pdu::Request),
        response(2..=2).prop_map(Pdu::Response),
        exception().prop_map(Pdu::Exception),
    ]
}

fn direction_of(pdu: &Pdu) -> Direction {
    match pdu {
        Pdu::Request(_) => Direction::Request,
        _ => Direction::Response,
    }
}

/// Feeds `stream` to a framer in pieces of `piece` bytes, collecting the frames it finds.
fn decode_stream(mode: Mode, direction: Direction, stream: &[u8], piece: usize) -> Vec<Frame> {
    let mut framer = Framer::new(mode, 0.0, 0);
    let mut events = Vec::new();
    for chunk in stream.chunks(piece.max(1)) {
        framer.push(chunk, &mut events);
    }
    framer.finish(&mut events);
    events
        .into_iter()
        .filter_map(|event| match event {
            Event::Frame(found) => Frame::decode(mode, &found.bytes, direction).ok(),
            Event::Noise(_) => None,
        })
        .collect()
}

/// Frames `stream` in order, all at once.
fn events_in_order(mode: Mode, stream: &[u8]) -> Vec<Event> {
    let mut framer = Framer::new(mode, 0.0, 0);
    framer.end_cut_frames();
    let mut events = Vec::new();
    framer.push(stream, &mut events);
    framer.finish(&mut events);
    events
}

/// Frames `stream` in blocks cut at `cuts`, each framed ahead from its own start and
/// caught up with; also says how many blocks were met.
fn events_ahead(mode: Mode, stream: &[u8], cuts: &[usize]) -> (Vec<Event>, usize) {
    let mut framer = Framer::new(mode, 0.0, 0);
    framer.end_cut_frames();
    let mut events = Vec::new();
    let mut bounds: Vec<usize> = cuts.iter().map(|cut| cut % (stream.len() + 1)).collect();
    bounds.extend([0, stream.len()]);
    bounds.sort_unstable();
    bounds.dedup();
    let mut met = 0;
    for (i, pair) in bounds.windows(2).enumerate() {
        let block = &stream[pair[0]..pair[1]];
        if i == 0 {
            framer.push(block, &mut events);
        } else {
            let ahead = framer
                .starting_at(pair[0] as u64)
                .frame_ahead(block, Vec::new());
            if let Some(mut rest) = framer.catch_up(block, ahead, &mut events) {
                met += 1;
                events.extend(rest.events.drain(rest.from..));
            }
        }
    }
    framer.finish(&mut events);
    (events, met)
}

/// A line's traffic: frames of both directions, some cut short, with noise between them:
/// a glitch byte or two, random bytes, a line held low or high, or a long line of text.
fn traffic(mode: Mode) -> impl Strategy<Value = Vec<u8>> {
    let piece = (
        prop_oneof![
            request(2..=2).prop_map(Pdu::Request),
            response(2..=2).prop_map(Pdu::Response),
            exception().prop_map(Pdu::Exception),
        ],
        1u8..=247,
        prop_oneof![
            8 => vec(any::<u8>(), 0..3),
            1 => vec(any::<u8>(), 0..120),
            1 => (prop_oneof![Just(0u8), Just(0xFF)], 0usize..300).prop_map(|(b, n)| vec![b; n]),
            // A line of text as long as a frame may be, or longer.
            1 => (400usize..700).prop_map(|n| [&b":"[..], &vec![b'0'; n], b"\r\n"].concat()),
        ],
        0usize..12,
    );
    vec(piece, 1..40).prop_map(move |pieces| {
        let mut stream = Vec::new();
        for (pdu, slave, noise, cut) in pieces {
            let frame = Frame {
                mode,
                slave,
                transaction: 0,
                pdu,
            }
            .encode()
            .unwrap();
            // One frame in twelve is cut short, by one byte or more.
            let keep = if cut == 0 {
                frame.len() / 2
            } else {
                frame.len()
            };
            stream.extend_from_slice(&frame[..keep]);
            stream.extend(noise);
        }
        stream
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// The ways a PDU of any function reads, told without reading its values, are the
    /// ways reading it finds: whole, or with a byte changed, cut or added.
    #[test]
    fn the_ways_any_pdu_reads_are_told_as_reading_it_finds(
        pdu in any_pdu(),
        change in 0..4u8,
        at in any::<prop::sample::Index>(),
        byte in any::<u8>(),
    ) {
        let mut bytes = Vec::new();
        pdu.encode(&mut bytes).unwrap();
        let at = at.index(bytes.len());
        match change {
            1 => bytes[at] = byte,
            2 => bytes.truncate(at),
            3 => bytes.push(byte),
            _ => {}
        }
        let expected = match Reading::infer(&bytes) {
            Reading::One(Pdu::Request(_)) => Ways::Request,
            Reading::One(_) => Ways::Answer,
            Reading::Both { .. } => Ways::Both,
            Reading::Neither { .. } => Ways::Neither,
        };
        prop_assert_eq!(Ways::of(&bytes), expected, "{:02X?}", bytes);
    }

    /// A master that has sent a request takes its answer on the answer's last byte, never
    /// waiting for silence or its timeout: the layout and the request tell the length.
    #[test]
    fn an_awaited_answer_is_complete_on_its_last_byte(
        slave in 1u8..=247,
        pdu in prop_oneof![
            response(2..=2).prop_map(Pdu::Response),
            exception().prop_map(Pdu::Exception),
        ],
        piece in 1usize..300,
    ) {
        let bytes = Frame { mode: Mode::Rtu, slave, transaction: 0, pdu: pdu.clone() }
            .encode()
            .expect("generated frames keep the protocol limits");
        // 19200 baud: a character every 573 us, silence after 2005 us.
        let mut framer = Framer::new(Mode::Rtu, 573.0, 2005);
        framer.await_answer(slave, pdu.function() & 0x7F);
        let mut events = Vec::new();
        let mut time = 1_000_000;
        for chunk in bytes.chunks(piece) {
            time += 573 * chunk.len() as u64;
            framer.push_at(chunk, time, &mut events);
        }
        let found: Vec<&[u8]> = events
            .iter()
            .filter_map(|event| match event {
                Event::Frame(found) if found.broken.is_none() => Some(found.bytes.as_slice()),
                _ => None,
            })
            .collect();
        prop_assert_eq!(found, vec![bytes.as_slice()], "{}", mbtool_core::codec::hex::spaced_hex(&bytes));
    }

    #[test]
    fn every_frame_decodes_back_to_itself(frame in frame(any_pdu())) {
        let bytes = frame.encode().expect("generated frames keep the protocol limits");
        let decoded = Frame::decode(frame.mode, &bytes, direction_of(&frame.pdu));
        prop_assert_eq!(decoded, Ok(frame.clone()));
        // The same frame described for a person is valid and names the same slave.
        let report = describe_frame(&bytes, Some(frame.mode), Some(direction_of(&frame.pdu)));
        prop_assert!(report.valid, "{:?}", report.error);
        prop_assert_eq!(report.slave, frame.slave);
    }

    #[test]
    fn a_stream_decodes_the_same_byte_by_byte_and_all_at_once(
        frames in (mode(), any::<bool>()).prop_flat_map(|(mode, requests)| {
            let pdu = if requests {
                request(2..=2).prop_map(Pdu::Request).boxed()
            } else {
                prop_oneof![
                    response(2..=2).prop_map(Pdu::Response),
                    exception().prop_map(Pdu::Exception)
                ].boxed()
            };
            vec((any::<u8>(), pdu), 1..8).prop_map(move |frames| {
                frames.into_iter().enumerate().map(|(i, (slave, pdu))| Frame {
                    mode, slave, transaction: if mode == Mode::Tcp { i as u16 } else { 0 }, pdu,
                }).collect::<Vec<_>>()
            })
        }),
        piece in 1usize..40,
    ) {
        let encoded: Vec<Vec<u8>> = frames.iter().map(|f| f.encode().unwrap()).collect();
        let stream = encoded.concat();
        let (mode, direction) = (frames[0].mode, direction_of(&frames[0].pdu));
        let whole = decode_stream(mode, direction, &stream, stream.len());
        prop_assert_eq!(&decode_stream(mode, direction, &stream, 1), &whole);
        prop_assert_eq!(&decode_stream(mode, direction, &stream, piece), &whole);
        // An RTU frame whose CRC ends in 00 reads valid one byte shorter too; where the
        // shorter reading travels the other way, the turn of the bus (request, then
        // answer) tells them apart, and a stream of requests only, or answers only, does
        // not take turns.
        let ambiguous = mode == Mode::Rtu
            && encoded.iter().any(|frame| frame.last() == Some(&0));
        if !ambiguous {
            prop_assert_eq!(&whole, &frames);
        }
    }

    #[test]
    fn noise_framed_in_blocks_ahead_is_framed_as_in_order(
        noise in vec(any::<u8>(), 0..3000),
        cuts in vec(any::<usize>(), 1..6),
    ) {
        let (ahead, _) = events_ahead(Mode::Rtu, &noise, &cuts);
        prop_assert_eq!(ahead, events_in_order(Mode::Rtu, &noise));
    }

    #[test]
    fn a_stream_framed_in_blocks_ahead_is_framed_as_in_order(
        (mode, stream) in prop_oneof![Just(Mode::Rtu), Just(Mode::Ascii)]
            .prop_flat_map(|mode| (Just(mode), traffic(mode))),
        cuts in vec(any::<usize>(), 1..6),
    ) {
        let (ahead, _) = events_ahead(mode, &stream, &cuts);
        prop_assert_eq!(ahead, events_in_order(mode, &stream));
    }

    #[test]
    fn the_framer_finds_each_framed_pdu(frame in frame(framed_pdu())) {
        let bytes = frame.encode().unwrap();
        prop_assert_eq!(decode_stream(frame.mode, direction_of(&frame.pdu), &bytes, bytes.len()), vec![frame.clone()]);
    }

    #[test]
    fn arbitrary_bytes_never_panic_a_decoder(bytes in vec(any::<u8>(), 0..600)) {
        for mode in [Mode::Rtu, Mode::Ascii, Mode::Tcp] {
            let _ = Envelope::open(mode, &bytes);
            for direction in [Direction::Request, Direction::Response] {
                let _ = Frame::decode(mode, &bytes, direction);
                let _ = describe_frame(&bytes, Some(mode), Some(direction));
            }
            let _ = describe_frame(&bytes, Some(mode), None);
        }
        let _ = describe_frame(&bytes, None, None);
        for mode in [Mode::Rtu, Mode::Ascii, Mode::Tcp] {
            let _ = decode_stream(mode, Direction::Request, &bytes, 3);
        }
        let _ = Reading::infer(&bytes);
        let _ = read_line(&bytes);
    }

    #[test]
    fn arbitrary_frames_with_a_good_crc_never_panic(body in vec(any::<u8>(), 1..300)) {
        // Most random bytes fail the CRC first; these reach the PDU parsers.
        let mut frame = body.clone();
        frame.extend_from_slice(&mbtool_core::codec::checksum::crc16(&body).to_le_bytes());
        let _ = describe_frame(&frame, Some(Mode::Rtu), None);
        for direction in [Direction::Request, Direction::Response] {
            let _ = describe_frame(&frame, Some(Mode::Rtu), Some(direction));
            let _ = decode_stream(Mode::Rtu, direction, &frame, 7);
        }
    }

    #[test]
    fn a_frame_on_a_log_line_reads_back_whatever_its_spelling_and_its_words(
        bytes in vec(any::<u8>(), 4..60),
        spelling in 0..5usize,
        mark in 0..3usize,
    ) {
        let hex: Vec<String> = bytes.iter().map(|b| format!("{b:02X}")).collect();
        let spelled = match spelling {
            0 => hex.join(" "),
            1 => hex.join(":"),
            2 => hex.iter().map(|h| format!("[{h}]")).collect(),
            3 => format!("{{{}}};", hex.iter().map(|h| format!("0x{h}")).collect::<Vec<_>>().join(", ")),
            _ => hex.join("-"),
        };
        let (word, direction) = [("", None), ("TX:", Some(Direction::Request)), ("<", Some(Direction::Response))][mark];
        // Bytes in [] are what libmodbus sent, when no mark says otherwise.
        let direction = direction.or((spelling == 2).then_some(Direction::Request));
        let text = format!("2026-11-23 08:15:02.125 {word} {spelled}  CRC ok  # from the panel");
        let frame = read_line(text.as_bytes()).map_err(|e| TestCaseError::fail(format!("{text}: {e}")))?;
        prop_assert_eq!(frame.len(), 1, "{}", text);
        let frame = frame.into_iter().next().ok_or_else(|| TestCaseError::fail(text.clone()))?;
        prop_assert_eq!(frame.bytes, bytes, "{}", text);
        prop_assert_eq!(frame.direction, direction);
    }

    #[test]
    fn arbitrary_text_never_panics(text in ".{0,300}") {
        for frame in read_line(text.as_bytes()).unwrap_or_default() {
            let _ = describe_frame(&frame.bytes, None, frame.direction);
        }
        let _ = mbtool_core::input::hexdump::dump_line(text.as_bytes());
    }

    /// A frame dumped as each tool dumps it reads back, line by line, the offsets counting.
    #[test]
    fn a_dump_reads_back_as_its_bytes(bytes in vec(any::<u8>(), 1..100), tool in 0..4usize) {
        let mut read = Vec::new();
        for (i, line) in bytes.chunks(16).enumerate() {
            let hex: Vec<String> = line.iter().map(|b| format!("{b:02x}")).collect();
            let chars: String = line.iter().map(|b| if b.is_ascii_graphic() { *b as char } else { '.' }).collect();
            let offset = i * 16;
            let text = match tool {
                0 => format!("{offset:04x}   {:<47}   {chars}", hex.join(" ")),
                1 => format!("{offset:08x}  {:<48} |{chars}|", hex.join(" ")),
                2 => format!("{offset:08x}: {:<39}  {chars}", hex.chunks(2).map(|p| p.concat()).collect::<Vec<_>>().join(" ")),
                _ => format!("{offset:06x} {}", hex.join(" ")),
            };
            let line = mbtool_core::input::hexdump::dump_line(text.as_bytes())
                .ok_or_else(|| TestCaseError::fail(text.clone()))?;
            prop_assert!(line.is_at(offset), "{}", text);
            read.extend(line.bytes);
        }
        prop_assert_eq!(read, bytes);
    }
}

/// The real recordings, repeated and cut into blocks at every few hundred bytes: the blocks
/// framed ahead are met nearly at once, so that framing them ahead pays, and the frames are
/// those found in order.
#[test]
fn real_recordings_framed_in_blocks_ahead_meet_and_match() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/captures");
    for name in ["wizmodbus", "brainchild-io-16do", "flowmeter_graph_tool"] {
        let recording = std::fs::read(format!("{dir}/{name}.bin")).unwrap();
        let stream = recording.repeat(20);
        let cuts: Vec<usize> = (1..stream.len() / 337).map(|i| i * 337).collect();
        let (ahead, met) = events_ahead(Mode::Rtu, &stream, &cuts);
        assert_eq!(ahead, events_in_order(Mode::Rtu, &stream), "{name}");
        assert!(
            met * 10 >= cuts.len() * 9,
            "{name}: met {met} of {} blocks",
            cuts.len()
        );
    }
}

/// Random bytes hold no frame to meet at: blocks framed ahead meet the framer that catches
/// up inside the noise, and what is found is what it finds in order, runs of noise whole.
#[test]
fn random_bytes_framed_in_blocks_ahead_meet_inside_noise_and_match() {
    use proptest::strategy::ValueTree;
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let stream = vec(any::<u8>(), 300_000)
        .new_tree(&mut runner)
        .unwrap()
        .current();
    let cuts: Vec<usize> = (1..stream.len() / 4099).map(|i| i * 4099).collect();
    let (ahead, met) = events_ahead(Mode::Rtu, &stream, &cuts);
    assert_eq!(ahead, events_in_order(Mode::Rtu, &stream));
    assert!(
        met * 10 >= cuts.len() * 9,
        "met {met} of {} blocks",
        cuts.len()
    );
}

mod sniffer {
    use super::*;
    use mbtool_core::sniff::session::{Filter, Record, Session};

    fn sniff(chunks: &[&[u8]], mode: Mode) -> Vec<Record> {
        let mut session = Session::new(mode, 573.0, 2005, Filter::default());
        let mut records = Vec::new();
        for chunk in chunks {
            session.push(chunk, &mut records);
        }
        session.finish(None, &mut records);
        records
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(300))]

        #[test]
        fn arbitrary_bytes_never_panic_the_sniffer(
            bytes in vec(any::<u8>(), 0..700),
            gaps in vec(0u64..10_000, 0..700),
        ) {
            for mode in [Mode::Rtu, Mode::Ascii] {
                let _ = sniff(&[&bytes], mode);
                let mut session = Session::new(mode, 573.0, 2005, Filter::default());
                let mut records = Vec::new();
                let mut time = 0;
                for (byte, gap) in bytes.iter().zip(gaps.iter().chain(std::iter::repeat(&0))) {
                    time += gap;
                    session.push_byte_at(*byte, time, &mut records);
                    session.idle(time + gap, &mut records);
                }
                session.finish(Some(time), &mut records);
            }
        }

        #[test]
        fn the_sniffer_reads_the_same_byte_by_byte_and_all_at_once(
            frames in vec(frame(framed_pdu()), 1..12),
            noise in vec(any::<u8>(), 0..4),
        ) {
            let mut stream = noise.clone();
            for frame in frames.iter().filter(|f| f.mode == Mode::Rtu) {
                stream.extend(frame.encode().unwrap());
            }
            let whole = sniff(&[&stream], Mode::Rtu);
            let singles: Vec<&[u8]> = stream.chunks(1).collect();
            prop_assert_eq!(whole, sniff(&singles, Mode::Rtu));
        }
    }
}
