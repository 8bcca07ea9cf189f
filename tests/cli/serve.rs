//! `mbtool serve` as masters we did not write see it (mbpoll, pymodbus) and as mbtool's own
//! master sees it: every table read and written, exceptions, injected faults, data files,
//! and a TCP server that one bad client cannot stop.

use std::io::Write;
use std::net::TcpStream;
use std::process::Command as Process;
use std::time::Duration;

use crate::support::{
    command_exists, mbtool, peer_available, python_has, run_against, serve, serve_pty, serve_tcp,
    values_of, writes_read_back, PtyPair,
};

#[test]
fn mbtool_against_serve_on_tcp() {
    let (_server, port, _) = serve_tcp(&[]);
    assert_eq!(
        values_of(&port, "read-holding 17 400108 3"),
        ["555", "0", "100"]
    );
    assert_eq!(values_of(&port, "read-input-registers 17 300009"), ["10"]);
    writes_read_back(&port);
}

#[test]
fn mbtool_against_serve_in_rtu_and_ascii_on_a_pty() {
    for mode in ["rtu", "ascii"] {
        let Some(pair) = PtyPair::new() else { return };
        let (_server, port) = serve_pty(&pair, &["--mode", mode]);
        assert_eq!(
            values_of(&port, "read-holding 17 400108 3"),
            ["555", "0", "100"],
            "{mode}"
        );
        writes_read_back(&port);
        // A broadcast is carried out and not answered.
        assert_eq!(run_against(&port, "write-register 0 400050 9").0, 0);
        assert_eq!(values_of(&port, "read-holding 17 400050"), ["9"]);
        // Another slave id is silent.
        assert_eq!(
            run_against(&port, "read-holding 18 400108 --timeout 200ms").0,
            3
        );
    }
}

#[test]
fn several_slave_ids_each_with_their_own_data() {
    let (_server, port, _) = serve_tcp(&["--slave", "17", "--slave", "18"]);
    assert_eq!(run_against(&port, "write-register 18 400001 5").0, 0);
    assert_eq!(values_of(&port, "read-holding 18 400001"), ["5"]);
    assert_eq!(values_of(&port, "read-holding 17 400001"), ["0"]);
    // Over TCP an unknown unit id is answered as a gateway would.
    assert_eq!(run_against(&port, "read-holding 19 400001").0, 21);
}

/// mbpoll's values for a read: the numbers after `[ref]:`.
fn mbpoll_values(output: &str) -> Vec<String> {
    output
        .lines()
        .filter(|l| l.starts_with('['))
        .filter_map(|l| l.split(':').nth(1))
        .map(|v| v.trim().to_string())
        .collect()
}

fn mbpoll(connection: &[&str], args: &str) -> Vec<String> {
    let output = Process::new("mbpoll")
        .args(connection)
        .args(args.split_whitespace())
        .output()
        .expect("mbpoll runs");
    let text = String::from_utf8_lossy(&output.stdout);
    assert!(
        output.status.success(),
        "mbpoll {args}: {text}{}",
        String::from_utf8_lossy(&output.stderr)
    );
    mbpoll_values(&text)
}

/// Every table read and written by mbpoll; what it wrote read back by mbtool too.
pub(crate) fn mbpoll_exercise(connection: &[&str], port: &[String]) {
    let read = |args: &str| mbpoll(connection, &format!("-a 17 -1 {args}"));
    assert_eq!(read("-t 4 -r 108 -c 3"), ["555", "0", "100"]);
    assert_eq!(read("-t 3 -r 9"), ["10"]);
    assert_eq!(
        read("-t 0 -r 20 -c 8"),
        ["1", "0", "1", "1", "0", "0", "1", "1"]
    );
    assert_eq!(
        read("-t 1 -r 197 -c 8"),
        ["0", "0", "1", "1", "0", "1", "0", "1"]
    );
    read("-t 4 -r 2 1234");
    assert_eq!(read("-t 4 -r 2"), ["1234"]);
    read("-t 4 -r 30 7 8 9");
    assert_eq!(values_of(port, "read-holding 17 400030 3"), ["7", "8", "9"]);
    read("-t 0 -r 173 1");
    assert_eq!(values_of(port, "read-coils 17 000173"), ["1"]);
    read("-t 0 -r 300 1 0 1");
    assert_eq!(values_of(port, "read-coils 17 000300 3"), ["1", "0", "1"]);
    // mbpoll stores floats low word first unless -B.
    read("-t 4:float -r 40 3.5");
    assert_eq!(
        values_of(port, "read-holding 17 400040 --type f32 --order CDAB"),
        ["3.5"]
    );
}

#[test]
fn mbpoll_against_serve_on_tcp() {
    if !peer_available("mbpoll", command_exists("mbpoll")) {
        return;
    }
    let (_server, port, tcp) = serve_tcp(&[]);
    let tcp = tcp.to_string();
    mbpoll_exercise(&["-m", "tcp", "-p", &tcp, "127.0.0.1"], &port);
}

#[test]
fn mbpoll_against_serve_in_rtu_on_a_pty() {
    if !peer_available("mbpoll", command_exists("mbpoll")) {
        return;
    }
    let Some(pair) = PtyPair::new() else { return };
    let (_server, port) = serve_pty(&pair, &[]);
    let device = pair.b.display().to_string();
    mbpoll_exercise(&["-m", "rtu", "-b", "19200", "-P", "even", &device], &port);
}

#[test]
fn pymodbus_master_in_ascii_against_serve() {
    if !peer_available("pymodbus (Python)", python_has("pymodbus")) {
        return;
    }
    let Some(pair) = PtyPair::new() else { return };
    let (_server, _) = serve_pty(&pair, &["--mode", "ascii"]);
    let script = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/peers/pymodbus_master.py"
    );
    let output = Process::new("python3")
        .args([
            script,
            "--framer",
            "ascii",
            "--serial",
            &pair.b.display().to_string(),
        ])
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let json: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(json["holding"], serde_json::json!([555, 0, 100]));
    assert_eq!(json["input_register"], serde_json::json!([10]));
    assert_eq!(json["coils"], serde_json::json!([1, 0, 1, 1, 0, 0, 1, 1]));
    assert_eq!(json["inputs"], serde_json::json!([0, 0, 1, 1, 0, 1, 0, 1]));
    assert_eq!(
        json["written_registers"],
        serde_json::json!([1234, 7, 8, 9])
    );
    assert_eq!(json["written_coils"], serde_json::json!([1, 0, 1, 1]));
}

#[test]
fn real_slave_exceptions() {
    let (_server, port, _) = serve_tcp(&["--read-only", "400001-400010"]);
    let (code, out) = run_against(&port, "raw 17 41");
    assert_eq!(code, 11, "{out}");
    let (code, out) = run_against(&port, "raw 17 03 00 00 00 00");
    assert_eq!(code, 13, "{out}");
    // A good quantity past the last address: 02, as the specification checks in that order.
    let (code, out) = run_against(&port, "raw 17 03 FF FF 00 02");
    assert_eq!(code, 12, "{out}");
    let (code, out) = run_against(&port, "write-register 17 400005 1");
    assert_eq!(code, 12, "{out}");
    assert_eq!(run_against(&port, "write-register 17 400011 1").0, 0);
    let (code, out) = run_against(&port, "raw 17 2B 0E 01 00 --json");
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("\"value\":\"mbtool\""), "{out}");
}

#[test]
fn over_tcp_function_00_and_80_ff_get_exception_01() {
    let (_server, _, tcp) = serve_tcp(&[]);
    for (pdu, answer) in [
        (&[0x00][..], [0x80, 0x01]),
        (&[0x83, 0x02][..], [0x83, 0x01]),
    ] {
        let mut client = TcpStream::connect(("127.0.0.1", tcp)).unwrap();
        client
            .set_read_timeout(Some(Duration::from_secs(5)))
            .unwrap();
        let len = u8::try_from(pdu.len() + 1).unwrap();
        client
            .write_all(&[&[0, 7, 0, 0, 0, len, 17][..], pdu].concat())
            .unwrap();
        let mut got = [0u8; 9];
        std::io::Read::read_exact(&mut client, &mut got).unwrap();
        assert_eq!(
            got,
            [0, 7, 0, 0, 0, 3, 17, answer[0], answer[1]],
            "{pdu:02X?}"
        );
    }
}

#[test]
fn injected_faults_give_what_the_master_promises() {
    let (_s, port, _) = serve_tcp(&["--exception", "4@400100-400120"]);
    assert_eq!(run_against(&port, "read-holding 17 400108").0, 14);
    assert_eq!(run_against(&port, "read-holding 17 400001").0, 0);

    let (_s, port, _) = serve_tcp(&["--drop", "1"]);
    assert_eq!(
        run_against(&port, "read-holding 17 400108 --timeout 300ms").0,
        3
    );

    let (_s, port, _) = serve_tcp(&["--corrupt", "100%"]);
    let (code, out) = run_against(&port, "read-holding 17 400108");
    assert_eq!(code, 4, "{out}");

    let (_s, port, _) = serve_tcp(&["--delay", "600ms"]);
    assert_eq!(
        run_against(&port, "read-holding 17 400108 --timeout 200ms").0,
        3
    );
    assert_eq!(
        run_against(&port, "read-holding 17 400108 --timeout 2s").0,
        0
    );

    let Some(pair) = PtyPair::new() else { return };
    let (_s, port) = serve_pty(&pair, &["--garbage", "--seed", "7"]);
    // The master passes over the noise in front of each answer.
    assert_eq!(
        values_of(&port, "read-holding 17 400108 3"),
        ["555", "0", "100"]
    );
    drop(_s);
    let Some(pair) = PtyPair::new() else { return };
    let a = pair.a.display().to_string();
    let _s = serve(&["--port", &a, "--corrupt", "1"]);
    let port = vec!["--port".to_string(), pair.b.display().to_string()];
    std::thread::sleep(Duration::from_millis(300));
    let (code, out) = run_against(&port, "read-holding 17 400108 --timeout 300ms");
    assert_eq!(code, 4, "{out}");
    // A corrupted answer is whole at once: it is told then, not at the timeout.
    let started = std::time::Instant::now();
    let (code, out) = run_against(&port, "read-holding 17 400108 --timeout 5s");
    assert_eq!(code, 4, "{out}");
    assert!(
        started.elapsed() < Duration::from_secs(1),
        "{:?}",
        started.elapsed()
    );
}

#[test]
fn a_data_file_sets_values_and_the_addresses_that_exist() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("plant.txt");
    std::fs::write(
        &path,
        "# pump station\n400001 = 3.14 f32\n400010-400019 = 7\n000001-000004 = on off on on\n",
    )
    .unwrap();
    let (_s, port, _) = serve_tcp(&["--data", path.to_str().unwrap()]);
    assert_eq!(
        values_of(&port, "read-holding 17 400001 --type f32"),
        ["3.14"]
    );
    assert_eq!(values_of(&port, "read-holding 17 400010-400019").len(), 10);
    assert_eq!(
        values_of(&port, "read-coils 17 000001 4"),
        ["1", "0", "1", "1"]
    );
    assert_eq!(run_against(&port, "read-holding 17 400020").0, 12);
    assert_eq!(run_against(&port, "read-input-registers 17 300001").0, 12);

    std::fs::write(&path, "400001 = 1\n400002 = twelve\n").unwrap();
    let output = crate::support::mbtool()
        .args([
            "serve",
            "--port",
            "tcp://127.0.0.1:1",
            "--data",
            path.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("plant.txt:2: 'twelve' is not a number"),
        "{stderr}"
    );
}

#[test]
fn a_client_sending_garbage_or_nothing_does_not_stop_the_server() {
    let (_server, port, tcp) = serve_tcp(&[]);
    // One client connects and never sends; another sends 1 MB of garbage.
    let _silent = TcpStream::connect(("127.0.0.1", tcp)).unwrap();
    let mut noisy = TcpStream::connect(("127.0.0.1", tcp)).unwrap();
    let garbage: Vec<u8> = (0..1_000_000u32)
        .map(|i| (i.wrapping_mul(2_654_435_761) >> 13) as u8)
        .collect();
    // The server may close the connection part way: that is what it should do.
    let _ = noisy.write_all(&garbage);
    assert_eq!(
        values_of(&port, "read-holding 17 400108 3"),
        ["555", "0", "100"]
    );
    drop(noisy);
    assert_eq!(
        values_of(&port, "read-holding 17 400108 3"),
        ["555", "0", "100"]
    );
}

#[test]
fn serve_refuses_what_it_cannot_do() {
    let output = crate::support::mbtool()
        .args(["serve", "--port", "sim"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    let output = crate::support::mbtool().args(["serve"]).output().unwrap();
    assert_eq!(output.status.code(), Some(2));
    let output = crate::support::mbtool()
        .args([
            "serve",
            "--port",
            "tcp://127.0.0.1:1",
            "--exception",
            "2@nowhere",
        ])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
}

/// `--address-base 1` counts as mbpoll's `-r` does: what one writes at number N the other
/// reads at N, at the ends of the table too, and the address column says N.
#[test]
fn address_base_one_counts_as_mbpoll_does() {
    if !peer_available("mbpoll", command_exists("mbpoll")) {
        return;
    }
    let (_server, port, tcp) = serve_tcp(&[]);
    let tcp = tcp.to_string();
    let connection = ["-m", "tcp", "-p", tcp.as_str(), "127.0.0.1"];
    let mut rng = fastrand::Rng::with_seed(26);
    // 5 or 6 digits that start with a table's digit are a reference unless --pdu-addresses.
    let numbers = [1, 2, 65535, 65536, rng.u32(3..10000), 19033, 40001];
    for (i, number) in numbers.into_iter().enumerate() {
        let value = 1000 + i;
        mbpoll(&connection, &format!("-a 17 -1 -t 4 -r {number} {value}"));
        let plain = if number > 9999 {
            "--pdu-addresses "
        } else {
            ""
        };
        let from_one = format!("--address-base 1 {plain}read-holding 17 {number} -o csv");
        let (code, csv) = run_against(&port, &from_one);
        assert_eq!(code, 0, "{from_one}: {csv}");
        let row = csv.lines().nth(1).unwrap_or_default().to_string();
        let fields: Vec<&str> = row.split(',').collect();
        assert_eq!(
            fields[1..],
            [
                number.to_string().as_str(),
                &format!("{value:04X}"),
                &value.to_string()
            ],
            "{from_one}"
        );
        assert_eq!(fields[0], format!("4{:05}", number), "{from_one}");

        let written = 2000 + i;
        let write = format!("--address-base 1 {plain}write-register 17 {number} {written}");
        assert_eq!(run_against(&port, &write).0, 0, "{write}");
        let read = mbpoll(&connection, &format!("-a 17 -1 -t 4 -r {number}"));
        assert_eq!(read, [written.to_string()], "{write}, read by mbpoll");
    }
    // Coils too, and from the environment.
    mbpoll(&connection, "-a 17 -1 -t 0 -r 500 1 0 1");
    let output = mbtool()
        .env("MBTOOL_ADDRESS_BASE", "1")
        .args(&port)
        .args(["read-coils", "17", "500", "3", "-o", "values"])
        .output()
        .expect("mbtool runs");
    assert_eq!(String::from_utf8_lossy(&output.stdout), "1\n0\n1\n");
}

/// A port another process listens on is refused with that process named, for serve and
/// for the gateway.
#[test]
fn a_taken_port_names_the_process_that_listens_on_it() {
    let (first, port_args, port) = crate::support::serve_tcp(&[]);
    for args in [
        vec![
            port_args[0].clone(),
            port_args[1].clone(),
            "serve".to_string(),
        ],
        vec![
            "--port".to_string(),
            "sim".to_string(),
            "gateway".to_string(),
            "--listen".to_string(),
            format!("tcp://127.0.0.1:{port}"),
        ],
    ] {
        let output = crate::support::mbtool().args(&args).output().unwrap();
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(1), "{stderr}");
        assert!(
            stderr.contains(&format!(
                "port {port} is taken by mbtool (pid {})",
                first.0.id()
            )),
            "{stderr}"
        );
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
    }
}
