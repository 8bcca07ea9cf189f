//! The framer's tests: frames found in streams as a line gives them, all at once and a
//! byte at a time; `timed` holds those whose reads come with their times.

use super::*;
use crate::codec::limits::{MAX_ASCII_ADU, MAX_RTU_ADU};

mod timed;

#[test]
fn frames_glued_on_one_line_are_split_and_nothing_else_is() {
    let request = [0x11, 0x03, 0x00, 0x6B, 0x00, 0x03, 0x76, 0x87];
    let response = [
        0x11, 0x03, 0x06, 0x02, 0x2B, 0x00, 0x00, 0x00, 0x64, 0xC8, 0xBA,
    ];
    let glued = [&request[..], &response[..]].concat();
    assert_eq!(
        split_glued(Mode::Rtu, &glued),
        Some(vec![request.to_vec(), response.to_vec()])
    );
    assert_eq!(split_glued(Mode::Rtu, &request), None);
    let mut bad = glued.clone();
    bad[12] ^= 1;
    assert_eq!(split_glued(Mode::Rtu, &bad), None);
    assert_eq!(
        split_glued(Mode::Rtu, &[&glued[..], &[0xFF][..]].concat()),
        None
    );
}
use crate::codec::checksum::{crc16, rtu};

const REQUEST: [u8; 8] = [0x11, 0x03, 0x00, 0x6B, 0x00, 0x03, 0x76, 0x87];
const ANSWER: [u8; 11] = [
    0x11, 0x03, 0x06, 0x02, 0x2B, 0x00, 0x00, 0x00, 0x64, 0xC8, 0xBA,
];

fn framer(mode: Mode) -> Framer {
    Framer::new(mode, 573.0, 2005)
}

/// Every event of `stream` fed all at once, then finished.
fn events(mode: Mode, stream: &[u8]) -> Vec<Event> {
    let mut framer = framer(mode);
    let mut out = Vec::new();
    framer.push(stream, &mut out);
    framer.finish(&mut out);
    out
}

/// Every event of `stream` fed a byte at a time, then finished.
fn events_byte_by_byte(mode: Mode, stream: &[u8]) -> Vec<Event> {
    let mut framer = framer(mode);
    let mut out = Vec::new();
    for byte in stream {
        framer.push(&[*byte], &mut out);
    }
    framer.finish(&mut out);
    out
}

/// The valid frames of `stream`.
fn frames(stream: &[u8]) -> Vec<Vec<u8>> {
    frames_that(stream, true)
}

/// The frames of `stream` that are valid, or (`valid` false) broken.
fn frames_that(stream: &[u8], valid: bool) -> Vec<Vec<u8>> {
    events(Mode::Rtu, stream)
        .into_iter()
        .filter_map(|e| match e {
            Event::Frame(f) if f.broken.is_none() == valid => Some(f.bytes.to_vec()),
            _ => None,
        })
        .collect()
}

#[test]
fn glued_frames_with_noise_between_them() {
    let mut stream = REQUEST.to_vec();
    stream.push(0x00);
    stream.extend_from_slice(&ANSWER);
    stream.push(0xFE);
    let out = events(Mode::Rtu, &stream);
    assert_eq!(frames(&stream), [REQUEST.to_vec(), ANSWER.to_vec()]);
    let noise = out.iter().filter(|e| matches!(e, Event::Noise(_))).count();
    assert_eq!(noise, 2);
}

#[test]
fn the_answer_awaited_from_a_reserved_address_after_noise_is_taken() {
    // A request to 250 (248-255 are reserved, but a device may use them), a glitch
    // byte, then its answer with its CRC sound: the conversation vouches for it, and a
    // frame whose CRC holds is never a CRC error.
    let functions: [&[u8]; 4] = [
        &[0xFA, 0x07],
        &[0xFA, 0x03, 0x00, 0x00, 0x00, 0x01],
        &[0xFA, 0x06, 0x00, 0x01, 0x12, 0x34],
        &[0xFA, 0x41, 0x01, 0x02],
    ];
    let answers: [&[u8]; 4] = [
        &[0xFA, 0x07, 0x29],
        &[0xFA, 0x03, 0x02, 0x00, 0x2A],
        &[0xFA, 0x06, 0x00, 0x01, 0x12, 0x34],
        &[0xFA, 0x41, 0x07],
    ];
    for (request, answer) in functions.iter().zip(answers) {
        // An echoed write, or a function without a known layout, reads both ways: only
        // a conversation already followed tells that it is a request, and what answer
        // it awaits.
        let both_ways = request == &answer || resync::may_lack_layout(request);
        let before: &[&[u8]] = if both_ways {
            &[&[&REQUEST[..], &ANSWER].concat()]
        } else {
            &[&[], &[&REQUEST[..], &ANSWER].concat()]
        };
        for (before, glitch) in before
            .iter()
            .flat_map(|before| [(before, &[0xFF][..]), (before, &[0x55, 0x55])])
        {
            let stream = [before, &rtu(request)[..], glitch, &rtu(answer)].concat();
            let mut expected = frames(before);
            expected.extend([rtu(request), rtu(answer)]);
            assert_eq!(frames(&stream), expected, "{stream:02X?}");
            assert!(frames_that(&stream, false).is_empty(), "{stream:02X?}");
        }
    }
}

/// Every frame of `stream`, valid or not, with why it is not.
fn frames_as_found(stream: &[u8]) -> Vec<(Vec<u8>, Option<Broken>)> {
    frames_of(events(Mode::Rtu, stream))
}

/// The frames among `events`, valid or not, with why they are not.
fn frames_of(events: Vec<Event>) -> Vec<(Vec<u8>, Option<Broken>)> {
    events
        .into_iter()
        .filter_map(|event| match event {
            Event::Frame(found) => Some((found.bytes.to_vec(), found.broken)),
            Event::Noise(_) => None,
        })
        .collect()
}

#[test]
fn a_malformed_answer_after_noise_whose_crc_holds_is_no_crc_error() {
    // Byte count 5 for function 3: a device's mistake, read as a frame with its CRC
    // sound whether noise comes before it or not.
    let malformed = rtu(&[0x11, 0x03, 0x05, 0x01, 0x02, 0x03, 0x04, 0x05]);
    for glitch in [&[][..], &[0xFF]] {
        let stream = [&REQUEST[..], glitch, &malformed, &REQUEST].concat();
        let found = frames_as_found(&stream);
        assert_eq!(found.len(), 3, "{stream:02X?}: {found:02X?}");
        assert_eq!(found[1].0, malformed, "{stream:02X?}");
        assert!(
            matches!(found[1].1, None | Some(Broken::Malformed)),
            "{stream:02X?}: {found:02X?}"
        );
    }
    // Write multiple coils answered with a quantity of 0: a glitch byte before it reads,
    // with its first bytes, as a request in step (slave 9A, function 0F). It must not
    // swallow the answer awaited into a CRC error.
    let request = rtu(&[0x0F, 0x0F, 0xD3, 0xCF, 0x00, 0x10, 0x02, 0x11, 0x37]);
    let answer = rtu(&[0x0F, 0x0F, 0xD3, 0xCF, 0x00, 0x00]);
    for glitch in [0x9A, 0xFF] {
        let stream = [&request[..], &[glitch], &answer].concat();
        let found = frames_as_found(&stream);
        assert_eq!(
            found,
            [
                (request.clone(), None),
                (answer.clone(), Some(Broken::Malformed))
            ],
            "{stream:02X?}"
        );
    }
}

#[test]
fn byte_by_byte_and_all_at_once_agree() {
    let mut stream = vec![0x00, 0xFE];
    stream.extend_from_slice(&REQUEST);
    stream.extend_from_slice(&ANSWER);
    assert_eq!(
        events(Mode::Rtu, &stream),
        events_byte_by_byte(Mode::Rtu, &stream)
    );
}

#[test]
fn a_corrupt_request_followed_by_its_answer_is_a_crc_error() {
    let mut bad = REQUEST;
    bad[7] ^= 0xFF;
    let mut stream = bad.to_vec();
    stream.extend_from_slice(&ANSWER);
    let out = events(Mode::Rtu, &stream);
    assert!(
        matches!(&out[0], Event::Frame(f) if f.broken == Some(Broken::Checksum) && f.bytes[..] == bad[..])
    );
    assert!(matches!(&out[1], Event::Frame(f) if f.broken.is_none() && f.bytes[..] == ANSWER[..]));
}

#[test]
fn a_corrupt_answer_before_a_frame_without_a_known_layout_is_a_crc_error() {
    // The answer awaited, its CRC broken, then function 65 asked and answered: the
    // conversation vouches for the answer's place, though what follows it needs
    // support of its own. Four bytes that read as a request in step, before the same
    // frames, are still noise: nothing vouches for them.
    let mut bad = ANSWER;
    bad[10] ^= 0xFF;
    let user_request = rtu(&[0x09, 0x41, 0x01, 0x02, 0x03]);
    let user_answer = rtu(&[0x09, 0x41, 0x04, 0x05]);
    let broken = |stream: &[u8]| frames_that(stream, false);
    let stream = [&REQUEST[..], &bad, &user_request, &user_answer].concat();
    assert_eq!(broken(&stream), [bad.to_vec()]);
    assert_eq!(
        frames(&stream),
        [REQUEST.to_vec(), user_request.clone(), user_answer.clone()]
    );
    let noise = [0xAA, 0x0B, 0xE7, 0x20];
    let stream = [&REQUEST[..], &ANSWER, &noise, &user_request, &user_answer].concat();
    assert_eq!(broken(&stream), Vec::<Vec<u8>>::new());
}

#[test]
fn the_start_of_a_long_request_passing_a_crc_as_an_answer_is_not_taken_for_one() {
    // A write of 1,036 coils, after a read that awaits its answer: its first eight
    // bytes read as a function 15 answer whose CRC holds, by chance. That answer is on
    // the turn but followed by nothing sound; the whole request is followed by a frame
    // right after it.
    let read = rtu(&[0x01, 0x01, 0x00, 0x00, 0x00, 0x01]);
    let mut packed = vec![0u8; 130];
    packed[0] = 0x5A;
    packed[128] = 0x02;
    let write = rtu(&[&[0x71, 0x0F, 0xC9, 0xD6, 0x04, 0x0C, 0x82][..], &packed].concat());
    assert!(crc16(&write[..8]) == 0, "the chance this test is about");
    let next = rtu(&[0x07, 0x01, 0x25, 0x3E, 0x06, 0xA0]);
    let stream = [&read[..], &write, &next].concat();
    assert_eq!(frames(&stream), [read, write, next]);
}

#[test]
fn a_request_supported_by_a_long_frame_further_on_is_found_read_a_byte_at_a_time_too() {
    // After noise, a request whose answer is cut short and followed by a line held
    // high: only a frame further on supports it, a write of 1,839 coils that starts
    // within the longest frame's reach but ends past it. Read all at once it is whole;
    // read a byte at a time it is not, until it is.
    let request = rtu(&[0x09, 0x02, 0x6D, 0x50, 0x00, 0xB4]);
    let cut_answer = &rtu(&[&[0x09, 0x02, 0x17][..], &[0x5A; 23]].concat())[..9];
    let mut coils = vec![0x11, 0x0F, 0x80, 0xE6, 0x07, 0x2F, 0xE6];
    coils.extend((0..230).map(|i| (i * 37 % 256) as u8));
    let write = rtu(&coils);
    let stream = [
        &[0x44, 0x64, 0x01][..],
        &request,
        cut_answer,
        &[0xFF; 76],
        &write,
        &REQUEST,
    ]
    .concat();
    assert_eq!(
        events_byte_by_byte(Mode::Rtu, &stream),
        events(Mode::Rtu, &stream)
    );
    assert_eq!(frames(&stream), [request, write, REQUEST.to_vec()]);
}

#[test]
fn an_unknown_function_before_a_request_does_not_swallow_it() {
    // 01 41: a byte whose next byte is a user-defined function.
    let mut stream = vec![0x01, 0x41];
    stream.extend_from_slice(&REQUEST);
    stream.extend_from_slice(&ANSWER);
    assert_eq!(frames(&stream), [REQUEST.to_vec(), ANSWER.to_vec()]);
}

#[test]
fn a_request_after_noise_is_taken_at_the_silence_after_it() {
    let mut framer = framer(Mode::Rtu);
    let mut out = Vec::new();
    let mut stream = vec![0x01, 0x41, 0x7F];
    stream.extend_from_slice(&REQUEST);
    framer.push_at(&stream, 10_000, &mut out);
    assert!(!out.iter().any(|e| matches!(e, Event::Frame(_))));
    assert!(!framer.idle(10_500, &mut out), "not silent yet");
    assert!(framer.idle(13_000, &mut out));
    assert!(matches!(out.last(), Some(Event::Frame(f)) if f.bytes[..] == REQUEST[..]));
}

#[test]
fn user_defined_functions_need_support_and_keep_a_crc_ending_in_00() {
    // Find a user-function frame whose CRC ends in 00, so that its prefix one byte
    // shorter passes the CRC too.
    let ends_in_00 = (0u16..)
        .map(|n| rtu(&[0x05, 0x41, (n >> 8) as u8, n as u8, 0x10]))
        .find(|f| f.last() == Some(&0))
        .unwrap();
    let answer = rtu(&[0x05, 0x41, 0x99]);
    let mut stream = ends_in_00.clone();
    stream.extend_from_slice(&answer);
    stream.extend_from_slice(&REQUEST);
    assert_eq!(frames(&stream), [ends_in_00, answer, REQUEST.to_vec()]);
}

#[test]
fn trailing_zeros_never_lengthen_a_frame() {
    let user = rtu(&[0x05, 0x42, 0x01, 0x02]);
    let mut stream = user.clone();
    stream.extend_from_slice(&[0, 0, 0, 0]);
    stream.extend_from_slice(&REQUEST);
    assert_eq!(frames(&stream), [user, REQUEST.to_vec()]);
}

#[test]
fn a_frame_in_two_pieces_is_whole_after_a_finished_transaction() {
    // A master finishes a transaction that got no answer, then awaits the next answer,
    // which a USB adapter delivers in two reads.
    let mut framer = framer(Mode::Rtu);
    let mut out = Vec::new();
    framer.await_answer(0x11, 0x03);
    framer.push_at(&ANSWER[..4], 1_000, &mut out);
    framer.finish(&mut out);
    framer.await_answer(0x11, 0x03);
    out.clear();
    framer.push_at(&ANSWER[..5], 100_000, &mut out);
    assert!(out.is_empty(), "{out:?}");
    framer.push_at(&ANSWER[5..], 104_000, &mut out);
    assert!(
        matches!(out.as_slice(), [Event::Frame(f)] if f.bytes[..] == ANSWER[..] && f.broken.is_none())
    );
}

#[test]
fn random_bytes_are_noise() {
    let mut rng = 0x2545_F491_4F6C_DD1Du64;
    let stream: Vec<u8> = (0..200_000)
        .map(|_| {
            rng ^= rng << 13;
            rng ^= rng >> 7;
            rng ^= rng << 17;
            rng as u8
        })
        .collect();
    // The very first position is in step and may be taken on its CRC alone; nothing
    // after it may.
    let found = frames(&stream);
    assert!(found.len() <= 1, "{} frames in random bytes", found.len());
}

#[test]
fn a_long_run_of_one_byte_is_counted_not_kept() {
    let mut framer = framer(Mode::Rtu);
    let mut out = Vec::new();
    for _ in 0..1000 {
        framer.push(&[0u8; 1000], &mut out);
        assert!(framer.unread().len() <= MAX_RTU_ADU);
    }
    framer.finish(&mut out);
    match out.as_slice() {
        [Event::Noise(noise)] => {
            assert_eq!(noise.len, 1_000_000);
            assert_eq!(noise.kept.len(), NOISE_KEPT);
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn ascii_frames_noise_a_cut_frame_and_a_slow_sender() {
    let stream = b"xx:1103006B00037E\r\n:1103006B:110306022B0000006455\r\n";
    let out = events(Mode::Ascii, stream);
    assert!(matches!(&out[0], Event::Noise(n) if n.kept[..] == b"xx"[..]));
    assert!(matches!(&out[1], Event::Frame(f) if f.broken.is_none()));
    assert!(
        matches!(&out[2], Event::Frame(f) if f.broken == Some(Broken::Incomplete) && f.bytes[..] == b":1103006B"[..])
    );
    assert!(matches!(&out[3], Event::Frame(f) if f.broken.is_none()));

    // Half a second between characters is within the one-second limit.
    let mut framer = framer(Mode::Ascii);
    let mut out = Vec::new();
    for (i, byte) in b":1103006B00037E\r\n".iter().enumerate() {
        framer.push_byte_at(*byte, i as u64 * 500_000, &mut out);
        framer.idle(i as u64 * 500_000 + 499_000, &mut out);
    }
    assert!(matches!(out.as_slice(), [Event::Frame(f)] if f.broken.is_none()));
}

#[test]
fn an_ascii_frame_too_short_to_spell_a_slave_and_function_is_noise() {
    let out = events(Mode::Ascii, b":F\r\n:11\r\n:1103006B00037E\r\n:1");
    assert!(matches!(&out[0], Event::Noise(n) if n.len == 9), "{out:?}");
    assert!(matches!(&out[1], Event::Frame(f) if f.broken.is_none()));
    assert!(matches!(&out[2], Event::Noise(n) if n.len == 2));
    assert_eq!(out.len(), 3);
}

#[test]
fn an_ascii_line_longer_than_a_frame_is_cut_alike_however_it_comes() {
    let mut stream = b":".to_vec();
    stream.extend([b'0'; 1200]);
    stream.extend(b"\r\n:1103006B00037E\r\n");
    let whole = events(Mode::Ascii, &stream);
    assert!(
        matches!(&whole[0], Event::Frame(f) if f.broken == Some(Broken::Incomplete) && f.bytes.len() == MAX_ASCII_ADU)
    );
    assert!(matches!(whole.last(), Some(Event::Frame(f)) if f.broken.is_none()));
    assert_eq!(events_byte_by_byte(Mode::Ascii, &stream), whole);
}

#[test]
fn tcp_frames_by_the_mbap_length_however_split() {
    let frame = [0, 1, 0, 0, 0, 6, 0x11, 0x03, 0x00, 0x6B, 0x00, 0x03];
    let mut stream = frame.to_vec();
    stream.extend_from_slice(&frame);
    let mut framer = framer(Mode::Tcp);
    let mut out = Vec::new();
    for byte in &stream {
        framer.push(&[*byte], &mut out);
    }
    assert_eq!(out.len(), 2);
    // Protocol id 99: no MBAP header, and nothing after it can be trusted.
    framer.push(&[0, 2, 0, 99, 0, 6, 0x11], &mut out);
    assert!(matches!(out.last(), Some(Event::Noise(n)) if n.len == 7));
    assert!(framer.is_lost());
}

/// Bytes that begin a device identification answer whose objects run past the longest RTU
/// frame are no frame, however many more come: the frame after them is found as soon as it
/// is followed, not when the input ends.
#[test]
fn an_identification_answer_too_long_for_a_frame_holds_back_nothing() {
    // Slave 5, 43/14, read code 1, conformity 1, more 0, next 0, 255 objects of 200 bytes.
    let mut stream = vec![0x05, 0x2B, 0x0E, 0x01, 0x01, 0x00, 0x00, 0xFF];
    stream.extend_from_slice(&[0x00, 0xC8]);
    stream.extend_from_slice(&[0x11; 400]);
    // Pairs after it, for as long as a frame may be: what follows the first is all here.
    for _ in 0..20 {
        stream.extend_from_slice(&REQUEST);
        stream.extend_from_slice(&ANSWER);
    }
    let mut framer = framer(Mode::Rtu);
    let mut out = Vec::new();
    framer.push(&stream, &mut out);
    let found = frames_of(out);
    assert!(
        found.contains(&(REQUEST.to_vec(), None)),
        "the request after the bytes waits: {found:?}"
    );
}
