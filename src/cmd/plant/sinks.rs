//! Where each poll's row goes: the screen (or standard output), and the servers that
//! take rows (InfluxDB) and values (an MQTT broker), each through its buffer.

use std::io::Write;
use std::sync::{mpsc, Arc};
use std::time::{SystemTime, UNIX_EPOCH};

use anyhow::Result;

use super::load::Device;
use super::Tally;
use mbtool::output::plant::{PlantRow, PlantWriter};
use mbtool::sink::metrics::Metrics;
use mbtool::sink::mqtt::{Message, Topics};
use mbtool::sink::Buffer;
use mbtool_core::master::plant::{Outcome, Polled};

pub(super) struct Sinks<'a> {
    pub screen: &'a mut PlantWriter,
    /// InfluxDB's buffer, and the writer of its lines.
    pub influx: Option<(&'a Buffer<String>, PlantWriter)>,
    pub mqtt: Option<(&'a Buffer<Message>, &'a mut Published)>,
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

impl Sinks<'_> {
    fn row(
        &mut self,
        out: &mut dyn Write,
        device: &Device,
        index: usize,
        row: &PlantRow,
    ) -> std::io::Result<()> {
        self.screen.row(out, row)?;
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
