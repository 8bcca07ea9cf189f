//! What the commands that send requests share: the framing and planning of a request from
//! the settings, the `-v` tracer, and what is said of a write done another way; and what
//! the servers (serve, gateway) share: their Modbus/TCP Security.

use std::io::Write;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Arc;
use std::time::Instant;

use anyhow::Result;
use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};

use mbtool::connection::{self, Connection, Connector, Role};
use mbtool::error::Error;
use mbtool::output::device::Outcome;
use mbtool::output::encode::frame_text;
use mbtool::settings::job::{RoleSettings, TypedWords};
use mbtool::settings::Settings;
use mbtool_core::codec::{Mode, Request};
use mbtool_core::listener::roles::Roles;
use mbtool_core::listener::Security;
use mbtool_core::master::device::Asked;
use mbtool_core::master::failover::{PathName, Switch};
use mbtool_core::master::plan::{parse_slave, plan, Plan, PlanOptions};
use mbtool_core::master::{Master, MasterError, Traffic};
use mbtool_core::transport::tls::TlsServer;
use mbtool_core::transport::Endpoint;

/// The framing: --mode, else TCP for a tcp:// port, else RTU. Unlike a connection, encode
/// accepts --mode tcp without a port.
pub fn mode(settings: &Settings) -> Mode {
    let endpoint = settings
        .connection
        .port
        .as_deref()
        .and_then(|port| Endpoint::parse(port).ok());
    connection::mode(&settings.connection, endpoint.as_ref(), Role::Encode).unwrap_or(Mode::Rtu)
}

/// What the options say about addresses, values and request sizes.
pub fn plan_options(settings: &Settings) -> PlanOptions {
    PlanOptions {
        numbering: settings.data.numbering,
        value_type: settings.data.value_type,
        order: settings.data.order,
        max_per_request: settings.data.max_per_request,
        tcp: mode(settings) == Mode::Tcp,
    }
}

/// Checks the command line of a request command and plans its requests.
pub fn plan_for(settings: &Settings, request: &TypedWords) -> Result<Plan, Error> {
    Ok(plan(&request.operation(), plan_options(settings))?)
}

/// `--retries` on a request that may do more when sent twice (a mask write, a user
/// function) is refused unless `--retry-non-idempotent` asks for it: the master would
/// send it only once.
pub fn refuse_unsafe_retries(settings: &Settings, requests: &[Request]) -> Result<(), Error> {
    let connection = &settings.connection;
    // Over UDP, retries not asked for leave such requests sent once.
    if connection.retries == 0 || connection.retry_non_idempotent || !connection.retries_given {
        return Ok(());
    }
    match requests.iter().find(|r| r.may_differ_when_repeated()) {
        Some(request) => Err(Error::usage(format!(
            "--retries {} (or MBTOOL_RETRIES) would send function {:02} ({}) again after a lost answer, and the device may have \
             carried it out already: give --retry-non-idempotent to retry it all the same, or --retries 0",
            connection.retries,
            request.function(),
            mbtool_core::codec::function::name(request.function())
        ))),
        None => Ok(()),
    }
}

/// Says that a bit was written without function 22.
pub fn note_mask_write_emulated(slave: u8, what: &str) {
    mbtool::note!(
        "mbtool: slave {slave} does not do function 22 (mask write register): {what} was set by \
         reading the register (03) and writing it whole (06)"
    );
}

/// `-v`: each frame on stderr with the seconds since the start.
pub fn tracer(mode: Mode) -> mbtool_core::master::Tracer {
    let start = Instant::now();
    Box::new(move |traffic, bytes| {
        let arrow = match traffic {
            Traffic::Sent => '>',
            Traffic::Received => '<',
        };
        let text = match mode {
            // Received bytes may be noise, not ASCII: show them as hex then.
            Mode::Ascii if bytes.is_ascii() => frame_text(mode, bytes).replace(['\r', '\n'], ""),
            _ => frame_text(Mode::Rtu, bytes),
        };
        mbtool::note!("[{:>12.6}] {arrow} {text}", start.elapsed().as_secs_f64());
    })
}

/// A connection to the one slave a device command names: the slave checked before the
/// port is opened, and `-v` showing every frame.
pub fn connect_to(settings: &Settings, slave: &str) -> Result<(Connection, u8)> {
    let connector = Connector::new(&settings.connection, Role::Master)?;
    let slave = parse_slave(slave, false, connector.is_tcp()).map_err(Error::from)?;
    let mut connection = connector.connect()?;
    if connection.master.path() == Some(PathName::Primary) {
        warn_if_secondary_unavailable(&connector);
    }
    if settings.output.verbose {
        connection.master.trace(tracer(connector.mode));
    }
    Ok((connection, slave))
}

/// The port of a path, as given.
pub fn path_name(settings: &Settings, path: PathName) -> &str {
    let connection = match (path, settings.connection.secondary.as_deref()) {
        (PathName::Secondary, Some(secondary)) => secondary,
        _ => &settings.connection,
    };
    connection.port.as_deref().unwrap_or_default()
}

/// `switched to the secondary path (tcp://10.0.0.5): 3 timeouts`.
pub fn switch_text(settings: &Settings, switch: &Switch) -> String {
    format!(
        "switched to the {} path ({}): {}",
        switch.to.name(),
        path_name(settings, switch.to),
        switch.why
    )
}

/// The changes of path the master has made, each a line on stderr.
pub fn tell_switches(settings: &Settings, master: &mut Master) {
    for switch in master.take_switches() {
        mbtool::note!("mbtool: {}", switch_text(settings, &switch));
    }
}

/// A line on stderr for each request that changes the device and was sent more than once
/// (the answers to the earlier tries were lost, so the device may have carried out each),
/// and one for the datagrams that came from elsewhere than the device (over UDP).
pub fn tell_after_requests(master: &mut Master) {
    for resent in master.take_resent() {
        mbtool::note!(
            "mbtool: function {:02} ({}) was sent to slave {} {} before an answer came: the device may have carried it out each time",
            resent.function,
            mbtool_core::codec::function::name(resent.function),
            resent.slave,
            mbtool_core::master::run::times(resent.sent),
        );
    }
    tell_foreign(master.foreign());
}

/// A line on stderr for the datagrams that came from elsewhere than the device, with
/// where the last came from: a device that answers from another address or port.
pub fn tell_foreign(foreign: Option<mbtool_core::transport::Foreign>) {
    if let Some(foreign) = foreign {
        let count = foreign.count;
        mbtool::note!(
            "mbtool: {} from {}, not the device asked ({}), {} passed over; a device that answers from another address or port is not heard",
            mbtool::output::plural(count as usize, "datagram"),
            foreign.last_from,
            foreign.device,
            if count == 1 { "was" } else { "were" },
        );
    }
}

/// A line on stderr when the secondary path cannot be opened now.
pub fn warn_if_secondary_unavailable(connector: &Connector) {
    if let Some(why) = connector.secondary_unavailable() {
        mbtool::note!(
            "mbtool: warning: the secondary path cannot be opened now ({why}); it is tried again when a change is due"
        );
    }
}

/// What Ctrl-C (SIGINT), SIGTERM and SIGHUP set, for a long command to end with what it
/// has: the flag the core watches, and which signal it was.
pub struct Stop {
    /// Set by any of the three.
    pub flag: Arc<AtomicBool>,
    signal: Arc<AtomicUsize>,
}

impl Stop {
    /// The exit status of a command the signal ended, as a shell reports one it killed:
    /// 128 + N (130 for Ctrl-C, 143 for SIGTERM, 129 for SIGHUP).
    pub fn exit_status(&self) -> u8 {
        let signal = match self.signal.load(Ordering::SeqCst) {
            0 => SIGINT.unsigned_abs() as usize,
            n => n,
        };
        128u8.saturating_add(u8::try_from(signal).unwrap_or(u8::MAX))
    }
}

/// Installed in place of the default actions, so that a command started in the background
/// of a script (where SIGINT is ignored) ends on them too.
pub fn stop_on_signal() -> Result<Stop> {
    let stop = Stop {
        flag: Arc::new(AtomicBool::new(false)),
        signal: Arc::new(AtomicUsize::new(0)),
    };
    for signal in [SIGINT, SIGTERM, SIGHUP] {
        // The number first: the flag is what the command watches.
        signal_hook::flag::register_usize(signal, Arc::clone(&stop.signal), signal as usize)
            .and_then(|_| signal_hook::flag::register(signal, Arc::clone(&stop.flag)))
            .map_err(|e| anyhow::anyhow!("cannot catch signal {signal}: {e}"))?;
    }
    Ok(stop)
}

/// Modbus/TCP Security for a server on `endpoint` (serve's port, a gateway's --listen):
/// the certificates read and the roles parsed before anything listens; `None` for a port
/// that is not tls://.
pub fn security(
    settings: &Settings,
    roles: &RoleSettings,
    endpoint: &Endpoint,
) -> Result<Option<Security>, Error> {
    if !matches!(endpoint, Endpoint::Tls { .. }) {
        if settings.connection.tls_typed {
            return Err(connection::tls_options_unused(endpoint));
        }
        return Ok(None);
    }
    let rules = roles_given(roles)?;
    let tls = TlsServer::new(&settings.connection.tls)?;
    if let Some(out_of_date) = &tls.out_of_date {
        mbtool::note!("mbtool: warning: {out_of_date}");
    }
    Ok(Some(Security::new(tls, rules)))
}

fn roles_given(roles: &RoleSettings) -> Result<Roles, Error> {
    Roles::new(&roles.rules, roles.default_role.as_deref()).map_err(|e| Error::usage(e.to_string()))
}

/// The role of the clients of a plain `tcp://` listener where roles are checked
/// (`--plain-role`): they have no certificate to claim one, and a listener that let them
/// past the roles would undo them. `plain` is the first plain listener, if any; `secure`
/// whether a tls:// one listens beside it.
pub fn plain_role(
    roles: &RoleSettings,
    plain: Option<&Endpoint>,
    secure: bool,
) -> Result<Option<Arc<mbtool_core::listener::roles::Role>>, Error> {
    let checked = !roles.rules.is_empty() || roles.default_role.is_some();
    let Some(name) = &roles.plain_role else {
        return match plain {
            Some(plain) if checked && secure => Err(Error::usage(format!(
                "--role is checked over tls:// only, and the clients of {plain} have no certificate: \
                 give --plain-role NAME for the role they get, or listen on tls:// only"
            ))),
            Some(_) if checked => Err(Error::usage(
                "--role and --default-role are for clients known by their certificates: listen on a tls:// port, \
                 or give --plain-role NAME for the role every client gets",
            )),
            _ => Ok(None),
        };
    };
    if plain.is_none() {
        return Err(Error::usage(
            "--plain-role is the role of the clients of a tcp:// listener, and there is none: leave it out",
        ));
    }
    if roles.default_role.is_some() && !secure {
        return Err(Error::usage(
            "--default-role is for tls:// clients whose certificate claims no role: with tcp:// only, --plain-role is the role",
        ));
    }
    let rules = roles_given(roles)?;
    match rules.named(name) {
        Some(role) => Ok(Some(Arc::new(role.clone()))),
        None => Err(Error::usage(format!(
            "--plain-role {name} is none of the roles given with --role: give one of them (--role {name}=read, say)"
        ))),
    }
}

/// One function's outcome; a timeout is kept as "no answer" so that the other function
/// still has its say, any other failure ends the command.
pub fn outcome<T>(asked: Result<Asked<T>, MasterError>) -> Result<Outcome<T>, MasterError> {
    match asked {
        Ok(asked) => Ok(asked.into()),
        Err(error @ MasterError::Timeout { .. }) => Ok(Outcome::NoAnswer(error.to_string())),
        Err(error) => Err(error),
    }
}

/// The file a dump or a map is written into before it is renamed to `path`: hidden, beside it.
fn partial_beside(path: &std::path::Path) -> std::path::PathBuf {
    let name = path.file_name().map_or_else(
        || std::ffi::OsString::from("dump"),
        std::ffi::OsStr::to_os_string,
    );
    let mut partial_name = std::ffi::OsString::from(".");
    partial_name.push(&name);
    partial_name.push(format!(".{}.partial", std::process::id()));
    path.with_file_name(partial_name)
}

/// Whether a dump or a map can be written to `path`: its partial file can be made beside it (a
/// device or a pipe is written as it is).
pub fn can_write(path: &std::path::Path) -> std::io::Result<()> {
    if path.metadata().is_ok_and(|m| !m.is_file()) {
        return Ok(());
    }
    let partial = partial_beside(path);
    std::fs::File::create(&partial)?;
    std::fs::remove_file(&partial)
}

/// Writes the file at `path` whole or not at all: into a file beside it, renamed over it
/// once written and synced, so that an interruption or a full disk never leaves half a
/// file (or an empty one) where a whole one is expected, and an older one there stays as
/// it was.
pub fn write_whole(path: &std::path::Path, bytes: &[u8]) -> std::io::Result<()> {
    // A device or a pipe (/dev/stdout, a fifo) is written as it is, never replaced.
    if path.metadata().is_ok_and(|m| !m.is_file()) {
        return std::fs::write(path, bytes);
    }
    let partial = partial_beside(path);
    let written = (|| {
        let mut file = std::fs::File::create(&partial)?;
        file.write_all(bytes)?;
        file.sync_all()?;
        std::fs::rename(&partial, path)
    })();
    if written.is_err() {
        let _ = std::fs::remove_file(&partial);
    }
    written
}
