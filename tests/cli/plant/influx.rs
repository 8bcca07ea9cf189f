//! `poll --influx` and `-o influx`: InfluxDB line protocol, and Debian's InfluxDB server
//! written to, restarted and read back.

use std::process::{Command as Process, Stdio};
use std::time::{Duration, Instant};

use super::*;

#[test]
fn influx_is_polls_format_and_values_is_not() {
    let (_dir, path) = plant(&[device("pump", "sim", 17, "100ms")]);
    for (args, said) in [
        (vec!["poll", &path, "-o", "values"], "mbtool: --output values: give a format: table, json, csv or influx\n"),
        (
            vec!["--port", "sim", "read-holding", "17", "1", "-o", "influx"],
            "mbtool: --output influx is poll's (mbtool poll PLANT -o influx): give table, json, values or csv\n",
        ),
    ] {
        let output = mbtool().args(&args).output().unwrap();
        assert_eq!(output.status.code(), Some(2), "{args:?}");
        assert_eq!(String::from_utf8_lossy(&output.stderr), said);
    }
    let help = mbtool().args(["poll", "-h"]).output().unwrap();
    let help = String::from_utf8_lossy(&help.stdout);
    assert!(
        help.contains("[possible values: table, json, csv, influx]"),
        "{help}"
    );
}

/// An InfluxDB 1.x server of Debian's on 127.0.0.1, its files in a folder of its own,
/// stopped on drop; `None` (skipped) where influxd is missing outside CI.
struct Influx {
    server: Option<crate::support::Stopped>,
    /// The admin's user and password, where the server asks for a login.
    login: Option<(&'static str, &'static str)>,
    config: std::path::PathBuf,
    port: u16,
    _dir: tempfile::TempDir,
}

impl Influx {
    fn start() -> Option<Influx> {
        Influx::start_with(None)
    }

    /// A server that asks for `login` (its admin) where given.
    fn start_with(login: Option<(&'static str, &'static str)>) -> Option<Influx> {
        if !crate::support::peer_available("influxd", crate::support::command_exists("influxd")) {
            return None;
        }
        let dir = tempfile::tempdir().unwrap();
        let (port, rpc) = (free_port(), free_port());
        let at = |name: &str| dir.path().join(name).display().to_string();
        let config = dir.path().join("influxdb.conf");
        std::fs::write(
            &config,
            format!(
                "reporting-disabled = true\nbind-address = \"127.0.0.1:{rpc}\"\n[meta]\n  dir = \"{}\"\n[data]\n  dir = \"{}\"\n  wal-dir = \"{}\"\n  query-log-enabled = false\n[http]\n  bind-address = \"127.0.0.1:{port}\"\n  log-enabled = false\n  auth-enabled = {}\n[monitor]\n  store-enabled = false\n",
                at("meta"),
                at("data"),
                at("wal"),
                login.is_some()
            ),
        )
        .unwrap();
        let mut influx = Influx {
            server: None,
            login,
            config,
            port,
            _dir: dir,
        };
        influx.run();
        if let Some((user, password)) = login {
            // The first user, an admin, is made without a login.
            influx.query(&format!(
                "CREATE USER {user} WITH PASSWORD '{password}' WITH ALL PRIVILEGES"
            ));
        }
        influx.query("CREATE DATABASE plant");
        Some(influx)
    }

    /// Starts the server (again, on the same files), and waits until it answers.
    fn run(&mut self) {
        let child = Process::new("influxd")
            .arg("-config")
            .arg(&self.config)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        self.server = Some(crate::support::Stopped(child));
        let deadline = Instant::now() + Duration::from_secs(20);
        while ureq::get(format!("http://127.0.0.1:{}/ping", self.port))
            .call()
            .is_err()
        {
            assert!(Instant::now() < deadline, "influxd did not start");
            std::thread::sleep(Duration::from_millis(100));
        }
    }

    fn stop(&mut self) {
        self.server = None;
    }

    fn write_url(&self) -> String {
        format!("http://127.0.0.1:{}/write?db=plant", self.port)
    }

    fn query(&self, q: &str) -> serde_json::Value {
        let login = match self.login.filter(|_| !q.starts_with("CREATE USER")) {
            Some((user, password)) => format!("&u={user}&p={password}"),
            None => String::new(),
        };
        let text = ureq::post(format!(
            "http://127.0.0.1:{}/query?db=plant&epoch=ns{login}",
            self.port
        ))
        .send_form([("q", q)])
        .unwrap()
        .body_mut()
        .read_to_string()
        .unwrap();
        serde_json::from_str(&text).unwrap()
    }

    /// Every row of `modbus`, as line protocol would write it: device, fields, time.
    fn rows(&self) -> Vec<String> {
        let result = self.query("SELECT * FROM modbus");
        let series = &result["results"][0]["series"][0];
        let columns: Vec<&str> = series["columns"]
            .as_array()
            .map(|c| c.iter().map(|c| c.as_str().unwrap()).collect())
            .unwrap_or_default();
        let at = |name: &str| columns.iter().position(|c| *c == name).unwrap();
        let mut rows: Vec<String> = series["values"]
            .as_array()
            .map(Vec::as_slice)
            .unwrap_or_default()
            .iter()
            .map(|row| {
                format!(
                    "modbus,device={},slave={} speed={}i,level={}i,flow={}i {}",
                    row[at("device")].as_str().unwrap(),
                    row[at("slave")].as_str().unwrap(),
                    row[at("speed")],
                    row[at("level")],
                    row[at("flow")],
                    row[at("time")]
                )
            })
            .collect();
        rows.sort();
        rows
    }
}

/// mbtool poll of the example plant, its rows on stdout as line protocol and written to
/// the InfluxDB of `url`, `during` run meanwhile; (stdout's lines sorted, stderr).
fn poll_into(url: &str, args: &[&str], during: impl FnOnce()) -> (Vec<String>, String) {
    let child = Process::new(assert_cmd::cargo::cargo_bin("mbtool"))
        .args([
            "poll",
            "examples/plant.yaml",
            "-o",
            "influx",
            "--influx",
            url,
        ])
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    during();
    let output = child.wait_with_output().unwrap();
    let mut lines: Vec<String> = String::from_utf8_lossy(&output.stdout)
        .lines()
        .map(String::from)
        .collect();
    lines.sort();
    (lines, String::from_utf8_lossy(&output.stderr).into_owned())
}

#[test]
fn what_influxdb_was_written_reads_back_exact() {
    let Some(influx) = Influx::start() else {
        return;
    };
    let (lines, stderr) = poll_into(&influx.write_url(), &["--for", "1s"], || ());
    assert!(lines.len() >= 4, "{lines:?}");
    // Values and nanosecond times, as the line protocol on stdout said them.
    assert_eq!(influx.rows(), lines, "{stderr}");
    assert!(
        stderr.contains(&format!("mbtool: InfluxDB: {} rows written", lines.len())),
        "{stderr}"
    );
}

/// A 1.x server that asks for a login takes `INFLUX_TOKEN=USER:PASSWORD`, and refuses a
/// wrong one, told.
#[test]
fn an_influxdb_that_asks_for_a_login_takes_the_token_as_user_and_password() {
    let Some(influx) = Influx::start_with(Some(("bob", "s3cret"))) else {
        return;
    };
    let poll = |token: &str| {
        mbtool()
            .args([
                "poll",
                "examples/plant.yaml",
                "--for",
                "500ms",
                "-o",
                "influx",
            ])
            .args(["--influx", &influx.write_url()])
            .env("INFLUX_TOKEN", token)
            .output()
            .unwrap()
    };
    let output = poll("bob:s3cret");
    let stderr = String::from_utf8_lossy(&output.stderr);
    let mut lines: Vec<String> = String::from_utf8_lossy(&output.stdout)
        .lines()
        .map(String::from)
        .collect();
    lines.sort();
    assert_eq!(influx.rows(), lines, "{stderr}");
    let output = poll("bob:wrong");
    let stderr = String::from_utf8_lossy(&output.stderr);
    // Told once, in the server's words, however many batches it refuses.
    assert_eq!(stderr.matches("with status 401").count(), 1, "{stderr}");
    assert!(
        stderr.contains("with status 401 ({\"error\":\"authorization failed\"})"),
        "{stderr}"
    );
}

#[test]
fn an_influxdb_that_restarts_loses_nothing_within_the_buffer_and_the_overflow_is_counted() {
    let Some(mut influx) = Influx::start() else {
        return;
    };
    let url = influx.write_url();
    let (lines, stderr) = poll_into(&url, &["--for", "4s"], || {
        std::thread::sleep(Duration::from_millis(800));
        influx.stop();
        std::thread::sleep(Duration::from_millis(1500));
        influx.run();
    });
    assert!(stderr.contains("does not take rows"), "{stderr}");
    assert!(stderr.contains("takes rows again"), "{stderr}");
    assert_eq!(influx.rows(), lines, "{stderr}");
    // A buffer of 3 rows: what came while the server was down past them is dropped,
    // counted, and the rest is there.
    influx.query("DROP SERIES FROM modbus");
    let (lines, stderr) = poll_into(&url, &["--for", "4s", "--buffer", "3"], || {
        std::thread::sleep(Duration::from_millis(800));
        influx.stop();
        std::thread::sleep(Duration::from_millis(1500));
        influx.run();
    });
    let dropped: usize = stderr
        .lines()
        .flat_map(|line| line.split(", "))
        .find_map(|part| {
            part.strip_suffix(
                " dropped while it was down (the buffer holds 3 rows; --buffer sets it)",
            )
        })
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("{stderr}"));
    assert!(dropped > 0, "{stderr}");
    let rows = influx.rows();
    assert_eq!(rows.len() + dropped, lines.len(), "{stderr}");
    assert!(rows.iter().all(|row| lines.contains(row)), "{stderr}");
}

/// A stand-in for InfluxDB 2.x's write API, which has no Debian package: it answers 204
/// as the server does, and hands over each request's head and body.
fn recording_server() -> (u16, std::sync::mpsc::Receiver<(String, String)>) {
    use std::io::{BufRead, BufReader, Read, Write};
    let listener = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    let port = listener.local_addr().unwrap().port();
    let (sender, requests) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        for stream in listener.incoming().map_while(Result::ok) {
            let mut reader = BufReader::new(stream);
            let mut head = String::new();
            while reader.read_line(&mut head).is_ok_and(|n| n > 2) {}
            let length = head
                .lines()
                .find_map(|l| {
                    l.to_ascii_lowercase()
                        .strip_prefix("content-length: ")?
                        .parse()
                        .ok()
                })
                .unwrap_or(0);
            let mut body = vec![0; length];
            let _ = reader.read_exact(&mut body);
            let _ = reader
                .get_mut()
                .write_all(b"HTTP/1.1 204 No Content\r\nConnection: close\r\n\r\n");
            let _ = sender.send((head, String::from_utf8_lossy(&body).into_owned()));
        }
    });
    (port, requests)
}

#[test]
fn the_2x_api_is_written_with_its_token_and_refused_without_one() {
    let (port, requests) = recording_server();
    let url = format!("http://127.0.0.1:{port}/api/v2/write?org=site&bucket=plant");
    let output = mbtool()
        .args([
            "poll",
            "examples/plant.yaml",
            "--for",
            "600ms",
            "--influx",
            &url,
        ])
        .env("INFLUX_TOKEN", "t0ken==")
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(0), "{stderr}");
    let polls = String::from_utf8_lossy(&output.stdout).lines().count();
    let mut lines = Vec::new();
    for (head, body) in requests.try_iter() {
        assert!(
            head.starts_with("POST /api/v2/write?org=site&bucket=plant HTTP/1.1\r\n"),
            "{head}"
        );
        let head = head.to_ascii_lowercase();
        assert!(
            head.contains("\r\nauthorization: token t0ken==\r\n"),
            "{head}"
        );
        lines.extend(body.lines().map(String::from));
    }
    assert_eq!(lines.len(), polls, "{lines:?}\n{stderr}");
    assert!(
        lines.iter().all(|l| l.starts_with("modbus,device=pump3")
            && l.contains(" speed=555i,level=0i,flow=100i ")),
        "{lines:?}"
    );
    assert!(
        stderr.contains(&format!("InfluxDB: {polls} rows written")),
        "{stderr}"
    );

    let output = mbtool()
        .args(["poll", "examples/plant.yaml", "--influx", &url])
        .env_remove("INFLUX_TOKEN")
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&output.stderr),
        format!("mbtool: --influx {url}: the 2.x API needs a token: set INFLUX_TOKEN\n")
    );
}
