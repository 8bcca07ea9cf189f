//! What is told when a connection fails or is made: a serial port that does not open
//! (the ports that are here, the process holding it), where a master asked when no
//! answer came, a TLS session with `-v`, and a TCP port another process listens on.

use std::io;

use crate::error::Error;
use crate::settings::ConnectionSettings;
use mbtool_core::codec::Mode;
use mbtool_core::model::line::{DirectionControl, LineSettings, Parity};
use mbtool_core::transport::tls::TlsSession;
use mbtool_core::transport::Endpoint;

/// A serial port that did not open, told with what to try: the ports that are here, who
/// holds it, or how else to switch its transceiver.
pub(super) fn serial_failure(path: &str, line: &LineSettings, e: io::Error) -> Error {
    if e.kind() != io::ErrorKind::Unsupported {
        return Error::Io(with_ports_here(path, e));
    }
    let hint = match line.direction {
        DirectionControl::Kernel(_) => "try --rts-toggle",
        _ => "try --rs485, or an adapter that switches its transceiver itself",
    };
    Error::Io(io::Error::new(e.kind(), format!("{e}: {hint}")))
}

/// `-v` on a TLS connection: what was agreed, whom it is with, and the role sent.
pub(super) fn tell_session(session: &TlsSession) {
    let role = session
        .role_sent
        .as_deref()
        .map_or_else(|| "none".to_string(), |role| format!("'{role}'"));
    crate::note!(
        "mbtool: {}, {}; device certificate {} (valid until {}); role sent: {role}",
        session.version,
        session.cipher_suite,
        session.subject,
        session.not_after
    );
}

/// Where and how a master asked, for a timeout's message, and what usually causes one there.
pub(super) fn tried(
    options: &ConnectionSettings,
    endpoint: &Endpoint,
    mode: Mode,
) -> (String, &'static str) {
    match endpoint {
        Endpoint::Serial(path) => {
            let line = options.line(mode);
            let parity = match line.parity {
                Parity::None => "no parity",
                Parity::Even => "even parity",
                Parity::Odd => "odd parity",
            };
            (
                format!(
                    "on {path} ({mode}, {} baud, {parity}, {} data bits, {} stop {})",
                    line.baud,
                    line.data_bits,
                    line.stop_bits,
                    if line.stop_bits == 1 { "bit" } else { "bits" },
                ),
                "check the slave id, and --baud, --parity and --mode against the device's \
                 settings, and the wiring (A and B swapped, no common ground)",
            )
        }
        Endpoint::RtuOverTcp { .. } | Endpoint::RtuOverUdp { .. } => (
            format!("through {endpoint} ({mode})"),
            "check the slave id, and the gateway's serial settings and wiring to the device",
        ),
        Endpoint::Sim => (
            "from the built-in slave (sim)".into(),
            "it answers as slave 17 only",
        ),
        Endpoint::Tcp { .. } | Endpoint::Tls { .. } | Endpoint::Udp { .. } => (
            format!("from {endpoint}"),
            "check the unit id (a gateway passes it on as the slave id) and that the device \
             behind it answers",
        ),
    }
}

/// A serial port that cannot be opened because it is not there, told with the serial
/// ports that are (`/dev/ttyUSB0, /dev/ttyS0`), or that there is none.
fn with_ports_here(path: &str, error: io::Error) -> io::Error {
    if std::path::Path::new(path).exists() {
        return with_holders(path, error);
    }
    let mut ports: Vec<String> = mbtool_core::transport::serial::ports_here();
    ports.retain(|port| port != path);
    let here = match ports.as_slice() {
        [] => "no serial port is here".to_string(),
        ports => format!("the serial ports here are {}", ports.join(", ")),
    };
    io::Error::new(error.kind(), format!("{error} ({here})"))
}

/// A port that another process has open is named with the process, so that it can be
/// closed (a terminal program, a forgotten `mbtool watch`, ModemManager).
fn with_holders(path: &str, error: io::Error) -> io::Error {
    let holders = mbtool_core::transport::ports::holders_of(std::path::Path::new("/"), path);
    if holders.is_empty() {
        return error;
    }
    io::Error::new(
        error.kind(),
        format!(
            "{error}: {path} is open in {}; close it there first",
            processes(&holders)
        ),
    )
}

/// Processes as a message names them: `minicom (pid 4242), pid 77`.
fn processes(holders: &[mbtool_core::transport::ports::Holder]) -> String {
    holders
        .iter()
        .map(|holder| match &holder.command {
            Some(command) => format!("{command} (pid {})", holder.pid),
            None => format!("pid {}", holder.pid),
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// A TCP listener on `host:port` for `endpoint`; a port another process listens on is
/// named with that process.
pub fn listen(endpoint: &Endpoint, host: &str, port: u16) -> anyhow::Result<std::net::TcpListener> {
    std::net::TcpListener::bind((host, port)).map_err(|error| {
        let holders = match error.kind() {
            io::ErrorKind::AddrInUse => {
                mbtool_core::transport::ports::listeners_of(std::path::Path::new("/"), port)
            }
            _ => Vec::new(),
        };
        match holders.as_slice() {
            [] => anyhow::anyhow!("cannot listen on {endpoint}: {error}"),
            held => anyhow::anyhow!(
                "cannot listen on {endpoint}: {error}: port {port} is taken by {}; stop it, or give another port",
                processes(held)
            ),
        }
    })
}
