//! `scan --hosts`: a sweep of addresses of 127.0.0.0/8 where some run `serve`, one listens
//! and never answers, and the others refuse; the hosts and unit ids found, and the
//! politeness the sweep promises, counted on a listener.

use std::process::{Command as Process, Stdio};
use std::time::{Duration, Instant};

use crate::support::{mbtool, serve, Stopped};

const LISTENER: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/peers/counting_listener.py"
);

/// Waits until `address:port` takes a connection.
fn listening(address: &str, port: u16) {
    let deadline = Instant::now() + Duration::from_secs(10);
    while std::net::TcpStream::connect((address, port)).is_err() {
        assert!(
            Instant::now() < deadline,
            "nothing listens on {address}:{port}"
        );
        std::thread::sleep(Duration::from_millis(50));
    }
}

#[test]
fn a_sweep_finds_the_hosts_and_units_that_answer_and_asks_politely() {
    let port = crate::support::free_port();
    let at = |address: &str| format!("tcp://{address}:{port}");
    let _one = serve(&["--port", &at("127.0.0.2"), "--slave", "1"]);
    let _two = serve(&["--port", &at("127.0.0.3"), "--slave", "1", "--slave", "5"]);
    listening("127.0.0.2", port);
    listening("127.0.0.3", port);
    let report = tempfile::NamedTempFile::new().unwrap();
    let _silent = Stopped(
        Process::new("python3")
            .arg(LISTENER)
            .args(["127.0.0.4", &port.to_string()])
            .arg(report.path())
            .stdout(Stdio::null())
            .spawn()
            .unwrap(),
    );
    listening("127.0.0.4", port);
    // The check above was one connection: it is closed, counted, and left out.
    std::thread::sleep(Duration::from_millis(200));
    let before: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(report.path()).unwrap()).unwrap();
    let output = mbtool()
        .args([
            "scan",
            "--hosts",
            "127.0.0.1-8",
            "--tcp-port",
            &port.to_string(),
        ])
        .args([
            "--ids",
            "5",
            "--timeout",
            "300ms",
            "--pause",
            "5ms",
            "-o",
            "json",
        ])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(0), "{output:?}");
    let hosts: Vec<serde_json::Value> = String::from_utf8_lossy(&output.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let host = |address: &str| hosts.iter().find(|h| h["host"] == address).unwrap();
    let units = |address: &str| -> Vec<u64> {
        host(address)["units"]
            .as_array()
            .unwrap()
            .iter()
            .map(|u| u["unit"].as_u64().unwrap())
            .collect()
    };
    assert_eq!(hosts.len(), 8);
    // Unit ids 0 and 255 mean "the device here"; 1 and 5 as each serve has them.
    assert_eq!(units("127.0.0.2"), [0, 1, 255]);
    assert_eq!(units("127.0.0.3"), [0, 1, 255, 5]);
    assert_eq!(
        host("127.0.0.2")["units"][1]["identification"],
        "mbtool mbtool-sim 0.1.0"
    );
    assert_eq!(
        (&host("127.0.0.4")["reach"], &host("127.0.0.4")["modbus"]),
        (&"open".into(), &false.into())
    );
    for refused in ["127.0.0.1", "127.0.0.5", "127.0.0.8"] {
        assert_eq!(host(refused)["reach"], "refused", "{refused}");
    }
    // The silent host saw one connection at a time, closed by the sweep with a FIN.
    std::thread::sleep(Duration::from_millis(300));
    let after: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(report.path()).unwrap()).unwrap();
    assert_eq!(after["most_at_once"], 1, "{after}");
    assert_eq!(
        after["closed_by_client"].as_u64().unwrap() - before["closed_by_client"].as_u64().unwrap(),
        1,
        "{after}"
    );
}

#[test]
fn a_sweep_that_finds_nothing_says_so_and_bad_hosts_are_refused() {
    let port = crate::support::free_port();
    let output = mbtool()
        .args([
            "scan",
            "--hosts",
            "127.0.0.10-12",
            "--tcp-port",
            &port.to_string(),
        ])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(3), "{output:?}");
    assert!(String::from_utf8_lossy(&output.stdout)
        .contains("3 host ports asked: 0 with Modbus, 0 open, 3 refused"));
    for (args, message) in [
        (
            vec!["scan", "--hosts", "10.0.0.0/8"],
            "mbtool: --hosts 10.0.0.0/8: more than 65536 hosts",
        ),
        (
            vec!["scan", "--hosts", "10.0.0.9-3"],
            "mbtool: --hosts 10.0.0.9-3: the first address",
        ),
        (
            vec!["--port", "sim", "scan", "--hosts", "127.0.0.1"],
            "mbtool: --hosts sweeps a network: leave out --port",
        ),
        (vec!["scan", "--tcp-port", "502"], "mbtool: "),
    ] {
        let output = mbtool().args(&args).output().unwrap();
        assert_eq!(output.status.code(), Some(2), "{args:?}: {output:?}");
        assert!(
            String::from_utf8_lossy(&output.stderr).starts_with(message),
            "{args:?}: {output:?}"
        );
    }
}
