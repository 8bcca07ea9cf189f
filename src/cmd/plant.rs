//! `mbtool poll PLANT...`: every device of a plant kept read, each at its rate, a worker a
//! port, until Ctrl-C, SIGTERM or `--for`; a summary per device at the end.

use std::io::Write;
use std::path::Path;
use std::sync::atomic::Ordering;
use std::sync::mpsc;
use std::time::{Duration, Instant, SystemTime, UNIX_EPOCH};

use anyhow::Result;

use mbtool::connection::{Connector, Role};
use mbtool::error::Error;
use mbtool::output::plant::{PlantFormat, PlantRow, PlantWriter};
use mbtool::output::{self, plural};
use mbtool::settings::{job, ConnectionSettings, Settings};
use mbtool::sink::metrics::Metrics;
use mbtool::sink::{influx, Buffer};
use mbtool_core::master::plant::{keep_read, Outcome, Polled, Scheduled};
use mbtool_core::model::map::{Point, RegisterMap};
use mbtool_core::model::map_file;
use mbtool_core::model::plant::{self, PlantDevice};

/// A device, ready to poll.
struct Device {
    plant: PlantDevice,
    points: Vec<Point>,
    connector: Connector,
}

pub fn run(settings: &Settings, job: &job::Plant) -> Result<u8> {
    let devices = load(settings, &job.files)?;
    let mut columns: Vec<String> = Vec::new();
    for point in devices.iter().flat_map(|d| &d.points) {
        if !columns.contains(&point.name) {
            columns.push(point.name.clone());
        }
    }
    let format = PlantFormat::of(settings.output.format, job.influx);
    let mut writer = PlantWriter::new(format, columns);
    // Bound before anything is polled, so that a port that is taken stops the command.
    let metrics = match &job.metrics {
        Some(address) => Some(serve_metrics(address)?),
        None => None,
    };
    let stop = super::shared::stop_on_signal()?;
    let deadline = job.duration.map(|d| Instant::now() + d);
    let (sender, polls) = mpsc::channel::<(usize, Polled, SystemTime)>();
    let max = settings.data.max_per_request;
    let verbose = settings.output.verbose;
    std::thread::scope(|scope| -> Result<u8> {
        for (_, members) in ports(&devices) {
            let sender = sender.clone();
            let flag = &stop.flag;
            let devices = &devices;
            scope.spawn(move || {
                let connector = &devices[members[0]].connector;
                let scheduled: Vec<Scheduled> = members
                    .iter()
                    .map(|i| Scheduled {
                        slave: devices[*i].plant.slave,
                        points: devices[*i].points.clone(),
                        every: devices[*i].plant.every,
                    })
                    .collect();
                let connect = || {
                    connector.connect().map(|connection| {
                        let mut master = connection.master;
                        if verbose {
                            master.trace(super::shared::tracer(connector.mode));
                        }
                        master
                    })
                };
                let wait = |time: Duration| {
                    let until = Instant::now() + time;
                    loop {
                        let now = Instant::now();
                        if flag.load(Ordering::SeqCst) || deadline.is_some_and(|d| now >= d) {
                            return true;
                        }
                        if now >= until {
                            return false;
                        }
                        std::thread::sleep((until - now).min(Duration::from_millis(50)));
                    }
                };
                keep_read(connect, &scheduled, max, wait, |polled| {
                    let device = members[polled.device];
                    let _ = sender.send((device, polled, SystemTime::now()));
                });
            });
        }
        drop(sender);
        // InfluxDB over HTTP: a buffer filled here, emptied by a thread of its own.
        let influx = job.influx_url.as_deref().map(|url| {
            let buffer = Buffer::new(job.buffer);
            let sending = buffer.clone();
            let sender = scope
                .spawn(move || influx::send(url, &sending, |said| mbtool::note!("mbtool: {said}")));
            (buffer, sender)
        });
        let mut sinks = Sinks {
            screen: &mut writer,
            influx: influx
                .as_ref()
                .map(|(buffer, _)| (buffer, PlantWriter::new(PlantFormat::Influx, Vec::new()))),
        };
        let mut tallies = vec![Tally::default(); devices.len()];
        let written = write_rows(&devices, polls, &mut sinks, metrics.as_ref(), &mut tallies);
        // Output that cannot be written (a closed pipe) ends the workers too.
        if written.is_err() {
            stop.flag.store(true, Ordering::SeqCst);
        }
        for (device, tally) in devices.iter().zip(&tallies) {
            mbtool::note!("mbtool: {}: {}", device.plant.name, tally.summary());
        }
        if let Some((buffer, sender)) = influx {
            buffer.close();
            if let Ok(delivered) = sender.join() {
                mbtool::note!("mbtool: InfluxDB: {}", delivered.summary(job.buffer));
            }
        }
        written?;
        Ok(match stop.flag.load(Ordering::SeqCst) {
            true => stop.exit_status(),
            false => 0,
        })
    })
}

/// Where each row goes: the screen (or standard output), and a server's buffer.
struct Sinks<'a> {
    screen: &'a mut PlantWriter,
    influx: Option<(&'a Buffer, PlantWriter)>,
}

impl Sinks<'_> {
    fn row(&mut self, out: &mut dyn Write, row: &PlantRow) -> std::io::Result<()> {
        self.screen.row(out, row)?;
        if let Some((buffer, lines)) = self.influx.as_mut() {
            let mut line = Vec::new();
            lines.row(&mut line, row)?;
            if !line.is_empty() {
                buffer.push(String::from_utf8_lossy(line.trim_ascii_end()).into_owned());
            }
        }
        Ok(())
    }
}

/// Each poll as it comes, until every worker has ended, tallied for the summary.
fn write_rows(
    devices: &[Device],
    polls: mpsc::Receiver<(usize, Polled, SystemTime)>,
    sinks: &mut Sinks,
    metrics: Option<&Metrics>,
    tallies: &mut [Tally],
) -> Result<()> {
    let mut out = output::stdout();
    for (index, polled, time) in polls {
        let device = &devices[index];
        tallies[index].add(&polled);
        if let Some(metrics) = metrics {
            let points: Vec<(&str, &str)> = device
                .points
                .iter()
                .map(|point| (point.name.as_str(), point.unit.as_str()))
                .collect();
            metrics.record(&device.plant.name, device.plant.slave, &points, &polled);
        }
        let row_time = chrono::DateTime::<chrono::Local>::from(time)
            .to_rfc3339_opts(chrono::SecondsFormat::Millis, false);
        let nanos = time.duration_since(UNIX_EPOCH).map_or(0, |d| d.as_nanos());
        let mut row = PlantRow {
            time: &row_time,
            nanos,
            device: &device.plant.name,
            slave: device.plant.slave,
            values: Vec::new(),
            errors: Vec::new(),
        };
        match &polled.outcome {
            Outcome::Read(read) => {
                for value in &read.values {
                    row.values
                        .push((device.points[value.point].name.as_str(), &value.value));
                }
                for failure in &read.failed {
                    for point in &failure.points {
                        let name = device.points[*point].name.as_str();
                        row.errors.push((name, failure.error.to_string()));
                    }
                }
                for point in &read.missing {
                    let name = device.points[*point].name.as_str();
                    row.errors.push((name, "no such address".into()));
                }
            }
            Outcome::Failed(error) => row.errors.push(("", error.to_string())),
            Outcome::Down(why) => row.errors.push(("", format!("not connected: {why}"))),
        }
        sinks.row(&mut out, &row)?;
        out.flush()?;
    }
    Ok(())
}

/// The devices of every plant file with their maps, or every fault of them at once.
fn load(settings: &Settings, files: &[std::path::PathBuf]) -> Result<Vec<Device>, Error> {
    let mut faults: Vec<String> = Vec::new();
    let mut devices: Vec<Device> = Vec::new();
    for file in files {
        let name = file.display().to_string();
        let text = match std::fs::read_to_string(file) {
            Ok(text) => text,
            Err(e) => {
                faults.push(format!("cannot read {name}: {e}"));
                continue;
            }
        };
        let folder = file.parent().unwrap_or(Path::new("."));
        let found: Vec<(PlantDevice, Result<Vec<Point>, String>)> = if is_plant(&text) {
            let parsed = plant::parse_all(&name, &text);
            if let Err(e) = parsed.faults {
                faults.extend(e.to_string().lines().map(String::from));
            }
            parsed
                .devices
                .into_iter()
                .map(|device| {
                    let map = map_file::load(&folder.join(&device.map));
                    (device, map.map(|map| map.points).map_err(|e| e.to_string()))
                })
                .collect()
        } else {
            // A Home Assistant configuration as it stands: its hubs are the devices.
            match map_file::load(file) {
                Ok(map) if map.hubs.is_empty() => {
                    faults.push(format!(
                        "{name} is a register map, not a plant: give a file of devices: (or a Home Assistant configuration with hubs), the map as a device's map:"
                    ));
                    continue;
                }
                Ok(map) => hub_devices(&name, &map, &mut faults),
                Err(e) => {
                    faults.extend(e.to_string().lines().map(String::from));
                    continue;
                }
            }
        };
        for (device, points) in found {
            if let Some(other) = devices.iter().find(|d| d.plant.name == device.name) {
                faults.push(format!(
                    "{name}:{}: the name '{}' is taken already, by a device of line {}",
                    device.line, device.name, other.plant.line
                ));
                continue;
            }
            let connection = ConnectionSettings {
                port: None,
                ..settings.connection.clone()
            }
            .with_map(Some(&device.connection));
            let connector = Connector::new(&connection, Role::Master);
            let at = format!("{name}:{}: {}", device.line, device.name);
            match (points, connector) {
                (Ok(points), Ok(connector)) => devices.push(Device {
                    plant: device,
                    points,
                    connector,
                }),
                (points, connector) => {
                    if let Err(e) = points {
                        faults.push(format!("{at}: {e}"));
                    }
                    if let Err(e) = connector {
                        faults.push(format!("{at}: {e}"));
                    }
                }
            }
        }
    }
    if faults.is_empty() && devices.is_empty() {
        faults.push("the plant has no device to poll".to_string());
    }
    match faults.is_empty() {
        true => Ok(devices),
        false => Err(Error::Faults(faults)),
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
struct Tally {
    polls: u64,
    read: u64,
    failed: u64,
    down: u64,
    time: Duration,
}

impl Tally {
    fn add(&mut self, polled: &Polled) {
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

/// Whether a file's text is mbtool's own plant form, by its `devices:` key.
fn is_plant(text: &str) -> bool {
    text.lines().any(|line| line.starts_with("devices:"))
}

/// How often Home Assistant reads an entity whose `scan_interval` is not given.
const HOME_ASSISTANT_RATE: Duration = Duration::from_secs(15);

/// The devices of a Home Assistant configuration: each hub's points by slave and by rate
/// (`scan_interval`, 15 s where not given), named after the hub (`meter`, `meter/2`,
/// `meter/2/5s`); an entity Home Assistant does not poll (`scan_interval: 0`) is left out.
fn hub_devices(
    file: &str,
    map: &RegisterMap,
    faults: &mut Vec<String>,
) -> Vec<(PlantDevice, Result<Vec<Point>, String>)> {
    let mut found = Vec::new();
    for hub in &map.hubs {
        let place = match &hub.place {
            Ok(place) => place,
            Err(why) => {
                faults.push(format!("{file}: hub {}: {why}", hub.name));
                continue;
            }
        };
        let mut groups: Vec<((u8, Duration), Vec<Point>)> = Vec::new();
        for (index, every) in &hub.points {
            let every = every.unwrap_or(HOME_ASSISTANT_RATE);
            if every.is_zero() {
                continue;
            }
            let point = &map.points[*index];
            let slave = point.slave.or(map.default_slave).unwrap_or(1);
            match groups.iter_mut().find(|(key, _)| *key == (slave, every)) {
                Some((_, points)) => points.push(point.clone()),
                None => groups.push(((slave, every), vec![point.clone()])),
            }
        }
        let slaves = {
            let mut slaves: Vec<u8> = groups.iter().map(|((slave, _), _)| *slave).collect();
            slaves.sort_unstable();
            slaves.dedup();
            slaves.len()
        };
        for ((slave, every), points) in &groups {
            let rates = groups.iter().filter(|((s, _), _)| s == slave).count();
            let name = match (slaves, rates) {
                (1, 1) => hub.name.clone(),
                (_, 1) => format!("{}/{slave}", hub.name),
                _ => format!("{}/{slave}/{}s", hub.name, every.as_secs()),
            };
            let device = PlantDevice {
                name,
                connection: place.clone(),
                slave: *slave,
                map: file.to_string(),
                every: *every,
                line: points.first().map_or(1, |point| point.line),
            };
            found.push((device, Ok(points.clone())));
        }
    }
    found
}
