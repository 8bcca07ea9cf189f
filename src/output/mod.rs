//! Rendering results for people and for scripts. Nothing here decides anything about
//! Modbus; it only shows what the logic produced.

pub mod backup;
mod columns;
pub mod decode;
pub mod device;
pub mod encode;
pub mod gateway;
pub mod hosts;
pub mod json;
pub mod layouts;
pub mod map;
pub mod plant;
pub mod ports;
pub mod progress;
pub mod read;
pub mod records;
pub mod scan;
pub mod serve;
pub mod sniff;
pub mod sunspec;
pub mod watch;
mod wide;

use std::fs::File;
use std::io::{self, IsTerminal, Write};

use comfy_table::{presets, Table};

use mbtool_core::codec::{Pdu, Request};
use mbtool_core::describe::{describe_pdu, Fields, Values};
use mbtool_core::model::address::AddressBase;
use mbtool_core::model::values::{ByteOrder, ValueType};

/// Standard output, buffered unless it is a terminal, where each line shows at once.
pub fn stdout() -> Box<dyn Write> {
    let stdout = io::stdout();
    let named = Named::new(stdout.lock(), "standard output");
    if stdout.is_terminal() {
        Box::new(named)
    } else {
        Box::new(io::BufWriter::with_capacity(1 << 16, named))
    }
}

/// A file that was created (or appended to) by name, buffered, its errors naming it.
pub fn create_file(path: &std::path::Path, append: bool) -> io::Result<io::BufWriter<Named<File>>> {
    let file = std::fs::OpenOptions::new()
        .write(true)
        .create(true)
        .append(append)
        .truncate(!append)
        .open(path)?;
    Ok(io::BufWriter::new(Named::new(
        file,
        &path.display().to_string(),
    )))
}

/// A writer whose errors say what it writes to (`cannot write standard output: No space
/// left on device`), keeping their kind, so that a full disk or a closed pipe is told of
/// the file it happened to.
pub struct Named<W> {
    inner: W,
    name: String,
}

impl<W> Named<W> {
    pub fn new(inner: W, name: &str) -> Self {
        Self {
            inner,
            name: name.to_string(),
        }
    }

    /// The writer itself, for what it can tell (a file's length).
    pub fn get_ref(&self) -> &W {
        &self.inner
    }

    fn named(&self, error: io::Error) -> io::Error {
        io::Error::new(error.kind(), format!("cannot write {}: {error}", self.name))
    }
}

impl<W: Write> Write for Named<W> {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.inner.write(buf).map_err(|e| self.named(e))
    }

    fn flush(&mut self) -> io::Result<()> {
        self.inner.flush().map_err(|e| self.named(e))
    }
}

/// What results are written as.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// A table for people.
    Table,
    /// One JSON object per line.
    Json,
    /// Only the values, one per line.
    Values,
    /// Comma-separated values with a header line.
    Csv,
}

/// How values are shown, as the settings resolve it once: the format, how registers are
/// read as values, and whether there is colour.
#[derive(Clone, Copy, Debug)]
pub struct Style {
    pub format: Format,
    pub value_type: ValueType,
    pub order: ByteOrder,
    /// What the address column counts from.
    pub address_base: AddressBase,
    pub colour: bool,
}

/// Colour only on a terminal, and never with NO_COLOR set (https://no-color.org).
pub fn colour_wanted() -> bool {
    io::stdout().is_terminal() && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty())
}

/// A table in the house style; on a terminal it fits the terminal's width, long cells
/// wrapping inside their column.
pub fn new_table(colour: bool) -> Table {
    let mut table = Table::new();
    table.load_preset(presets::UTF8_FULL_CONDENSED);
    table.apply_modifier(comfy_table::modifiers::UTF8_ROUND_CORNERS);
    if let Some((terminal_size::Width(width), _)) = terminal_size::terminal_size_of(io::stdout()) {
        table.set_content_arrangement(comfy_table::ContentArrangement::Dynamic);
        table.set_width(width);
    }
    if colour {
        table.enforce_styling();
    } else {
        table.force_no_tty();
    }
    table
}

/// Values as `a b c`, at most `most` of them, then how many there are in all.
pub fn shown_values(values: &Values, most: usize) -> String {
    let mut text = String::new();
    write_values(&mut text, values, most);
    text
}

/// [`shown_values`], written into `out`.
pub fn write_values(out: &mut String, values: &Values, most: usize) {
    use std::fmt::Write as _;
    let len = values.len();
    for i in 0..len.min(most) {
        if i > 0 {
            out.push(' ');
        }
        write_value(out, values, i);
    }
    if len > most {
        let _ = write!(out, " ... ({len} in all)");
    }
}

/// Value `i` of `values`, written into `out`.
pub fn write_value(out: &mut String, values: &Values, i: usize) {
    let mut digits = itoa::Buffer::new();
    out.push_str(match values {
        Values::Registers(v) => digits.format(v[i]),
        Values::Bits(v) => digits.format(v[i]),
    });
}

/// What a PDU's fields say in a few words, for the one-line views of `sniff` and `serve`:
/// `400108 x3`, `400002 = 10 258`, `3 values: 555 0 100`.
pub fn fields_summary(fields: &Fields) -> String {
    let mut text = String::new();
    write_fields_summary(&mut text, fields);
    text
}

/// [`fields_summary`], written into `out`.
pub fn write_fields_summary(out: &mut String, fields: &Fields) {
    use std::fmt::Write as _;
    let place = |out: &mut String| match (&fields.reference, fields.address) {
        (Some(reference), _) => {
            out.push_str(reference);
            true
        }
        (None, Some(address)) => {
            out.push_str(itoa::Buffer::new().format(address));
            true
        }
        (None, None) => false,
    };
    if let Some(files) = &fields.files {
        write_files(out, files);
        return;
    }
    match (&fields.values, fields.count) {
        (Some(values), _) => {
            if place(out) {
                out.push_str(" = ");
            } else if let Some(most) = fields.max_count {
                let sure = values.len();
                let _ = write!(
                    out,
                    "{sure} to {most} values (the request not seen), the first {sure}: "
                );
            } else {
                let _ = write!(out, "{} values: ", values.len());
            }
            write_values(out, values, 8);
            // Function 23: the read that follows the write.
            if fields.read_address.is_some() {
                out.push_str(", ");
                out.push_str(&fields_detail(fields));
            }
        }
        (None, count) => {
            let data = fields.text.as_ref().or(fields.data.as_ref());
            if place(out) {
                if let Some(count) = count {
                    out.push_str(" x");
                    out.push_str(itoa::Buffer::new().format(count));
                }
                if let (Some(and), Some(or)) = (fields.and_mask, fields.or_mask) {
                    let _ = write!(out, " AND {and:04X} OR {or:04X}");
                }
            } else if let Some(sub_function) = fields.sub_function {
                let _ = write!(out, "sub-function {sub_function}");
                if let Some(data) = data {
                    let _ = write!(out, ": {data}");
                }
            } else if fields.read_code.is_some() {
                write_identification(out, fields);
            } else if let Some(status) = fields.status {
                let _ = write!(out, "status {status:02X}");
            } else if let Some(data) = data {
                out.push_str(data);
            }
        }
    }
}

/// What a PDU's fields hold past an address, a count and values, in a few words: file
/// record groups, a mask write's masks, the read of a read/write; empty for the others.
pub fn fields_detail(fields: &Fields) -> String {
    use std::fmt::Write as _;
    let mut out = String::new();
    if let Some(files) = &fields.files {
        write_files(&mut out, files);
    }
    if let (Some(and), Some(or)) = (fields.and_mask, fields.or_mask) {
        let _ = write!(out, "AND {and:04X} OR {or:04X}");
    }
    if let (Some(address), Some(count)) = (fields.read_address, fields.read_count) {
        let read = mbtool_core::model::address::reference(
            mbtool_core::model::address::Table::HoldingRegisters,
            address,
        );
        let _ = write!(out, "then read {read} x{count}");
    }
    out
}

/// File record groups in a few words: `file 4 record 1 x2 = 3582 32; file 3 record 9 x2`.
fn write_files(out: &mut String, files: &[mbtool_core::describe::FileGroupField]) {
    use std::fmt::Write as _;
    for (i, group) in files.iter().enumerate() {
        if i > 0 {
            out.push_str("; ");
        }
        if let (Some(file), Some(record)) = (group.file, group.record) {
            let _ = write!(out, "file {file} record {record} ");
        }
        let _ = write!(out, "x{}", group.count);
        if let Some(values) = &group.values {
            out.push_str(" = ");
            write_values(out, &Values::Registers(values.iter().copied().collect()), 8);
        }
    }
}

/// Function 43/14 in a few words: what a request asks for, the objects an answer gives.
fn write_identification(out: &mut String, fields: &Fields) {
    use std::fmt::Write as _;
    match &fields.objects {
        None => {
            let _ = match (fields.read_code, fields.object_id) {
                (Some(4), Some(id)) => write!(out, "object {id:02X}"),
                (Some(code), Some(id)) => write!(out, "read code {code} from object {id:02X}"),
                _ => Ok(()),
            };
        }
        Some(objects) => {
            for (i, object) in objects.iter().enumerate() {
                if i > 0 {
                    out.push_str(", ");
                }
                let _ = write!(out, "{} = \"{}\"", object.name, object.value);
            }
            if let (Some(true), Some(next)) = (fields.more_follows, fields.next_object_id) {
                let _ = write!(out, "; more from object {next:02X}");
            }
        }
    }
}

/// A request in a few words.
pub fn request_summary(request: &Request) -> String {
    let (_, fields) = describe_pdu(&Pdu::Request(request.clone()));
    fields_summary(&fields)
}

/// A CSV field, quoted when it needs to be.
pub fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// The time of day of a row's RFC 3339 time, as a line on a terminal shows it:
/// `2026-11-28T06:43:25.162+01:00` is `06:43:25.162`.
pub fn time_of_day(time: &str) -> &str {
    time.get(11..23).unwrap_or(time)
}

/// `1 request`, `3 requests`.
pub fn plural(count: usize, noun: &str) -> String {
    match count {
        1 => format!("1 {noun}"),
        // address, addresses
        n if noun.ends_with('s') => format!("{n} {noun}es"),
        n => format!("{n} {noun}s"),
    }
}

/// The rows of a poll, each with its time: results, and the polls that gave none.
pub trait PollRows {
    /// What one poll read.
    type Item;
    /// A poll's result.
    fn row(&mut self, out: &mut dyn Write, item: &Self::Item, time: &str) -> io::Result<()>;
    /// A poll that gave no result: a row with its error where the format has rows.
    fn failure(&mut self, out: &mut dyn Write, time: &str, error: &str) -> io::Result<()>;
    /// The exit status a poll's result gives: 0, or that of a point that failed in it.
    fn status(&self, _item: &Self::Item) -> u8 {
        0
    }
    /// The rows go on a file that has its CSV header already.
    fn continuing(&mut self);
    /// The format the rows are written in.
    fn format(&self) -> Format;
    /// The master changed to its other path `to` because of `why`: in JSON a row of its
    /// own, `{"time":..,"switched":"secondary","why":"3 timeouts"}`; in CSV a row with
    /// the change in the error column.
    fn switched(&mut self, out: &mut dyn Write, time: &str, to: &str, why: &str) -> io::Result<()> {
        match self.format() {
            Format::Json => {
                let row = JsonSwitch {
                    time,
                    switched: to,
                    why,
                };
                serde_json::to_writer(&mut *out, &row)?;
                writeln!(out)
            }
            _ => self.failure(out, time, &format!("switched to the {to} path: {why}")),
        }
    }
}

/// A change of path, as a JSON row.
#[derive(serde::Serialize)]
struct JsonSwitch<'a> {
    time: &'a str,
    switched: &'a str,
    why: &'a str,
}

/// A poll that gave no result, as a JSON row.
#[derive(serde::Serialize)]
pub struct JsonFailure<'a> {
    pub time: &'a str,
    pub error: &'a str,
}
