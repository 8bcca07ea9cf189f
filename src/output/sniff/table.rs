//! A line per frame, for people.

use std::io::{self, Write};

use mbtool_core::codec::function;
use mbtool_core::codec::hex::push_spaced_hex;
use mbtool_core::describe::Kind;
use mbtool_core::sniff::session::{Counts, FrameRecord, Record};
use mbtool_core::sniff::stats::Stats;
use mbtool_core::sniff::tcp::PacketCounts;

use super::super::columns::{column, pad_to, Align, Offset, Seconds};
use super::super::request_summary;
use super::{
    check_column, connection, duration, exceptions, frame_summary, kind_column,
    write_serial_summary, FrameWriter,
};

const RED: &str = "\x1b[31m";
const YELLOW: &str = "\x1b[33m";
const RESET: &str = "\x1b[0m";

pub struct TableWriter {
    colour: bool,
    /// One line put together here: no allocation per frame.
    text: String,
}

impl TableWriter {
    pub fn new(colour: bool) -> Self {
        Self {
            colour,
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
}

impl FrameWriter for TableWriter {
    fn record(&mut self, out: &mut dyn Write, record: &Record) -> io::Result<()> {
        self.line(out, record)
    }

    fn summary(
        &mut self,
        out: &mut dyn Write,
        counts: &Counts,
        packets: Option<&PacketCounts>,
    ) -> io::Result<()> {
        let n = |count: u64, noun: &str| super::super::plural(count as usize, noun);
        {
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
    }

    fn stats(&mut self, out: &mut dyn Write, stats: &Stats) -> io::Result<()> {
        {
            let mut table = super::super::new_table(self.colour);
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
    }
}

impl TableWriter {
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
}
