//! A plant's rows, one a device a poll: `name=value` lines, CSV with a column for every
//! point name of the plant, JSON Lines, or InfluxDB line protocol.

use std::collections::BTreeMap;
use std::io::{self, Write};

use serde::Serialize;

use super::{csv_field, Format};
use mbtool_core::model::shown::UNKNOWN;
use mbtool_core::model::values::Value;

/// How the rows are written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlantFormat {
    /// A line a row, for people.
    Lines,
    Csv,
    Json,
    /// InfluxDB line protocol.
    Influx,
}

impl PlantFormat {
    /// The format of `-o`, or InfluxDB's where asked.
    pub fn of(format: Format, influx: bool) -> PlantFormat {
        match (influx, format) {
            (true, _) => PlantFormat::Influx,
            (false, Format::Csv) => PlantFormat::Csv,
            (false, Format::Json) => PlantFormat::Json,
            (false, Format::Table | Format::Values) => PlantFormat::Lines,
        }
    }
}

/// One device's poll.
pub struct PlantRow<'a> {
    /// RFC 3339 with milliseconds and the local offset.
    pub time: &'a str,
    /// Nanoseconds since the Unix epoch, for InfluxDB.
    pub nanos: u128,
    pub device: &'a str,
    pub slave: u8,
    /// Each point's name and value, in the device's order; a point without a value is not
    /// here.
    pub values: Vec<(&'a str, &'a Value)>,
    /// Each point that has no value, and why; or the poll's own failure, under "".
    pub errors: Vec<(&'a str, String)>,
}

#[derive(Serialize)]
struct JsonRow<'a> {
    time: &'a str,
    device: &'a str,
    slave: u8,
    values: BTreeMap<&'a str, &'a Value>,
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    errors: BTreeMap<&'a str, &'a str>,
    /// Why the poll read nothing.
    #[serde(skip_serializing_if = "Option::is_none")]
    error: Option<&'a str>,
}

/// Writes a plant's rows.
pub struct PlantWriter {
    format: PlantFormat,
    /// Every point name of the plant, in order: the CSV's columns.
    columns: Vec<String>,
    header_written: bool,
}

impl PlantWriter {
    pub fn new(format: PlantFormat, columns: Vec<String>) -> Self {
        Self {
            format,
            columns,
            header_written: false,
        }
    }

    /// The CSV header, for a CSV writer.
    pub fn header(&self) -> Option<String> {
        let names: Vec<String> = self.columns.iter().map(|c| csv_field(c)).collect();
        (self.format == PlantFormat::Csv).then(|| format!("time,device,{},error", names.join(",")))
    }

    /// Rows appended to a file that has its header already.
    pub fn continuing(&mut self) {
        self.header_written = true;
    }

    pub fn row(&mut self, out: &mut dyn Write, row: &PlantRow) -> io::Result<()> {
        match self.format {
            PlantFormat::Lines => {
                let mut line = format!("{} {} ", super::time_of_day(row.time), row.device);
                let shown: Vec<String> = row
                    .values
                    .iter()
                    .map(|(name, value)| format!("{name}={value}"))
                    .chain(row.errors.iter().map(|(name, error)| match *name {
                        "" => format!("({error})"),
                        name => format!("{name}=- ({error})"),
                    }))
                    .collect();
                line.push_str(&shown.join(" "));
                writeln!(out, "{line}")
            }
            PlantFormat::Csv => {
                if let Some(header) = self.header().filter(|_| !self.header_written) {
                    self.header_written = true;
                    writeln!(out, "{header}")?;
                }
                let cells: Vec<String> = self
                    .columns
                    .iter()
                    .map(|column| {
                        let value = row.values.iter().find(|(name, _)| name == column);
                        csv_field(&value.map(|(_, v)| v.to_string()).unwrap_or_default())
                    })
                    .collect();
                let error = row.errors.first().map(|(name, error)| match *name {
                    "" => error.clone(),
                    name => format!("{name}: {error}"),
                });
                writeln!(
                    out,
                    "{},{},{},{}",
                    row.time,
                    csv_field(row.device),
                    cells.join(","),
                    csv_field(&error.unwrap_or_default())
                )
            }
            PlantFormat::Json => {
                let json = JsonRow {
                    time: row.time,
                    device: row.device,
                    slave: row.slave,
                    values: row.values.iter().copied().collect(),
                    errors: row
                        .errors
                        .iter()
                        .filter(|(name, _)| !name.is_empty())
                        .map(|(name, error)| (*name, error.as_str()))
                        .collect(),
                    error: row
                        .errors
                        .iter()
                        .find(|(name, _)| name.is_empty())
                        .map(|(_, error)| error.as_str()),
                };
                serde_json::to_writer(&mut *out, &json)?;
                writeln!(out)
            }
            PlantFormat::Influx => {
                // A value the device marks as none (unknown, NaN) is left out: written as
                // text into a numeric field, it would make InfluxDB refuse the batch.
                let fields: Vec<String> = row
                    .values
                    .iter()
                    .filter(|(_, value)| !no_number(value))
                    .map(|(name, value)| format!("{}={}", influx_key(name), influx_value(value)))
                    .collect();
                // A poll without a value has no line: InfluxDB takes no point without a
                // field, and a gap is a gap.
                if fields.is_empty() {
                    return Ok(());
                }
                writeln!(
                    out,
                    "modbus,device={},slave={} {} {}",
                    influx_key(row.device),
                    row.slave,
                    fields.join(","),
                    row.nanos
                )
            }
        }
    }
}

/// A tag or field key as the line protocol takes it: commas, equals signs and spaces
/// escaped.
fn influx_key(text: &str) -> String {
    let mut escaped = String::with_capacity(text.len());
    for c in text.chars() {
        if matches!(c, ',' | '=' | ' ' | '\\') {
            escaped.push('\\');
        }
        if c == '\n' {
            escaped.push_str("\\n");
            continue;
        }
        escaped.push(c);
    }
    escaped
}

/// Whether a value stands for no number: a point the device marks as none, a NaN or an
/// infinity.
fn no_number(value: &Value) -> bool {
    match value {
        Value::Text(text) => text == UNKNOWN,
        Value::Float32(f) => !f.is_finite(),
        Value::Float(f) | Value::Decimal(f, _) => !f.is_finite(),
        Value::Unsigned(_) | Value::Signed(_) => false,
    }
}

/// A field value: integers with `i`, floats as they are, text quoted.
fn influx_value(value: &Value) -> String {
    match value {
        Value::Unsigned(n) => format!("{n}i"),
        Value::Signed(n) => format!("{n}i"),
        Value::Float32(_) | Value::Float(..) | Value::Decimal(..) => value.to_string(),
        Value::Text(text) => format!("\"{}\"", text.replace('\\', "\\\\").replace('"', "\\\"")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_line_protocol_escapes_names_and_types_its_values() {
        let values = [
            Value::Unsigned(1500),
            Value::Float32(4.5),
            Value::Signed(-3),
            Value::Text("a\"b".into()),
        ];
        let row = PlantRow {
            time: "2026-11-28T07:00:00.000+00:00",
            nanos: 1_700_000_000_123_000_000,
            device: "pump 3,a",
            slave: 17,
            values: vec![
                ("speed", &values[0]),
                ("flow rate", &values[1]),
                ("t=1", &values[2]),
                ("label", &values[3]),
            ],
            errors: Vec::new(),
        };
        let mut out = Vec::new();
        PlantWriter::new(PlantFormat::Influx, Vec::new())
            .row(&mut out, &row)
            .unwrap();
        assert_eq!(
            String::from_utf8(out).unwrap(),
            "modbus,device=pump\\ 3\\,a,slave=17 speed=1500i,flow\\ rate=4.5,t\\=1=-3i,label=\"a\\\"b\" 1700000000123000000\n"
        );
    }

    #[test]
    fn a_value_that_is_no_number_is_no_field_of_the_line() {
        let values = [
            Value::Unsigned(1500),
            Value::Text(UNKNOWN.into()),
            Value::Float32(f32::NAN),
        ];
        let row = PlantRow {
            time: "T",
            nanos: 7,
            device: "inverter",
            slave: 1,
            values: vec![
                ("W", &values[0]),
                ("PhVphA", &values[1]),
                ("AphA", &values[2]),
            ],
            errors: Vec::new(),
        };
        let mut out = Vec::new();
        let mut writer = PlantWriter::new(PlantFormat::Influx, Vec::new());
        writer.row(&mut out, &row).unwrap();
        assert_eq!(
            String::from_utf8(out).unwrap(),
            "modbus,device=inverter,slave=1 W=1500i 7\n"
        );
        let none = PlantRow {
            values: vec![("PhVphA", &values[1])],
            ..row
        };
        let mut out = Vec::new();
        writer.row(&mut out, &none).unwrap();
        assert!(out.is_empty());
    }

    #[test]
    fn a_csv_row_has_a_cell_for_every_point_of_the_plant() {
        let value = Value::Unsigned(7);
        let row = PlantRow {
            time: "T",
            nanos: 0,
            device: "m2",
            slave: 2,
            values: vec![("b", &value)],
            errors: vec![("c", "no answer".into())],
        };
        let mut out = Vec::new();
        let mut writer =
            PlantWriter::new(PlantFormat::Csv, vec!["a".into(), "b".into(), "c".into()]);
        writer.row(&mut out, &row).unwrap();
        writer.row(&mut out, &row).unwrap();
        assert_eq!(
            String::from_utf8(out).unwrap(),
            "time,device,a,b,c,error\nT,m2,,7,,c: no answer\nT,m2,,7,,c: no answer\n"
        );
    }
}
