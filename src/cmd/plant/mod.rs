//! `mbtool poll PLANT...`: every device of a plant kept read, each at its rate, a worker a
//! port, until Ctrl-C, SIGTERM or `--for`; a summary per device at the end.

mod load;
mod sinks;
mod worker;

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{mpsc, Arc};
use std::time::{Duration, Instant, SystemTime};

use anyhow::Result;

use mbtool::error::Error;
use mbtool::output::plant::{PlantFormat, PlantWriter};
use mbtool::output::plural;
use mbtool::settings::{job, Settings};
use mbtool::sink::metrics::Metrics;
use mbtool::sink::mqtt::{Broker, Message, Topics};
use mbtool::sink::{influx, Buffer};
use mbtool_core::master::map::{write_request, written_value};
use mbtool_core::master::plant::{Outcome, Polled, Scheduled};
use mbtool_core::model::map::Point;

use load::{load, Device};
use sinks::{write_rows, LogFile, Published, Sinks};
use worker::{Worker, Write};

pub fn run(settings: &Settings, job: &job::Plant) -> Result<u8> {
    let devices = load(settings, &job.files)?;
    let mut columns: Vec<String> = Vec::new();
    for point in devices.iter().flat_map(|d| &d.points) {
        if !columns.contains(&point.name) {
            columns.push(point.name.clone());
        }
    }
    let format = PlantFormat::of(settings.output.format, job.influx);
    let mut logs = job
        .logs
        .iter()
        .map(|path| LogFile::open(path, &columns))
        .collect::<Result<Vec<_>>>()?;
    let mut screen = PlantWriter::new(format, columns);
    let named: Vec<(&str, &[Point])> = devices
        .iter()
        .map(|d| (d.plant.name.as_str(), d.points.as_slice()))
        .collect();
    let broker = match &job.mqtt {
        Some(mqtt) => {
            let topics = Topics::new(&mqtt.prefix, &named);
            let clashes = topics.clashes(&named);
            if !clashes.is_empty() {
                return Err(Error::Faults(clashes).into());
            }
            let broker = Broker::new(mqtt, &topics.status()).map_err(Error::usage)?;
            Some((broker, topics))
        }
        None => None,
    };
    // Bound before anything is polled, so that a port that is taken stops the command.
    let metrics = match &job.metrics {
        Some(address) => Some(serve_metrics(address)?),
        None => None,
    };
    let stop = super::shared::stop_on_signal()?;
    let deadline = job.duration.map(|d| Instant::now() + d);
    let (polled, polls) = mpsc::channel::<(usize, Polled, SystemTime)>();
    let ports = ports(&devices);
    // Where a write to a device goes: its port's worker, and its index there.
    let mut writers = Vec::new();
    let mut reaches = vec![(0, 0); devices.len()];
    // Set when polling ends, by a signal or at the end of --for.
    let ending = Arc::new(AtomicBool::new(false));
    std::thread::scope(|scope| -> Result<u8> {
        scope.spawn(|| {
            while !ending.load(Ordering::SeqCst) {
                let over = deadline.is_some_and(|d| Instant::now() >= d);
                if over || stop.flag.load(Ordering::SeqCst) {
                    ending.store(true, Ordering::SeqCst);
                }
                std::thread::sleep(Duration::from_millis(20));
            }
        });
        for (port, (_, members)) in ports.iter().enumerate() {
            let (write, writes) = mpsc::channel();
            writers.push(write);
            for (local, device) in members.iter().enumerate() {
                reaches[*device] = (port, local);
            }
            let scheduled: Vec<Scheduled> = members
                .iter()
                .map(|i| Scheduled {
                    slave: devices[*i].plant.slave,
                    points: devices[*i].points.clone(),
                    every: devices[*i].plant.every,
                })
                .collect();
            let worker = Worker {
                connector: &devices[members[0]].connector,
                verbose: settings.output.verbose,
                ending: Arc::clone(&ending),
                members,
                polls: polled.clone(),
                writes,
                writing: String::new(),
            };
            let max = settings.data.max_per_request;
            scope.spawn(move || worker.run(&scheduled, max));
        }
        drop(polled);
        let tell = |said: &str| mbtool::note!("mbtool: {said}");
        // InfluxDB over HTTP: a buffer filled here, emptied by a thread of its own.
        let influx = job.influx_server.as_ref().map(|server| {
            let buffer = Buffer::new(job.buffer);
            let sending = buffer.clone();
            (
                buffer,
                scope.spawn(move || influx::send(server, &sending, tell)),
            )
        });
        let reaches = &reaches;
        let mut mqtt = broker.map(|(broker, topics)| {
            // --buffer counts rows: a row is a message a value, and one of availability.
            let widest = devices.iter().map(|d| d.points.len()).max().unwrap_or(0);
            let buffer = Buffer::new(job.buffer.saturating_mul(widest + 1));
            let sending = buffer.clone();
            let (retain, discovery) = job
                .mqtt
                .as_ref()
                .map(|m| (m.retain, m.discovery.clone()))
                .unwrap_or_default();
            let mut announce = match &discovery {
                Some(prefix) => topics.discovery(prefix, &named),
                None => Vec::new(),
            };
            announce.push(Message {
                topic: topics.status(),
                payload: "online".into(),
                retain: true,
            });
            let subscriptions = topics.set_filters();
            let topics = Arc::new(topics);
            let published = Published::new(Arc::clone(&topics), retain, devices.len());
            let set = writes_asked(&devices, topics, writers, reaches, tell);
            let sender = scope.spawn(move || {
                broker.run(
                    |sender| sender.send(&sending, &subscriptions, &announce),
                    set,
                    tell,
                )
            });
            (buffer, sender, published)
        });
        let mut sinks = Sinks {
            screen: &mut screen,
            influx: influx
                .as_ref()
                .map(|(buffer, _)| (buffer, PlantWriter::new(PlantFormat::Influx, Vec::new()))),
            mqtt: mqtt
                .as_mut()
                .map(|(buffer, _, published)| (&*buffer, published)),
            logs: &mut logs,
        };
        let mut tallies = vec![Tally::default(); devices.len()];
        let written = write_rows(&devices, polls, &mut sinks, metrics.as_ref(), &mut tallies);
        drop(sinks);
        // Output that cannot be written (a closed pipe) ends the workers too.
        if written.is_err() {
            stop.flag.store(true, Ordering::SeqCst);
        }
        ending.store(true, Ordering::SeqCst);
        for (device, tally) in devices.iter().zip(&tallies) {
            mbtool::note!("mbtool: {}: {}", device.plant.name, tally.summary());
        }
        // Both sinks given their last try at once.
        if let Some((buffer, _)) = &influx {
            buffer.close();
        }
        if let Some((buffer, _, _)) = &mqtt {
            buffer.close();
        }
        if let Some((_, sender)) = influx {
            if let Ok(delivered) = sender.join() {
                mbtool::note!("mbtool: InfluxDB: {}", delivered.summary(job.buffer, "row"));
            }
        }
        if let Some((_, sender, _)) = mqtt {
            if let Ok(delivered) = sender.join() {
                mbtool::note!("mbtool: MQTT: {}", delivered.summary(job.buffer, "message"));
            }
        }
        for said in logs.iter().filter_map(LogFile::summary) {
            mbtool::note!("mbtool: {said}");
        }
        written?;
        // Rows that a --log file could not take make it an I/O failure.
        let lost = logs.iter().any(|log| log.lost > 0);
        Ok(match (stop.flag.load(Ordering::SeqCst), lost) {
            (true, _) => stop.exit_status(),
            (false, true) => 1,
            (false, false) => 0,
        })
    })
}

/// What is done with a value published to a `.../set` topic: the point's write, checked
/// against the map, handed to the worker of the device's port; or why not, told.
fn writes_asked<'a>(
    devices: &'a [Device],
    topics: Arc<Topics>,
    writers: Vec<mpsc::Sender<Write>>,
    reaches: &'a [(usize, usize)],
    tell: impl Fn(&str) + Send + 'a,
) -> impl Fn(&str, &str) + Send + 'a {
    move |topic: &str, payload: &str| {
        let Some((device, point)) = topics.setting(topic) else {
            return tell(&format!(
                "{topic}: no point of the plant has this topic; nothing written"
            ));
        };
        let device_name = &devices[device].plant.name;
        let point = &devices[device].points[point];
        match write_request(point, payload) {
            Ok(request) => {
                let (port, local) = reaches[device];
                // What the point holds of the value asked, where it holds less (12.5 in
                // a whole-number point is 13).
                let written = written_value(point, &request).map(|v| v.to_string());
                let number = |text: &str| text.trim().parse::<f64>().ok();
                let said = match written {
                    Some(written)
                        if number(&written)
                            .zip(number(payload))
                            .is_some_and(|(w, p)| w != p) =>
                    {
                        format!(
                            "{device_name}: {}={written} (asked {payload} on {topic})",
                            point.name
                        )
                    }
                    _ => format!("{device_name}: {}={payload} (asked on {topic})", point.name),
                };
                let write = Write {
                    device: local,
                    request,
                    said,
                };
                // The port's worker has ended: polling is ending.
                if let Err(unsent) = writers[port].send(write) {
                    tell(&format!(
                        "{} not written: polling ended first",
                        unsent.0.said
                    ));
                }
            }
            Err(why) => tell(&format!("{topic}: {why}; nothing written")),
        }
    }
}

/// The devices of each port, by index: the devices one connection reaches, polled in turn
/// by one worker (a serial line, a TCP host and port).
fn ports(devices: &[Device]) -> Vec<(String, Vec<usize>)> {
    let mut ports: Vec<(String, Vec<usize>)> = Vec::new();
    for (index, device) in devices.iter().enumerate() {
        let port = device.connector.endpoint.to_string();
        match ports.iter_mut().find(|(known, _)| *known == port) {
            Some((_, members)) => members.push(index),
            None => ports.push((port, vec![index])),
        }
    }
    ports
}

/// What a device's polls gave, for the summary.
#[derive(Clone, Default)]
pub(super) struct Tally {
    polls: u64,
    read: u64,
    failed: u64,
    down: u64,
    time: Duration,
}

impl Tally {
    pub(super) fn add(&mut self, polled: &Polled) {
        self.polls += 1;
        match &polled.outcome {
            Outcome::Read(read) if read.failed.is_empty() => {
                self.read += 1;
                self.time += polled.took;
            }
            Outcome::Read(_) | Outcome::Failed(_) => self.failed += 1,
            Outcome::Down(_) => self.down += 1,
        }
    }

    fn summary(&self) -> String {
        let mean = match self.read {
            0 => String::new(),
            n => format!(
                "; mean {} ms",
                (self.time / u32::try_from(n).unwrap_or(u32::MAX)).as_millis()
            ),
        };
        format!(
            "{}, {} read whole, {} with failures, {} while not connected{mean}",
            plural(self.polls as usize, "poll"),
            self.read,
            self.failed,
            self.down
        )
    }
}

/// `--metrics ADDR`: the metrics served on ADDR (`:9502` is 127.0.0.1's) by a thread that
/// lasts as long as the process.
fn serve_metrics(address: &str) -> Result<Metrics> {
    let address = match address.strip_prefix(':') {
        Some(port) => format!("127.0.0.1:{port}"),
        None => address.to_string(),
    };
    let (host, port) = address
        .rsplit_once(':')
        .and_then(|(host, port)| Some((host, port.parse::<u16>().ok()?)))
        .ok_or_else(|| {
            Error::usage(format!(
                "--metrics {address}: give ADDRESS:PORT, as 127.0.0.1:9502"
            ))
        })?;
    let endpoint = mbtool_core::transport::Endpoint::Tcp {
        host: host.to_string(),
        port,
    };
    let listener = mbtool::connection::listen(&endpoint, host, port)?;
    mbtool::note!(
        "mbtool: metrics on http://{}/metrics",
        listener.local_addr()?
    );
    let metrics = Metrics::default();
    let serving = metrics.clone();
    std::thread::spawn(move || serving.serve(listener));
    Ok(metrics)
}
