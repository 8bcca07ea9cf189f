//! How read results and write confirmations are shown.

use mbtool_core::input::choice::Choice;
use std::io::{self, Write};

use comfy_table::{Cell, Color};
use serde::Serialize;

use super::wide::WideRows;
use super::Format;
use super::{csv_field, new_table, Style};
use mbtool_core::master::plan::Plan;
use mbtool_core::master::range::RangeRead;
use mbtool_core::master::run::ReadResult;
use mbtool_core::model::address::{bit_reference, reference};
use mbtool_core::model::values::ReadData;
use mbtool_core::model::values::{text, Value, ValueType};

#[derive(Serialize)]
struct JsonEntry<'a> {
    address: u32,
    #[serde(rename = "ref")]
    reference: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    value: Option<&'a Value>,
    #[serde(skip_serializing_if = "Option::is_none")]
    registers: Option<&'a [u16]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    error: Option<&'static str>,
}

/// What a row of an address the device does not have says in place of its value.
const NO_SUCH_ADDRESS: &str = "no such address";

#[derive(Serialize)]
struct JsonRead<'a> {
    #[serde(skip_serializing_if = "Option::is_none")]
    time: Option<&'a str>,
    slave: u8,
    function: u8,
    values: Vec<JsonEntry<'a>>,
}

/// One shown value: where it is, its registers, what it means.
struct Row<'a> {
    /// The address as shown: counted from the address base.
    address: u32,
    /// `400108`, or `400108.05` for a bit of a register.
    reference: String,
    registers: &'a [u16],
    /// `None` for an address the device said it does not have.
    value: Option<Value>,
}

impl super::PollRows for ReadWriter {
    type Item = RangeRead;

    fn row(&mut self, out: &mut dyn Write, item: &RangeRead, time: &str) -> io::Result<()> {
        self.write_at(out, item, Some(time))
    }

    fn failure(&mut self, out: &mut dyn Write, time: &str, error: &str) -> io::Result<()> {
        self.write_failure(out, time, error)
    }

    fn continuing(&mut self) {
        self.csv_header_written = true;
        if let Some(wide) = self.wide.as_mut() {
            wide.continuing();
        }
    }

    fn format(&self) -> Format {
        self.style.format
    }
}

pub struct ReadWriter {
    style: Style,
    /// The previous rows' references and values, when polling: changed values are marked.
    previous: Option<Vec<(String, Option<Value>)>>,
    csv_header_written: bool,
    /// Every row starts with its time (a poll's rows, a log).
    timed: bool,
    /// A poll's rows in CSV and the table: one line a poll, a column a value.
    wide: Option<WideRows>,
}

impl ReadWriter {
    pub fn new(style: Style) -> Self {
        Self {
            style,
            previous: None,
            csv_header_written: false,
            timed: false,
            wide: None,
        }
    }

    /// A writer for the polls of `plan`, whose rows are timed and whose wide rows have a
    /// column for each value it reads: the references its rows would show.
    pub fn polling(mut self, plan: &Plan) -> Self {
        self.timed = true;
        let Some((table, address)) = plan.reads else {
            return self;
        };
        let quantity: usize = plan
            .requests
            .iter()
            .map(|request| usize::from(request.read_quantity()))
            .sum();
        let (data, first_bit) = match plan.bits {
            Some(bits) => (
                ReadData::Bits(vec![false; bits.count as usize]),
                Some(bits.first),
            ),
            None if table.is_bits() => (ReadData::Bits(vec![false; quantity]), None),
            None => (ReadData::Registers(vec![0; quantity]), None),
        };
        let all = ReadResult {
            slave: plan.slave,
            function: table.read_function(),
            table,
            address,
            data,
            first_bit,
        };
        let columns = self
            .part_rows(&all)
            .into_iter()
            .map(|row| row.reference)
            .collect();
        if matches!(self.style.format, Format::Csv | Format::Table) {
            self.wide = Some(WideRows::new(columns, self.style.colour));
        }
        self
    }

    /// A poll that gave no values: a row with its error in CSV and JSON; in the table and
    /// the values, nothing (the error goes to stderr).
    fn write_failure(&mut self, out: &mut dyn Write, time: &str, error: &str) -> io::Result<()> {
        if let Some(wide) = self.wide.as_mut() {
            return wide.gap(out, self.style.format, time, error);
        }
        match self.style.format {
            Format::Json => {
                serde_json::to_writer(&mut *out, &super::JsonFailure { time, error })?;
                writeln!(out)
            }
            Format::Csv | Format::Table | Format::Values => Ok(()),
        }
    }

    /// The rows of one run of addresses read.
    fn part_rows<'a>(&self, result: &'a ReadResult) -> Vec<Row<'a>> {
        let start = u32::from(result.address);
        let ref_of = |address: u32| String::from(reference(result.table, address as u16));
        let shown = |address: u32| address + self.style.address_base.first();
        match &result.data {
            // Text is one value, whatever the number of registers that hold it.
            ReadData::Registers(registers) if self.style.value_type == ValueType::Ascii => {
                vec![Row {
                    address: shown(start),
                    reference: ref_of(start),
                    registers,
                    value: Some(text(registers, self.style.order)),
                }]
            }
            ReadData::Registers(registers) => {
                let width = self.style.value_type.width();
                registers
                    .chunks_exact(width)
                    .enumerate()
                    .map(|(i, chunk)| Row {
                        address: shown(start + (i * width) as u32),
                        reference: ref_of(start + (i * width) as u32),
                        registers: chunk,
                        value: Some(self.style.value_type.read(chunk, self.style.order)),
                    })
                    .collect()
            }
            // Bits of registers: each names its register and its bit.
            ReadData::Bits(bits) if result.first_bit.is_some() => {
                let first = usize::from(result.first_bit.unwrap_or_default());
                bits.iter()
                    .enumerate()
                    .map(|(i, bit)| {
                        let address = start + ((first + i) / 16) as u32;
                        let number = ((first + i) % 16) as u8;
                        Row {
                            address: shown(address),
                            reference: bit_reference(result.table, address as u16, number),
                            registers: &[],
                            value: Some(Value::Unsigned(u64::from(*bit))),
                        }
                    })
                    .collect()
            }
            ReadData::Bits(bits) => bits
                .iter()
                .enumerate()
                .map(|(i, bit)| Row {
                    address: shown(start + i as u32),
                    reference: ref_of(start + i as u32),
                    registers: &[],
                    value: Some(Value::Unsigned(u64::from(*bit))),
                })
                .collect(),
        }
    }

    /// The rows of a range: those of its runs, and one for each address it lacks, in
    /// address order.
    fn rows<'a>(&self, range: &'a RangeRead) -> Vec<Row<'a>> {
        let table = range.parts.first().map(|part| part.table);
        let mut rows: Vec<Row> = range
            .parts
            .iter()
            .flat_map(|part| self.part_rows(part))
            .collect();
        for (address, table) in range.missing.iter().zip(std::iter::repeat(table).flatten()) {
            rows.push(Row {
                address: self.style.address_base.number(*address),
                reference: reference(table, *address).into(),
                registers: &[],
                value: None,
            });
        }
        // Stable: the bits of one register keep their order.
        rows.sort_by_key(|row| row.address);
        rows
    }

    /// Which rows' values differ from the previous poll's.
    fn changed(&self, rows: &[Row]) -> Vec<bool> {
        match &self.previous {
            Some(previous) if previous.len() == rows.len() => rows
                .iter()
                .zip(previous)
                .map(|(row, (reference, value))| row.reference == *reference && row.value != *value)
                .collect(),
            _ => vec![false; rows.len()],
        }
    }

    pub fn write(&mut self, out: &mut dyn Write, range: &RangeRead) -> io::Result<()> {
        self.write_at(out, range, None)
    }

    /// A result, its rows starting with `time` when the writer is timed.
    pub fn write_at(
        &mut self,
        out: &mut dyn Write,
        range: &RangeRead,
        time: Option<&str>,
    ) -> io::Result<()> {
        let Some(first) = range.parts.first() else {
            return Ok(());
        };
        let time = time.filter(|_| self.timed);
        let rows = self.rows(range);
        let bits = matches!(first.data, ReadData::Bits(_));
        if let (Some(wide), Some(time)) = (self.wide.as_mut(), time) {
            let format = self.style.format;
            let values = wide.columns().iter().map(|column| {
                let row = rows.iter().find(|row| row.reference == *column)?;
                row.value.as_ref().map(|value| match format {
                    Format::Table => shown_value(value, bits),
                    _ => value.to_string(),
                })
            });
            let error = match rows.iter().find(|row| row.value.is_none()) {
                Some(row) => format!("{}: {NO_SUCH_ADDRESS}", row.reference),
                None => String::new(),
            };
            let values = values.collect();
            return wide.row(out, format, time, values, &error);
        }
        let changed = self.changed(&rows);
        match self.style.format {
            Format::Json => {
                let wide = self.style.value_type.width() > 1;
                let values = rows
                    .iter()
                    .map(|row| JsonEntry {
                        address: row.address,
                        reference: row.reference.clone(),
                        value: row.value.as_ref(),
                        registers: (wide && row.value.is_some()).then_some(row.registers),
                        error: row.value.is_none().then_some(NO_SUCH_ADDRESS),
                    })
                    .collect();
                let json = JsonRead {
                    time,
                    slave: first.slave,
                    function: first.function,
                    values,
                };
                serde_json::to_writer(&mut *out, &json)?;
                writeln!(out)?;
            }
            Format::Values => {
                // A line for every row, so that the lines stay in step with the addresses.
                for row in &rows {
                    match &row.value {
                        Some(value) => writeln!(out, "{value}")?,
                        None => writeln!(out, "-")?,
                    }
                }
            }
            Format::Csv => {
                // Bits have no registers, so no hex column.
                if !self.csv_header_written {
                    let header = match bits {
                        true => "ref,address,value",
                        false => "ref,address,hex,value",
                    };
                    writeln!(out, "{header}")?;
                    self.csv_header_written = true;
                }
                for row in &rows {
                    let value = csv_field(
                        &row.value
                            .as_ref()
                            .map(ToString::to_string)
                            .unwrap_or_default(),
                    );
                    match bits {
                        true => writeln!(out, "{},{},{value}", row.reference, row.address)?,
                        false => writeln!(
                            out,
                            "{},{},{},{value}",
                            row.reference,
                            row.address,
                            hex_of(row.registers)
                        )?,
                    }
                }
            }
            Format::Table => {
                let mut table = new_table(self.style.colour);
                let mut header = vec!["ref".to_string(), "address".to_string()];
                if bits {
                    header.push("state".into());
                } else {
                    header.extend(["hex".to_string(), self.style.value_type.name().to_string()]);
                }
                if self.previous.is_some() {
                    header.push("changed".into());
                }
                table.set_header(header);
                for (row, changed) in rows.iter().zip(&changed) {
                    let shown = match &row.value {
                        None => NO_SUCH_ADDRESS.to_string(),
                        Some(value) => shown_value(value, bits),
                    };
                    let mut value = Cell::new(shown);
                    if *changed && self.style.colour {
                        value = value.fg(Color::Yellow);
                    }
                    let mut cells = vec![Cell::new(&row.reference), Cell::new(row.address)];
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
        self.previous = Some(
            rows.into_iter()
                .map(|row| (row.reference, row.value))
                .collect(),
        );
        Ok(())
    }
}

/// A value as the table shows it: a bit ON or OFF.
fn shown_value(value: &Value, bits: bool) -> String {
    match value {
        Value::Unsigned(1) if bits => "ON".to_string(),
        _ if bits => "OFF".to_string(),
        value => value.to_string(),
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
    /// The first address as shown: counted from the address base.
    pub address: u32,
    #[serde(rename = "ref")]
    pub reference: String,
    pub count: usize,
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub broadcast: bool,
    #[serde(flatten)]
    pub detail: WriteDetail,
}

/// What a write of file records or a mask write says beside its place, for scripts.
#[derive(Default, Serialize)]
pub struct WriteDetail {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub file: Option<u16>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub record: Option<u16>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub and_mask: Option<u16>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub or_mask: Option<u16>,
}

pub fn write_done(out: &mut dyn Write, format: Format, done: &WriteDone) -> io::Result<()> {
    match format {
        Format::Json => {
            serde_json::to_writer(&mut *out, done)?;
            writeln!(out)
        }
        Format::Table => {
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
        Format::Values | Format::Csv => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use mbtool_core::model::address::AddressBase;
    use mbtool_core::model::address::Table;
    use mbtool_core::model::values::{ByteOrder, ValueType};

    fn holding(registers: Vec<u16>) -> ReadResult {
        ReadResult {
            slave: 17,
            function: 3,
            table: Table::HoldingRegisters,
            address: 107,
            data: ReadData::Registers(registers),
            first_bit: None,
        }
    }

    fn shown(format: Format, value_type: ValueType, result: &ReadResult) -> String {
        let mut writer = ReadWriter::new(Style {
            format,
            value_type,
            order: ByteOrder::Abcd,
            address_base: AddressBase::Zero,
            colour: false,
        });
        let mut out = Vec::new();
        writer.write(&mut out, &result.clone().into()).unwrap();
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn values_are_one_a_line_for_scripts() {
        let result = holding(vec![555, 0, 100]);
        assert_eq!(
            shown(Format::Values, ValueType::U16, &result),
            "555\n0\n100\n"
        );
    }

    #[test]
    fn csv_has_a_header_and_a_row_per_value() {
        let result = holding(vec![555, 0, 100]);
        assert_eq!(
            shown(Format::Csv, ValueType::U16, &result),
            "ref,address,hex,value\n400108,107,022B,555\n400109,108,0000,0\n400110,109,0064,100\n"
        );
    }

    #[test]
    fn json_wide_values_carry_their_registers() {
        // 1.5 as an f32, high word first.
        let result = holding(vec![0x3FC0, 0x0000]);
        let line = shown(Format::Json, ValueType::F32, &result);
        let json: serde_json::Value = serde_json::from_str(line.trim()).unwrap();
        assert_eq!(json["slave"], 17);
        assert_eq!(json["values"][0]["ref"], "400108");
        assert_eq!(
            json["values"][0]["registers"],
            serde_json::json!([0x3FC0, 0])
        );
        assert_eq!(json["values"][0]["value"], 1.5);
    }

    #[test]
    fn a_table_shows_reference_address_hex_and_value() {
        let table = shown(Format::Table, ValueType::U16, &holding(vec![555]));
        assert!(table.contains("400108"), "{table}");
        assert!(table.contains("022B"), "{table}");
        assert!(table.contains("555"), "{table}");
    }

    #[test]
    fn a_write_is_confirmed_in_json() {
        let done = WriteDone {
            slave: 17,
            function: 6,
            address: 1,
            reference: reference(Table::HoldingRegisters, 1).into(),
            count: 1,
            broadcast: false,
            detail: WriteDetail::default(),
        };
        let mut out = Vec::new();
        write_done(&mut out, Format::Json, &done).unwrap();
        assert_eq!(
            String::from_utf8(out).unwrap(),
            "{\"slave\":17,\"function\":6,\"address\":1,\"ref\":\"400002\",\"count\":1}\n"
        );
    }
}
