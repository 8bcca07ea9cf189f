//! How `sunspec` shows a device: a table a model, each point with its value, unit and
//! reference (the points not implemented counted, not shown); JSON of every model and
//! point; CSV and `name=value` lines of the points that have a value.

use std::io::{self, Write};

use serde::Serialize;

use super::{csv_field, new_table, plural, Format};
use mbtool_core::model::address::{reference, Table};
use mbtool_core::model::values::Value;
use mbtool_core::sunspec::points::{NoValue, SunSpecPoint};
use mbtool_core::sunspec::walk::{ModelReading, SunSpecDevice};

fn point_ref(point: &SunSpecPoint) -> String {
    reference(Table::HoldingRegisters, point.address).to_string()
}

fn why_not(no_value: &NoValue) -> String {
    match no_value {
        NoValue::NotImplemented => "not implemented".into(),
        NoValue::ScaleFactor(why) => why.clone(),
        NoValue::Refused(code) => format!("the device refused its registers ({code})"),
    }
}

/// The value with its unit and meaning, as the table shows it.
fn shown(point: &SunSpecPoint, value: &Value) -> String {
    let mut text = value.to_string();
    if !point.units.is_empty() {
        text.push(' ');
        text.push_str(&point.units);
    }
    if let Some(meaning) = point.meaning.as_ref().filter(|m| !m.is_empty()) {
        text.push_str(&format!(" ({meaning})"));
    }
    text
}

#[derive(Serialize)]
struct JsonDevice<'a> {
    slave: u8,
    base: u16,
    requests: usize,
    models: Vec<JsonModel<'a>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    cut: Option<&'a str>,
}

#[derive(Serialize)]
struct JsonModel<'a> {
    id: u16,
    name: &'a str,
    #[serde(skip_serializing_if = "Option::is_none")]
    label: Option<&'a str>,
    #[serde(rename = "ref")]
    reference: String,
    length: u16,
    points: Vec<JsonPoint<'a>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    problem: Option<&'a str>,
}

#[derive(Serialize)]
struct JsonPoint<'a> {
    name: &'a str,
    label: &'a str,
    #[serde(rename = "ref")]
    reference: String,
    /// `null` for a point without a value; `error` says why.
    value: Option<&'a Value>,
    unit: &'a str,
    #[serde(skip_serializing_if = "Option::is_none")]
    meaning: Option<&'a str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    scale_factor: Option<i16>,
    raw: &'a [u16],
    #[serde(skip_serializing_if = "Option::is_none")]
    error: Option<String>,
}

fn json_model(model: &ModelReading) -> JsonModel<'_> {
    JsonModel {
        id: model.id,
        name: &model.name,
        label: model.label.as_deref(),
        reference: reference(Table::HoldingRegisters, model.address).to_string(),
        length: model.length,
        points: model
            .points
            .iter()
            .map(|point| JsonPoint {
                name: &point.name,
                label: &point.label,
                reference: point_ref(point),
                value: point.value.as_ref().ok(),
                unit: &point.units,
                meaning: point.meaning.as_deref(),
                scale_factor: point.scale_factor,
                raw: &point.raw,
                error: point.value.as_ref().err().map(why_not),
            })
            .collect(),
        problem: model.problem.as_deref(),
    }
}

/// Writes the device as `format` says.
pub fn write_device(
    out: &mut dyn Write,
    format: Format,
    slave: u8,
    device: &SunSpecDevice,
    colour: bool,
) -> io::Result<()> {
    let valued = || {
        device.models.iter().flat_map(|model| {
            model
                .points
                .iter()
                .filter_map(|point| Some((point, point.value.as_ref().ok()?)))
        })
    };
    match format {
        Format::Json => {
            let json = JsonDevice {
                slave,
                base: device.base,
                requests: device.requests,
                models: device.models.iter().map(json_model).collect(),
                cut: device.cut.as_ref().map(|cut| cut.reason.as_str()),
            };
            serde_json::to_writer(&mut *out, &json)?;
            writeln!(out)
        }
        Format::Values => {
            for (point, value) in valued() {
                writeln!(out, "{}={value}", point.name)?;
            }
            Ok(())
        }
        Format::Csv => {
            writeln!(out, "model,name,ref,value,unit,meaning,raw,error")?;
            for model in &device.models {
                for point in &model.points {
                    // Points not implemented are left out, as from the table.
                    let (value, error) = match &point.value {
                        Ok(value) => (value.to_string(), String::new()),
                        Err(NoValue::NotImplemented) => continue,
                        Err(why) => (String::new(), why_not(why)),
                    };
                    let raw: Vec<String> = point.raw.iter().map(|r| format!("{r:04X}")).collect();
                    writeln!(
                        out,
                        "{},{},{},{},{},{},{},{}",
                        model.id,
                        csv_field(&point.name),
                        point_ref(point),
                        csv_field(&value),
                        csv_field(&point.units),
                        csv_field(point.meaning.as_deref().unwrap_or_default()),
                        raw.join(" "),
                        csv_field(&error)
                    )?;
                }
            }
            Ok(())
        }
        Format::Table => {
            for model in &device.models {
                write_model_table(out, model, colour)?;
            }
            Ok(())
        }
    }
}

fn write_model_table(out: &mut dyn Write, model: &ModelReading, colour: bool) -> io::Result<()> {
    let label = model
        .label
        .as_deref()
        .map(|label| format!(" ({label})"))
        .unwrap_or_default();
    writeln!(
        out,
        "model {} {}{label} at {}, {}",
        model.id,
        model.name,
        reference(Table::HoldingRegisters, model.address),
        plural(usize::from(model.length), "register")
    )?;
    let mut table = new_table(colour);
    table.set_header(["point", "value", "ref"]);
    let mut missing = 0;
    for point in &model.points {
        match &point.value {
            Ok(value) => {
                table.add_row([point.name.clone(), shown(point, value), point_ref(point)]);
            }
            Err(NoValue::NotImplemented) => missing += 1,
            Err(why) => {
                let why = why_not(why);
                table.add_row([
                    point.name.clone(),
                    format!("no value: {why}"),
                    point_ref(point),
                ]);
            }
        }
    }
    if !table.is_empty() {
        writeln!(out, "{table}")?;
    }
    if missing > 0 {
        writeln!(
            out,
            "{} not implemented by the device",
            plural(missing, "point")
        )?;
    }
    if let Some(problem) = &model.problem {
        writeln!(out, "{problem}")?;
    }
    writeln!(out)
}
