//! `mbtool sniff --input` over generated captures of a real bus's faults: noise bursts, bit
//! flips, truncated frames, user-defined function codes, long runs of 00 and FF, and all of
//! them mixed. Each holds at least 20,000 real frames; every one must come out, whole and
//! valid, no frame may be invented, and a frame with flipped bits is never shown as valid.

use std::collections::HashMap;
use std::io::Write;

use crate::support::{mbtool, random_request, rtu};
use mbtool_core::codec::checksum::crc_matches;
use mbtool_core::codec::{Frame, Mode, Pdu};
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
}

impl Capture {
    fn add(&mut self, what: &'static str, bytes: &[u8]) {
        self.parts.push((what, self.bytes.len()));
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

/// A request of the common functions and the answer a slave gives it.
fn exchange(rng: &mut fastrand::Rng, slave: &mut Slave) -> [Vec<u8>; 2] {
    let id = [1u8, 2, 17, 58, 247][rng.usize(..5)];
    let request = random_request(rng);
    let answer = slave.handle(id, &request).expect("the slave answers");
    [Pdu::Request(request), answer].map(|pdu| {
        Frame {
            mode: Mode::Rtu,
            slave: id,
            transaction: 0,
            pdu,
        }
        .encode()
        .expect("generated frames keep the limits")
    })
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

fn generate(faults: &[Fault], pairs: usize, seed: u64) -> Capture {
    let mut rng = fastrand::Rng::with_seed(seed);
    let mut slave = Slave::new(&[1, 2, 17, 58, 247], DataModel::manual_examples());
    let mut capture = Capture {
        bytes: Vec::new(),
        frames: Vec::new(),
        damaged: Vec::new(),
        parts: Vec::new(),
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
            if completing.take() == frame.first().copied() {
                capture.add("noise", &[!frame[0]]);
            }
            capture.add("frame", &frame);
            let ends_in_00 = frame.last() == Some(&0);
            capture.frames.push(frame);
            // A frame of unknown layout whose CRC ends in 00 reads valid one byte shorter
            // too, and a frame followed by a 00 one byte longer: followed by noise, the
            // one is byte for byte the other, and nothing can tell them apart.
            if rng.u8(..10) != 0 || (user && ends_in_00) {
                continue;
            }
            let fault = faults[rng.usize(..faults.len())];
            match fault {
                Fault::NoiseBurst => {
                    let mut noise: Vec<u8> = (0..rng.usize(1..=20)).map(|_| rng.u8(..)).collect();
                    if user && noise[0] == 0 {
                        noise[0] = 0x55;
                    }
                    capture.add("noise", &noise);
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
                    capture.add("run", &vec![byte; rng.usize(2..=300)]);
                }
                Fault::UserFunctions => {}
            }
        }
    }
    capture
}

/// The frames sniff reports: (hex, valid).
fn sniffed(capture: &[u8]) -> Vec<(String, bool)> {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("capture.bin");
    std::fs::File::create(&path)
        .and_then(|mut f| f.write_all(capture))
        .unwrap();
    let output = mbtool()
        .args(["sniff", "-b", "9600", "--json", "--input"])
        .arg(&path)
        .output()
        .unwrap();
    assert!(output.status.success());
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

fn check(faults: &[Fault], seed: u64) {
    let capture = generate(faults, 10_000, seed);
    assert!(capture.frames.len() >= 20_000);
    let reported = sniffed(&capture.bytes);
    let valid: Vec<&String> = reported
        .iter()
        .filter(|(_, valid)| *valid)
        .map(|(hex, _)| hex)
        .collect();
    let sent: Vec<String> = capture.frames.iter().map(hex::encode_upper).collect();
    // The real frames, in order, and nothing else that reads as valid.
    let mut expected: HashMap<&str, usize> = HashMap::new();
    for frame in &sent {
        *expected.entry(frame).or_default() += 1;
    }
    let damaged: Vec<String> = capture.damaged.iter().map(hex::encode_upper).collect();
    let invented: Vec<&&String> = valid
        .iter()
        .filter(|hex| !expected.contains_key(hex.as_str()))
        .collect();
    if let Some(first) = invented.first() {
        panic!(
            "{} frames invented, the first: {first} in\n  {}",
            invented.len(),
            capture.around(first)
        );
    }
    for hex in &valid {
        assert!(
            !damaged.contains(hex) || expected.contains_key(hex.as_str()),
            "a damaged frame shown as valid: {hex}"
        );
    }
    let mut at = 0;
    for (i, frame) in sent.iter().enumerate() {
        match valid[at..].iter().position(|v| *v == frame) {
            Some(0) => at += 1,
            _ => panic!(
                "frame {i} lost: {frame} (next reported: {:?}) in\n  {}",
                valid.get(at),
                capture.around(frame)
            ),
        }
    }
    assert_eq!(valid.len(), sent.len());
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
    let reported = sniffed(&bytes);
    // The first position of a capture is in step with the bus and may pass on its CRC
    // alone; nothing after it may.
    assert!(
        reported.len() <= 1,
        "{} frames in random bytes",
        reported.len()
    );
}
