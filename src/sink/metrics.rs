//! `poll --metrics ADDR`: the plant as Prometheus reads it, on `http://ADDR/metrics` in its
//! text format. A gauge per point that the last poll of its device read (a point that
//! failed has none until it is read again: no value is shown that was not read), counters
//! of polls and of errors by kind, and a histogram of response times.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::io::{BufRead, BufReader, Write};
use std::net::{TcpListener, TcpStream};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Duration;

use mbtool_core::master::plant::{Outcome, Polled};
use mbtool_core::master::run::RunError;
use mbtool_core::master::MasterError;
use mbtool_core::model::values::Value;

/// The upper bounds of the response time histogram, in seconds.
const BUCKETS: [f64; 11] = [
    0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 0.5, 1.0, 2.5, 5.0, 10.0,
];

/// How long a scraper may take to send its request.
const REQUEST_TIMEOUT: Duration = Duration::from_secs(2);

/// Clients answered at once; past them a new one is closed until one is done (an idle
/// one within the request timeout).
const MOST_CLIENTS: usize = 256;

/// A device's series.
#[derive(Default)]
struct DeviceMetrics {
    slave: u8,
    polls: u64,
    /// Errors by kind: timeout, exception, bad_frame, disconnected, other.
    errors: BTreeMap<&'static str, u64>,
    /// Response time counts per bucket (cumulative when written), their sum and count.
    buckets: [u64; BUCKETS.len()],
    seconds: f64,
    answered: u64,
    /// The last value of each point the last poll read, with its unit.
    values: BTreeMap<String, (String, f64)>,
}

/// The plant's metrics, updated by the poll and read by the scrapers.
#[derive(Clone, Default)]
pub struct Metrics {
    devices: Arc<Mutex<BTreeMap<String, DeviceMetrics>>>,
}

impl Metrics {
    /// A poll of `device` (slave `slave`), whose points are `points` (name and unit).
    pub fn record(&self, device: &str, slave: u8, points: &[(&str, &str)], polled: &Polled) {
        let mut devices = self.devices.lock().unwrap_or_else(|p| p.into_inner());
        let metrics = devices.entry(device.to_string()).or_default();
        metrics.slave = slave;
        metrics.polls += 1;
        match &polled.outcome {
            Outcome::Read(read) => {
                let seconds = polled.took.as_secs_f64();
                metrics.answered += 1;
                metrics.seconds += seconds;
                for (count, bound) in metrics.buckets.iter_mut().zip(BUCKETS) {
                    *count += u64::from(seconds <= bound);
                }
                metrics.values.clear();
                for value in &read.values {
                    let Some(number) = number(&value.value) else {
                        continue;
                    };
                    let (name, unit) = points[value.point];
                    metrics
                        .values
                        .insert(name.to_string(), (unit.to_string(), number));
                }
                for failure in &read.failed {
                    *metrics.errors.entry(kind(&failure.error)).or_default() += 1;
                }
            }
            Outcome::Failed(error) => {
                metrics.values.clear();
                *metrics.errors.entry(kind(error)).or_default() += 1;
            }
            Outcome::Down(_) => {
                metrics.values.clear();
                *metrics.errors.entry("disconnected").or_default() += 1;
            }
        }
    }

    /// The text format of every series now.
    pub fn text(&self) -> String {
        let devices = self.devices.lock().unwrap_or_else(|p| p.into_inner());
        let mut text = String::new();
        text.push_str("# HELP modbus_value The value of a point, as its last poll read it.\n# TYPE modbus_value gauge\n");
        for (device, metrics) in devices.iter() {
            for (name, (unit, value)) in &metrics.values {
                let _ = writeln!(
                    text,
                    "modbus_value{{device=\"{}\",slave=\"{}\",name=\"{}\",unit=\"{}\"}} {value}",
                    label(device),
                    metrics.slave,
                    label(name),
                    label(unit)
                );
            }
        }
        text.push_str(
            "# HELP modbus_polls_total Polls of a device.\n# TYPE modbus_polls_total counter\n",
        );
        for (device, metrics) in devices.iter() {
            let _ = writeln!(
                text,
                "modbus_polls_total{{device=\"{}\"}} {}",
                label(device),
                metrics.polls
            );
        }
        text.push_str("# HELP modbus_errors_total Failed polls and points of a device, by kind.\n# TYPE modbus_errors_total counter\n");
        for (device, metrics) in devices.iter() {
            for (kind, count) in &metrics.errors {
                let _ = writeln!(
                    text,
                    "modbus_errors_total{{device=\"{}\",kind=\"{kind}\"}} {count}",
                    label(device)
                );
            }
        }
        text.push_str("# HELP modbus_response_seconds How long a device took to give its points.\n# TYPE modbus_response_seconds histogram\n");
        for (device, metrics) in devices.iter() {
            let device = label(device);
            for (count, bound) in metrics.buckets.iter().zip(BUCKETS) {
                let _ = writeln!(
                    text,
                    "modbus_response_seconds_bucket{{device=\"{device}\",le=\"{bound}\"}} {count}"
                );
            }
            let _ = writeln!(
                text,
                "modbus_response_seconds_bucket{{device=\"{device}\",le=\"+Inf\"}} {}",
                metrics.answered
            );
            let _ = writeln!(
                text,
                "modbus_response_seconds_sum{{device=\"{device}\"}} {}",
                metrics.seconds
            );
            let _ = writeln!(
                text,
                "modbus_response_seconds_count{{device=\"{device}\"}} {}",
                metrics.answered
            );
        }
        text
    }

    /// Serves `/metrics` on `listener` until the process ends, a scraper at a time.
    pub fn serve(&self, listener: TcpListener) {
        // Each client on a thread of its own, so that one that sends nothing holds back
        // no scrape; past a bound, a new client is closed at once.
        let clients = Arc::new(AtomicUsize::new(0));
        for stream in listener.incoming().flatten() {
            if clients.fetch_add(1, Ordering::SeqCst) >= MOST_CLIENTS {
                clients.fetch_sub(1, Ordering::SeqCst);
                continue;
            }
            let (metrics, done) = (self.clone(), Arc::clone(&clients));
            let answering = std::thread::Builder::new()
                .stack_size(128 * 1024)
                .spawn(move || {
                    let _ = metrics.answer(stream);
                    done.fetch_sub(1, Ordering::SeqCst);
                });
            if answering.is_err() {
                clients.fetch_sub(1, Ordering::SeqCst);
            }
        }
    }

    fn answer(&self, mut stream: TcpStream) -> std::io::Result<()> {
        stream.set_read_timeout(Some(REQUEST_TIMEOUT))?;
        stream.set_write_timeout(Some(REQUEST_TIMEOUT))?;
        let mut reader = BufReader::new(std::io::Read::take(stream.try_clone()?, 16 * 1024));
        let mut request = String::new();
        reader.read_line(&mut request)?;
        // The headers, up to the blank line that ends them.
        let mut header = String::new();
        while reader.read_line(&mut header)? > 2 {
            header.clear();
        }
        let path = request.split_whitespace().nth(1).unwrap_or_default();
        let (status, body) = match path.split('?').next() {
            Some("/metrics") => ("200 OK", self.text()),
            _ => ("404 Not Found", "mbtool serves /metrics\n".to_string()),
        };
        write!(
            stream,
            "HTTP/1.1 {status}\r\nContent-Type: text/plain; version=0.0.4\r\nContent-Length: {}\r\nConnection: close\r\n\r\n{body}",
            body.len()
        )
    }
}

/// A point's value as a gauge: numbers only.
fn number(value: &Value) -> Option<f64> {
    match value {
        Value::Unsigned(n) => Some(*n as f64),
        Value::Signed(n) => Some(*n as f64),
        Value::Float32(f) => Some(f64::from(*f)),
        Value::Float(f) | Value::Decimal(f, _) => Some(*f),
        Value::Text(_) => None,
    }
}

/// What kind of error a failure was, for `modbus_errors_total`.
fn kind(error: &RunError) -> &'static str {
    match error {
        RunError::Exception { .. } => "exception",
        RunError::Master(MasterError::Timeout { .. }) => "timeout",
        RunError::Master(MasterError::Io(_)) => "disconnected",
        RunError::Master(MasterError::BadFrame { .. } | MasterError::OutOfStep { .. }) => {
            "bad_frame"
        }
        _ => "other",
    }
}

/// A label value, escaped as the text format asks.
fn label(text: &str) -> String {
    text.replace('\\', "\\\\")
        .replace('"', "\\\"")
        .replace('\n', "\\n")
}

#[cfg(test)]
mod tests {
    use super::*;
    use mbtool_core::master::map::{MapRead, PointValue};

    #[test]
    fn a_value_is_shown_only_while_its_last_poll_read_it() {
        let metrics = Metrics::default();
        let read = MapRead {
            values: vec![PointValue {
                point: 0,
                raw: vec![1500],
                value: Value::Unsigned(1500),
            }],
            ..MapRead::default()
        };
        let polled = |outcome| Polled {
            device: 0,
            outcome,
            took: Duration::from_millis(3),
        };
        let points = [("speed", "rpm")];
        metrics.record("pump \"3\"", 17, &points, &polled(Outcome::Read(read)));
        let text = metrics.text();
        assert!(text.contains("modbus_value{device=\"pump \\\"3\\\"\",slave=\"17\",name=\"speed\",unit=\"rpm\"} 1500\n"), "{text}");
        assert!(
            text.contains(
                "modbus_response_seconds_bucket{device=\"pump \\\"3\\\"\",le=\"0.005\"} 1\n"
            ),
            "{text}"
        );
        metrics.record(
            "pump \"3\"",
            17,
            &points,
            &polled(Outcome::Down("refused".into())),
        );
        let text = metrics.text();
        assert!(!text.contains("modbus_value{"), "{text}");
        assert!(
            text.contains(
                "modbus_errors_total{device=\"pump \\\"3\\\"\",kind=\"disconnected\"} 1\n"
            ),
            "{text}"
        );
        assert!(
            text.contains("modbus_polls_total{device=\"pump \\\"3\\\"\"} 2\n"),
            "{text}"
        );
    }
}
