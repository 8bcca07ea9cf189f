//! How `scan --hosts` shows a network swept: a row per host and port that took a
//! connection, a summary of the rest; JSON and CSV a row per host and port asked.

use std::io::{self, Write};

use serde::Serialize;

use super::{csv_field, new_table, plural, Format};
use mbtool_core::codec::DeviceObject;
use mbtool_core::master::hosts::{HostReport, Instead, Reach, Unit};
use mbtool_core::model::values::escape_text;

/// Whether Modbus answered, or what the connection did instead.
fn modbus_text(report: &HostReport) -> &'static str {
    match (report.modbus, report.interrupted, report.instead) {
        (true, false, _) => "yes",
        (true, true, _) => "yes (interrupted)",
        (false, true, _) => "interrupted",
        (false, false, Some(Instead::Garbage)) => "no: bytes that are no Modbus answer",
        (false, false, Some(Instead::Closed)) => "no: the host closed the connection",
        (false, false, Some(Instead::Tls)) => "no: it speaks TLS (Modbus/TCP Security?)",
        (false, false, None) => "no answer",
    }
}

fn instead_name(instead: Instead) -> &'static str {
    match instead {
        Instead::Garbage => "garbage",
        Instead::Closed => "closed",
        Instead::Tls => "tls",
    }
}

fn reach_name(reach: Reach) -> &'static str {
    match reach {
        Reach::Open => "open",
        Reach::Refused => "refused",
        Reach::Silent => "no answer",
        Reach::Unknown => "unknown name",
    }
}

/// A unit's identification in a few words: its vendor, product code and revision.
fn identity(unit: &Unit) -> String {
    let Some(found) = &unit.identification else {
        return String::new();
    };
    let words: Vec<String> = found
        .objects
        .iter()
        .filter(|object| object.id <= 2)
        .map(|object: &DeviceObject| escape_text(&object.value))
        .collect();
    words.join(" ")
}

fn server_id(unit: &Unit) -> String {
    unit.server_id
        .as_ref()
        .map(|id| escape_text(&id.data))
        .unwrap_or_default()
}

#[derive(Serialize)]
struct JsonUnit {
    unit: u8,
    #[serde(skip_serializing_if = "Option::is_none")]
    exception: Option<u8>,
    #[serde(skip_serializing_if = "String::is_empty")]
    identification: String,
    #[serde(skip_serializing_if = "String::is_empty")]
    server_id: String,
}

#[derive(Serialize)]
struct JsonHost<'a> {
    host: &'a str,
    #[serde(skip_serializing_if = "Option::is_none")]
    address: Option<String>,
    port: u16,
    reach: &'static str,
    modbus: bool,
    units: Vec<JsonUnit>,
    /// Where Modbus did not answer, what the connection did instead: garbage, closed,
    /// reset.
    #[serde(skip_serializing_if = "Option::is_none")]
    instead: Option<&'static str>,
    /// The TLS handshake failed: why.
    #[serde(skip_serializing_if = "Option::is_none")]
    tls_failed: Option<&'a str>,
    /// Silent to 0, 1 and 255: the other ids were not asked (--all asks them).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    others_not_asked: bool,
    /// Every id asked answered: the device does not tell unit ids apart.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    ignores_unit_id: bool,
    /// A signal ended its asking: its units are those found until then.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    interrupted: bool,
}

/// Whether every id asked answered, more than the usual three: a device that does not
/// tell unit ids apart, whose list would say nothing.
fn ignores_unit_id(report: &HostReport, ids_asked: usize) -> bool {
    ids_asked > 3 && report.units.len() == ids_asked
}

fn units_text(report: &HostReport, ids_asked: usize) -> String {
    if ignores_unit_id(report, ids_asked) {
        return format!("all {ids_asked} asked: the device does not tell unit ids apart");
    }
    let ids: Vec<String> = report.units.iter().map(|u| u.id.to_string()).collect();
    ids.join(" ")
}

/// Every report, in the order given (the caller sorts them).
pub fn write_hosts(
    out: &mut dyn Write,
    format: Format,
    colour: bool,
    reports: &[HostReport],
    ids_asked: usize,
) -> io::Result<()> {
    match format {
        Format::Json => {
            for report in reports {
                let host = JsonHost {
                    host: &report.host,
                    address: report.address.map(|a| a.ip().to_string()),
                    port: report.port,
                    reach: reach_name(report.reach),
                    modbus: report.modbus,
                    units: report
                        .units
                        .iter()
                        .map(|unit| JsonUnit {
                            unit: unit.id,
                            exception: unit.exception.map(|code| code.0),
                            identification: identity(unit),
                            server_id: server_id(unit),
                        })
                        .collect(),
                    instead: report.instead.filter(|_| !report.modbus).map(instead_name),
                    tls_failed: report.tls_failed.as_deref(),
                    others_not_asked: report.given_up,
                    ignores_unit_id: ignores_unit_id(report, ids_asked),
                    interrupted: report.interrupted,
                };
                serde_json::to_writer(&mut *out, &host)?;
                writeln!(out)?;
            }
            Ok(())
        }
        Format::Csv => {
            writeln!(
                out,
                "host,port,reach,modbus,units,identification,server_id,interrupted"
            )?;
            for report in reports {
                let first = report.units.first();
                writeln!(
                    out,
                    "{},{},{},{},{},{},{},{}",
                    csv_field(&report.host),
                    report.port,
                    reach_name(report.reach),
                    report.modbus,
                    units_text(report, ids_asked),
                    csv_field(&first.map(identity).unwrap_or_default()),
                    csv_field(&first.map(server_id).unwrap_or_default()),
                    report.interrupted,
                )?;
            }
            Ok(())
        }
        Format::Values => {
            for report in reports.iter().filter(|r| r.modbus) {
                writeln!(out, "{}:{}", report.host, report.port)?;
            }
            Ok(())
        }
        Format::Table => {
            let open: Vec<&HostReport> =
                reports.iter().filter(|r| r.reach == Reach::Open).collect();
            if !open.is_empty() {
                let mut table = new_table(colour);
                table.set_header(vec![
                    "host",
                    "port",
                    "modbus",
                    "units",
                    "identification",
                    "server id",
                ]);
                for report in open {
                    let first = report.units.first();
                    table.add_row(vec![
                        report.host.clone(),
                        report.port.to_string(),
                        match &report.tls_failed {
                            Some(why) => format!("no: TLS failed: {why}"),
                            None => modbus_text(report).to_string(),
                        },
                        units_text(report, ids_asked),
                        first.map(identity).unwrap_or_default(),
                        first.map(server_id).unwrap_or_default(),
                    ]);
                }
                writeln!(out, "{table}")?;
            }
            let given_up = reports.iter().filter(|r| r.given_up).count();
            if given_up > 0 {
                writeln!(
                    out,
                    "{} silent to unit ids 0, 1 and 255: their other ids not asked (--all asks them)",
                    plural(given_up, "host port")
                )?;
            }
            let count = |reach| reports.iter().filter(|r| r.reach == reach).count();
            writeln!(
                out,
                "{} asked: {} with Modbus, {} open, {} refused, {} silent{}",
                plural(reports.len(), "host port"),
                reports.iter().filter(|r| r.modbus).count(),
                count(Reach::Open),
                count(Reach::Refused),
                count(Reach::Silent),
                match count(Reach::Unknown) {
                    0 => String::new(),
                    n => format!(", {n} unknown names"),
                }
            )
        }
    }
}
