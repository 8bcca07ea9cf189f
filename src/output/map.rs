//! How the points of a map read are shown: name, reference, value with its unit and the
//! raw registers in hex; JSON with the stable keys docs/maps.md gives; `name=value` lines; CSV.

use std::io::{self, Write};

use serde::Serialize;

use super::wide::WideRows;
use super::Format;
use super::{csv_field, new_table};
use mbtool_core::master::map::{MapRead, PointValue};
use mbtool_core::model::map::Point;
use mbtool_core::model::values::Value;

/// The keys docs/maps.md gives, in its order.
#[derive(Serialize)]
struct JsonMap<'a> {
    #[serde(skip_serializing_if = "Option::is_none")]
    time: Option<&'a str>,
    slave: u8,
    points: Vec<JsonPoint<'a>>,
}

#[derive(Serialize)]
struct JsonPoint<'a> {
    name: &'a str,
    #[serde(rename = "ref")]
    reference: String,
    /// `null` for a point that failed.
    value: Option<&'a Value>,
    unit: &'a str,
    raw: &'a [u16],
    #[serde(skip_serializing_if = "str::is_empty")]
    description: &'a str,
    /// The point's own slave, where the map gives it one other than the command's.
    #[serde(skip_serializing_if = "Option::is_none")]
    slave: Option<u8>,
    /// Why the point has no value.
    #[serde(skip_serializing_if = "Option::is_none")]
    error: Option<&'a str>,
}

pub struct MapWriter {
    format: Format,
    colour: bool,
    csv_header_written: bool,
}

/// A map's reads as the rows of a poll.
pub struct MapRows<'a> {
    writer: MapWriter,
    slave: u8,
    points: Vec<&'a Point>,
    /// In CSV and the table, one line a poll, a column a point.
    wide: Option<WideRows>,
}

impl<'a> MapRows<'a> {
    pub fn new(writer: MapWriter, slave: u8, points: Vec<&'a Point>) -> Self {
        let wide = matches!(writer.format, Format::Csv | Format::Table).then(|| {
            let names = points.iter().map(|point| point.name.clone()).collect();
            WideRows::new(names, writer.colour)
        });
        Self {
            writer,
            slave,
            points,
            wide,
        }
    }
}

impl super::PollRows for MapRows<'_> {
    type Item = MapRead;

    fn row(&mut self, out: &mut dyn Write, item: &MapRead, time: &str) -> io::Result<()> {
        let Some(wide) = self.wide.as_mut() else {
            return self
                .writer
                .write_at(out, self.slave, &self.points, item, Some(time));
        };
        let format = self.writer.format;
        let readings = readings(item, self.points.len());
        let values = self.points.iter().zip(&readings).map(|(point, reading)| {
            let value = reading.as_ref()?.value()?;
            Some(match (format, point.unit.as_str()) {
                (Format::Table, unit) if !unit.is_empty() => format!("{value} {unit}"),
                _ => value.to_string(),
            })
        });
        let values = values.collect();
        let failed = self
            .points
            .iter()
            .zip(&readings)
            .find_map(|(point, reading)| {
                let error = reading.as_ref()?.error()?;
                Some(format!("{}: {error}", point.name))
            });
        wide.row(out, format, time, values, &failed.unwrap_or_default())
    }

    fn failure(&mut self, out: &mut dyn Write, time: &str, error: &str) -> io::Result<()> {
        if let Some(wide) = self.wide.as_mut() {
            return wide.gap(out, self.writer.format, time, error);
        }
        match self.writer.format {
            Format::Json => {
                serde_json::to_writer(&mut *out, &super::JsonFailure { time, error })?;
                writeln!(out)
            }
            Format::Csv | Format::Table | Format::Values => Ok(()),
        }
    }

    fn status(&self, item: &MapRead) -> u8 {
        item.first_failure()
            .map_or(0, |(_, error)| crate::error::run_exit_code(error))
    }

    fn continuing(&mut self) {
        self.writer.csv_header_written = true;
        if let Some(wide) = self.wide.as_mut() {
            wide.continuing();
        }
    }

    fn format(&self) -> Format {
        self.writer.format
    }
}

/// What a point read as: its registers in hex, or a coil's or input's 0 or 1.
fn raw_text(point: &Point, raw: &[u16]) -> String {
    if point.table.is_bits() {
        return raw.iter().map(u16::to_string).collect::<Vec<_>>().join(" ");
    }
    raw.iter()
        .map(|r| format!("{r:04X}"))
        .collect::<Vec<_>>()
        .join(" ")
}

impl MapWriter {
    pub fn new(format: Format, colour: bool) -> Self {
        Self {
            format,
            colour,
            csv_header_written: false,
        }
    }

    fn header(&mut self, out: &mut dyn Write) -> io::Result<()> {
        if !self.csv_header_written {
            writeln!(out, "name,ref,value,unit,raw,error")?;
            self.csv_header_written = true;
        }
        Ok(())
    }

    pub fn write(
        &mut self,
        out: &mut dyn Write,
        slave: u8,
        points: &[&Point],
        read: &MapRead,
    ) -> io::Result<()> {
        self.write_at(out, slave, points, read, None)
    }

    /// A read, its rows starting with `time` when it is one of a poll's. Every point has
    /// its row, in the order of the points: its value, or why it has none.
    pub fn write_at(
        &mut self,
        out: &mut dyn Write,
        slave: u8,
        points: &[&Point],
        read: &MapRead,
        time: Option<&str>,
    ) -> io::Result<()> {
        let rows: Vec<(&Point, Reading)> = points
            .iter()
            .zip(readings(read, points.len()))
            .filter_map(|(point, reading)| Some((*point, reading?)))
            .collect();
        match self.format {
            Format::Json => {
                let points = rows
                    .iter()
                    .map(|(point, reading)| JsonPoint {
                        name: &point.name,
                        reference: point.reference(),
                        value: reading.value(),
                        unit: &point.unit,
                        raw: reading.raw(),
                        description: &point.description,
                        slave: point.slave.filter(|own| *own != slave),
                        error: reading.error(),
                    })
                    .collect();
                serde_json::to_writer(
                    &mut *out,
                    &JsonMap {
                        time,
                        slave,
                        points,
                    },
                )?;
                writeln!(out)
            }
            Format::Values => {
                for (point, reading) in &rows {
                    match reading {
                        Reading::Value(value) => writeln!(out, "{}={}", point.name, value.value)?,
                        // A script reading `name=value` lines finds no value for the point.
                        Reading::Failed(_) => {}
                    }
                }
                Ok(())
            }
            Format::Csv => {
                self.header(out)?;
                for (point, reading) in &rows {
                    let value = reading.value().map(Value::to_string).unwrap_or_default();
                    writeln!(
                        out,
                        "{},{},{},{},{},{}",
                        csv_field(&point.name),
                        point.reference(),
                        csv_field(&value),
                        csv_field(&point.unit),
                        raw_text(point, reading.raw()),
                        csv_field(reading.error().unwrap_or_default())
                    )?;
                }
                Ok(())
            }
            Format::Table => {
                let mut table = new_table(self.colour);
                table.set_header(["name", "ref", "value", "raw"]);
                for (point, reading) in &rows {
                    let shown = match (reading, point.unit.as_str()) {
                        (Reading::Failed(error), _) => error.clone(),
                        (Reading::Value(value), "") => value.value.to_string(),
                        (Reading::Value(value), unit) => format!("{} {unit}", value.value),
                    };
                    table.add_row(vec![
                        point.name.clone(),
                        point.reference(),
                        shown,
                        raw_text(point, reading.raw()),
                    ]);
                }
                writeln!(out, "{table}")
            }
        }
    }
}

/// What became of one point of a read.
enum Reading<'a> {
    Value(&'a PointValue),
    Failed(String),
}

impl Reading<'_> {
    fn value(&self) -> Option<&Value> {
        match self {
            Reading::Value(value) => Some(&value.value),
            Reading::Failed(_) => None,
        }
    }

    fn raw(&self) -> &[u16] {
        match self {
            Reading::Value(value) => &value.raw,
            Reading::Failed(_) => &[],
        }
    }

    fn error(&self) -> Option<&str> {
        match self {
            Reading::Value(_) => None,
            Reading::Failed(error) => Some(error),
        }
    }
}

/// Each of `count` points' value, or why it has none, by the point's index; `None` for a
/// point the read did not ask. One pass over the read, however many points a map has.
fn readings(read: &MapRead, count: usize) -> Vec<Option<Reading<'_>>> {
    let mut readings: Vec<Option<Reading<'_>>> = (0..count).map(|_| None).collect();
    let failed = read.failed.iter().flat_map(|failure| {
        let error = failure.error.to_string();
        failure
            .points
            .iter()
            .map(move |index| (*index, Reading::Failed(error.clone())))
    });
    let missing = read
        .missing
        .iter()
        .map(|index| (*index, Reading::Failed("no such address".to_string())));
    let values = read
        .values
        .iter()
        .map(|value| (value.point, Reading::Value(value)));
    for (index, reading) in failed.chain(missing).chain(values) {
        if let Some(slot) = readings.get_mut(index) {
            *slot = Some(reading);
        }
    }
    readings
}
