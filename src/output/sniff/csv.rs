//! Comma-separated values, a header first.

use std::io::{self, Write};

use mbtool_core::sniff::session::{Counts, FrameRecord, Record, TcpPlace};
use mbtool_core::sniff::tcp::PacketCounts;

use super::super::columns::Seconds;
use super::super::csv_field;
use super::frame_json::seconds;
use super::{frame_summary, write_serial_summary, FrameWriter};

/// The columns of a serial line's frames.
const CSV_HEADER: &str = "number,time,gap,slave,function,kind,valid,summary";

/// The columns of a TCP capture's frames.
const TCP_CSV_HEADER: &str =
    "number,time,client,server,packet,transaction,slave,function,kind,valid,response_time_us,summary";

#[derive(Default)]
pub struct CsvWriter {
    header_written: bool,
}

impl FrameWriter for CsvWriter {
    fn record(&mut self, out: &mut dyn Write, record: &Record) -> io::Result<()> {
        match record {
            Record::Frame(frame) => self.csv(out, frame),
            _ => Ok(()),
        }
    }

    fn summary(
        &mut self,
        out: &mut dyn Write,
        _counts: &Counts,
        packets: Option<&PacketCounts>,
    ) -> io::Result<()> {
        // No frame, no header yet: the header alone, so that a script reading the
        // columns finds them in an empty result too.
        if self.header_written {
            return Ok(());
        }
        self.header_written = true;
        let header = match packets {
            Some(_) => TCP_CSV_HEADER,
            None => CSV_HEADER,
        };
        writeln!(out, "{header}")
    }
}

impl CsvWriter {
    fn csv(&mut self, out: &mut dyn Write, frame: &FrameRecord) -> io::Result<()> {
        if let Some(place) = &frame.tcp {
            return self.tcp_csv(out, frame, place);
        }
        if !self.header_written {
            writeln!(out, "{CSV_HEADER}")?;
            self.header_written = true;
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
        if !self.header_written {
            writeln!(out, "{TCP_CSV_HEADER}")?;
            self.header_written = true;
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
}
