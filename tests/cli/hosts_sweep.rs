//! `scan --hosts` over 40 addresses of 127.0.0.0/8 as a plant's network has them: `serve`
//! in the clear and over TLS, pymodbus servers that answer every unit id, listeners that
//! never answer, and addresses that refuse. The same hosts and unit ids as nmap's
//! modbus-discover finds, and never more than one connection at a time to any host,
//! counted in front of every server.

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::process::{Command as Process, Stdio};

use crate::hosts::{listening, nmap_units, serve_tls};
use crate::support::{
    command_exists, free_port, mbtool, peer_available, python_has, serve, Stopped,
};

const COUNTER: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/peers/counting_listener.py"
);
const PYMODBUS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/peers/pymodbus_slave.py");
const PKI: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/pki/");

/// A counter on `address:port`: in front of the server on `address:behind`, or, without
/// one, a listener that never answers; its report file.
fn counter(
    address: &str,
    port: u16,
    behind: Option<u16>,
    dir: &std::path::Path,
) -> (Stopped, PathBuf) {
    let report = dir.join(format!("{address}-{port}.json"));
    let mut command = Process::new("python3");
    command
        .arg(COUNTER)
        .args([address, &port.to_string()])
        .arg(&report);
    if let Some(behind) = behind {
        command.arg(behind.to_string());
    }
    let child = command.stdout(Stdio::null()).spawn().unwrap();
    (Stopped(child), report)
}

fn report(path: &PathBuf) -> serde_json::Value {
    std::fs::read_to_string(path)
        .ok()
        .and_then(|text| serde_json::from_str(&text).ok())
        .unwrap_or_else(
            || serde_json::json!({"most_at_once": 0, "accepted": 0, "closed_by_client": 0}),
        )
}

#[test]
fn forty_addresses_give_what_nmap_finds_and_never_two_connections_to_a_host() {
    if !peer_available("nmap", command_exists("nmap"))
        || !peer_available("pymodbus (Python)", python_has("pymodbus"))
    {
        return;
    }
    // 802 is below 1024: where only root may listen, the sweep is of the plain port alone.
    let tls = std::net::TcpListener::bind("127.0.3.4:802").is_ok();
    assert!(
        tls || std::env::var_os("CI").is_none(),
        "CI runs as root: 802 must be free"
    );
    let dir = tempfile::tempdir().unwrap();
    let port = free_port();
    let behind = free_port();
    let at = |address: &str, port: u16| format!("tcp://{address}:{port}");
    let mut running = Vec::new();
    let mut counted = BTreeMap::new();
    for (address, slaves) in [
        ("127.0.3.2", &["1", "5"][..]),
        ("127.0.3.3", &["200"]),
        ("127.0.3.4", &["1"]),
    ] {
        let mut args = vec!["--port".to_string(), at(address, behind), "--quiet".into()];
        for slave in slaves {
            args.extend(["--slave".to_string(), slave.to_string()]);
        }
        running.push(serve(&args.iter().map(String::as_str).collect::<Vec<_>>()));
        listening(address, behind);
        let (guard, path) = counter(address, port, Some(behind), dir.path());
        running.push(guard);
        counted.insert(format!("{address}:{port}"), path);
    }
    for address in ["127.0.3.6", "127.0.3.7"] {
        running.push(Stopped(
            Process::new("python3")
                .args([PYMODBUS, "--framer", "socket", "--tcp", &behind.to_string()])
                .args(["--address", address, "--every-unit"])
                .stdout(Stdio::null())
                .stderr(Stdio::null())
                .spawn()
                .unwrap(),
        ));
        listening(address, behind);
        let (guard, path) = counter(address, port, Some(behind), dir.path());
        running.push(guard);
        counted.insert(format!("{address}:{port}"), path);
    }
    for address in ["127.0.3.20", "127.0.3.21", "127.0.3.22"] {
        let (guard, path) = counter(address, port, None, dir.path());
        running.push(guard);
        counted.insert(format!("{address}:{port}"), path);
    }
    let tls_behind = free_port();
    if tls {
        running.push(serve_tls(&format!("127.0.3.4:{tls_behind}"), "3"));
        listening("127.0.3.4", tls_behind);
        let (guard, path) = counter("127.0.3.4", 802, Some(tls_behind), dir.path());
        running.push(guard);
        counted.insert("127.0.3.4:802".into(), path);
    }
    for place in counted.keys() {
        let (address, port) = place.split_once(':').unwrap();
        listening(address, port.parse().unwrap());
    }
    std::thread::sleep(std::time::Duration::from_millis(300));
    let before: BTreeMap<String, serde_json::Value> = counted
        .iter()
        .map(|(place, path)| (place.clone(), report(path)))
        .collect();

    let mut sweep = mbtool();
    let ports = if tls {
        format!("{port},802")
    } else {
        port.to_string()
    };
    sweep
        .args(["scan", "--hosts", "127.0.3.1-40", "--tcp-port", &ports])
        .args([
            "--ids",
            "1-246",
            "--probe",
            "id",
            "--timeout",
            "500ms",
            "-o",
            "json",
        ]);
    if tls {
        for (option, name) in [
            ("--cert", "operator.pem"),
            ("--key", "operator.key"),
            ("--ca", "plant-ca.pem"),
        ] {
            sweep.args([option, &format!("{PKI}{name}")]);
        }
        sweep.args(["--tls-server-name", "localhost"]);
    }
    let output = sweep.output().unwrap();
    assert_eq!(output.status.code(), Some(0), "{output:?}");
    let rows: Vec<serde_json::Value> = String::from_utf8_lossy(&output.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(rows.len(), if tls { 80 } else { 40 });
    let units_on = |wanted: u16| -> BTreeMap<String, Vec<u64>> {
        rows.iter()
            .filter(|row| row["port"] == wanted)
            .filter_map(|row| {
                let mut units: Vec<u64> = row["units"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|u| u["unit"].as_u64().unwrap())
                    // nmap asks 1-246: 0 and 255 are mbtool's own first askings.
                    .filter(|id| (1..=246).contains(id))
                    .collect();
                units.sort_unstable();
                (!units.is_empty()).then(|| (row["host"].as_str().unwrap().to_string(), units))
            })
            .collect()
    };
    // Every server saw one connection at a time, each closed by the sweep with a FIN.
    std::thread::sleep(std::time::Duration::from_millis(500));
    for (place, path) in &counted {
        let after = report(path);
        let opened =
            after["accepted"].as_u64().unwrap() - before[place]["accepted"].as_u64().unwrap();
        let closed = after["closed_by_client"].as_u64().unwrap()
            - before[place]["closed_by_client"].as_u64().unwrap();
        assert_eq!(after["most_at_once"], 1, "{place}: {after}");
        assert!(opened >= 1 && closed == opened, "{place}: {after}");
    }
    // nmap after: its own connections are none of the sweep's.
    let theirs = nmap_units(port, &["127.0.3.1-40"]);
    let ours = units_on(port);
    assert_eq!(ours, theirs);
    assert_eq!(ours.len(), 5, "{ours:?}");
    assert_eq!(ours["127.0.3.2"], [1, 5]);
    assert_eq!(ours["127.0.3.6"].len(), 246);
    // pymodbus answers every id alike: said so, the ids listed in JSON all the same.
    let every = rows
        .iter()
        .find(|r| r["host"] == "127.0.3.6" && r["port"] == port)
        .unwrap();
    assert_eq!(every["ignores_unit_id"], true);
    let one = rows
        .iter()
        .find(|r| r["host"] == "127.0.3.2" && r["port"] == port)
        .unwrap();
    assert!(one.get("ignores_unit_id").is_none(), "{one}");
    for silent in ["127.0.3.20", "127.0.3.21", "127.0.3.22"] {
        let row = rows
            .iter()
            .find(|r| r["host"] == silent && r["port"] == port)
            .unwrap();
        assert_eq!(
            (&row["reach"], &row["modbus"]),
            (&"open".into(), &false.into()),
            "{row}"
        );
    }
    let refused = rows
        .iter()
        .filter(|r| r["port"] == port && r["reach"] == "refused")
        .count();
    assert_eq!(refused, 40 - 8);
    if tls {
        let over_tls = units_on(802);
        assert_eq!(over_tls.keys().collect::<Vec<_>>(), ["127.0.3.4"]);
        assert_eq!(over_tls["127.0.3.4"], [3]);
    }
    drop(running);
}

/// A host named twice (its address and its name) still gets one connection at a time; a
/// gateway silent for 0, 1 and 255 is given up, unless --all asks every id.
#[test]
fn a_host_named_twice_gets_one_connection_and_all_asks_a_silent_gateway() {
    let dir = tempfile::tempdir().unwrap();
    let port = free_port();
    let (_silent, path) = counter("127.0.0.1", port, None, dir.path());
    listening("127.0.0.1", port);
    // The probe's connection is seen closed before the sweep begins: else, on a loaded
    // machine, it is counted open beside the sweep's first.
    let before = (0..100)
        .map(|_| {
            std::thread::sleep(std::time::Duration::from_millis(50));
            report(&path)
        })
        .find(|seen| seen["accepted"] == 1 && seen["closed_by_client"] == 1)
        .expect("the probe's connection is seen closed");
    // The device has as long as the timeout (up to a second) to close its side after the
    // sweep's FIN before the next connection; 200 ms was too short for the counter's
    // thread on a loaded machine, which then saw the next connection first.
    let output = mbtool()
        .args(["scan", "--hosts", "127.0.0.1,localhost", "--tcp-port"])
        .args([&port.to_string(), "--timeout", "1s", "-o", "json"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(3), "{output:?}");
    std::thread::sleep(std::time::Duration::from_millis(300));
    let after = report(&path);
    assert_eq!(after["most_at_once"], 1, "{after}");
    assert_eq!(
        after["accepted"].as_u64().unwrap() - before["accepted"].as_u64().unwrap(),
        2
    );

    let gateway_port = free_port();
    let script = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/peers/one_unit_gateway.py"
    );
    let _gateway = Stopped(
        Process::new("python3")
            .args([script, "127.0.0.1", &gateway_port.to_string(), "7"])
            .spawn()
            .unwrap(),
    );
    listening("127.0.0.1", gateway_port);
    let sweep = |extra: &[&str]| -> serde_json::Value {
        let output = mbtool()
            .args([
                "scan",
                "--hosts",
                "127.0.0.1",
                "--tcp-port",
                &gateway_port.to_string(),
            ])
            .args(["--ids", "5-8", "--timeout", "200ms", "-o", "json"])
            .args(extra)
            .output()
            .unwrap();
        serde_json::from_slice(&output.stdout).unwrap()
    };
    let given_up = sweep(&[]);
    assert_eq!(
        (&given_up["modbus"], &given_up["others_not_asked"]),
        (&false.into(), &true.into())
    );
    let all = sweep(&["--all"]);
    assert_eq!(all["units"][0]["unit"], 7, "{all}");
    assert_eq!(all["units"][0]["server_id"], "GW-7", "{all}");
}

/// A port where something else than Modbus listens is told apart from a silent one: bytes
/// that are no answer (a web server), a connection closed or reset.
#[test]
fn what_answers_instead_of_modbus_is_told() {
    let port = free_port();
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/peers/not_modbus.py");
    let mut running = Vec::new();
    for (address, mode) in [
        ("127.0.6.2", "garbage"),
        ("127.0.6.3", "close"),
        ("127.0.6.4", "reset"),
    ] {
        running.push(Stopped(
            Process::new("python3")
                .args([script, mode, address, &port.to_string()])
                .spawn()
                .unwrap(),
        ));
        listening(address, port);
    }
    let output = mbtool()
        .args([
            "scan",
            "--hosts",
            "127.0.6.2-4",
            "--tcp-port",
            &port.to_string(),
        ])
        .args(["--timeout", "300ms", "-o", "json"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(3), "{output:?}");
    let instead: Vec<String> = String::from_utf8_lossy(&output.stdout)
        .lines()
        .map(|l| serde_json::from_str::<serde_json::Value>(l).unwrap()["instead"].to_string())
        .collect();
    assert_eq!(instead, ["\"garbage\"", "\"closed\"", "\"closed\""]);
    let table = mbtool()
        .args([
            "scan",
            "--hosts",
            "127.0.6.2",
            "--tcp-port",
            &port.to_string(),
        ])
        .args(["--timeout", "300ms", "-v"])
        .output()
        .unwrap();
    assert!(
        String::from_utf8_lossy(&table.stdout).contains("no: bytes that are no Modbus answer"),
        "{table:?}"
    );
    // -v shows each frame with the host and port it went to.
    let frames = String::from_utf8_lossy(&table.stderr);
    assert!(
        frames.contains(&format!(
            "] 127.0.6.2:{port} > 00 01 00 00 00 06 00 03 00 00 00 01\n"
        )),
        "{frames}"
    );
    drop(running);
}
