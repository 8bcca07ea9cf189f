//! `--poll`: a read every interval until Ctrl-C or `--count`, as the rows of a log: a
//! failed read is a row of its own, a dropped connection is opened again, and `--log FILE`
//! appends the same rows while the screen shows the usual output.

use std::io::Write;
use std::sync::mpsc;
use std::time::Duration;

use anyhow::Result;

use mbtool::connection::Connector;
use mbtool::error::Error;
use mbtool::output::Format;
use mbtool::output::{self, PollRows};
use mbtool::settings::Settings;
use mbtool_core::master::poll::{poll, PollOptions, Tick};
use mbtool_core::master::run::RunError;
use mbtool_core::master::Master;

/// Now, as a row of a log shows it: RFC 3339 with milliseconds and the local offset.
pub(super) fn now() -> String {
    chrono::Local::now().to_rfc3339_opts(chrono::SecondsFormat::Millis, false)
}

/// The rows of a poll appended to `--log FILE`: CSV for a `.csv` name, JSON Lines else.
pub(super) struct Log<W> {
    pub(super) rows: W,
    pub(super) file: std::io::BufWriter<output::Named<std::fs::File>>,
}

pub(super) fn open_log<W: PollRows>(
    path: &std::path::Path,
    writer: impl Fn(Format) -> W,
) -> Result<Log<W>> {
    let csv = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("csv"));
    let file = output::create_file(path, true)
        .map_err(|e| anyhow::anyhow!("cannot open {}: {e}", path.display()))?;
    let mut rows = writer(if csv { Format::Csv } else { Format::Json });
    // A log appended to has its header already.
    if file
        .get_ref()
        .get_ref()
        .metadata()
        .is_ok_and(|m| m.len() > 0)
    {
        rows.continuing();
    }
    Ok(Log { rows, file })
}

/// Polls with `read`, showing each poll as `writer` (given a format) writes it; the
/// summary on stderr at the end. The exit status is the last poll's.
pub fn run<W: PollRows>(
    settings: &Settings,
    target: &Connector,
    interval: Duration,
    mut read: impl FnMut(&mut Master) -> Result<W::Item, RunError>,
    writer: impl Fn(Format) -> W,
) -> Result<u8> {
    // Datagrams from elsewhere, told at the end with the summary.
    let mut foreign = None;
    let read = |master: &mut Master| {
        let item = read(master);
        foreign = master.foreign().or(foreign);
        item
    };
    let mut screen = writer(settings.output.format);
    let mut log = settings
        .poll
        .log
        .as_deref()
        .map(|path| open_log(path, &writer))
        .transpose()?;
    // Ctrl-C ends the poll between reads, so that no line is cut and the summary shows.
    let (stop, stopped) = mpsc::channel();
    ctrlc::set_handler(move || {
        let _ = stop.send(());
    })
    .map_err(|e| anyhow::anyhow!("cannot catch Ctrl-C: {e}"))?;
    let connect = |path| -> Result<Master, Error> {
        let mut master = target.master_on(path)?;
        if settings.output.verbose {
            master.trace(super::shared::tracer(target.mode));
        }
        Ok(master)
    };
    super::shared::warn_if_secondary_unavailable(target);
    let mut out = output::stdout();
    let mut last_status = 0;
    let options = PollOptions {
        interval,
        count: settings.poll.count,
    };
    let wait = |time| {
        !matches!(
            stopped.recv_timeout(time),
            Err(mpsc::RecvTimeoutError::Timeout)
        )
    };
    let mut path = None;
    // Polls read whole but for some points (a map's): the tally counts them as answered.
    let mut failing_polls = 0u64;
    let stats = poll(connect, read, options, wait, |tick| {
        let time = now();
        let failure = match tick {
            Tick::Read(item) => {
                screen.row(&mut out, &item, &time)?;
                if let Some(log) = log.as_mut() {
                    log.rows.row(&mut log.file, &item, &time)?;
                }
                last_status = screen.status(&item);
                failing_polls += u64::from(last_status != 0);
                None
            }
            Tick::Failed(error) => {
                let (tried, advice) = target.tried_on(path);
                let error = Error::from(error).tried(tried, advice);
                last_status = error.exit_code();
                Some(error.to_string())
            }
            Tick::Disconnected(why) => {
                last_status = 1;
                Some(why)
            }
            Tick::Switched(switch) => {
                path = Some(switch.to);
                let (to, why) = (switch.to.name(), switch.why.as_str());
                mbtool::note!("mbtool: {}", super::shared::switch_text(settings, &switch));
                screen.switched(&mut out, &time, to, why)?;
                if let Some(log) = log.as_mut() {
                    log.rows.switched(&mut log.file, &time, to, why)?;
                }
                None
            }
        };
        if let Some(error) = failure {
            // Where the format has no rows for it, the error goes to stderr.
            if matches!(settings.output.format, Format::Table | Format::Values) {
                mbtool::note!("mbtool: {error}");
            }
            screen.failure(&mut out, &time, &error)?;
            if let Some(log) = log.as_mut() {
                log.rows.failure(&mut log.file, &time, &error)?;
            }
        }
        out.flush()?;
        if let Some(log) = log.as_mut() {
            log.file.flush()?;
        }
        Ok(())
    })?;
    let failing = match failing_polls {
        0 => String::new(),
        n => format!(
            "; in {} some points failed (their rows say why)",
            output::plural(n as usize, "poll")
        ),
    };
    mbtool::note!("mbtool: {}{failing}", stats.summary());
    super::shared::tell_foreign(foreign);
    Ok(last_status)
}
