//! `mbtool sniff`: a passive capture of a bus, live from a port or replayed from a file.

use std::fs::File;
use std::io::{self, BufRead, Read, Write};
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, SystemTime, UNIX_EPOCH};

use anyhow::{Context, Result};

use mbtool::cli::SniffArgs;
use mbtool::connection;
use mbtool::error::Error;
use mbtool::output;
use mbtool::output::sniff::{self, OutputFile, SniffSink};
use mbtool::settings::Settings;
use mbtool_core::codec::Mode;
use mbtool_core::model::line::DirectionControl;
use mbtool_core::model::line::LineSettings;
use mbtool_core::sniff::capture;
use mbtool_core::sniff::line;
use mbtool_core::sniff::pcap::PcapWriter;
use mbtool_core::sniff::session::{Filter, Session};
use mbtool_core::sniff::stats::Stats;
use mbtool_core::sniff::tcp::{TcpSession, MODBUS_PORT};
use mbtool_core::sniff::timing::{self, RecordedLine, Saver};
use mbtool_core::transport::serial;
use mbtool_core::transport::Endpoint;

use mbtool_core::sniff::replay::{self, Pace, RecordSink, TimingFile};

/// A capture file or standard input, its first bytes readable before it is read.
type Input = io::BufReader<Box<dyn Read + Send>>;

fn open_input(path: &Path) -> Result<Input> {
    let mut input: Box<dyn Read + Send> = if path.as_os_str() == "-" {
        Box::new(mbtool::stdin::StoppableStdin::new(
            super::shared::stop_on_signal()?.flag,
        ))
    } else {
        Box::new(File::open(path).with_context(|| format!("cannot open {}", path.display()))?)
    };
    let head = capture::read_head(&mut input)
        .with_context(|| format!("cannot read {}", path.display()))?;
    Ok(io::BufReader::with_capacity(
        1 << 16,
        Box::new(io::Cursor::new(head).chain(input)),
    ))
}

pub fn run(settings: &Settings, args: &SniffArgs) -> Result<u8> {
    let mut input = match &args.input {
        Some(path) => Some(open_input(path)?),
        None => None,
    };
    match (&args.input, input.as_mut()) {
        (Some(path), Some(reader)) => {
            let start = reader
                .fill_buf()
                .with_context(|| format!("cannot read {}", path.display()))?;
            if capture::is_capture(start) {
                return replay_capture(settings, args, path, reader);
            }
            // A file is what its bytes are, whatever its name: `--save bus.cap` is read
            // back as the raw serial capture it is.
            if !args.tcp_ports.is_empty() {
                return Err(Error::usage(format!(
                    "{} is neither a pcap nor a pcapng file: give a capture written by \
                     tcpdump, dumpcap or Wireshark; a raw serial capture takes no --tcp-port",
                    path.display()
                ))
                .into());
            }
            if capture::named_as_capture(path) && !timing::beside(path).exists() {
                // Text is no line's bytes: a log or a paste given the wrong name.
                let what = match capture::content(start) {
                    capture::Content::Empty => Some("empty"),
                    capture::Content::Text => Some("text"),
                    capture::Content::Bytes => None,
                };
                if let Some(what) = what {
                    return Err(Error::usage(format!(
                        "{} is neither a pcap nor a pcapng file ({what}): give a capture \
                         written by tcpdump, dumpcap or Wireshark; mbtool decode reads the \
                         frames of a log",
                        path.display()
                    ))
                    .into());
                }
                mbtool::note!(
                    "mbtool: {} is no pcap or pcapng file: read as the bytes of a serial line",
                    path.display()
                );
            }
        }
        _ if args.interface.is_some() => return capture_live(settings, args),
        _ if !args.tcp_ports.is_empty() => {
            return Err(Error::usage(
                "--tcp-port picks the Modbus connections of a capture: give --input FILE.pcap",
            )
            .into())
        }
        _ => {}
    }
    let timing = match &args.input {
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
    let (mode, line) = connection::sniffed_line(&settings.connection, timing.as_ref())?;
    let filter = Filter {
        slaves: args.slaves.clone(),
        functions: args.functions.clone(),
    };
    let silence = line.frame_gap();
    let mut session = Session::new(
        mode,
        line.character_us(),
        silence.as_micros() as u64,
        filter,
    );
    let mut save = match &args.save {
        Some(path) => {
            let live = args.input.is_none();
            Some(save_file(
                path,
                live.then(|| RecordedLine::of(mode, &line)),
            )?)
        }
        None => None,
    };
    let pcap = pcap_file(args)?;
    let epoch_us = SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_micros() as u64);
    let mut sinks = SniffSink {
        writer: sniff::writer(settings.output.format, output::colour_wanted()),
        out: output::stdout(),
        pcap,
        epoch_us: if args.input.is_some() { 0 } else { epoch_us },
        mode,
        live: args
            .input
            .as_ref()
            .is_none_or(|path| path.as_os_str() == "-"),
        stats: args.stats.then(Stats::default),
    };
    let mut records = Vec::new();
    let end = match (&args.input, input.as_mut()) {
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
            args,
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

/// The TCP session of a capture, and where its records go.
fn tcp_session(
    settings: &Settings,
    args: &SniffArgs,
    live: bool,
) -> Result<(TcpSession, SniffSink)> {
    let mode = match settings.connection.mode {
        None | Some(Mode::Tcp) => Mode::Tcp,
        Some(Mode::Rtu) => Mode::Rtu,
        Some(Mode::Ascii) => {
            return Err(Error::usage(
                "a capture carries MBAP frames (--mode tcp) or RTU frames through a gateway (--mode rtu)",
            )
            .into())
        }
    };
    let filter = Filter {
        slaves: args.slaves.clone(),
        functions: args.functions.clone(),
    };
    let session = TcpSession::new(mode, modbus_ports(args), filter);
    let sinks = SniffSink {
        writer: sniff::writer(settings.output.format, output::colour_wanted()),
        out: output::stdout(),
        pcap: pcap_file(args)?,
        epoch_us: 0,
        mode,
        live,
        stats: args.stats.then(Stats::default),
    };
    Ok((session, sinks))
}

/// The ports of the Modbus servers: `--tcp-port`, else 502.
fn modbus_ports(args: &SniffArgs) -> Vec<u16> {
    match args.tcp_ports.is_empty() {
        true => vec![MODBUS_PORT],
        false => args.tcp_ports.clone(),
    }
}

/// The end of a TCP capture: what the connections hold, the summary and the stats.
fn end_tcp(mut session: TcpSession, mut sinks: SniffSink) -> Result<()> {
    let mut records = Vec::new();
    session.finish(&mut records);
    sinks.write(&mut records)?;
    let packets = session.packet_counts();
    sinks
        .writer
        .summary(&mut sinks.out, session.counts(), Some(&packets))?;
    // Two packets at least, so that a stray one of another protocol is no Modbus port.
    let elsewhere: Vec<(u16, u64)> = session
        .modbus_elsewhere()
        .into_iter()
        .filter(|(_, count)| *count >= 2)
        .collect();
    if !elsewhere.is_empty() {
        let ports: Vec<String> = elsewhere
            .iter()
            .take(4)
            .map(|(port, count)| format!("{port} ({count} packets)"))
            .collect();
        let options: Vec<String> = elsewhere
            .iter()
            .take(4)
            .map(|(port, _)| format!("--tcp-port {port}"))
            .collect();
        mbtool::note!(
            "mbtool: packets on TCP port {} carry Modbus TCP headers: give {} to read them",
            ports.join(", "),
            options.join(" ")
        );
    }
    if let Some(stats) = &sinks.stats {
        sinks.writer.stats(&mut sinks.out, stats)?;
    }
    sinks.out.flush()?;
    if let Some(pcap) = sinks.pcap.as_mut() {
        pcap.flush()?;
    }
    Ok(())
}

/// A pcap or pcapng capture of Modbus TCP (or RTU over TCP): every packet through the
/// TCP session, the records shown as they come.
fn replay_capture(
    settings: &Settings,
    args: &SniffArgs,
    path: &Path,
    input: &mut Input,
) -> Result<u8> {
    if args.save.is_some() {
        return Err(Error::usage(
            "--save keeps the bytes of a serial line; a capture file is kept already (--pcap writes its Modbus frames)",
        )
        .into());
    }
    let (mut session, mut sinks) = tcp_session(settings, args, false)?;
    let mut records = Vec::new();
    let mut written = Ok(());
    let read = capture::read_packets(input, |packet| {
        session.packet(&packet, &mut records);
        sinks.epoch_us = session.first_time();
        written = sinks.write(&mut records);
        written.is_ok()
    });
    written?;
    end_tcp(session, sinks)?;
    let path = path.display();
    match read {
        Ok(_) => Ok(0),
        // Its first bytes are a capture's magic: the file ends inside its header.
        Err(capture::CaptureError::NotACapture) => Err(Error::usage(format!(
            "{path} ends inside its file header: the capture was cut off before its first packet"
        ))
        .into()),
        Err(error) => {
            Err(Error::usage(format!("{path} {error}; what came before is shown")).into())
        }
    }
}

/// `--interface NAME`: Modbus TCP captured live until Ctrl-C or SIGTERM, each frame shown
/// as it comes; `--save` keeps the packets as pcapng.
fn capture_live(settings: &Settings, args: &SniffArgs) -> Result<u8> {
    use mbtool_core::sniff::live::LiveCapture;
    use mbtool_core::sniff::pcap::PcapNgWriter;
    let interface = args.interface.as_deref().unwrap_or_default();
    let (mut session, mut sinks) = tcp_session(settings, args, true)?;
    let ports = modbus_ports(args);
    let mut capture = LiveCapture::open(interface, &ports).map_err(|e| anyhow::anyhow!("{e}"))?;
    let mut save = match &args.save {
        Some(path) => Some(PcapNgWriter::new(
            output::create_file(path, false)
                .with_context(|| format!("cannot create {}", path.display()))?,
            capture.link(),
        )?),
        None => None,
    };
    let stop = super::shared::stop_on_signal()?.flag;
    mbtool::note!(
        "mbtool: capturing Modbus TCP on {interface} (ports {}); Ctrl-C ends with a summary",
        ports
            .iter()
            .map(ToString::to_string)
            .collect::<Vec<_>>()
            .join(", ")
    );
    let mut records = Vec::new();
    let mut saved = Ok(());
    while !stop.load(Ordering::SeqCst) {
        capture
            .next(Duration::from_millis(100), |packet| {
                if let Some(save) = save.as_mut() {
                    saved = save.packet(packet.time_us, packet.data, packet.original_len);
                }
                session.packet(&packet, &mut records);
                sinks.epoch_us = session.first_time();
            })
            .map_err(|e| anyhow::anyhow!("{interface}: {e}"))?;
        saved.as_ref().map_err(|e| anyhow::anyhow!("{e}"))?;
        sinks.write(&mut records)?;
    }
    if let Some(save) = save.as_mut() {
        save.flush()?;
    }
    end_tcp(session, sinks)?;
    Ok(0)
}

/// `--pcap FILE`: the frames found, for Wireshark.
fn pcap_file(args: &SniffArgs) -> Result<Option<PcapWriter<OutputFile>>> {
    let Some(path) = &args.pcap else {
        return Ok(None);
    };
    let file = output::create_file(path, false)
        .with_context(|| format!("cannot create {}", path.display()))?;
    Ok(Some(PcapWriter::new(file)?))
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
    args: &SniffArgs,
    line: LineSettings,
    mode: Mode,
    session: &mut Session,
    sinks: &mut SniffSink,
    save: &mut Option<Saver>,
) -> Result<u64> {
    let path = match settings.connection.port.as_deref().map(Endpoint::parse) {
        Some(Ok(Endpoint::Serial(path))) => path,
        Some(Ok(_)) => {
            return Err(
                Error::usage("sniff listens on a serial device; for a file give --input").into(),
            )
        }
        Some(Err(e)) => return Err(Error::from(e).into()),
        None => {
            return Err(Error::usage(
                "sniff needs --port DEVICE, or --input FILE to replay a capture",
            )
            .into())
        }
    };
    if args.low_latency {
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
    let mut port = connection::open_serial(&path, &line)?;
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
