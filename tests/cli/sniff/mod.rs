//! `mbtool sniff`: the real captures come out as listed beside them, glued frames are split,
//! noise is counted and never invents a frame, a live pty capture reports the gaps the
//! writer made, and --save replays as --input.

use std::io::Read;

use std::path::{Path, PathBuf};

use std::process::{Command as Process, Stdio};

use std::time::{Duration, Instant};

use crate::support::{mbtool, random_exchange, rtu, write_all, Pty, WORKED_FRAMES as WORKED};

use mbtool_core::codec::Mode;

use mbtool_core::slave::{DataModel, Slave};

use mbtool_core::sniff::session::{Filter, Record, Session};

use serialport::SerialPort;

fn captures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/captures")
}

/// What a capture's frames.txt lists: ("frame", hex, "req"/"resp") or ("noise", hex, "").
fn listed(name: &str) -> Vec<(String, String, String)> {
    let text = std::fs::read_to_string(captures().join(format!("{name}.frames.txt"))).unwrap();
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|line| {
            let (data, note) = line.split_once('#').unwrap_or((line, ""));
            if let Some(noise) = data.trim().strip_prefix("noise:") {
                ("noise".into(), noise.trim().to_string(), String::new())
            } else {
                let hex = data.trim().trim_end_matches("CRC ok").trim().to_string();
                let direction = note
                    .split_whitespace()
                    .nth(1)
                    .unwrap_or_default()
                    .to_string();
                ("frame".into(), hex, direction)
            }
        })
        .collect()
}

fn json_lines(stdout: &[u8]) -> Vec<serde_json::Value> {
    String::from_utf8_lossy(stdout)
        .lines()
        .map(|l| serde_json::from_str(l).expect("JSON Lines"))
        .collect()
}

/// What sniff reported, in the same shape as `listed`, and its summary.
fn reported(lines: &[serde_json::Value]) -> (Vec<(String, String, String)>, serde_json::Value) {
    let mut seen = Vec::new();
    let mut summary = serde_json::Value::Null;
    for line in lines {
        match line["type"].as_str() {
            Some("frame") => {
                let direction = match line["kind"].as_str() {
                    Some("request") => "req",
                    _ => "resp",
                };
                seen.push((
                    "frame".into(),
                    line["bytes"].as_str().unwrap().to_string(),
                    direction.into(),
                ));
            }
            Some("noise") => seen.push((
                "noise".into(),
                line["bytes"].as_str().unwrap().to_string(),
                String::new(),
            )),
            Some("summary") => summary = line.clone(),
            _ => {}
        }
    }
    (seen, summary)
}

#[test]
fn the_real_captures_come_out_as_listed() {
    for (name, line) in [
        ("brainchild-io-16do", ["-b", "19200", "--parity", "even"]),
        ("flowmeter_graph_tool", ["-b", "9600", "--parity", "none"]),
        ("wizmodbus", ["-b", "9600", "--parity", "none"]),
    ] {
        let input = captures().join(format!("{name}.bin"));
        let output = mbtool()
            .arg("sniff")
            .args(line)
            .args(["--json", "--input"])
            .arg(&input)
            .output()
            .unwrap();
        assert!(
            output.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&output.stderr)
        );
        let (seen, summary) = reported(&json_lines(&output.stdout));
        assert_eq!(seen, listed(name), "{name}");
        let frames = seen.iter().filter(|s| s.0 == "frame").count() as u64;
        assert_eq!(summary["frames"].as_u64(), Some(frames), "{name}");
        assert_eq!(
            summary["answers"], summary["requests"],
            "{name}: every request answered"
        );
        assert_eq!(summary["unanswered"], 0, "{name}");
        assert_eq!(summary["crc_errors"], 0, "{name}");
        // The tally by slave: a map keyed by each address seen, adding up to the whole.
        let slaves = summary["slaves"].as_object().expect("slaves is a map");
        assert!(
            slaves.keys().all(|slave| slave.parse::<u8>().is_ok()),
            "{name}"
        );
        let by_slave: u64 = slaves.values().filter_map(|s| s["requests"].as_u64()).sum();
        assert_eq!(Some(by_slave), summary["requests"].as_u64(), "{name}");
    }
}

/// Replays a timed capture byte by byte at its recorded times; (frames, gaps in us).
fn replay_timed(name: &str, char_us: f64, silence_us: u64) -> (usize, Vec<u64>) {
    let (frames, gaps) = replay_timed_frames(name, char_us, silence_us);
    (frames.len(), gaps)
}

/// Replays a timed capture byte by byte at its recorded times; the frames in the shape of
/// `listed`, and the gaps in us.
fn replay_timed_frames(
    name: &str,
    char_us: f64,
    silence_us: u64,
) -> (Vec<(String, String, String)>, Vec<u64>) {
    let text = std::fs::read_to_string(captures().join(format!("{name}.timed.txt"))).unwrap();
    let mut session = Session::new(Mode::Rtu, char_us, silence_us, Filter::default());
    let mut records = Vec::new();
    for line in text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
    {
        let mut parts = line.split_whitespace();
        let time: u64 = parts.next().unwrap().parse().unwrap();
        let byte = u8::from_str_radix(parts.next().unwrap(), 16).unwrap();
        session.push_byte_at(byte, time, &mut records);
    }
    session.finish(None, &mut records);
    let frames: Vec<_> = records
        .iter()
        .filter_map(|r| match r {
            Record::Frame(f) => Some(f),
            _ => None,
        })
        .collect();
    let shown = frames
        .iter()
        .map(|f| {
            let direction = match (f.report().kind, f.report().valid) {
                (mbtool_core::describe::Kind::Request, _) => "req",
                (_, true) => "resp",
                (_, false) => "broken",
            };
            (
                "frame".to_string(),
                mbtool_core::codec::hex::spaced_hex(&f.found.bytes),
                direction.to_string(),
            )
        })
        .collect();
    (shown, frames.iter().filter_map(|f| f.gap).collect())
}

#[test]
fn timed_captures_give_the_gaps_listed_beside_them() {
    // brainchild, 19200 8E1: request -> answer 2.058-2.116 ms, answer -> request 3.14 ms
    // within a pass, 54 ms between the passes.
    let (frames, gaps) = replay_timed("brainchild-io-16do", 11.0 * 1e6 / 19200.0, 2005);
    assert_eq!(frames, 30);
    let turnarounds: Vec<u64> = gaps.iter().step_by(2).copied().collect();
    assert!(
        turnarounds.iter().all(|g| (2057..=2117).contains(g)),
        "{turnarounds:?}"
    );
    assert!(
        gaps.iter().any(|g| (53_000..56_000).contains(g)),
        "{gaps:?}"
    );
    // flowmeter, 9600 8N1 as sigrok decodes it: request -> answer 4.009-4.016 ms.
    let (frames, gaps) = replay_timed("flowmeter_graph_tool", 10.0 * 1e6 / 9600.0, 3646);
    assert_eq!(frames, 18);
    let turnarounds: Vec<u64> = gaps.iter().step_by(2).copied().collect();
    assert!(
        turnarounds.iter().all(|g| (4008..=4017).contains(g)),
        "{turnarounds:?}"
    );
    // wizmodbus: the glitch bytes lie inside the gaps, some glued to the request before
    // them (a 00 that makes it read as an answer one byte longer), and still the frames
    // come out as listed, each request and answer as such.
    // So too with the line's speed set too high (19200), which makes more of its pauses
    // silences.
    let frames_listed: Vec<_> = listed("wizmodbus")
        .into_iter()
        .filter(|l| l.0 == "frame")
        .collect();
    for (char_us, silence_us) in [(10.0 * 1e6 / 9600.0, 3646), (10.0 * 1e6 / 19200.0, 1823)] {
        let (frames, _) = replay_timed_frames("wizmodbus", char_us, silence_us);
        assert_eq!(frames, frames_listed, "{char_us} us a character");
    }
}

#[test]
fn the_worked_frames_glued_together_come_out_paired() {
    let glued: Vec<u8> = WORKED.concat();
    let output = mbtool()
        .args(["sniff", "--json", "--input", "-"])
        .write_stdin(glued)
        .output()
        .unwrap();
    let lines = json_lines(&output.stdout);
    let frames: Vec<&serde_json::Value> = lines.iter().filter(|l| l["type"] == "frame").collect();
    assert_eq!(frames.len(), WORKED.len());
    for (i, (frame, bytes)) in frames.iter().zip(WORKED.iter()).enumerate() {
        let hex: Vec<String> = bytes.iter().map(|b| format!("{b:02X}")).collect();
        assert_eq!(frame["bytes"], hex.join(" "), "frame {i}");
        let want = if i % 2 == 0 { "request" } else { "response" };
        assert_eq!(frame["kind"], want, "frame {i}");
        if i % 2 == 1 {
            assert_eq!(frame["paired"], true, "frame {i}");
        }
    }
    // The 03 answer carries the addresses of its request.
    assert_eq!(frames[5]["ref"], "400108");
    assert_eq!(frames[5]["values"], serde_json::json!([555, 0, 100]));
    // The 01 answer is cut to the 37 coils asked.
    assert_eq!(frames[1]["values"].as_array().unwrap().len(), 37);
    // Without timing, a frame's time is where it stands at the line's speed (19200 8E1,
    // 11 bits a character): the 03 request starts 34 bytes in, at 19.479 ms.
    assert_eq!(frames[4]["time"].as_f64(), Some(0.019479));
    // To the nearest microsecond: the 02 request, 26 bytes in, starts at 14,895.83 us.
    assert_eq!(frames[3]["time"].as_f64(), Some(0.014896));
    assert!(
        frames[4].get("gap").is_none(),
        "no gap is made up without timing"
    );
    let summary = lines.last().unwrap();
    assert_eq!(
        (summary["requests"].as_u64(), summary["answers"].as_u64()),
        (Some(7), Some(7))
    );
    assert_eq!(summary["noise_bytes"], 0);
}

/// An answer that does not fit the request awaiting it is told so in every format, and
/// its request is not reported unanswered.
#[test]
fn an_answer_that_does_not_fit_its_request_says_so_in_every_format() {
    let read_two = rtu(&[0x11, 0x03, 0x00, 0x6B, 0x00, 0x02]);
    let capture = [read_two, rtu(&[0x11, 0x03, 0x02, 0x00, 0x05])].concat();
    let sniffed = |format: &str| -> String {
        let output = mbtool()
            .env("NO_COLOR", "1")
            .args(["sniff", "-o", format, "--input", "-"])
            .write_stdin(capture.clone())
            .output()
            .unwrap();
        assert!(output.status.success(), "{output:?}");
        String::from_utf8(output.stdout).unwrap()
    };
    let told = "answer carries registers: 1, the request asked for 2";
    let lines = json_lines(sniffed("json").as_bytes());
    assert_eq!(lines[1]["mismatch"], told);
    assert!(lines[1].get("paired").is_none());
    let summary = lines.last().unwrap();
    assert_eq!(
        (
            summary["mismatched"].as_u64(),
            summary["unanswered"].as_u64()
        ),
        (Some(1), Some(0))
    );
    let table = sniffed("table");
    assert!(
        table.contains(&format!("(does not fit the request: {told})")),
        "{table}"
    );
    assert!(
        table.contains("0 unanswered, 1 not fitting the request"),
        "{table}"
    );
    assert!(sniffed("csv").contains(&format!("(does not fit the request: {told})")));
}

/// The slaves whose traffic is generated.
const IDS: [u8; 4] = [1, 2, 17, 247];

/// A random exchange with one of [`IDS`].
fn exchange(rng: &mut fastrand::Rng, slave: &mut Slave) -> [Vec<u8>; 2] {
    random_exchange(rng, slave, &IDS)
}

#[test]
fn a_hundred_thousand_pairs_with_noise_lose_and_invent_nothing() {
    let mut rng = fastrand::Rng::with_seed(20261122);
    let mut slave = Slave::new(&[1, 2, 17, 247], DataModel::manual_examples());
    let mut stream = Vec::new();
    let mut frames = Vec::new();
    let mut noise = 0u64;
    for _ in 0..100_000 {
        for bytes in exchange(&mut rng, &mut slave) {
            stream.extend_from_slice(&bytes);
            frames.push(bytes);
        }
        if rng.u8(..100) == 0 {
            for _ in 0..rng.usize(1..=3) {
                stream.push(rng.u8(..));
                noise += 1;
            }
        }
    }
    let mut session = Session::new(Mode::Rtu, 573.0, 2005, Filter::default());
    let mut records = Vec::new();
    for chunk in stream.chunks(4096) {
        session.push(chunk, &mut records);
    }
    session.finish(None, &mut records);
    let found: Vec<Vec<u8>> = records
        .iter()
        .filter_map(|r| match r {
            Record::Frame(f) => Some(f.found.bytes.to_vec()),
            _ => None,
        })
        .collect();
    assert_eq!(found.len(), frames.len(), "frames lost or invented");
    if let Some(i) = (0..frames.len()).find(|i| found[*i] != frames[*i]) {
        panic!(
            "frame {i} differs: found {:02X?}, sent {:02X?} (before it: {:02X?})",
            found[i],
            frames[i],
            frames[i.saturating_sub(1)]
        );
    }
    assert_eq!(session.counts().noise_bytes, noise);
    assert_eq!(session.counts().crc_errors, 0);
    assert_eq!(session.counts().unanswered, 0);
}

/// A capture file is framed on every core, block by block; a pipe in order, as it comes.
/// Both must give the same frames, noise, pairs and summary, byte for byte, whatever the
/// traffic at the blocks' edges: frames of four slaves, glitch bytes, frames cut short and
/// runs of a line held low. Four megabytes: sixteen blocks.
#[test]
fn a_capture_file_framed_on_every_core_reads_as_the_same_bytes_piped() {
    let mut rng = fastrand::Rng::with_seed(20261126);
    let mut slave = Slave::new(&[1, 2, 17, 247], DataModel::manual_examples());
    let mut stream = Vec::new();
    while stream.len() < 1 << 22 {
        for bytes in exchange(&mut rng, &mut slave) {
            let keep = match rng.u8(..50) {
                0 => rng.usize(1..bytes.len()),
                _ => bytes.len(),
            };
            stream.extend_from_slice(&bytes[..keep]);
            match rng.u8(..20) {
                0 => stream.extend(std::iter::repeat_n(0, rng.usize(1..300))),
                1..=4 => stream.push(rng.u8(..)),
                _ => {}
            }
        }
    }
    let dir = tempfile::tempdir().unwrap();
    let capture = dir.path().join("capture.bin");
    std::fs::write(&capture, &stream).unwrap();
    for filter in [&["--slave", "17"][..], &["--function", "16"], &[]] {
        let from_file = mbtool()
            .args(["sniff", "--json", "--input"])
            .arg(&capture)
            .args(filter)
            .args(["--save"])
            .arg(dir.path().join("saved.bin"))
            .output()
            .unwrap();
        let piped = mbtool()
            .args(["sniff", "--json", "--input", "-"])
            .args(filter)
            .write_stdin(stream.clone())
            .output()
            .unwrap();
        assert_eq!(from_file.status.code(), Some(0), "{filter:?}");
        assert!(from_file.stdout.len() > 1000, "{filter:?}");
        assert!(
            from_file.stdout == piped.stdout,
            "{filter:?}: the file and the pipe differ"
        );
        assert_eq!(from_file.stderr, piped.stderr, "{filter:?}");
        assert!(std::fs::read(dir.path().join("saved.bin")).unwrap() == stream);
    }
}

#[test]
fn csv_gives_the_time_json_gives_without_timing_too() {
    let glued: Vec<u8> = WORKED.concat();
    let output = mbtool()
        .args(["sniff", "-o", "csv", "--input", "-"])
        .write_stdin(glued)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    let rows: Vec<Vec<&str>> = stdout.lines().map(|l| l.split(',').collect()).collect();
    assert_eq!(rows[0][..3], ["number", "time", "gap"]);
    // The 03 request, 34 bytes in at 19200 8E1: at 19.479 ms, no gap made up.
    assert_eq!(rows[5][..3], ["5", "0.019479", ""], "{stdout}");
}

#[test]
fn an_ascii_frame_ending_in_lf_alone_is_shown_broken_at_its_end_not_with_its_lrc_ok() {
    let capture = b":1103006B00037E\n:110306022B0000006455\r\n";
    let run = |format: &str| {
        mbtool()
            .args(["sniff", "--mode", "ascii", "-o", format, "--input", "-"])
            .write_stdin(&capture[..])
            .output()
            .unwrap()
    };
    let lines = json_lines(&run("json").stdout);
    assert_eq!(lines[0]["valid"], false, "{}", lines[0]);
    assert_eq!(
        lines[0]["error"], "the frame ends in LF without the CR before it",
        "{}",
        lines[0]
    );
    let table = String::from_utf8(run("table").stdout).unwrap();
    let first = table.lines().next().unwrap();
    assert!(
        first.contains("without the CR") && first.ends_with("[no CR LF]"),
        "{table}"
    );
    // A frame whose PDU reads neither way is not valid either, and its LRC still holds.
    let malformed = b":1103006B0081\r\n";
    let output = mbtool()
        .args(["sniff", "--mode", "ascii", "--input", "-"])
        .write_stdin(&malformed[..])
        .output()
        .unwrap();
    let table = String::from_utf8(output.stdout).unwrap();
    let first = table.lines().next().unwrap();
    assert!(
        first.contains("not a valid request") && first.ends_with("[LRC ok]"),
        "{table}"
    );
}

#[test]
fn csv_of_a_capture_without_a_frame_to_show_is_its_header() {
    let dir = tempfile::tempdir().unwrap();
    let empty = dir.path().join("empty.bin");
    std::fs::write(&empty, b"").unwrap();
    let csv = |capture: &Path, options: &[&str]| {
        let output = mbtool()
            .args(["sniff", "-o", "csv"])
            .args(options)
            .arg("--input")
            .arg(capture)
            .output()
            .unwrap();
        assert!(output.status.success(), "{output:?}");
        String::from_utf8(output.stdout).unwrap()
    };
    let header = "number,time,gap,slave,function,kind,valid,summary\n";
    assert_eq!(csv(&empty, &[]), header);
    let recording = captures().join("wizmodbus.bin");
    assert_eq!(csv(&recording, &["-b", "9600", "--slave", "9"]), header);
    assert!(csv(&captures().join("modbus-tcp.pcap"), &["--slave", "9"])
        .starts_with("number,time,client,server,"));
}

#[test]
fn an_ascii_capture_with_noise_and_a_cut_frame() {
    let capture = b"\x00:1103006B00037E\r\n\xFE:110306022B0000006455\r\n:1103006B:1103006B00037E\r\n:110306022B0000006455\r\n";
    let output = mbtool()
        .args(["sniff", "--mode", "ascii", "--json", "--input", "-"])
        .write_stdin(&capture[..])
        .output()
        .unwrap();
    let lines = json_lines(&output.stdout);
    let kinds: Vec<String> = lines
        .iter()
        .map(|l| format!("{} {}", l["type"].as_str().unwrap(), l["valid"]))
        .collect();
    assert_eq!(
        kinds,
        [
            "noise null",
            "frame true",
            "noise null",
            "frame true",
            "frame false",
            "frame true",
            "frame true",
            "summary null"
        ]
    );
    assert!(
        lines[4]["error"]
            .as_str()
            .unwrap()
            .starts_with("incomplete"),
        "{}",
        lines[4]
    );
    // JSON bytes are hex in every mode.
    assert_eq!(lines[4]["bytes"], "3A 31 31 30 33 30 30 36 42");
    assert_eq!(lines[6]["paired"], true);
}

#[test]
fn a_corrupt_frame_is_a_crc_error_not_noise() {
    let mut bad = WORKED[4].clone();
    bad[7] ^= 0x55;
    let capture = [bad, WORKED[5].clone(), WORKED[4].clone(), WORKED[5].clone()].concat();
    let output = mbtool()
        .args(["sniff", "--json", "--input", "-"])
        .write_stdin(capture)
        .output()
        .unwrap();
    let lines = json_lines(&output.stdout);
    assert_eq!(lines[0]["valid"], false);
    assert!(
        lines[0]["error"].as_str().unwrap().contains("CRC"),
        "{}",
        lines[0]
    );
    let summary = lines.last().unwrap();
    assert_eq!(summary["crc_errors"], 1);
    assert_eq!(summary["noise_bytes"], 0);
    // The answer after the broken request has no request to pair with.
    assert!(lines[1].get("paired").is_none());
}

#[test]
fn a_bit_answer_without_its_request_shows_only_the_bits_sure_to_be_values() {
    // 10 coils asked, 2 bytes answered: the last byte's high bits are set where the
    // padding should be 0, as some devices send. Without the request only 9 bits are sure.
    let request = rtu(&[0x11, 0x01, 0x00, 0x13, 0x00, 0x0A]);
    let answer = rtu(&[0x11, 0x01, 0x02, 0xCD, 0xF1]);
    let sniff = |capture: Vec<u8>, format: &str| {
        let output = mbtool()
            .args(["sniff", "-o", format, "--input", "-"])
            .write_stdin(capture)
            .output()
            .unwrap();
        assert!(output.status.success(), "{output:?}");
        String::from_utf8(output.stdout).unwrap()
    };
    let alone = json_lines(sniff(answer.clone(), "json").as_bytes());
    assert_eq!(
        alone[0]["values"],
        serde_json::json!([1, 0, 1, 1, 0, 0, 1, 1, 1])
    );
    assert_eq!(alone[0]["max_count"], 16);
    assert!(alone[0].get("count").is_none());
    let table = sniff(answer.clone(), "table");
    assert!(
        table.contains("9 to 16 values (the request not seen), the first 9: 1 0 1 1 0 0 1 1"),
        "{table}"
    );
    // With its request, the quantity asked: 10 values, the padding left out.
    let paired = json_lines(sniff([request, answer].concat(), "json").as_bytes());
    assert_eq!(paired[1]["count"], 10);
    assert_eq!(
        paired[1]["values"],
        serde_json::json!([1, 0, 1, 1, 0, 0, 1, 1, 1, 0])
    );
    assert!(paired[1].get("max_count").is_none());
}

#[test]
fn filters_show_one_slave_or_function() {
    let other = rtu(&[0x05, 0x04, 0x00, 0x00, 0x00, 0x01]);
    let capture = [WORKED[4].clone(), WORKED[5].clone(), other].concat();
    let output = mbtool()
        .args(["sniff", "--json", "--input", "-", "--slave", "5"])
        .write_stdin(capture.clone())
        .output()
        .unwrap();
    let lines = json_lines(&output.stdout);
    assert_eq!(
        lines.len(),
        3,
        "one frame, its unanswered line, and the summary"
    );
    assert_eq!(lines[0]["slave"], 5);
    let output = mbtool()
        .args(["sniff", "-o", "table", "--input", "-", "--function", "3"])
        .write_stdin(capture)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&output.stdout);
    assert!(
        text.contains("400108 = 555, 400109 = 0, 400110 = 100"),
        "{text}"
    );
    assert!(!text.contains("slave 5 "), "{text}");
}

#[test]
fn a_pcap_file_holds_every_frame() {
    let dir = tempfile::tempdir().unwrap();
    let pcap = dir.path().join("bus.pcap");
    mbtool()
        .args(["sniff", "--input", "-", "--pcap"])
        .arg(&pcap)
        .write_stdin(WORKED.concat())
        .assert()
        .success();
    let bytes = std::fs::read(&pcap).unwrap();
    assert_eq!(&bytes[..4], &0xA1B2_C3D4u32.to_le_bytes());
    assert_eq!(&bytes[20..24], &147u32.to_le_bytes(), "link type DLT_USER0");
    // Walk the records: each is a 16-byte header and the frame.
    let (mut at, mut records) = (24, Vec::new());
    while at < bytes.len() {
        let len = u32::from_le_bytes(bytes[at + 8..at + 12].try_into().unwrap()) as usize;
        records.push(bytes[at + 16..at + 16 + len].to_vec());
        at += 16 + len;
    }
    let want: Vec<Vec<u8>> = WORKED.to_vec();
    assert_eq!(records, want);
}

#[test]
fn started_with_standard_output_closed_the_table_goes_nowhere_not_into_the_pcap() {
    // `mbtool sniff ... >&-` in a script: the pcap file, the first file opened, would take
    // descriptor 1, and the table would be written into it.
    let dir = tempfile::tempdir().unwrap();
    let capture = dir.path().join("capture.bin");
    std::fs::write(&capture, WORKED.concat()).unwrap();
    let pcap_written = |name: &str, redirect: &str| {
        let pcap = dir.path().join(name);
        let status = Process::new("sh")
            .arg("-c")
            .arg(format!(
                "exec \"$0\" sniff --input - --pcap \"$1\" < \"$2\" {redirect}"
            ))
            .arg(assert_cmd::cargo::cargo_bin("mbtool"))
            .arg(&pcap)
            .arg(&capture)
            .stdout(Stdio::null())
            .status()
            .unwrap();
        assert_eq!(status.code(), Some(0), "{redirect}");
        std::fs::read(pcap).unwrap()
    };
    let open = pcap_written("open.pcap", "");
    assert!(open.len() > 24, "a header and the frames");
    let closed = pcap_written("closed.pcap", ">&-");
    assert!(
        closed == open,
        "the pcap holds {} bytes, not {}: {:?}",
        closed.len(),
        open.len(),
        String::from_utf8_lossy(&closed[..closed.len().min(80)])
    );
}

/// What a live `mbtool sniff` gave: its JSON Lines, when each chunk was written, and what
/// it said on standard error.
struct Sniffed {
    lines: Vec<serde_json::Value>,
    written: Vec<Instant>,
    said: String,
}

/// Runs `mbtool sniff` at 9600 baud on a pty while the test writes `chunks`, each followed
/// by its pause.
fn sniff_live(chunks: &[(Vec<u8>, Duration)], extra: &[&str]) -> Sniffed {
    let pty = Pty::new();
    let mut port = pty.master.try_clone_native().unwrap();
    let mut child = Process::new(assert_cmd::cargo::cargo_bin("mbtool"))
        .args([
            "sniff", "--json", "-b", "9600", "--parity", "none", "--port", &pty.path,
        ])
        .args(extra)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let child_guard_pid = child.id();
    // Wait until sniff listens (it says so on stderr).
    let mut stderr = child.stderr.take().unwrap();
    let mut said = vec![0u8; 16];
    let first = stderr.read(&mut said).unwrap_or(0);
    said.truncate(first);
    let mut written = Vec::new();
    for (bytes, pause) in chunks {
        write_all(&mut port, bytes);
        written.push(Instant::now());
        std::thread::sleep(*pause);
    }
    std::thread::sleep(Duration::from_millis(100));
    let _ = Process::new("kill")
        .args(["-INT", &child_guard_pid.to_string()])
        .status();
    let output = child.wait_with_output().unwrap();
    stderr.read_to_end(&mut said).unwrap();
    assert!(
        output.status.success(),
        "sniff ended with {:?}",
        output.status
    );
    // Nothing came back to the writer: sniff never transmits.
    port.set_timeout(Duration::from_millis(50)).unwrap();
    let mut echo = [0u8; 16];
    assert!(port.read(&mut echo).is_err(), "sniff wrote to the bus");
    Sniffed {
        lines: json_lines(&output.stdout),
        written,
        said: String::from_utf8_lossy(&said).into_owned(),
    }
}

/// Runs `mbtool sniff` on a pty while the test writes frames with chosen gaps at 9600
/// baud; returns sniff's JSON Lines and the gaps the writer made, in microseconds.
fn live_capture(extra: &[&str]) -> (Vec<serde_json::Value>, Vec<u64>) {
    let pauses = [30_000u64, 90_000, 50_000, 120_000, 40_000, 0];
    let chunks: Vec<(Vec<u8>, Duration)> = WORKED[4..10]
        .iter()
        .zip(pauses)
        .map(|(frame, pause)| (frame.clone(), Duration::from_micros(pause)))
        .collect();
    let Sniffed { lines, written, .. } = sniff_live(&chunks, extra);
    // 10 bits a character at 9600 baud; the writer sends each frame whole. The gap the
    // writer made: from the end of a frame's last character to the start of the next
    // frame's first, with frames placed as they arrive whole.
    let char_us = 10.0 * 1e6 / 9600.0;
    let gaps = written
        .windows(2)
        .zip(&chunks[1..])
        .map(|(w, (next, _))| {
            let start2 =
                w[1].duration_since(w[0]).as_micros() as f64 - (next.len() as f64 - 1.0) * char_us;
            (start2 - char_us) as u64
        })
        .collect();
    (lines, gaps)
}

/// The frames of a sniff's JSON Lines: bytes and whether valid.
fn frames_of(lines: &[serde_json::Value]) -> Vec<(serde_json::Value, serde_json::Value)> {
    lines
        .iter()
        .filter(|l| l["type"] == "frame")
        .map(|l| (l["bytes"].clone(), l["valid"].clone()))
        .collect()
}

/// The notice that a line's gaps are not its silences, and the adapter setting that fixes it.
const LATENCY_TIMER_NOTICE: &str = "bytes arrive in bursts";

/// The peak resident memory of a running process, in kB.
fn peak_memory_kb(pid: u32) -> u64 {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).unwrap();
    status
        .lines()
        .find_map(|line| line.strip_prefix("VmHWM:"))
        .and_then(|rest| rest.trim().trim_end_matches("kB").trim().parse().ok())
        .expect("VmHWM in /proc/PID/status")
}

mod replay;
