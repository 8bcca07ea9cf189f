//! `sniff --input` on captures of Modbus TCP, against Wireshark's own dissector: tcpdump
//! records the loopback while pymodbus, mbpoll and raw sockets talk to `serve` and to
//! pymodbus's server, and every PDU tshark finds mbtool finds, paired alike, with the
//! same response time to the microsecond; in pcap, pcapng and a capture on `any`.

use std::collections::{BTreeMap, BTreeSet};

use std::io::{BufRead, BufReader};

use std::path::Path;

use std::process::{Command as Process, Stdio};

use crate::support::{command_exists, mbtool, peer_available, pymodbus_tcp, serve_tcp, Stopped};

/// A PDU as both tools place it: the client's port, packet, transaction id, unit id,
/// function (without the exception bit).
type Place = (u16, u64, u16, u8, u8);

/// For an answer: the request's packet and the response time in microseconds.
type Pairing = (u64, u64);

/// tcpdump recording `interface` to `file`, once it says it listens.
fn tcpdump(interface: &str, file: &Path, filter: &str) -> Stopped {
    // A buffer of 32 MB, not the 2 MB default: on a loaded machine the kernel drops what
    // a slow tcpdump has not taken yet, and the comparison then has too little to go by.
    let mut child = Process::new("tcpdump")
        .args([
            "-i",
            interface,
            "--immediate-mode",
            "-U",
            "-B",
            "32768",
            "-s",
            "0",
            "-w",
        ])
        .arg(file)
        .arg(filter)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("tcpdump starts");
    let stderr = child.stderr.take().expect("tcpdump's stderr");
    let mut lines = BufReader::new(stderr).lines();
    let listening = lines.any(|line| line.is_ok_and(|l| l.contains("listening on")));
    assert!(listening, "tcpdump did not start listening on {interface}");
    // Its later words are not read: they must not fill the pipe.
    std::thread::spawn(move || lines.for_each(drop));
    Stopped(child)
}

/// Ends a tcpdump as Ctrl-C does, so that it writes out what it holds.
fn stop(mut tcpdump: Stopped) {
    let pid = tcpdump.0.id().to_string();
    let _ = Process::new("kill").args(["-INT", &pid]).status();
    let _ = tcpdump.0.wait();
}

/// What tshark's Modbus/TCP dissector finds on `port`.
fn tshark(file: &Path, port: u16) -> BTreeMap<Place, Option<Pairing>> {
    let output = Process::new("tshark")
        .arg("-r")
        .arg(file)
        .args(["-o", &format!("mbtcp.tcp.port:{port}")])
        .args(["-Y", &format!("mbtcp && tcp.port == {port}")])
        .args(["-T", "fields", "-E", "occurrence=a", "-E", "aggregator=,"])
        .args([
            "-e",
            "frame.number",
            "-e",
            "mbtcp.trans_id",
            "-e",
            "mbtcp.unit_id",
        ])
        .args(["-e", "modbus.func_code", "-e", "modbus.request_frame"])
        .args([
            "-e",
            "modbus.response_time",
            "-e",
            "tcp.srcport",
            "-e",
            "tcp.dstport",
        ])
        .output()
        .expect("tshark runs");
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let mut pdus = BTreeMap::new();
    for line in String::from_utf8_lossy(&output.stdout).lines() {
        let fields: Vec<Vec<&str>> = line
            .split('\t')
            .map(|f| f.split(',').filter(|v| !v.is_empty()).collect())
            .collect();
        let packet: u64 = fields[0][0].parse().unwrap();
        let count = fields[1].len();
        let ports: Vec<u16> = [&fields[6], &fields[7]]
            .map(|f| f[0].parse().unwrap())
            .to_vec();
        let client = if ports[1] == port { ports[0] } else { ports[1] };
        for i in 0..count {
            let function: u8 = fields[3].get(i).map_or(0, |f| f.parse().unwrap());
            let place = (
                client,
                packet,
                fields[1][i].parse().unwrap(),
                fields[2][i].parse().unwrap(),
                function & 0x7F,
            );
            // Where some PDUs of a packet are paired and others not, which is which is not
            // told: those are left out of the pairing compared.
            let paired = (fields[4].len() == count && fields[5].len() == count).then(|| {
                let seconds: f64 = fields[5][i].parse().unwrap();
                (
                    fields[4][i].parse().unwrap(),
                    (seconds * 1e6).round() as u64,
                )
            });
            pdus.insert(place, paired);
        }
    }
    pdus
}

/// What mbtool's sniff finds on `port`, as JSON Lines.
fn mbtool_sniff(file: &Path, port: u16) -> (BTreeMap<Place, Option<Pairing>>, String) {
    let output = mbtool()
        .args(["sniff", "--input"])
        .arg(file)
        .args(["--tcp-port", &port.to_string(), "--json"])
        .output()
        .expect("mbtool runs");
    let stdout = String::from_utf8_lossy(&output.stdout).into_owned();
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let mut pdus = BTreeMap::new();
    for line in stdout.lines() {
        let json: serde_json::Value = serde_json::from_str(line).unwrap();
        if json["type"] != "frame" {
            continue;
        }
        let number = |key: &str| json[key].as_u64();
        let client = json["client"].as_str().unwrap().rsplit(':').next().unwrap();
        let place = (
            client.parse().unwrap(),
            number("packet").unwrap(),
            number("transaction").unwrap() as u16,
            number("slave").unwrap() as u8,
            number("function").unwrap() as u8 & 0x7F,
        );
        let paired = number("request_packet").zip(number("response_time_us"));
        pdus.insert(place, paired);
    }
    (pdus, stdout)
}

/// The client ports of the connections where the capture missed bytes that were sent
/// (tcpdump on `any` does, now and then): there a PDU after the hole is placed by tshark in
/// its own packet at once, and by mbtool once the hole is known to be one.
fn lossy(file: &Path, port: u16) -> BTreeSet<u16> {
    let output = Process::new("tshark")
        .arg("-r")
        .arg(file)
        .args([
            "-Y",
            "tcp.analysis.lost_segment || tcp.analysis.ack_lost_segment",
        ])
        .args(["-T", "fields", "-e", "tcp.srcport", "-e", "tcp.dstport"])
        .output()
        .expect("tshark runs");
    String::from_utf8_lossy(&output.stdout)
        .lines()
        .flat_map(|line| {
            line.split('\t')
                .map(|p| p.parse::<u16>().unwrap_or(port))
                .collect::<Vec<_>>()
        })
        .filter(|p| *p != port)
        .collect()
}

/// Every PDU tshark finds, mbtool finds and no other; every answer tshark pairs, mbtool
/// pairs with the same request and the same response time. On a connection the capture
/// lost bytes of, the same PDUs are found, in the same or a later packet.
/// `least`: the PDUs tshark must find for the comparison to mean something.
fn agree(file: &Path, port: u16, least: usize) -> String {
    let lost = lossy(file, port);
    let (mut theirs, (mut ours, json)) = (tshark(file, port), mbtool_sniff(file, port));
    assert!(
        theirs.len() >= least,
        "too little traffic on {port}: {theirs:?}"
    );
    let of_lossy = |pdus: &mut BTreeMap<Place, Option<Pairing>>| {
        let taken: BTreeSet<_> = pdus
            .keys()
            .filter(|p| lost.contains(&p.0))
            .copied()
            .collect();
        pdus.retain(|p, _| !lost.contains(&p.0));
        taken
            .into_iter()
            .map(|(c, _, t, u, f)| (c, t, u, f))
            .collect::<BTreeSet<_>>()
    };
    assert_eq!(
        of_lossy(&mut ours),
        of_lossy(&mut theirs),
        "{}",
        file.display()
    );
    let places =
        |pdus: &BTreeMap<Place, Option<Pairing>>| pdus.keys().copied().collect::<BTreeSet<_>>();
    let missed: Vec<_> = places(&theirs)
        .difference(&places(&ours))
        .copied()
        .collect();
    assert_eq!(
        missed,
        [],
        "PDUs tshark finds in {} and mbtool does not",
        file.display()
    );
    // tshark passes over a request whose first segment is shorter than an MBAP header
    // (the one written a byte at a time, transaction 200); mbtool puts it together.
    let more: Vec<_> = places(&ours)
        .difference(&places(&theirs))
        .copied()
        .collect();
    assert!(
        more.iter().all(|place| place.2 == 200),
        "{more:?} in {}",
        file.display()
    );
    let mut paired = 0;
    for (place, pairing) in &theirs {
        if let Some(pairing) = pairing {
            assert_eq!(
                ours[place],
                Some(*pairing),
                "{place:?} in {}",
                file.display()
            );
            paired += 1;
        }
    }
    assert!(
        paired >= least / 8,
        "tshark paired only {paired} answers on {port}"
    );
    json
}

#[test]
fn every_pdu_tshark_finds_mbtool_finds_paired_alike() {
    let root = Process::new("id")
        .arg("-u")
        .output()
        .is_ok_and(|o| o.stdout == b"0\n");
    let tools = ["tcpdump", "tshark", "editcap", "mbpoll"]
        .iter()
        .all(|t| command_exists(t));
    if !peer_available(
        "tcpdump, tshark, editcap and mbpoll, as root (captures the loopback)",
        root && tools,
    ) {
        return;
    }
    let Some((_pymodbus, pymodbus_port)) = pymodbus_tcp(&[]) else {
        return;
    };
    let (_serve, serve_port, serve_tcp_port) = serve_tcp(&[]);
    let pymodbus_tcp_port: u16 = pymodbus_port[1]
        .rsplit(':')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    let dir = tempfile::tempdir().unwrap();
    let on_lo = dir.path().join("lo.pcap");
    let on_any = dir.path().join("any.pcap");
    let filter = format!("tcp port {serve_tcp_port} or tcp port {pymodbus_tcp_port}");
    let lo = tcpdump("lo", &on_lo, &filter);
    let any = tcpdump("any", &on_any, &filter);

    let traffic = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/peers/mbap_traffic.py");
    for port in [serve_tcp_port, pymodbus_tcp_port] {
        let status = Process::new("timeout")
            .args(["60", "python3", traffic, &port.to_string()])
            .status()
            .expect("python3 runs");
        assert!(status.success(), "the traffic to {port}");
        let status = Process::new("mbpoll")
            .args([
                "-m",
                "tcp",
                "-p",
                &port.to_string(),
                "-a",
                "17",
                "-r",
                "1",
                "-c",
                "4",
            ])
            .args(["-1", "127.0.0.1"])
            .stdout(Stdio::null())
            .status()
            .expect("mbpoll runs");
        assert!(status.success());
    }
    for args in ["read-holding 17 400108 3", "read-coils 17 1 20", "info 17"] {
        let _ = mbtool().args(&serve_port).args(args.split(' ')).output();
    }
    stop(lo);
    stop(any);

    let pcapng = dir.path().join("lo.pcapng");
    let status = Process::new("editcap")
        .args(["-F", "pcapng"])
        .arg(&on_lo)
        .arg(&pcapng)
        .status()
        .expect("editcap runs");
    assert!(status.success());
    for port in [serve_tcp_port, pymodbus_tcp_port] {
        let from_pcap = agree(&on_lo, port, 40);
        let from_pcapng = agree(&pcapng, port, 40);
        assert_eq!(from_pcapng, from_pcap, "the same capture as pcapng");
        // tcpdump on `any` drops packets now and then on a busy machine.
        agree(&on_any, port, 10);
    }
    cut_off_capture_is_shown_then_refused(&on_lo, serve_tcp_port);
    stats_hold_what_tshark_timed(&on_lo, serve_tcp_port);
    frames_written_for_wireshark(&on_lo, serve_tcp_port);
}

/// A capture cut off in the middle of a record (tcpdump killed) shows what came before,
/// then says so in one line with exit status 2.
fn cut_off_capture_is_shown_then_refused(whole: &Path, port: u16) {
    let bytes = std::fs::read(whole).unwrap();
    let cut = whole.with_extension("cut.pcap");
    std::fs::write(&cut, &bytes[..bytes.len() - 7]).unwrap();
    let output = mbtool()
        .args(["sniff", "--input"])
        .arg(&cut)
        .args(["--tcp-port", &port.to_string()])
        .output()
        .unwrap();
    let (stdout, stderr) = (
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr),
    );
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert!(
        stdout.contains("request") && stdout.contains("\nsummary: "),
        "{stdout}"
    );
    // Besides the other servers of the capture, named with the option that reads them.
    let told: Vec<&str> = stderr
        .lines()
        .filter(|line| !line.contains("carry Modbus TCP headers: give --tcp-port"))
        .collect();
    assert_eq!(told.len(), 1, "{stderr}");
    assert!(
        stderr.contains("ends in the middle of a record"),
        "{stderr}"
    );
}

#[test]
fn a_file_that_is_no_capture_or_a_port_without_one_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("plant.pcap");
    std::fs::write(&file, "these are not packets\n").unwrap();
    let cut = dir.path().join("cut.pcap");
    std::fs::write(&cut, [0xD4, 0xC3, 0xB2, 0xA1, 2, 0, 4, 0, 0, 0]).unwrap();
    for (args, says) in [
        (
            vec!["sniff", "--input", file.to_str().unwrap()],
            "is neither a pcap nor a pcapng file",
        ),
        (
            vec!["sniff", "--input", cut.to_str().unwrap()],
            "ends inside its file header",
        ),
        (
            vec!["sniff", "--port", "/dev/null", "--tcp-port", "5020"],
            "--tcp-port picks the Modbus connections of a capture",
        ),
    ] {
        let output = mbtool().args(&args).output().unwrap();
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(
            stderr.starts_with("mbtool: ") && stderr.contains(says),
            "{stderr}"
        );
        assert_eq!(stderr.lines().count(), 1);
    }
}

/// `--stats`: the valid requests and answers of unit 17 counted, the exception told by
/// its code, and the response times spanning those tshark measured.
fn stats_hold_what_tshark_timed(file: &Path, port: u16) {
    let theirs: Vec<u64> = tshark(file, port)
        .values()
        .flatten()
        .map(|(_, us)| *us)
        .collect();
    let output = mbtool()
        .args(["sniff", "--input"])
        .arg(file)
        .args(["--tcp-port", &port.to_string(), "--stats", "--json"])
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    let lines: Vec<serde_json::Value> = stdout
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let frames = |kind: &str| {
        lines
            .iter()
            .filter(|l| l["type"] == "frame" && l["valid"] == true)
            .filter(|l| l["slave"] == 17 && l["kind"] == kind)
            .count() as u64
    };
    let stats = lines
        .iter()
        .find(|l| l["type"] == "stats" && l["unit"] == 17)
        .unwrap_or_else(|| panic!("{stdout}"));
    assert_eq!(stats["server"], format!("127.0.0.1:{port}"));
    assert_eq!(stats["requests"], frames("request"));
    assert_eq!(stats["answers"], frames("response") + frames("exception"));
    // A code none of the capture's answers carries is left out; tcpdump may drop the one
    // exception answer on a busy machine.
    let exceptions = stats["exceptions"]["02"].as_u64().unwrap_or(0);
    assert_eq!(exceptions, frames("exception"), "{stats}");
    let time = |key: &str| stats["response_time_us"][key].as_u64().unwrap();
    assert!(time("min") <= *theirs.iter().min().unwrap(), "{stats}");
    assert!(time("max") >= *theirs.iter().max().unwrap(), "{stats}");
    assert!(
        time("min") <= time("mean") && time("mean") <= time("max"),
        "{stats}"
    );
    assert!(
        time("min") <= time("p95") && time("p95") <= time("max"),
        "{stats}"
    );
}

/// `--interface lo`: a poll running beside the capture is seen request by request, each
/// answer paired, as it happens; Ctrl-C ends it at once with the summary, and `--save`
/// kept the packets as a pcapng file that reads back the same. Without privileges, one
/// line says what to do.
#[test]
fn live_on_lo_a_poll_is_seen_request_by_request() {
    let root = Process::new("id")
        .arg("-u")
        .output()
        .is_ok_and(|o| o.stdout == b"0\n");
    if !peer_available("root, to capture on lo", root) {
        return;
    }
    let (_serve, port, tcp) = serve_tcp(&[]);
    let dir = tempfile::tempdir().unwrap();
    let saved = dir.path().join("live.pcapng");
    let mut sniff = Stopped(
        crate::support::mbtool_process()
            .args([
                "sniff",
                "--interface",
                "lo",
                "--tcp-port",
                &tcp.to_string(),
                "--json",
                "--save",
            ])
            .arg(&saved)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap(),
    );
    let mut said = BufReader::new(sniff.0.stderr.take().unwrap()).lines();
    let first = said.next().unwrap().unwrap();
    assert!(first.contains("capturing Modbus TCP on lo"), "{first}");
    let stdout = sniff.0.stdout.take().unwrap();
    let (seen, lines) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        for line in BufReader::new(stdout).lines().map_while(Result::ok) {
            let _ = seen.send(line);
        }
    });
    let poll = mbtool()
        .args(&port)
        .args([
            "read-holding",
            "17",
            "400108",
            "3",
            "--poll",
            "50ms",
            "--count",
            "10",
        ])
        .output()
        .unwrap();
    assert!(poll.status.success());
    // Each request and answer shown as it passes, before the capture ends.
    let mut frames = Vec::new();
    while frames.len() < 20 {
        let line = lines
            .recv_timeout(std::time::Duration::from_secs(5))
            .expect("a frame shown");
        frames.push(serde_json::from_str::<serde_json::Value>(&line).unwrap());
    }
    let stopped = std::time::Instant::now();
    let _ = Process::new("kill")
        .args(["-INT", &sniff.0.id().to_string()])
        .status();
    assert!(sniff.0.wait().unwrap().success());
    assert!(stopped.elapsed() < std::time::Duration::from_secs(1));
    for (i, pair) in frames.chunks(2).enumerate() {
        let transaction = i as u64 + 1;
        assert_eq!(pair[0]["kind"], "request", "{pair:?}");
        assert_eq!(pair[1]["kind"], "response", "{pair:?}");
        assert_eq!(pair[0]["transaction"], transaction);
        assert_eq!(pair[1]["transaction"], transaction);
        assert_eq!(pair[1]["request_packet"], pair[0]["packet"]);
        assert_eq!(pair[1]["values"], serde_json::json!([555, 0, 100]));
    }
    let summary: Vec<String> = lines.try_iter().collect();
    assert!(
        summary.iter().any(|l| l.contains("\"type\":\"summary\"")),
        "{summary:?}"
    );
    let (from_file, _) = mbtool_sniff(&saved, tcp);
    assert_eq!(from_file.len(), 20);

    let denied = Process::new("setpriv")
        .args(["--reuid=65534", "--regid=65534", "--clear-groups"])
        .arg(env!("CARGO_BIN_EXE_mbtool"))
        .args(["sniff", "--interface", "lo"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&denied.stderr);
    if denied.status.code() != Some(126) {
        assert_eq!(denied.status.code(), Some(1), "{stderr}");
        assert!(
            stderr.contains("needs privileges") && stderr.contains("setcap"),
            "{stderr}"
        );
        assert_eq!(stderr.lines().count(), 1);
    }
}

/// `--pcap OUT` from a TCP capture: each frame found, as the RTU frame it carries, which
/// Wireshark's Modbus RTU dissector reads unit for unit and function for function.
fn frames_written_for_wireshark(file: &Path, port: u16) {
    let out = file.with_extension("frames.pcap");
    let (ours, _) = mbtool_sniff(file, port);
    let status = mbtool()
        .args(["sniff", "--input"])
        .arg(file)
        .args(["--tcp-port", &port.to_string(), "--pcap"])
        .arg(&out)
        .output()
        .unwrap()
        .status;
    assert!(status.success());
    let output = Process::new("tshark")
        .arg("-r")
        .arg(&out)
        .args([
            "-o",
            r#"uat:user_dlts:"User 0 (DLT=147)","mbrtu","0","","0","""#,
        ])
        .args([
            "-T",
            "fields",
            "-e",
            "mbrtu.unit_id",
            "-e",
            "modbus.func_code",
        ])
        .output()
        .unwrap();
    // A frame tshark cannot classify (a request that breaks its function's rules, a
    // function 23 it cannot tell request from answer by) lacks a field or two.
    let mut read: Vec<(u8, Option<u8>)> = String::from_utf8_lossy(&output.stdout)
        .lines()
        .filter_map(|line| {
            let (unit, function) = line.split_once('\t')?;
            let function = function.parse::<u8>().ok().map(|f| f & 0x7F);
            Some((unit.parse().ok()?, function))
        })
        .collect();
    let mut written: Vec<(u8, Option<u8>)> = ours.keys().map(|p| (p.3, Some(p.4))).collect();
    written.sort_unstable();
    read.sort_unstable();
    assert!(
        read.len() + 4 >= written.len() && read.len() <= written.len(),
        "{read:?}"
    );
    let unknown = read.iter().filter(|(_, f)| f.is_none()).count();
    assert!(unknown <= 4, "{read:?}");
    let known: Vec<_> = read.iter().filter(|(_, f)| f.is_some()).collect();
    assert!(
        known.iter().all(|frame| written.contains(frame)),
        "{read:?}"
    );
}

/// Where mbtool reads a public capture otherwise than tshark, by file and packet, and why;
/// everything else in them both tools read alike.
const DISAGREEMENTS: &[(&str, u64, &str)] = &[
    // A segment's bytes after its PDU frame nothing (3 bytes): tshark takes them as the
    // start of the next PDU, joins the next segment to them and reads no header; mbtool
    // passes them over as noise and finds the header that starts the next segment.
    (
        "01-",
        113,
        "a PDU at the start of a segment after bytes that frame nothing",
    ),
    // tshark pairs every answer with the latest request of its transaction id; three
    // writes pipelined with one id are answered in order, each echoing its own write,
    // which mbtool pairs them by.
    (
        "10-",
        70,
        "an answer paired with the oldest request its echo fits",
    ),
];

/// The packets whose sequence numbers tshark finds wrong (a retransmission, out of order,
/// after a segment not captured). tshark does not read them as Modbus; mbtool puts a
/// retransmission that fills a hole in its place, as the receiver did, and frames one whose
/// number is far off the stream on its own.
fn out_of_sequence(file: &Path) -> BTreeSet<u64> {
    let output = Process::new("tshark")
        .arg("-r")
        .arg(file)
        .args([
            "-Y",
            "tcp.analysis.flags",
            "-T",
            "fields",
            "-e",
            "frame.number",
        ])
        .output()
        .expect("tshark runs");
    String::from_utf8_lossy(&output.stdout)
        .lines()
        .filter_map(|line| line.trim().parse().ok())
        .collect()
}

mod captures;
