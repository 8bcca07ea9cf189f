//! From the connection settings to what a command opens on `--port`: the [`Connector`],
//! built once from the settings, checks the port and its framing for the command's
//! [`Role`] and opens masters, serial lines and listeners on it; `told` says what went
//! wrong, with what to try.

mod told;

use std::io;

use crate::error::{Error, Result};
use crate::settings::ConnectionSettings;
use mbtool_core::codec::{ExceptionCode, Mode};
use mbtool_core::master::failover::{open_pair, PairError, PathName, SwitchRule};
use mbtool_core::master::open::{self, PathSettings};
use mbtool_core::master::Master;
use mbtool_core::model::line::{LineSettings, Parity};
use mbtool_core::transport::serial::Serial;
use mbtool_core::transport::tls::{ClientTls, TlsSession};
use mbtool_core::transport::Endpoint;

pub use told::listen;

/// The way to the device the settings name, for a command in its role: its endpoint and
/// framing checked (a second path's too) before anything is opened, and everything a
/// command opens on it and tells of it.
#[derive(Clone, Debug)]
pub struct Connector {
    options: ConnectionSettings,
    pub endpoint: Endpoint,
    pub mode: Mode,
}

impl Connector {
    /// The connector of `options` for a command in `role`: the endpoint of `--port`, which
    /// the role must be able to use, and its framing.
    pub fn new(options: &ConnectionSettings, role: Role) -> Result<Connector> {
        let endpoint = endpoint(options, role)?;
        if role == Role::Master {
            tls_fits(options, &endpoint)?;
        }
        let mode = mode(options, Some(&endpoint), role)?;
        match role {
            Role::Master => {
                secondary_target(options)?;
            }
            Role::Serve | Role::Gateway => direction_needs_serial(options, &endpoint)?,
            Role::Sniff | Role::Encode => {}
        }
        Ok(Connector {
            options: options.clone(),
            endpoint,
            mode,
        })
    }

    /// Whether slave ids are TCP unit ids here.
    pub fn is_tcp(&self) -> bool {
        self.mode == Mode::Tcp
    }

    /// The serial line settings, defaults filled in as docs/serial-line.md gives them.
    pub fn line(&self) -> LineSettings {
        self.options.line(self.mode)
    }

    /// The serial line settings at `baud` and `parity` (a step of a scan's sweep).
    pub fn line_at(&self, baud: u32, parity: Parity) -> LineSettings {
        self.options.line_at(self.mode, baud, parity)
    }

    /// The serial port of `--port`, opened with `line`; a port that cannot switch its
    /// RS-485 transceiver as asked says what to try instead.
    pub fn open_serial(&self, line: &LineSettings) -> Result<Serial> {
        let Endpoint::Serial(path) = &self.endpoint else {
            return Err(Error::usage(format!(
                "{} is no serial device: give one (/dev/ttyUSB0)",
                self.endpoint
            )));
        };
        Serial::open(path, line).map_err(|e| told::serial_failure(path, line, e))
    }

    /// A master on the device, for a command that ends at a failure: a failed request is
    /// asked again on its path until the rule of a second path decides.
    pub fn connect(&self) -> Result<Connection> {
        let master = open_master(&self.options, &self.endpoint, self.mode, None, true)?;
        Ok(Connection {
            master,
            connector: self.clone(),
        })
    }

    /// A master for a poll, which counts a failure and asks again at its next interval,
    /// starting on the path `first` where there are two (the primary if `None`).
    pub fn master_on(&self, first: Option<PathName>) -> Result<Master> {
        open_master(&self.options, &self.endpoint, self.mode, first, false)
    }

    /// A master on the primary path with the serial settings `line` and the patience
    /// `answer` (a step of a scan, which sets its own).
    pub fn master_with(&self, line: &LineSettings, answer: Patience) -> Result<Master> {
        opened(
            &self.options,
            &self.endpoint,
            self.mode,
            line,
            answer,
            open::master,
        )
    }

    /// Where and how the master on `path` asked, for a failure's message, and what
    /// usually causes one there.
    pub fn tried_on(&self, path: Option<PathName>) -> (String, &'static str) {
        match (path, secondary_target(&self.options)) {
            (Some(PathName::Secondary), Ok(Some((secondary, endpoint, mode)))) => {
                told::tried(secondary, &endpoint, mode)
            }
            _ => told::tried(&self.options, &self.endpoint, self.mode),
        }
    }

    /// Why the secondary path cannot be opened now, if it cannot: for a long command to
    /// say at its start that the path it may need is not there (a typo, an unplugged
    /// adapter), rather than when it is needed.
    pub fn secondary_unavailable(&self) -> Option<String> {
        let (secondary, endpoint, mode) = secondary_target(&self.options).ok()??;
        single_master(secondary, &endpoint, mode)
            .err()
            .map(|error| error.to_string())
    }
}

/// A master on the device, with what a failure on it should tell.
pub struct Connection {
    pub master: Master,
    pub connector: Connector,
}

impl Connection {
    /// `error`, a timeout told with where and how the master asked and what usually
    /// causes one there. Exception 01 over TLS is told as what it may be: the server's
    /// role check.
    pub fn explain(&self, error: Error) -> Error {
        if let (
            Error::Exception {
                code: ExceptionCode::ILLEGAL_FUNCTION,
                ..
            },
            Endpoint::Tls { .. },
        ) = (&error, &self.connector.endpoint)
        {
            return Error::MaybeRole(Box::new(error));
        }
        let (tried, advice) = self.connector.tried_on(self.master.path());
        error.tried(tried, advice)
    }
}

/// The endpoint of `--port`, which `role` must be able to use; a missing port says what
/// to give.
fn endpoint(options: &ConnectionSettings, role: Role) -> Result<Endpoint> {
    let needed = match role {
        Role::Serve => "serve needs --port: a serial device, or tcp://127.0.0.1:5020 to listen on TCP",
        Role::Gateway => "gateway needs --port: the serial line (/dev/ttyUSB0), rtu+tcp://HOST:PORT or tcp://HOST:PORT",
        Role::Sniff => "sniff needs --port DEVICE, or --input FILE to replay a capture",
        Role::Master | Role::Encode => "no --port: give a serial device (/dev/ttyUSB0), tcp://HOST[:PORT], tls://HOST[:PORT], rtu+tcp://HOST:PORT, or sim to try the built-in slave",
    };
    let port = options
        .port
        .as_deref()
        .ok_or_else(|| Error::usage(needed))?;
    let endpoint = match role {
        Role::Serve => Endpoint::parse_listen(port)?,
        _ => Endpoint::parse(port)?,
    };
    match (role, &endpoint) {
        (Role::Serve, Endpoint::Sim) => Err(Error::usage(
            "--port sim is the built-in slave for the master commands; serve needs a serial device or tcp://ADDRESS:PORT",
        )),
        // --cert, --key and --ca are the listener's: a line that is itself behind TLS
        // would need a second set.
        (Role::Gateway, Endpoint::Tls { .. }) => Err(Error::usage(
            "gateway --port: the line is a serial device, rtu+tcp:// or tcp://; tls:// is for --listen",
        )),
        (Role::Sniff, Endpoint::Serial(_)) => Ok(endpoint),
        (Role::Sniff, _) => Err(Error::usage(
            "sniff listens on a serial device; for a file give --input",
        )),
        _ => Ok(endpoint),
    }
}

/// The certificate options against the port: for tls://, read and checked now, so that a
/// poll or a watch does not start on files that cannot work; typed for another port (and
/// no tls:// second path), refused, since they would do nothing.
fn tls_fits(options: &ConnectionSettings, endpoint: &Endpoint) -> Result<()> {
    let secondary_tls = options
        .secondary
        .as_deref()
        .and_then(|secondary| secondary.port.as_deref())
        .is_some_and(|port| matches!(Endpoint::parse(port), Ok(Endpoint::Tls { .. })));
    if secondary_tls || matches!(endpoint, Endpoint::Tls { .. }) {
        ClientTls::new(&options.tls)?;
    } else if options.tls_typed {
        return Err(tls_options_unused(endpoint));
    }
    Ok(())
}

/// The certificate options typed for a port that is not tls://.
pub fn tls_options_unused(endpoint: &Endpoint) -> Error {
    Error::usage(format!(
        "--cert, --key, --ca and --tls-server-name are for tls:// ports: {endpoint} is not one"
    ))
}

/// What a command does with `--port`. The framing rules are the same for every command;
/// the role changes only what a mistake is told, and `encode`, which sends nothing, takes
/// any `--mode`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// A master: the commands that ask a device.
    Master,
    /// `serve`: a slave on a serial line or a TCP listener.
    Serve,
    /// `gateway`'s line: a master to a serial line or a server.
    Gateway,
    /// `sniff`: a serial line listened to.
    Sniff,
    /// `encode`: frames printed, nothing opened.
    Encode,
}

/// The framing on the wire: TCP for tcp://, otherwise --mode (RTU by default). `endpoint`
/// is `None` where the command has no port to go by (`encode`, a capture replayed).
pub fn mode(options: &ConnectionSettings, endpoint: Option<&Endpoint>, role: Role) -> Result<Mode> {
    let tcp_port = matches!(
        endpoint,
        Some(Endpoint::Tcp { .. } | Endpoint::Tls { .. } | Endpoint::Udp { .. })
    );
    match (tcp_port, options.mode, role) {
        (_, Some(mode), Role::Encode) => Ok(mode),
        (_, Some(Mode::Tcp), Role::Sniff) => Err(Error::usage(
            "sniff watches serial lines: --mode rtu or ascii",
        )),
        (true, None | Some(Mode::Tcp), _) => Ok(Mode::Tcp),
        (true, Some(_), Role::Serve) => Err(Error::usage(format!(
            "{} serves Modbus TCP: for RTU frames over TCP use rtu+tcp://",
            scheme(endpoint)
        ))),
        (true, Some(_), _) => Err(Error::usage(format!(
            "{} carries Modbus TCP frames: for RTU through a gateway use rtu+tcp://HOST:PORT or rtu+udp://HOST:PORT",
            scheme(endpoint)
        ))),
        (false, Some(Mode::Tcp), Role::Serve) => {
            Err(Error::usage("--mode tcp needs a tcp:// port"))
        }
        (false, Some(Mode::Tcp), _) => {
            Err(Error::usage("--mode tcp needs a tcp://HOST[:PORT] port"))
        }
        (false, Some(mode), _) => Ok(mode),
        (false, None, _) => Ok(Mode::Rtu),
    }
}

/// `tls://` or `tcp://`, as the port names it, for messages about its framing.
fn scheme(endpoint: Option<&Endpoint>) -> &'static str {
    match endpoint {
        Some(Endpoint::Tls { .. }) => "tls://",
        Some(Endpoint::Udp { .. }) => "udp://",
        _ => "tcp://",
    }
}

/// `--rs485` or `--rts-toggle` typed for a port that has no RTS to drive. From the
/// environment they are left to the serial commands of the same shell.
fn direction_needs_serial(options: &ConnectionSettings, endpoint: &Endpoint) -> Result<()> {
    // With two paths, the options are for the one that is a serial line.
    let secondary_serial = options
        .secondary
        .as_deref()
        .and_then(|secondary| secondary.port.as_deref())
        .is_some_and(|port| matches!(Endpoint::parse(port), Ok(Endpoint::Serial(_))));
    match endpoint {
        Endpoint::Serial(_) => Ok(()),
        _ if !options.direction_typed || secondary_serial => Ok(()),
        Endpoint::Sim => Err(Error::usage(
            "--rs485 and --rts-toggle drive the RTS line of a serial port: sim has none",
        )),
        _ => Err(Error::usage(format!(
            "--rs485 and --rts-toggle drive the RTS line of a serial port: {endpoint} has none (a gateway switches its own transceiver)"
        ))),
    }
}

/// What `open` (the core's transport or master) gives on the path of the options to
/// `endpoint`: its RS-485 and TLS options checked first (the certificates read before
/// anything is sent), a failure told with what to try, the TLS session told with `-v`.
fn opened<T>(
    options: &ConnectionSettings,
    endpoint: &Endpoint,
    mode: Mode,
    line: &LineSettings,
    patience: Patience,
    open: impl FnOnce(&PathSettings) -> io::Result<(T, Option<TlsSession>)>,
) -> Result<T> {
    direction_needs_serial(options, endpoint)?;
    let tls = match endpoint {
        Endpoint::Tls { .. } => Some(ClientTls::new(&options.tls)?),
        _ => None,
    };
    let path = PathSettings {
        endpoint,
        mode,
        line: *line,
        timeout: patience.timeout,
        retries: patience.retries,
        retry_non_idempotent: options.retry_non_idempotent,
        frame_gap: options.frame_gap,
        tls: tls.as_ref(),
    };
    let (opened, session) = open(&path).map_err(|e| match endpoint {
        Endpoint::Serial(device) => told::serial_failure(device, line, e),
        _ => Error::Io(io::Error::new(
            e.kind(),
            format!("cannot connect to {endpoint}: {e}"),
        )),
    })?;
    if let (true, Some(session)) = (options.tell_session, session) {
        told::tell_session(&session);
    }
    Ok(opened)
}

fn open_master(
    options: &ConnectionSettings,
    endpoint: &Endpoint,
    mode: Mode,
    first: Option<PathName>,
    persistent: bool,
) -> Result<Master> {
    match secondary_target(options)? {
        None => single_master(options, endpoint, mode),
        Some((secondary, secondary_endpoint, secondary_mode)) => {
            let paths = [
                (options.clone(), endpoint.clone(), mode),
                (secondary.clone(), secondary_endpoint, secondary_mode),
            ];
            let first = first.unwrap_or(PathName::Primary);
            let master = redundant_master(paths, options.switch.clone(), first)?;
            Ok(master.persistent(persistent))
        }
    }
}

/// A master on one path.
fn single_master(options: &ConnectionSettings, endpoint: &Endpoint, mode: Mode) -> Result<Master> {
    let answer = Patience {
        timeout: options.timeout,
        retries: options.retries,
    };
    opened(
        options,
        endpoint,
        mode,
        &options.line(mode),
        answer,
        open::master,
    )
}

/// The secondary path's settings and where they point, checked as `--port` is.
fn secondary_target(
    options: &ConnectionSettings,
) -> Result<Option<(&ConnectionSettings, Endpoint, Mode)>> {
    let Some(secondary) = options.secondary.as_deref() else {
        return Ok(None);
    };
    let port = secondary.port.as_deref().unwrap_or_default();
    let endpoint =
        Endpoint::parse(port).map_err(|e| Error::usage(format!("--secondary-port {port}: {e}")))?;
    let mode = mode(secondary, Some(&endpoint), Role::Master)
        .map_err(|e| Error::usage(format!("--secondary-port {port}: {e}")))?;
    Ok(Some((secondary, endpoint, mode)))
}

/// A master on the path `first` of the two `paths`, or on the other where it cannot be
/// opened, changing between them as `rule` says. A port that cannot switch its RS-485
/// transceiver as asked is a setting to correct, told as without a second path, not a
/// path that is down.
fn redundant_master(
    paths: [(ConnectionSettings, Endpoint, Mode); 2],
    rule: SwitchRule,
    first: PathName,
) -> Result<Master> {
    let open_path = move |path: PathName| {
        let (options, endpoint, mode) = match path {
            PathName::Primary => &paths[0],
            PathName::Secondary => &paths[1],
        };
        single_master(options, endpoint, *mode)
    };
    let setting =
        |error: &Error| matches!(error, Error::Io(e) if e.kind() == io::ErrorKind::Unsupported);
    open_pair(open_path, setting, rule, first).map_err(|error| match error {
        PairError::Setting(error) => error,
        PairError::Neither(failed, other) => Error::Io(io::Error::other(format!(
            "neither path opens: {failed}; {other}"
        ))),
    })
}

/// How long a master waits for an answer, and how often it asks again.
#[derive(Clone, Copy, Debug)]
pub struct Patience {
    pub timeout: std::time::Duration,
    pub retries: u32,
}
