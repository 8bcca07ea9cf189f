//! How `info` and `diag` show what a device said about itself: a table of names and
//! values for people (CSV and bare values from the same rows), one JSON object for scripts.

use std::io::{self, Write};

use serde_json::{json, Map, Value};

use super::Format;
use super::{csv_field, new_table};
use mbtool_core::codec::{DeviceObject, ExceptionCode};
use mbtool_core::master::device::Asked;
use mbtool_core::master::device::{Counter, Identification, RoundTrips, ServerId};
use mbtool_core::model::values::escape_text;

/// What one function gave: an answer, a refusal, or nothing in time.
#[derive(Clone, Debug)]
pub enum Outcome<T> {
    Answered(T),
    Refused(ExceptionCode),
    NoAnswer(String),
}

impl<T> From<Asked<T>> for Outcome<T> {
    fn from(asked: Asked<T>) -> Self {
        match asked {
            Asked::Answered(answer) => Outcome::Answered(answer),
            Asked::Refused(code) => Outcome::Refused(code),
        }
    }
}

impl<T> Outcome<T> {
    /// How a function that gave no answer is shown.
    fn failure(&self) -> Option<String> {
        match self {
            Outcome::Answered(_) => None,
            Outcome::Refused(code) if *code == ExceptionCode::ILLEGAL_FUNCTION => {
                Some(format!("not supported (exception {code})"))
            }
            Outcome::Refused(code) => Some(format!("refused: exception {code}")),
            Outcome::NoAnswer(why) => Some(format!("no answer: {why}")),
        }
    }

    /// The failure for JSON: `{"exception":1}` or `{"error":"..."}`.
    fn failure_json(&self) -> Value {
        match self {
            Outcome::Answered(_) => Value::Null,
            Outcome::Refused(code) => json!({ "exception": code.0 }),
            Outcome::NoAnswer(why) => json!({ "error": why }),
        }
    }
}

/// What `info` learnt.
pub struct InfoReport {
    pub slave: u8,
    pub identification: Outcome<Identification>,
    pub server_id: Outcome<ServerId>,
}

/// What `diag` learnt.
pub struct DiagReport {
    pub slave: u8,
    pub round_trips: Outcome<RoundTrips>,
    pub counters: Outcome<Vec<Counter>>,
    pub exception_status: Outcome<u8>,
    /// `--clear`: whether the counters were cleared.
    pub cleared: Option<Outcome<()>>,
}

/// An object's name: its standard name, or its number for the others.
fn object_name(id: u8) -> String {
    match DeviceObject::name(id) {
        "reserved" | "private" => format!("0x{id:02X}"),
        name => name.to_string(),
    }
}

fn conformity_text(conformity: u8) -> String {
    let level = match conformity & 0x7F {
        0x01 => "basic",
        0x02 => "regular",
        0x03 => "extended",
        _ => "unknown",
    };
    let single = if conformity & 0x80 != 0 {
        ", single objects too"
    } else {
        ""
    };
    format!("0x{conformity:02X} {level}{single}")
}

/// The data of report server id: text where every byte is printable, else hex.
fn server_data(data: &[u8]) -> String {
    if data.iter().all(|b| (0x20..=0x7E).contains(b)) {
        escape_text(data)
    } else {
        mbtool_core::codec::hex::spaced_hex(data)
    }
}

fn run_status(running: Option<bool>) -> &'static str {
    match running {
        Some(true) => "ON",
        Some(false) => "OFF",
        None => "not told (no byte reads 00 or FF)",
    }
}

fn info_rows(report: &InfoReport) -> Vec<(String, String)> {
    let mut rows = Vec::new();
    match &report.identification {
        Outcome::Answered(id) => {
            for object in &id.objects {
                rows.push((object_name(object.id), escape_text(&object.value)));
            }
            rows.push(("conformity".into(), conformity_text(id.conformity)));
            if id.cut_short {
                rows.push((
                    "identification".into(),
                    "cut short: the device stopped, or kept saying more follows".into(),
                ));
            }
        }
        other => rows.push((
            "identification (43/14)".into(),
            other.failure().unwrap_or_default(),
        )),
    }
    match &report.server_id {
        Outcome::Answered(server) => {
            if let Some(id) = server.id {
                rows.push(("server id".into(), format!("{id} (0x{id:02X})")));
            }
            rows.push(("run status".into(), run_status(server.running).into()));
            if !server.data.is_empty() {
                rows.push(("server data".into(), server_data(&server.data)));
            }
        }
        other => rows.push((
            "report server id (17)".into(),
            other.failure().unwrap_or_default(),
        )),
    }
    rows
}

fn info_json(report: &InfoReport) -> Value {
    let mut top = Map::new();
    top.insert("slave".into(), json!(report.slave));
    match &report.identification {
        Outcome::Answered(id) => {
            let objects: Map<String, Value> = id
                .objects
                .iter()
                .map(|o| (object_name(o.id), json!(escape_text(&o.value))))
                .collect();
            top.insert("identification".into(), Value::Object(objects));
            top.insert("conformity".into(), json!(id.conformity));
            top.insert("requests".into(), json!(id.requests));
            if id.cut_short {
                top.insert("cut_short".into(), json!(true));
            }
        }
        other => {
            top.insert("identification".into(), other.failure_json());
        }
    }
    match &report.server_id {
        Outcome::Answered(server) => {
            top.insert(
                "server_id".into(),
                json!({
                    "id": server.id,
                    "running": server.running,
                    "data": server_data(&server.data),
                }),
            );
        }
        other => {
            top.insert("server_id".into(), other.failure_json());
        }
    }
    Value::Object(top)
}

fn millis(duration: std::time::Duration) -> String {
    format!("{:.2} ms", duration.as_secs_f64() * 1e3)
}

fn diag_rows(report: &DiagReport) -> Vec<(String, String)> {
    let mut rows = Vec::new();
    let trips = match &report.round_trips {
        Outcome::Answered(trips) => {
            let asked = trips.times.len() + trips.lost;
            let mut text = format!("{} of {asked} answered", trips.times.len());
            if let Some((min, mean, max)) = trips.min_mean_max() {
                text.push_str(&format!(
                    ", min {} / mean {} / max {}",
                    millis(min),
                    millis(mean),
                    millis(max)
                ));
            }
            text.push_str(if trips.intact {
                ", every echo intact"
            } else {
                ", an echo came back changed"
            });
            text
        }
        other => other.failure().unwrap_or_default(),
    };
    rows.push(("round trips (08/00)".into(), trips));
    match &report.counters {
        Outcome::Answered(counters) => {
            for counter in counters {
                let value = match &counter.value {
                    Ok(Asked::Answered(value)) => value.to_string(),
                    Ok(Asked::Refused(code)) => {
                        Outcome::<()>::Refused(*code).failure().unwrap_or_default()
                    }
                    Err(data) => format!(
                        "not a 16-bit counter: the answer carried {}",
                        mbtool_core::codec::hex::spaced_hex(data)
                    ),
                };
                rows.push((
                    format!("{} (08/{:02X})", counter.name, counter.sub_function),
                    value,
                ));
            }
        }
        other => rows.push(("counters (08)".into(), other.failure().unwrap_or_default())),
    }
    let status = match &report.exception_status {
        Outcome::Answered(status) => format!("{status:08b} (0x{status:02X})"),
        other => other.failure().unwrap_or_default(),
    };
    rows.push(("exception status (07)".into(), status));
    if let Some(cleared) = &report.cleared {
        let text = match cleared {
            Outcome::Answered(()) => "cleared".to_string(),
            other => other.failure().unwrap_or_default(),
        };
        rows.push(("clear counters (08/0A)".into(), text));
    }
    rows
}

fn diag_json(report: &DiagReport) -> Value {
    let micros = |d: std::time::Duration| d.as_micros() as u64;
    let trips = match &report.round_trips {
        Outcome::Answered(trips) => {
            let times = trips.min_mean_max();
            json!({
                "answered": trips.times.len(),
                "lost": trips.lost,
                "min_us": times.map(|(min, _, _)| micros(min)),
                "mean_us": times.map(|(_, mean, _)| micros(mean)),
                "max_us": times.map(|(_, _, max)| micros(max)),
                "intact": trips.intact,
            })
        }
        other => other.failure_json(),
    };
    let counters = match &report.counters {
        Outcome::Answered(counters) => Value::Object(
            counters
                .iter()
                .map(|c| {
                    let value = match &c.value {
                        Ok(Asked::Answered(value)) => json!(value),
                        Ok(Asked::Refused(code)) => json!({ "exception": code.0 }),
                        Err(data) => {
                            json!({ "data": mbtool_core::codec::hex::spaced_hex(data) })
                        }
                    };
                    (c.name.replace(' ', "_").to_lowercase(), value)
                })
                .collect(),
        ),
        other => other.failure_json(),
    };
    let status = match &report.exception_status {
        Outcome::Answered(status) => json!(status),
        other => other.failure_json(),
    };
    let mut top = json!({
        "slave": report.slave,
        "round_trips": trips,
        "counters": counters,
        "exception_status": status,
    });
    if let (Some(cleared), Some(top)) = (&report.cleared, top.as_object_mut()) {
        let cleared = match cleared {
            Outcome::Answered(()) => json!(true),
            other => other.failure_json(),
        };
        top.insert("cleared".into(), cleared);
    }
    top
}

fn write_rows(
    out: &mut dyn Write,
    format: Format,
    rows: &[(String, String)],
    json: impl FnOnce() -> Value,
    colour: bool,
) -> io::Result<()> {
    match format {
        Format::Json => {
            serde_json::to_writer(&mut *out, &json())?;
            writeln!(out)
        }
        Format::Table => {
            let mut table = new_table(colour);
            for (name, value) in rows {
                table.add_row(vec![name, value]);
            }
            writeln!(out, "{table}")
        }
        Format::Csv => {
            writeln!(out, "name,value")?;
            for (name, value) in rows {
                writeln!(out, "{},{}", csv_field(name), csv_field(value))?;
            }
            Ok(())
        }
        Format::Values => {
            for (_, value) in rows {
                writeln!(out, "{value}")?;
            }
            Ok(())
        }
    }
}

pub fn write_info(
    out: &mut dyn Write,
    format: Format,
    report: &InfoReport,
    colour: bool,
) -> io::Result<()> {
    write_rows(
        out,
        format,
        &info_rows(report),
        || info_json(report),
        colour,
    )
}

pub fn write_diag(
    out: &mut dyn Write,
    format: Format,
    report: &DiagReport,
    colour: bool,
) -> io::Result<()> {
    write_rows(
        out,
        format,
        &diag_rows(report),
        || diag_json(report),
        colour,
    )
}
