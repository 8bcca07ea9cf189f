//! The framer read with times: silences, a USB adapter's latency timer, slow hosts.

use super::*;

/// Feeds `pieces` as reads at their times (microseconds), each read's bytes one
/// character apart before it; returns the frames, valid or not.
fn timed_frames(pieces: &[(&[u8], u64)]) -> Vec<(Vec<u8>, Option<Broken>)> {
    let mut framer = framer(Mode::Rtu);
    framer.end_cut_frames();
    let mut out = Vec::new();
    for (bytes, time) in pieces {
        framer.push_at(bytes, *time, &mut out);
    }
    framer.finish(&mut out);
    frames_of(out)
}

#[test]
fn a_gap_a_read_may_hide_does_not_cut_the_answer_awaited_where_a_longer_reading_ends_at_silence() {
    // The answer to a user-defined request (function 41), 12 bytes whose first four
    // pass a CRC too, read as 9 bytes and 3, back to back, then silence. The 9 came in a
    // read long after the one before, which could have hidden a gap after the fourth
    // byte; the silence seen after the twelfth tells the answer's length.
    let answer = [
        0xF7, 0x41, 0x87, 0xB0, 0x54, 0x98, 0x1E, 0xA7, 0xAF, 0x00, 0xE6, 0x33,
    ];
    assert!(crc_holds(&answer[..4]) && crc_holds(&answer));
    let reads: [(&[u8], u64); 8] = [
        (&[0x01, 0x01, 0x01, 0x5B, 0x10, 0x73], 10_000),
        (&[0xF7, 0x41, 0xC0, 0xF0], 23_066),
        (&[0x32], 23_639),
        (&answer[..9], 43_862),
        (&answer[9..], 45_581),
        (&[0x2A, 0x05, 0x0F, 0x0A, 0x00], 63_389),
        (&[0x00, 0xE8], 64_535),
        (&[0xC7], 65_108),
    ];
    let frames = timed_frames(&reads);
    assert_eq!(
        frames.get(2),
        Some(&(answer.to_vec(), None)),
        "{frames:02X?}"
    );
    assert_eq!(frames.len(), 4, "{frames:02X?}");
}

#[test]
fn silence_ends_a_frame_cut_short_and_the_next_starts_clean() {
    // The answer cut one byte short, then silence, then a request that starts with the
    // missing byte: read together, the cut answer and that byte pass the CRC.
    let cut = &ANSWER[..10];
    let mut request = vec![ANSWER[10]];
    request.extend_from_slice(&[0x03, 0x00, 0x01, 0x00, 0x01]);
    let request = rtu(&request);
    let out = timed_frames(&[(&REQUEST, 10_000), (cut, 20_000), (&request, 40_000)]);
    assert_eq!(
        out,
        [
            (REQUEST.to_vec(), None),
            (cut.to_vec(), Some(Broken::Incomplete)),
            (request, None)
        ]
    );
}

#[test]
fn a_host_late_now_and_then_leaves_a_line_read_a_byte_at_a_time() {
    // Read a byte a read, but the host once late: the request's first two bytes came in
    // one read. A device then pauses 5 ms inside its answer: on this line that is a
    // silence, and the answer is cut there, though its CRC holds across it.
    let mut time = 2 * 573;
    let mut reads: Vec<(&[u8], u64)> = vec![(&REQUEST[..2], time)];
    for (bytes, silence_before) in [
        (&REQUEST[2..], 0),
        (&ANSWER[..6], 5_000),
        (&ANSWER[6..], 5_000),
    ] {
        time += silence_before;
        for byte in bytes {
            time += 573;
            reads.push((std::slice::from_ref(byte), time));
        }
    }
    let frames = timed_frames(&reads);
    assert_eq!(
        frames,
        [
            (REQUEST.to_vec(), None),
            (ANSWER[..6].to_vec(), Some(Broken::Incomplete))
        ]
    );
}

#[test]
fn a_request_cut_short_by_silence_at_the_end_of_a_capture_is_cut_as_anywhere_else() {
    // A transaction, then a request cut after four bytes and a silence the times told:
    // the same [incomplete] as before a later frame. Without the silence told, the
    // capture itself may have cut it: noise.
    let ended = |silence_told: bool| {
        let mut framer = framer(Mode::Rtu);
        framer.end_cut_frames();
        let mut out = Vec::new();
        framer.push_at(&REQUEST, 10_000, &mut out);
        framer.push_at(&ANSWER, 20_000, &mut out);
        framer.push_at(&REQUEST[..4], 40_000, &mut out);
        if silence_told {
            assert!(framer.idle(140_000, &mut out));
        }
        framer.finish(&mut out);
        out.into_iter().last()
    };
    assert!(
        matches!(ended(true), Some(Event::Frame(f)) if f.bytes[..] == REQUEST[..4] && f.broken == Some(Broken::Incomplete))
    );
    assert!(matches!(ended(false), Some(Event::Noise(n)) if n.len == 4));
}

#[test]
fn a_frame_whose_rest_comes_after_a_gap_is_whole_and_then_gaps_are_not_silence() {
    // A USB adapter's latency timer: the answer in two reads 16 ms apart.
    let out = timed_frames(&[
        (&REQUEST, 10_000),
        (&ANSWER[..4], 16_000),
        (&ANSWER[4..], 32_000),
    ]);
    assert_eq!(out, [(REQUEST.to_vec(), None), (ANSWER.to_vec(), None)]);
    // Once the reads have shown the adapter's period, such a frame tells that the gaps
    // lie: from then on a request cut short by a gap is kept, as without timing.
    let mut framer = framer(Mode::Rtu);
    framer.end_cut_frames();
    let mut out = Vec::new();
    let mut ticks = (1..).map(|tick| tick * 16_000);
    for piece in [&REQUEST[..], &ANSWER[..]].repeat(5) {
        framer.push_at(piece, ticks.next().unwrap(), &mut out);
    }
    framer.push_at(&REQUEST, ticks.next().unwrap(), &mut out);
    assert!(!framer.gaps_lie());
    framer.push_at(&ANSWER[..4], ticks.next().unwrap(), &mut out);
    framer.push_at(&ANSWER[4..], ticks.next().unwrap(), &mut out);
    assert!(framer.gaps_lie());
    framer.push_at(&REQUEST[..5], ticks.next().unwrap(), &mut out);
    framer.push_at(&REQUEST[5..], ticks.next().unwrap(), &mut out);
    assert!(matches!(out.last(), Some(Event::Frame(f)) if f.bytes[..] == REQUEST[..]));
}

#[test]
fn a_frame_across_a_gap_at_no_period_of_the_reads_leaves_the_gaps_believed() {
    // The same answer in two reads 16 ms apart, on a line whose reads come where the
    // bytes end (a frame a read, 5 ms of silence after each): a device that paused
    // inside its frame, not an adapter's tick. The frame is taken whole, and a request
    // cut short later is still ended by its silence.
    let mut pieces = exchanges(50);
    pieces.extend([
        (&REQUEST[..], 5_000),
        (&ANSWER[..4], 16_000 - 7 * 573),
        (&ANSWER[4..], 5_000),
    ]);
    pieces.extend(exchanges(30));
    pieces.extend([(&REQUEST[..6], 5_000), (&REQUEST[..], 5_000)]);
    let out = read_at_their_ends(&pieces);
    assert_eq!(out[101], (ANSWER.to_vec(), None));
    assert_ends_with_a_cut_request_told(&out);
}

#[test]
fn a_gap_longer_than_an_adapter_makes_ends_a_frame_on_a_line_read_in_bursts() {
    // The answer's last byte comes 200 ms after the rest, and no frame after it: an
    // adapter's latency timer splits a frame into reads one period apart, never that far.
    let after = [ANSWER[10], 0xF3, 0x7A];
    let out = timed_frames(&[
        (&REQUEST, 10_000),
        (&ANSWER[..10], 20_000),
        (&after, 220_000),
    ]);
    assert_eq!(
        out,
        [
            (REQUEST.to_vec(), None),
            (ANSWER[..10].to_vec(), Some(Broken::Incomplete))
        ]
    );
    // 16 ms apart, the two reads are one answer.
    let out = timed_frames(&[
        (&REQUEST, 10_000),
        (&ANSWER[..10], 20_000),
        (&ANSWER[10..], 36_000),
    ]);
    assert_eq!(out, [(REQUEST.to_vec(), None), (ANSWER.to_vec(), None)]);
}

#[test]
fn behind_an_adapter_the_answer_awaited_is_taken_with_bytes_after_it_in_its_read() {
    // A user-defined answer and three bytes of noise in one read: an adapter gathers
    // whatever came in its period, so no gap can show between them, and the answer
    // stands on the conversation as it does without timing.
    let request = rtu(&[0x48, 0x46, 0xD4, 0xB7, 0xC2]);
    let answer = rtu(&[0x48, 0x46, 0x5D, 0x86, 0x90]);
    let read = [&answer[..], &[0x2A, 0x43, 0x5F]].concat();
    let out = timed_frames(&[
        (&REQUEST, 10_000),
        (&ANSWER, 20_000),
        (&request, 40_000),
        (&read, 56_000),
        (&REQUEST, 80_000),
        (&ANSWER, 90_000),
    ]);
    let valid: Vec<Vec<u8>> = out
        .into_iter()
        .filter(|(_, broken)| broken.is_none())
        .map(|(bytes, _)| bytes)
        .collect();
    assert_eq!(
        valid,
        [
            REQUEST.to_vec(),
            ANSWER.to_vec(),
            request,
            answer,
            REQUEST.to_vec(),
            ANSWER.to_vec()
        ]
    );
}

/// The frames of pieces read one a read, each read at its last byte (one character a
/// byte at 19200 8E1), with the silence after it in us: a line read a frame at a time.
fn read_at_their_ends(pieces: &[(&[u8], u64)]) -> Vec<(Vec<u8>, Option<Broken>)> {
    let mut time = 0;
    let reads: Vec<(&[u8], u64)> = pieces
        .iter()
        .map(|(bytes, silence)| {
            time += 573 * bytes.len() as u64;
            let read_at = time;
            time += silence;
            (*bytes, read_at)
        })
        .collect();
    timed_frames(&reads)
}

/// Feeds `pieces` (bytes, then the silence after them in microseconds) a byte a read,
/// one character apart: a line no adapter gathers; returns the frames, valid or not.
fn read_a_byte_at_a_time(pieces: &[(&[u8], u64)]) -> Vec<(Vec<u8>, Option<Broken>)> {
    let mut time = 0;
    let mut reads: Vec<(&[u8], u64)> = Vec::new();
    for (bytes, silence) in pieces {
        for byte in *bytes {
            time += 573;
            reads.push((std::slice::from_ref(byte), time));
        }
        time += silence;
    }
    timed_frames(&reads)
}

#[test]
fn read_a_byte_at_a_time_a_cut_request_that_reads_as_an_answer_is_no_crc_error_across_its_silence()
{
    // Read Input Registers cut two bytes short: its first six bytes read as an answer of
    // one byte, a length that ends at the silence. No request awaits that answer, so
    // they are a request cut short, not the start of one running across the silence.
    let request = rtu(&[0x11, 0x04, 0x01, 0x35, 0x00, 0x0C]);
    let out = read_a_byte_at_a_time(&[
        (&REQUEST, 5_000),
        (&ANSWER, 5_000),
        (&request[..6], 133_000),
        (&[0x11, 0x17], 250_000),
        (&request, 5_000),
    ]);
    assert_eq!(
        out,
        [
            (REQUEST.to_vec(), None),
            (ANSWER.to_vec(), None),
            (request[..6].to_vec(), Some(Broken::Incomplete)),
            (vec![0x11, 0x17], Some(Broken::Incomplete)),
            (request, None),
        ]
    );
}

#[test]
fn the_awaited_answer_that_fills_its_turn_is_a_crc_error_whatever_passes_a_crc_inside() {
    // The answer to Read Input Registers x6, corrupted; its last seven bytes pass a CRC
    // as a frame of user-defined function 65, which the silence after it would support.
    let request = rtu(&[0x11, 0x04, 0x00, 0x00, 0x00, 0x06]);
    let mut answer = vec![0x11, 0x04, 0x0C, 0x10, 0x20, 0x30, 0x40, 0x50, 0x60, 0x70];
    answer.extend_from_slice(&rtu(&[0x05, 0x41, 0xAA, 0xBB, 0xCC]));
    assert!(!crc_holds(&answer));
    let out = read_a_byte_at_a_time(&[(&request, 5_000), (&answer, 5_000), (&REQUEST, 5_000)]);
    assert_eq!(
        out,
        [
            (request, None),
            (answer, Some(Broken::Checksum)),
            (REQUEST.to_vec(), None)
        ]
    );
}

#[test]
fn read_a_byte_at_a_time_the_broken_answer_of_a_user_defined_function_ends_at_its_silence() {
    // Function 67 has no layout: its answer's length is where the silence falls. Bytes
    // of the slave and function awaited, up to the silence, are that answer: a CRC
    // error, or cut short when too few to hold a CRC; not noise.
    let request = rtu(&[0x11, 0x43]);
    for broken in [
        &[0x11, 0x43, 0xF4, 0x48, 0x8A, 0x46, 0x5D, 0xD2, 0x0C, 0xA2][..],
        &[0x11, 0x43, 0xF4][..],
    ] {
        // After an exchange, so that the frame of function 67 is read as a request.
        let out = read_a_byte_at_a_time(&[
            (&REQUEST, 5_000),
            (&ANSWER, 5_000),
            (&request, 5_000),
            (broken, 5_000),
            (&REQUEST, 5_000),
            (&ANSWER, 5_000),
        ]);
        let expected = match broken.len() {
            3 => Broken::Incomplete,
            _ => Broken::Checksum,
        };
        assert_eq!(
            out,
            [
                (REQUEST.to_vec(), None),
                (ANSWER.to_vec(), None),
                (request.clone(), None),
                (broken.to_vec(), Some(expected)),
                (REQUEST.to_vec(), None),
                (ANSWER.to_vec(), None)
            ]
        );
    }
}

/// The exchanges of a busy line, each frame followed by 5 ms of silence.
fn exchanges(count: usize) -> Vec<(&'static [u8], u64)> {
    [(&REQUEST[..], 5_000), (&ANSWER[..], 5_000)].repeat(count)
}

/// Asserts that `out` ends with a request cut short and ended by its silence, then the
/// request whole: the line's silences are believed.
fn assert_ends_with_a_cut_request_told(out: &[(Vec<u8>, Option<Broken>)]) {
    assert!(
        out.ends_with(&[
            (REQUEST[..6].to_vec(), Some(Broken::Incomplete)),
            (REQUEST.to_vec(), None),
        ]),
        "{:?}",
        &out[out.len().saturating_sub(4)..]
    );
}

#[test]
fn one_frame_by_chance_across_a_silence_in_many_does_not_make_the_gaps_lie() {
    // A line read a frame at a time (a UART with a FIFO, an adapter that hands bytes
    // over when the line goes quiet): 300 frames, then the answer cut one byte short,
    // silence, and a piece whose first byte passes the answer's CRC with it. One such
    // frame in 300 is chance, not an adapter's latency timer: a request cut short later
    // is still ended by the silence after it.
    let mut pieces = exchanges(150);
    pieces.extend([
        (&REQUEST[..], 5_000),
        (&ANSWER[..10], 5_000),
        (&[ANSWER[10], 0x03, 0x00][..], 5_000),
        (&REQUEST[..6], 5_000),
        (&REQUEST[..], 5_000),
    ]);
    let out = read_at_their_ends(&pieces);
    assert_ends_with_a_cut_request_told(&out);
}

#[test]
fn a_device_that_paused_once_inside_its_first_frame_leaves_the_later_silences_believed() {
    // Read a frame at a time: the first answer with a 4 ms pause inside it, taken whole
    // across it; then 2,200 frames; then a request cut short and ended by silence.
    let mut pieces = vec![
        (&REQUEST[..], 5_000),
        (&ANSWER[..6], 4_000),
        (&ANSWER[6..], 5_000),
    ];
    pieces.extend(exchanges(1_100));
    pieces.extend([(&REQUEST[..6], 5_000), (&REQUEST[..], 5_000)]);
    let out = read_at_their_ends(&pieces);
    assert_eq!(out[1], (ANSWER.to_vec(), None));
    assert_ends_with_a_cut_request_told(&out);
}

#[test]
fn behind_a_usb_adapter_the_gaps_stay_unbelieved_past_two_thousand_frames() {
    // Every answer split by a 16 ms tick, for 6,000 frames: once the reads have shown
    // their period, the frames across gaps go on being counted while the gaps are not
    // believed, so the line stays an adapter's.
    let mut framer = framer(Mode::Rtu);
    framer.end_cut_frames();
    let mut out = Vec::new();
    let mut tick = 0;
    for exchange in 0..3_000 {
        for piece in [&REQUEST[..], &ANSWER[..4], &ANSWER[4..]] {
            tick += 16_000;
            framer.push_at(piece, tick, &mut out);
        }
        assert!(
            framer.gaps_lie() || exchange < 3,
            "gaps believed at exchange {exchange}"
        );
    }
    let whole = out
        .iter()
        .filter(|event| matches!(event, Event::Frame(f) if f.broken.is_none()))
        .count();
    assert_eq!(whole, 6_000);
}

#[test]
fn read_a_byte_at_a_time_a_cut_answer_and_the_next_byte_are_no_frame_by_their_crc() {
    // The answer awaited, cut one byte short; silence; then a request cut short whose
    // first byte happens to be the answer's missing last byte, and silence again.
    // Read together the answer passes its CRC, but on a line read a byte at a time the
    // silence is real: the answer was cut, and no frame is made up across the silence.
    let out = read_a_byte_at_a_time(&[
        (&REQUEST, 5_000),
        (&ANSWER[..10], 5_000),
        (&[ANSWER[10], 0x03, 0x00], 5_000),
        (&REQUEST, 5_000),
    ]);
    assert!(
        !out.contains(&(ANSWER.to_vec(), None)),
        "a frame made up across the silence: {out:?}"
    );
    assert_eq!(out[1], (ANSWER[..10].to_vec(), Some(Broken::Incomplete)));
    assert_eq!(out.last(), Some(&(REQUEST.to_vec(), None)));
}

#[test]
fn a_malformed_request_after_glued_noise_is_shown_when_its_exception_follows() {
    // Noise glued before a request whose CRC holds but whose PDU does not read (a coil
    // value of 0004; function 15 with a byte count of 2 for one coil), then the slave's
    // exception. The second noise starts as a request of function 21 would, so that the
    // bytes up to the silence also look like a frame cut short.
    let coil = rtu(&[0x11, 0x05, 0x01, 0x69, 0x00, 0x04]);
    let coil_refused = rtu(&[0x11, 0x85, 0x03]);
    let coils = rtu(&[0x03, 0x0F, 0x00, 0x01, 0x00, 0x01, 0x02, 0x00, 0x00]);
    let coils_refused = rtu(&[0x03, 0x8F, 0x04]);
    let first_noise = [0x8D, 0xB8, 0x0A, 0xD7, 0x97, 0x59];
    let second_noise = [0x44, 0x15, 0x95, 0xCE, 0x7F, 0x52];
    let lines: [&[u8]; 8] = [
        &REQUEST,
        &ANSWER,
        &[&first_noise[..], &coil].concat(),
        &coil_refused,
        &[&second_noise[..], &coils].concat(),
        &coils_refused,
        &REQUEST,
        &ANSWER,
    ];
    let shown = |out: &[(Vec<u8>, Option<Broken>)]| {
        out.iter()
            .filter(|(_, broken)| broken.is_none())
            .map(|(bytes, _)| bytes.clone())
            .collect::<Vec<_>>()
    };
    let expected = [
        REQUEST.to_vec(),
        ANSWER.to_vec(),
        coil.clone(),
        coil_refused.clone(),
        coils.clone(),
        coils_refused.clone(),
        REQUEST.to_vec(),
        ANSWER.to_vec(),
    ];
    // The bytes alone, and each byte read alone with a silence after every line.
    let all_at_once: Vec<(Vec<u8>, Option<Broken>)> = frames(&lines.concat())
        .into_iter()
        .map(|f| (f, None))
        .collect();
    assert_eq!(shown(&all_at_once), expected);
    let timed = read_a_byte_at_a_time(&lines.map(|line| (line, 5_000)));
    assert_eq!(shown(&timed), expected, "{timed:?}");
    assert!(
        timed.iter().all(|(_, broken)| broken.is_none()),
        "{timed:?}"
    );
}

#[test]
fn a_user_defined_frame_ending_in_00_00_ends_at_its_silence() {
    // An answer of function 65 whose data ends with the CRC of the bytes before it, so
    // that its own CRC is 00 00 and the bytes before those pass a CRC too. From the
    // bytes alone the shorter frame is taken; read a byte at a time, or a frame a read,
    // the silence comes after the 00 00 and not before: they are the answer's own.
    let request = rtu(&[0x01, 0x41, 0x01, 0x02]);
    let answer = rtu(&rtu(&[0x01, 0x41, 0xAA, 0xBB]));
    assert_eq!(answer[6..], [0, 0]);
    let lines: [&[u8]; 4] = [&request, &answer, &REQUEST, &ANSWER];
    assert_eq!(frames(&lines.concat())[1], answer[..6].to_vec());
    let found = |lines: &[&[u8]], byte_a_read: bool| -> Vec<Vec<u8>> {
        let pieces: Vec<(&[u8], u64)> = lines.iter().map(|line| (*line, 3_000)).collect();
        let out = if byte_a_read {
            read_a_byte_at_a_time(&pieces)
        } else {
            read_at_their_ends(&pieces)
        };
        out.into_iter().map(|(frame, _)| frame).collect()
    };
    for byte_a_read in [true, false] {
        assert_eq!(found(&lines, byte_a_read), lines.map(<[u8]>::to_vec));
        // A longer run of 00 after a frame, up to the silence, is a line held low after
        // it, not its CRC.
        let held_low = [&answer[..6], &[0; 5][..]].concat();
        let lines: [&[u8]; 4] = [&request, &held_low, &REQUEST, &ANSWER];
        assert_eq!(
            found(&lines, byte_a_read),
            [
                request.clone(),
                answer[..6].to_vec(),
                REQUEST.to_vec(),
                ANSWER.to_vec()
            ]
        );
    }
}

#[test]
fn read_a_byte_at_a_time_a_silence_inside_a_frame_ends_it() {
    // A device pauses 3 ms inside its answer; later, a frame of function 72 followed by
    // silence and a frame cut short. Each byte is read alone, one character apart, so
    // no adapter gathered them: the pause is the line's own, and ends the answer for
    // every receiver on the bus, though the bytes across it pass their CRC. The gaps
    // after it still end what they cut.
    let user = rtu(&[0x85, 0x48, 0xA3, 0x7F, 0x4F, 0x50, 0x82, 0x7F, 0xD2, 0x0F]);
    let cut = [0x85, 0x48, 0xDB];
    let next = rtu(&[0x6F, 0x03, 0xAB, 0xAA, 0x00, 0x27]);
    let mut reads = Vec::new();
    let mut time = 0;
    let mut line = |bytes: &[u8], pause_after: Option<usize>| {
        for (i, byte) in bytes.iter().enumerate() {
            time += 573;
            reads.push((vec![*byte], time));
            if pause_after == Some(i) {
                time += 3_000;
            }
        }
        time += 3_000;
    };
    line(&REQUEST, None);
    line(&ANSWER, Some(6));
    line(&user, None);
    line(&cut, None);
    line(&next, None);
    let pieces: Vec<(&[u8], u64)> = reads.iter().map(|(b, t)| (&b[..], *t)).collect();
    let mut framer = Framer::new(Mode::Rtu, 573.0, 2005);
    framer.end_cut_frames();
    let mut events = Vec::new();
    for (bytes, time) in &pieces {
        framer.push_at(bytes, *time, &mut events);
    }
    framer.finish(&mut events);
    let shown: Vec<(Vec<u8>, Option<Broken>)> = events
        .into_iter()
        .map(|event| match event {
            Event::Frame(found) => (found.bytes.to_vec(), found.broken),
            Event::Noise(noise) => (noise.kept.to_vec(), None),
        })
        .collect();
    assert_eq!(
        shown,
        [
            (REQUEST.to_vec(), None),
            // The answer's first 7 bytes, cut by the pause; its last 4 bytes are noise.
            (ANSWER[..7].to_vec(), Some(Broken::Incomplete)),
            (ANSWER[7..].to_vec(), None),
            (user, None),
            // The slave and function the frame before asked, cut by the silence: its
            // answer cut short, though a function without a layout tells no length.
            (cut.to_vec(), Some(Broken::Incomplete)),
            (next, None),
        ]
    );
    // In reads of several bytes the same gap is an adapter's: see
    // a_frame_whose_rest_comes_after_a_gap_is_whole_and_then_gaps_are_not_silence.
}

#[test]
fn an_answer_without_a_known_layout_across_a_usb_tick_is_taken_whole() {
    // Function 72, request and answer, then noise and a request, in the reads of a USB
    // adapter's 16 ms latency timer at 19200 baud: the answer crosses a tick before any
    // frame of known layout has shown that the gaps lie.
    let hex = "110fa6a300040125229e110fa6a3000484324494f7486d132cded6237b2eb3bcf748d91e3f72\
               1fcb197121b0d654af4d11174ef80012d0ed00060c34c36030beaa31e220251e8461ef";
    let digits: Vec<char> = hex.chars().filter(char::is_ascii_hexdigit).collect();
    let stream: Vec<u8> = digits
        .chunks(2)
        .map(|pair| u8::from_str_radix(&pair.iter().collect::<String>(), 16).unwrap())
        .collect();
    let answer = &stream[32..44];
    let out = timed_frames(&[
        (&stream[..18], 16_000),
        (&stream[18..34], 32_000),
        (&stream[34..52], 48_000),
        (&stream[52..], 64_000),
    ]);
    assert!(out.contains(&(answer.to_vec(), None)), "{out:?}");
}

#[test]
fn a_frame_whose_answer_a_usb_tick_cuts_waits_for_the_rest() {
    // After noise, a request whose answer's first bytes end a read, the adapter's read
    // timing out (told as quiet) before the tick brings the rest.
    let mut framer = framer(Mode::Rtu);
    framer.end_cut_frames();
    let mut out = Vec::new();
    framer.push_at(
        &[&[0x7F, 0xFE][..], &REQUEST, &ANSWER[..2]].concat(),
        16_000,
        &mut out,
    );
    framer.idle(24_000, &mut out);
    framer.push_at(&ANSWER[2..], 32_000, &mut out);
    framer.finish(&mut out);
    let frames: Vec<&[u8]> = out
        .iter()
        .filter_map(|event| match event {
            Event::Frame(found) if found.broken.is_none() => Some(&found.bytes[..]),
            _ => None,
        })
        .collect();
    assert_eq!(frames, [&REQUEST[..], &ANSWER[..]]);
}

#[test]
fn noise_before_a_frame_that_a_usb_tick_splits_is_noise_not_a_broken_frame() {
    // Six bytes of noise, then a request whose last four bytes come a tick later: read
    // as function 15, noise and the request's first four bytes make a broken frame
    // that the gap seems to end; the request runs whole across that gap.
    let stream = [
        &[0x81, 0x0F, 0xD4, 0x5A, 0xE2, 0xCC][..],
        &rtu(&[0x01, 0x03, 0x00, 0x00, 0x00, 0x02]),
    ]
    .concat();
    let out = timed_frames(&[(&stream[..10], 10_000), (&stream[10..], 26_000)]);
    assert_eq!(out, [(stream[6..].to_vec(), None)]);
}

#[test]
fn a_user_defined_frame_after_a_glitch_byte_across_a_usb_tick_is_whole() {
    // A glitch byte and the first byte of a function 102 frame end a read: they begin a
    // function 3 frame that the gap seems to cut short.
    let user = rtu(&[0x03, 0x66, 0x58, 0x59, 0xD8, 0x32, 0x44, 0xE3, 0x25, 0x01]);
    let stream = [&[0xD3][..], &user].concat();
    let out = timed_frames(&[(&stream[..2], 10_192), (&stream[2..], 26_192)]);
    assert_eq!(out, [(user, None)]);
}

#[test]
fn a_long_answer_in_a_usb_adapters_reads_is_whole_from_its_first_two_bytes() {
    // A capture that starts with an answer of 89 bytes (function 23), its first two
    // bytes alone in the first read; each read seems to end at a silence.
    let mut body = vec![0x11, 0x17, 84];
    body.extend((0..84u8).map(|i| i.wrapping_mul(97).wrapping_add(13)));
    let answer = rtu(&body);
    let reads: Vec<(&[u8], u64)> = [0, 2, 22, 42, 62, 82]
        .iter()
        .zip([2, 22, 42, 62, 82, answer.len()])
        .zip([10_000, 26_000, 42_000, 58_000, 74_000, 90_000])
        .map(|((from, to), time)| (&answer[*from..to], time))
        .collect();
    assert_eq!(timed_frames(&reads), [(answer.clone(), None)]);
}

#[test]
fn a_request_against_the_turn_then_a_cut_answer_is_supported_by_a_frame_further_on() {
    // A request nobody answers; after a gap, another slave's request, its answer cut
    // short, and a request again, in one read: the second request stands on the frame
    // further on, as it would after noise.
    let other = rtu(&[0x03, 0x0C]);
    let cut = [
        0x03, 0x0C, 0x25, 0x00, 0x00, 0x1A, 0x02, 0x2B, 0x0E, 0x03, 0x80,
    ];
    let read = [&other[..], &cut, &REQUEST].concat();
    let out = timed_frames(&[(&REQUEST, 10_000), (&read, 40_000)]);
    let valid: Vec<Vec<u8>> = out
        .into_iter()
        .filter(|(_, broken)| broken.is_none())
        .map(|(bytes, _)| bytes)
        .collect();
    assert_eq!(valid, [REQUEST.to_vec(), other, REQUEST.to_vec()]);
}

#[test]
fn an_answer_ending_in_00_whose_request_was_lost_runs_to_the_silence() {
    // After an answer the bus expects a request, and the 8 bytes before the 00 that
    // ends this answer read as one; the silence falls after the 00.
    let request = rtu(&[0x01, 0x03, 0x00, 0x00, 0x00, 0x02]);
    let answer = rtu(&[0x01, 0x03, 0x04, 0x00, 0x01, 0x00, 0x02]);
    let ends_in_00 = rtu(&[0x01, 0x03, 0x04, 0x00, 0x00, 0x05, 0x84]);
    assert_eq!(ends_in_00.last(), Some(&0x00));
    let out = timed_frames(&[(&request, 5_000), (&answer, 15_000), (&ends_in_00, 30_000)]);
    assert_eq!(out, [(request, None), (answer, None), (ends_in_00, None)]);
}

#[test]
fn a_device_that_pauses_inside_its_answer_has_it_taken_whole() {
    // The first byte after the pause comes alone: too soon to tell.
    let out = timed_frames(&[
        (&REQUEST, 10_000),
        (&ANSWER[..3], 20_000),
        (&ANSWER[3..4], 30_000),
        (&ANSWER[4..], 34_000),
    ]);
    assert_eq!(out, [(REQUEST.to_vec(), None), (ANSWER.to_vec(), None)]);
}

#[test]
fn a_frame_cut_short_before_a_user_defined_one_that_completes_its_crc_is_cut() {
    // A request cut one byte short, silence, then a frame of function 70 from the
    // slave whose address is the missing byte: read together, the cut request passes.
    let whole = rtu(&[0x01, 0x07]);
    let user = rtu(&[whole[3], 0x46, 0x10, 0x20, 0x30]);
    let out = timed_frames(&[(&whole[..3], 10_000), (&user, 20_000)]);
    assert_eq!(
        out,
        [
            (whole[..3].to_vec(), Some(Broken::Incomplete)),
            (user, None)
        ]
    );
}

#[test]
fn a_request_that_reads_both_ways_after_an_unanswered_one_awaits_its_own_answer() {
    // 02 04 03 8C 00 0E is a read of input registers, and as long as an answer of 3
    // bytes: after a request nobody answered, it is the next request, not that answer.
    let unanswered = rtu(&[0x3A, 0x04, 0x1B, 0x69, 0x00, 0x0E]);
    let request = rtu(&[0x02, 0x04, 0x03, 0x8C, 0x00, 0x0E]);
    let mut body = vec![0x02, 0x04, 28];
    body.extend((0..28u8).map(|i| i.wrapping_mul(37)));
    let answer = rtu(&body);
    let stream = [&unanswered[..], &request, &answer, &[0xA1, 0xB2, 0xC3]].concat();
    assert_eq!(frames(&stream), [unanswered, request, answer]);
}
