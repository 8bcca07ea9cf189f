//! How `sniff` shows what passes: a line per frame for people, or JSON Lines.

use std::collections::BTreeMap;
use std::io::{self, Write};

use serde::Serialize;

use super::json::JsonObject;
use super::sniff_json::{frame_json, json_line, seconds, JsonSummary, JsonTcp, JsonUnanswered};
use super::Format;
use super::{csv_field, request_summary, shown_values, write_fields_summary, write_value};
use mbtool_core::codec::function;
use mbtool_core::codec::hex::push_spaced_hex;
use mbtool_core::codec::ExceptionCode;
use mbtool_core::codec::Mode;
use mbtool_core::describe::{describe_pdu, FrameReport, Kind};
use mbtool_core::sniff::pcap::{self, PcapWriter};
use mbtool_core::sniff::replay::RecordSink;
use mbtool_core::sniff::session::{Counts, FrameRecord, Record, TcpPlace, ENDS_WITHOUT_CR};

use super::columns::{column, pad_to, Align, Offset, Seconds};
use mbtool_core::sniff::stats::{Stats, Times};
use mbtool_core::sniff::tcp::PacketCounts;

const RED: &str = "\x1b[31m";
const YELLOW: &str = "\x1b[33m";
const RESET: &str = "\x1b[0m";

/// The columns of a serial line's frames in CSV.
const CSV_HEADER: &str = "number,time,gap,slave,function,kind,valid,summary";

/// The columns of a TCP capture's frames in CSV.
const TCP_CSV_HEADER: &str =
    "number,time,client,server,packet,transaction,slave,function,kind,valid,response_time_us,summary";

pub struct SniffWriter {
    format: Format,
    colour: bool,
    csv_header_written: bool,
    /// One JSON line is put together here and written at once: serde writes token by
    /// token, and each write through the boxed output costs a dynamic call.
    line: Vec<u8>,
    /// One line of the table or one field of JSON, put together here: no allocation per
    /// frame.
    text: String,
}

/// The kind column: an answer, or a frame that reads both ways as a request with a doubt.
fn kind_column(report: &FrameReport) -> &'static str {
    match (report.kind, report.ambiguous) {
        (_, true) => "request?",
        (Kind::Response, _) => "answer",
        (kind, _) => kind.name(),
    }
}

/// The checksum column of a serial frame.
fn check_column(report: &FrameReport) -> &'static str {
    use mbtool_core::codec::Checksum;
    match (&report.checksum, &report.error) {
        (_, Some(error)) if error.starts_with("incomplete") => "incomplete",
        (_, Some(error)) if error == ENDS_WITHOUT_CR => "no CR LF",
        (Checksum::Lrc { found, expected }, _) if found == expected => "LRC ok",
        (Checksum::Lrc { .. }, _) => "LRC BAD",
        (Checksum::Crc { found, expected }, _) if found == expected => "CRC ok",
        (Checksum::Crc { .. }, _) => "CRC BAD",
        _ => "",
    }
}

/// What a frame says, in a few words.
fn frame_summary(report: &FrameReport) -> String {
    let mut text = String::new();
    write_frame_summary(&mut text, report);
    text
}

/// What a frame of a serial line says, and how an answer does not fit the request it
/// follows.
fn write_serial_summary(out: &mut String, frame: &FrameRecord) {
    use std::fmt::Write as _;
    write_frame_summary(out, frame.report());
    if let Some(mismatch) = &frame.mismatch {
        let _ = write!(out, " (does not fit the request: {mismatch})");
    }
}

/// [`frame_summary`], written into `out`.
fn write_frame_summary(out: &mut String, report: &FrameReport) {
    use std::fmt::Write as _;
    let f = &report.fields;
    // The kind column already says "exception".
    let _ = match (f.exception, &report.error) {
        (Some(code), None) => write!(out, "{}", ExceptionCode(code)),
        (Some(code), Some(error)) => write!(out, "{} ({error})", ExceptionCode(code)),
        (None, Some(error)) => write!(out, "{error}"),
        (None, None) => Ok(()),
    };
    if f.exception.is_some() || report.error.is_some() {
        return;
    }
    let table = mbtool_core::model::address::Table::of_function(report.function);
    match (report.kind, &f.values, f.address, f.count) {
        (Kind::Response, Some(values), Some(start), Some(_)) => {
            // A read answer located by its request: reference = value pairs.
            for i in 0..values.len().min(6) {
                if i > 0 {
                    out.push_str(", ");
                }
                match (table, u16::try_from(u32::from(start) + i as u32)) {
                    (Some(table), Ok(address)) => {
                        out.push_str(&mbtool_core::model::address::reference(table, address));
                    }
                    _ => {
                        let _ = match &f.reference {
                            Some(reference) => write!(out, "{reference}+{i}"),
                            None => write!(out, "{start}+{i}"),
                        };
                    }
                }
                out.push_str(" = ");
                write_value(out, values, i);
            }
            if values.len() > 6 {
                let _ = write!(out, ", ... ({} in all)", values.len());
            }
        }
        _ => write_fields_summary(out, f),
    }
}

impl SniffWriter {
    pub fn new(format: Format, colour: bool) -> Self {
        Self {
            format,
            colour,
            csv_header_written: false,
            line: Vec::with_capacity(512),
            text: String::with_capacity(256),
        }
    }

    fn paint(&self, colour: &str, text: String) -> String {
        if self.colour {
            format!("{colour}{text}{RESET}")
        } else {
            text
        }
    }

    pub fn record(&mut self, out: &mut dyn Write, record: &Record) -> io::Result<()> {
        match (self.format, record) {
            (Format::Json, Record::Frame(frame)) => {
                self.line.clear();
                self.text.clear();
                push_spaced_hex(&mut self.text, &frame.found.bytes);
                frame_json(&mut self.line, frame, &self.text)?;
                self.line.push(b'\n');
                out.write_all(&self.line)
            }
            (
                Format::Json,
                Record::Noise {
                    kept,
                    len,
                    offset,
                    at,
                    ..
                },
            ) => {
                self.line.clear();
                self.text.clear();
                push_spaced_hex(&mut self.text, kept);
                let mut object = JsonObject::open(&mut self.line);
                object.plain("type", "noise");
                object.field("time", &seconds(*at))?;
                object.field("offset", offset)?;
                object.field("count", len)?;
                object.plain("bytes", &self.text);
                object.close();
                self.line.push(b'\n');
                out.write_all(&self.line)
            }
            (
                Format::Json,
                Record::Unanswered {
                    slave,
                    request,
                    waited,
                    capture_ended,
                    tcp,
                },
            ) => {
                let (_, fields) = describe_pdu(&mbtool_core::codec::Pdu::Request(request.clone()));
                json_line(
                    out,
                    &mut self.line,
                    &JsonUnanswered {
                        kind: "unanswered",
                        slave: *slave,
                        function: request.function(),
                        request: fields,
                        waited: waited.map(seconds),
                        capture_ended: *capture_ended,
                        transaction: tcp.map(|(_, transaction)| transaction),
                        tcp: tcp.as_ref().map(|(place, _)| JsonTcp::from(place)),
                    },
                )
            }
            (Format::Csv, Record::Frame(frame)) => self.csv(out, frame),
            (Format::Csv, _) => Ok(()),
            (Format::Values, Record::Frame(frame)) => match &frame.report().fields.values {
                Some(values) if frame.report().kind == Kind::Response => {
                    for value in shown_values(values, usize::MAX).split(' ') {
                        writeln!(out, "{value}")?;
                    }
                    Ok(())
                }
                _ => Ok(()),
            },
            (Format::Values, _) => Ok(()),
            (Format::Table, record) => self.line(out, record),
        }
    }

    fn csv(&mut self, out: &mut dyn Write, frame: &FrameRecord) -> io::Result<()> {
        if let Some(place) = &frame.tcp {
            return self.tcp_csv(out, frame, place);
        }
        if !self.csv_header_written {
            writeln!(out, "{CSV_HEADER}")?;
            self.csv_header_written = true;
        }
        let r = frame.report();
        writeln!(
            out,
            "{},{},{},{},{},{},{},{}",
            frame.number,
            // As JSON gives it: when the frame came, or without timing where it stands at
            // the line's speed.
            Seconds(frame.at),
            frame
                .gap
                .map(|t| Seconds(t).to_string())
                .unwrap_or_default(),
            r.slave,
            r.function,
            r.kind.name(),
            r.valid,
            csv_field(&{
                let mut summary = String::new();
                write_serial_summary(&mut summary, frame);
                summary
            }),
        )
    }

    /// A frame of a TCP capture: its connection, transaction and response time instead
    /// of the silence before it.
    fn tcp_csv(
        &mut self,
        out: &mut dyn Write,
        frame: &FrameRecord,
        place: &TcpPlace,
    ) -> io::Result<()> {
        if !self.csv_header_written {
            writeln!(out, "{TCP_CSV_HEADER}")?;
            self.csv_header_written = true;
        }
        let r = frame.report();
        let show = |value: Option<u64>| value.map(|v| v.to_string()).unwrap_or_default();
        writeln!(
            out,
            "{},{:.6},{},{},{},{},{},{},{},{},{},{}",
            frame.number,
            seconds(frame.at),
            place.client,
            place.server,
            place.packet,
            show(r.transaction.map(u64::from)),
            r.slave,
            r.function,
            r.kind.name(),
            r.valid,
            show(place.response_time),
            csv_field(&frame_summary(r)),
        )
    }

    /// The time column: seconds when the time is known, else `@offset`, 12 wide.
    fn when(time: Option<u64>, offset: u64) -> String {
        let mut text = String::new();
        Self::write_when(&mut text, 0, 12, time, offset);
        text
    }

    /// The time column, ending `stop` characters into the line that began at byte `line`.
    fn write_when(out: &mut String, line: usize, stop: usize, time: Option<u64>, offset: u64) {
        match time {
            Some(us) => column(out, line, stop, Align::Right, Seconds(us)),
            None => column(out, line, stop, Align::Right, Offset(offset)),
        }
    }

    /// A serial frame's line, put together in `self.text`: the number, time, gap, slave,
    /// function, kind, what it says and its checksum.
    fn serial_frame_line(&mut self, frame: &FrameRecord) {
        let r = frame.report();
        let text = &mut self.text;
        text.clear();
        let colour = if !r.valid {
            Some(RED)
        } else if r.kind == Kind::Exception || frame.mismatch.is_some() {
            Some(YELLOW)
        } else {
            None
        };
        if let (true, Some(colour)) = (self.colour, colour) {
            text.push_str(colour);
        }
        // The stops of the columns: number, time, gap, slave, function code, name, kind.
        let line = text.len();
        text.push('#');
        column(text, line, 7, Align::Left, frame.number);
        Self::write_when(text, line, 19, frame.found.start, frame.found.offset);
        text.push(' ');
        match frame.gap {
            Some(gap) => column(
                text,
                line,
                32,
                Align::Right,
                format_args!(
                    "+{}",
                    mbtool_core::input::duration::show(std::time::Duration::from_micros(gap))
                ),
            ),
            None => pad_to(text, line, 32),
        }
        text.push_str("  slave ");
        column(text, line, 43, Align::Left, r.slave);
        text.push(' ');
        column(text, line, 46, Align::Right, r.function & 0x7F);
        text.push(' ');
        column(text, line, 77, Align::Left, function::name(r.function));
        text.push(' ');
        column(text, line, 87, Align::Left, kind_column(r));
        text.push(' ');
        write_serial_summary(text, frame);
        // A frame that could not be opened has no checksum to show: its error says why.
        let check = check_column(r);
        if !check.is_empty() {
            text.push_str("  [");
            text.push_str(check);
            text.push(']');
        }
        if let (true, Some(_)) = (self.colour, colour) {
            text.push_str(RESET);
        }
        text.push('\n');
    }

    fn line(&mut self, out: &mut dyn Write, record: &Record) -> io::Result<()> {
        match record {
            Record::Frame(frame) => {
                let Some(place) = &frame.tcp else {
                    self.serial_frame_line(frame);
                    return out.write_all(self.text.as_bytes());
                };
                let r = frame.report();
                // An answer that does not fit its request, or answers none seen, says so.
                let note = match (&frame.mismatch, r.kind, place.request_packet) {
                    (Some(mismatch), ..) => format!(" (does not fit the request: {mismatch})"),
                    (None, Kind::Response | Kind::Exception, None) => " (no request seen)".into(),
                    _ => String::new(),
                };
                let mut text = format!(
                    "#{:<6}{} {}  tid {:<5} unit {:<3} {:>2} {:<30} {:<9} {}{note}{}",
                    frame.number,
                    Self::when(Some(frame.at), frame.found.offset),
                    connection(place),
                    r.transaction.unwrap_or_default(),
                    r.slave,
                    r.function & 0x7F,
                    function::name(r.function),
                    kind_column(r),
                    frame_summary(r),
                    place
                        .response_time
                        .map(|us| format!("  [{}]", duration(us)))
                        .unwrap_or_default(),
                );
                if !r.valid {
                    text = self.paint(RED, text);
                } else if r.kind == Kind::Exception {
                    text = self.paint(YELLOW, text);
                }
                writeln!(out, "{text}")
            }
            Record::Noise {
                kept,
                len,
                offset,
                time,
                ..
            } => {
                let text = &mut self.text;
                text.clear();
                text.push_str("       ");
                Self::write_when(text, 0, 19, *time, *offset);
                pad_to(text, 0, 32);
                text.push_str("  noise: ");
                text.push_str(itoa::Buffer::new().format(*len));
                text.push_str(if *len == 1 { " byte: " } else { " bytes: " });
                push_spaced_hex(text, &kept[..kept.len().min(16)]);
                text.push_str(if *len > 16 { " ...\n" } else { "\n" });
                out.write_all(text.as_bytes())
            }
            Record::Unanswered {
                slave,
                request,
                waited,
                capture_ended,
                tcp,
            } => {
                let waited = waited
                    .map(|w| {
                        format!(
                            " (waited {})",
                            mbtool_core::input::duration::show(std::time::Duration::from_micros(w))
                        )
                    })
                    .unwrap_or_default();
                let on = tcp
                    .map(|(place, transaction)| {
                        format!(" on {}, tid {transaction}", connection(&place))
                    })
                    .unwrap_or_default();
                let ended = if *capture_ended {
                    " before the capture ended"
                } else {
                    ""
                };
                // A request with nothing after its function code says nothing more.
                let summary = request_summary(request);
                let space = if summary.is_empty() { "" } else { " " };
                let text = format!(
                    "       no answer from slave {slave} to {} {}{space}{summary}{ended}{waited}{on}",
                    request.function(),
                    function::name(request.function()),
                );
                writeln!(out, "{}", self.paint(YELLOW, text))
            }
        }
    }

    /// The counts at the end; `packets` for a pcap or pcapng capture.
    pub fn summary(
        &mut self,
        out: &mut dyn Write,
        counts: &Counts,
        packets: Option<&PacketCounts>,
    ) -> io::Result<()> {
        let n = |count: u64, noun: &str| super::plural(count as usize, noun);
        match self.format {
            Format::Json => {
                serde_json::to_writer(
                    &mut *out,
                    &JsonSummary {
                        kind: "summary",
                        counts,
                        packets,
                    },
                )?;
                out.write_all(b"\n")
            }
            Format::Table => {
                if let Some(p) = packets {
                    let jumps = match p.sequence_jumps {
                        0 => String::new(),
                        count => format!(", {} passed over", n(count, "corrupt sequence number")),
                    };
                    writeln!(
                        out,
                        "capture: {} ({} of Modbus connections, {} passed over), {} repeated, {} missing{jumps}",
                        n(p.packets, "packet"),
                        p.modbus,
                        p.other,
                        n(p.repeated_bytes, "byte"),
                        n(p.missing_bytes, "byte"),
                    )?;
                }
                // Frames whose CRC holds but whose PDU reads neither way are counted
                // too, so that the kinds add up to the frames with the CRC errors.
                let malformed = match counts.malformed {
                    0 => String::new(),
                    count => format!(", {count} malformed"),
                };
                let mismatched = match counts.mismatched {
                    0 => String::new(),
                    count => format!(", {count} not fitting the request"),
                };
                writeln!(
                    out,
                    "summary: {} ({}, {}, {}{malformed}), {} unanswered{mismatched}, {}, {}",
                    n(counts.frames, "frame"),
                    n(counts.requests, "request"),
                    n(counts.answers, "answer"),
                    n(counts.exceptions, "exception"),
                    counts.unanswered,
                    n(counts.crc_errors, "CRC error"),
                    n(counts.noise_bytes, "noise byte"),
                )?;
                for (slave, c) in counts.slaves.iter() {
                    writeln!(
                        out,
                        "  slave {slave}: {}, {}, {}, {} unanswered, {}",
                        n(c.requests, "request"),
                        n(c.answers, "answer"),
                        n(c.exceptions, "exception"),
                        c.unanswered,
                        n(c.crc_errors, "CRC error"),
                    )?;
                }
                Ok(())
            }
            // No frame, no header yet: the header alone, so that a script reading the
            // columns finds them in an empty result too.
            Format::Csv if !self.csv_header_written => {
                self.csv_header_written = true;
                let header = match packets {
                    Some(_) => TCP_CSV_HEADER,
                    None => CSV_HEADER,
                };
                writeln!(out, "{header}")
            }
            Format::Values | Format::Csv => Ok(()),
        }
    }
}

/// One station's line of `--stats` in JSON.
#[derive(Serialize)]
struct JsonStats {
    #[serde(rename = "type")]
    kind: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    server: Option<String>,
    unit: u8,
    requests: u64,
    answers: u64,
    exceptions: BTreeMap<String, u64>,
    unanswered: u64,
    #[serde(skip_serializing_if = "Option::is_none")]
    response_time_us: Option<Times>,
}

impl SniffWriter {
    /// `--stats`: a table, or a JSON line per server and unit.
    pub fn stats(&mut self, out: &mut dyn Write, stats: &Stats) -> io::Result<()> {
        let exceptions = |codes: &BTreeMap<u8, u64>| -> BTreeMap<String, u64> {
            codes
                .iter()
                .map(|(code, n)| (format!("{code:02X}"), *n))
                .collect()
        };
        match self.format {
            Format::Json => {
                for ((server, unit), tally) in &stats.stations {
                    let line = JsonStats {
                        kind: "stats",
                        server: server.map(|s| s.to_string()),
                        unit: *unit,
                        requests: tally.requests,
                        answers: tally.answers,
                        exceptions: exceptions(&tally.exceptions),
                        unanswered: tally.unanswered,
                        response_time_us: tally.times(),
                    };
                    json_line(out, &mut self.line, &line)?;
                }
                Ok(())
            }
            Format::Table => {
                let mut table = super::new_table(self.colour);
                table.set_header([
                    "server",
                    "unit",
                    "requests",
                    "answers",
                    "exceptions",
                    "unanswered",
                    "min",
                    "mean",
                    "p95",
                    "max",
                    "slowest",
                ]);
                for ((server, unit), tally) in &stats.stations {
                    let codes: Vec<String> = exceptions(&tally.exceptions)
                        .iter()
                        .map(|(code, n)| format!("{code} x{n}"))
                        .collect();
                    let mut row = vec![
                        server.map_or_else(|| "the line".to_string(), |s| s.to_string()),
                        unit.to_string(),
                        tally.requests.to_string(),
                        tally.answers.to_string(),
                        codes.join(", "),
                        tally.unanswered.to_string(),
                    ];
                    match tally.times() {
                        Some(t) => row.extend([
                            duration(t.spread.min),
                            duration(t.spread.mean),
                            duration(t.spread.p95),
                            duration(t.spread.max),
                            format!(
                                "{} {}",
                                t.slowest_function,
                                function::name(t.slowest_function)
                            ),
                        ]),
                        None => row.extend(["-", "-", "-", "-", "-"].map(String::from)),
                    }
                    table.add_row(row);
                }
                writeln!(out, "{table}")
            }
            Format::Values | Format::Csv => Ok(()),
        }
    }
}

/// `client → server`, as a line shows a connection.
fn connection(place: &TcpPlace) -> String {
    match place.from_client {
        true => format!("{} → {}", place.client, place.server),
        false => format!("{} ← {}", place.client, place.server),
    }
}

fn duration(us: u64) -> String {
    mbtool_core::input::duration::show(std::time::Duration::from_micros(us))
}

/// Where the records go: the screen (or a pipe), and the pcap file.
pub struct SniffSink {
    pub writer: SniffWriter,
    pub out: Box<dyn Write>,
    pub pcap: Option<PcapWriter<OutputFile>>,
    /// Microseconds since 1970 of capture time 0, for pcap timestamps.
    pub epoch_us: u64,
    pub mode: Mode,
    /// Records are flushed as they are written: a live line, or standard input, which may
    /// be another program's live capture.
    pub live: bool,
    /// `--stats`: the tallies, kept from every record shown.
    pub stats: Option<Stats>,
}

impl RecordSink for SniffSink {
    fn write(&mut self, records: &mut Vec<Record>) -> io::Result<()> {
        // Written where they lie, then dropped together: a frame record is large to move.
        for record in records.iter() {
            if let Some(stats) = self.stats.as_mut() {
                stats.record(record);
            }
            if let (Some(pcap), Record::Frame(frame)) = (self.pcap.as_mut(), record) {
                pcap.frame(
                    self.epoch_us + frame.at,
                    &pcap::rtu_form(self.mode, &frame.found.bytes),
                )?;
            }
            self.writer.record(&mut self.out, record)?;
        }
        records.clear();
        if self.live {
            self.out.flush()?;
        }
        Ok(())
    }
}

/// A file sniff writes, buffered, its errors naming it.
pub type OutputFile = std::io::BufWriter<super::Named<std::fs::File>>;

#[cfg(test)]
mod tests;
