use super::frame_json::{report_fields, seconds, tcp_fields, JsonTcp};
use super::*;
use crate::output::columns::{column, Align, ColumnText, Seconds};
use crate::output::json::JsonObject;
use mbtool_core::codec::Mode;
use mbtool_core::sniff::session::{Filter, Session};

/// What sniff writes in `format` for a stream of bytes without timing, with its summary.
fn sniffed(stream: &[u8], format: Format) -> String {
    let mut session = Session::new(Mode::Rtu, 1145.8, 4010, Filter::default());
    let mut records = Vec::new();
    session.push(stream, &mut records);
    session.finish(None, &mut records);
    let mut writer = writer(format, false);
    let mut out = Vec::new();
    for record in &records {
        writer.record(&mut out, record).unwrap();
    }
    writer.summary(&mut out, session.counts(), None).unwrap();
    String::from_utf8(out).unwrap()
}

/// Sniff's JSON Lines for a stream of bytes without timing.
fn json_of(stream: &[u8]) -> Vec<serde_json::Value> {
    sniffed(stream, Format::Json)
        .lines()
        .map(|line| serde_json::from_str(line).unwrap())
        .collect()
}

/// The JSON of a frame's report is written field by field for speed; it must stay what
/// `FrameReport`'s own `Serialize` gives (as `decode -o json` writes it), to the byte.
#[test]
fn a_report_as_a_sniffed_frame_is_its_serialize_to_the_byte() {
    use mbtool_core::codec::checksum::crc16;
    use mbtool_core::codec::Direction;
    use mbtool_core::describe::describe_frame;
    let mut rng = fastrand::Rng::with_seed(23);
    let functions = [
        1, 2, 3, 4, 5, 6, 7, 8, 11, 12, 15, 16, 17, 20, 21, 22, 23, 24, 43, 65,
    ];
    for round in 0..5000 {
        let mut frame = vec![rng.u8(0..=247), functions[rng.usize(..functions.len())]];
        if rng.u8(..) < 40 {
            frame[1] |= 0x80;
        }
        // Half of them with a byte count that fits, so that answers carry values.
        let len = rng.usize(0..24);
        if round % 2 == 0 {
            frame.push(len as u8);
        }
        frame.extend((0..len).map(|_| rng.u8(..)));
        frame.extend_from_slice(&crc16(&frame).to_le_bytes());
        if round % 7 == 0 {
            frame[2] ^= 0x10;
        }
        let direction = [None, Some(Direction::Request), Some(Direction::Response)][round % 3];
        let report = describe_frame(&frame, Some(Mode::Rtu), direction);
        let mut line = Vec::new();
        let mut object = JsonObject::open(&mut line);
        report_fields(&mut object, &report).unwrap();
        object.close();
        assert_eq!(
            String::from_utf8(line).unwrap(),
            serde_json::to_string(&report).unwrap(),
            "{frame:02X?}"
        );
    }
}

#[test]
fn the_table_summary_counts_a_malformed_frame() {
    use mbtool_core::codec::checksum::crc16;
    // Read holding registers with an odd byte count, or a request for 515 registers:
    // neither way does it read.
    let mut frame = vec![0x11, 0x03, 0x03, 0x01, 0x02, 0x03];
    frame.extend_from_slice(&crc16(&frame).to_le_bytes());
    let mut session = Session::new(Mode::Rtu, 1145.8, 4010, Filter::default());
    let mut records = Vec::new();
    session.push(&frame, &mut records);
    session.finish(None, &mut records);
    let mut out = Vec::new();
    writer(Format::Table, false)
        .summary(&mut out, session.counts(), None)
        .unwrap();
    let out = String::from_utf8(out).unwrap();
    assert!(
        out.starts_with("summary: 1 frame (0 requests, 0 answers, 0 exceptions, 1 malformed),"),
        "{out}"
    );
}

#[test]
fn a_request_noise_and_its_answer_as_json_lines() {
    let stream = [
        &[0x11, 0x03, 0x00, 0x6B, 0x00, 0x03, 0x76, 0x87][..],
        &[0x00],
        &[
            0x11, 0x03, 0x06, 0x02, 0x2B, 0x00, 0x00, 0x00, 0x64, 0xC8, 0xBA,
        ],
    ]
    .concat();
    let lines = json_of(&stream);
    let kinds: Vec<&str> = lines.iter().map(|l| l["type"].as_str().unwrap()).collect();
    assert_eq!(kinds, ["frame", "noise", "frame", "summary"]);
    assert_eq!(lines[0]["bytes"], "11 03 00 6B 00 03 76 87");
    assert_eq!(lines[0]["kind"], "request");
    assert_eq!(lines[1]["count"], 1);
    assert_eq!(lines[1]["bytes"], "00");
    assert_eq!(lines[2]["kind"], "response");
    assert_eq!(lines[3]["frames"], 2);
    assert_eq!(lines[3]["noise_bytes"], 1);
}

/// Sniff's table for a stream of bytes without timing, a line each.
fn table_of(stream: &[u8]) -> Vec<String> {
    sniffed(stream, Format::Table)
        .lines()
        .map(String::from)
        .collect()
}

fn rtu(body: &[u8]) -> Vec<u8> {
    let crc = mbtool_core::codec::checksum::crc16(body);
    [body, &crc.to_le_bytes()[..]].concat()
}

#[test]
fn wide_values_leave_the_columns_after_them_in_place() {
    let stream = [
        rtu(&[0x11, 0x03, 0x00, 0x6B, 0x00, 0x03]),
        rtu(&[0x11, 0x2B, 0x0E, 0x01, 0x00]),
        rtu(&[0xF7, 0x64, 0x01, 0x02, 0x03]),
    ]
    .concat();
    let lines = table_of(&stream);
    let frames: Vec<&String> = lines.iter().filter(|l| l.starts_with('#')).collect();
    assert_eq!(frames.len(), 3, "{lines:?}");
    // What the frame says starts at the same place whatever the code and name before it
    // (a code of 100, the longest name).
    for line in &frames {
        assert!(
            line[..88].ends_with(' ') && !line[88..].starts_with(' '),
            "{line}"
        );
    }
    let mut line = String::from("#");
    column(&mut line, 0, 7, Align::Left, 1_234_567_u64);
    column(&mut line, 0, 19, Align::Right, "@5");
    line.push('|');
    assert_eq!(line, "#1234567         @5|");
    let mut line = String::from("#");
    column(&mut line, 0, 7, Align::Left, 1_234_567_u64);
    column(&mut line, 0, 19, Align::Right, "100000.000000");
    assert_eq!(
        line, "#1234567 100000.000000",
        "a blank is kept between columns"
    );
}

proptest::proptest! {
    #[test]
    fn a_time_column_reads_as_the_formatter_writes_seconds(us in 0u64..1 << 44) {
        let mut text = String::new();
        Seconds(us).push_to(&mut text);
        proptest::prop_assert_eq!(text, format!("{:.6}", seconds(us)));
    }
}

#[test]
fn mask_writes_and_device_identification_say_what_they_carry() {
    let stream = [
        rtu(&[0x11, 0x16, 0x00, 0x04, 0x00, 0xF2, 0x00, 0x25]),
        rtu(&[0x11, 0x16, 0x00, 0x04, 0x00, 0xF2, 0x00, 0x25]),
        rtu(&[0x11, 0x2B, 0x0E, 0x01, 0x00]),
        rtu(&[
            0x11, 0x2B, 0x0E, 0x01, 0x01, 0xFF, 0x02, 0x02, 0x00, 0x03, 0x41, 0x42, 0x43, 0x01,
            0x02, 0x58, 0x31,
        ]),
    ]
    .concat();
    let lines = table_of(&stream);
    assert!(lines[0].contains("400005 AND 00F2 OR 0025"), "{lines:?}");
    assert!(lines[2].contains("read code 1 from object 00"), "{lines:?}");
    assert!(
        lines[3].contains(r#"VendorName = "ABC", ProductCode = "X1"; more from object 02"#),
        "{lines:?}"
    );
}

/// The TCP place of a frame is written field by field; it must stay what `JsonTcp`'s
/// `Serialize` gives (as an unanswered request's place is written), to the byte.
#[test]
fn a_tcp_place_as_a_sniffed_frame_is_its_serialize_to_the_byte() {
    use mbtool_core::sniff::session::TcpPlace;
    let mut rng = fastrand::Rng::with_seed(29);
    let addresses = [
        "10.0.0.1:40000",
        "[fe80::1]:502",
        "127.0.0.1:1502",
        "[::1]:65535",
    ];
    for _ in 0..200 {
        let mut address = || addresses[rng.usize(..addresses.len())].parse().unwrap();
        let (client, server) = (address(), address());
        let place = TcpPlace {
            client,
            server,
            udp: rng.bool(),
            from_client: rng.bool(),
            packet: rng.u64(1..1 << 40),
            time_us: rng.u64(..),
            request_packet: rng.bool().then(|| rng.u64(1..1000)),
            response_time: rng.bool().then(|| rng.u64(..1 << 33)),
        };
        let mut line = Vec::new();
        let mut object = JsonObject::open(&mut line);
        tcp_fields(&mut object, &place);
        object.close();
        let serialized = serde_json::to_string(&JsonTcp::from(&place)).unwrap();
        assert_eq!(String::from_utf8(line).unwrap(), serialized);
    }
}
