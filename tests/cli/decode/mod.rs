//! `mbtool decode` as a user meets it: input spellings, nasty input, exit codes, output.

use std::io::{BufRead, BufReader, Write};

use std::process::{Command as Process, Stdio};

use crate::support::{mbtool, spaced_hex};

/// An RTU frame with its CRC, as spaced hex.
fn rtu(body: &[u8]) -> String {
    spaced_hex(&crate::support::rtu(body))
}

struct Run {
    code: i32,
    stdout: String,
    stderr: String,
}

fn decode(args: &[&str], stdin: &[u8]) -> Run {
    let output = mbtool()
        .arg("decode")
        .args(args)
        .write_stdin(stdin)
        .output()
        .unwrap();
    Run {
        code: output.status.code().unwrap_or(-1),
        stdout: String::from_utf8_lossy(&output.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&output.stderr).into_owned(),
    }
}

fn json_lines(stdout: &str) -> Vec<serde_json::Value> {
    stdout
        .lines()
        .map(|l| serde_json::from_str(l).expect("one JSON object per line"))
        .collect()
}

/// Every diagnostic is one line starting `mbtool: `.
fn assert_one_line_errors(stderr: &str) {
    for line in stderr.lines() {
        assert!(
            line.starts_with("mbtool: "),
            "not an mbtool message: {line:?}"
        );
    }
}

/// Decodes one RTU frame as JSON and returns its object and the exit status.
fn decode_one(body_with_crc: &str) -> (serde_json::Value, i32) {
    let run = decode(&["--json"], body_with_crc.as_bytes());
    assert_one_line_errors(&run.stderr);
    let mut lines = json_lines(&run.stdout);
    assert_eq!(lines.len(), 1, "{}", run.stdout);
    (lines.remove(0), run.code)
}

#[test]
fn every_input_spelling_gives_the_same_frame() {
    let spellings = [
        "11 03 00 6B 00 03 76 87",
        "1103006B00037687",
        "0x11,0x03,0x00,0x6B,0x00,0x03,0x76,0x87",
        ":1103006B00037E",
        "3A 31 31 30 33 30 30 36 42 30 30 30 33 37 45 0D 0A",
    ];
    for spelling in spellings {
        let (json, code) = decode_one(spelling);
        assert_eq!(code, 0, "{spelling}");
        assert_eq!(json["slave"], 17, "{spelling}");
        assert_eq!(json["function"], 3, "{spelling}");
        assert_eq!(json["kind"], "request", "{spelling}");
        assert_eq!(json["address"], 107, "{spelling}");
        assert_eq!(json["ref"], "400108", "{spelling}");
        assert_eq!(json["count"], 3, "{spelling}");
    }
}

#[test]
fn a_tcp_frame_is_detected() {
    let (json, code) = decode_one("00 01 00 00 00 06 11 03 00 6B 00 03");
    assert_eq!(code, 0);
    assert_eq!(json["mode"], "tcp");
    assert_eq!(json["slave"], 17);
    assert_eq!(json["transaction"], 1);
}

#[test]
fn crlf_lf_and_cr_line_ends_and_empty_lines() {
    let input =
        b"11 03 00 6B 00 03 76 87\r\n\n11 03 00 6B 00 03 76 87\r11 03 00 6B 00 03 76 87\n\r\n";
    let run = decode(&["--json"], input);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(json_lines(&run.stdout).len(), 3);
}

#[test]
fn a_bad_crc_names_both_crcs_and_exits_4() {
    let run = decode(&["--json"], b"11 03 00 6B 00 03 76 88\n");
    assert_eq!(run.code, 4);
    let json = &json_lines(&run.stdout)[0];
    assert_eq!(json["valid"], false);
    let error = json["error"].as_str().unwrap();
    assert!(
        error.contains("76 88") && error.contains("76 87"),
        "{error}"
    );
    assert_one_line_errors(&run.stderr);
}

#[test]
fn a_line_that_is_not_hex_exits_2_and_outranks_a_bad_crc() {
    let run = decode(
        &[],
        b"11 03 00 6B 00 03 76 88\n110\nh\xC3\xA9llo\n11 03 00 6B 00 03 76 87\n",
    );
    assert_eq!(run.code, 2);
    assert!(
        run.stderr.contains("line 2: odd number of hex digits"),
        "{}",
        run.stderr
    );
    assert!(run.stderr.contains("line 3:"), "{}", run.stderr);
    assert_one_line_errors(&run.stderr);
    // The good frame after the bad lines is still decoded.
    assert!(run.stdout.contains("400108"));
}

#[test]
fn nasty_frames_are_reported_not_trusted() {
    let cases: Vec<(&str, String, &str)> = vec![
        ("colon alone", ":".to_string(), "too short"),
        (
            "byte count larger than the frame",
            rtu(&[0x11, 0x03, 0x08, 0x02, 0x2B, 0x00, 0x00]),
            "PDU bytes",
        ),
        (
            "quantity 0",
            rtu(&[0x11, 0x03, 0x00, 0x6B, 0x00, 0x00]),
            "quantity 0",
        ),
        (
            "quantity 0xFFFF",
            rtu(&[0x11, 0x03, 0x00, 0x00, 0xFF, 0xFF]),
            "quantity 65535",
        ),
        (
            "address + quantity past 65535",
            rtu(&[0x11, 0x01, 0xFF, 0xF0, 0x00, 0x20]),
            "past 65535",
        ),
        ("300-byte frame", rtu(&[0x11; 298]), "longer than the 256"),
        (
            "CVE-2019-14462: byte count disagrees with the quantity",
            rtu(&[0x11, 0x10, 0x00, 0x01, 0x00, 0x02, 0x06, 0, 1, 0, 2, 0, 3]),
            "byte count 6 does not match quantity 2",
        ),
        (
            "CVE-2019-14463: coil byte count disagrees with the quantity",
            rtu(&[0x11, 0x0F, 0x00, 0x13, 0x00, 0x0A, 0x01, 0xCD]),
            "byte count 1 does not match quantity 10",
        ),
        (
            "CVE-2022-0367: function 23 writes past the end",
            rtu(&[
                0x11, 0x17, 0x00, 0x00, 0x00, 0x01, 0xFF, 0xFF, 0x00, 0x02, 0x04, 0, 1, 0, 2,
            ]),
            "past 65535",
        ),
        ("bare function 03", rtu(&[0x11, 0x03]), "needs"),
        (
            "exception with extra bytes",
            rtu(&[0x11, 0x83, 0x02, 0x00]),
            "1 byte after the exception code: 00",
        ),
        (
            "MBAP length too short",
            "00 01 00 00 00 01 11".to_string(),
            "too short",
        ),
        (
            "MBAP length too long",
            "00 01 00 00 00 FF 11 03 00 6B 00 03".to_string(),
            "MBAP length",
        ),
    ];
    for (name, frame, says) in cases {
        let mode: &[&str] = if name.starts_with("MBAP") {
            &["--mode", "tcp"]
        } else {
            &[]
        };
        let mut args = vec!["--json"];
        args.extend_from_slice(mode);
        let run = decode(&args, frame.as_bytes());
        assert_eq!(run.code, 4, "{name}: {}", run.stderr);
        let json = &json_lines(&run.stdout)[0];
        assert_eq!(json["valid"], false, "{name}");
        let error = json["error"].as_str().unwrap_or_default();
        assert!(error.contains(says), "{name}: {error}");
    }
}

#[test]
fn bare_function_codes_07_and_17_are_valid_requests() {
    for function in [0x07, 0x11] {
        let (json, code) = decode_one(&rtu(&[0x11, function]));
        assert_eq!(code, 0);
        assert_eq!(json["kind"], "request");
        assert_eq!(json["function"], function);
    }
}

#[test]
fn an_exception_is_named() {
    let (json, code) = decode_one(&rtu(&[0x11, 0x83, 0x02]));
    assert_eq!(code, 0);
    assert_eq!(json["kind"], "exception");
    assert_eq!(json["function"], 0x83);
    assert_eq!(json["exception"], 2);
    assert_eq!(json["exception_name"], "illegal data address");
}

#[test]
fn a_frame_that_reads_both_ways_says_so_and_direction_settles_it() {
    // 8 bytes, function 01, third byte 3: a request for 10 coils at 0x0300, or an answer
    // carrying 3 bytes of bits.
    let frame = rtu(&[0x11, 0x01, 0x03, 0x00, 0x00, 0x0A]);
    let (json, _) = decode_one(&frame);
    assert_eq!(json["ambiguous"], true);
    assert_eq!(json["kind"], "request");
    assert_eq!(json["alternative"]["kind"], "response");
    let table = decode(&[&frame], b"");
    assert!(
        table.stdout.contains("also reads as a response"),
        "{}",
        table.stdout
    );

    let run = decode(&["--json", "--direction", "response", &frame], b"");
    let json = &json_lines(&run.stdout)[0];
    assert_eq!(json["kind"], "response");
    assert!(json.get("ambiguous").is_none());
    // 3 bytes of bits: 17 to 24 values, of which the first 17 are sure.
    assert_eq!(json["values"].as_array().unwrap().len(), 17);
    assert_eq!(json["max_count"], 24);
}

#[test]
fn an_empty_frame_argument_is_refused_and_empty_input_is_nothing_to_show() {
    let request = rtu(&[0x11, 0x03, 0x00, 0x6B, 0x00, 0x03]);
    let answer = rtu(&[0x11, 0x03, 0x06, 0x02, 0x2B, 0x00, 0x00, 0x00, 0x64]);
    // `mbtool decode "$REQUEST" "$ANSWER"` with a variable unset or blank, alone or beside
    // real frames (which it must not make into one line).
    for (args, blank) in [
        (vec![""], 1),
        (vec!["  "], 1),
        (vec!["", " "], 1),
        (vec![request.as_str(), answer.as_str(), ""], 3),
        (vec![request.as_str(), "\t", answer.as_str()], 2),
    ] {
        let run = decode(&args, b"");
        assert_eq!(run.code, 2, "{args:?}");
        let said = format!("mbtool: frame {blank} is empty");
        assert!(run.stderr.starts_with(&said), "{args:?}: {}", run.stderr);
        assert_one_line_errors(&run.stderr);
        assert_eq!(run.stdout, "", "nothing is decoded before the check");
    }
    // Comments alone are no frames; a comment line inside an argument hides nothing after
    // it, as on standard input.
    for args in [&["#"][..], &["# c", "#"]] {
        let run = decode(args, b"");
        assert_eq!(run.code, 2, "{args:?}");
        assert!(
            run.stderr
                .starts_with("mbtool: the arguments hold no frame"),
            "{}",
            run.stderr
        );
    }
    let log = format!("# saved at the panel\n{request}\n{answer}\n");
    let run = decode(&["-o", "csv", &log], b"");
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(
        run.stdout.lines().count(),
        3,
        "a header and two frames: {}",
        run.stdout
    );
    // A filter given nothing prints nothing.
    for stdin in [&b""[..], b"\n\n", b"# no frames today\n"] {
        let run = decode(&[], stdin);
        assert_eq!(
            (run.code, run.stdout.as_str(), run.stderr.as_str()),
            (0, "", "")
        );
    }
}

#[test]
fn a_binary_file_gets_one_message_not_one_a_line() {
    // An executable, a capture of raw bytes: text never holds a NUL byte.
    let mut binary: Vec<u8> = b"11 03 00 6B 00 03 76 87\n".to_vec();
    for i in 0u32..20_000 {
        binary.extend_from_slice(&i.wrapping_mul(2_654_435_761).to_le_bytes());
        if i % 50 == 0 {
            binary.push(b'\n');
        }
    }
    let run = decode(&[], &binary);
    assert_eq!(run.code, 2);
    assert_eq!(run.stderr.lines().count(), 1, "{}", run.stderr);
    assert!(
        run.stderr
            .contains("line 2 holds NUL bytes: the input is binary"),
        "{}",
        run.stderr
    );
    // The frame before it is shown all the same.
    assert!(
        run.stdout.contains("Read Holding Registers"),
        "{}",
        run.stdout
    );

    // A log saved as UTF-16 by a Windows editor is told as such.
    let utf16: Vec<u8> = [0xFF, 0xFE]
        .into_iter()
        .chain("11 03 00 6B 00 03 76 87\r\n".bytes().flat_map(|b| [b, 0]))
        .collect();
    let run = decode(&[], &utf16);
    assert_eq!(run.code, 2);
    assert!(run.stderr.contains("UTF-16"), "{}", run.stderr);
    assert_one_line_errors(&run.stderr);
    // Without its byte-order mark too, big-endian.
    let utf16be: Vec<u8> = "11 03 00 6B 00 03 76 87\n"
        .bytes()
        .flat_map(|b| [0, b])
        .collect();
    let run = decode(&[], &utf16be);
    assert_eq!(run.code, 2);
    assert!(run.stderr.contains("UTF-16"), "{}", run.stderr);
}

#[test]
fn functions_kept_byte_for_byte_read_only_the_way_their_length_allows() {
    // The manual's worked frames for functions 11, 12 and 24, each kept as bytes: a Get
    // Comm Event Counter request is its function code alone, its answer four bytes more.
    for (body, kind) in [
        (&[0x11, 0x0B][..], "request"),
        (&[0x11, 0x0B, 0xFF, 0xFF, 0x01, 0x08][..], "response"),
        (&[0x11, 0x0C][..], "request"),
        (
            &[
                0x11, 0x0C, 0x08, 0x00, 0x00, 0x01, 0x08, 0x01, 0x21, 0x01, 0x20,
            ][..],
            "response",
        ),
        (&[0x11, 0x18, 0x04, 0xDE][..], "request"),
        (
            &[0x11, 0x18, 0x00, 0x06, 0x00, 0x02, 0x01, 0xB8, 0x12, 0x84][..],
            "response",
        ),
    ] {
        let (json, code) = decode_one(&rtu(body));
        assert_eq!(code, 0, "{json}");
        assert_eq!(json["kind"], kind, "{json}");
        assert!(json.get("ambiguous").is_none(), "{json}");
    }
    // Read File Record's byte count fits both ways: its groups tell, 7 bytes each in a
    // request, a length and as many bytes in its answer (the manual's frames). A group
    // without reference type 06 is neither.
    let read_request = [
        0x11, 0x14, 0x0E, 0x06, 0x00, 0x04, 0x00, 0x01, 0x00, 0x02, 0x06, 0x00, 0x03, 0x00, 0x09,
        0x00, 0x02,
    ];
    let read_answer = [
        0x11, 0x14, 0x0C, 0x05, 0x06, 0x0D, 0xFE, 0x00, 0x20, 0x05, 0x06, 0x33, 0xCD, 0x00, 0x40,
    ];
    for (body, kind) in [(&read_request[..], "request"), (&read_answer, "response")] {
        let (json, code) = decode_one(&rtu(body));
        assert_eq!(code, 0, "{json}");
        assert_eq!(json["kind"], kind, "{json}");
        assert!(json.get("ambiguous").is_none(), "{json}");
    }
    let mut no_reference = read_request;
    no_reference[10] = 0x07;
    let (json, code) = decode_one(&rtu(&no_reference));
    assert_eq!(code, 4, "{json}");
    assert!(
        json["error"]
            .as_str()
            .unwrap()
            .contains("reference type 06"),
        "{json}"
    );
    // Write File Record's answer echoes its request: it reads both ways, and says so.
    let write = [
        0x11, 0x15, 0x0D, 0x06, 0x00, 0x04, 0x00, 0x07, 0x00, 0x03, 0x06, 0xAF, 0x04, 0xBE, 0x10,
        0x0D,
    ];
    let (json, code) = decode_one(&rtu(&write));
    assert_eq!(code, 0, "{json}");
    assert_eq!(json["ambiguous"], true, "{json}");
    // Asked to read one the other way, it is told why not.
    let run = decode(
        &[
            "--direction",
            "request",
            &rtu(&[0x11, 0x0B, 0xFF, 0xFF, 0x01, 0x08]),
        ],
        b"",
    );
    assert_ne!(run.code, 0);
    assert!(
        // The function in decimal, as everywhere else: 11, not 0B.
        run.stdout
            .contains("function 11 carries 1 PDU bytes, the frame has 5"),
        "{}",
        run.stdout
    );
}

#[test]
fn a_bit_table_shows_every_byte_as_the_frame_has_it_padding_included() {
    // 10 coils: the last byte holds 2 values and 6 padding bits, set here (FD), so that a
    // byte made up from the values (01), or none, would show. The write's last byte is 01.
    let request = rtu(&[0x11, 0x01, 0x00, 0x13, 0x00, 0x0A]);
    let answer = rtu(&[0x11, 0x01, 0x02, 0xCD, 0xFD]);
    let write = rtu(&[0x11, 0x0F, 0x00, 0x13, 0x00, 0x0A, 0x02, 0xCD, 0x01]);
    let lines = format!("{request}\n{answer}\n{answer}\n{write}\n");
    let run = decode(&["-o", "table"], lines.as_bytes());
    assert_eq!(run.code, 0, "{}", run.stderr);
    // Each table row's cells, between its borders.
    let rows: Vec<Vec<&str>> = run
        .stdout
        .lines()
        .filter(|line| line.starts_with('│'))
        .map(|line| line.trim_matches('│').split('┆').map(str::trim).collect())
        .collect();
    let has = |cells: &[&str]| rows.iter().any(|row| row.as_slice() == cells);
    // The answer after its request: 10 coils, its last byte as sent.
    assert!(has(&["000028", "27", "FD", "1 0"]), "{}", run.stdout);
    // The same answer alone: the bits sure to be values, the byte as sent, and the bits
    // that are values or padding as they are, not as values.
    assert!(has(&["8", "FD", "1"]), "{}", run.stdout);
    assert!(
        has(&[
            "count",
            "9 to 16: the request decides (the bits after the first 9, 0 1 1 1 1 1 1, may be \
             padding)"
        ]),
        "{}",
        run.stdout
    );
    // The write of 10 coils.
    assert!(has(&["000028", "27", "01", "1 0"]), "{}", run.stdout);
}

#[test]
fn an_answer_after_its_request_reads_with_the_request_addresses_and_quantity() {
    // 10 coils from 0x0013; the answer's last byte holds 2 values and 6 padding bits, set
    // here so that a padding bit taken for a coil would show.
    let request = rtu(&[0x11, 0x01, 0x00, 0x13, 0x00, 0x0A]);
    let answer = rtu(&[0x11, 0x01, 0x02, 0xCD, 0xFD]);
    let holding = rtu(&[0x11, 0x03, 0x00, 0x6B, 0x00, 0x02]);
    let registers = rtu(&[0x11, 0x03, 0x04, 0x02, 0x2B, 0x00, 0x64]);
    let other_slave = rtu(&[0x12, 0x01, 0x00, 0x13, 0x00, 0x0A]);
    let lines = [
        &request,
        &answer,
        &answer,
        &holding,
        &registers,
        &other_slave,
        &answer,
    ]
    .map(|frame| format!("{frame}\n"))
    .concat();
    let run = decode(&["--json"], lines.as_bytes());
    let json = json_lines(&run.stdout);
    let coils = [1, 0, 1, 1, 0, 0, 1, 1, 1, 0];
    assert_eq!(json[1]["count"], 10, "{}", run.stdout);
    assert_eq!(json[1]["ref"], "000020");
    assert_eq!(json[1]["values"], serde_json::json!(coils));
    assert!(json[1].get("max_count").is_none());
    // The same answer again has no request before it: only the bits sure to be values.
    assert_eq!(json[2]["max_count"], 16);
    assert_eq!(json[2]["values"].as_array().unwrap().len(), 9);
    assert_eq!(json[4]["ref"], "400108");
    assert_eq!(json[4]["values"], serde_json::json!([555, 100]));
    // A request to another slave is not what slave 17 answers.
    assert_eq!(json[6]["max_count"], 16);

    // Glued on one line, as a log may write a request and its answer.
    let glued = format!("{request}{answer}").replace(' ', "");
    let run = decode(&["--json", &glued], b"");
    let json = json_lines(&run.stdout);
    assert_eq!(
        json[1]["values"],
        serde_json::json!(coils),
        "{}",
        run.stdout
    );
    // On TCP the transaction must match too.
    let mbap = |transaction: u8, pdu: &[u8]| {
        let mut frame = vec![0, transaction, 0, 0, 0, pdu.len() as u8 + 1, 0x11];
        frame.extend_from_slice(pdu);
        hex::encode_upper(frame)
    };
    let request = mbap(1, &[0x01, 0x00, 0x13, 0x00, 0x0A]);
    let lines = [
        request.clone(),
        mbap(2, &[0x01, 0x02, 0xCD, 0xFD]),
        request,
        mbap(1, &[0x01, 0x02, 0xCD, 0xFD]),
    ]
    .map(|frame| format!("{frame}\n"))
    .concat();
    let run = decode(&["--json", "--mode", "tcp"], lines.as_bytes());
    let json = json_lines(&run.stdout);
    assert_eq!(json[1]["max_count"], 16, "{}", run.stdout);
    assert_eq!(
        json[3]["values"],
        serde_json::json!(coils),
        "{}",
        run.stdout
    );
}

#[test]
fn json_gives_register_values_as_the_type_asked_beside_the_registers() {
    let answer = rtu(&[0x01, 0x03, 0x04, 0x40, 0x49, 0x0F, 0xDB]);
    let run = decode(&["--json", "-t", "f32", &answer], b"");
    let json = &json_lines(&run.stdout)[0];
    assert_eq!(json["values"], serde_json::json!([16457, 4059]));
    assert_eq!(json["value_type"], "f32");
    assert_eq!(json["typed_values"].to_string(), "[3.1415927]");
    let run = decode(
        &["--json", "-t", "i16", &rtu(&[0x01, 0x03, 0x02, 0xFF, 0xFF])],
        b"",
    );
    assert_eq!(
        json_lines(&run.stdout)[0]["typed_values"],
        serde_json::json!([-1])
    );
    let run = decode(&["--json", "--order", "CDAB", "-t", "u32", &answer], b"");
    assert_eq!(
        json_lines(&run.stdout)[0]["typed_values"],
        serde_json::json!([0x0FDB_4049_u32])
    );
    // Without a type, the registers alone.
    let run = decode(&["--json", &answer], b"");
    assert!(json_lines(&run.stdout)[0].get("typed_values").is_none());
}

#[test]
fn device_strings_are_escaped_never_raw() {
    // Report server id whose text holds ESC [2J (clear screen) and a newline.
    let frame = rtu(&[0x11, 0x11, 0x07, b'P', b'L', b'C', 0x1B, b'[', b'2', b'\n']);
    for format in ["table", "json", "csv"] {
        let run = decode(&["--direction", "response", "-o", format, &frame], b"");
        assert_eq!(run.code, 0, "{format}: {}", run.stderr);
        assert!(
            !run.stdout.contains('\u{1b}'),
            "{format}: raw escape in {:?}",
            run.stdout
        );
        let shown = match format {
            "json" => json_lines(&run.stdout)[0]["text"]
                .as_str()
                .unwrap_or_default()
                .to_string(),
            _ => run.stdout.clone(),
        };
        assert!(
            format == "csv" || shown.contains(r"PLC\x1B[2\n"),
            "{format}: {shown}"
        );
    }
    // Device identification objects likewise.
    let frame = rtu(&[
        0x11, 0x2B, 0x0E, 0x01, 0x01, 0x00, 0x00, 0x01, 0x00, 0x03, b'A', 0x07, b'B',
    ]);
    let run = decode(&["--json", "--direction", "response", &frame], b"");
    let json = &json_lines(&run.stdout)[0];
    assert_eq!(json["objects"][0]["name"], "VendorName");
    assert_eq!(json["objects"][0]["value"], "A\\x07B");
}

/// `mbtool decode ARGS` fed `line` `times` over, or until it stops reading, and the thread
/// that feeds it.
fn fed_decode(
    args: &[&str],
    line: &'static [u8],
    times: usize,
) -> (std::process::Child, std::thread::JoinHandle<()>) {
    let mut child = Process::new(assert_cmd::cargo::cargo_bin("mbtool"))
        .arg("decode")
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdin = child.stdin.take().unwrap();
    let feeder = std::thread::spawn(move || {
        for _ in 0..times {
            if stdin.write_all(line).is_err() {
                break;
            }
        }
    });
    (child, feeder)
}

mod logs;
