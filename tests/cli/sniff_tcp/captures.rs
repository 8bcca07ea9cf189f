//! Captures piped in, the public captures read as tshark reads them, Modbus on other ports

use super::*;

/// `mbtool sniff --json --input -`, its standard input and output pipes.
fn sniffing_a_pipe() -> std::process::Child {
    crate::support::mbtool_process()
        .args(["sniff", "--json", "--input", "-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap()
}

#[test]
fn a_capture_piped_in_pieces_is_read_as_the_file_is() {
    // `tcpdump -w - | mbtool sniff --input -`: the file header may come in pieces, a byte
    // first, the rest later.
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/captures/modbus-tcp.pcap");
    let capture = std::fs::read(&path).unwrap();
    let from_file = mbtool()
        .args(["sniff", "--json", "--input"])
        .arg(&path)
        .output()
        .unwrap();
    assert_eq!(from_file.status.code(), Some(0));
    for split in [1, 8, 23] {
        let mut child = sniffing_a_pipe();
        let mut stdin = child.stdin.take().unwrap();
        let pieces = capture.clone();
        let feeder = std::thread::spawn(move || {
            std::io::Write::write_all(&mut stdin, &pieces[..split]).unwrap();
            std::thread::sleep(std::time::Duration::from_millis(200));
            std::io::Write::write_all(&mut stdin, &pieces[split..]).unwrap();
        });
        let piped = child.wait_with_output().unwrap();
        feeder.join().unwrap();
        assert_eq!(piped.status.code(), Some(0), "split at {split}");
        assert_eq!(
            String::from_utf8_lossy(&piped.stdout),
            String::from_utf8_lossy(&from_file.stdout),
            "split at {split}"
        );
    }
}

/// `tcpdump -U -w - | mbtool sniff --input -` on a live network: each frame is shown when
/// its packet comes, not once the capture ends or a batch has gathered.
#[test]
fn a_capture_piped_in_shows_each_frame_as_its_packet_comes() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/captures/modbus-tcp.pcap");
    let capture = std::fs::read(&path).unwrap();
    let mut child = sniffing_a_pipe();
    let mut stdin = child.stdin.take().unwrap();
    // All but the last byte: the capture is still going on.
    std::io::Write::write_all(&mut stdin, &capture[..capture.len() - 1]).unwrap();
    let stdout = child.stdout.take().unwrap();
    let (line, lines) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        for text in BufReader::new(stdout).lines() {
            if line.send(text.unwrap()).is_err() {
                return;
            }
        }
    });
    let first = lines.recv_timeout(std::time::Duration::from_secs(5));
    drop(stdin);
    child.wait().unwrap();
    let first = first.expect("no frame shown while the capture went on");
    assert!(first.starts_with(r#"{"type":"frame""#), "{first}");
}

/// The public Modbus TCP captures of `tests/corpus/modbus-tcp` (each with its source in
/// SOURCES.md), read by mbtool and by tshark: the same PDUs in the same packets, paired
/// with the same requests and the same response times, but for the disagreements above;
/// and the summary's counts are those of the records.
#[test]
fn the_public_captures_read_as_tshark_reads_them() {
    if !peer_available("tshark", command_exists("tshark")) {
        return;
    }
    let corpus = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/corpus/modbus-tcp");
    let mut files: Vec<_> = std::fs::read_dir(&corpus)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "pcap" || e == "pcapng"))
        .collect();
    files.sort();
    assert!(files.len() >= 10);
    let (mut pdus, mut pairs) = (0, 0);
    for file in &files {
        let name = file.file_name().unwrap().to_string_lossy().into_owned();
        let known = |packet: u64| {
            DISAGREEMENTS
                .iter()
                .any(|(prefix, at, _)| name.starts_with(prefix) && *at == packet)
        };
        let theirs = tshark(file, 502);
        let (ours, json) = mbtool_sniff(file, 502);
        let out_of_sequence = out_of_sequence(file);
        for place in theirs.keys().filter(|p| !ours.contains_key(p)) {
            assert!(
                known(place.1),
                "{name}: tshark finds {place:?}, mbtool does not"
            );
        }
        for place in ours.keys().filter(|p| !theirs.contains_key(p)) {
            assert!(
                known(place.1) || out_of_sequence.contains(&place.1),
                "{name}: mbtool finds {place:?}, tshark does not"
            );
        }
        for (place, pairing) in &theirs {
            let (Some((request, time)), Some(ours)) = (pairing, ours.get(place)) else {
                continue;
            };
            // Nanosecond stamps (pcapng) give tshark's times a fraction of a microsecond.
            let alike = ours.is_some_and(|(r, t)| r == *request && t.abs_diff(*time) <= 1);
            assert!(
                alike || known(place.1),
                "{name}: {place:?} tshark {pairing:?}, mbtool {ours:?}"
            );
            pairs += 1;
        }
        pdus += theirs.len();
        // The summary counts what the records show.
        let records: Vec<serde_json::Value> = json
            .lines()
            .map(|l| serde_json::from_str(l).unwrap())
            .collect();
        let count = |kind: &str| records.iter().filter(|r| r["kind"] == kind).count() as u64;
        let summary = records.iter().find(|r| r["type"] == "summary").unwrap();
        let unanswered = records.iter().filter(|r| r["type"] == "unanswered").count() as u64;
        assert_eq!(
            [
                &summary["requests"],
                &summary["answers"],
                &summary["exceptions"],
                &summary["unanswered"]
            ]
            .map(|v| v.as_u64().unwrap()),
            [
                count("request"),
                count("response") + count("exception"),
                count("exception"),
                unanswered
            ],
            "{name}"
        );
    }
    assert!(
        pdus > 40_000 && pairs > 15_000,
        "{pdus} PDUs, {pairs} answers paired"
    );
}

/// A capture of Modbus TCP on a port not asked for names the port and the option that
/// reads it; an exception with a byte after its code keeps its code.
#[test]
fn modbus_on_another_port_is_named_and_an_exception_keeps_its_code() {
    let corpus = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/corpus/modbus-tcp");
    let output = mbtool()
        .args(["sniff", "--tcp-port", "5020", "--input"])
        .arg(corpus.join("20-paciente-fc3-tiny.pcap"))
        .output()
        .unwrap();
    assert!(output.status.success());
    assert!(String::from_utf8_lossy(&output.stderr).contains(
        "mbtool: packets on TCP port 502 (4 packets) carry Modbus TCP headers: give --tcp-port 502 to read them"
    ));
    let output = mbtool()
        .args(["sniff", "--json", "--input"])
        .arg(corpus.join("01-digitalbond-part1-multiconn.pcap"))
        .output()
        .unwrap();
    let busy = String::from_utf8_lossy(&output.stdout)
        .lines()
        .map(|line| serde_json::from_str::<serde_json::Value>(line).unwrap())
        .find(|record| record["packet"] == 91)
        .unwrap();
    assert_eq!(
        (&busy["kind"], &busy["exception"], &busy["error"]),
        (
            &serde_json::json!("exception"),
            &serde_json::json!(6),
            &serde_json::json!("1 byte after the exception code: 00")
        )
    );
}
