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
pub(crate) fn listening(address: &str, port: u16) {
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

/// `serve` over TLS on `place` (`ADDRESS:PORT`) with the server certificate of docs/pki,
/// standing for `slave`.
pub(crate) fn serve_tls(place: &str, slave: &str) -> Stopped {
    let file = |name: &str| format!("{}/docs/pki/{name}", env!("CARGO_MANIFEST_DIR"));
    serve(&[
        "--port",
        &format!("tls://{place}"),
        "--cert",
        &file("server.pem"),
        "--key",
        &file("server.key"),
        "--ca",
        &file("plant-ca.pem"),
        "--slave",
        slave,
        "--quiet",
    ])
}

/// nmap's modbus-discover (aggressive: every sid 1-246, asked with function 17) over the
/// same hosts: the same hosts with Modbus and the same unit ids, where nmap's units leave
/// out the sids a gateway (or a server standing for one) answers 0A or 0B.
pub(crate) fn nmap_units(
    port: u16,
    hosts: &[&str],
) -> std::collections::BTreeMap<String, Vec<u64>> {
    let output = Process::new("nmap")
        .args(["-n", "-Pn", "-p", &port.to_string()])
        .args([
            "--script",
            "+modbus-discover",
            "--script-args",
            "modbus-discover.aggressive=true",
        ])
        // A host that takes the connection and never answers would cost 2 s an id.
        .args(["--script-timeout", "15s", "-oX", "-"])
        .args(hosts)
        .output()
        .unwrap();
    assert!(output.status.success(), "{output:?}");
    let xml = String::from_utf8_lossy(&output.stdout);
    let mut found = std::collections::BTreeMap::new();
    for host in xml.split("<host ").skip(1) {
        let address = host
            .split("<address addr=\"")
            .nth(1)
            .and_then(|rest| rest.split('"').next())
            .unwrap()
            .to_string();
        let mut units = Vec::new();
        for sid in host.split("<table key=\"sid 0x").skip(1) {
            let id = u64::from_str_radix(sid.split('"').next().unwrap(), 16).unwrap();
            let body = sid.split("</table>").next().unwrap();
            if !body.contains("GATEWAY") {
                units.push(id);
            }
        }
        if !units.is_empty() {
            found.insert(address, units);
        }
    }
    found
}

#[test]
fn a_sweep_finds_what_nmap_s_modbus_discover_finds() {
    if !crate::support::peer_available("nmap", crate::support::command_exists("nmap"))
        || !crate::support::peer_available(
            "pymodbus (Python)",
            crate::support::python_has("pymodbus"),
        )
    {
        return;
    }
    let port = crate::support::free_port();
    let at = |address: &str| format!("tcp://{address}:{port}");
    let _one = serve(&["--port", &at("127.0.0.2"), "--slave", "1", "--slave", "5"]);
    let _two = serve(&["--port", &at("127.0.0.3"), "--slave", "200"]);
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/peers/pymodbus_slave.py");
    let _pymodbus = Stopped(
        Process::new("python3")
            .args([script, "--framer", "socket", "--tcp", &port.to_string()])
            .args(["--address", "127.0.0.6", "--every-unit"])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap(),
    );
    for address in ["127.0.0.2", "127.0.0.3", "127.0.0.6"] {
        listening(address, port);
    }
    let hosts = ["127.0.0.1-3", "127.0.0.5-7"];
    let theirs = nmap_units(port, &hosts);
    let output = mbtool()
        .args([
            "scan",
            "--hosts",
            &hosts.join(","),
            "--tcp-port",
            &port.to_string(),
        ])
        .args([
            "--ids",
            "1-246",
            "--probe",
            "id",
            "--timeout",
            "500ms",
            "--pause",
            "0s",
        ])
        .args(["-o", "json"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(0), "{output:?}");
    let ours: std::collections::BTreeMap<String, Vec<u64>> =
        String::from_utf8_lossy(&output.stdout)
            .lines()
            .map(|l| serde_json::from_str::<serde_json::Value>(l).unwrap())
            .filter_map(|host| {
                let units: Vec<u64> = host["units"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|u| u["unit"].as_u64().unwrap())
                    // nmap asks 1-246: 0 and 255 are mbtool's own first askings.
                    .filter(|id| (1..=246).contains(id))
                    .collect();
                let mut units = units;
                units.sort_unstable();
                (!units.is_empty()).then(|| (host["host"].as_str().unwrap().to_string(), units))
            })
            .collect();
    assert_eq!(ours, theirs);
    assert_eq!(ours["127.0.0.2"], [1, 5]);
    assert_eq!(ours["127.0.0.3"], [200]);
    assert_eq!(ours["127.0.0.6"].len(), 246);
}

/// Port 802 is asked over TLS with this end's certificates, beside 502 in the clear;
/// without them it is told open, and that certificates are wanted.
#[test]
fn port_802_is_asked_over_tls() {
    // 802 is a port below 1024: only root may listen on it.
    if std::net::TcpListener::bind("127.0.0.12:802").is_err() {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI runs as root: 802 must be free"
        );
        eprintln!("skipping: only root may listen on port 802");
        return;
    }
    let pki = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/pki/");
    let file = |name: &str| format!("{pki}{name}");
    let _tls = serve_tls("127.0.0.12:802", "3");
    let _plain = serve(&["--port", "tcp://127.0.0.12:502", "--slave", "4"]);
    listening("127.0.0.12", 802);
    listening("127.0.0.12", 502);
    let sweep = |tls: &[String]| -> Vec<serde_json::Value> {
        let output = mbtool()
            .args([
                "scan",
                "--hosts",
                "127.0.0.12",
                "--tcp-port",
                "502,802",
                "--ids",
                "3,4",
            ])
            .args(["--timeout", "500ms", "-o", "json"])
            .args(tls)
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(0), "{output:?}");
        String::from_utf8_lossy(&output.stdout)
            .lines()
            .map(|l| serde_json::from_str(l).unwrap())
            .collect()
    };
    let units = |host: &serde_json::Value| -> Vec<u64> {
        host["units"]
            .as_array()
            .unwrap()
            .iter()
            .map(|u| u["unit"].as_u64().unwrap())
            .collect()
    };
    let certificates: Vec<String> = [
        ("--cert", "operator.pem"),
        ("--key", "operator.key"),
        ("--ca", "plant-ca.pem"),
    ]
    .iter()
    .flat_map(|(option, name)| [option.to_string(), file(name)])
    .chain(["--tls-server-name".to_string(), "localhost".to_string()])
    .collect();
    let hosts = sweep(&certificates);
    assert_eq!(units(&hosts[0]), [0, 255, 4]);
    assert_eq!(units(&hosts[1]), [0, 255, 3]);
    // Without the name its certificate holds, the handshake fails: the host took the
    // connection, and the reason is told.
    let hosts = sweep(&certificates[..6]);
    assert_eq!(hosts[1]["reach"], "open", "{}", hosts[1]);
    assert!(
        hosts[1]["tls_failed"]
            .as_str()
            .unwrap()
            .contains("certificate is not for '127.0.0.12'"),
        "{}",
        hosts[1]
    );
    let hosts = sweep(&[]);
    assert_eq!(
        (
            &hosts[1]["reach"],
            &hosts[1]["modbus"],
            &hosts[1]["instead"]
        ),
        (&"open".into(), &false.into(), &"tls".into()),
        "{}",
        hosts[1]
    );
}

/// A /16 of hosts that refuse is swept and shown in seconds: no step of it grows faster
/// than the hosts.
#[test]
fn a_sweep_of_a_slash_16_ends_in_seconds() {
    let port = crate::support::free_port();
    let started = Instant::now();
    let output = mbtool()
        .args([
            "scan",
            "--hosts",
            "127.1.0.0/16",
            "--tcp-port",
            &port.to_string(),
            "-o",
            "csv",
        ])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(3), "{output:?}");
    assert_eq!(
        String::from_utf8_lossy(&output.stdout).lines().count(),
        65535
    );
    assert!(
        started.elapsed() < Duration::from_secs(20),
        "{:?}",
        started.elapsed()
    );
}
