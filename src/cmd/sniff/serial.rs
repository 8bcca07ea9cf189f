//! `sniff` of a serial line: live from a port, or a capture of one replayed, with its
//! timing when it was saved with it.

use std::io::{self, Read, Write};
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{SystemTime, UNIX_EPOCH};

use anyhow::{Context, Result};

use mbtool::connection::{self, Connector, Role};
use mbtool::output;
use mbtool::output::sniff::{self, SniffSink};
use mbtool::settings::{job, ConnectionSettings, Settings};
use mbtool_core::codec::Mode;
use mbtool_core::model::line::{DirectionControl, LineSettings};
use mbtool_core::sniff::line;
use mbtool_core::sniff::replay::{self, Pace, RecordSink, TimingFile};
use mbtool_core::sniff::session::{Filter, Session};
use mbtool_core::sniff::stats::Stats;
use mbtool_core::sniff::timing::{self, RecordedLine, Saver};
use mbtool_core::transport::serial;

use super::{pcap_file, Input};

/// The line's frames, live from `--port` or replayed from `input`, then the summary.
pub(super) fn run(settings: &Settings, job: &job::Sniff, mut input: Option<Input>) -> Result<u8> {
    let timing = match &job.input {
        Some(path) => TimingFile::beside(path).map_err(mbtool::error::replay_failed)?,
        None => None,
    };
    if let Some((timing, line)) = timing.as_ref().and_then(|t| Some((t, t.cut_off()?))) {
        mbtool::note!(
            "mbtool: {}:{line} is cut off before its end (the capture was stopped as it was \
             written): replaying the capture with the timing before it",
            timing.path().display()
        );
    }
    let (mode, line) = sniffed_line(&settings.connection, timing.as_ref())?;
    let filter = Filter {
        slaves: job.slaves.clone(),
        functions: job.functions.clone(),
    };
    let silence = line.frame_gap();
    let mut session = Session::new(
        mode,
        line.character_us(),
        silence.as_micros() as u64,
        filter,
    );
    let mut save = match &job.save {
        Some(path) => {
            let live = job.input.is_none();
            Some(save_file(
                path,
                live.then(|| RecordedLine::of(mode, &line)),
            )?)
        }
        None => None,
    };
    let pcap = pcap_file(job)?;
    let epoch_us = SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_micros() as u64);
    let mut sinks = SniffSink {
        writer: sniff::writer(settings.output.format, output::colour_wanted()),
        out: output::stdout(),
        pcap,
        epoch_us: if job.input.is_some() { 0 } else { epoch_us },
        mode,
        live: job
            .input
            .as_ref()
            .is_none_or(|path| path.as_os_str() == "-"),
        stats: job.stats.then(Stats::default),
    };
    let mut records = Vec::new();
    let end = match (&job.input, input.as_mut()) {
        (Some(path), Some(input)) => {
            let pace = match &timing {
                Some(timing) => Pace::Timed(timing),
                // A file is read whole and can be framed on every core; a pipe may be a
                // live line, whose frames are shown as they come.
                None if mode != Mode::Tcp
                    && path.as_os_str() != "-"
                    && std::fs::metadata(path).is_ok_and(|m| m.is_file()) =>
                {
                    Pace::Ahead
                }
                None => Pace::AsItComes,
            };
            let replayed = match save.as_mut() {
                Some(save) => {
                    let mut kept = Kept { input, save };
                    replay::replay(&mut kept, pace, &mut session, &mut sinks)
                }
                None => replay::replay(input, pace, &mut session, &mut sinks),
            }
            .map_err(mbtool::error::replay_failed)?;
            if replayed.untimed > 0 {
                mbtool::note!(
                    "mbtool: the .timing file covers the capture's first {} bytes; the last {} are framed without timing",
                    replayed.bytes - replayed.untimed,
                    replayed.untimed
                );
            }
            // The capture ended at its last read or idle, not at its last frame.
            replayed.end
        }
        _ => Some(live(
            settings,
            job,
            line,
            mode,
            &mut session,
            &mut sinks,
            &mut save,
        )?),
    };
    session.finish(end, &mut records);
    sinks.write(&mut records)?;
    sinks
        .writer
        .summary(&mut sinks.out, session.counts(), None)?;
    sinks.out.flush()?;
    if let Some(pcap) = sinks.pcap.as_mut() {
        pcap.flush()?;
    }
    if let Some(save) = save.as_mut() {
        save.flush()?;
    }
    Ok(0)
}

/// A capture read through `--save`, which keeps every byte read.
struct Kept<'a> {
    input: &'a mut Input,
    save: &'a mut Saver,
}

impl Read for Kept<'_> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let n = self.input.read(buf)?;
        self.save.bytes(&buf[..n], None)?;
        Ok(n)
    }
}

/// `--save FILE`: a capture of a port, on `line`, keeps its timing beside it; a replay's
/// does not.
fn save_file(path: &Path, line: Option<RecordedLine>) -> Result<Saver> {
    let create = |path: &Path| -> Result<Box<dyn Write + Send>> {
        let file = output::create_file(path, false)
            .with_context(|| format!("cannot create {}", path.display()))?;
        Ok(Box::new(file))
    };
    let timing = match line {
        Some(line) => Some((create(&timing::beside(path))?, line)),
        None => None,
    };
    Ok(Saver::new(create(path)?, timing)?)
}

/// Reads the port until Ctrl-C; returns the time the capture ended, in microseconds.
fn live(
    settings: &Settings,
    job: &job::Sniff,
    line: LineSettings,
    mode: Mode,
    session: &mut Session,
    sinks: &mut SniffSink,
    save: &mut Option<Saver>,
) -> Result<u64> {
    let connector = Connector::new(&settings.connection, Role::Sniff)?;
    let path = connector.endpoint.to_string();
    if job.low_latency {
        if let Err(message) = serial::set_low_latency(&path) {
            mbtool::note!("mbtool: {message}");
        }
    }
    // Opened like any serial port, but nothing is ever written to it, and RTS is left
    // as it is: --rs485 and --rts-toggle are for the commands that send.
    let line = LineSettings {
        direction: DirectionControl::Automatic,
        ..line
    };
    let mut port = connector.open_serial(&line)?;
    let stop = Arc::new(AtomicBool::new(false));
    let stopper = Arc::clone(&stop);
    ctrlc::set_handler(move || stopper.store(true, Ordering::SeqCst))
        .map_err(|e| anyhow::anyhow!("cannot catch Ctrl-C: {e}"))?;
    mbtool::note!(
        "mbtool: listening on {path} ({mode}, {} baud); Ctrl-C ends with a summary",
        line.baud
    );
    let bursts = || {
        mbtool::note!(
            "mbtool: bytes arrive in bursts, so gaps between frames are not real (frames are still split by content); set the adapter's latency timer: echo 1 | sudo tee /sys/bus/usb-serial/devices/*/latency_timer, or use --low-latency"
        );
    };
    Ok(line::listen(
        &mut port,
        session,
        sinks,
        save.as_mut(),
        &stop,
        bursts,
    )?)
}

/// The mode and line the bytes were sent on: as the options give them, but for a capture
/// whose `timing` file records the line it was taken on, which a replay takes (so that a
/// silence is what it was live) save where an option is typed (or set in the
/// environment), and then says so.
fn sniffed_line(
    options: &ConnectionSettings,
    timing: Option<&TimingFile>,
) -> Result<(Mode, LineSettings)> {
    let Some((timing, recorded)) = timing.and_then(|timing| Some((timing, timing.line()?))) else {
        let mode = connection::mode(options, None, Role::Sniff)?;
        let line = options.line(mode);
        if let Some(timing) = timing.filter(|_| !options.baud_given && !options.parity_given) {
            mbtool::note!(
                "mbtool: {} does not say which line the capture was taken on: replaying it as \
                 {}; give -b and --parity if it was another",
                timing.path().display(),
                timing::RecordedLine::of(mode, &line)
            );
        }
        return Ok((mode, line));
    };
    let mode = match options.mode {
        Some(_) => connection::mode(options, None, Role::Sniff)?,
        None => recorded.mode,
    };
    let baud = match options.baud_given {
        true => options.baud(),
        false => recorded.baud,
    };
    let parity = match options.parity_given {
        true => options.parity(),
        false => recorded.parity,
    };
    // The character as recorded, unless the mode or the parity given changes it: then the
    // data and stop bits that go with those, as on a port.
    let mut line = options.line_at(mode, baud, parity);
    if options.data_bits.is_none() && mode == recorded.mode {
        line.data_bits = recorded.data_bits;
    }
    if options.stop_bits.is_none() && parity == recorded.parity {
        line.stop_bits = recorded.stop_bits;
    }
    let replayed = timing::RecordedLine::of(mode, &line);
    if replayed != recorded {
        mbtool::note!(
            "mbtool: {} records the line as {recorded}; replaying it as {replayed}, as the \
             options say",
            timing.path().display()
        );
    }
    Ok((mode, line))
}
