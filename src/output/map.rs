//! How the points of a map read are shown: name, reference, value with its unit and the
//! raw registers in hex; JSON with the stable keys of CLI.md; `name=value` lines; CSV.

use std::io::{self, Write};

use serde::Serialize;

use super::Format;
use super::{csv_field, new_table};
use mbtool_core::master::map::MapRead;
use mbtool_core::model::map::Point;
use mbtool_core::model::values::Value;

/// The keys of CLI.md, in its order.
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
    value: &'a Value,
    unit: &'a str,
    raw: &'a [u16],
    #[serde(skip_serializing_if = "str::is_empty")]
    description: &'a str,
    /// The point's own slave, where the map gives it one other than the command's.
    #[serde(skip_serializing_if = "Option::is_none")]
    slave: Option<u8>,
}

pub struct MapWriter {
    format: Format,
    colour: bool,
    csv_header_written: bool,
}

/// A map's reads as the rows of a poll.
pub struct MapRows<'a> {
    pub writer: MapWriter,
    pub slave: u8,
    pub points: Vec<&'a Point>,
}

impl super::PollRows for MapRows<'_> {
    type Item = MapRead;

    fn row(&mut self, out: &mut dyn Write, item: &MapRead, time: &str) -> io::Result<()> {
        self.writer
            .write_at(out, self.slave, &self.points, item, Some(time))
    }

    fn failure(&mut self, out: &mut dyn Write, time: &str, error: &str) -> io::Result<()> {
        match self.writer.format {
            Format::Json => {
                serde_json::to_writer(&mut *out, &super::JsonFailure { time, error })?;
                writeln!(out)
            }
            Format::Csv => {
                self.writer.header(out, true)?;
                writeln!(out, "{time},,,,,,{}", csv_field(error))
            }
            Format::Table | Format::Values => Ok(()),
        }
    }

    fn continuing(&mut self) {
        self.writer.csv_header_written = true;
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

    fn header(&mut self, out: &mut dyn Write, timed: bool) -> io::Result<()> {
        if !self.csv_header_written {
            let time = if timed { "time," } else { "" };
            let error = if timed { ",error" } else { "" };
            writeln!(out, "{time}name,ref,value,unit,raw{error}")?;
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

    /// A read, its rows starting with `time` when it is one of a poll's.
    pub fn write_at(
        &mut self,
        out: &mut dyn Write,
        slave: u8,
        points: &[&Point],
        read: &MapRead,
        time: Option<&str>,
    ) -> io::Result<()> {
        let rows = read
            .values
            .iter()
            .filter_map(|value| Some((points.get(value.point)?, value)));
        match self.format {
            Format::Json => {
                let points = rows
                    .map(|(point, value)| JsonPoint {
                        name: &point.name,
                        reference: point.reference(),
                        value: &value.value,
                        unit: &point.unit,
                        raw: &value.raw,
                        description: &point.description,
                        slave: point.slave.filter(|own| *own != slave),
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
                for (point, value) in rows {
                    writeln!(out, "{}={}", point.name, value.value)?;
                }
                Ok(())
            }
            Format::Csv => {
                self.header(out, time.is_some())?;
                for (point, value) in rows {
                    let (time, error) = match time {
                        Some(time) => (format!("{time},"), ","),
                        None => (String::new(), ""),
                    };
                    writeln!(
                        out,
                        "{time}{},{},{},{},{}{error}",
                        csv_field(&point.name),
                        point.reference(),
                        csv_field(&value.value.to_string()),
                        csv_field(&point.unit),
                        raw_text(point, &value.raw)
                    )?;
                }
                Ok(())
            }
            Format::Table => {
                let mut table = new_table(self.colour);
                table.set_header(["name", "ref", "value", "raw"]);
                for (point, value) in rows {
                    let shown = match point.unit.as_str() {
                        "" => value.value.to_string(),
                        unit => format!("{} {unit}", value.value),
                    };
                    table.add_row(vec![
                        point.name.clone(),
                        point.reference(),
                        shown,
                        raw_text(point, &value.raw),
                    ]);
                }
                writeln!(out, "{table}")
            }
        }
    }
}
