//! `sniff` of Modbus TCP: a pcap or pcapng capture replayed, or an interface captured
//! live through libpcap.

use std::path::Path;
use std::sync::atomic::Ordering;
use std::time::Duration;

use anyhow::{Context, Result};

use mbtool::error::{replay_failed, Error};
use mbtool::output;
use mbtool::output::sniff::{self, SniffSink};
use mbtool::settings::{job, Settings};
use mbtool_core::codec::Mode;
use mbtool_core::sniff::capture;
use mbtool_core::sniff::replay::{self, RecordSink};
use mbtool_core::sniff::session::Filter;
use mbtool_core::sniff::stats::Stats;
use mbtool_core::sniff::tcp::{TcpSession, MODBUS_PORT};

use super::{pcap_file, Input};

/// The TCP session of a capture, and where its records go.
fn tcp_session(
    settings: &Settings,
    job: &job::Sniff,
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
        slaves: job.slaves.clone(),
        functions: job.functions.clone(),
    };
    let session = TcpSession::new(mode, modbus_ports(job), filter);
    let sinks = SniffSink {
        writer: sniff::writer(settings.output.format, output::colour_wanted()),
        out: output::stdout(),
        pcap: pcap_file(job)?,
        epoch_us: 0,
        mode,
        live,
        stats: job.stats.then(Stats::default),
    };
    Ok((session, sinks))
}

/// The ports of the Modbus servers: `--tcp-port`, else 502.
fn modbus_ports(job: &job::Sniff) -> Vec<u16> {
    match job.tcp_ports.is_empty() {
        true => vec![MODBUS_PORT],
        false => job.tcp_ports.clone(),
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
pub(super) fn replay_capture(
    settings: &Settings,
    job: &job::Sniff,
    path: &Path,
    input: &mut Input,
) -> Result<u8> {
    if job.save.is_some() {
        return Err(Error::usage(
            "--save keeps the bytes of a serial line; a capture file is kept already (--pcap writes its Modbus frames)",
        )
        .into());
    }
    // Standard input may be another program's live capture: shown as it comes.
    let piped = path.as_os_str() == "-";
    let (mut session, mut sinks) = tcp_session(settings, job, piped)?;
    let read =
        replay::replay_packets(input, piped, &mut session, &mut sinks).map_err(replay_failed)?;
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
pub(super) fn capture_live(settings: &Settings, job: &job::Sniff) -> Result<u8> {
    use mbtool_core::sniff::live::LiveCapture;
    use mbtool_core::sniff::pcap::PcapNgWriter;
    let interface = job.interface.as_deref().unwrap_or_default();
    let (mut session, mut sinks) = tcp_session(settings, job, true)?;
    let ports = modbus_ports(job);
    let mut capture = LiveCapture::open(interface, &ports).map_err(|e| anyhow::anyhow!("{e}"))?;
    let mut save = match &job.save {
        Some(path) => Some(PcapNgWriter::new(
            output::create_file(path, false)
                .with_context(|| format!("cannot create {}", path.display()))?,
            capture.link(),
        )?),
        None => None,
    };
    let stop = super::super::shared::stop_on_signal()?.flag;
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
