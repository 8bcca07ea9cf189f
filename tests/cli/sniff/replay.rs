//! sniff's replays: timing files, standard input, pipes, filters and what a replay says of its line

use super::*;

#[test]
fn an_exception_line_names_its_function_and_code() {
    let capture = [WORKED[4].clone(), rtu(&[0x11, 0x83, 0x02])].concat();
    let output = mbtool()
        .args(["sniff", "--input", "-"])
        .write_stdin(capture)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&output.stdout);
    let line = text.lines().nth(1).unwrap_or_default();
    assert!(
        line.contains("slave 17   3 Read Holding Registers"),
        "{line}"
    );
    assert!(line.contains("exception 02 illegal data address"), "{line}");
    assert!(
        text.contains("(1 request, 1 answer, 1 exception)"),
        "{text}"
    );
}

#[test]
fn a_first_frame_that_reads_both_ways_says_so() {
    // 8 bytes, function 01, third byte 3: a request for 10 coils, or an answer with 3 bytes
    // of bits. Nothing before it settles which; the 8-byte answer after it does.
    let both = rtu(&[0x11, 0x01, 0x03, 0x00, 0x00, 0x0A]);
    let answer = rtu(&[0x11, 0x01, 0x02, 0xFF, 0x03]);
    let capture = [both.clone(), answer].concat();
    let output = mbtool()
        .args(["sniff", "--json", "--input", "-"])
        .write_stdin(capture.clone())
        .output()
        .unwrap();
    let lines = json_lines(&output.stdout);
    assert_eq!(lines[0]["ambiguous"], true);
    assert_eq!(lines[0]["alternative"]["kind"], "response");
    assert_eq!(
        lines[1]["paired"], true,
        "the answer settles the first frame as a request"
    );
    let output = mbtool()
        .args(["sniff", "--input", "-"])
        .write_stdin(capture)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&output.stdout);
    assert!(
        text.lines().next().unwrap_or_default().contains("request?"),
        "{text}"
    );
}

#[test]
fn an_rtu_frame_from_slave_58_is_hex_in_json() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("slave58.bin");
    let frame = rtu(&[0x3A, 0x03, 0x00, 0x6B, 0x00, 0x03]);
    std::fs::write(&path, &frame).unwrap();
    let output = mbtool()
        .args(["sniff", "--json", "--input"])
        .arg(&path)
        .output()
        .unwrap();
    let lines = json_lines(&output.stdout);
    assert_eq!(lines[0]["type"], "frame");
    assert_eq!(lines[0]["bytes"], "3A 03 00 6B 00 03 70 9C");
    assert_eq!(lines[0]["slave"], 58);
}

#[test]
fn low_latency_on_a_port_that_is_no_usb_adapter_says_so_and_sniffs_on() {
    let request = rtu(&[0x11, 0x03, 0x00, 0x6B, 0x00, 0x03]);
    let sniffed = sniff_live(
        &[(request.clone(), Duration::from_millis(10))],
        &["--low-latency"],
    );
    assert!(
        sniffed.said.contains("is no USB serial adapter")
            && sniffed.said.contains("leave out --low-latency"),
        "{}",
        sniffed.said
    );
    assert!(!sniffed.said.contains("latency_timer"), "{}", sniffed.said);
    assert_eq!(frames_of(&sniffed.lines).len(), 1, "{:?}", sniffed.lines);
}

#[test]
fn reads_on_an_adapters_latency_ticks_are_told_and_a_device_pausing_in_a_frame_is_not() {
    let request = rtu(&[0x11, 0x03, 0x00, 0x6B, 0x00, 0x03]);
    let answer = rtu(&[0x11, 0x03, 0x06, 0x02, 0x2B, 0x00, 0x00, 0x00, 0x64]);
    // A USB adapter with a 32 ms latency timer: a read on each tick, and every answer
    // split across two of them, 25 ms apart on the line though back to back on the wire.
    let tick = Duration::from_millis(32);
    let adapter: Vec<(Vec<u8>, Duration)> = (0..15)
        .flat_map(|_| [&request[..], &answer[..4], &answer[4..]])
        .map(|piece| (piece.to_vec(), tick))
        .collect();
    let sniffed = sniff_live(&adapter, &[]);
    assert!(
        sniffed.said.contains(LATENCY_TIMER_NOTICE),
        "{}",
        sniffed.said
    );
    let valid = frames_of(&sniffed.lines)
        .iter()
        .filter(|(_, valid)| *valid == true)
        .count();
    assert_eq!(valid, 30, "{:?}", frames_of(&sniffed.lines));
    // A frame a write, where the bytes end, at the pace of a polling master; one device
    // pauses 25 ms inside an answer, as long as the adapter's gap. Its reads keep no
    // period: the line's gaps are its own, and nothing is said of a latency timer.
    let ms = Duration::from_millis;
    let mut paced = Vec::new();
    for (exchange, (turnaround, idle)) in [(7, 41), (9, 23), (12, 55), (8, 30), (14, 47), (6, 36)]
        .into_iter()
        .enumerate()
    {
        paced.push((request.clone(), ms(turnaround)));
        if exchange == 3 {
            paced.push((answer[..4].to_vec(), ms(25)));
            paced.push((answer[4..].to_vec(), ms(idle)));
        } else {
            paced.push((answer.clone(), ms(idle)));
        }
    }
    let sniffed = sniff_live(&paced, &[]);
    assert!(
        !sniffed.said.contains(LATENCY_TIMER_NOTICE),
        "{}",
        sniffed.said
    );
}

#[test]
fn where_only_silence_tells_a_replay_of_save_agrees_with_the_live_session() {
    // A user-defined function (no layout: only the silence after it supports it), noise
    // glued to a request, a frame cut short, and the frames after them.
    let quiet = Duration::from_millis(40);
    let user = rtu(&[0x11, 0x41, 0x05, 0x06, 0x07]);
    let request = WORKED[4].clone();
    let chunks = vec![
        (user.clone(), quiet),
        ([&[0x5A, 0x11, 0x03][..], &request].concat(), quiet),
        (WORKED[5].clone(), quiet),
        (request[..5].to_vec(), quiet),
        (request.clone(), quiet),
        (WORKED[5].clone(), quiet),
        // Still unanswered when the capture ends: it waited until then, live and replayed.
        (request.clone(), quiet),
    ];
    let dir = tempfile::tempdir().unwrap();
    let saved = dir.path().join("bus.bin");
    let lines = sniff_live(&chunks, &["--save", saved.to_str().unwrap()]).lines;
    let live = frames_of(&lines);
    let hex = |bytes: &[u8]| serde_json::Value::from(crate::support::spaced_hex(bytes));
    let valid: Vec<serde_json::Value> = live
        .iter()
        .filter(|(_, valid)| *valid == true)
        .map(|(bytes, _)| bytes.clone())
        .collect();
    assert_eq!(
        valid,
        [
            &user,
            &request,
            &WORKED[5].clone(),
            &request,
            &WORKED[5].clone(),
            &request
        ]
        .map(|f| hex(f))
    );
    let unanswered = |lines: &[serde_json::Value]| -> Vec<serde_json::Value> {
        lines
            .iter()
            .filter(|l| l["type"] == "unanswered")
            .cloned()
            .collect()
    };
    let waited_live = unanswered(&lines);
    let last = waited_live.last().expect("the last request waits in vain");
    assert!(
        last["capture_ended"] == true && last["waited"].as_f64().unwrap() > 0.1,
        "{last}"
    );
    let timing = std::fs::read_to_string(saved.with_extension("bin.timing"))
        .expect("the timing is kept beside the bytes");
    assert_eq!(
        timing.lines().nth(1),
        Some("# line: rtu 9600 8N2"),
        "the line the capture was taken on is kept with it"
    );
    // Replayed without a word of the line's settings: the timing file gives them.
    let replay = mbtool()
        .args(["sniff", "--json", "--input"])
        .arg(&saved)
        .output()
        .unwrap();
    assert_eq!(String::from_utf8_lossy(&replay.stderr), "");
    let replayed = json_lines(&replay.stdout);
    assert_eq!(frames_of(&replayed), live);
    // The timing ends where the capture did, so the last request waited as long.
    assert!(timing.trim_end().ends_with(" end"), "{timing}");
    assert_eq!(unanswered(&replayed), waited_live);
    // Replayed at another speed on purpose: the options rule, and the difference is said.
    let faster = mbtool()
        .args(["sniff", "--json", "-b", "115200", "--input"])
        .arg(&saved)
        .output()
        .unwrap();
    assert!(faster.status.success());
    assert_eq!(
        String::from_utf8_lossy(&faster.stderr).trim_end(),
        format!(
            "mbtool: {} records the line as rtu 9600 8N2; replaying it as rtu 115200 8N2, as \
             the options say",
            saved.with_extension("bin.timing").display()
        )
    );
}

#[test]
fn two_hundred_mebibytes_of_00_take_under_50_mb() {
    let mut child = Process::new(assert_cmd::cargo::cargo_bin("mbtool"))
        .args(["sniff", "--json", "--input", "-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let pid = child.id();
    let mut stdin = child.stdin.take().unwrap();
    let zeros = vec![0u8; 1 << 20];
    for _ in 0..200 {
        std::io::Write::write_all(&mut stdin, &zeros).unwrap();
    }
    // Read while sniff still runs: all but a pipe's worth is framed by now.
    let peak = peak_memory_kb(pid);
    drop(stdin);
    let output = child.wait_with_output().unwrap();
    assert!(output.status.success());
    assert!(peak < 50_000, "sniff held {peak} kB");
    let lines = json_lines(&output.stdout);
    let summary = lines.last().unwrap();
    assert_eq!(summary["noise_bytes"], 200u64 << 20);
    assert_eq!(summary["frames"], 0);
}

#[test]
fn a_replay_whose_reader_goes_away_ends_at_once_quietly_with_status_0() {
    // Like `mbtool sniff --input big.bin --json | head -1`: frames are still being found
    // when the pipe closes, and the replay stops there rather than framing the rest.
    let dir = tempfile::tempdir().unwrap();
    let capture = dir.path().join("capture.bin");
    let recording = std::fs::read(captures().join("wizmodbus.bin")).unwrap();
    std::fs::write(&capture, recording.repeat(20_000)).unwrap();
    let started = Instant::now();
    let mut child = Process::new(assert_cmd::cargo::cargo_bin("mbtool"))
        .args([
            "sniff", "-b", "9600", "--parity", "none", "--json", "--input",
        ])
        .arg(&capture)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = String::new();
    std::io::BufRead::read_line(
        &mut std::io::BufReader::new(child.stdout.take().unwrap()),
        &mut first,
    )
    .unwrap();
    assert!(first.contains("\"function\":3"), "{first}");
    let output = child.wait_with_output().unwrap();
    assert_eq!(output.status.code(), Some(0));
    assert_eq!(String::from_utf8_lossy(&output.stderr), "");
    // The whole capture (1.76 million frames) takes seconds to frame.
    assert!(
        started.elapsed() < Duration::from_secs(1),
        "{:?}",
        started.elapsed()
    );
}

#[test]
fn a_timed_replay_says_how_long_the_last_request_waited_in_vain() {
    // A request read at 10 ms, and the line quiet until 60 ms, where the capture ends.
    let dir = tempfile::tempdir().unwrap();
    let capture = dir.path().join("capture.bin");
    std::fs::write(&capture, &WORKED[4]).unwrap();
    std::fs::write(
        dir.path().join("capture.bin.timing"),
        format!("10000 {}\n60000 idle\n", WORKED[4].len()),
    )
    .unwrap();
    let output = mbtool()
        .args(["sniff", "-b", "19200", "--json", "--input"])
        .arg(&capture)
        .output()
        .unwrap();
    let lines = json_lines(&output.stdout);
    let unanswered = lines
        .iter()
        .find(|l| l["type"] == "unanswered")
        .expect("the request is unanswered");
    let waited = unanswered["waited"].as_f64().unwrap();
    assert!((0.049..0.051).contains(&waited), "{unanswered}");
    assert_eq!(unanswered["capture_ended"], true, "{unanswered}");
}

#[test]
fn a_filter_does_not_change_the_time_of_a_frame_it_shows() {
    // A request of slave 1 at 10 ms and a glitch byte at 50 ms are timed; slave 2's request
    // after them is not (the timing stopped short), so its time goes on from the glitch's.
    let dir = tempfile::tempdir().unwrap();
    let capture = dir.path().join("capture.bin");
    let (first, second) = (rtu(&[1, 3, 0, 0, 0, 1]), rtu(&[2, 3, 0, 0, 0, 1]));
    std::fs::write(&capture, [&first[..], &[0xFF], &second].concat()).unwrap();
    std::fs::write(
        dir.path().join("capture.bin.timing"),
        "# line: rtu 9600 8N1\n10000 8\n50000 1\n",
    )
    .unwrap();
    let time_of_slave_2 = |filter: &[&str]| {
        let output = mbtool()
            .args(["sniff", "--json", "--input"])
            .arg(&capture)
            .args(filter)
            .output()
            .unwrap();
        assert!(output.status.success(), "{output:?}");
        let lines = json_lines(&output.stdout);
        let frame = lines
            .iter()
            .find(|l| l["type"] == "frame" && l["slave"] == 2)
            .cloned()
            .unwrap_or_else(|| panic!("slave 2's request is shown: {lines:?}"));
        frame["time"].as_f64().unwrap()
    };
    let unfiltered = time_of_slave_2(&[]);
    // One character after the glitch byte, at 9600 8N1.
    assert!((0.0510..0.0511).contains(&unfiltered), "{unfiltered}");
    assert_eq!(time_of_slave_2(&["--slave", "2"]), unfiltered);
}

#[test]
fn a_request_that_ends_the_capture_is_told_as_such_not_as_waiting_no_time() {
    // The capture's last read is the request itself: it waited no time that the capture
    // shows, and its answer may have come after the capture ended.
    let dir = tempfile::tempdir().unwrap();
    let capture = dir.path().join("capture.bin");
    std::fs::write(&capture, [&WORKED[4][..], &WORKED[5], &WORKED[4]].concat()).unwrap();
    let timing = format!(
        "10000 {}\n20000 {}\n900000 {}\n",
        WORKED[4].len(),
        WORKED[5].len(),
        WORKED[4].len()
    );
    std::fs::write(dir.path().join("capture.bin.timing"), timing).unwrap();
    let run = |format: &str| {
        let output = mbtool()
            .args(["sniff", "-b", "19200", "-o", format, "--input"])
            .arg(&capture)
            .env("NO_COLOR", "1")
            .output()
            .unwrap();
        assert!(output.status.success(), "{output:?}");
        String::from_utf8(output.stdout).unwrap()
    };
    let table = run("table");
    let told: Vec<&str> = table.lines().filter(|l| l.contains("no answer")).collect();
    assert_eq!(told.len(), 1, "{table}");
    assert!(told[0].ends_with("before the capture ended"), "{table}");
    let lines = json_lines(run("json").as_bytes());
    let unanswered: Vec<&serde_json::Value> =
        lines.iter().filter(|l| l["type"] == "unanswered").collect();
    assert_eq!(unanswered.len(), 1, "{lines:?}");
    assert_eq!(unanswered[0]["capture_ended"], true);
    assert!(unanswered[0].get("waited").is_none(), "{}", unanswered[0]);
}

#[test]
fn a_replay_says_which_line_it_frames_on_where_the_timing_does_not_say_or_the_options_differ() {
    let dir = tempfile::tempdir().unwrap();
    let capture = dir.path().join("capture.bin");
    std::fs::write(&capture, &WORKED[4]).unwrap();
    let timing = dir.path().join("capture.bin.timing");
    let said = |timing_text: &str, options: &[&str]| {
        std::fs::write(&timing, timing_text).unwrap();
        let output = mbtool()
            .args(["sniff", "--json"])
            .args(options)
            .arg("--input")
            .arg(&capture)
            .output()
            .unwrap();
        assert!(output.status.success(), "{output:?}");
        String::from_utf8(output.stderr).unwrap()
    };
    // A timing file from before the line was recorded: the defaults, and that is said,
    // unless the options give the line.
    let old = "10000 8\n";
    assert_eq!(
        said(old, &[]).trim_end(),
        format!(
            "mbtool: {} does not say which line the capture was taken on: replaying it as rtu \
             19200 8E1; give -b and --parity if it was another",
            timing.display()
        )
    );
    assert_eq!(said(old, &["-b", "9600", "--parity", "none"]), "");
    // Another parity given: the stop bits that go with it, as on a port, unless given too.
    let recorded = "# line: rtu 9600 8N2\n10000 8\n";
    assert_eq!(said(recorded, &[]), "");
    for (options, replayed) in [
        (&["--parity", "even"][..], "rtu 9600 8E1"),
        (
            &["--parity", "even", "--stop-bits", "2"][..],
            "rtu 9600 8E2",
        ),
        (&["--mode", "ascii"][..], "ascii 9600 7N2"),
    ] {
        let told = said(recorded, options);
        assert!(
            told.contains(&format!(
                "records the line as rtu 9600 8N2; replaying it as {replayed},"
            )),
            "{options:?}: {told}"
        );
    }
}

#[test]
fn a_timing_file_that_goes_back_or_falls_short_is_told() {
    let dir = tempfile::tempdir().unwrap();
    let capture = dir.path().join("capture.bin");
    std::fs::write(&capture, [&WORKED[4][..], &WORKED[5][..]].concat()).unwrap();
    let timing = dir.path().join("capture.bin.timing");
    let sniff = || {
        mbtool()
            .args(["sniff", "-b", "19200", "--json", "--input"])
            .arg(&capture)
            .output()
            .unwrap()
    };
    // Edited by hand: a time before the one above it is refused, with its line.
    std::fs::write(&timing, "9000 8\n1000 11\n").unwrap();
    let output = sniff();
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("capture.bin.timing:2:"), "{stderr}");
    // Reads that come to more than the capture (a count of 2^64 - 1, of 4 GB): refused
    // before anything is framed or allocated, and nothing is shown.
    for count in ["18446744073709551615", "4294967296", "12"] {
        std::fs::write(&timing, format!("9000 8\n9500 {count}\n")).unwrap();
        let output = sniff();
        assert_eq!(output.status.code(), Some(2), "{output:?}");
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(
            stderr.starts_with("mbtool: ")
                && stderr.contains("capture.bin.timing:2: the reads come to more"),
            "{stderr}"
        );
        assert!(output.stdout.is_empty());
    }
    // Not text at all: a usage error too, with what to do.
    std::fs::write(&timing, [0xFF, 0xFE, b'\n']).unwrap();
    assert_eq!(sniff().status.code(), Some(2));
    // Covering only the request: the answer is framed without timing, and that is said.
    std::fs::write(&timing, "9000 8\n").unwrap();
    let output = sniff();
    assert!(output.status.success());
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("first 8 bytes; the last 11"), "{stderr}");
    let times = |stdout: &[u8]| -> Vec<f64> {
        json_lines(stdout)
            .into_iter()
            .filter(|l| l["type"] == "frame")
            .map(|l| l["time"].as_f64().unwrap())
            .collect()
    };
    // The answer goes on from the request's time at the line's speed, never before it.
    let shown = times(&output.stdout);
    assert_eq!(shown.len(), 2);
    assert!(shown[0] < shown[1] && shown[1] < 0.1, "{shown:?}");
    // Two reads stamped alike: the second is placed after the first, not over it.
    std::fs::write(&timing, "9000 8\n9000 11\n").unwrap();
    let shown = times(&sniff().stdout);
    assert!(shown.len() == 2 && shown[0] < shown[1], "{shown:?}");
    // Written by an editor: a byte order mark and a tab are read as the text they frame.
    std::fs::write(&timing, "\u{feff}9000\t8\n9600 11\n").unwrap();
    let output = sniff();
    assert!(
        output.status.success() && output.stderr.is_empty(),
        "{output:?}"
    );
    // A line of 100,000 characters is quoted by its start, in one short line.
    std::fs::write(&timing, "9".repeat(100_000) + " x\n").unwrap();
    let output = sniff();
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.len() < 300 && stderr.lines().count() == 1,
        "{stderr}"
    );
    // A directory or a FIFO of that name: refused at once, a FIFO not waited on.
    std::fs::remove_file(&timing).unwrap();
    std::fs::create_dir(&timing).unwrap();
    let output = sniff();
    assert_eq!(output.status.code(), Some(2), "{output:?}");
    assert!(String::from_utf8_lossy(&output.stderr).contains("is not a file"));
    std::fs::remove_dir(&timing).unwrap();
    let made = std::process::Command::new("mkfifo")
        .arg(&timing)
        .status()
        .unwrap();
    assert!(made.success());
    let started = std::time::Instant::now();
    let output = sniff();
    assert_eq!(output.status.code(), Some(2), "{output:?}");
    assert!(started.elapsed() < std::time::Duration::from_secs(1));
}

#[test]
fn with_timing_a_user_defined_answer_runs_to_the_silence_after_it() {
    // Generated traffic at 9600 8E1 (a window of a long mix, as a UART delivered it): the
    // answer of function 106 comes 3.5 ms after its request and its first six bytes pass
    // their CRC; with the timing it is taken whole, to the silence after it.
    let bytes = hex::decode(concat!(
        "1E72BAB11B0C7F3515C26EE5C74B767255154FCFE756E50F111708D60009000A000102A9F8DA3611",
        "171245CDCC26D03C4C7BEF9EE7C02B8A43AF13401318896A70538530005FA4896A60C6A236540083",
        "9DB17DDADCF87C890206DCF8DA9AE8930206DCF8DA9AE8930104543000052036",
    ))
    .unwrap();
    let timing: String = [
        "31170345 2; 31171466 1; 31172667 1; 31176084 3; 31177192 1; 31178424 1",
        "31185669 3; 31188054 2; 31192572 4; 31194842 2; 31197126 2; 31199502 2",
        "31204604 idle; 31209412 2; 31213946 4; 31218524 4; 31221920 3; 31223083 1",
        "31224191 1; 31231467 3; 31233730 2; 31236047 2; 31238260 2; 31241681 3",
        "31246283 4; 31247462 1; 31249765 2; 31253241 3; 31254299 1; 31259449 idle",
        "31262023 2; 31265486 3; 31267846 2; 31270137 2; 31277094 3; 31281625 4",
        "31285125 3; 31288482 3; 31293196 4; 31298264 idle; 31302269 1; 31304673 2",
        "31309203 4; 31310382 1; 31314585 1; 31317981 3; 31321357 3; 31322562 1",
        "31327683 idle; 31330589 2; 31334012 3; 31335131 1; 31337384 2; 31363669 idle",
    ]
    .iter()
    .flat_map(|row| row.split("; "))
    .map(|line| format!("{line}\n"))
    .collect();
    let dir = tempfile::tempdir().unwrap();
    let capture = dir.path().join("capture.bin");
    std::fs::write(&capture, bytes).unwrap();
    std::fs::write(dir.path().join("capture.bin.timing"), timing).unwrap();
    let output = mbtool()
        .args([
            "sniff", "-b", "9600", "--parity", "even", "--json", "--input",
        ])
        .arg(&capture)
        .output()
        .unwrap();
    let answer = "89 6A 60 C6 A2 36 54 00 83 9D B1 7D DA DC F8 7C 89";
    let frames: Vec<String> = json_lines(&output.stdout)
        .iter()
        .filter(|l| l["type"] == "frame" && l["valid"] == true)
        .map(|l| l["bytes"].as_str().unwrap().to_string())
        .collect();
    assert!(frames.iter().any(|f| f == answer), "{frames:#?}");
}

#[test]
fn a_pipe_that_pauses_has_its_frames_shown_at_once_even_beside_a_file_named_dash() {
    // `socat ... | mbtool sniff --input -`: the frames of a live line are shown as they
    // come, not once a batch of them has gathered; a file that happens to be named `-` in
    // the working directory changes nothing.
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("-"), WORKED.concat()).unwrap();
    let mut child = crate::support::mbtool_process()
        .args(["sniff", "--input", "-", "--json"])
        .current_dir(dir.path())
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdin = child.stdin.take().unwrap();
    let stdout = child.stdout.take().unwrap();
    let (line, first_line) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let mut first = String::new();
        let _ = std::io::BufRead::read_line(&mut std::io::BufReader::new(stdout), &mut first);
        let _ = line.send(first);
    });
    let sent = Instant::now();
    std::io::Write::write_all(&mut stdin, &WORKED.concat()).unwrap();
    // The pipe stays open: the line may still be going.
    let first = first_line.recv_timeout(Duration::from_secs(5));
    let shown = sent.elapsed();
    drop(stdin);
    let output = child.wait_with_output().unwrap();
    assert_eq!(output.status.code(), Some(0));
    let first = first.expect("no frame shown while the pipe stayed open");
    assert!(first.contains("\"type\":\"frame\""), "{first}");
    assert!(shown < Duration::from_secs(1), "shown after {shown:?}");
}

#[test]
fn standard_input_still_open_ends_on_sigterm_and_sigint_with_its_frames_and_the_summary() {
    // `socat ... | mbtool sniff --input -`: a line captured by another program, ended by
    // Ctrl-C or SIGTERM while the pipe is quiet, as a live capture ends.
    for signal in ["TERM", "INT"] {
        let mut child = crate::support::mbtool_process()
            .args(["sniff", "--input", "-", "--json"])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let mut stdin = child.stdin.take().unwrap();
        std::io::Write::write_all(&mut stdin, &WORKED.concat()).unwrap();
        // The replay writes in batches: give it time to take the bytes in.
        std::thread::sleep(Duration::from_millis(500));
        let sent = Instant::now();
        let killed = Process::new("kill")
            .args([&format!("-{signal}"), &child.id().to_string()])
            .status()
            .unwrap();
        assert!(killed.success());
        // Its input still open, it must end on the signal alone.
        while child.try_wait().unwrap().is_none() {
            if sent.elapsed() > Duration::from_secs(5) {
                let _ = child.kill();
                panic!("sniff --input - did not end on SIG{signal}");
            }
            std::thread::sleep(Duration::from_millis(20));
        }
        assert!(
            sent.elapsed() < Duration::from_secs(2),
            "{:?}",
            sent.elapsed()
        );
        let output = child.wait_with_output().unwrap();
        drop(stdin);
        assert_eq!(output.status.code(), Some(0), "SIG{signal}");
        let rest = String::from_utf8_lossy(&output.stdout);
        let lines: Vec<&str> = rest.lines().collect();
        let frames = lines
            .iter()
            .filter(|l| l.contains("\"type\":\"frame\""))
            .count();
        assert_eq!(frames, WORKED.len(), "SIG{signal}: {rest}");
        assert!(
            lines.last().unwrap().contains("\"type\":\"summary\""),
            "{rest}"
        );
    }
}

/// A file is read as what its bytes are, whatever its name: the bytes `--save bus.cap`
/// kept of a serial line are read back from bus.cap, with a word that it is no pcap.
#[test]
fn a_serial_capture_named_as_a_pcap_is_read_as_what_it_holds() {
    let dir = tempfile::tempdir().unwrap();
    let named = dir.path().join("bus.cap");
    std::fs::copy(captures().join("wizmodbus.bin"), &named).unwrap();
    let read = |path: &Path| {
        mbtool()
            .args(["sniff", "-b", "9600", "--json", "--input"])
            .arg(path)
            .output()
            .unwrap()
    };
    let (as_cap, as_bin) = (read(&named), read(&captures().join("wizmodbus.bin")));
    assert!(as_cap.status.success(), "{as_cap:?}");
    assert_eq!(as_cap.stdout, as_bin.stdout);
    assert_eq!(
        String::from_utf8_lossy(&as_cap.stderr),
        format!(
            "mbtool: {} is no pcap or pcapng file: read as the bytes of a serial line\n",
            named.display()
        )
    );
}

#[test]
fn live_on_a_pty_the_gaps_match_and_save_replays() {
    let dir = tempfile::tempdir().unwrap();
    let saved = dir.path().join("bus.bin");
    let (lines, written) = live_capture(&["--save", saved.to_str().unwrap()]);
    let frames: Vec<&serde_json::Value> = lines.iter().filter(|l| l["type"] == "frame").collect();
    assert_eq!(frames.len(), 6);
    let gaps: Vec<u64> = frames[1..]
        .iter()
        .map(|f| (f["gap"].as_f64().unwrap() * 1e6) as u64)
        .collect();
    // Each gap is seen as a gap, and the longest the writer made is the longest seen: the
    // pty hands bytes over at once, so the gaps differ from those made only by scheduling,
    // which a loaded machine stretches (the figures are measured, not asserted).
    assert!(
        gaps.iter().all(|gap| *gap > 2_000),
        "{gaps:?} vs {written:?}"
    );
    let longest = |g: &[u64]| (0..g.len()).max_by_key(|i| g[*i]);
    assert_eq!(longest(&gaps), longest(&written), "{gaps:?} vs {written:?}");
    // The same bytes replayed give the same frames.
    let replay = mbtool()
        .args(["sniff", "--json", "--input"])
        .arg(&saved)
        .output()
        .unwrap();
    assert_eq!(frames_of(&json_lines(&replay.stdout)), frames_of(&lines));
    assert_eq!(std::fs::read(&saved).unwrap(), WORKED[4..10].concat());
}
