//! `mbtool encode` and the rule that a bad command line is refused before anything happens.
//! Expected CRCs were computed with an independent CRC-16/MODBUS (bit by bit, poly 0xA001).

use crate::support::mbtool;

/// The frames `mbtool encode ARGS` prints, one per line.
fn encode(args: &str) -> Vec<String> {
    let output = mbtool()
        .arg("encode")
        .args(args.split_whitespace())
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "encode {args}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    String::from_utf8_lossy(&output.stdout)
        .lines()
        .map(str::to_string)
        .collect()
}

/// Runs a command line that must be refused: exit 2, nothing on stdout, one `mbtool:` line
/// that contains `says`.
fn refused(args: &str, says: &str) {
    let output = mbtool().args(args.split_whitespace()).output().unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{args}: {stderr}");
    assert!(
        output.stdout.is_empty(),
        "{args} printed {:?}",
        output.stdout
    );
    assert_eq!(stderr.lines().count(), 1, "{args}: {stderr}");
    assert!(stderr.starts_with("mbtool: "), "{args}: {stderr}");
    assert!(stderr.contains(says), "{args}: {stderr:?} lacks {says:?}");
}

#[test]
fn a_reference_of_another_table_is_refused_naming_the_right_command() {
    refused("read-coils 17 400108", "read-holding");
    refused("encode read-coils 17 400108", "read-holding");
    refused("encode read-holding 17 000020", "read-coils");
    refused("encode read-inputs 17 300009", "read-input-registers");
    refused("encode read-holding 17 100001", "read-inputs");
}

#[test]
fn pdu_addresses_take_every_number_as_a_protocol_address() {
    assert_eq!(
        encode("--pdu-addresses read-coils 17 40108"),
        ["11 01 9C AC 00 01 11 2B"]
    );
    assert_eq!(
        encode("read-holding 17 0x6B 3"),
        ["11 03 00 6B 00 03 76 87"]
    );
    assert_eq!(encode("read-holding 17 107 3"), ["11 03 00 6B 00 03 76 87"]);
    assert_eq!(
        encode("read-holding 17 40108 3"),
        ["11 03 00 6B 00 03 76 87"]
    );
}

#[test]
fn slaves_out_of_range_are_refused() {
    refused("encode read-holding 0 400108", "broadcast");
    refused("encode read-holding 248 400108", "reserved");
    refused("encode read-holding 300 400108", "out of range");
    refused("encode read-holding x 400108", "not a number");
    // Broadcast writes are fine, and over TCP every unit id is.
    assert_eq!(
        encode("write-register 0 400002 3"),
        ["00 06 00 01 00 03 99 DA"]
    );
    assert_eq!(
        encode("--mode tcp read-holding 255 400108 3"),
        ["00 01 00 00 00 06 FF 03 00 6B 00 03"]
    );
}

#[test]
fn counts_past_the_protocol_limit_are_split() {
    let frames = encode("read-holding 17 400001 300");
    assert_eq!(frames.len(), 3);
    assert!(frames[0].starts_with("11 03 00 00 00 7D"), "{frames:?}");
    assert!(frames[1].starts_with("11 03 00 7D 00 7D"), "{frames:?}");
    assert!(frames[2].starts_with("11 03 00 FA 00 32"), "{frames:?}");
    let frames = encode("--max-per-request 10 read-coils 17 1 25");
    let quantities: Vec<&str> = frames.iter().map(|f| &f[15..17]).collect();
    assert_eq!(quantities, ["0A", "0A", "05"]);
    // A 32-bit value is never cut in two: 7 per request becomes 6 registers.
    let frames = encode("--max-per-request 7 --type f32 read-holding 17 400001 4");
    assert_eq!(frames.len(), 2);
    assert!(frames[0].starts_with("11 03 00 00 00 06"), "{frames:?}");
}

#[test]
fn bad_counts_and_ranges_are_refused() {
    refused(
        "encode read-holding 17 465536 2",
        "goes past the end of the table, which holds 65536",
    );
    refused("encode read-holding 17 400001 0", "COUNT");
    refused(
        "encode read-holding 17 400010-400001",
        "ends before it starts",
    );
    refused("encode read-holding 17 400001-400003 3", "not both");
    refused("encode write 17 300001 5", "read-only");
    refused(
        "encode write-registers 17 400001-400003 1 2",
        "holds 3 addresses but 2 values",
    );
}

#[test]
fn ranges_and_read_by_reference() {
    assert_eq!(
        encode("read-holding 17 400108-400110"),
        ["11 03 00 6B 00 03 76 87"]
    );
    assert_eq!(encode("read 17 400108 3"), ["11 03 00 6B 00 03 76 87"]);
    assert_eq!(encode("read 17 000020 37"), ["11 01 00 13 00 25 0E 84"]);
    refused("encode read 17 107", "not a Modicon reference");
}

#[test]
fn typed_writes_and_byte_orders() {
    assert_eq!(
        encode("write 17 400001 3.14 --type f32"),
        ["11 10 00 00 00 02 04 40 48 F5 C3 35 B8"]
    );
    let swapped = encode("write 17 400001 3.14 --type f32 --order CDAB");
    assert!(swapped[0].contains("04 F5 C3 40 48"), "{swapped:?}");
    assert_eq!(
        encode("write-register 17 400001 -1"),
        ["11 06 00 00 FF FF 8A EA"]
    );
    refused(
        "encode write-register 17 400001 3.14 --type f32",
        "use write-registers",
    );
    refused(
        "encode write-register 17 400001 70000",
        "does not fit in u16: give 0 to 65535",
    );
    // --function forces single writes, one request per register.
    assert_eq!(encode("write 17 400001 1 2 --function 6").len(), 2);
    refused("encode write 17 400001 1 --function 5", "--function 6");
}

#[test]
fn coils_as_words_or_a_bit_string() {
    let bits = encode("write-coils 17 000020 10110");
    let words = encode("write-coils 17 000020 on off 1 true 0");
    assert_eq!(bits, words);
    assert!(bits[0].starts_with("11 0F 00 13 00 05 01 0D"), "{bits:?}");
    assert_eq!(
        encode("write-coil 17 000173 on"),
        ["11 05 00 AC FF 00 4E 8B"]
    );
    refused("encode write-coil 17 000173 maybe", "not a coil value");
}

#[test]
fn tcp_and_ascii_framing() {
    assert_eq!(
        encode("--mode tcp read-holding 17 400108 3"),
        ["00 01 00 00 00 06 11 03 00 6B 00 03"]
    );
    assert_eq!(
        encode("--port tcp://127.0.0.1:5020 read-holding 17 400108 3"),
        ["00 01 00 00 00 06 11 03 00 6B 00 03"]
    );
    // Options may stand after the command too.
    assert_eq!(
        encode("read-holding 17 400108 3 --mode ascii"),
        [":1103006B00037E"]
    );
    assert_eq!(
        encode("write-coil 17 000173 on --mode ascii"),
        [":110500ACFF003F"]
    );
}

#[test]
fn json_output_of_encode() {
    let lines = encode("--json read-holding 17 400108 3");
    let json: serde_json::Value = serde_json::from_str(&lines[0]).unwrap();
    assert_eq!(json["frame"], "11 03 00 6B 00 03 76 87");
    assert_eq!(json["mode"], "rtu");
    assert_eq!(json["slave"], 17);
}

#[test]
fn raw_sends_the_pdu_as_given_even_when_malformed() {
    assert_eq!(encode("raw 17 03 00 6B 00 03"), ["11 03 00 6B 00 03 76 87"]);
    // Quantity 0: kept, so that a device's answer to it can be tested.
    assert_eq!(encode("raw 17 0300000000").len(), 1);
    refused("encode raw 17 83 02", "not a request");
    refused("encode raw 17 0", "odd number of hex digits");
}

#[test]
fn usage_errors_are_one_line() {
    refused(
        "encode read-holding",
        "encode read-holding needs SLAVE and ADDRESS",
    );
    refused("bogus", "unknown command 'bogus'");
    refused(
        "decode --output nope",
        "--output nope: give a format: table, json, values or csv",
    );
    refused(
        "encode write 17 400001 1 --function 7",
        "possible values: 5, 6, 15, 16",
    );
}

#[test]
fn help_and_version_succeed() {
    mbtool().arg("--help").assert().success();
    mbtool().args(["read-holding", "--help"]).assert().success();
    mbtool().arg("--version").assert().success();
}
