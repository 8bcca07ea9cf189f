//! decode's outputs, closed pipes, and the logs and dumps of other tools

use super::*;

#[test]
fn a_10_mb_line_is_refused_in_one_line() {
    let mut input = vec![b'A'; 10 * 1024 * 1024];
    input.extend_from_slice(b"\n11 03 00 6B 00 03 76 87\n");
    let run = decode(&["-o", "values"], &input);
    assert_eq!(run.code, 2);
    assert_eq!(run.stderr.lines().count(), 1, "{}", run.stderr);
    assert!(
        run.stderr.starts_with("mbtool: line 1: longer than"),
        "{}",
        run.stderr
    );
}

#[test]
fn values_and_csv_outputs() {
    let answer = "11 03 06 02 2B 00 00 00 64 C8 BA";
    let run = decode(&["-o", "values", answer], b"");
    assert_eq!(run.stdout, "555\n0\n100\n");
    let run = decode(
        &[
            "-o",
            "values",
            "--type",
            "i16",
            &rtu(&[0x11, 0x03, 0x02, 0xFF, 0xFE]),
        ],
        b"",
    );
    assert_eq!(run.stdout, "-2\n");
    let run = decode(&["-o", "csv", answer], b"");
    let mut lines = run.stdout.lines();
    assert_eq!(
        lines.next(),
        Some(
            "mode,kind,slave,function,valid,address,ref,count,max_count,values,exception,error,\
             ambiguous,detail"
        )
    );
    assert_eq!(
        lines.next(),
        Some("rtu,response,17,3,true,,,3,,555 0 100,,,false,")
    );
    // A bit answer alone: the count is not known, the most its bytes can hold is.
    let run = decode(&["-o", "csv", &rtu(&[0x11, 0x02, 0x01, 0xFF])], b"");
    assert_eq!(
        run.stdout.lines().nth(1),
        Some("rtu,response,17,2,true,,,,8,1,,,false,")
    );
    // A frame that reads both ways: the request's fields, and the column before the last
    // says so.
    let run = decode(
        &["-o", "csv", &rtu(&[0x11, 0x01, 0x03, 0x00, 0x00, 0x0A])],
        b"",
    );
    assert_eq!(
        run.stdout.lines().nth(1),
        Some("rtu,request,17,1,true,768,000769,10,,,,,true,")
    );
}

#[test]
fn the_table_shows_the_fields_and_values() {
    let run = decode(&["11 03 06 02 2B 00 00 00 64 C8 BA"], b"");
    assert_eq!(run.code, 0);
    for expected in [
        "RTU response",
        "3 (0x03) Read Holding Registers",
        "022B",
        "555",
        "100",
        "BA ok",
    ] {
        assert!(
            run.stdout.contains(expected),
            "{expected} missing from\n{}",
            run.stdout
        );
    }
}

#[test]
fn a_closed_pipe_ends_quietly_with_status_0() {
    let (mut child, feeder) =
        fed_decode(&["--json"], b"11 03 06 02 2B 00 00 00 64 C8 BA\n", 200_000);
    let mut first = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut first)
        .unwrap();
    assert!(first.contains("\"values\":[555,0,100]"));
    // The reader is gone: like `| head -1`.
    let output = child.wait_with_output().unwrap();
    feeder.join().unwrap();
    assert_eq!(output.status.code(), Some(0));
    assert_eq!(String::from_utf8_lossy(&output.stderr), "");
}

#[test]
fn a_closed_stderr_ends_quietly_too() {
    // `2>&1 | head -1` closes stderr while mbtool still has malformed frames to report.
    let (mut child, feeder) = fed_decode(&[], b"11 03 00\n", 2_000);
    drop(child.stderr.take());
    let mut stdout = child.stdout.take().unwrap();
    let reader = std::thread::spawn(move || std::io::copy(&mut stdout, &mut std::io::sink()));
    feeder.join().unwrap();
    let status = child.wait().unwrap();
    reader.join().unwrap().unwrap();
    // Not 101 (a panic), nor a signal: the status decode gives malformed frames.
    assert_eq!(status.code(), Some(4), "{status:?}");
}

#[test]
fn an_rtu_frame_from_slave_58_is_shown_as_hex_though_it_starts_with_a_colon() {
    // 0x3A is ':', the first character of an ASCII frame; the mode, not the first byte,
    // says how bytes are shown.
    let frame = rtu(&[0x3A, 0x03, 0x00, 0x6B, 0x00, 0x03]);
    let run = decode(&[&frame], b"");
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert!(run.stdout.contains(&frame), "{}", run.stdout);
    assert!(run.stdout.contains("slave    ┆ 58"), "{}", run.stdout);
    let json = decode(&["-o", "json", &frame], b"");
    let value: serde_json::Value = serde_json::from_str(json.stdout.trim()).unwrap();
    assert_eq!(value["slave"], 58);
    assert_eq!(value["mode"], "rtu");
}

/// A log as commissioning tools and libraries write it: each line decodes to the frame
/// on it, whatever stands around it, and a direction mark settles a frame that reads both
/// ways.
#[test]
fn log_lines_are_read_as_they_are() {
    // Function 06: the request and its echo are the same bytes, so only the mark tells.
    let write = rtu(&[0x11, 0x06, 0x00, 0x01, 0x00, 0x03]);
    let log = format!(
        "# commissioning log, panel 3\n\
         [    0.000021] > 11 03 00 6B 00 03 76 87\n\
         [    0.000190] < 11 03 06 02 2B 00 00 00 64 C8 BA\n\
         [11][03][00][6B][00][03][76][87]\n\
         <11><03><06><02><2B><00><00><00><64><C8><BA>\n\
         11:03:00:6b:00:03:76:87\n\
         11-03-00-6B-00-03-76-87\n\
         {{0x11, 0x03, 0x00, 0x6B, 0x00, 0x03, 0x76, 0x87}};\n\
         01 03 03 E8 00 02 44 7B  CRC ok  # t=0 req slave=1 fc=3\n\
         2026-11-23 08:15:02.125 TX: {write}\n\
         2026-11-23 08:15:02.141 RX: {write}\n\
         \n\
         11 03 00 6B 00 03 76 87 11 03 06 02 2B 00 00 00 64 C8 BA\n"
    );
    let run = decode(&["--json"], log.as_bytes());
    assert_eq!((run.code, run.stderr.as_str()), (0, ""), "{}", run.stdout);
    let frames = json_lines(&run.stdout);
    let seen: Vec<(String, u64, bool)> = frames
        .iter()
        .map(|f| {
            let kind = f["kind"].as_str().unwrap().to_string();
            (kind, f["slave"].as_u64().unwrap(), f["valid"] == true)
        })
        .collect();
    let want = |kind: &str, slave| (kind.to_string(), slave, true);
    assert_eq!(
        seen,
        [
            want("request", 17),
            want("response", 17),
            want("request", 17),
            want("response", 17),
            want("request", 17),
            want("request", 17),
            want("request", 17),
            want("request", 1),
            want("request", 17),
            want("response", 17),
            // Two frames glued on one line, split as sniff splits them.
            want("request", 17),
            want("response", 17),
        ]
    );
    // A direction from the log is no guess: the frame is not called ambiguous.
    assert!(frames[8].get("ambiguous").is_none(), "{}", frames[8]);
    assert_eq!(frames[1]["values"], serde_json::json!([555, 0, 100]));
}

/// What mbtool's own `-v` prints can be piped straight back into `decode`.
#[test]
fn the_verbose_trace_decodes() {
    let trace = mbtool()
        .args(["--port", "sim", "read-holding", "17", "400108", "3", "-v"])
        .output()
        .unwrap();
    assert!(trace.status.success());
    let run = decode(&["--json"], &trace.stderr);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let frames = json_lines(&run.stdout);
    let kinds: Vec<&str> = frames.iter().map(|f| f["kind"].as_str().unwrap()).collect();
    assert_eq!(kinds, ["request", "response"]);
    assert_eq!(frames[1]["values"], serde_json::json!([555, 0, 100]));
}

/// A line whose hex bytes are too few for a frame, such as a sniffer's noise, is named.
#[test]
fn a_log_line_without_a_frame_is_named() {
    let run = decode(&[], b"noise: 00  # t=8339\n11 03 00 6B 00 03 76 87\n");
    assert_eq!(run.code, 2);
    assert_eq!(
        run.stderr,
        "mbtool: line 1: no frame: the line's longest run of hex bytes, 00, is shorter than any \
         frame (4 bytes at least); give one frame a line\n"
    );
}

/// Bytes read as an ASCII frame that are not one are shown escaped, never raw.
#[test]
fn an_rtu_frame_read_as_ascii_shows_no_control_characters() {
    let run = decode(&["--mode", "ascii", "11 03 00 6B 00 03 76 87"], b"");
    assert_eq!(run.code, 4);
    assert!(
        run.stdout.contains(r"\x11\x03\0k\0\x03v\x87"),
        "{}",
        run.stdout
    );
    assert!(!run.stdout.contains('\u{11}'), "{}", run.stdout);
}

/// The traffic logs of the tools engineers come from, piped in as they are: every line is
/// decoded whole, as the request or answer its tool marks it.
#[test]
fn the_traffic_logs_of_other_tools_decode_with_their_directions() {
    let request = crate::support::rtu(&[0x01, 0x03, 0x00, 0x00, 0x00, 0x0A]);
    let mut answer_body = vec![0x01, 0x03, 0x14];
    answer_body.extend((0..20u8).map(|i| i * 3));
    let answer = crate::support::rtu(&answer_body);
    let spaced = |bytes: &[u8], sep: &str| {
        bytes
            .iter()
            .map(|b| format!("{b:02X}"))
            .collect::<Vec<_>>()
            .join(sep)
    };
    let pymodbus = |bytes: &[u8]| {
        bytes
            .iter()
            .map(|b| format!("{b:#x}"))
            .collect::<Vec<_>>()
            .join(" ")
    };
    let brackets = |bytes: &[u8], open: char, close: char| {
        bytes
            .iter()
            .map(|b| format!("{open}{b:02X}{close}"))
            .collect::<String>()
    };
    let logs = [
        // Modbus Poll's Communication Traffic.
        format!(
            "000000-Tx:{}\n000001-Rx:{}\n000002-Tx:{}\n000003-Rx:{}\n",
            spaced(&request, " "),
            spaced(&answer, " "),
            spaced(&request, " "),
            spaced(&answer, " ")
        ),
        // QModMaster's bus monitor.
        format!(
            "Sys > 10:33:38:100 : Connecting to Serial Port [/dev/ttyUSB0]...OK\n\
             [RTU]>Tx > 10:33:38:290 : {}  \n[RTU]>Rx > 10:33:38:374 : {}  \n",
            spaced(&request, "  "),
            spaced(&answer, "  ")
        ),
        // mbpoll -v (libmodbus debug).
        format!(
            "{}\nWaiting for a confirmation...\n{}\n",
            brackets(&request, '[', ']'),
            brackets(&answer, '<', '>')
        ),
        // pymodbus debug logging.
        format!(
            "DEBUG:pymodbus.transaction:SEND: {}\nDEBUG:pymodbus.transaction:RECV: {}\n",
            pymodbus(&request),
            pymodbus(&answer)
        ),
    ];
    for log in logs {
        let run = decode(&["--json"], log.as_bytes());
        assert_eq!(run.code, 0, "{log}{}", run.stderr);
        let frames = json_lines(&run.stdout);
        assert!(frames.len() >= 2, "{log}{}", run.stdout);
        for (i, frame) in frames.iter().enumerate() {
            let kind = if i % 2 == 0 { "request" } else { "response" };
            assert_eq!(frame["kind"], kind, "{log}{frame}");
            assert_eq!(frame["slave"], 1, "{log}{frame}");
            assert_eq!(frame["function"], 3, "{log}{frame}");
            assert_eq!(frame["valid"], true, "{log}{frame}");
        }
    }
}

/// A frame pasted without its CRC or LRC is told so in a line that fits 80 columns, with
/// the frame whole.
#[test]
fn a_frame_without_its_checksum_is_told_with_the_checksum_it_lacks() {
    for (pasted, says) in [
        (
            "11 03 00 6B 00 03",
            "without its CRC? With it: 11 03 00 6B 00 03 76 87",
        ),
        (":1103006B0003", "without its LRC? With it: :1103006B00037E"),
        (
            "11 10 00 01 00 02 04 00 0A 01 02",
            "without its CRC? With it: 11 10 00 01 00 02 04 00 0A 01 02 C6 F0",
        ),
        (
            "01 03 14 00 00 00 01 00 02 00 03 00 04 00 05 00 06 00 07 00 08 00 09",
            "without its CRC? It would end ",
        ),
    ] {
        let run = decode(&[pasted], b"");
        assert_eq!(run.code, 4, "{pasted}: {}", run.stderr);
        let error = run
            .stdout
            .lines()
            .find(|line| line.contains("error"))
            .unwrap_or_default();
        assert!(error.contains(says), "{pasted}: {}", run.stdout);
        // With the table's label column and borders, the row fits 80 columns.
        let message = error
            .split('┆')
            .nth(1)
            .unwrap_or_default()
            .trim_matches(['│', ' ']);
        assert!(message.chars().count() + 15 <= 80, "{message}");
    }
    // A wrong CRC is still a wrong CRC.
    let run = decode(&["11 03 00 6B 00 03 76 88"], b"");
    assert!(run.stdout.contains("CRC mismatch"), "{}", run.stdout);
}

/// A log's direction mark is its logger's point of view: Modbus Slave marks the requests
/// it receives `Rx`. Where the bytes read only the other way, they decide; Modbus Poll's
/// newer lines put the counter after the mark.
#[test]
fn a_mark_the_bytes_contradict_gives_way_to_them() {
    let log = "000000-Rx:01 03 00 00 00 0A C5 CD\nTx:000002-01 03 00 00 00 0A C5 CD\nRx:000003-01 83 02 C0 F1\n";
    let run = decode(&["--json"], log.as_bytes());
    assert_eq!(run.code, 0, "{}", run.stderr);
    let kinds: Vec<String> = json_lines(&run.stdout)
        .iter()
        .map(|frame| format!("{} {} {}", frame["kind"], frame["slave"], frame["valid"]))
        .collect();
    assert_eq!(
        kinds,
        [
            "\"request\" 1 true",
            "\"request\" 1 true",
            "\"exception\" 1 true"
        ]
    );
}

/// mbpoll's `-v` output and a pymodbus 2.x debug log, piped whole: their own lines are
/// passed over, and the PDU pymodbus logs without unit or CRC is no frame.
#[test]
fn mbpoll_verbose_output_and_pymodbus_2_logs_pipe_into_decode() {
    let log = "Set mode=rtu\nSet rtu parity=even\niCount=1\n[01][03][00][00][00][03][05][CB]\nWaiting for a confirmation...\n<01><03><06><02><2B><00><00><00><64><05><7A>\n[1]: \t555\n[2]: \t0\n[3]: \t100\nDEBUG:pymodbus.transaction:Running transaction 1\nDEBUG:pymodbus.framer.rtu_framer:Getting Frame - 0x3 0x6 0x2 0x2b 0x0 0x0 0x0 0x64\nDEBUG:pymodbus.transaction:SEND: 0x1 0x3 0x0 0x0 0x0 0x3 0x5 0xcb\n";
    let run = decode(&["--json"], log.as_bytes());
    assert_eq!(run.code, 0, "{}", run.stderr);
    let frames = json_lines(&run.stdout);
    let kinds: Vec<String> = frames
        .iter()
        .map(|f| format!("{} {}", f["kind"], f["valid"]))
        .collect();
    assert_eq!(
        kinds,
        ["\"request\" true", "\"response\" true", "\"request\" true"]
    );
    assert_eq!(frames[1]["values"], serde_json::json!([555, 0, 100]));
    assert!(run.stderr.contains("9 lines passed over"), "{}", run.stderr);
}

/// Hex dumps as people paste them: the offsets and the characters are set aside, and the
/// lines of one dump are one frame, however many lines it takes.
#[test]
fn hex_dumps_of_every_tool_are_their_frames() {
    let request = "11 03 00 6B 00 03 76 87";
    for dump in [
        // Wireshark, Copy as Hex Dump.
        "0000   11 03 00 6b 00 03 76 87                           ...k..v.\n",
        // hexdump -C: the answer glued after the request, over two lines and its length.
        "00000000  11 03 00 6b 00 03 76 87  11 03 06 02 2b 00 00 00  |...k..v.....+...|\n\
         00000010  64 c8 ba                                          |d..|\n00000013\n",
        // xxd.
        "00000000: 1103 006b 0003 7687                      ...k..v.\n",
        // od -A x -t x1.
        "000000 11 03 00 6b 00 03 76 87\n000008\n",
    ] {
        let run = decode(&["--json"], dump.as_bytes());
        assert_eq!(run.code, 0, "{dump}: {}", run.stderr);
        let lines = json_lines(&run.stdout);
        assert_eq!(lines[0]["ref"], "400108", "{dump}");
        assert_eq!(lines[0]["valid"], true, "{dump}");
        if dump.contains("00000013") {
            assert_eq!(lines[1]["values"], serde_json::json!([555, 0, 100]));
        }
    }
    // A log line holding a request and its answer is two frames.
    let run = decode(
        &["--json"],
        format!("12:00:01 TX: {request} RX: 11 03 06 02 2B 00 00 00 64 C8 BA\n").as_bytes(),
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    let kinds: Vec<_> = json_lines(&run.stdout)
        .iter()
        .map(|l| l["kind"].as_str().unwrap().to_string())
        .collect();
    assert_eq!(kinds, ["request", "response"]);
}

/// `decode` alone on a terminal says that it reads standard input and how to end it.
#[test]
fn decode_on_a_terminal_says_what_it_waits_for() {
    let Some(terminal) = crate::support::Terminal::run("decode", 120, 10) else {
        return;
    };
    let screen = terminal.wait_for(std::time::Duration::from_secs(10), |screen| {
        screen.iter().any(|line| line.contains("Ctrl-D ends"))
    });
    assert!(
        screen
            .iter()
            .any(|l| l.contains("decode reads frames from standard input")),
        "{screen:?}"
    );
    terminal.keys(&["11 03 00 6B 00 03 76 87", "Enter", "C-d"]);
    let screen = terminal.wait_for(std::time::Duration::from_secs(10), |_| terminal.done());
    assert!(screen.iter().any(|l| l.contains("400108")), "{screen:?}");
}
