//! How read results and write confirmations are shown.

use mbtool_core::model::choice::Choice;
use std::io::{self, Write};

use comfy_table::{Cell, Color};
use serde::Serialize;

use super::{csv_field, new_table};
use crate::cli::OutputFormat;
use mbtool_core::master::run::{ReadData, ReadResult};
use mbtool_core::model::address::reference;
use mbtool_core::model::values::{ByteOrder, Value, ValueType};

#[derive(Serialize)]
struct JsonEntry<'a> {
    address: u32,
    #[serde(rename = "ref")]
    reference: String,
    value: &'a Value,
    #[serde(skip_serializing_if = "Option::is_none")]
    registers: Option<&'a [u16]>,
}

#[derive(Serialize)]
struct JsonRead<'a> {
    slave: u8,
    function: u8,
    values: Vec<JsonEntry<'a>>,
}

/// One shown value: where it is, its registers, what it means.
struct Row<'a> {
    address: u32,
    registers: &'a [u16],
    value: Value,
}

pub struct ReadWriter {
    format: OutputFormat,
    value_type: ValueType,
    order: ByteOrder,
    colour: bool,
    /// The previous result, when polling: changed values are marked.
    previous: Option<ReadResult>,
    csv_header_written: bool,
}

impl ReadWriter {
    pub fn new(
        format: OutputFormat,
        value_type: ValueType,
        order: ByteOrder,
        colour: bool,
    ) -> Self {
        Self {
            format,
            value_type,
            order,
            colour,
            previous: None,
            csv_header_written: false,
        }
    }

    fn rows<'a>(&self, result: &'a ReadResult) -> Vec<Row<'a>> {
        let start = u32::from(result.address);
        match &result.data {
            ReadData::Registers(registers) => {
                let width = self.value_type.width();
                registers
                    .chunks_exact(width)
                    .enumerate()
                    .map(|(i, chunk)| Row {
                        address: start + (i * width) as u32,
                        registers: chunk,
                        value: self.value_type.read(chunk, self.order),
                    })
                    .collect()
            }
            ReadData::Bits(bits) => bits
                .iter()
                .enumerate()
                .map(|(i, bit)| Row {
                    address: start + i as u32,
                    registers: &[],
                    value: Value::Unsigned(u64::from(*bit)),
                })
                .collect(),
        }
    }

    /// Indices of rows whose value differs from the previous poll.
    fn changed(&self, result: &ReadResult) -> Vec<bool> {
        let now = self.rows(result);
        match &self.previous {
            Some(previous) if previous.data.len() == result.data.len() => {
                let before = self.rows(previous);
                now.iter()
                    .zip(&before)
                    .map(|(a, b)| a.value != b.value)
                    .collect()
            }
            _ => vec![false; now.len()],
        }
    }

    pub fn write(&mut self, out: &mut dyn Write, result: &ReadResult) -> io::Result<()> {
        let changed = self.changed(result);
        let rows = self.rows(result);
        let ref_of = |address: u32| reference(result.table, address as u16);
        match self.format {
            OutputFormat::Json => {
                let wide = self.value_type.width() > 1;
                let values = rows
                    .iter()
                    .map(|row| JsonEntry {
                        address: row.address,
                        reference: ref_of(row.address),
                        value: &row.value,
                        registers: wide.then_some(row.registers),
                    })
                    .collect();
                let json = JsonRead {
                    slave: result.slave,
                    function: result.function,
                    values,
                };
                serde_json::to_writer(&mut *out, &json)?;
                writeln!(out)?;
            }
            OutputFormat::Values => {
                for row in &rows {
                    writeln!(out, "{}", row.value)?;
                }
            }
            OutputFormat::Csv => {
                if !self.csv_header_written {
                    writeln!(out, "ref,address,hex,value")?;
                    self.csv_header_written = true;
                }
                for row in &rows {
                    writeln!(
                        out,
                        "{},{},{},{}",
                        ref_of(row.address),
                        row.address,
                        hex_of(row.registers),
                        csv_field(&row.value.to_string())
                    )?;
                }
            }
            OutputFormat::Table => {
                let mut table = new_table(self.colour);
                let bits = matches!(result.data, ReadData::Bits(_));
                let mut header = vec!["ref".to_string(), "address".to_string()];
                if bits {
                    header.push("state".into());
                } else {
                    header.extend(["hex".to_string(), self.value_type.name().to_string()]);
                }
                if self.previous.is_some() {
                    header.push("changed".into());
                }
                table.set_header(header);
                for (row, changed) in rows.iter().zip(&changed) {
                    let shown = if bits {
                        if row.value == Value::Unsigned(1) {
                            "ON"
                        } else {
                            "OFF"
                        }
                        .to_string()
                    } else {
                        row.value.to_string()
                    };
                    let mut value = Cell::new(shown);
                    if *changed && self.colour {
                        value = value.fg(Color::Yellow);
                    }
                    let mut cells = vec![Cell::new(ref_of(row.address)), Cell::new(row.address)];
                    if !bits {
                        cells.push(Cell::new(hex_of(row.registers)));
                    }
                    cells.push(value);
                    if self.previous.is_some() {
                        cells.push(Cell::new(if *changed { "*" } else { "" }));
                    }
                    table.add_row(cells);
                }
                writeln!(out, "{table}")?;
            }
        }
        self.previous = Some(result.clone());
        Ok(())
    }

    /// Keeps the first result, so that the next poll's changes show.
    pub fn polling(&mut self, result: &ReadResult) {
        self.previous.get_or_insert_with(|| result.clone());
    }
}

fn hex_of(registers: &[u16]) -> String {
    registers
        .iter()
        .map(|r| format!("{r:04X}"))
        .collect::<Vec<_>>()
        .join(" ")
}

/// A completed write, as the user sees it.
#[derive(Serialize)]
pub struct WriteDone {
    pub slave: u8,
    pub function: u8,
    pub address: u16,
    #[serde(rename = "ref")]
    pub reference: String,
    pub count: usize,
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub broadcast: bool,
}

pub fn write_done(out: &mut dyn Write, format: OutputFormat, done: &WriteDone) -> io::Result<()> {
    match format {
        OutputFormat::Json => {
            serde_json::to_writer(&mut *out, done)?;
            writeln!(out)
        }
        OutputFormat::Table => {
            let what = if done.broadcast {
                "broadcast".to_string()
            } else {
                format!("slave {}", done.slave)
            };
            writeln!(
                out,
                "wrote {} {} from {} ({what}, function {} {})",
                done.count,
                if done.count == 1 { "value" } else { "values" },
                done.reference,
                done.function,
                mbtool_core::codec::function::name(done.function)
            )
        }
        OutputFormat::Values | OutputFormat::Csv => Ok(()),
    }
}
