//! Where each poll's row goes: the screen (or standard output), and the servers that
//! take rows (InfluxDB) and values (an MQTT broker), each through its buffer.

use std::io::{BufRead, BufReader, Read, Write};
use std::path::{Path, PathBuf};
use std::sync::{mpsc, Arc};
use std::time::{SystemTime, UNIX_EPOCH};

use anyhow::Result;

use super::load::Device;
use super::Tally;
use mbtool::error::Error;
use mbtool::output::plant::{PlantFormat, PlantRow, PlantWriter};
use mbtool::sink::metrics::Metrics;
use mbtool::sink::mqtt::{Message, Topics};
use mbtool::sink::Buffer;
use mbtool_core::master::plant::{Outcome, Polled};

pub(super) struct Sinks<'a> {
    pub screen: &'a mut PlantWriter,
    /// InfluxDB's buffer, and the writer of its lines.
    pub influx: Option<(&'a Buffer<String>, PlantWriter)>,
    pub mqtt: Option<(&'a Buffer<Message>, &'a mut Published)>,
    pub logs: &'a mut [LogFile],
}

/// What is published to the broker for a poll.
pub(super) struct Published {
    topics: Arc<Topics>,
    retain: bool,
    /// Each device's availability as last published.
    online: Vec<Option<bool>>,
}

impl Published {
    pub fn new(topics: Arc<Topics>, retain: bool, devices: usize) -> Published {
        Published {
            topics,
            retain,
            online: vec![None; devices],
        }
    }

    /// A message a value of the row; the device's availability where it changed (online
    /// when the poll read any value).
    fn messages(&mut self, device: &Device, index: usize, row: &PlantRow) -> Vec<Message> {
        let mut messages = Vec::with_capacity(row.values.len() + 1);
        let online = !row.values.is_empty();
        if self.online[index] != Some(online) {
            self.online[index] = Some(online);
            messages.push(Message {
                topic: self.topics.available(index),
                payload: if online { "online" } else { "offline" }.into(),
                retain: true,
            });
        }
        for (name, value) in &row.values {
            if let Some(point) = device.points.iter().position(|p| p.name == *name) {
                messages.push(Message {
                    topic: self.topics.value(index, point),
                    payload: value.to_string(),
                    retain: self.retain,
                });
            }
        }
        messages
    }
}

/// A file every row is appended to (`--log`): CSV for a `.csv` name, JSON Lines else. A
/// row that cannot be written (a full disk) is taken back out, so that the file holds only
/// whole rows, and counted; the polling goes on.
pub(super) struct LogFile {
    path: PathBuf,
    file: std::fs::File,
    rows: PlantWriter,
    /// Rows not saved.
    pub lost: u64,
    failing: bool,
}

impl LogFile {
    /// Opens `path` to append to, checking that a CSV already there has the plant's
    /// columns; a new CSV gets its header.
    pub fn open(path: &Path, columns: &[String]) -> Result<LogFile> {
        let csv = path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("csv"));
        let format = if csv {
            PlantFormat::Csv
        } else {
            PlantFormat::Json
        };
        let mut rows = PlantWriter::new(format, columns.to_vec());
        let cannot = |e: std::io::Error| anyhow::anyhow!("cannot open {}: {e}", path.display());
        let mut file = std::fs::OpenOptions::new()
            .append(true)
            .create(true)
            .read(true)
            .open(path)
            .map_err(cannot)?;
        if let Some(header) = rows.header() {
            // The header of a file with rows already (not of a device file, which
            // never ends), read no further than a header can be long.
            let mut first = String::new();
            if file.metadata().is_ok_and(|m| m.is_file() && m.len() > 0) {
                BufReader::new(Read::take(&file, 1 << 20))
                    .read_line(&mut first)
                    .map_err(cannot)?;
            }
            match first.trim_end() {
                "" => writeln!(file, "{header}").map_err(|e| {
                    anyhow::anyhow!("cannot write {}: {e}", path.display())
                })?,
                given if given == header => {}
                // The same columns in another order (the plant's devices given in
                // another order): the rows take the file's.
                given if same_columns(given, columns) => {
                    let names = given.split(',').collect::<Vec<_>>();
                    let order = names[2..names.len() - 1].iter().map(|n| n.to_string());
                    rows = PlantWriter::new(format, order.collect());
                }
                given => {
                    return Err(Error::usage(format!(
                        "{} has other columns ({given}) than this plant's ({header}): give a new file to --log",
                        path.display()
                    ))
                    .into())
                }
            }
            rows.continuing();
        }
        Ok(LogFile {
            path: path.to_path_buf(),
            file,
            rows,
            lost: 0,
            failing: false,
        })
    }

    fn row(&mut self, row: &PlantRow) {
        let mut bytes = Vec::new();
        if self.rows.row(&mut bytes, row).is_err() || bytes.is_empty() {
            return;
        }
        let before = self.file.metadata().map(|m| m.len());
        match self.file.write_all(&bytes) {
            Ok(()) if self.failing => {
                self.failing = false;
                mbtool::note!("mbtool: {}: rows are saved again", self.path.display());
            }
            Ok(()) => {}
            Err(error) => {
                self.lost += 1;
                // What went in of the row is taken back out.
                if let Ok(length) = before {
                    let _ = self.file.set_len(length);
                }
                if !std::mem::replace(&mut self.failing, true) {
                    mbtool::note!(
                        "mbtool: cannot write {}: {error}; its rows are not saved until it can be written",
                        self.path.display()
                    );
                }
            }
        }
    }

    /// `plant.csv: 12 rows not saved`, where rows were lost.
    pub fn summary(&self) -> Option<String> {
        (self.lost > 0).then(|| {
            format!(
                "{}: {} not saved",
                self.path.display(),
                mbtool::output::plural(self.lost as usize, "row")
            )
        })
    }
}

/// Whether a CSV header holds `columns` (between time, device and error) in some order;
/// names that CSV quotes are not compared so.
fn same_columns(header: &str, columns: &[String]) -> bool {
    let names: Vec<&str> = header.split(',').collect();
    let plain = columns.iter().all(|c| !c.contains([',', '"', '\n']));
    let mut given: Vec<&str> = match names.as_slice() {
        ["time", "device", middle @ .., "error"] => middle.to_vec(),
        _ => return false,
    };
    let mut ours: Vec<&str> = columns.iter().map(String::as_str).collect();
    given.sort_unstable();
    ours.sort_unstable();
    plain && given == ours
}

impl Sinks<'_> {
    fn row(
        &mut self,
        out: &mut dyn Write,
        device: &Device,
        index: usize,
        row: &PlantRow,
    ) -> std::io::Result<()> {
        self.screen.row(out, row)?;
        for log in self.logs.iter_mut() {
            log.row(row);
        }
        if let Some((buffer, lines)) = self.influx.as_mut() {
            let mut line = Vec::new();
            lines.row(&mut line, row)?;
            if !line.is_empty() {
                buffer.push(String::from_utf8_lossy(line.trim_ascii_end()).into_owned());
            }
        }
        if let Some((buffer, published)) = self.mqtt.as_mut() {
            for message in published.messages(device, index, row) {
                buffer.push(message);
            }
        }
        Ok(())
    }
}

/// Each poll as it comes, until every worker has ended, tallied for the summary.
pub(super) fn write_rows(
    devices: &[Device],
    polls: mpsc::Receiver<(usize, Polled, SystemTime)>,
    sinks: &mut Sinks,
    metrics: Option<&Metrics>,
    tallies: &mut [Tally],
) -> Result<()> {
    let mut out = mbtool::output::stdout();
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
        sinks.row(&mut out, device, index, &row)?;
        out.flush()?;
    }
    Ok(())
}
