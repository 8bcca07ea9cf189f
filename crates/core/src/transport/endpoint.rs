//! The `--port` argument: a serial device, `tcp://HOST[:PORT]`, `tls://HOST[:PORT]`,
//! `rtu+tcp://HOST:PORT`, `udp://HOST[:PORT]`, `rtu+udp://HOST:PORT`, or `sim`.

use std::fmt;

use thiserror::Error;

/// Where the bus is: what `--port` names.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Endpoint {
    /// A serial device by its path (`/dev/ttyUSB0`, `COM3`).
    Serial(String),
    /// Modbus TCP (MBAP framing).
    Tcp {
        /// Host name or IP address.
        host: String,
        /// TCP port.
        port: u16,
    },
    /// Modbus/TCP Security: Modbus TCP inside TLS.
    Tls {
        /// Host name or IP address.
        host: String,
        /// TCP port.
        port: u16,
    },
    /// RTU frames through a transparent serial gateway.
    RtuOverTcp {
        /// Host name or IP address of the gateway.
        host: String,
        /// TCP port of the gateway.
        port: u16,
    },
    /// Modbus over UDP: MBAP frames, one a datagram.
    Udp {
        /// Host name or IP address.
        host: String,
        /// UDP port.
        port: u16,
    },
    /// RTU frames in UDP datagrams, as serial device servers carry them.
    RtuOverUdp {
        /// Host name or IP address of the device server.
        host: String,
        /// UDP port of the device server.
        port: u16,
    },
    /// The built-in simulated slave, in process.
    Sim,
}

impl fmt::Display for Endpoint {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Endpoint::Serial(path) => f.write_str(path),
            Endpoint::Tcp { host, port } => write!(f, "tcp://{}:{port}", Bracketed(host)),
            Endpoint::Tls { host, port } => write!(f, "tls://{}:{port}", Bracketed(host)),
            Endpoint::RtuOverTcp { host, port } => {
                write!(f, "rtu+tcp://{}:{port}", Bracketed(host))
            }
            Endpoint::Udp { host, port } => write!(f, "udp://{}:{port}", Bracketed(host)),
            Endpoint::RtuOverUdp { host, port } => {
                write!(f, "rtu+udp://{}:{port}", Bracketed(host))
            }
            Endpoint::Sim => f.write_str("sim"),
        }
    }
}

/// A host as it stands before `:PORT`: an IPv6 address in brackets.
struct Bracketed<'a>(&'a str);

impl fmt::Display for Bracketed<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0.contains(':') {
            true => write!(f, "[{}]", self.0),
            false => f.write_str(self.0),
        }
    }
}

/// The standard Modbus TCP port.
pub const MODBUS_TCP_PORT: u16 = 502;

/// Where a listener binds when its address leaves out the host: this machine only.
pub const LISTEN_HOST: &str = "127.0.0.1";

/// Why a `--port` text names no endpoint.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum EndpointError {
    /// An IPv6 address without its closing `]`.
    #[error("{scheme}{rest}: an IPv6 address needs its closing ']'")]
    OpenBracket {
        /// The scheme as typed (`tcp://`, `rtu+tcp://`).
        scheme: &'static str,
        /// What followed the scheme.
        rest: String,
    },
    /// No host before the port.
    #[error(
        "{scheme}{rest}: give a host, as in {scheme}127.0.0.1:{}",
        example_port(scheme)
    )]
    NoHost {
        /// The scheme as typed (`tcp://`, `rtu+tcp://`).
        scheme: &'static str,
        /// What followed the scheme.
        rest: String,
    },
    /// A port that is no number 1-65535.
    #[error("{scheme}{rest}: '{port}' is not a port number (1-65535)")]
    BadPort {
        /// The scheme as typed (`tcp://`, `rtu+tcp://`).
        scheme: &'static str,
        /// What followed the scheme.
        rest: String,
        /// The port as typed.
        port: String,
    },
    /// An RTU-over-TCP (or UDP) gateway without a port: gateways have no standard one.
    #[error("{scheme}{rest}: give the gateway's port, as in {scheme}{host}:4001")]
    NoPort {
        /// The scheme as typed (`tcp://`, `rtu+tcp://`).
        scheme: &'static str,
        /// What followed the scheme.
        rest: String,
        /// The host given.
        host: String,
    },
    /// A `scheme://` that mbtool does not know.
    #[error("'{0}': the port is a serial device, tcp://HOST[:PORT], tls://HOST[:PORT], rtu+tcp://HOST:PORT, udp://HOST[:PORT], rtu+udp://HOST:PORT or sim")]
    UnknownScheme(String),
    /// An empty `--port`.
    #[error("--port is empty: give a serial device, tcp://HOST[:PORT] or sim")]
    Empty,
}

/// The port an example of `scheme` shows: its standard one.
fn example_port(scheme: &str) -> u16 {
    match scheme {
        "tls://" => super::tls::MODBUS_TLS_PORT,
        _ => MODBUS_TCP_PORT,
    }
}

fn host_port(
    rest: &str,
    default_port: Option<u16>,
    scheme: &'static str,
    listening: bool,
) -> Result<(String, u16), EndpointError> {
    // [v6]:port, host:port, or host alone.
    let (host, port) = if let Some(v6) = rest.strip_prefix('[') {
        let (host, after) = v6
            .split_once(']')
            .ok_or_else(|| EndpointError::OpenBracket {
                scheme,
                rest: rest.to_string(),
            })?;
        (host, after.strip_prefix(':'))
    } else {
        match rest.rsplit_once(':') {
            Some((host, port)) => (host, Some(port)),
            None => (rest, None),
        }
    };
    let host = match host {
        "" if listening => LISTEN_HOST,
        "" => {
            return Err(EndpointError::NoHost {
                scheme,
                rest: rest.to_string(),
            })
        }
        host => host,
    };
    let port =
        match (port, default_port) {
            (Some(port), _) => port.parse::<u16>().ok().filter(|p| *p > 0).ok_or_else(|| {
                EndpointError::BadPort {
                    scheme,
                    rest: rest.to_string(),
                    port: port.to_string(),
                }
            })?,
            (None, Some(default)) => default,
            (None, None) => {
                return Err(EndpointError::NoPort {
                    scheme,
                    rest: rest.to_string(),
                    host: host.to_string(),
                })
            }
        };
    Ok((host.to_string(), port))
}

impl Endpoint {
    /// A port to connect to.
    pub fn parse(text: &str) -> Result<Endpoint, EndpointError> {
        Self::parse_as(text, false)
    }

    /// A port to listen on: `tcp://:5020` binds 127.0.0.1, so nothing is exposed to
    /// other machines unless an address says so.
    pub fn parse_listen(text: &str) -> Result<Endpoint, EndpointError> {
        Self::parse_as(text, true)
    }

    fn parse_as(text: &str, listening: bool) -> Result<Endpoint, EndpointError> {
        let text = text.trim();
        if text.eq_ignore_ascii_case("sim") {
            return Ok(Endpoint::Sim);
        }
        if let Some(rest) = text.strip_prefix("tcp://") {
            let (host, port) = host_port(rest, Some(MODBUS_TCP_PORT), "tcp://", listening)?;
            return Ok(Endpoint::Tcp { host, port });
        }
        if let Some(rest) = text.strip_prefix("tls://") {
            let (host, port) =
                host_port(rest, Some(super::tls::MODBUS_TLS_PORT), "tls://", listening)?;
            return Ok(Endpoint::Tls { host, port });
        }
        if let Some(rest) = text.strip_prefix("rtu+tcp://") {
            let (host, port) = host_port(rest, None, "rtu+tcp://", listening)?;
            return Ok(Endpoint::RtuOverTcp { host, port });
        }
        if let Some(rest) = text.strip_prefix("udp://") {
            let (host, port) = host_port(rest, Some(MODBUS_TCP_PORT), "udp://", listening)?;
            return Ok(Endpoint::Udp { host, port });
        }
        if let Some(rest) = text.strip_prefix("rtu+udp://") {
            let (host, port) = host_port(rest, None, "rtu+udp://", listening)?;
            return Ok(Endpoint::RtuOverUdp { host, port });
        }
        if text.contains("://") {
            return Err(EndpointError::UnknownScheme(text.to_string()));
        }
        if text.is_empty() {
            return Err(EndpointError::Empty);
        }
        if names_tcp(text) {
            let (host, port) = host_port(text, Some(MODBUS_TCP_PORT), "tcp://", listening)?;
            return Ok(Endpoint::Tcp { host, port });
        }
        Ok(Endpoint::Serial(text.to_string()))
    }
}

/// Whether a port without a scheme means Modbus TCP, as mbpoll users type it: a bare IPv4
/// address (`192.168.1.10`) or `HOST:PORT` (`127.0.0.1:5020`, `plc1:502`, `[::1]:502`). A
/// path (`/dev/ttyUSB0`, `./pty`) or `COMn` is a serial line.
fn names_tcp(text: &str) -> bool {
    if text.starts_with(['/', '.', '\\']) || is_com_port(text) {
        return false;
    }
    if text.parse::<std::net::Ipv4Addr>().is_ok() || text.starts_with('[') {
        return true;
    }
    matches!(
        text.rsplit_once(':'),
        Some((host, port)) if !host.contains(':') && !port.is_empty()
            && port.bytes().all(|b| b.is_ascii_digit())
    )
}

fn is_com_port(text: &str) -> bool {
    text.get(..3)
        .is_some_and(|com| com.eq_ignore_ascii_case("com"))
        && text.len() > 3
        && text.bytes().skip(3).all(|b| b.is_ascii_digit())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_kind_of_port() {
        assert_eq!(Endpoint::parse("sim"), Ok(Endpoint::Sim));
        assert_eq!(
            Endpoint::parse("/dev/ttyUSB0"),
            Ok(Endpoint::Serial("/dev/ttyUSB0".into()))
        );
        assert_eq!(
            Endpoint::parse("tcp://127.0.0.1"),
            Ok(Endpoint::Tcp {
                host: "127.0.0.1".into(),
                port: 502
            })
        );
        assert_eq!(
            Endpoint::parse("tcp://[::1]:5020"),
            Ok(Endpoint::Tcp {
                host: "::1".into(),
                port: 5020
            })
        );
        assert_eq!(
            Endpoint::parse("rtu+tcp://gw:4001"),
            Ok(Endpoint::RtuOverTcp {
                host: "gw".into(),
                port: 4001
            })
        );
        assert!(Endpoint::parse("rtu+tcp://gw").is_err());
        // Without a scheme, as mbpoll users type them.
        let tcp = |host: &str, port| {
            Ok(Endpoint::Tcp {
                host: host.into(),
                port,
            })
        };
        assert_eq!(Endpoint::parse("192.168.1.10"), tcp("192.168.1.10", 502));
        assert_eq!(Endpoint::parse("127.0.0.1:5020"), tcp("127.0.0.1", 5020));
        assert_eq!(Endpoint::parse("plc1:502"), tcp("plc1", 502));
        assert_eq!(Endpoint::parse("[::1]:502"), tcp("::1", 502));
        assert_eq!(Endpoint::parse_listen(":5020"), tcp("127.0.0.1", 5020));
        assert_eq!(Endpoint::parse("COM3"), Ok(Endpoint::Serial("COM3".into())));
        assert_eq!(
            Endpoint::parse("./pty0"),
            Ok(Endpoint::Serial("./pty0".into()))
        );
        assert!(Endpoint::parse("10.0.0.5:0").is_err());
        assert!(Endpoint::parse("tcp://:5020").is_err());
        assert_eq!(
            Endpoint::parse_listen("tcp://:5020"),
            Ok(Endpoint::Tcp {
                host: "127.0.0.1".into(),
                port: 5020
            })
        );
        assert_eq!(
            Endpoint::parse("tls://plc1"),
            Ok(Endpoint::Tls {
                host: "plc1".into(),
                port: 802
            })
        );
        assert_eq!(
            Endpoint::parse_listen("tls://:8802"),
            Ok(Endpoint::Tls {
                host: "127.0.0.1".into(),
                port: 8802
            })
        );
        assert_eq!(
            Endpoint::parse("udp://plc1"),
            Ok(Endpoint::Udp {
                host: "plc1".into(),
                port: 502
            })
        );
        assert_eq!(
            Endpoint::parse_listen("rtu+udp://:4001"),
            Ok(Endpoint::RtuOverUdp {
                host: "127.0.0.1".into(),
                port: 4001
            })
        );
        assert!(Endpoint::parse("rtu+udp://gw").is_err());
        assert!(Endpoint::parse("sctp://x").is_err());
        assert!(Endpoint::parse("tcp://x:99999").is_err());
    }
}
