//! How `read --layouts` and `read --expect` show the registers read: a row a layout, and
//! for `--expect` the map line of the best.

use std::io::{self, Write};

use serde::Serialize;

use super::{csv_field, new_table, Format};
use mbtool_core::input::choice::Choice;
use mbtool_core::model::address::{reference, Table};
use mbtool_core::model::layouts::{Candidate, Reading};
use mbtool_core::model::values::{Value, ValueType};

/// Where the registers read start.
pub struct Start {
    /// Their table.
    pub table: Table,
    /// The first register's protocol address.
    pub address: u16,
}

impl Start {
    /// The reference of the register `offset` after the first.
    fn reference(&self, offset: usize) -> String {
        reference(self.table, self.address.wrapping_add(offset as u16)).into()
    }
}

#[derive(Serialize)]
struct JsonLayout<'a> {
    #[serde(rename = "ref")]
    reference: String,
    #[serde(rename = "type")]
    value_type: String,
    order: &'static str,
    value: &'a Value,
    registers: &'a [u16],
    #[serde(skip_serializing_if = "Option::is_none")]
    distance: Option<f64>,
}

/// A layout's type as a map's `type` column takes it: text is `string:N`.
fn type_name(reading: &Reading) -> String {
    match reading.layout.value_type {
        ValueType::Ascii => format!("string:{}", reading.registers.len()),
        value_type => value_type.name().to_string(),
    }
}

fn hex_of(registers: &[u16]) -> String {
    let words: Vec<String> = registers.iter().map(|r| format!("{r:04X}")).collect();
    words.join(" ")
}

fn row<'a>(start: &Start, reading: &'a Reading, distance: Option<f64>) -> JsonLayout<'a> {
    JsonLayout {
        reference: start.reference(reading.offset),
        value_type: type_name(reading),
        order: reading.layout.order.name(),
        value: &reading.value,
        registers: &reading.registers,
        distance,
    }
}

fn write_rows(
    out: &mut dyn Write,
    format: Format,
    rows: &[JsonLayout],
    colour: bool,
) -> io::Result<()> {
    let ranked = rows.iter().any(|row| row.distance.is_some());
    match format {
        Format::Json => {
            for row in rows {
                serde_json::to_writer(&mut *out, row)?;
                writeln!(out)?;
            }
            Ok(())
        }
        Format::Values => rows
            .iter()
            .try_for_each(|row| writeln!(out, "{}", row.value)),
        Format::Csv => {
            writeln!(
                out,
                "ref,type,order,hex,value{}",
                if ranked { ",distance" } else { "" }
            )?;
            for row in rows {
                write!(
                    out,
                    "{},{},{},{},{}",
                    row.reference,
                    row.value_type,
                    row.order,
                    hex_of(row.registers),
                    csv_field(&row.value.to_string())
                )?;
                match row.distance {
                    Some(distance) => writeln!(out, ",{distance}")?,
                    None => writeln!(out)?,
                }
            }
            Ok(())
        }
        Format::Table => {
            let mut table = new_table(colour);
            let mut header = vec!["ref", "type", "order", "hex", "value"];
            if ranked {
                header.push("off by");
            }
            table.set_header(header);
            for row in rows {
                let mut cells = vec![
                    row.reference.clone(),
                    row.value_type.clone(),
                    row.order.to_string(),
                    hex_of(row.registers),
                    row.value.to_string(),
                ];
                if let Some(distance) = row.distance {
                    cells.push(distance.to_string());
                }
                table.add_row(cells);
            }
            writeln!(out, "{table}")
        }
    }
}

/// Every layout of the registers read from the first.
pub fn write_layouts(
    out: &mut dyn Write,
    format: Format,
    colour: bool,
    start: &Start,
    readings: &[Reading],
) -> io::Result<()> {
    let rows: Vec<JsonLayout> = readings.iter().map(|r| row(start, r, None)).collect();
    write_rows(out, format, &rows, colour)
}

/// The map line of a layout: `name,ref,type,order` as a CSV map takes it.
pub fn map_line(start: &Start, reading: &Reading) -> String {
    format!(
        "value,{},{},{}",
        start.reference(reading.offset),
        type_name(reading),
        reading.layout.order.name()
    )
}

/// The layouts that give the value expected, nearest first.
pub fn write_candidates(
    out: &mut dyn Write,
    format: Format,
    colour: bool,
    start: &Start,
    candidates: &[Candidate],
) -> io::Result<()> {
    let rows: Vec<JsonLayout> = candidates
        .iter()
        .map(|c| row(start, &c.reading, Some(c.distance)))
        .collect();
    write_rows(out, format, &rows, colour)
}
