//! Each value published to an MQTT broker: `PREFIX/DEVICE/POINT`, the value as text,
//! retained where asked; whether each device answers at `PREFIX/DEVICE/available`
//! (`online`, `offline`) and whether mbtool runs at `PREFIX/status` (its last will);
//! Home Assistant MQTT discovery; and writes asked on `PREFIX/DEVICE/POINT/set`.
//!
//! The messages wait in a bounded buffer and are handed to the client only while it is
//! connected; the client resends, after a reconnection, what the broker had not
//! acknowledged (QoS 1). One thread drives the connection, another sends.

use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use rumqttc::{
    Client, Connection, ConnectionError, Event, LastWill, MqttOptions, Packet, QoS, Transport,
};
use serde_json::{json, Map, Value as Json};

use super::{Buffer, Delivered};
use mbtool_core::model::map::{Kind, Point};
use mbtool_core::model::shown::States;
use mbtool_core::model::values::ValueType;

/// How the broker is reached and what is published.
#[derive(Clone, Debug, PartialEq)]
pub struct MqttSettings {
    pub host: String,
    pub port: u16,
    /// `mqtts://`: TLS, the broker's certificate checked against `ca` (or the system's).
    pub tls: bool,
    pub ca: Option<PathBuf>,
    /// The first level of every topic.
    pub prefix: String,
    /// Values published retained, so that a subscriber has the last at once.
    pub retain: bool,
    /// Home Assistant's discovery prefix, where discovery is asked.
    pub discovery: Option<String>,
    pub user: Option<String>,
    pub password: Option<String>,
}

/// Reads `mqtt://HOST[:PORT]` or `mqtts://HOST[:PORT]`: the host, the port (1883 and
/// 8883 where not given) and whether it is TLS.
pub fn parse_url(url: &str) -> Result<(String, u16, bool), String> {
    let (rest, tls, port) = match url.split_once("://") {
        Some(("mqtt" | "tcp", rest)) => (rest, false, 1883),
        Some(("mqtts" | "ssl", rest)) => (rest, true, 8883),
        _ => {
            return Err(format!(
                "--mqtt {url}: give the broker as mqtt://HOST[:PORT] or mqtts://HOST[:PORT]"
            ))
        }
    };
    let rest = rest.trim_end_matches('/');
    if rest.contains('@') {
        return Err(format!(
            "--mqtt {url}: give the user and password with --mqtt-user and MBTOOL_MQTT_PASSWORD, not in the URL"
        ));
    }
    let (host, port) = match rest.rsplit_once(':') {
        Some((host, given)) if !host.is_empty() && !given.contains(']') => {
            let port = given
                .parse::<u16>()
                .ok()
                .filter(|p| *p != 0)
                .ok_or_else(|| format!("--mqtt {url}: the port {given} is not 1 to 65535"))?;
            (host, port)
        }
        _ => (rest, port),
    };
    let host = host.trim_start_matches('[').trim_end_matches(']');
    if host.is_empty() {
        return Err(format!("--mqtt {url}: the URL names no host"));
    }
    Ok((host.to_string(), port, tls))
}

/// A message waiting to be published.
#[derive(Clone, Debug, PartialEq)]
pub struct Message {
    pub topic: String,
    pub payload: String,
    pub retain: bool,
}

/// A name as one level of a topic: MQTT's wildcards (`+`, `#`) and the level separator
/// become `_`.
pub fn level(name: &str) -> String {
    name.chars()
        .map(|c| match c {
            '+' | '#' | '/' | '\0' => '_',
            c => c,
        })
        .collect()
}

/// A device's name as topic levels: a `/` in it (`meter/2`, the devices of a Home
/// Assistant hub) stays a level separator.
fn device_levels(name: &str) -> String {
    name.split('/').map(level).collect::<Vec<_>>().join("/")
}

/// The topics of a plant's devices and points.
pub struct Topics {
    prefix: String,
    /// Each device's topic levels and its points' own levels.
    devices: Vec<(String, Vec<String>)>,
}

impl Topics {
    /// The topics of `devices`, each a name and its points.
    pub fn new(prefix: &str, devices: &[(&str, &[Point])]) -> Topics {
        Topics {
            prefix: prefix.trim_end_matches('/').to_string(),
            devices: devices
                .iter()
                .map(|(name, points)| {
                    let points = points.iter().map(|p| level(&p.name)).collect();
                    (device_levels(name), points)
                })
                .collect(),
        }
    }

    /// `PREFIX/DEVICE/POINT`, where a point's value is published.
    pub fn value(&self, device: usize, point: usize) -> String {
        let (name, points) = &self.devices[device];
        format!("{}/{name}/{}", self.prefix, points[point])
    }

    /// `PREFIX/DEVICE/available`: `online` while the device answers, else `offline`.
    pub fn available(&self, device: usize) -> String {
        format!("{}/{}/available", self.prefix, self.devices[device].0)
    }

    /// `PREFIX/status`: `online` while mbtool runs, `offline` (its last will) after.
    pub fn status(&self) -> String {
        format!("{}/status", self.prefix)
    }

    /// The device and point a `.../set` topic names.
    pub fn setting(&self, topic: &str) -> Option<(usize, usize)> {
        let rest = topic.strip_prefix(&self.prefix)?.strip_prefix('/')?;
        let rest = rest.strip_suffix("/set")?;
        self.devices
            .iter()
            .enumerate()
            .find_map(|(device, (name, points))| {
                let point = rest.strip_prefix(name.as_str())?.strip_prefix('/')?;
                Some((device, points.iter().position(|p| p == point)?))
            })
    }

    /// Each topic that two things of the plant would share (two point names that differ
    /// only in `/`, `+` or `#`, a point named `available`, ...), told with what shares it:
    /// a value published there, or a write asked, would be taken for the other's.
    pub fn clashes(&self, devices: &[(&str, &[Point])]) -> Vec<String> {
        let mut owners: Vec<(String, String)> = vec![(self.status(), "mbtool's status".into())];
        for (index, (name, points)) in devices.iter().enumerate() {
            owners.push((self.available(index), format!("{name}'s availability")));
            for (p, point) in points.iter().enumerate() {
                let value = self.value(index, p);
                owners.push((
                    format!("{value}/set"),
                    format!("{name}'s {} writes", point.name),
                ));
                owners.push((value, format!("{name}'s {}", point.name)));
            }
        }
        let mut clashes: Vec<(&str, String)> = Vec::new();
        for (i, (topic, owner)) in owners.iter().enumerate() {
            if let Some((_, first)) = owners[..i].iter().find(|(t, _)| t == topic) {
                clashes.push((topic, format!(
                    "{first} and {owner} are both the MQTT topic {topic}: give names that differ in more than /, + and #"
                )));
            }
        }
        // Two values of one topic have one `set` topic too: told once.
        let told: Vec<&str> = clashes.iter().map(|(topic, _)| *topic).collect();
        clashes
            .into_iter()
            .filter(|(topic, _)| {
                !topic
                    .strip_suffix("/set")
                    .is_some_and(|v| told.contains(&v))
            })
            .map(|(_, said)| said)
            .collect()
    }

    /// The subscriptions that take every `.../set` topic of the plant's writable points.
    pub fn set_filters(&self) -> Vec<String> {
        let mut depths: Vec<usize> = self
            .devices
            .iter()
            .map(|(name, _)| name.split('/').count())
            .collect();
        depths.sort_unstable();
        depths.dedup();
        depths
            .into_iter()
            .map(|depth| format!("{}/{}+/set", self.prefix, "+/".repeat(depth)))
            .collect()
    }

    /// Home Assistant's discovery messages for every point: a sensor, a binary sensor, a
    /// switch (a writable bit) or a number (a writable register), under `discovery`.
    pub fn discovery(&self, discovery: &str, devices: &[(&str, &[Point])]) -> Vec<Message> {
        let mut messages = Vec::new();
        for (index, (name, points)) in devices.iter().enumerate() {
            let id = format!("mbtool_{}", object_id(name));
            for (p, point) in points.iter().enumerate() {
                let state = self.value(index, p);
                let mut config = Map::new();
                config.insert("name".into(), json!(point.name));
                let unique = format!("{id}_{}", object_id(&point.name));
                config.insert("unique_id".into(), json!(unique));
                config.insert("state_topic".into(), json!(state));
                config.insert(
                    "availability".into(),
                    json!([{"topic": self.status()}, {"topic": self.available(index)}]),
                );
                config.insert("availability_mode".into(), json!("all"));
                config.insert(
                    "device".into(),
                    json!({"identifiers": [id], "name": name, "manufacturer": "mbtool"}),
                );
                let command = format!("{state}/set");
                // An entity of Home Assistant's that is on or off is published as `on` and
                // `off`; a bit as `1` and `0`.
                let on_off = point
                    .shown
                    .as_ref()
                    .is_some_and(|shown| matches!(shown.states, Some(States::OnOff { .. })));
                let cover = point
                    .shown
                    .as_ref()
                    .is_some_and(|shown| matches!(shown.states, Some(States::Cover { .. })));
                let component = match (point.kind, point.writable) {
                    _ if cover => "sensor",
                    (kind, writable) if on_off || kind == Kind::Bool => {
                        let (on, off) = if on_off { ("on", "off") } else { ("1", "0") };
                        config.insert("payload_on".into(), json!(on));
                        config.insert("payload_off".into(), json!(off));
                        if writable {
                            config.insert("command_topic".into(), json!(command));
                            "switch"
                        } else {
                            "binary_sensor"
                        }
                    }
                    (Kind::Number(value_type), true) => {
                        let (low, high) = match value_type {
                            ValueType::F32 => (f64::from(f32::MIN), f64::from(f32::MAX)),
                            ValueType::F64 => (f64::MIN, f64::MAX),
                            _ => {
                                let (low, high) = value_type.strict_range();
                                (low as f64, high as f64)
                            }
                        };
                        // In the scale's steps, without a float's noise (3276.7, not
                        // 3276.7000000000003).
                        let floating = matches!(value_type, ValueType::F32 | ValueType::F64);
                        let shown = |raw: f64| {
                            let value = raw * point.scale + point.offset;
                            let rounded = format!("{value:.9e}").parse::<f64>();
                            match rounded {
                                Ok(rounded) if !floating && rounded.is_finite() => rounded,
                                _ => value,
                            }
                        };
                        let ends = [shown(low), shown(high)];
                        config.insert("command_topic".into(), json!(command));
                        config.insert("min".into(), json!(ends[0].min(ends[1])));
                        config.insert("max".into(), json!(ends[0].max(ends[1])));
                        config.insert("step".into(), json!(step(point)));
                        config.insert("mode".into(), json!("box"));
                        unit(&mut config, point);
                        "number"
                    }
                    (Kind::Number(_), false) => {
                        config.insert("state_class".into(), json!("measurement"));
                        unit(&mut config, point);
                        "sensor"
                    }
                    (Kind::Bool | Kind::Text(_) | Kind::Packed(_), _) => "sensor",
                };
                messages.push(Message {
                    topic: format!("{discovery}/{component}/{unique}/config"),
                    payload: Json::Object(config).to_string(),
                    retain: true,
                });
            }
        }
        messages
    }
}

fn unit(config: &mut Map<String, Json>, point: &Point) {
    if !point.unit.is_empty() {
        config.insert("unit_of_measurement".into(), json!(point.unit));
    }
}

/// The step of a writable number: its scale where that is finer than 1, else 1; a float
/// as it is, in thousandths (Home Assistant's finest step).
fn step(point: &Point) -> f64 {
    match point.kind {
        Kind::Number(ValueType::F32 | ValueType::F64) if point.is_unscaled() => 0.001,
        _ => point.scale.abs().clamp(0.001, 1.0),
    }
}

/// A name as Home Assistant's object ids take it (letters, digits, `-` and `_`), one id a
/// name: letters, digits and `-` as they are, any other byte as `_` and its hex (`_5f` for
/// `_`, `_2f` for `/`).
fn object_id(name: &str) -> String {
    let mut id = String::with_capacity(name.len());
    for byte in name.bytes() {
        match byte.is_ascii_alphanumeric() || byte == b'-' {
            true => id.push(char::from(byte)),
            false => id.push_str(&format!("_{byte:02x}")),
        }
    }
    id
}

/// What the connection thread and the sending thread share.
#[derive(Default)]
struct State {
    connected: AtomicBool,
    /// Set on each connection: subscribe and announce again (a broker that restarted
    /// without keeping them has lost both).
    announce: AtomicBool,
    /// No more is sent: the connection thread ends at its next error.
    ending: AtomicBool,
    acknowledged: AtomicU64,
    /// Connections made so far: an acknowledgement counts on the connection it came on.
    connections: AtomicU64,
    /// The last availability of each device, by topic, published again on each
    /// connection.
    latest: std::sync::Mutex<std::collections::BTreeMap<String, Message>>,
}

/// A client of the broker, connected by a thread of its own.
pub struct Broker {
    client: Client,
    connection: Connection,
    state: Arc<State>,
}

/// How long messages left at the end are tried for, with a broker that is down.
const LAST_TRY: Duration = Duration::from_secs(3);

/// How long a connection to the broker may take.
const CONNECTION_TIMEOUT: Duration = Duration::from_secs(2);

/// Messages published at once before their acknowledgements are waited for.
const WINDOW: usize = 500;

/// Messages the client holds at once before publishing waits.
const CLIENT_QUEUE: usize = 1000;

impl Broker {
    /// A client of the broker `settings` name (not yet connected), whose last will is
    /// `status` `offline`.
    pub fn new(settings: &MqttSettings, status: &str) -> Result<Broker, String> {
        let id = format!("mbtool-{}-{}", std::process::id(), fastrand::u32(..));
        let mut options = MqttOptions::new(id, settings.host.clone(), settings.port);
        options.set_keep_alive(Duration::from_secs(30));
        options.set_max_packet_size(1 << 20, 1 << 20);
        options.set_last_will(LastWill::new(status, "offline", QoS::AtLeastOnce, true));
        if let Some(user) = &settings.user {
            options.set_credentials(user, settings.password.clone().unwrap_or_default());
        }
        if settings.tls {
            options.set_transport(Transport::Tls(rumqttc::TlsConfiguration::Rustls(Arc::new(
                tls_config(settings)?,
            ))));
        }
        let (client, mut connection) = Client::new(options, CLIENT_QUEUE);
        // A broker that does not answer is given up on soon, and asked again.
        let mut network = rumqttc::NetworkOptions::new();
        network.set_connection_timeout(CONNECTION_TIMEOUT.as_secs());
        connection.eventloop.set_network_options(network);
        Ok(Broker {
            client,
            connection,
            state: Arc::default(),
        })
    }

    /// Drives the connection until the sender ends: reconnects (waiting longer each time
    /// up to 10 s), tells when the broker goes and comes back, and hands each `.../set`
    /// message (not a retained one: a command left on the broker is no command now) to
    /// `set`.
    pub fn run(
        mut self,
        sender: impl FnOnce(Sender) -> Delivered + Send,
        set: impl Fn(&str, &str) + Send,
        tell: impl Fn(&str) + Sync,
    ) -> Delivered {
        let state = Arc::clone(&self.state);
        let handed = Sender {
            client: self.client.clone(),
            state: Arc::clone(&state),
        };
        std::thread::scope(|scope| {
            let sending = scope.spawn(move || sender(handed));
            let mut wait = Duration::from_millis(250);
            let mut down = false;
            let mut told_down = false;
            for event in self.connection.iter() {
                match event {
                    Ok(Event::Incoming(Packet::ConnAck(_))) => {
                        state.connections.fetch_add(1, Ordering::SeqCst);
                        state.connected.store(true, Ordering::SeqCst);
                        state.announce.store(true, Ordering::SeqCst);
                        wait = Duration::from_millis(250);
                        if std::mem::take(&mut down) && told_down {
                            tell("the MQTT broker takes messages again");
                        }
                        told_down = false;
                    }
                    Ok(Event::Incoming(Packet::PubAck(_))) => {
                        state.acknowledged.fetch_add(1, Ordering::SeqCst);
                    }
                    Ok(Event::Incoming(Packet::Publish(message))) if !message.retain => {
                        match std::str::from_utf8(&message.payload) {
                            Ok(payload) => set(&message.topic, payload.trim()),
                            Err(_) => tell(&format!(
                                "{}: the value is not text; nothing written",
                                message.topic
                            )),
                        }
                    }
                    Ok(_) => {}
                    Err(error) => {
                        state.connected.store(false, Ordering::SeqCst);
                        if state.ending.load(Ordering::SeqCst) {
                            break;
                        }
                        down = true;
                        if !told_down {
                            told_down = true;
                            tell(&refusal(&error));
                        }
                        // In steps, so that the end is not held up by a broker away.
                        let until = Instant::now() + wait;
                        while Instant::now() < until && !state.ending.load(Ordering::SeqCst) {
                            std::thread::sleep(Duration::from_millis(50));
                        }
                        wait = (wait * 2).min(Duration::from_secs(10));
                    }
                }
            }
            sending.join().unwrap_or_default()
        })
    }
}

/// Why the broker takes no message, in words that say what to do.
fn refusal(error: &ConnectionError) -> String {
    use rumqttc::ConnectReturnCode as Code;
    let keeping = "keeping the messages to send when it does";
    match error {
        ConnectionError::ConnectionRefused(Code::BadUserNamePassword | Code::NotAuthorized) => {
            format!("the MQTT broker refused mbtool's login (not authorized): check --mqtt-user and MBTOOL_MQTT_PASSWORD; {keeping}")
        }
        ConnectionError::Tls(tls) => format!(
            "the MQTT broker's TLS failed ({tls}): check mqtts://, its port and --mqtt-ca; {keeping}"
        ),
        error => format!("the MQTT broker does not take messages ({error}); {keeping}"),
    }
}

/// Publishes the buffer's messages while the broker is connected.
pub struct Sender {
    client: Client,
    state: Arc<State>,
}

impl Sender {
    /// Sends `buffer`'s messages until it is closed and empty (or its last messages could
    /// not be sent within a few seconds). On each connection it first subscribes to
    /// `subscriptions` and publishes `announce` (retained discovery, `online`).
    pub fn send(
        self,
        buffer: &Buffer<Message>,
        subscriptions: &[String],
        announce: &[Message],
    ) -> Delivered {
        let state = &self.state;
        let mut delivered = Delivered::default();
        let mut closed_at: Option<Instant> = None;
        // The last try, counted from when the buffer was closed.
        let mut out_of_time = |closing: bool| {
            closing
                && closed_at
                    .get_or_insert_with(|| buffer.closed_at().unwrap_or_else(Instant::now))
                    .elapsed()
                    >= LAST_TRY
        };
        loop {
            if state.announce.swap(false, Ordering::SeqCst) {
                for filter in subscriptions {
                    let _ = self.client.subscribe(filter.as_str(), QoS::AtLeastOnce);
                }
                // The devices' availability as last told, which a broker that restarted
                // without keeping it has lost.
                let latest = self
                    .state
                    .latest
                    .lock()
                    .map(|l| l.clone())
                    .unwrap_or_default();
                let mut first: Vec<Message> = announce.to_vec();
                first.extend(latest.into_values());
                // A connection lost meanwhile announces again when it is back.
                self.publish_all(&first, Duration::from_secs(5));
            }
            if !state.connected.load(Ordering::SeqCst) {
                if out_of_time(buffer.closed_at().is_some()) {
                    break;
                }
                std::thread::sleep(Duration::from_millis(100));
                continue;
            }
            let (messages, closing) = buffer.oldest(WINDOW, Duration::from_millis(200));
            if messages.is_empty() && closing {
                break;
            }
            // Taken out of the buffer only once the broker has them: a connection lost
            // meanwhile has them published again on the next (at least once, as QoS 1).
            if self.publish_all(&messages, LAST_TRY) {
                buffer.sent(messages.len());
                delivered.sent += messages.len() as u64;
            } else if out_of_time(closing) {
                break;
            }
        }
        // mbtool ends: said, as its last will says it when it ends otherwise.
        let status = announce.iter().rev().find(|m| m.payload == "online");
        if let Some(status) = status.filter(|_| state.connected.load(Ordering::SeqCst)) {
            let offline = Message {
                payload: "offline".into(),
                ..status.clone()
            };
            self.publish_all(&[offline], Duration::from_secs(1));
        }
        state.ending.store(true, Ordering::SeqCst);
        let _ = self.client.disconnect();
        let (dropped, unsent) = buffer.counts();
        delivered.dropped = dropped;
        delivered.unsent = unsent;
        delivered
    }

    /// Publishes `messages` and waits up to `within` for the broker to acknowledge them
    /// all on one connection; whether it did.
    fn publish_all(&self, messages: &[Message], within: Duration) -> bool {
        let state = &self.state;
        let connection = state.connections.load(Ordering::SeqCst);
        let acknowledged = state.acknowledged.load(Ordering::SeqCst);
        for message in messages {
            self.publish(message);
        }
        let end = Instant::now() + within;
        loop {
            let now_acknowledged = state.acknowledged.load(Ordering::SeqCst);
            if now_acknowledged.saturating_sub(acknowledged) >= messages.len() as u64 {
                return true;
            }
            let same = state.connections.load(Ordering::SeqCst) == connection;
            if !same || !state.connected.load(Ordering::SeqCst) || Instant::now() >= end {
                return false;
            }
            std::thread::sleep(Duration::from_millis(1));
        }
    }

    fn publish(&self, message: &Message) {
        if message.retain && message.topic.ends_with("/available") {
            if let Ok(mut latest) = self.state.latest.lock() {
                latest.insert(message.topic.clone(), message.clone());
            }
        }
        // Refused only once the client is gone, at the end.
        let _ = self.client.publish(
            message.topic.as_str(),
            QoS::AtLeastOnce,
            message.retain,
            message.payload.as_bytes(),
        );
    }
}

/// TLS to the broker: its certificate checked against `--mqtt-ca`, or against the
/// system's certificate authorities.
fn tls_config(settings: &MqttSettings) -> Result<rustls::ClientConfig, String> {
    use mbtool_core::transport::tls;
    let roots = match &settings.ca {
        Some(ca) => tls::root_store(ca).map_err(|e| format!("--mqtt-ca: {e}"))?,
        None => {
            let mut roots = rustls::RootCertStore::empty();
            let found = rustls_native_certs::load_native_certs();
            roots.add_parsable_certificates(found.certs);
            if roots.is_empty() {
                return Err(
                    "mqtts://: the system has no CA certificates: give the broker's CA with --mqtt-ca FILE".into(),
                );
            }
            roots
        }
    };
    tls::standard_client(roots).map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_broker_url_gives_host_port_and_tls() {
        assert_eq!(
            parse_url("mqtt://127.0.0.1"),
            Ok(("127.0.0.1".into(), 1883, false))
        );
        assert_eq!(
            parse_url("mqtts://broker:8884/"),
            Ok(("broker".into(), 8884, true))
        );
        assert_eq!(
            parse_url("mqtt://[::1]:1884"),
            Ok(("::1".into(), 1884, false))
        );
        assert!(parse_url("http://broker").is_err());
        assert!(parse_url("mqtt://user:secret@broker").is_err());
        assert!(parse_url("mqtt://broker:0").is_err());
        assert!(parse_url("mqtt://").is_err());
    }

    #[test]
    fn names_that_would_share_a_topic_or_an_object_id_are_told() {
        let point = |name: &str| {
            let text = format!("name,ref\n\"{name}\",400001\n");
            mbtool_core::model::map::parse_csv("m.csv", &text).map(|map| map.points[0].clone())
        };
        let (Ok(slash), Ok(under), Ok(x)) = (point("a/b"), point("a_b"), point("x")) else {
            panic!("the maps are good");
        };
        let one = [slash, under];
        let two = [x.clone()];
        let three = [x];
        let devices: [(&str, &[Point]); 3] = [("p-1", &one), ("p+1", &two), ("p_1", &three)];
        let clashes = Topics::new("m", &devices).clashes(&devices);
        assert_eq!(
            clashes,
            [
                "p-1's a/b and p-1's a_b are both the MQTT topic m/p-1/a_b: give names that differ in more than /, + and #",
                "p+1's availability and p_1's availability are both the MQTT topic m/p_1/available: give names that differ in more than /, + and #",
                "p+1's x and p_1's x are both the MQTT topic m/p_1/x: give names that differ in more than /, + and #",
            ]
        );
        let ids: Vec<String> = ["p-1", "p_1", "p 1", "p/1", "P-1"]
            .iter()
            .map(|n| object_id(n))
            .collect();
        assert_eq!(ids, ["p-1", "p_5f1", "p_201", "p_2f1", "P-1"]);
    }

    #[test]
    fn a_set_topic_names_its_device_and_point_even_where_names_hold_slashes() {
        let point = |name: &str| {
            mbtool_core::model::map::parse_csv("m.csv", &format!("name,ref\n{name},400001\n"))
                .map(|map| map.points[0].clone())
        };
        let (Ok(a), Ok(b)) = (point("setpoint"), point("L1+L2")) else {
            panic!("the maps are good");
        };
        let meter = [a.clone(), b];
        let drive = [a];
        let devices: [(&str, &[Point]); 2] = [("meter/2", &meter), ("drive", &drive)];
        let topics = Topics::new("plant/", &devices);
        assert_eq!(topics.value(0, 1), "plant/meter/2/L1_L2");
        assert_eq!(topics.setting("plant/meter/2/L1_L2/set"), Some((0, 1)));
        assert_eq!(topics.setting("plant/drive/setpoint/set"), Some((1, 0)));
        assert_eq!(topics.setting("plant/drive/setpoint"), None);
        assert_eq!(topics.setting("plant/drive/nothing/set"), None);
        assert_eq!(
            topics.set_filters(),
            vec!["plant/+/+/set".to_string(), "plant/+/+/+/set".to_string()]
        );
    }
}
