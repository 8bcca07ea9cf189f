use super::*;
use crate::codec::checksum::rtu;

/// A session over the RTU `capture`, to its end: its counts and records.
fn sniffed(capture: &[u8]) -> (Counts, Vec<Record>) {
    let mut session = Session::new(Mode::Rtu, 573.0, 2005, Filter::default());
    let mut out = Vec::new();
    session.push(capture, &mut out);
    session.finish(None, &mut out);
    (session.counts().clone(), out)
}

/// A read, an answer to it whose byte count is wrong but whose CRC holds, after
/// `glitch`, and the read again.
fn malformed_answer_after(glitch: &[u8]) -> (Counts, Vec<Record>) {
    let request = rtu(&[0x11, 0x03, 0x00, 0x6B, 0x00, 0x03]);
    let malformed = rtu(&[0x11, 0x03, 0x05, 0x01, 0x02, 0x03, 0x04, 0x05]);
    sniffed(&[&request[..], glitch, &malformed, &request].concat())
}

/// The kind and error of the first frame among `records` that is not valid.
fn first_invalid(records: &[Record]) -> Option<(Kind, Option<String>)> {
    records.iter().find_map(|record| match record {
        Record::Frame(frame) if !frame.report().valid => {
            Some((frame.report().kind, frame.report().error.clone()))
        }
        _ => None,
    })
}

#[test]
fn a_malformed_answer_is_counted_so_whether_noise_came_before_it_or_not() {
    for glitch in [&[][..], &[0xFF]] {
        let (counts, _) = malformed_answer_after(glitch);
        assert_eq!(
            (counts.frames, counts.malformed, counts.crc_errors),
            (3, 1, 0),
            "glitch {glitch:02X?}"
        );
    }
}

#[test]
fn a_malformed_frame_is_told_as_the_way_it_travels_whether_noise_came_before_it_or_not() {
    let told: Vec<_> = [&[][..], &[0xFF]]
        .into_iter()
        .map(|glitch| {
            let (_, records) = malformed_answer_after(glitch);
            first_invalid(&records)
        })
        .collect();
    assert_eq!(
        told[0],
        Some((
            Kind::Response,
            Some("byte count 5 is not valid for function 3".to_string())
        ))
    );
    assert_eq!(told[0], told[1]);
}

#[test]
fn a_malformed_frame_of_the_same_layout_both_ways_is_read_as_the_conversation_has_it() {
    let pair = [
        rtu(&[0x02, 0x03, 0x00, 0x00, 0x00, 0x01]),
        rtu(&[0x02, 0x03, 0x02, 0x00, 0x07]),
    ]
    .concat();
    // A write of coil value 0004, refused with exception 03; then a read of two
    // registers answered with a byte count of 3: eight bytes each, as a request and
    // as an answer alike.
    let cases = [
        (
            [
                pair.clone(),
                rtu(&[0x01, 0x05, 0x00, 0x10, 0x00, 0x04]),
                rtu(&[0x01, 0x85, 0x03]),
            ]
            .concat(),
            Kind::Request,
            "coil value 0004 is neither FF00 (on) nor 0000 (off)",
        ),
        (
            [
                rtu(&[0x01, 0x03, 0x00, 0x00, 0x00, 0x02]),
                rtu(&[0x01, 0x03, 0x03, 0x00, 0x01, 0x02]),
            ]
            .concat(),
            Kind::Response,
            "byte count 3 is not valid for function 3",
        ),
    ];
    for (capture, kind, error) in cases {
        let (_, records) = sniffed(&[capture, pair.clone()].concat());
        assert_eq!(
            first_invalid(&records),
            Some((kind, Some(error.to_string())))
        );
    }
}

#[test]
fn a_malformed_frame_takes_its_place_in_the_conversation_as_it_is_shown() {
    let write_register = rtu(&[0x11, 0x06, 0x00, 0x01, 0x00, 0x03]);
    let bad_coil = rtu(&[0x11, 0x05, 0x00, 0xAC, 0x00, 0x04]);
    // For each request left unanswered: whether it was still waiting at the end.
    let unanswered = |capture: &[Vec<u8>]| {
        let (_, records) = sniffed(&capture.concat());
        records
            .iter()
            .filter_map(|record| match record {
                Record::Unanswered { capture_ended, .. } => Some(*capture_ended),
                _ => None,
            })
            .collect::<Vec<_>>()
    };
    // A malformed request: the write before it got no answer, and the write after it
    // is answered by its echo, not taken for the first one's answer.
    let request = [
        write_register.clone(),
        bad_coil.clone(),
        rtu(&[0x11, 0x85, 0x03]),
        write_register.clone(),
        write_register.clone(),
    ];
    assert_eq!(unanswered(&request), [false]);
    // Its exception is its answer, paired with it.
    let (_, records) = sniffed(&request.concat());
    let exception_paired = records.iter().any(|record| {
        matches!(record, Record::Frame(frame) if frame.found.bytes[1] == 0x85 && frame.paired)
    });
    assert!(exception_paired);
    // Unanswered, it is told as any request is.
    let (_, records) =
        sniffed(&[rtu(&[0x11, 0x03, 0x00, 0x00, 0x00, 0x01]), bad_coil.clone()].concat());
    let told: Vec<u8> = records
        .iter()
        .filter_map(|record| match record {
            Record::Unanswered { request, .. } => Some(request.function()),
            _ => None,
        })
        .collect();
    assert_eq!(told, [0x03, 0x05]);
    // A malformed answer: the write it answers is answered.
    let answer = [
        rtu(&[0x02, 0x03, 0x00, 0x00, 0x00, 0x01]),
        rtu(&[0x02, 0x03, 0x02, 0x00, 0x07]),
        rtu(&[0x11, 0x05, 0x00, 0xAC, 0xFF, 0x00]),
        bad_coil,
    ];
    assert!(unanswered(&answer).is_empty());
}

#[test]
fn an_answer_that_does_not_fit_its_request_is_shown_counted_and_answers_it() {
    let read_two = rtu(&[0x01, 0x03, 0x00, 0x00, 0x00, 0x02]);
    let capture = [
        read_two.clone(),
        rtu(&[0x01, 0x03, 0x02, 0x00, 0x05]),
        read_two,
        rtu(&[0x01, 0x03, 0x04, 0x00, 0x05, 0x00, 0x06]),
    ];
    let (counts, records) = sniffed(&capture.concat());
    assert_eq!((counts.mismatched, counts.unanswered), (1, 0));
    let frames: Vec<&FrameRecord> = records
        .iter()
        .filter_map(|record| match record {
            Record::Frame(frame) => Some(frame),
            _ => None,
        })
        .collect();
    let shown: Vec<(bool, bool)> = frames
        .iter()
        .map(|frame| (frame.paired, frame.mismatch.is_some()))
        .collect();
    assert_eq!(
        shown,
        [(false, false), (false, true), (false, false), (true, false)]
    );
}

#[test]
fn the_tallies_by_slave_list_the_addresses_seen_lowest_first() {
    let mut counts = Counts::default();
    counts.tell(247, Some(Kind::Request));
    counts.tell(0, Some(Kind::Request));
    counts.unanswered(17);
    counts.tell(247, Some(Kind::Exception));
    let listed: Vec<u8> = counts.slaves.iter().map(|(slave, _)| slave).collect();
    assert_eq!(listed, [0, 17, 247]);
    assert_eq!(counts.slaves.get(5), None);
    let high = counts.slaves.get(247).copied().unwrap_or_default();
    assert_eq!((high.requests, high.answers, high.exceptions), (1, 1, 1));
    assert_eq!(counts.slaves.get(17).map(|c| c.unanswered), Some(1));
    assert_eq!(
        format!("{:?}", counts.slaves)
            .matches("SlaveCounts")
            .count(),
        3
    );
}
