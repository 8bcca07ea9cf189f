//! `mbtool info SLAVE`: who the device says it is.

use std::io::Write;

use anyhow::Result;

use mbtool::error::Error;
use mbtool::output::device::{write_info, InfoReport, Outcome};
use mbtool::output::{self, colour_wanted};
use mbtool::settings::{job, Settings};
use mbtool_core::codec::function;
use mbtool_core::master::device::{identification, server_id};
use mbtool_core::master::MasterError;

use super::shared::outcome;

pub fn run(settings: &Settings, job: &job::Device) -> Result<u8> {
    let (mut connection, slave) = super::shared::connect_to(settings, &job.slave)?;
    let master = &mut connection.master;
    let asked = outcome(identification(master, slave))
        .and_then(|id| Ok((id, outcome(server_id(master, slave))?)));
    super::shared::tell_foreign(connection.master.foreign());
    let (identification, server_id) = asked.map_err(|e| connection.explain(e.into()))?;
    let report = InfoReport {
        slave,
        identification,
        server_id,
    };
    match (&report.identification, &report.server_id) {
        (Outcome::Answered(_), _) | (_, Outcome::Answered(_)) => {}
        // Neither answered. A refusal is the device's word, and outranks silence.
        (Outcome::Refused(code), _) | (_, Outcome::Refused(code)) => {
            let function = match report.identification {
                Outcome::Refused(_) => function::ENCAPSULATED_INTERFACE,
                _ => function::REPORT_SERVER_ID,
            };
            return Err(Error::Exception {
                slave,
                function,
                code: *code,
            }
            .into());
        }
        (Outcome::NoAnswer(_), Outcome::NoAnswer(_)) => {
            let timeout = MasterError::Timeout {
                slave,
                timeout: settings.connection.timeout,
            };
            return Err(connection.explain(timeout.into()).into());
        }
    }
    let mut out = output::stdout();
    write_info(&mut out, settings.output.format, &report, colour_wanted())?;
    out.flush()?;
    Ok(0)
}
