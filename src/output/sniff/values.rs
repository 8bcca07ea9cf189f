//! Only the values an answer read, one per line.

use std::io::{self, Write};

use mbtool_core::describe::Kind;
use mbtool_core::sniff::session::Record;

use super::super::shown_values;
use super::FrameWriter;

pub struct ValuesWriter;

impl FrameWriter for ValuesWriter {
    fn record(&mut self, out: &mut dyn Write, record: &Record) -> io::Result<()> {
        match record {
            Record::Frame(frame) => match &frame.report().fields.values {
                Some(values) if frame.report().kind == Kind::Response => {
                    for value in shown_values(values, usize::MAX).split(' ') {
                        writeln!(out, "{value}")?;
                    }
                    Ok(())
                }
                _ => Ok(()),
            },
            _ => Ok(()),
        }
    }
}
