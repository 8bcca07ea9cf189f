//! `poll --mqtt`: values, availability and Home Assistant discovery published to Debian's
//! mosquitto broker and read back by its own client; writes asked on `.../set` topics
//! round trip to a `serve` slave; a broker that restarts loses nothing within the buffer.

use std::io::{BufRead, BufReader};
use std::process::{Child, Command as Process, Stdio};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use super::device;
use crate::support::{
    command_exists, free_port, mbtool, mbtool_process, peer_available, serve_tcp, Stopped,
};

/// The points of the tests: writable and read-only registers, coils and inputs.
const MAP: &str = "name,ref,type,unit,access\nspeed,400108,u16,rpm,rw\nlevel,400109,u16,cm,r\nrunning,000001,bool,,rw\nalarm,100001,bool,,r\ntemp,300001,f32,°C,r\n";

/// A mosquitto broker on 127.0.0.1, keeping its sessions in a folder of its own (so that
/// a persistent subscriber keeps its messages across a restart), stopped on drop; `None`
/// (skipped) where mosquitto is missing outside CI.
struct Broker {
    server: Option<Child>,
    config: std::path::PathBuf,
    port: u16,
    _dir: tempfile::TempDir,
}

impl Broker {
    fn start() -> Option<Broker> {
        Broker::start_with(|port, _| {
            format!("listener {port} 127.0.0.1\nallow_anonymous true\npersistence true\n")
        })
    }

    /// A broker whose listener is configured by `listener`, given the port and the
    /// broker's folder, where it may write the files it names.
    fn start_with(listener: impl FnOnce(u16, &std::path::Path) -> String) -> Option<Broker> {
        let found = command_exists("mosquitto") && command_exists("mosquitto_sub");
        if !peer_available("mosquitto", found) {
            return None;
        }
        let dir = tempfile::tempdir().unwrap();
        // Started as root, mosquitto runs as its own user, which saves its sessions here.
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(dir.path(), std::fs::Permissions::from_mode(0o777)).unwrap();
        let port = free_port();
        let config = dir.path().join("mosquitto.conf");
        std::fs::write(
            &config,
            format!(
                "{}\npersistence_location {}/\nmax_queued_messages 100000\n",
                listener(port, dir.path()),
                dir.path().display()
            ),
        )
        .unwrap();
        let mut broker = Broker {
            server: None,
            config,
            port,
            _dir: dir,
        };
        broker.run();
        Some(broker)
    }

    /// Starts the broker (again, on the same files), and waits until it listens.
    fn run(&mut self) {
        let child = Process::new("mosquitto")
            .arg("-c")
            .arg(&self.config)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        self.server = Some(child);
        assert!(
            crate::support::wait_for_listener(self.port, Duration::from_secs(10)),
            "mosquitto did not start"
        );
    }

    /// Stops the broker as a service manager does (SIGTERM: it saves its sessions).
    fn stop(&mut self) {
        if let Some(mut child) = self.server.take() {
            super::send_signal(child.id(), "TERM");
            let _ = child.wait();
        }
    }

    fn url(&self) -> String {
        format!("mqtt://127.0.0.1:{}", self.port)
    }

    /// The retained messages under `filter`, as `topic payload` lines.
    fn retained(&self, filter: &str) -> Vec<String> {
        let output = Process::new("mosquitto_sub")
            .args(["-h", "127.0.0.1", "-p", &self.port.to_string()])
            .args(["-t", filter, "-v", "--retained-only", "-W", "1"])
            .output()
            .unwrap();
        let mut lines: Vec<String> = String::from_utf8_lossy(&output.stdout)
            .lines()
            .map(String::from)
            .collect();
        lines.sort();
        lines
    }

    /// A subscriber to `filter` with a persistent session (QoS 1), whose messages are
    /// collected as `topic payload` lines.
    fn subscribe(&self, filter: &str) -> Subscriber {
        let id = format!("test-{}", free_port());
        let mut child = Process::new("mosquitto_sub")
            .args(["-h", "127.0.0.1", "-p", &self.port.to_string()])
            .args(["-t", filter, "-v", "-q", "1", "-c", "-i", &id])
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        let lines = Arc::new(Mutex::new(Vec::new()));
        let stdout = child.stdout.take().unwrap();
        let collected = Arc::clone(&lines);
        std::thread::spawn(move || {
            for line in BufReader::new(stdout).lines().map_while(Result::ok) {
                collected.lock().unwrap().push(line);
            }
        });
        // Subscribed before anything is published.
        std::thread::sleep(Duration::from_millis(300));
        Subscriber {
            _client: Stopped(child),
            lines,
        }
    }

    fn publish(&self, topic: &str, payload: &str) {
        let status = Process::new("mosquitto_pub")
            .args(["-h", "127.0.0.1", "-p", &self.port.to_string()])
            .args(["-t", topic, "-m", payload, "-q", "1"])
            .status()
            .unwrap();
        assert!(status.success());
    }
}

impl Drop for Broker {
    fn drop(&mut self) {
        if let Some(mut child) = self.server.take() {
            let _ = child.kill();
            let _ = child.wait();
        }
    }
}

struct Subscriber {
    _client: Stopped,
    lines: Arc<Mutex<Vec<String>>>,
}

impl Subscriber {
    fn lines(&self) -> Vec<String> {
        self.lines.lock().unwrap().clone()
    }

    /// Waits up to `within` for a line; whether it came.
    fn wait_for(&self, line: &str, within: Duration) -> bool {
        let deadline = Instant::now() + within;
        while Instant::now() < deadline {
            if self.lines().iter().any(|l| l == line) {
                return true;
            }
            std::thread::sleep(Duration::from_millis(50));
        }
        false
    }
}

/// A plant of one device `pump` on a `serve` slave, every 100 ms.
fn pump_plant() -> (Stopped, tempfile::TempDir, String) {
    let (server, _, port) = serve_tcp(&[]);
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("map.csv"), MAP).unwrap();
    let path = dir.path().join("plant.yaml");
    let pump = device("pump", &format!("tcp://127.0.0.1:{port}"), 17, "100ms");
    std::fs::write(&path, format!("devices:\n{pump}")).unwrap();
    (server, dir, path.display().to_string())
}

fn poll_in_background(args: &[&str]) -> Child {
    mbtool_process()
        .arg("poll")
        .args(args)
        .args(["-o", "json"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap()
}

#[test]
fn values_availability_and_discovery_are_on_the_broker_as_home_assistant_reads_them() {
    let Some(broker) = Broker::start() else {
        return eprintln!("skipped: mosquitto is not installed");
    };
    let (_server, _dir, plant) = pump_plant();
    let output = mbtool()
        .args(["poll", &plant, "--for", "1s", "--mqtt", &broker.url()])
        .args([
            "--mqtt-retain",
            "--mqtt-discovery",
            "--mqtt-prefix",
            "site/",
        ])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(0), "{stderr}");
    assert!(stderr.contains("mbtool: MQTT: "), "{stderr}");
    // The last values, retained; the device answered; mbtool said it ended.
    assert_eq!(
        broker.retained("site/#"),
        [
            "site/pump/alarm 0",
            "site/pump/available online",
            "site/pump/level 0",
            "site/pump/running 0",
            "site/pump/speed 555",
            "site/pump/temp 0",
            "site/status offline",
        ]
    );
    // Discovery: a component a point, as Home Assistant's own schemas read them.
    let discovery = broker.retained("homeassistant/#");
    assert_eq!(discovery.len(), 5, "{discovery:?}");
    let configs: Vec<(String, serde_json::Value)> = discovery
        .iter()
        .map(|line| {
            let (topic, payload) = line.split_once(' ').unwrap();
            (topic.to_string(), serde_json::from_str(payload).unwrap())
        })
        .collect();
    let config = |component: &str, name: &str| {
        let topic = format!("homeassistant/{component}/mbtool_pump_{name}/config");
        configs
            .iter()
            .find(|(t, _)| *t == topic)
            .map(|(_, c)| c.clone())
            .unwrap_or_else(|| panic!("no {topic} in {discovery:?}"))
    };
    let speed = config("number", "speed");
    assert_eq!(speed["command_topic"], "site/pump/speed/set");
    assert_eq!(speed["state_topic"], "site/pump/speed");
    assert_eq!(
        (speed["min"].as_f64(), speed["max"].as_f64()),
        (Some(0.0), Some(65535.0))
    );
    assert_eq!(config("sensor", "temp")["unit_of_measurement"], "°C");
    assert_eq!(
        config("switch", "running")["command_topic"],
        "site/pump/running/set"
    );
    assert!(config("binary_sensor", "alarm")
        .get("command_topic")
        .is_none());
    assert!(config("sensor", "level").get("command_topic").is_none());
    home_assistant_reads(&discovery);
}

/// Each discovery message read by Home Assistant's MQTT schemas, where its virtual
/// environment is (tests/run.sh makes it).
fn home_assistant_reads(discovery: &[String]) {
    let python = "target/home-assistant/bin/python";
    let found = std::path::Path::new(python).exists();
    if !peer_available("Home Assistant", found) {
        return eprintln!("skipped: Home Assistant's check (target/home-assistant is missing)");
    }
    let script = r#"
import json, sys
from homeassistant.components.mqtt import number, sensor, switch, binary_sensor
schemas = dict(number=number, sensor=sensor, switch=switch, binary_sensor=binary_sensor)
for line in sys.stdin:
    topic, payload = line.rstrip("\n").split(" ", 1)
    component = topic.split("/")[1]
    config = schemas[component].DISCOVERY_SCHEMA(json.loads(payload))
    print(component, config["name"], config["state_topic"], config.get("command_topic"))
"#;
    let mut child = Process::new(python)
        .args(["-c", script])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    use std::io::Write;
    child
        .stdin
        .take()
        .unwrap()
        .write_all((discovery.join("\n") + "\n").as_bytes())
        .unwrap();
    let output = child.wait_with_output().unwrap();
    let read = String::from_utf8_lossy(&output.stdout);
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let mut read: Vec<&str> = read.lines().collect();
    read.sort_unstable();
    assert_eq!(
        read,
        [
            "binary_sensor alarm site/pump/alarm None",
            "number speed site/pump/speed site/pump/speed/set",
            "sensor level site/pump/level None",
            "sensor temp site/pump/temp None",
            "switch running site/pump/running site/pump/running/set",
        ]
    );
}

#[test]
fn a_set_topic_writes_the_device_once_the_map_allows_it() {
    let Some(broker) = Broker::start() else {
        return eprintln!("skipped: mosquitto is not installed");
    };
    let (_server, _dir, plant) = pump_plant();
    let subscriber = broker.subscribe("mbtool/pump/+");
    let poll = poll_in_background(&[&plant, "--for", "6s", "--mqtt", &broker.url()]);
    assert!(subscriber.wait_for("mbtool/pump/speed 555", Duration::from_secs(5)));
    // Refused, each told, nothing sent: read-only, out of range, not a number, no point.
    broker.publish("mbtool/pump/level/set", "5");
    broker.publish("mbtool/pump/speed/set", "70000");
    broker.publish("mbtool/pump/speed/set", "fast");
    broker.publish("mbtool/pump/nothing/set", "1");
    // Written, and read back by the next polls.
    broker.publish("mbtool/pump/speed/set", "1234");
    broker.publish("mbtool/pump/running/set", "on");
    let started = Instant::now();
    assert!(subscriber.wait_for("mbtool/pump/speed 1234", Duration::from_secs(3)));
    assert!(subscriber.wait_for("mbtool/pump/running 1", Duration::from_secs(3)));
    // The write went out between polls, not after a wait.
    assert!(
        started.elapsed() < Duration::from_secs(2),
        "{:?}",
        started.elapsed()
    );
    let lines = subscriber.lines();
    assert!(!lines.contains(&"mbtool/pump/level 5".to_string()));
    assert!(!lines
        .iter()
        .any(|l| l.starts_with("mbtool/pump/speed 70000")));
    let output = poll.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    for said in [
        "mbtool: mbtool/pump/level/set: level (400109) is read-only in the map; nothing written",
        "mbtool: mbtool/pump/speed/set: speed: 70000 rpm is out of range for this u16 point: give 0 to 65535; nothing written",
        "mbtool: mbtool/pump/speed/set: speed: 'fast' is not a number; nothing written",
        "mbtool: mbtool/pump/nothing/set: no point of the plant has this topic; nothing written",
        "mbtool: pump: speed=1234 (asked on mbtool/pump/speed/set) written",
        "mbtool: pump: running=on (asked on mbtool/pump/running/set) written",
    ] {
        assert!(stderr.contains(said), "{said}\n{stderr}");
    }
}

/// How many of `lines` are of `topic`.
fn count(lines: &[String], topic: &str) -> usize {
    lines
        .iter()
        .filter(|l| l.starts_with(&format!("{topic} ")))
        .count()
}

/// A poll of the pump every 100 ms for 4 s, `args` added, through which the broker is
/// down from the first second for `outage`: the polls that read the speed, stderr, and
/// a subscriber to the speed's topic since before the poll began.
fn poll_through_outage(
    broker: &mut Broker,
    args: &[&str],
    outage: Duration,
) -> (usize, String, Subscriber) {
    let (_server, _dir, plant) = pump_plant();
    let subscriber = broker.subscribe("mbtool/pump/speed");
    let url = broker.url();
    let mut all = vec![plant.as_str(), "--for", "4s", "--mqtt", &url];
    all.extend_from_slice(args);
    let poll = poll_in_background(&all);
    std::thread::sleep(Duration::from_millis(1000));
    broker.stop();
    std::thread::sleep(outage);
    broker.run();
    let output = poll.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
    let rows = String::from_utf8_lossy(&output.stdout)
        .lines()
        .filter(|row| row.contains("\"speed\":555"))
        .count();
    assert!(rows >= 30, "{rows} rows\n{stderr}");
    assert!(
        stderr.contains("the MQTT broker does not take messages"),
        "{stderr}"
    );
    assert!(
        stderr.contains("the MQTT broker takes messages again"),
        "{stderr}"
    );
    (rows, stderr, subscriber)
}

#[test]
fn a_broker_that_restarts_loses_nothing_within_the_buffer_and_the_overflow_is_counted() {
    let Some(mut broker) = Broker::start() else {
        return eprintln!("skipped: mosquitto is not installed");
    };
    // A buffer that holds the outage: every poll's value arrives.
    let (rows, stderr, subscriber) =
        poll_through_outage(&mut broker, &[], Duration::from_millis(1500));
    let deadline = Instant::now() + Duration::from_secs(5);
    while count(&subscriber.lines(), "mbtool/pump/speed") < rows && Instant::now() < deadline {
        std::thread::sleep(Duration::from_millis(100));
    }
    // At least once (QoS 1): a message the broker took just before it stopped may come twice.
    let received = count(&subscriber.lines(), "mbtool/pump/speed");
    assert!(
        (rows..rows + 5).contains(&received),
        "{received} of {rows}\n{stderr}"
    );
    assert!(!stderr.contains("dropped"), "{stderr}");

    // A buffer of 5 rows (30 messages: five values and an availability a row) for an
    // outage of about 100 messages (ten polls a second): the oldest give way, counted,
    // and the rest arrive.
    let (rows, stderr, subscriber) =
        poll_through_outage(&mut broker, &["--buffer", "5"], Duration::from_secs(2));
    let dropped: usize = stderr
        .split(" dropped while it was down (the buffer holds 5 rows;")
        .next()
        .and_then(|before| before.rsplit(", ").next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("no count of dropped messages in {stderr}"));
    std::thread::sleep(Duration::from_millis(500));
    let received = count(&subscriber.lines(), "mbtool/pump/speed");
    assert!(dropped >= 50, "{dropped}\n{stderr}");
    // Each poll is five messages: those of dropped/5 polls never came.
    let expected = rows - dropped / 5;
    assert!(
        received.abs_diff(expected) <= 3,
        "{received} received, {rows} polls, {dropped} dropped\n{stderr}"
    );
}

#[test]
fn a_broker_over_tls_with_a_password_is_published_to_and_a_wrong_password_is_told() {
    let Some(broker) = Broker::start_with(|port, dir| {
        let ca_key = rcgen::KeyPair::generate().unwrap();
        let mut ca = rcgen::CertificateParams::new(Vec::<String>::new()).unwrap();
        ca.is_ca = rcgen::IsCa::Ca(rcgen::BasicConstraints::Unconstrained);
        ca.distinguished_name
            .push(rcgen::DnType::CommonName, "Plant CA");
        ca.key_usages = vec![
            rcgen::KeyUsagePurpose::KeyCertSign,
            rcgen::KeyUsagePurpose::DigitalSignature,
        ];
        let ca_pem = ca.self_signed(&ca_key).unwrap().pem();
        let issuer = rcgen::Issuer::new(ca, ca_key);
        let key = rcgen::KeyPair::generate().unwrap();
        let names = vec!["localhost".to_string()];
        let mut cert = rcgen::CertificateParams::new(names).unwrap();
        cert.distinguished_name
            .push(rcgen::DnType::CommonName, "localhost");
        let cert = cert.signed_by(&key, &issuer).unwrap();
        std::fs::write(dir.join("ca.pem"), ca_pem).unwrap();
        std::fs::write(dir.join("broker.pem"), cert.pem()).unwrap();
        std::fs::write(dir.join("broker.key"), key.serialize_pem()).unwrap();
        let passwords = dir.join("passwords");
        let made = Process::new("mosquitto_passwd")
            .arg("-c")
            .arg("-b")
            .arg(&passwords)
            .args(["plant", "s3cret"])
            .status()
            .unwrap();
        assert!(made.success());
        let d = dir.display();
        format!(
            "listener {port} 127.0.0.1\nallow_anonymous false\npassword_file {d}/passwords\ncafile {d}/ca.pem\ncertfile {d}/broker.pem\nkeyfile {d}/broker.key\npersistence true\n"
        )
    }) else {
        return eprintln!("skipped: mosquitto is not installed");
    };
    let ca = broker._dir.path().join("ca.pem").display().to_string();
    let (_server, _dir, plant) = pump_plant();
    let url = format!("mqtts://localhost:{}", broker.port);
    let poll = |password: &str| {
        mbtool()
            .args([
                "poll",
                &plant,
                "--for",
                "1s",
                "--mqtt",
                &url,
                "--mqtt-retain",
            ])
            .args(["--mqtt-ca", &ca, "--mqtt-user", "plant"])
            .env("MBTOOL_MQTT_PASSWORD", password)
            .output()
            .unwrap()
    };
    let output = poll("s3cret");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(0), "{stderr}");
    assert!(!stderr.contains("does not take"), "{stderr}");
    let read = Process::new("mosquitto_sub")
        .args([
            "-h",
            "localhost",
            "-p",
            &broker.port.to_string(),
            "--cafile",
            &ca,
        ])
        .args([
            "-u",
            "plant",
            "-P",
            "s3cret",
            "-t",
            "mbtool/pump/speed",
            "-v",
        ])
        .args(["--retained-only", "-W", "2"])
        .output()
        .unwrap();
    assert_eq!(
        String::from_utf8_lossy(&read.stdout),
        "mbtool/pump/speed 555\n",
        "{}\n{stderr}",
        String::from_utf8_lossy(&read.stderr)
    );
    // A wrong password: the polling goes on, the broker's refusal told once, in words.
    let output = poll("wrong");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(0), "{stderr}");
    assert!(
        stderr.contains("pump: 10 polls") || stderr.contains("pump: 11 polls"),
        "{stderr}"
    );
    assert_eq!(
        stderr.matches("the MQTT broker refused mbtool's login (not authorized): check --mqtt-user and MBTOOL_MQTT_PASSWORD").count(),
        1,
        "{stderr}"
    );
}

/// A Home Assistant configuration's binary sensors and switches (a coil, and one kept in a
/// register with its own commands) are announced as such, published as `on` and `off` as
/// their discovery says, and a switch's `set` writes its command.
#[test]
fn entities_of_a_home_assistant_configuration_are_announced_as_what_they_are() {
    let Some(broker) = Broker::start() else {
        return eprintln!("skipped: mosquitto is not installed");
    };
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("data.txt");
    std::fs::write(
        &data,
        "400001-400005 = 0\n400006 = 1\n400007 = 3\n400008-400010 = 0\n000001-000008 = on\n",
    )
    .unwrap();
    let (_server, _, port) = serve_tcp(&["--data", data.to_str().unwrap()]);
    let config = dir.path().join("configuration.yaml");
    std::fs::write(
        &config,
        format!(
            "modbus:\n  - name: hub\n    type: tcp\n    host: 127.0.0.1\n    port: {port}\n    binary_sensors:\n      - name: Alarm\n        address: 5\n        input_type: holding\n        slave: 17\n    switches:\n      - name: Valve\n        address: 6\n        write_type: holding\n        command_on: 7\n        command_off: 3\n        slave: 17\n        scan_interval: 1\n      - name: Pump\n        address: 0\n        write_type: coil\n        slave: 17\n        scan_interval: 1\n"
        ),
    )
    .unwrap();
    let subscriber = broker.subscribe("mbtool/#");
    let url = broker.url();
    let poll = poll_in_background(&[
        config.to_str().unwrap(),
        "--for",
        "4s",
        "--mqtt",
        &url,
        "--mqtt-discovery",
    ]);
    assert!(
        subscriber.wait_for("mbtool/hub/17/1s/Valve off", Duration::from_secs(3)),
        "{:?}",
        subscriber.lines()
    );
    broker.publish("mbtool/hub/17/1s/Valve/set", "on");
    assert!(
        subscriber.wait_for("mbtool/hub/17/1s/Valve on", Duration::from_secs(3)),
        "{:?}",
        subscriber.lines()
    );
    let output = poll.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr
            .contains("mbtool: hub/17/1s: Valve=on (asked on mbtool/hub/17/1s/Valve/set) written"),
        "{stderr}"
    );
    let lines = subscriber.lines();
    for line in ["mbtool/hub/17/15s/Alarm on", "mbtool/hub/17/1s/Pump on"] {
        assert!(lines.iter().any(|l| l == line), "{line}: {lines:?}");
    }
    let discovery = broker.retained("homeassistant/#");
    let config = |component: &str, name: &str| -> serde_json::Value {
        let found = discovery
            .iter()
            .find(|line| {
                line.starts_with(&format!("homeassistant/{component}/"))
                    && line.contains(&format!("\"name\":\"{name}\""))
            })
            .unwrap_or_else(|| panic!("no {component} {name} in {discovery:?}"));
        serde_json::from_str(found.split_once(' ').unwrap().1).unwrap()
    };
    let alarm = config("binary_sensor", "Alarm");
    assert_eq!(
        (alarm["payload_on"].as_str(), alarm["payload_off"].as_str()),
        (Some("on"), Some("off"))
    );
    for name in ["Valve", "Pump"] {
        let switch = config("switch", name);
        assert_eq!(
            (
                switch["payload_on"].as_str(),
                switch["payload_off"].as_str()
            ),
            (Some("on"), Some("off")),
            "{switch}"
        );
        assert!(switch["command_topic"]
            .as_str()
            .is_some_and(|t| t.ends_with(&format!("{name}/set"))));
    }
}

/// A broker that restarts without keeping anything (no persistence) has the devices'
/// availability again, as Home Assistant's discovery needs it, and mbtool's status.
#[test]
fn a_broker_that_forgets_gets_the_availability_again() {
    let Some(mut broker) = Broker::start_with(|port, _| {
        format!("listener {port} 127.0.0.1\nallow_anonymous true\npersistence false\n")
    }) else {
        return eprintln!("skipped: mosquitto is not installed");
    };
    let (_server, _dir, plant) = pump_plant();
    let poll = poll_in_background(&[&plant, "--for", "8s", "--mqtt", &broker.url()]);
    std::thread::sleep(Duration::from_millis(1000));
    broker.stop();
    broker.run();
    // Reconnected within the client's first wait (250 ms), and announced.
    std::thread::sleep(Duration::from_millis(2000));
    assert_eq!(
        broker.retained("mbtool/+/available"),
        ["mbtool/pump/available online"]
    );
    assert_eq!(broker.retained("mbtool/status"), ["mbtool/status online"]);
    let output = poll.wait_with_output().unwrap();
    assert_eq!(output.status.code(), Some(0));
}

/// A write asked while the device is slow to answer, then SIGTERM: the poll ends at once,
/// and the write it did not send is told.
#[test]
fn a_write_left_unsent_at_the_end_is_told() {
    let Some(broker) = Broker::start() else {
        return eprintln!("skipped: mosquitto is not installed");
    };
    let (_server, _, port) = serve_tcp(&["--delay", "1500ms"]);
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("map.csv"), MAP).unwrap();
    let plant = dir.path().join("plant.yaml");
    let pump = device("pump", &format!("tcp://127.0.0.1:{port}"), 17, "100ms");
    std::fs::write(&plant, format!("devices:\n{pump}")).unwrap();
    let url = broker.url();
    let poll = poll_in_background(&[plant.to_str().unwrap(), "--timeout", "5s", "--mqtt", &url]);
    std::thread::sleep(Duration::from_millis(700));
    broker.publish("mbtool/pump/speed/set", "4321");
    std::thread::sleep(Duration::from_millis(300));
    let started = std::time::Instant::now();
    super::send_signal(poll.id(), "TERM");
    let output = poll.wait_with_output().unwrap();
    assert!(
        started.elapsed() < Duration::from_secs(2),
        "{:?}",
        started.elapsed()
    );
    assert_eq!(output.status.code(), Some(143));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("mbtool: pump: speed=4321 (asked on mbtool/pump/speed/set) not written: polling ended first"),
        "{stderr}"
    );
}
