//! `mbtool sniff`: a passive capture of a bus, live from a port or replayed from a file.

use std::fs::File;
use std::io::{self, BufRead, Read};
use std::path::Path;

use anyhow::{Context, Result};

use mbtool::error::Error;
use mbtool::output;
use mbtool::output::sniff::OutputFile;
use mbtool::settings::{job, Settings};
use mbtool_core::sniff::capture;
use mbtool_core::sniff::pcap::PcapWriter;
use mbtool_core::sniff::timing;

mod serial;
mod tcp;

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

pub fn run(settings: &Settings, job: &job::Sniff) -> Result<u8> {
    let mut input = match &job.input {
        Some(path) => Some(open_input(path)?),
        None => None,
    };
    match (&job.input, input.as_mut()) {
        (Some(path), Some(reader)) => {
            let start = reader
                .fill_buf()
                .with_context(|| format!("cannot read {}", path.display()))?;
            if capture::is_capture(start) {
                return tcp::replay_capture(settings, job, path, reader);
            }
            // A file is what its bytes are, whatever its name: `--save bus.cap` is read
            // back as the raw serial capture it is.
            if !job.tcp_ports.is_empty() {
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
        _ if job.interface.is_some() => return tcp::capture_live(settings, job),
        _ if !job.tcp_ports.is_empty() => {
            return Err(Error::usage(
                "--tcp-port picks the Modbus connections of a capture: give --input FILE.pcap",
            )
            .into())
        }
        _ => {}
    }
    serial::run(settings, job, input)
}

/// `--pcap FILE`: the frames found, for Wireshark.
fn pcap_file(job: &job::Sniff) -> Result<Option<PcapWriter<OutputFile>>> {
    let Some(path) = &job.pcap else {
        return Ok(None);
    };
    let file = output::create_file(path, false)
        .with_context(|| format!("cannot create {}", path.display()))?;
    Ok(Some(PcapWriter::new(file)?))
}
