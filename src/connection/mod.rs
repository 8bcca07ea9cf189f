//! From the connection options to a master talking to a slave.

use std::io;

use crate::error::{Error, Result};
use crate::settings::ConnectionSettings;
use mbtool_core::codec::{ExceptionCode, Mode};
use mbtool_core::master::failover::{open_pair, PairError, PathName, SwitchRule};
use mbtool_core::master::open::{self, PathSettings};
use mbtool_core::master::Master;
use mbtool_core::model::line::DirectionControl;
use mbtool_core::model::line::{LineSettings, Parity};
use mbtool_core::model::map::MapConnection;
use mbtool_core::sniff::replay::TimingFile;
use mbtool_core::sniff::timing;
use mbtool_core::transport::serial::Serial;
use mbtool_core::transport::tls::{ClientTls, TlsSession};
use mbtool_core::transport::Endpoint;

/// The endpoint of `--port`; a missing port says what to give.
pub fn endpoint(options: &ConnectionSettings) -> Result<Endpoint> {
    let port = options.port.as_deref().ok_or_else(|| {
        Error::usage(
            "no --port: give a serial device (/dev/ttyUSB0), tcp://HOST[:PORT], tls://HOST[:PORT], rtu+tcp://HOST:PORT, or sim to try the built-in slave",
        )
    })?;
    let endpoint = Endpoint::parse(port)?;
    tls_fits(options, &endpoint)?;
    Ok(endpoint)
}

/// The certificate options against the port: for tls://, read and checked now, so that a
/// poll or a watch does not start on files that cannot work; typed for another port (and
/// no tls:// second path), refused, since they would do nothing.
pub fn tls_fits(options: &ConnectionSettings, endpoint: &Endpoint) -> Result<()> {
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
    Master,
    Serve,
    Sniff,
    Encode,
}

/// The framing on the wire: TCP for tcp://, otherwise --mode (RTU by default). `endpoint`
/// is `None` where the command has no port to go by.
pub fn mode(options: &ConnectionSettings, endpoint: Option<&Endpoint>, role: Role) -> Result<Mode> {
    let tcp_port = matches!(endpoint, Some(Endpoint::Tcp { .. } | Endpoint::Tls { .. }));
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
            "{} carries Modbus TCP frames: for RTU through a gateway use rtu+tcp://HOST:PORT",
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
        _ => "tcp://",
    }
}

/// The serial line settings, defaults filled in as docs/serial-line.md gives them.
pub fn line_settings(options: &ConnectionSettings, mode: Mode) -> LineSettings {
    line_at(options, mode, options.baud(), options.parity())
}

/// The serial line settings at `baud` and `parity` (a step of a scan's sweep), the data
/// and stop bits as the options give them.
pub fn line_at(
    options: &ConnectionSettings,
    mode: Mode,
    baud: u32,
    parity: Parity,
) -> LineSettings {
    LineSettings {
        baud,
        parity,
        data_bits: options
            .data_bits
            .unwrap_or(if mode == Mode::Ascii { 7 } else { 8 }),
        stop_bits: options
            .stop_bits
            .unwrap_or(if parity == Parity::None { 2 } else { 1 }),
        direction: options.direction,
    }
}

/// `--rs485` or `--rts-toggle` typed for a port that has no RTS to drive. From the
/// environment they are left to the serial commands of the same shell.
pub fn direction_needs_serial(options: &ConnectionSettings, endpoint: &Endpoint) -> Result<()> {
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

/// Opens the serial port at `path` with `line`; a port that cannot switch its RS-485
/// transceiver as asked says what to try instead.
pub fn open_serial(path: &str, line: &LineSettings) -> Result<Serial> {
    Serial::open(path, line).map_err(|e| serial_failure(path, line, e))
}

/// A serial port that did not open, told with what to try: the ports that are here, who
/// holds it, or how else to switch its transceiver.
fn serial_failure(path: &str, line: &LineSettings, e: io::Error) -> Error {
    if e.kind() != io::ErrorKind::Unsupported {
        return Error::Io(with_ports_here(path, e));
    }
    let hint = match line.direction {
        DirectionControl::Kernel(_) => "try --rts-toggle",
        _ => "try --rs485, or an adapter that switches its transceiver itself",
    };
    Error::Io(io::Error::new(e.kind(), format!("{e}: {hint}")))
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
        Endpoint::Serial(device) => serial_failure(device, line, e),
        _ => Error::Io(io::Error::new(
            e.kind(),
            format!("cannot connect to {endpoint}: {e}"),
        )),
    })?;
    if let (true, Some(session)) = (options.tell_session, session) {
        tell_session(&session);
    }
    Ok(opened)
}

/// `-v` on a TLS connection: what was agreed, whom it is with, and the role sent.
fn tell_session(session: &TlsSession) {
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
pub fn tried(
    options: &ConnectionSettings,
    endpoint: &Endpoint,
    mode: Mode,
) -> (String, &'static str) {
    match endpoint {
        Endpoint::Serial(path) => {
            let line = line_settings(options, mode);
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
        Endpoint::RtuOverTcp { .. } => (
            format!("through {endpoint} ({mode})"),
            "check the slave id, and the gateway's serial settings and wiring to the device",
        ),
        Endpoint::Sim => (
            "from the built-in slave (sim)".into(),
            "it answers as slave 17 only",
        ),
        Endpoint::Tcp { .. } | Endpoint::Tls { .. } => (
            format!("from {endpoint}"),
            "check the unit id (a gateway passes it on as the slave id) and that the device \
             behind it answers",
        ),
    }
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
    master_at(
        options,
        endpoint,
        mode,
        &line_settings(options, mode),
        answer,
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

/// A master on `endpoint` with the serial settings `line` and `answer`, the rest as the
/// options resolved them.
pub fn master_at(
    options: &ConnectionSettings,
    endpoint: &Endpoint,
    mode: Mode,
    line: &LineSettings,
    answer: Patience,
) -> Result<Master> {
    opened(options, endpoint, mode, line, answer, open::master)
}

/// The way to the device the options name, built once from them: its endpoint and
/// framing checked (a second path's too) before anything is opened, and everything a
/// command opens on it and tells of it.
#[derive(Clone)]
pub struct Connector<'a> {
    options: &'a ConnectionSettings,
    pub endpoint: Endpoint,
    pub mode: Mode,
}

impl<'a> Connector<'a> {
    /// The connector of `options`: the endpoint of `--port` and its framing.
    pub fn new(options: &'a ConnectionSettings) -> Result<Connector<'a>> {
        let endpoint = endpoint(options)?;
        let mode = mode(options, Some(&endpoint), Role::Master)?;
        secondary_target(options)?;
        Ok(Connector {
            options,
            endpoint,
            mode,
        })
    }

    /// The connector of `options` to `endpoint`, framed in `mode`, as another command's
    /// line (the gateway's) is reached.
    pub fn at(options: &'a ConnectionSettings, endpoint: Endpoint, mode: Mode) -> Connector<'a> {
        Connector {
            options,
            endpoint,
            mode,
        }
    }

    /// Whether slave ids are TCP unit ids here.
    pub fn is_tcp(&self) -> bool {
        self.mode == Mode::Tcp
    }

    /// A master on the device, for a command that ends at a failure: a failed request is
    /// asked again on its path until the rule of a second path decides.
    pub fn connect(&self) -> Result<Connection<'a>> {
        let master = open_master(self.options, &self.endpoint, self.mode, None, true)?;
        Ok(Connection {
            master,
            connector: self.clone(),
        })
    }

    /// A master for a poll, which counts a failure and asks again at its next interval,
    /// starting on the path `first` where there are two (the primary if `None`).
    pub fn master_on(&self, first: Option<PathName>) -> Result<Master> {
        open_master(self.options, &self.endpoint, self.mode, first, false)
    }

    /// Where and how the master on `path` asked, for a failure's message, and what
    /// usually causes one there.
    pub fn tried_on(&self, path: Option<PathName>) -> (String, &'static str) {
        tried_on(self.options, &self.endpoint, self.mode, path)
    }

    /// Why the secondary path cannot be opened now, if it cannot: for a long command to
    /// say at its start that the path it may need is not there (a typo, an unplugged
    /// adapter), rather than when it is needed.
    pub fn secondary_unavailable(&self) -> Option<String> {
        let (secondary, endpoint, mode) = secondary_target(self.options).ok()??;
        single_master(secondary, &endpoint, mode)
            .err()
            .map(|error| error.to_string())
    }
}

/// A master on the device, with what a failure on it should tell.
pub struct Connection<'a> {
    pub master: Master,
    pub connector: Connector<'a>,
}

impl Connection<'_> {
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

/// [`tried`] on the path `path` of the options, where there are two: the secondary's
/// port and line when the master is there.
fn tried_on(
    options: &ConnectionSettings,
    endpoint: &Endpoint,
    mode: Mode,
    path: Option<PathName>,
) -> (String, &'static str) {
    match (path, secondary_target(options)) {
        (Some(PathName::Secondary), Ok(Some((secondary, endpoint, mode)))) => {
            tried(secondary, &endpoint, mode)
        }
        _ => tried(options, endpoint, mode),
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
pub fn processes(holders: &[mbtool_core::transport::ports::Holder]) -> String {
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

/// The connection settings with what a map's file says of its device (a Home Assistant
/// hub's host and port, or serial device and line) where the command line says nothing.
pub fn with_map_connection(
    options: &ConnectionSettings,
    from_map: Option<&MapConnection>,
) -> ConnectionSettings {
    let mut options = options.clone();
    let Some(from_map) = from_map.filter(|_| options.port.is_none()) else {
        return options;
    };
    options.port = Some(from_map.port.clone());
    if options.mode.is_none() {
        options.mode = match from_map.mode.as_deref() {
            Some("ascii") => Some(Mode::Ascii),
            Some("rtu") => Some(Mode::Rtu),
            _ => None,
        };
    }
    if let (false, Some(baud)) = (options.baud_given, from_map.baud) {
        options.bauds = vec![baud];
    }
    let parity = match from_map.parity.map(|p| p.to_ascii_uppercase()) {
        Some('E') => Some(Parity::Even),
        Some('O') => Some(Parity::Odd),
        Some('N') => Some(Parity::None),
        _ => None,
    };
    if let (false, Some(parity)) = (options.parity_given, parity) {
        options.parities = vec![parity];
    }
    options.data_bits = options.data_bits.or(from_map.data_bits);
    options.stop_bits = options.stop_bits.or(from_map.stop_bits);
    options
}

/// The mode and line the bytes were sent on: as the options give them, but for a capture
/// whose `timing` file records the line it was taken on, which a replay takes (so that a
/// silence is what it was live) save where an option is typed (or set in the
/// environment), and then says so.
pub fn sniffed_line(
    options: &ConnectionSettings,
    timing: Option<&TimingFile>,
) -> Result<(Mode, LineSettings)> {
    let Some((timing, recorded)) = timing.and_then(|timing| Some((timing, timing.line()?))) else {
        let mode = mode(options, None, Role::Sniff)?;
        let line = line_settings(options, mode);
        if let Some(timing) = timing.filter(|_| !options.baud_given && !options.parity_given) {
            crate::note!(
                "mbtool: {} does not say which line the capture was taken on: replaying it as \
                 {}; give -b and --parity if it was another",
                timing.path().display(),
                timing::RecordedLine::of(mode, &line)
            );
        }
        return Ok((mode, line));
    };
    let mode = match options.mode {
        Some(_) => mode(options, None, Role::Sniff)?,
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
    let mut line = line_at(options, mode, baud, parity);
    if options.data_bits.is_none() && mode == recorded.mode {
        line.data_bits = recorded.data_bits;
    }
    if options.stop_bits.is_none() && parity == recorded.parity {
        line.stop_bits = recorded.stop_bits;
    }
    let replayed = timing::RecordedLine::of(mode, &line);
    if replayed != recorded {
        crate::note!(
            "mbtool: {} records the line as {recorded}; replaying it as {replayed}, as the \
             options say",
            timing.path().display()
        );
    }
    Ok((mode, line))
}
