//! A master opened on a path to a device: the transport of its endpoint, a serial line
//! with the line's settings, and the master's pace taken from the line.

use std::io;
use std::time::Duration;

use crate::codec::Mode;
use crate::model::line::LineSettings;
use crate::slave::sim::SimTransport;
use crate::transport::serial::Serial;
use crate::transport::tcp::Tcp;
use crate::transport::tls::{ClientTls, Tls, TlsSession};
use crate::transport::udp::Udp;
use crate::transport::{Endpoint, Transport};

use super::{Master, MasterOptions};

/// After a broadcast, the slaves need time to act before the next request (the Modbus
/// serial line specification suggests 100-200 ms).
const BROADCAST_TURNAROUND: Duration = Duration::from_millis(100);

/// A path to a device, as a master is opened on it.
pub struct PathSettings<'a> {
    /// Where the device is.
    pub endpoint: &'a Endpoint,
    /// How its frames are wrapped.
    pub mode: Mode,
    /// A serial line's settings (those of the device's line behind an RTU over TCP
    /// gateway too).
    pub line: LineSettings,
    /// How long an answer is waited for, and a connection.
    pub timeout: Duration,
    /// How many times a request is asked again after a timeout or a bad answer.
    pub retries: u32,
    /// Whether a request that may do more when sent twice is asked again too.
    pub retry_non_idempotent: bool,
    /// The silence kept between transactions; `None`: the line's own (3.5 characters for
    /// RTU on a serial line, none elsewhere).
    pub frame_gap: Option<Duration>,
    /// For a tls:// endpoint: this end's certificates, read and checked.
    pub tls: Option<&'a ClientTls>,
}

/// The transport of `path`'s endpoint, with the TLS session agreed on a tls:// one.
pub fn transport(path: &PathSettings) -> io::Result<(Box<dyn Transport>, Option<TlsSession>)> {
    let timeout = path.timeout;
    Ok(match path.endpoint {
        Endpoint::Serial(device) => (Box::new(Serial::open(device, &path.line)?), None),
        Endpoint::Tcp { host, port } => {
            (Box::new(Tcp::connect(host, *port, timeout, false)?), None)
        }
        Endpoint::RtuOverTcp { host, port } => {
            (Box::new(Tcp::connect(host, *port, timeout, true)?), None)
        }
        Endpoint::Tls { host, port } => {
            let tls = path.tls.ok_or_else(|| {
                io::Error::new(
                    io::ErrorKind::InvalidInput,
                    "a tls:// port needs this end's certificate and key",
                )
            })?;
            let stream = Tls::connect(host, *port, timeout, tls)?;
            let session = stream.session().cloned();
            (Box::new(stream), session)
        }
        Endpoint::Udp { host, port } => (Box::new(Udp::connect(host, *port, false)?), None),
        Endpoint::RtuOverUdp { host, port } => (Box::new(Udp::connect(host, *port, true)?), None),
        Endpoint::Sim => (Box::new(SimTransport::new(path.mode)), None),
    })
}

/// A master on `path`, with the TLS session agreed on a tls:// one.
pub fn master(path: &PathSettings) -> io::Result<(Master, Option<TlsSession>)> {
    let (transport, session) = transport(path)?;
    let serial_line = matches!(
        path.endpoint,
        Endpoint::Serial(_) | Endpoint::RtuOverTcp { .. } | Endpoint::RtuOverUdp { .. }
    );
    let line = &path.line;
    let gap = path.frame_gap.unwrap_or(match path.mode {
        Mode::Rtu if serial_line => line.frame_gap(),
        _ => Duration::ZERO,
    });
    let (character, silence) = match serial_line {
        true => (line.character_time(), line.frame_gap()),
        false => (Duration::ZERO, Duration::ZERO),
    };
    let master = Master::new(
        transport,
        MasterOptions {
            mode: path.mode,
            timeout: path.timeout,
            retries: path.retries,
            retry_non_idempotent: path.retry_non_idempotent,
            frame_gap: gap,
            character,
            silence,
            turnaround: BROADCAST_TURNAROUND,
        },
    );
    Ok((master, session))
}
