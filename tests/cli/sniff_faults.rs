//! `mbtool sniff --input` over generated captures of a real bus's faults: noise bursts, bit
//! flips, truncated frames, user-defined function codes, long runs of 00 and FF, and all of
//! them mixed. Each holds at least 20,000 real frames; every one must come out, whole and
//! valid, no frame may be invented, and a frame with flipped bits is never shown as valid.

use std::collections::HashSet;

use crate::support::{mbtool, random_exchange, rtu};
use mbtool_core::codec::checksum::crc_matches;
use mbtool_core::slave::{DataModel, Slave};

/// What goes on the line between two real frames.
#[derive(Clone, Copy, PartialEq)]
enum Fault {
    NoiseBurst,
    BitFlip,
    Truncated,
    UserFunctions,
    ZeroOrFfRun,
}

const ALL: [Fault; 5] = [
    Fault::NoiseBurst,
    Fault::BitFlip,
    Fault::Truncated,
    Fault::UserFunctions,
    Fault::ZeroOrFfRun,
];

/// A generated capture: its bytes, the real frames in it, and the damaged frames.
struct Capture {
    bytes: Vec<u8>,
    frames: Vec<Vec<u8>>,
    damaged: Vec<Vec<u8>>,
    /// What each stretch of the bytes is, to show where a failure happened.
    parts: Vec<(&'static str, usize)>,
    /// Which stretches run straight into the next one on the wire; the others are followed
    /// by silence.
    glued: Vec<bool>,
}

impl Capture {
    fn add(&mut self, what: &'static str, bytes: &[u8]) {
        self.add_glued(what, bytes, false);
    }

    /// Bytes the next stretch follows at once, with no silence between.
    fn add_glued(&mut self, what: &'static str, bytes: &[u8], glued: bool) {
        self.parts.push((what, self.bytes.len()));
        self.glued.push(glued);
        self.bytes.extend_from_slice(bytes);
    }

    /// The stretches around a frame reported by sniff, labelled.
    fn around(&self, frame: &str) -> String {
        let whole = hex::encode_upper(&self.bytes);
        let place = (0..whole.len())
            .step_by(2)
            .find(|i| whole[*i..].starts_with(frame))
            .unwrap_or(0)
            / 2;
        let index = self.parts.partition_point(|(_, start)| *start <= place);
        let from = index.saturating_sub(4);
        let to = (index + 3).min(self.parts.len());
        (from..to)
            .map(|i| {
                let (what, start) = self.parts[i];
                let end = self.parts.get(i + 1).map_or(self.bytes.len(), |p| p.1);
                format!("{what} {}", hex::encode_upper(&self.bytes[start..end]))
            })
            .collect::<Vec<_>>()
            .join("\n  ")
    }
}

/// The slaves whose traffic is generated.
const IDS: [u8; 5] = [1, 2, 17, 58, 247];

/// A random exchange with one of [`IDS`].
fn exchange(rng: &mut fastrand::Rng, slave: &mut Slave) -> [Vec<u8>; 2] {
    random_exchange(rng, slave, &IDS)
}

/// A request and answer of a user-defined function (65-72, 100-110), data of any length.
fn user_exchange(rng: &mut fastrand::Rng) -> [Vec<u8>; 2] {
    let id = rng.u8(1..=247);
    let function = if rng.bool() {
        rng.u8(65..=72)
    } else {
        rng.u8(100..=110)
    };
    [0, 1].map(|_| loop {
        let mut body = vec![id, function];
        body.extend((0..rng.usize(0..24)).map(|_| rng.u8(..)));
        let frame = rtu(&body);
        // A CRC of 00 00 makes the frame byte for byte a shorter frame followed by two
        // 00 bytes, and trailing 00 bytes never lengthen a frame.
        if !frame.ends_with(&[0, 0]) {
            break frame;
        }
    })
}

/// Whether the bytes start with a frame whose CRC holds: damage that leaves one is no
/// damage any receiver could see.
fn starts_with_a_frame(bytes: &[u8]) -> bool {
    !crc_matches(bytes, 4, bytes.len()).is_empty()
}

/// `timed`: the capture is for a replay with its timing, where silence follows every frame
/// and cut frame, so that the cases only silence tells apart are left in.
fn generate(faults: &[Fault], pairs: usize, seed: u64, timed: bool) -> Capture {
    let mut rng = fastrand::Rng::with_seed(seed);
    let mut slave = Slave::new(&[1, 2, 17, 58, 247], DataModel::manual_examples());
    let mut capture = Capture {
        bytes: Vec::new(),
        frames: Vec::new(),
        damaged: Vec::new(),
        parts: Vec::new(),
        glued: Vec::new(),
    };
    let mut completing = None;
    for _ in 0..pairs {
        let user = faults.contains(&Fault::UserFunctions) && rng.u8(..4) == 0;
        let pair = if user {
            user_exchange(&mut rng)
        } else {
            exchange(&mut rng, &mut slave)
        };
        for frame in pair {
            // A frame cut one byte short and followed at once by a frame that starts with
            // the missing byte reads as whole: only the silence of a live line between
            // them could tell. Keep them a byte apart.
            if completing.take() == frame.first().copied() && !timed {
                capture.add_glued("noise", &[!frame[0]], true);
            }
            capture.add("frame", &frame);
            let ends_in_00 = frame.last() == Some(&0);
            capture.frames.push(frame);
            // A frame of unknown layout whose CRC ends in 00 reads valid one byte shorter
            // too, and a frame followed by a 00 one byte longer: followed by noise, the
            // one is byte for byte the other, and nothing can tell them apart.
            if rng.u8(..10) != 0 || (user && ends_in_00 && !timed) {
                continue;
            }
            let fault = faults[rng.usize(..faults.len())];
            match fault {
                Fault::NoiseBurst => {
                    let mut noise: Vec<u8> = (0..rng.usize(1..=20)).map(|_| rng.u8(..)).collect();
                    if user && noise[0] == 0 && !timed {
                        noise[0] = 0x55;
                    }
                    capture.add_glued("noise", &noise, rng.bool());
                }
                Fault::BitFlip => {
                    // A frame sent again with one to three bits flipped.
                    let sent = &capture.frames[capture.frames.len() - 1];
                    let damaged = loop {
                        let mut damaged = sent.clone();
                        let mut bits: Vec<usize> = (0..damaged.len() * 8).collect();
                        rng.shuffle(&mut bits);
                        for bit in &bits[..rng.usize(1..=3)] {
                            damaged[bit / 8] ^= 1 << (bit % 8);
                        }
                        if !starts_with_a_frame(&damaged) {
                            break damaged;
                        }
                    };
                    capture.add("flipped", &damaged);
                    capture.damaged.push(damaged);
                }
                Fault::Truncated => {
                    let (_, frame) = exchange(&mut rng, &mut slave).into();
                    let cut = rng.usize(1..frame.len());
                    capture.add("truncated", &frame[..cut]);
                    if cut == frame.len() - 1 {
                        completing = Some(frame[cut]);
                    }
                    capture.damaged.push(frame[..cut].to_vec());
                }
                Fault::ZeroOrFfRun => {
                    let byte = if rng.bool() { 0x00 } else { 0xFF };
                    capture.add_glued("run", &vec![byte; rng.usize(2..=300)], rng.bool());
                }
                Fault::UserFunctions => {}
            }
        }
    }
    capture
}

/// The frames sniff reports: (hex, valid). With `timing`, the capture is replayed with it
/// as a `.timing` file beside it, as `sniff --save` keeps one.
fn sniffed(capture: &[u8], timing: Option<&str>) -> Vec<(String, bool)> {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("capture.bin");
    std::fs::write(&path, capture).unwrap();
    if let Some(timing) = timing {
        std::fs::write(dir.path().join("capture.bin.timing"), timing).unwrap();
    }
    let output = mbtool()
        .args([
            "sniff", "-b", "19200", "--parity", "even", "--json", "--input",
        ])
        .arg(&path)
        .output()
        .unwrap();
    assert!(output.status.success(), "{output:?}");
    String::from_utf8_lossy(&output.stdout)
        .lines()
        .map(|l| serde_json::from_str::<serde_json::Value>(l).unwrap())
        .filter(|l| l["type"] == "frame")
        .map(|l| {
            (
                l["bytes"].as_str().unwrap().replace(' ', ""),
                l["valid"].as_bool().unwrap(),
            )
        })
        .collect()
}

/// What went wrong in a sniff of a capture: real frames not reported valid, in order;
/// frames reported valid that were never sent; damaged frames reported valid.
#[derive(Debug)]
struct Tally {
    lost: Vec<String>,
    invented: Vec<String>,
    damaged_shown_valid: Vec<String>,
}

fn tally(capture: &Capture, reported: &[(String, bool)]) -> Tally {
    let sent: Vec<String> = capture.frames.iter().map(hex::encode_upper).collect();
    let real: HashSet<&str> = sent.iter().map(String::as_str).collect();
    let damaged: HashSet<String> = capture.damaged.iter().map(hex::encode_upper).collect();
    let valid: Vec<&String> = reported
        .iter()
        .filter(|(_, valid)| *valid)
        .map(|(hex, _)| hex)
        .collect();
    let mut tally = Tally {
        lost: Vec::new(),
        invented: Vec::new(),
        damaged_shown_valid: Vec::new(),
    };
    for hex in &valid {
        if !real.contains(hex.as_str()) {
            tally.invented.push((*hex).clone());
            if damaged.contains(*hex) {
                tally.damaged_shown_valid.push((*hex).clone());
            }
        }
    }
    // The real frames in order: each is matched by the next valid report that is real.
    let mut reports = valid
        .iter()
        .filter(|hex| real.contains(hex.as_str()))
        .peekable();
    for frame in &sent {
        match reports.peek() {
            Some(hex) if **hex == frame => {
                reports.next();
            }
            _ => tally.lost.push(frame.clone()),
        }
    }
    tally
}

/// Fails, showing the bytes around the first, if anything was lost or invented.
fn assert_clean(capture: &Capture, tally: &Tally, what: &str) {
    if let Some(first) = tally.invented.first() {
        panic!(
            "{what}: {} frames invented ({} of them damaged frames), the first: {first} in\n  {}",
            tally.invented.len(),
            tally.damaged_shown_valid.len(),
            capture.around(first)
        );
    }
    if let Some(first) = tally.lost.first() {
        panic!(
            "{what}: {} frames lost, the first: {first} in\n  {}",
            tally.lost.len(),
            capture.around(first)
        );
    }
}

fn check(faults: &[Fault], seed: u64) {
    let capture = generate(faults, 10_000, seed, false);
    assert!(capture.frames.len() >= 20_000);
    let reported = sniffed(&capture.bytes, None);
    assert_clean(&capture, &tally(&capture, &reported), "from bytes alone");
}

/// One character at 19200 baud, 8E1 (11 bits), and 3.5 of them: in microseconds.
const CHARACTER_US: u64 = 573;
const SILENCE_US: u64 = 2005;

/// How the bytes of a capture reached the sniffer.
#[derive(Clone, Copy)]
enum Delivery {
    /// A UART read as the characters arrive, one to four at a time, and the reads that
    /// time out in the silences told as idle.
    Uart,
    /// A USB adapter with a 16 ms latency timer: at each tick, whatever came since the
    /// last; the reads between ticks time out.
    UsbLatencyTimer,
}

/// When each byte of the capture has arrived on a 19200-baud line: back to back within a
/// stretch and into a stretch glued to it, and after the others at least t3.5 (up to 6
/// ms) of silence.
fn arrivals(capture: &Capture, rng: &mut fastrand::Rng) -> Vec<u64> {
    let mut times = Vec::with_capacity(capture.bytes.len());
    let mut time = 100_000;
    for (i, (_, start)) in capture.parts.iter().enumerate() {
        let end = capture
            .parts
            .get(i + 1)
            .map_or(capture.bytes.len(), |p| p.1);
        for _ in *start..end {
            time += CHARACTER_US;
            times.push(time);
        }
        if !capture.glued[i] {
            time += SILENCE_US + rng.u64(100..4_000);
        }
    }
    times
}

/// The `.timing` file a live `sniff --save` of the capture would have written.
fn timing(capture: &Capture, delivery: Delivery, seed: u64) -> String {
    let mut rng = fastrand::Rng::with_seed(seed);
    let arrived = arrivals(capture, &mut rng);
    let mut lines = vec![mbtool_core::sniff::timing::HEADER.to_string()];
    match delivery {
        Delivery::Uart => {
            let mut at = 0;
            while at < arrived.len() {
                // Up to four characters, never across a silence.
                let mut count = 1;
                while count < rng.usize(1..=4)
                    && arrived.get(at + count) == Some(&(arrived[at + count - 1] + CHARACTER_US))
                {
                    count += 1;
                }
                let last = arrived[at + count - 1];
                lines.push(format!("{} {count}", last + rng.u64(0..150)));
                at += count;
                let quiet = last + CHARACTER_US + SILENCE_US + 50;
                if arrived.get(at).is_none_or(|next| quiet < *next) {
                    lines.push(format!("{quiet} idle"));
                }
            }
        }
        Delivery::UsbLatencyTimer => {
            const TICK: u64 = 16_000;
            let mut at = 0;
            let mut tick = arrived[0] / TICK + 1;
            while at < arrived.len() {
                let count = arrived[at..]
                    .iter()
                    .take_while(|time| **time <= tick * TICK)
                    .count();
                if count > 0 {
                    lines.push(format!("{} {count}", tick * TICK + rng.u64(0..300)));
                    lines.push(format!("{} idle", tick * TICK + TICK / 2));
                    at += count;
                }
                tick += 1;
            }
        }
    }
    lines.join("\n") + "\n"
}

/// A capture of one fault model replayed with its timing: as a UART delivers it, nothing
/// may be lost or invented; as a USB adapter with a 16 ms latency timer delivers it, no
/// more than from the bytes alone.
fn check_timed(fault: Fault, seed: u64) {
    let capture = generate(&[fault], 10_000, seed, true);
    let uart = sniffed(
        &capture.bytes,
        Some(&timing(&capture, Delivery::Uart, seed)),
    );
    assert_clean(&capture, &tally(&capture, &uart), "with a UART's timing");
    if let Err(failure) = no_worse_behind_usb(&capture, seed) {
        panic!("{failure}");
    }
}

/// Whether the capture delivered as a USB adapter with a 16 ms latency timer delivers it
/// loses no frame that the bytes alone give, and invents no more.
fn no_worse_behind_usb(capture: &Capture, seed: u64) -> Result<(), String> {
    let alone = tally(capture, &sniffed(&capture.bytes, None));
    let usb = tally(
        capture,
        &sniffed(
            &capture.bytes,
            Some(&timing(capture, Delivery::UsbLatencyTimer, seed)),
        ),
    );
    let lost_more = usb.lost.iter().find(|frame| !alone.lost.contains(frame));
    if lost_more.is_some() || usb.invented.len() > alone.invented.len() {
        return Err(format!(
            "behind a USB adapter's latency timer: {} lost and {} invented, from bytes alone \
             {} and {}; the first lost or invented in\n  {}",
            usb.lost.len(),
            usb.invented.len(),
            alone.lost.len(),
            alone.invented.len(),
            capture.around(lost_more.or(usb.invented.first()).map_or("", |s| s))
        ));
    }
    if !usb.damaged_shown_valid.is_empty() {
        return Err(format!("{usb:?}"));
    }
    Ok(())
}

/// Short captures of every fault behind a USB adapter: where a frame is lost is where the
/// capture starts, before any frame has shown that the gaps lie, so many starts are tried.
#[test]
fn short_captures_behind_a_usb_adapter_lose_nothing_the_bytes_alone_give() {
    for seed in 0..300 {
        let capture = generate(&ALL, 10, 1000 + seed, true);
        if let Err(failure) = no_worse_behind_usb(&capture, seed) {
            panic!("seed {}: {failure}", 1000 + seed);
        }
    }
}

#[test]
fn timed_noise_bursts() {
    check_timed(Fault::NoiseBurst, 11);
}

#[test]
fn timed_flipped_bits() {
    check_timed(Fault::BitFlip, 12);
}

#[test]
fn timed_truncated_frames() {
    check_timed(Fault::Truncated, 13);
}

#[test]
fn timed_user_defined_functions() {
    check_timed(Fault::UserFunctions, 14);
}

#[test]
fn timed_runs_of_00_and_ff() {
    check_timed(Fault::ZeroOrFfRun, 15);
}

#[test]
fn noise_bursts_lose_and_invent_nothing() {
    check(&[Fault::NoiseBurst], 1);
}

#[test]
fn flipped_bits_are_never_valid_and_cost_no_other_frame() {
    check(&[Fault::BitFlip], 2);
}

#[test]
fn truncated_frames_cost_no_other_frame() {
    check(&[Fault::Truncated], 3);
}

#[test]
fn user_defined_functions_are_found_whole() {
    check(&[Fault::UserFunctions], 4);
}

#[test]
fn long_runs_of_00_and_ff_are_noise() {
    check(&[Fault::ZeroOrFfRun], 5);
}

#[test]
fn every_fault_mixed() {
    check(&ALL, 6);
}

#[test]
fn ten_megabytes_of_random_bytes_make_no_frame() {
    let mut rng = fastrand::Rng::with_seed(7);
    let bytes: Vec<u8> = (0..10_000_000).map(|_| rng.u8(..)).collect();
    let reported = sniffed(&bytes, None);
    // The first position of a capture is in step with the bus and may pass on its CRC
    // alone; nothing after it may.
    assert!(
        reported.len() <= 1,
        "{} frames in random bytes",
        reported.len()
    );
}
