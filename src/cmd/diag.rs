//! `mbtool diag SLAVE`: round trips, the device's counters and exception status.

use std::io::Write;

use anyhow::Result;

use mbtool::cli::{Cli, DiagArgs};
use mbtool::connection;
use mbtool::error::Error;
use mbtool::output::device::{write_diag, DiagReport, Outcome};
use mbtool::output::{self, colour_wanted};
use mbtool_core::master::device::{clear_counters, counters, exception_status, round_trips, Asked};
use mbtool_core::master::plan::parse_slave;

use super::info::outcome;

/// Round trips timed when `--count` does not say.
const ROUND_TRIPS: u32 = 5;

pub fn run(cli: &Cli, args: &DiagArgs) -> Result<u8> {
    let count = match cli.poll.count.map(u32::try_from) {
        None => ROUND_TRIPS,
        Some(Ok(count)) => count,
        Some(Err(_)) => {
            return Err(Error::usage("--count: give at most 4294967295 round trips").into())
        }
    };
    let mut connection = connection::connect(cli)?;
    let slave = parse_slave(&args.slave, false, connection.is_tcp()).map_err(Error::from)?;
    if cli.output.verbose {
        connection
            .master
            .trace(super::request::tracer(connection.mode));
    }
    let master = &mut connection.master;
    // A device that does not answer at all fails here, with what was tried.
    let round_trips = round_trips(master, slave, count)
        .map(Outcome::from)
        .map_err(|e| connection.explain(cli, e.into()))?;
    let master = &mut connection.master;
    let report = (|| {
        Ok(DiagReport {
            slave,
            round_trips,
            counters: outcome(counters(master, slave).map(Asked::Answered))?,
            exception_status: outcome(exception_status(master, slave))?,
            cleared: match args.clear {
                true => Some(outcome(clear_counters(master, slave))?),
                false => None,
            },
        })
    })()
    .map_err(|e: mbtool_core::master::MasterError| connection.explain(cli, e.into()))?;
    let mut out = output::stdout();
    write_diag(&mut out, cli.output.format(), &report, colour_wanted())?;
    out.flush()?;
    Ok(0)
}
