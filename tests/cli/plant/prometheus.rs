//! `poll --metrics`: what promtool and a Prometheus server read of it.

use std::process::{Command as Process, Stdio};
use std::time::{Duration, Instant};

use super::*;

/// mbtool poll of the example plant in the background, serving metrics on a free port.
fn poll_with_metrics(duration: &str) -> (crate::support::Stopped, u16) {
    let port = free_port();
    let child = Process::new(assert_cmd::cargo::cargo_bin("mbtool"))
        .args(["poll", "examples/plant.yaml", "--for", duration])
        .args(["--metrics", &format!("127.0.0.1:{port}")])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let poller = crate::support::Stopped(child);
    assert!(crate::support::wait_for_listener(
        port,
        Duration::from_secs(10)
    ));
    (poller, port)
}

fn get(url: &str) -> String {
    ureq::get(url)
        .call()
        .unwrap()
        .body_mut()
        .read_to_string()
        .unwrap()
}

#[test]
fn the_metrics_are_what_promtool_and_a_prometheus_server_read() {
    if !crate::support::peer_available("prometheus", crate::support::command_exists("promtool")) {
        return;
    }
    let (_poller, port) = poll_with_metrics("30s");
    std::thread::sleep(Duration::from_millis(600));
    let text = get(&format!("http://127.0.0.1:{port}/metrics"));
    assert!(
        text.contains(
            "modbus_value{device=\"pump3\",slave=\"17\",name=\"speed\",unit=\"rpm\"} 555"
        ),
        "{text}"
    );
    assert!(
        text.contains("modbus_polls_total{device=\"pump3-fast\"}"),
        "{text}"
    );
    let mut check = Process::new("promtool")
        .args(["check", "metrics"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    std::io::Write::write_all(check.stdin.as_mut().unwrap(), text.as_bytes()).unwrap();
    drop(check.stdin.take());
    let checked = check.wait_with_output().unwrap();
    assert!(checked.status.success(), "{checked:?}");
    // A Prometheus server scrapes them, and its API gives the values back.
    let dir = tempfile::tempdir().unwrap();
    let config = dir.path().join("prometheus.yml");
    std::fs::write(
        &config,
        format!("global:\n  scrape_interval: 1s\nscrape_configs:\n  - job_name: plant\n    static_configs:\n      - targets: ['127.0.0.1:{port}']\n"),
    )
    .unwrap();
    let web = free_port();
    let _server = crate::support::Stopped(
        Process::new("prometheus")
            .arg(format!("--config.file={}", config.display()))
            .arg(format!(
                "--storage.tsdb.path={}",
                dir.path().join("data").display()
            ))
            .arg(format!("--web.listen-address=127.0.0.1:{web}"))
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap(),
    );
    let query =
        format!("http://127.0.0.1:{web}/api/v1/query?query=modbus_value%7Bname%3D%22speed%22%7D");
    let deadline = Instant::now() + Duration::from_secs(25);
    let found = loop {
        let answer = ureq::get(&query)
            .call()
            .ok()
            .and_then(|mut r| r.body_mut().read_to_string().ok())
            .and_then(|text| serde_json::from_str::<serde_json::Value>(&text).ok());
        let results = answer
            .as_ref()
            .and_then(|a| a["data"]["result"].as_array().cloned())
            .unwrap_or_default();
        if results.len() == 2 || Instant::now() > deadline {
            break results;
        }
        std::thread::sleep(Duration::from_millis(250));
    };
    assert_eq!(found.len(), 2, "{found:?}");
    for result in &found {
        assert_eq!(result["value"][1], "555", "{result}");
        assert_eq!(result["metric"]["unit"], "rpm", "{result}");
    }
}

/// Clients that connect and say nothing (a hundred of them) hold back no scrape: it is
/// answered at once.
#[test]
fn idle_clients_hold_back_no_scrape() {
    let (_poller, port) = poll_with_metrics("10s");
    let idle: Vec<std::net::TcpStream> = (0..100)
        .filter_map(|_| std::net::TcpStream::connect(("127.0.0.1", port)).ok())
        .collect();
    assert_eq!(idle.len(), 100);
    let started = Instant::now();
    let text = get(&format!("http://127.0.0.1:{port}/metrics"));
    assert!(
        started.elapsed() < Duration::from_secs(1),
        "{:?}",
        started.elapsed()
    );
    assert!(text.contains("modbus_polls_total"), "{text}");
}
