//! `mbtool diag SLAVE`: round trips, the device's counters and exception status.

use std::io::Write;

use anyhow::Result;

use mbtool::error::Error;
use mbtool::output::device::{write_diag, DiagReport, Outcome};
use mbtool::output::{self, colour_wanted};
use mbtool::settings::{job, Settings};
use mbtool_core::codec::function;
use mbtool_core::master::device::{clear_counters, counters, exception_status, round_trips, Asked};

use super::shared::outcome;

/// Round trips timed when `--count` does not say.
const ROUND_TRIPS: u64 = 5;

pub fn run(settings: &Settings, job: &job::Diag) -> Result<u8> {
    let count = settings.poll.count.unwrap_or(ROUND_TRIPS);
    let (mut connection, slave) = super::shared::connect_to(settings, &job.slave)?;
    let master = &mut connection.master;
    // A device that does not answer at all fails here, with what was tried.
    let round_trips = round_trips(master, slave, count)
        .map(Outcome::from)
        .map_err(|e| connection.explain(e.into()))?;
    let master = &mut connection.master;
    let report = (|| {
        Ok(DiagReport {
            slave,
            round_trips,
            counters: outcome(counters(master, slave).map(Asked::Answered))?,
            exception_status: outcome(exception_status(master, slave))?,
            cleared: match job.clear {
                true => Some(outcome(clear_counters(master, slave))?),
                false => None,
            },
        })
    })()
    .map_err(|e: mbtool_core::master::MasterError| connection.explain(e.into()))?;
    super::shared::tell_foreign(connection.master.foreign());
    // A device that refuses every diagnostic (or a gateway with nothing behind that id)
    // told nothing of its health: that is its answer.
    if let Outcome::Refused(code) = report.round_trips {
        let counted = match &report.counters {
            Outcome::Answered(counters) => counters
                .iter()
                .any(|c| matches!(c.value, Ok(Asked::Answered(_)))),
            _ => false,
        };
        if !counted && !matches!(report.exception_status, Outcome::Answered(_)) {
            return Err(Error::Exception {
                slave,
                function: function::DIAGNOSTICS,
                code,
            }
            .into());
        }
    }
    let mut out = output::stdout();
    write_diag(&mut out, settings.output.format, &report, colour_wanted())?;
    out.flush()?;
    Ok(0)
}
