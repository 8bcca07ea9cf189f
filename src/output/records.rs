//! How file records (function 20) and a FIFO queue (24) are shown: a row a value of
//! `--type`, placed by file and record, or by its place in the queue.

use std::io::{self, Write};

use mbtool_core::input::choice::Choice;
use serde::Serialize;

use super::{csv_field, new_table, Format, Style};
use mbtool_core::codec::FileRecords;
use mbtool_core::model::values::{text, Value, ValueType};

/// One shown value: its registers and what they mean. `None`: registers left over that
/// make no whole value of the type.
struct Row<'a> {
    /// Registers from the start of its group.
    offset: usize,
    registers: &'a [u16],
    value: Option<Value>,
}

fn rows<'a>(registers: &'a [u16], style: Style) -> Vec<Row<'a>> {
    if style.value_type == ValueType::Ascii {
        return vec![Row {
            offset: 0,
            registers,
            value: Some(text(registers, style.order)),
        }];
    }
    let width = style.value_type.width();
    registers
        .chunks(width)
        .enumerate()
        .map(|(i, chunk)| Row {
            offset: i * width,
            registers: chunk,
            value: (chunk.len() == width).then(|| style.value_type.read(chunk, style.order)),
        })
        .collect()
}

fn hex_of(registers: &[u16]) -> String {
    let words: Vec<String> = registers.iter().map(|r| format!("{r:04X}")).collect();
    words.join(" ")
}

/// What a row says in place of a value its registers do not make.
const NOT_WHOLE: &str = "not a whole value";

fn shown(value: &Option<Value>) -> String {
    value
        .as_ref()
        .map_or_else(|| NOT_WHOLE.to_string(), ToString::to_string)
}

#[derive(Serialize)]
struct JsonRow<'a> {
    #[serde(flatten)]
    place: serde_json::Value,
    #[serde(skip_serializing_if = "Option::is_none")]
    value: Option<&'a Value>,
    #[serde(skip_serializing_if = "Option::is_none")]
    registers: Option<&'a [u16]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    error: Option<&'static str>,
}

/// What a JSON line says before its values.
#[derive(Serialize)]
struct Head<'a> {
    slave: u8,
    function: u8,
    /// A FIFO queue's pointer.
    #[serde(skip_serializing_if = "Option::is_none")]
    address: Option<u32>,
    #[serde(rename = "ref", skip_serializing_if = "Option::is_none")]
    reference: Option<&'a str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    count: Option<usize>,
}

#[derive(Serialize)]
struct JsonRecords<'a> {
    #[serde(flatten)]
    head: Head<'a>,
    values: Vec<JsonRow<'a>>,
}

/// Rows under `place` columns, in every format.
fn write_rows(
    out: &mut dyn Write,
    style: Style,
    head: Head,
    columns: &[&str],
    rows: &[(Vec<String>, Row)],
) -> io::Result<()> {
    let wide = style.value_type.width() > 1;
    match style.format {
        Format::Json => {
            let values: Vec<JsonRow> = rows
                .iter()
                .map(|(place, row)| JsonRow {
                    place: columns
                        .iter()
                        .zip(place)
                        .map(|(column, shown)| {
                            let number = shown.parse::<u64>().map(serde_json::Value::from);
                            (
                                column.to_string(),
                                number.unwrap_or_else(|_| shown.clone().into()),
                            )
                        })
                        .collect::<serde_json::Map<_, _>>()
                        .into(),
                    value: row.value.as_ref(),
                    registers: (wide || row.value.is_none()).then_some(row.registers),
                    error: row.value.is_none().then_some(NOT_WHOLE),
                })
                .collect();
            serde_json::to_writer(&mut *out, &JsonRecords { head, values })?;
            writeln!(out)
        }
        Format::Values => {
            for (_, row) in rows {
                match &row.value {
                    Some(value) => writeln!(out, "{value}")?,
                    None => writeln!(out, "-")?,
                }
            }
            Ok(())
        }
        Format::Csv => {
            writeln!(out, "{},hex,value", columns.join(","))?;
            for (place, row) in rows {
                let value = row.value.as_ref().map(ToString::to_string);
                writeln!(
                    out,
                    "{},{},{}",
                    place.join(","),
                    hex_of(row.registers),
                    csv_field(&value.unwrap_or_default())
                )?;
            }
            Ok(())
        }
        Format::Table => {
            let mut table = new_table(style.colour);
            let mut header: Vec<String> = columns.iter().map(ToString::to_string).collect();
            header.extend(["hex".to_string(), style.value_type.name().to_string()]);
            table.set_header(header);
            for (place, row) in rows {
                let mut cells = place.clone();
                cells.extend([hex_of(row.registers), shown(&row.value)]);
                table.add_row(cells);
            }
            writeln!(out, "{table}")
        }
    }
}

/// The records read, a row a value.
pub fn write_files(
    out: &mut dyn Write,
    style: Style,
    slave: u8,
    groups: &[FileRecords],
) -> io::Result<()> {
    let rows: Vec<(Vec<String>, Row)> = groups
        .iter()
        .flat_map(|group| {
            rows(&group.values, style).into_iter().map(|row| {
                let record = usize::from(group.record) + row.offset;
                (vec![group.file.to_string(), record.to_string()], row)
            })
        })
        .collect();
    let head = Head {
        slave,
        function: 20,
        address: None,
        reference: None,
        count: None,
    };
    write_rows(out, style, head, &["file", "record"], &rows)
}

/// A FIFO queue read, oldest value first, numbered from 0.
pub fn write_fifo(
    out: &mut dyn Write,
    style: Style,
    slave: u8,
    (address, reference): (u32, &str),
    values: &[u16],
) -> io::Result<()> {
    let rows: Vec<(Vec<String>, Row)> = rows(values, style)
        .into_iter()
        .enumerate()
        .map(|(i, row)| (vec![i.to_string()], row))
        .collect();
    if style.format == Format::Table && rows.is_empty() {
        return writeln!(out, "the queue at {reference} is empty");
    }
    let head = Head {
        slave,
        function: 24,
        address: Some(address),
        reference: Some(reference),
        count: Some(values.len()),
    };
    write_rows(out, style, head, &["entry"], &rows)
}
