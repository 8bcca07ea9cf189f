//! The rest of the protocol: file records (20, 21), mask write (22), read/write (23) and
//! the FIFO queue (24) as commands, in `serve`'s data model, in `decode`, `encode`,
//! `sniff`, `gateway`, `dump` and `restore`; and Modbus over UDP (`udp.rs`). Their peers
//! are in `peers.rs`.

mod peers;
mod udp;

use std::time::{Duration, Instant};

use crate::support::{mbtool, rtu, serve, serve_tcp, spaced_hex, values_of, Stopped};

/// The worked examples of the Modbus application protocol specification for functions
/// 20-24: the command that sends each request (slave 17), the request's PDU, and the
/// answer's PDU.
const SPECIFICATION: &[(&str, &str, &str)] = &[
    (
        "read-file 17 4:1 2 3:9 2",
        "14 0E 06 00 04 00 01 00 02 06 00 03 00 09 00 02",
        "14 0C 05 06 0D FE 00 20 05 06 33 CD 00 40",
    ),
    (
        "write-file 17 4:7 0x06AF 0x04BE 0x100D",
        "15 0D 06 00 04 00 07 00 03 06 AF 04 BE 10 0D",
        "15 0D 06 00 04 00 07 00 03 06 AF 04 BE 10 0D",
    ),
    (
        "mask-write 17 400005 0x00F2 0x0025",
        "16 00 04 00 F2 00 25",
        "16 00 04 00 F2 00 25",
    ),
    (
        "read-write 17 400004 6 400015 0x00FF 0x00FF 0x00FF",
        "17 00 03 00 06 00 0E 00 03 06 00 FF 00 FF 00 FF",
        "17 0C 00 FE 0A CD 00 01 00 03 00 0D 00 FF",
    ),
    (
        "read-fifo 17 401247",
        "18 04 DE",
        "18 00 06 00 02 01 B8 12 84",
    ),
];

fn pdu(spaced: &str) -> Vec<u8> {
    hex::decode(spaced.replace(' ', "")).unwrap()
}

fn stdout(args: &[&str]) -> String {
    let output = mbtool().args(args).output().unwrap();
    assert!(output.status.success(), "{args:?}: {output:?}");
    String::from_utf8(output.stdout).unwrap()
}

/// `encode` builds each request of the specification byte for byte, as RTU and as TCP;
/// `decode` reads each answer with the fields the specification gives.
#[test]
fn the_specification_s_examples_are_built_and_read_byte_for_byte() {
    for (command, request, _) in SPECIFICATION {
        let body = [&[17u8][..], &pdu(request)].concat();
        let words: Vec<&str> = command.split_whitespace().collect();
        let built = stdout(&[&["encode"], &words[..]].concat());
        assert_eq!(built.trim(), spaced_hex(&rtu(&body)), "{command}");
        let tcp = stdout(&[&["encode", "--mode", "tcp"], &words[..]].concat());
        let mbap = format!("00 01 00 00 00 {:02X} {}", body.len(), spaced_hex(&body));
        assert_eq!(tcp.trim(), mbap, "{command}");
    }
    let answers: Vec<String> = SPECIFICATION
        .iter()
        .map(|(_, _, answer)| spaced_hex(&rtu(&[&[17u8][..], &pdu(answer)].concat())))
        .collect();
    let json = stdout(
        &[
            &["decode", "-o", "json", "--direction", "response"][..],
            &answers.iter().map(String::as_str).collect::<Vec<_>>(),
        ]
        .concat(),
    );
    let lines: Vec<serde_json::Value> = json
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(
        lines[0]["files"],
        serde_json::json!([{"count": 2, "values": [0x0DFE, 0x0020]}, {"count": 2, "values": [0x33CD, 0x0040]}])
    );
    assert_eq!(
        lines[1]["files"],
        serde_json::json!([{"file": 4, "record": 7, "count": 3, "values": [0x06AF, 0x04BE, 0x100D]}])
    );
    assert_eq!(
        (&lines[2]["and_mask"], &lines[2]["or_mask"]),
        (&0xF2.into(), &0x25.into())
    );
    assert_eq!(
        lines[3]["values"],
        serde_json::json!([0xFE, 0x0ACD, 1, 3, 0x0D, 0xFF])
    );
    assert_eq!(lines[4]["values"], serde_json::json!([0x01B8, 0x1284]));
    // A request and its answer side by side: the answer gets the files and records asked.
    let request = spaced_hex(&rtu(&[&[17u8][..], &pdu(SPECIFICATION[0].1)].concat()));
    let csv = stdout(&["decode", "-o", "csv", &request]);
    assert!(
        csv.ends_with(",false,file 4 record 1 x2; file 3 record 9 x2\n"),
        "{csv}"
    );
    let paired = stdout(&["decode", "-o", "json", &request, &answers[0]]);
    let answer: serde_json::Value = serde_json::from_str(paired.lines().nth(1).unwrap()).unwrap();
    assert_eq!(
        answer["files"][1],
        serde_json::json!({"file": 3, "record": 9, "count": 2, "values": [0x33CD, 0x0040]})
    );
}

/// The built-in slave holds the specification's files and FIFO queue: each command reads
/// what the specification's answers carry, in every format.
#[test]
fn the_built_in_slave_answers_as_the_specification_s_device() {
    let values = |args: &str| values_of(&["--port".into(), "sim".into()], args);
    assert_eq!(
        values("read-file 17 4:1 2 3:9 2"),
        ["3582", "32", "13261", "64"]
    );
    assert_eq!(values("read-fifo 17 401247"), ["440", "4740"]);
    assert_eq!(values("read-file 17 4:1 1 --type f32"), ["1.5653989e-30"]);
    let csv = stdout(&["--port", "sim", "read-file", "17", "4:1", "2", "-o", "csv"]);
    assert_eq!(csv, "file,record,hex,value\n4,1,0DFE,3582\n4,2,0020,32\n");
    let json = stdout(&["--port", "sim", "read-fifo", "17", "401247", "-o", "json"]);
    assert_eq!(
        json.trim(),
        r#"{"slave":17,"function":24,"address":1246,"ref":"401247","count":2,"values":[{"entry":0,"value":440},{"entry":1,"value":4740}]}"#
    );
    let table = stdout(&[
        "--port",
        "sim",
        "read-fifo",
        "17",
        "401247",
        "--type",
        "hex",
    ]);
    assert!(table.contains("01B8") && table.contains("entry"), "{table}");
    // A bit set alone, and 23's read after its write.
    let done = stdout(&["--port", "sim", "mask-write", "17", "400108.05=1"]);
    assert_eq!(
        done.trim(),
        "wrote 1 value from 400108.05 (slave 17, function 22 Mask Write Register)"
    );
    assert_eq!(
        values("read-write 17 400108 3 400109 7"),
        ["555", "7", "100"]
    );
}

/// What the specification forbids is refused in one line, before anything is sent.
#[test]
fn what_the_specification_forbids_is_refused_before_anything_is_sent() {
    for (args, message) in [
        (
            "read-file 17 0:1 2",
            "mbtool: 0:1: file 0 does not exist: files are numbered 1-65535",
        ),
        (
            "read-file 17 4:10000 1",
            "mbtool: 4:10000: record 10000 is past 9999",
        ),
        (
            "read-file 17 4:9990 11",
            "mbtool: 4:9990 with 11 records runs to record 10000, past 9999",
        ),
        ("read-file 17 4:1", "mbtool: give FILE:RECORD COUNT pairs"),
        (
            "write-file 17 4:9999 1 2",
            "mbtool: 4:9999 with 2 records runs to record 10000",
        ),
        (
            "write-file 17 65536:1 1",
            "mbtool: '65536:1' is no FILE:RECORD",
        ),
        (
            "read-write 17 400001 126 400001 1",
            "mbtool: COUNT 126 is out of range 1-125: function 23 reads at most 125 registers",
        ),
        (
            "mask-write 17 400001 0x10000 0",
            "mbtool: AND 0x10000 is out of range 0-65535",
        ),
        (
            "mask-write 17 400001 1",
            "mbtool: give the AND and OR masks",
        ),
        ("mask-write 17 300001.02=1", "mbtool: "),
        (
            "read-fifo 17 400001-400002",
            "mbtool: 400001-400002: a FIFO queue's pointer is one register",
        ),
    ] {
        // A port nobody listens on: a refusal is told before it is opened.
        let output = mbtool()
            .args(["--port", "udp://127.0.0.1:9"])
            .args(args.split_whitespace())
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(2), "{args}: {output:?}");
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(stderr.starts_with(message), "{args}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{args}: {stderr}");
    }
    // An empty text is no value: refused, not a panic at record 9999.
    for command in [
        &["write-file", "17", "4:9999"][..],
        &["read-write", "17", "400001", "1", "400001"],
    ] {
        let output = mbtool()
            .args(["--port", "sim"])
            .args(command)
            .args(["", "--type", "ascii"])
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(2), "{output:?}");
        assert!(
            String::from_utf8_lossy(&output.stderr).starts_with("mbtool: give at least one VALUE")
        );
    }
    let many: Vec<String> = (0..122).map(|i| i.to_string()).collect();
    let output = mbtool()
        .args(["--port", "sim", "read-write", "17", "400001", "1", "400001"])
        .args(&many)
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&output.stderr).contains("function 23 writes at most 121"));
}

/// A data file for `serve` with `text`, kept as long as the guard.
fn data_file(text: &str) -> tempfile::NamedTempFile {
    let mut file = tempfile::NamedTempFile::new().unwrap();
    std::io::Write::write_all(&mut file, text.as_bytes()).unwrap();
    file
}

/// `serve --data` with `text` over TCP: the guard, the connection options, and the file.
fn serve_data(text: &str, extra: &[&str]) -> (Stopped, Vec<String>, tempfile::NamedTempFile) {
    let file = data_file(text);
    let path = file.path().display().to_string();
    let (server, port, _) = serve_tcp(&[&["--data", &path][..], extra].concat());
    (server, port, file)
}

/// A read of more records than one answer holds is cut into requests that each fit, and
/// the records come back whole and in order; forty groups need two requests.
#[test]
fn a_file_record_read_past_one_answer_is_split_and_put_back_together() {
    let values: Vec<String> = (0..300).map(|i| (i * 7).to_string()).collect();
    let text = format!(
        "file 7 record 0 = {}\nfile 2 record 0 = {}\n",
        values.join(" "),
        values[..40].join(" ")
    );
    let (_server, port, _file) = serve_data(&text, &[]);
    let read = mbtool()
        .args(&port)
        .args(["-v", "read-file", "17", "7:0", "300", "-o", "values"])
        .output()
        .unwrap();
    assert!(read.status.success(), "{read:?}");
    assert_eq!(
        String::from_utf8_lossy(&read.stdout)
            .lines()
            .collect::<Vec<_>>(),
        values
    );
    // -v shows each request sent: three, of 121, 121 and 58 records.
    let sent = String::from_utf8_lossy(&read.stderr);
    assert_eq!(
        sent.lines().filter(|l| l.contains("] > ")).count(),
        3,
        "{sent}"
    );
    let groups: Vec<String> = (0..40)
        .flat_map(|i| [format!("2:{i}"), "1".into()])
        .collect();
    let read = mbtool()
        .args(&port)
        .args(["-v", "read-file", "17"])
        .args(&groups)
        .args(["-o", "values"])
        .output()
        .unwrap();
    assert_eq!(
        String::from_utf8_lossy(&read.stdout)
            .lines()
            .collect::<Vec<_>>(),
        values[..40]
    );
    let sent = String::from_utf8_lossy(&read.stderr);
    assert_eq!(
        sent.lines().filter(|l| l.contains("] > ")).count(),
        2,
        "{sent}"
    );
}

/// A FIFO queue of 31 registers is read whole; one of 32 is more than an answer carries,
/// and `serve` answers exception 03 as the specification says, which mbtool tells.
#[test]
fn a_fifo_of_31_is_read_and_one_of_32_is_refused_with_exception_03() {
    let queue = |n: usize| (1..=n).map(|i| i.to_string()).collect::<Vec<_>>().join(" ");
    let text = format!(
        "fifo 400100 = {}\nfifo 400200 = {}\nfifo 400300 = 9\n",
        queue(31),
        queue(32)
    );
    let (_server, port, _file) = serve_data(&text, &[]);
    let expected: Vec<String> = (1..=31).map(|i| i.to_string()).collect();
    assert_eq!(values_of(&port, "read-fifo 17 400100"), expected);
    let output = mbtool()
        .args(&port)
        .args(["read-fifo", "17", "400200"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(13), "{output:?}");
    assert!(
        String::from_utf8_lossy(&output.stderr).contains("exception 03"),
        "{output:?}"
    );
    // No queue there: exception 02.
    let output = mbtool()
        .args(&port)
        .args(["read-fifo", "17", "400301"])
        .output()
        .unwrap();
    assert!(
        String::from_utf8_lossy(&output.stderr).contains("exception 02"),
        "{output:?}"
    );
}

/// `serve`'s records exist where its data file says: a write elsewhere is exception 02 and
/// changes nothing, a write of several groups is all or nothing; `dump` carries the
/// records asked for and `restore` writes them back and reads them back.
#[test]
fn files_live_in_serve_s_data_file_and_go_through_dump_and_restore() {
    let text = "400001-400004 = 1 2 3 4\nfile 4 record 0 = 10 11 12 13\nfile 9 record 100 = 7 8\nfile 102 record 2 = 2 3 4\n";
    let (_server, port, _file) = serve_data(text, &[]);
    let output = mbtool()
        .args(&port)
        .args(["write-file", "17", "4:3", "5", "6"])
        .output()
        .unwrap();
    assert!(
        String::from_utf8_lossy(&output.stderr).contains("exception 02"),
        "{output:?}"
    );
    assert_eq!(
        values_of(&port, "read-file 17 4:0 4"),
        ["10", "11", "12", "13"]
    );
    let dump = mbtool()
        .args(&port)
        .args(["dump", "17", "400001-400004", "4:0-3", "9:100-101", "9:0-1"])
        .output()
        .unwrap();
    assert!(dump.status.success(), "{dump:?}");
    let saved = String::from_utf8(dump.stdout).unwrap();
    assert!(
        saved.contains("\nfile 4 record 0 = 10 11 12 13\nfile 9 record 100 = 7 8\n"),
        "{saved}"
    );
    let told = String::from_utf8_lossy(&dump.stderr);
    assert!(
        told.contains("no such records (exception 02), left out: file 9 records 0-1"),
        "{told}"
    );
    assert!(told.contains("dumped 4 addresses and 6 records"), "{told}");
    // A run that is only partly there: read in halves, down to what the device has.
    let dump = mbtool()
        .args(&port)
        .args(["dump", "17", "102:0-5", "--max-per-request", "4"])
        .output()
        .unwrap();
    assert!(dump.status.success(), "{dump:?}");
    assert!(String::from_utf8_lossy(&dump.stdout).contains("\nfile 102 record 2 = 2 3 4\n"));
    let told = String::from_utf8_lossy(&dump.stderr);
    assert!(
        told.contains("left out: file 102 records 0-1, file 102 record 5"),
        "{told}"
    );
    // The backup changed, written back, read back.
    let changed = data_file(&saved.replace("= 10 11 12 13", "= 20 21 22 23"));
    let restored = mbtool()
        .args(&port)
        .arg("restore")
        .arg("17")
        .arg(changed.path())
        .output()
        .unwrap();
    assert!(restored.status.success(), "{restored:?}");
    assert!(String::from_utf8_lossy(&restored.stderr).contains("every one reads back as written"));
    assert_eq!(
        values_of(&port, "read-file 17 4:0 4"),
        ["20", "21", "22", "23"]
    );
    // --dry-run shows the write of the records too.
    let dry = stdout(&[
        "restore",
        "17",
        &changed.path().display().to_string(),
        "--dry-run",
    ]);
    assert!(
        dry.contains("Write File Record") || dry.contains(" 15 "),
        "{dry}"
    );
}

/// The gateway passes every one of these functions, over TCP and UDP, as the line answers.
#[test]
fn the_gateway_passes_files_fifo_masks_and_read_write() {
    let text = "400001-400010 = 0\nfile 4 record 0 = 1 2 3\nfifo 400100 = 5 6\n";
    let (_server, line, _file) = serve_data(text, &[]);
    let tcp = crate::support::free_port();
    let udp = udp_port();
    let _gateway = Stopped(
        std::process::Command::new(assert_cmd::cargo::cargo_bin("mbtool"))
            .args(["gateway", "-q"])
            .args(&line)
            .args(["--listen", &format!("tcp://127.0.0.1:{tcp}")])
            .args(["--listen", &format!("udp://127.0.0.1:{udp}")])
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap(),
    );
    assert!(crate::support::wait_for_listener(
        tcp,
        Duration::from_secs(10)
    ));
    for port in [
        format!("tcp://127.0.0.1:{tcp}"),
        format!("udp://127.0.0.1:{udp}"),
    ] {
        let port = vec!["--port".to_string(), port];
        assert_eq!(values_of(&port, "read-file 17 4:0 3"), ["1", "2", "3"]);
        assert_eq!(values_of(&port, "read-fifo 17 400100"), ["5", "6"]);
        assert_eq!(
            crate::support::run_against(&port, "write-file 17 4:1 9").0,
            0
        );
        assert_eq!(
            crate::support::run_against(&port, "mask-write 17 400002.04=1").0,
            0
        );
        assert_eq!(
            values_of(&port, "read-write 17 400001 2 400003 5"),
            ["0", "16"]
        );
        assert_eq!(values_of(&port, "read-file 17 4:0 3"), ["1", "9", "3"]);
        // Put back for the other transport.
        assert_eq!(
            crate::support::run_against(&port, "write-file 17 4:1 2").0,
            0
        );
        assert_eq!(crate::support::run_against(&port, "write 17 400002 0").0, 0);
    }
}

/// A UDP port free on 127.0.0.1.
pub fn udp_port() -> u16 {
    std::net::UdpSocket::bind("127.0.0.1:0")
        .and_then(|s| s.local_addr())
        .map(|a| a.port())
        .unwrap()
}

/// `mbtool serve` over UDP (`scheme` udp:// or rtu+udp://) with `extra`, answering: the
/// guard and the connection options for a master.
pub fn serve_udp(scheme: &str, extra: &[&str]) -> (Stopped, Vec<String>) {
    let address = format!("{scheme}127.0.0.1:{}", udp_port());
    let server = serve(&[&["--port", address.as_str()][..], extra].concat());
    let port = vec!["--port".to_string(), address];
    let deadline = Instant::now() + Duration::from_secs(10);
    // Any answer, an exception too, says it is there; 3 is no answer.
    while crate::support::run_against(&port, "read-holding 17 400108 --timeout 200ms").0 == 3 {
        assert!(Instant::now() < deadline, "serve never answered over UDP");
    }
    (server, port)
}
