//! How `sniff` shows what passes: a line per frame for people (`table`), JSON Lines
//! (`json`), CSV (`csv`), or the values read alone (`values`), each a [`FrameWriter`].

use std::collections::BTreeMap;
use std::io::{self, Write};

use super::Format;
use super::{write_fields_summary, write_value};
use mbtool_core::codec::ExceptionCode;
use mbtool_core::codec::Mode;
use mbtool_core::describe::{FrameReport, Kind};
use mbtool_core::sniff::pcap::{self, PcapWriter};
use mbtool_core::sniff::replay::RecordSink;
use mbtool_core::sniff::session::{Counts, FrameRecord, Record, TcpPlace, ENDS_WITHOUT_CR};
use mbtool_core::sniff::stats::Stats;
use mbtool_core::sniff::tcp::PacketCounts;

mod csv;
mod frame_json;
mod json;
mod table;
mod values;

/// One output format of sniff: each record as it comes, the counts at the end, and the
/// `--stats` tallies.
pub trait FrameWriter: Send {
    /// Writes one record.
    fn record(&mut self, out: &mut dyn Write, record: &Record) -> io::Result<()>;

    /// The counts at the end; `packets` for a pcap or pcapng capture.
    fn summary(
        &mut self,
        _out: &mut dyn Write,
        _counts: &Counts,
        _packets: Option<&PacketCounts>,
    ) -> io::Result<()> {
        Ok(())
    }

    /// `--stats`: the tallies per server and unit.
    fn stats(&mut self, _out: &mut dyn Write, _stats: &Stats) -> io::Result<()> {
        Ok(())
    }
}

/// The writer of `format`.
pub fn writer(format: Format, colour: bool) -> Box<dyn FrameWriter> {
    match format {
        Format::Table => Box::new(table::TableWriter::new(colour)),
        Format::Json => Box::new(json::JsonWriter::default()),
        Format::Csv => Box::new(csv::CsvWriter::default()),
        Format::Values => Box::new(values::ValuesWriter),
    }
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

/// Exception counts by code, as `--stats` shows them: `02`.
fn exceptions(codes: &BTreeMap<u8, u64>) -> BTreeMap<String, u64> {
    codes
        .iter()
        .map(|(code, n)| (format!("{code:02X}"), *n))
        .collect()
}

/// `client → server`, as a line shows a connection.
/// Who sent a frame to whom; a UDP flow is marked so.
fn connection(place: &TcpPlace) -> String {
    let udp = if place.udp { " udp" } else { "" };
    match place.from_client {
        true => format!("{} → {}{udp}", place.client, place.server),
        false => format!("{} ← {}{udp}", place.client, place.server),
    }
}

fn duration(us: u64) -> String {
    mbtool_core::input::duration::show(std::time::Duration::from_micros(us))
}

/// Where the records go: the screen (or a pipe), and the pcap file.
pub struct SniffSink {
    pub writer: Box<dyn FrameWriter>,
    pub out: Box<dyn Write>,
    pub pcap: Option<PcapWriter<OutputFile>>,
    /// Microseconds since 1970 of a serial capture's time 0, for pcap timestamps.
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
                // A packet capture's frames keep their packets' times.
                let time = match frame.tcp {
                    Some(place) => place.time_us,
                    None => self.epoch_us + frame.at,
                };
                pcap.frame(time, &pcap::rtu_form(self.mode, &frame.found.bytes))?;
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
