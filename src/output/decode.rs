//! How `decode` shows frames: a table per frame, JSON Lines, bare values, or CSV.

use mbtool_core::input::choice::Choice;
use std::io::{self, Write};

use comfy_table::{Cell, Color};

use super::Format;
use super::{csv_field, new_table, Style};
use mbtool_core::codec::hex::spaced_hex;
use mbtool_core::codec::{Checksum, ExceptionCode, Mode};
use mbtool_core::describe::{Fields, FrameReport, Values};
use mbtool_core::model::address::{reference, Table};
use mbtool_core::model::values::{ByteOrder, ValueType};

pub struct DecodeWriter {
    style: Style,
    csv_header_written: bool,
    /// A JSON line is put together here and written at once (see output::sniff).
    line: Vec<u8>,
}

/// `detail`: what the other columns cannot hold (file record groups, masks, the read of a
/// read/write), in a few words.
const CSV_HEADER: &str = "mode,kind,slave,function,valid,address,ref,count,max_count,values,\
                          exception,error,ambiguous,detail";

impl DecodeWriter {
    pub fn new(style: Style) -> Self {
        Self {
            style,
            csv_header_written: false,
            line: Vec::with_capacity(512),
        }
    }

    /// Shows one frame; `shown` is the frame as the user gave it, for the table view.
    pub fn write(
        &mut self,
        out: &mut dyn Write,
        shown: &[u8],
        report: &FrameReport,
    ) -> io::Result<()> {
        match self.style.format {
            Format::Json => {
                self.line.clear();
                serde_json::to_writer(&mut self.line, report)?;
                self.typed_json(report)?;
                self.line.push(b'\n');
                out.write_all(&self.line)
            }
            Format::Values => self.write_values(out, &report.fields),
            Format::Csv => self.write_csv(out, report),
            Format::Table => self.write_table(out, shown, report),
        }
    }

    /// With `--type` or `--order`, register values also as that type, after the registers
    /// as they are: `"value_type":"f32","typed_values":[3.14]`.
    fn typed_json(&mut self, report: &FrameReport) -> io::Result<()> {
        let default =
            self.style.value_type == ValueType::U16 && self.style.order == ByteOrder::Abcd;
        let Some(Values::Registers(registers)) = &report.fields.values else {
            return Ok(());
        };
        if default || self.line.last() != Some(&b'}') {
            return Ok(());
        }
        self.line.pop();
        self.line.extend_from_slice(b",\"value_type\":");
        serde_json::to_writer(&mut self.line, self.style.value_type.name())?;
        self.line.extend_from_slice(b",\"typed_values\":");
        let typed = self.style.value_type.read_all(registers, self.style.order);
        serde_json::to_writer(&mut self.line, &typed)?;
        self.line.push(b'}');
        Ok(())
    }

    fn typed(&self, registers: &[u16]) -> Vec<String> {
        self.style
            .value_type
            .read_all(registers, self.style.order)
            .iter()
            .map(ToString::to_string)
            .collect()
    }

    fn value_strings(&self, values: &Values) -> Vec<String> {
        match values {
            Values::Registers(registers) => self.typed(registers),
            Values::Bits(bits) => bits.iter().map(ToString::to_string).collect(),
        }
    }

    fn write_values(&self, out: &mut dyn Write, fields: &Fields) -> io::Result<()> {
        if let Some(values) = &fields.values {
            for value in self.value_strings(values) {
                writeln!(out, "{value}")?;
            }
        }
        Ok(())
    }

    fn write_csv(&mut self, out: &mut dyn Write, report: &FrameReport) -> io::Result<()> {
        if !self.csv_header_written {
            writeln!(out, "{CSV_HEADER}")?;
            self.csv_header_written = true;
        }
        let f = &report.fields;
        let opt = |v: Option<String>| v.unwrap_or_default();
        let values = f.values.as_ref().map(|v| self.value_strings(v).join(" "));
        writeln!(
            out,
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
            report.mode,
            report.kind.name(),
            report.slave,
            report.function,
            report.valid,
            opt(f.address.map(|a| a.to_string())),
            opt(f.reference.map(String::from)),
            opt(f.count.map(|c| c.to_string())),
            opt(f.max_count.map(|c| c.to_string())),
            csv_field(&opt(values)),
            opt(f.exception.map(|e| e.to_string())),
            csv_field(&opt(report.error.clone())),
            report.ambiguous,
            csv_field(&super::fields_detail(f)),
        )
    }

    fn write_table(
        &self,
        out: &mut dyn Write,
        shown: &[u8],
        report: &FrameReport,
    ) -> io::Result<()> {
        let mut table = new_table(self.style.colour);
        // By the mode, not by the first byte: an RTU frame from slave 58 starts with ':'.
        let frame = if report.mode == Mode::Ascii.name() {
            // Escaped: bytes read as ASCII that are not may hold control characters.
            mbtool_core::model::values::escape_text(shown.trim_ascii_end())
        } else {
            spaced_hex(shown)
        };
        table.add_row(vec!["frame".to_string(), frame]);
        let mut kind = format!("{} {}", report.mode.to_uppercase(), report.kind.name());
        if let Some(other) = &report.alternative {
            kind.push_str(&format!(
                " (also reads as a {}: --direction settles it)",
                other.kind.name()
            ));
        }
        table.add_row(vec!["kind".to_string(), kind]);
        if let Some(transaction) = report.transaction {
            table.add_row(vec!["transaction".to_string(), transaction.to_string()]);
        }
        let slave = match report.slave {
            0 => "0 (broadcast)".to_string(),
            s => s.to_string(),
        };
        table.add_row(vec!["slave".to_string(), slave]);
        table.add_row(vec![
            "function".to_string(),
            // In decimal as everywhere else, and as the byte on the wire (an exception's
            // has 0x80 set).
            format!(
                "{} (0x{:02X}) {}",
                report.function & 0x7F,
                report.function,
                report.function_name
            ),
        ]);
        for (name, value) in field_rows(&report.fields) {
            table.add_row(vec![name.to_string(), value]);
        }
        if let Some(other) = &report.alternative {
            for (name, value) in field_rows(&other.fields) {
                table.add_row(vec![format!("as {}: {name}", other.kind.name()), value]);
            }
        }
        match report.checksum {
            Checksum::Crc { found, expected } if found == expected => {
                let [lo, hi] = found.to_le_bytes();
                table.add_row(vec![
                    Cell::new("CRC"),
                    self.ok(format!("{lo:02X} {hi:02X} ok")),
                ]);
            }
            Checksum::Lrc { found, expected } if found == expected => {
                table.add_row(vec![Cell::new("LRC"), self.ok(format!("{found:02X} ok"))]);
            }
            _ => {}
        }
        if let Some(error) = &report.error {
            table.add_row(vec![Cell::new("error"), self.bad(error.clone())]);
        }
        writeln!(out, "{table}")?;
        if let Some(values) = report.fields.values.as_ref().filter(|v| v.len() > 1) {
            let table_of = Table::of_function(report.function);
            writeln!(
                out,
                "{}",
                self.values_table(values, &report.fields, table_of)
            )?;
        }
        Ok(())
    }

    fn ok(&self, text: String) -> Cell {
        let cell = Cell::new(text);
        if self.style.colour {
            cell.fg(Color::Green)
        } else {
            cell
        }
    }

    fn bad(&self, text: String) -> Cell {
        let cell = Cell::new(text);
        if self.style.colour {
            cell.fg(Color::Red)
        } else {
            cell
        }
    }

    /// A table of values; with a known start address each row carries its reference.
    fn values_table(
        &self,
        values: &Values,
        fields: &Fields,
        table_of: Option<Table>,
    ) -> comfy_table::Table {
        let mut table = new_table(self.style.colour);
        let located = fields.address.zip(table_of);
        let place = |offset: usize| -> Vec<String> {
            match located {
                Some((start, table)) => {
                    let address = u32::from(start) + offset as u32;
                    match u16::try_from(address) {
                        Ok(address) => vec![reference(table, address).into(), address.to_string()],
                        Err(_) => vec![String::new(), address.to_string()],
                    }
                }
                None => vec![offset.to_string()],
            }
        };
        let mut header: Vec<String> = match located {
            Some(_) => vec!["ref".into(), "address".into()],
            None => vec!["#".into()],
        };
        match values {
            Values::Registers(registers) => {
                header.extend(["hex".to_string(), self.style.value_type.name().to_string()]);
                table.set_header(header);
                let width = self.style.value_type.width();
                for (i, chunk) in registers.chunks_exact(width).enumerate() {
                    let hex = chunk
                        .iter()
                        .map(|r| format!("{r:04X}"))
                        .collect::<Vec<_>>()
                        .join(" ");
                    let mut row = place(i * width);
                    row.push(hex);
                    row.push(
                        self.style
                            .value_type
                            .read(chunk, self.style.order)
                            .to_string(),
                    );
                    table.add_row(row);
                }
            }
            Values::Bits(bits) => {
                // A row per byte as it stands in the frame: first bit on the left. The last
                // byte's bits past the values are padding (or, the request not seen, not
                // known to be values): its byte is the frame's, never made up from the
                // values.
                header.extend(["byte".to_string(), "bits (first to last)".to_string()]);
                table.set_header(header);
                for (i, chunk) in bits.chunks(8).enumerate() {
                    let byte = match chunk.len() {
                        8 => Some(
                            chunk
                                .iter()
                                .enumerate()
                                .fold(0u8, |byte, (bit, on)| byte | (*on & 1) << bit),
                        ),
                        _ => fields.last_packed,
                    };
                    let shown: Vec<String> = chunk.iter().map(ToString::to_string).collect();
                    let mut row = place(i * 8);
                    row.push(byte.map(|byte| format!("{byte:02X}")).unwrap_or_default());
                    row.push(shown.join(" "));
                    table.add_row(row);
                }
            }
        }
        table
    }
}

/// The fields of a PDU as (name, shown value) rows, in the order the PDU carries them.
fn field_rows(f: &Fields) -> Vec<(&'static str, String)> {
    let mut rows = Vec::new();
    if let (Some(address), Some(count)) = (f.read_address, f.read_count) {
        rows.push((
            "read address",
            format!(
                "{address} ({})",
                reference(Table::HoldingRegisters, address)
            ),
        ));
        rows.push(("read count", count.to_string()));
    }
    if let Some(address) = f.address {
        rows.push(match &f.reference {
            Some(reference) => ("address", format!("{address} ({reference})")),
            None => ("address", address.to_string()),
        });
    }
    if let Some(count) = f.count {
        rows.push(("count", count.to_string()));
    }
    if let (Some(values), Some(most)) = (&f.values, f.max_count) {
        // The last byte's bits that are values or padding, shown as they are, not as values:
        // an input that is ON must not vanish from view, nor a padding bit become a coil.
        let sure = values.len();
        let undecided = match f.last_packed {
            Some(last) => ((sure + 8).saturating_sub(usize::from(most))..8)
                .map(|bit| ((last >> bit) & 1).to_string())
                .collect::<Vec<_>>()
                .join(" "),
            None => String::new(),
        };
        rows.push((
            "count",
            format!(
                "{sure} to {most}: the request decides (the bits after the first {sure}, \
                 {undecided}, may be padding)"
            ),
        ));
    }
    if let Some(values) = f.values.as_ref().filter(|v| v.len() == 1) {
        rows.push(match values {
            Values::Registers(r) => ("value", format!("{} (0x{:04X})", r[0], r[0])),
            Values::Bits(b) => ("value", if b[0] == 1 { "ON" } else { "OFF" }.to_string()),
        });
    }
    for group in f.files.iter().flatten() {
        let records = match (group.file, group.record) {
            (Some(file), Some(record)) => format!(
                "file {file}, records {record}-{}",
                u32::from(record) + u32::from(group.count).max(1) - 1
            ),
            _ => format!("{} records", group.count),
        };
        let values = group.values.as_ref().map(|values| {
            let shown: Vec<String> = values.iter().map(u16::to_string).collect();
            format!(" = {}", shown.join(" "))
        });
        rows.push((
            "file group",
            format!("{records}{}", values.unwrap_or_default()),
        ));
    }
    if let Some(mask) = f.and_mask {
        rows.push(("AND mask", format!("{mask:04X}")));
    }
    if let Some(mask) = f.or_mask {
        rows.push(("OR mask", format!("{mask:04X}")));
    }
    if let Some(sub) = f.sub_function {
        rows.push(("sub-function", format!("{sub:04X}")));
    }
    if let Some(status) = f.status {
        rows.push(("status", format!("{status:08b}")));
    }
    if let Some(code) = f.exception {
        rows.push(("exception", ExceptionCode(code).to_string()));
    }
    if let Some(code) = f.read_code {
        rows.push(("read code", format!("{code:02X}")));
    }
    if let Some(id) = f.object_id {
        rows.push(("object id", format!("{id:02X}")));
    }
    if let Some(level) = f.conformity {
        rows.push(("conformity", format!("{level:02X}")));
    }
    if let Some(more) = f.more_follows {
        rows.push(("more follows", if more { "yes" } else { "no" }.to_string()));
    }
    if let Some(next) = f.next_object_id {
        rows.push(("next object", format!("{next:02X}")));
    }
    for object in f.objects.iter().flatten() {
        rows.push((
            "object",
            format!("{:02X} {}: {}", object.id, object.name, object.value),
        ));
    }
    if let Some(data) = &f.data {
        rows.push(("data", data.clone()));
    }
    if let Some(text) = &f.text {
        rows.push(("text", text.clone()));
    }
    rows
}

#[cfg(test)]
mod tests {
    use super::*;
    use mbtool_core::codec::Mode;
    use mbtool_core::describe::describe_frame;
    use mbtool_core::model::address::AddressBase;
    use mbtool_core::model::values::{ByteOrder, ValueType};

    fn shown(format: Format, frame: &[u8]) -> String {
        let report = describe_frame(frame, Some(Mode::Rtu), None);
        let mut writer = DecodeWriter::new(Style {
            format,
            value_type: ValueType::U16,
            order: ByteOrder::Abcd,
            address_base: AddressBase::Zero,
            colour: false,
        });
        let mut out = Vec::new();
        writer.write(&mut out, frame, &report).unwrap();
        String::from_utf8(out).unwrap()
    }

    const REQUEST: [u8; 8] = [0x3A, 0x03, 0x00, 0x6B, 0x00, 0x03, 0x70, 0x9C];

    #[test]
    fn json_holds_the_decode_keys() {
        assert_eq!(
            shown(Format::Json, &REQUEST),
            "{\"mode\":\"rtu\",\"kind\":\"request\",\"slave\":58,\"function\":3,\"valid\":true,\"function_name\":\"Read Holding Registers\",\"address\":107,\"ref\":\"400108\",\"count\":3}\n"
        );
    }

    #[test]
    fn a_table_shows_an_rtu_frame_as_hex_whatever_its_first_byte() {
        let table = shown(Format::Table, &REQUEST);
        assert!(table.contains("3A 03 00 6B 00 03 70 9C"), "{table}");
        assert!(!table.contains(":\u{3}"), "{table}");
    }
}
