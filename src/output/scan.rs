//! How `scan` shows the slaves it found: a table or CSV for people, one JSON line per
//! slave for scripts, the bare ids for `$(...)`; and a summary line.

use std::io::{self, Write};

use serde_json::json;

use super::Format;
use super::{csv_field, new_table};
use mbtool_core::codec::Mode;
use mbtool_core::input::choice::Choice;
use mbtool_core::master::scan::{Answer, Hit, ScanReport};
use mbtool_core::model::line::LineSettings;

/// Where the scan asked: the serial settings of each step of the sweep, or none over TCP.
pub struct Where<'a> {
    pub mode: Mode,
    pub settings: &'a [LineSettings],
    pub serial: bool,
}

impl Where<'_> {
    fn line(&self, index: usize) -> Option<&LineSettings> {
        self.settings.get(index).filter(|_| self.serial)
    }

    /// Adds `"baud"` and `"parity"` of a serial setting to a JSON line.
    fn add_setting(&self, line: &mut serde_json::Value, index: usize) {
        if let (Some(object), Some(setting)) = (line.as_object_mut(), self.line(index)) {
            object.insert("baud".into(), json!(setting.baud));
            object.insert("parity".into(), json!(setting.parity.name()));
        }
    }

    /// `19200 baud, even parity`.
    pub fn describe(&self, index: usize) -> String {
        match self.line(index) {
            Some(line) => format!("{} baud, {} parity", line.baud, line.parity.name()),
            None => self.mode.to_string(),
        }
    }
}

fn answer_text(answer: Option<Answer>) -> String {
    match answer {
        Some(Answer::Ok) => "ok".into(),
        Some(Answer::Exception(code)) => format!("exception {code}"),
        None => "heard answering another master".into(),
    }
}

fn answer_json(answer: Option<Answer>) -> (&'static str, Option<u8>) {
    match answer {
        Some(Answer::Ok) => ("ok", None),
        Some(Answer::Exception(code)) => ("exception", Some(code.0)),
        None => ("heard", None),
    }
}

/// How a slave found answered: a late one says so, and one asked again in vain is only
/// known by its late answer.
fn hit_text(hit: &Hit) -> String {
    match (hit.late, hit.answer) {
        (false, answer) => answer_text(answer),
        (true, None) => "late: answered after the timeout".into(),
        (true, answer) => format!("{}, after the timeout", answer_text(answer)),
    }
}

fn hit_json(hit: &Hit) -> (&'static str, Option<u8>) {
    match (hit.late, hit.answer) {
        (true, None) => ("late", None),
        (_, answer) => answer_json(answer),
    }
}

pub fn write_scan(
    out: &mut dyn Write,
    format: Format,
    report: &ScanReport,
    place: &Where,
    colour: bool,
) -> io::Result<()> {
    if let Some(answer) = report.ignores_unit_id {
        match format {
            Format::Json => {
                let (answer, exception) = answer_json(Some(answer));
                let line = json!({"ignores_unit_id": true, "mode": place.mode.name(),
                    "answer": answer, "exception": exception});
                writeln!(out, "{line}")?;
            }
            Format::Table => writeln!(
                out,
                "every id answered ({}): the device does not tell unit ids apart{}",
                answer_text(Some(answer)),
                if report.telling_hits().next().is_some() {
                    "; these answered otherwise:"
                } else {
                    ""
                }
            )?,
            Format::Csv | Format::Values => {}
        }
    }
    match format {
        Format::Json => {
            for hit in report.telling_hits() {
                let (answer, exception) = hit_json(hit);
                let mut line = json!({
                    "slave": hit.slave,
                    "mode": place.mode.name(),
                    "answer": answer,
                    "confirmed": hit.confirmed,
                    "late": hit.late,
                });
                place.add_setting(&mut line, hit.setting);
                if let (Some(object), Some(code)) = (line.as_object_mut(), exception) {
                    object.insert("exception".into(), json!(code));
                }
                writeln!(out, "{line}")?;
            }
            for garbled in &report.garbled {
                let mut line = json!({"slave": garbled.slave, "mode": place.mode.name(),
                    "answer": "garbled", "detail": garbled.detail});
                place.add_setting(&mut line, garbled.setting);
                writeln!(out, "{line}")?;
            }
            Ok(())
        }
        Format::Values => {
            for hit in report.telling_hits() {
                writeln!(out, "{}", hit.slave)?;
            }
            Ok(())
        }
        Format::Csv => {
            writeln!(out, "slave,settings,answer,confirmed")?;
            for hit in report.telling_hits() {
                writeln!(
                    out,
                    "{},{},{},{}",
                    hit.slave,
                    csv_field(&place.describe(hit.setting)),
                    csv_field(&hit_text(hit)),
                    hit.confirmed
                )?;
            }
            Ok(())
        }
        Format::Table => {
            if report.telling_hits().next().is_none() {
                return Ok(());
            }
            let mut table = new_table(colour);
            table.set_header(["slave", "settings", "answer", "confirmed"]);
            for hit in report.telling_hits() {
                let confirmed = if hit.confirmed {
                    "yes"
                } else {
                    "no: silent when asked again"
                };
                table.add_row(vec![
                    hit.slave.to_string(),
                    place.describe(hit.setting),
                    hit_text(hit),
                    confirmed.to_string(),
                ]);
            }
            writeln!(out, "{table}")
        }
    }
}
