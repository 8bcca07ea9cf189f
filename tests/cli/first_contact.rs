//! What a new user meets first: `mbtool` alone, usage errors, messages that say what to do,
//! values refused for their type, the output of a terminal.

use crate::support::{free_port, mbtool, serve, wait_for_listener};

/// Runs mbtool; (exit status, stdout, stderr).
fn run(args: &str) -> (i32, String, String) {
    let output = mbtool()
        .args(args.split_whitespace())
        .output()
        .expect("mbtool runs");
    (
        output.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&output.stdout).into_owned(),
        String::from_utf8_lossy(&output.stderr).into_owned(),
    )
}

/// A usage error: exit status 2, nothing on stdout, and exactly `message` as the one line.
fn refused_with(args: &str, message: &str) {
    let (code, stdout, stderr) = run(args);
    assert_eq!(code, 2, "{args}: {stderr}");
    assert_eq!(stdout, "", "{args}");
    assert_eq!(stderr, format!("mbtool: {message}\n"), "{args}");
}

#[test]
fn mbtool_alone_prints_a_short_usage_and_the_commands() {
    let (code, stdout, stderr) = run("");
    assert_eq!(code, 2);
    assert_eq!(stdout, "");
    assert!(stderr.starts_with("Usage: mbtool [OPTIONS] <COMMAND> [ARGS]\n\nCommands:\n"));
    assert!(stderr.contains("\n  read-holding "), "{stderr}");
    assert!(stderr.contains("mbtool --port sim read-holding 17 400108 3"));
    // Neither the hidden command nor the aliases are offered.
    for hidden in ["generate", "read-holding-registers", "read-input-regs"] {
        assert!(!stderr.contains(hidden), "{hidden} listed:\n{stderr}");
    }
    assert!(
        stderr.lines().all(|line| line.chars().count() <= 80),
        "{stderr}"
    );
}

/// A usage error points to the help of the command it is about, and never to a help
/// that does not exist; `mbtool encode` alone lists the requests it encodes.
#[test]
fn a_usage_error_points_to_a_help_that_exists() {
    refused_with(
        "help nosuch",
        "unknown command 'nosuch' (see 'mbtool --help')",
    );
    refused_with(
        "encode encode read-holding 17 1",
        "unknown command 'encode' (see 'mbtool encode --help')",
    );
    refused_with(
        "-p sim -p sim read-holding 17 1",
        "the argument '--port <PORT>' cannot be used multiple times (see 'mbtool --help')",
    );
    refused_with(
        "--port scan read-holding 17 1 --nope",
        "unexpected argument '--nope' found; to pass '--nope' as a value, use '-- --nope' \
         (see 'mbtool read-holding --help')",
    );
    let (code, stdout, stderr) = run("encode");
    assert_eq!((code, stdout.as_str()), (2, ""));
    assert!(
        stderr.starts_with(
            "Usage: mbtool encode [OPTIONS] <COMMAND> [ARGS]\n\nCommands:\n  read-coils "
        ),
        "{stderr}"
    );
    assert!(!stderr.contains("\n  scan "), "{stderr}");
}

#[test]
fn a_word_or_a_variable_that_is_not_utf8_is_told_not_panicked_on() {
    use std::ffi::OsStr;
    use std::os::unix::ffi::OsStrExt;
    let bad = OsStr::from_bytes(b"caf\xe9");
    for args in [
        vec![OsStr::new("decode"), bad],
        vec![
            OsStr::new("--port"),
            bad,
            OsStr::new("read-holding"),
            OsStr::new("17"),
            OsStr::new("0"),
        ],
        vec![
            OsStr::new("sniff"),
            OsStr::new("--slave"),
            bad,
            OsStr::new("--input"),
            OsStr::new("x"),
        ],
        vec![bad],
    ] {
        let output = mbtool().args(&args).output().unwrap();
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{args:?}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
        assert!(stderr.starts_with("mbtool: "), "{stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
    let output = mbtool()
        .args(["decode", "--", "01"])
        .arg(bad)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.starts_with("mbtool: argument 4 ('caf\u{FFFD}') is not UTF-8 text"),
        "{stderr}"
    );

    let output = mbtool()
        .env("MBTOOL_PORT", bad)
        .args(["read-holding", "17", "0"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.starts_with("mbtool: the environment variable MBTOOL_PORT is not UTF-8 text"),
        "{stderr}"
    );
}

#[test]
fn a_missing_argument_is_named() {
    refused_with(
        "read-holding 17",
        "read-holding needs ADDRESS (see 'mbtool read-holding --help')",
    );
    refused_with("raw 17", "raw needs PDU_HEX (see 'mbtool raw --help')");
    refused_with(
        "encode raw 17",
        "encode raw needs PDU_HEX (see 'mbtool encode raw --help')",
    );
    let (code, _, stderr) = run("--port sim read 17 400108 --count 3");
    assert_eq!(code, 2);
    assert!(
        stderr.starts_with("mbtool: --count N stops a --poll after N reads"),
        "{stderr}"
    );
}

#[test]
fn each_command_shows_and_takes_only_its_options() {
    let help = |command: &str| run(&format!("{command} --help")).1;
    let options = |text: &str| -> Vec<String> {
        text.lines()
            .filter_map(|line| {
                line.trim_start()
                    .split([' ', ','])
                    .find(|w| w.starts_with("--"))
            })
            .map(str::to_string)
            .collect()
    };
    let decode = options(&help("decode"));
    for taken in [
        "--mode",
        "--output",
        "--json",
        "--type",
        "--order",
        "--direction",
    ] {
        assert!(
            decode.iter().any(|o| o == taken),
            "decode lacks {taken}: {decode:?}"
        );
    }
    for untaken in [
        "--port",
        "--baud",
        "--timeout",
        "--poll",
        "--verbose",
        "--max-per-request",
    ] {
        assert!(
            !decode.iter().any(|o| o == untaken),
            "decode shows {untaken}"
        );
    }
    let coils = options(&help("read-coils"));
    assert!(coils.iter().any(|o| o == "--poll") && coils.iter().any(|o| o == "--baud"));
    assert!(
        !coils.iter().any(|o| o == "--type" || o == "--order"),
        "{coils:?}"
    );
    let encode = options(&help("encode write-register"));
    assert!(encode.iter().any(|o| o == "--type") && encode.iter().any(|o| o == "--mode"));
    assert!(
        !encode.iter().any(|o| o == "--timeout" || o == "--baud"),
        "{encode:?}"
    );

    // Typed before or after the command name, an option the command does not take is refused.
    refused_with(
        "decode --poll 1s 11 03 00 6B 00 03 76 87",
        "decode does not take --poll (see 'mbtool decode --help' for the options it takes)",
    );
    refused_with(
        "-b 9600 decode 11 03 00 6B 00 03 76 87",
        "decode does not take --baud (see 'mbtool decode --help' for the options it takes)",
    );
    refused_with(
        "--port sim read-coils 17 000020 3 --type f32",
        "read-coils does not take --type (see 'mbtool read-coils --help' for the options it takes)",
    );
    refused_with(
        "--port sim write-register 17 400002 3 --poll 1s",
        "write-register does not take --poll (see 'mbtool write-register --help' for the options it takes)",
    );
    refused_with(
        "encode --timeout 2s read-holding 17 400108 3",
        "encode read-holding does not take --timeout (see 'mbtool encode read-holding --help' for the options it takes)",
    );
    // A value from the environment, exported for a whole shell session, is never refused,
    // nor a list of baud rates set there for scans.
    let output = mbtool()
        .env("MBTOOL_PORT", "sim")
        .env("MBTOOL_BAUD", "9600,19200")
        .args(["decode", "11 03 00 6B 00 03 76 87"])
        .output()
        .expect("mbtool runs");
    assert!(output.status.success(), "{output:?}");
    let (code, stdout, _) = run("encode --port tcp://plc1 read-holding 17 400108 3");
    assert_eq!(
        (code, stdout.trim()),
        (0, "00 01 00 00 00 06 11 03 00 6B 00 03")
    );
}

/// What each command's help says of its arguments fits that command.
#[test]
fn each_command_describes_its_own_arguments() {
    let arguments = |command: &str| -> String {
        let help = run(&format!("{command} --help")).1;
        let start = help.find("Arguments:").unwrap_or(0);
        let end = help.find("Options:").unwrap_or(help.len());
        help[start..end].to_string()
    };
    for (command, says, never) in [
        ("read-coils", "000020", "400108"),
        ("read-inputs", "100197", "400108"),
        ("read-input-registers", "300009", "400108"),
        ("read", "[REFERENCE]", "0x6B"),
        ("write-registers", "--type", "coil"),
        ("write-coils", "10110", "--type"),
        ("write", "[REFERENCE]", "0x6B"),
        ("encode read-coils", "000020", "400108"),
    ] {
        let text = arguments(command);
        assert!(text.contains(says), "{command}: {text}");
        assert!(!text.contains(never), "{command}: {text}");
    }
}

#[test]
fn a_mistyped_command_suggests_the_nearest_one() {
    refused_with(
        "read-holdin 17 1",
        "unknown command 'read-holdin': did you mean 'read-holding'? (see 'mbtool --help')",
    );
    refused_with(
        "frobnicate",
        "unknown command 'frobnicate' (see 'mbtool --help')",
    );
}

#[test]
fn a_reference_of_the_wrong_table_names_the_command_that_fits() {
    refused_with(
        "--port sim write-coil 17 400001 on",
        "400001 is a holding register reference: use write-register",
    );
    refused_with(
        "--port sim write-registers 17 000001 1 2",
        "000001 is a coil reference: use write-coils, or give --pdu-addresses to mean \
         protocol address 000001",
    );
    refused_with(
        "--port sim write-register 17 300009 5",
        "300009 is an input register reference, and that table is read-only: write to coils \
         (0xxxxx) or holding registers (4xxxxx)",
    );
    refused_with(
        "--port sim read-holding 17 40000",
        "40000 is not a valid reference: references count from 1 (400001 is the first), or \
         give --pdu-addresses to mean protocol address 40000",
    );
    refused_with(
        "--port sim read-holding 17 65535 2",
        "65535 with 2 items goes past the end of the table, which holds 65536",
    );
}

#[test]
fn a_value_outside_its_type_is_refused_and_nothing_is_written() {
    refused_with(
        "--port sim write 17 400001 1e39 --type f32",
        "1e39 does not fit in f32: give at most ±3.4028235e38 in size (or --type f64)",
    );
    refused_with(
        "--port sim write-register 17 400200 40000 --type i16",
        "40000 does not fit in i16: give -32768 to 32767 (or an unsigned --type for 0 to 65535)",
    );
    refused_with(
        "--port sim write-registers 17 400001 3.7",
        "'3.7' is not a whole number, which u16 takes: give --type f32 or f64 for it",
    );
}

#[test]
fn one_f32_written_is_one_value() {
    let (code, stdout, _) = run("--port sim write 17 400001 1.5 --type f32");
    assert_eq!(code, 0);
    assert_eq!(
        stdout,
        "wrote 1 value from 400001 (slave 17, function 16 Write Multiple Registers)\n"
    );
}

#[test]
fn options_out_of_range_say_the_range_and_whose_value_it_was() {
    refused_with(
        "--port sim -b 0 read-holding 17 1",
        "invalid value '0' for '--baud <BAUD>': give a whole number from 50 to 12000000 (see \
         'mbtool read-holding --help')",
    );
    refused_with(
        "--port sim read-holding 17 1 --timeout 0",
        "invalid value '0' for '--timeout <TIMEOUT>': give a timeout above zero, as 500ms or \
         1s (see 'mbtool read-holding --help')",
    );
    refused_with(
        "--port sim --retries -1 read-holding 17 1",
        "invalid value '-1' for '--retries <N>': give a whole number from 0 to 100 (see \
         'mbtool read-holding --help')",
    );
    let output = mbtool()
        .env("MBTOOL_BAUD", "fast")
        .args(["--port", "sim", "read-holding", "17", "1"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&output.stderr),
        "mbtool: invalid value 'fast' in MBTOOL_BAUD (which sets --baud): give a whole number \
         from 50 to 12000000 (see 'mbtool read-holding --help')\n"
    );
    // Typed over, before the command or after it, a bad variable is refused all the same,
    // and named.
    for line in [
        "--port sim read-holding 17 1 --baud 9600",
        "--baud 9600 --port sim read-holding 17 1",
        "-b9600 --port sim read-holding 17 1",
    ] {
        let output = mbtool()
            .env("MBTOOL_BAUD", "fast")
            .args(line.split_whitespace())
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(2), "{line}");
        assert!(
            String::from_utf8_lossy(&output.stderr)
                .starts_with("mbtool: invalid value 'fast' in MBTOOL_BAUD (which sets --baud)"),
            "{line}: {output:?}"
        );
    }
}

#[test]
fn a_timeout_says_what_was_tried_and_exits_3_for_raw_too() {
    let (code, _, stderr) = run("--port sim --timeout 50ms read-holding 5 1");
    assert_eq!(code, 3);
    assert_eq!(
        stderr,
        "mbtool: no answer from slave 5 within 50.00 ms from the built-in slave (sim): it \
         answers as slave 17 only\n"
    );
    let (code, _, stderr) = run("--port sim --timeout 50ms raw 5 03 00 6B 00 03");
    assert_eq!(code, 3, "{stderr}");
}

#[test]
fn the_sim_answers_a_malformed_pdu_with_its_exception() {
    let (code, stdout, _) = run("--port sim --json raw 17 03 00");
    assert_eq!(code, 13, "{stdout}");
    assert!(stdout.contains(r#""exception":3"#), "{stdout}");
}

#[test]
fn a_bare_address_and_port_is_modbus_tcp() {
    let port = free_port();
    let _server = serve(&["--port", &format!("tcp://127.0.0.1:{port}")]);
    assert!(wait_for_listener(port, std::time::Duration::from_secs(10)));
    let (code, stdout, stderr) = run(&format!(
        "--port 127.0.0.1:{port} read-holding 17 400108 -o values"
    ));
    assert_eq!((code, stdout.as_str()), (0, "555\n"), "{stderr}");
}

#[test]
fn a_serial_timeout_names_the_line_settings_and_the_usual_causes() {
    let Some(pair) = crate::support::PtyPair::new() else {
        return;
    };
    let (code, _, stderr) = run(&format!(
        "--port {} -b 9600 --parity none --timeout 50ms read-holding 7 1",
        pair.a.display()
    ));
    assert_eq!(code, 3);
    assert_eq!(
        stderr,
        format!(
            "mbtool: no answer from slave 7 within 50.00 ms on {} (RTU, 9600 baud, no parity, \
             8 data bits, 2 stop bits): check the slave id, and --baud, --parity and --mode \
             against the device's settings, and the wiring (A and B swapped, no common \
             ground)\n",
            pair.a.display()
        )
    );
}

#[test]
fn ascii_is_one_string_floats_are_short_and_bits_in_csv_have_no_hex_column() {
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("data.txt");
    std::fs::write(
        &data,
        "400020 = \"PUMP 1\" ascii\n400023 = 0\n400030 = 0 0x3FC2\n000020 = on off\n",
    )
    .unwrap();
    let port = free_port();
    let _server = serve(&[
        "--port",
        &format!("tcp://127.0.0.1:{port}"),
        "--data",
        data.to_str().unwrap(),
    ]);
    assert!(wait_for_listener(port, std::time::Duration::from_secs(10)));
    let at = format!("--port tcp://127.0.0.1:{port}");
    let (code, stdout, stderr) = run(&format!(
        "{at} read-holding 17 400020 4 --type ascii -o values"
    ));
    assert_eq!((code, stdout.as_str()), (0, "PUMP 1\n"), "{stderr}");
    let (_, stdout, _) = run(&format!("{at} read-coils 17 000020 2 -o csv"));
    assert_eq!(stdout, "ref,address,value\n000020,19,1\n000021,20,0\n");
    // A denormal f32 in its shortest form, not forty zeros.
    let (_, stdout, _) = run(&format!("{at} read-holding 17 400030 --type f32 -o values"));
    assert_eq!(stdout, "2.2872e-41\n");
}

/// The lines of `command` as an 80-column terminal shows them (tmux, capture-pane).
fn in_a_terminal(command: &str) -> Option<Vec<String>> {
    let terminal = crate::support::Terminal::run(command, 80, 60)?;
    let _ = terminal.wait_for(std::time::Duration::from_secs(20), |_| terminal.done());
    Some(terminal.screen())
}

#[test]
fn tables_fit_an_80_column_terminal() {
    let long_frame = "11 10 00 01 00 0A 14 00 01 00 02 00 03 00 04 00 05 00 06 00 07 00 08 00 09 \
                      00 0A 00 00";
    for command in [
        format!("decode {long_frame}"),
        "--port sim raw 17 2B0E0100".to_string(),
        "--port sim read-holding 17 400108 3 --type f64".to_string(),
    ] {
        let Some(lines) = in_a_terminal(&command) else {
            return;
        };
        assert!(
            lines.iter().any(|l| l.contains('│')),
            "{command}: no table in {lines:#?}"
        );
        for line in &lines {
            assert!(
                line.chars().count() <= 80,
                "{command}: {} columns: {line}",
                line.chars().count()
            );
        }
    }
}

#[test]
fn help_names_the_environment_variables_without_empty_values() {
    let output = mbtool().args(["read-holding", "--help"]).output().unwrap();
    let help = String::from_utf8_lossy(&output.stdout);
    assert!(help.contains("[env: MBTOOL_PORT]"), "{help}");
    assert!(!help.contains("MBTOOL_PORT=]"), "{help}");
}

/// A bare number above 60 for a duration is refused with the spelling probably meant, from
/// the command line and from the environment, before anything is sent.
#[test]
fn a_bare_timeout_of_500_is_not_taken_for_eight_minutes() {
    let run = |args: &[&str], env: Option<&str>| {
        let mut command = crate::support::mbtool();
        if let Some(value) = env {
            command.env("MBTOOL_TIMEOUT", value);
        }
        let output = command.args(args).output().unwrap();
        (
            output.status.code(),
            String::from_utf8_lossy(&output.stderr).into_owned(),
        )
    };
    for (args, env) in [
        (
            vec![
                "--port",
                "sim",
                "--timeout",
                "500",
                "read-holding",
                "17",
                "1",
            ],
            None,
        ),
        (
            vec!["--port", "sim", "read-holding", "17", "1"],
            Some("500"),
        ),
        (
            vec!["--port", "sim", "--poll", "250", "read-holding", "17", "1"],
            None,
        ),
    ] {
        let (code, stderr) = run(&args, env);
        assert_eq!(code, Some(2), "{args:?}: {stderr}");
        assert!(
            stderr.contains("give 500ms") || stderr.contains("give 250ms"),
            "{stderr}"
        );
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
    }
    // Up to 60 a bare number is seconds, as before.
    let (code, stderr) = run(
        &["--port", "sim", "--timeout", "2", "read-holding", "17", "1"],
        None,
    );
    assert_eq!(code, Some(0), "{stderr}");
}

/// mbpoll's and modpoll's options, typed out of habit, get mbtool's spelling, and a whole
/// mbpoll line the mbtool command that does the same; never clap's `-- -c`.
#[test]
fn mbpoll_habits_get_mbtools_spelling() {
    for (line, says) in [
        (
            "--port sim -a 17 -r 1 -c 2",
            "mbtool: -a is mbpoll's slave address: here it is the first argument after the command, read-holding 17 ...; the line given is mbtool read-holding 17 400001 2",
        ),
        (
            "--port sim read 17 400001 -c 2",
            "mbtool: -c is mbpoll's count: here it is the third argument, read 17 400001 2",
        ),
        (
            "--port sim -t 3 -a 5 -r 10 -c 4",
            "the line given is mbtool read-input-registers 5 300010 4",
        ),
        ("--port sim read-holding 17 1 -l 1000", "-l is mbpoll's poll rate: here it is --poll 1s"),
        ("--port sim read-holding 17 1 -P none", "-P is mbpoll's parity: here it is --parity"),
        ("--port /dev/ttyS0 read-holding 17 1 -R", "-R is mbpoll's RS-485 mode: here it is --rts-toggle"),
    ] {
        let output = crate::support::mbtool()
            .args(line.split(' '))
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{line}: {stderr}");
        assert!(stderr.contains(says), "{line}: {stderr}");
        assert!(!stderr.contains("-- -"), "{line}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
    }
}

/// Small things a newcomer meets: a port that is not there names the ones that are, and
/// `dump` without a range says what one looks like.
#[test]
fn a_missing_port_and_a_missing_range_say_what_is_there_and_what_to_give() {
    let output = crate::support::mbtool()
        .args(["--port", "/dev/ttyUSB-none", "read-holding", "17", "1"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.starts_with("mbtool: cannot open /dev/ttyUSB-none: No such file or directory (")
            && (stderr.contains("the serial ports here are /dev/")
                || stderr.contains("no serial port is here")),
        "{stderr}"
    );
    let output = crate::support::mbtool()
        .args(["--port", "sim", "dump", "17"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("dump needs RANGE, the addresses to save: 400001-400100"),
        "{stderr}"
    );
}

/// With `--address-base 1` a bare number is a register number counted from 1, in what is
/// typed and in the address column shown; references are unchanged; the help of every
/// command that takes an address says which base its numbers are in.
#[test]
fn address_base_one_counts_register_numbers_from_one() {
    let csv = |args: &str| {
        let (code, stdout, stderr) = run(args);
        assert_eq!(code, 0, "{args}: {stderr}");
        stdout
    };
    assert_eq!(
        csv("--port sim --address-base 1 read-holding 17 108 3 -o csv"),
        "ref,address,hex,value\n400108,108,022B,555\n400109,109,0000,0\n400110,110,0064,100\n"
    );
    assert_eq!(
        csv("--port sim --address-base 1 read-holding 17 400108-400110 -o csv"),
        csv("--port sim --address-base 1 read-holding 17 108-110 -o csv"),
    );
    assert_eq!(
        csv("--port sim --address-base 1 read-coils 17 20 2 -o csv"),
        "ref,address,value\n000020,20,1\n000021,21,0\n"
    );
    assert_eq!(
        csv("--port sim --address-base 1 read-holding 17 108.05 -o csv"),
        "ref,address,value\n400108.05,108,1\n"
    );
    assert_eq!(
        csv("--port sim --address-base 1 write-register 17 2 7 -o json"),
        "{\"slave\":17,\"function\":6,\"address\":2,\"ref\":\"400002\",\"count\":1}\n"
    );
    // The environment says it as well, and the command line wins.
    let from_env = |args: &str| {
        let output = mbtool()
            .env("MBTOOL_ADDRESS_BASE", "1")
            .args(args.split_whitespace())
            .output()
            .expect("mbtool runs");
        String::from_utf8_lossy(&output.stdout).into_owned()
    };
    assert_eq!(
        from_env("--port sim read-holding 17 108 -o csv"),
        "ref,address,hex,value\n400108,108,022B,555\n"
    );
    assert_eq!(
        from_env("--port sim --address-base 0 read-holding 17 107 -o csv"),
        "ref,address,hex,value\n400108,107,022B,555\n"
    );
    assert_eq!(
        from_env("--address-base 1 encode read-holding 17 108 3"),
        "11 03 00 6B 00 03 76 87\n"
    );

    refused_with(
        "--port sim --address-base 1 read-holding 17 0",
        "0 is no register number: with --address-base 1 they count from 1 (the first register \
         is 1); give --address-base 0 to mean protocol address 0",
    );
    refused_with(
        "--port sim --address-base 1 read-holding 17 65537",
        "register number 65537 is out of range 1-65536",
    );
    refused_with(
        "--port sim --address-base 1 read-holding 17 19033",
        "19033 is a discrete input reference: use read-inputs, or give --pdu-addresses to \
         mean register number 19033",
    );
    refused_with(
        "--port sim --address-base 2 read-holding 17 1",
        "invalid value '2' for '--address-base <BASE>'; possible values: 0, 1 (see 'mbtool \
         read-holding --help')",
    );

    for command in [
        "read-coils",
        "read-inputs",
        "read-holding",
        "read-input-registers",
        "write-coil",
        "write-coils",
        "write-register",
        "write-registers",
    ] {
        for line in [command.to_string(), format!("encode {command}")] {
            let help = csv(&format!("{line} --help"));
            let address = help
                .split("<ADDRESS>")
                .nth(2)
                .unwrap_or_default()
                .split("\n\n")
                .next()
                .unwrap_or_default()
                .split_whitespace()
                .collect::<Vec<_>>()
                .join(" ");
            assert!(
                address.contains("counted from 0, or from 1 with --address-base 1"),
                "{line}: {address}"
            );
            assert!(help.contains("--address-base <BASE>"), "{line}");
        }
    }
    for command in ["read", "write", "watch"] {
        let help = csv(&format!("{command} --help"));
        assert!(help.contains("1-based"), "{command}");
    }
}
