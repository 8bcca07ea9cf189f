//! `mbtool gateway`: Modbus TCP clients bridged to a line, every transaction shown.

use std::io::{self, Write};
use std::net::{TcpListener, UdpSocket};
use std::sync::{mpsc, Arc, Mutex};

use anyhow::{Context, Result};

use mbtool::connection::{self, Connector, Role};
use mbtool::error::Error;
use mbtool::output::gateway::GatewayWriter;
use mbtool::output::{colour_wanted, Format, Named, PollRows};
use mbtool::settings::{job, Settings};
use mbtool_core::gateway::{Event, Gateway, GatewayOptions, Line, Listening, Report};
use mbtool_core::transport::Endpoint;

use super::poll::{now, open_log, Log};

/// A `--listen` bound: TCP clients connect to it, UDP clients send to it.
enum Bound {
    Tcp(TcpListener),
    Udp(UdpSocket),
}

/// Every `--listen`, bound before anything else is done, with how its clients connect.
fn listeners(settings: &Settings, job: &job::Gateway) -> Result<Vec<(Bound, Listening)>> {
    if job.listen.is_empty() {
        return Err(Error::usage(
            "gateway needs --listen: where clients connect, tcp://0.0.0.0:502 (tcp://:1502 for this machine only)",
        )
        .into());
    }
    let mut endpoints = Vec::new();
    for text in &job.listen {
        let endpoint = Endpoint::parse_listen(text)
            .map_err(|e| Error::usage(format!("--listen {text}: {e}")))?;
        if !matches!(
            endpoint,
            Endpoint::Tcp { .. } | Endpoint::Tls { .. } | Endpoint::Udp { .. }
        ) {
            return Err(Error::usage(format!(
                "--listen {text}: clients come over Modbus TCP or UDP: give tcp://ADDRESS[:PORT], tls://ADDRESS[:PORT] or udp://ADDRESS[:PORT]"
            ))
            .into());
        }
        endpoints.push(endpoint);
    }
    // The roles are for a tls:// listener; one is enough to take them. A tcp:// one
    // beside it gives its clients --plain-role.
    let secure = endpoints
        .iter()
        .find(|endpoint| matches!(endpoint, Endpoint::Tls { .. }));
    let plain = endpoints
        .iter()
        .find(|endpoint| matches!(endpoint, Endpoint::Tcp { .. } | Endpoint::Udp { .. }));
    let security = match secure {
        Some(endpoint) => super::shared::security(settings, &job.roles, endpoint)?.map(Arc::new),
        None => super::shared::security(settings, &job.roles, &endpoints[0])?.map(Arc::new),
    };
    let plain_role = super::shared::plain_role(&job.roles, plain, secure.is_some())?;
    let mut bound = Vec::new();
    for endpoint in endpoints {
        let listening = match (&endpoint, &security) {
            (Endpoint::Tls { .. }, Some(security)) => Listening::Secure(Arc::clone(security)),
            _ => Listening::Plain(plain_role.clone()),
        };
        match &endpoint {
            Endpoint::Tcp { host, port } | Endpoint::Tls { host, port } => {
                let listener = connection::listen(&endpoint, host, *port)?;
                bound.push((Bound::Tcp(listener), listening));
            }
            Endpoint::Udp { host, port } => {
                let socket = UdpSocket::bind((host.as_str(), *port))
                    .with_context(|| format!("cannot listen on UDP {host}:{port}"))?;
                bound.push((Bound::Udp(socket), listening));
            }
            _ => {}
        }
    }
    Ok(bound)
}

/// Where each transaction's row goes: the screen (or the pipe) and the log.
struct Monitor {
    screen: Option<(GatewayWriter, Box<dyn Write + Send>)>,
    log: Option<Log<GatewayWriter>>,
    /// A write failed (the reader of stdout went away, the disk filled): told once, and
    /// the bridging goes on.
    told_failure: bool,
}

impl Monitor {
    fn row(&mut self, transaction: &mbtool_core::gateway::Transaction) {
        let time = now();
        let mut written = Ok(());
        if let Some((writer, out)) = self.screen.as_mut() {
            written = writer
                .row(out, transaction, &time)
                .and_then(|()| out.flush());
        }
        if let Some(log) = self.log.as_mut() {
            let logged = log.rows.row(&mut log.file, transaction, &time);
            written = written.and(logged.and_then(|()| log.file.flush()));
        }
        if let Err(error) = written {
            if !self.told_failure {
                self.told_failure = true;
                mbtool::note!("mbtool: the monitor cannot write ({error}); the gateway goes on");
            }
        }
    }
}

pub fn run(settings: &Settings, job: &job::Gateway) -> Result<u8> {
    let connector = Connector::new(&settings.connection, Role::Gateway)?;
    let mode = connector.mode;
    // A port that cannot switch its RS-485 transceiver would be told as a line down
    // for ever: it is refused before clients are let in.
    if let (Endpoint::Serial(_), false) = (
        &connector.endpoint,
        settings.connection.direction.is_automatic(),
    ) {
        connector.open_serial(&connector.line())?;
    }
    let format = settings.output.format;
    let log = settings
        .poll
        .log
        .as_deref()
        .map(|path| open_log(path, |format| GatewayWriter::new(format, false)))
        .transpose()?;
    // Bound last of what can fail, so that a bad command line leaves no port taken.
    let listeners = listeners(settings, job)?;
    let screen = (!job.quiet).then(|| {
        let out = Named::new(io::stdout(), "standard output");
        let writer = GatewayWriter::new(format, colour_wanted());
        (
            writer,
            Box::new(io::BufWriter::new(out)) as Box<dyn Write + Send>,
        )
    });
    let monitor = Mutex::new(Monitor {
        screen,
        log,
        told_failure: false,
    });
    let report: Report = Arc::new(move |event| match event {
        Event::Transaction(transaction) => {
            let mut monitor = monitor.lock().unwrap_or_else(|p| p.into_inner());
            monitor.row(transaction);
        }
        Event::LineDown(why) => {
            mbtool::note!("mbtool: line down: {why}; clients get exception 0A until it is back");
        }
        Event::LineUp => mbtool::note!("mbtool: line up again"),
        Event::ClientClosed(error) => mbtool::note!("mbtool: {error}"),
    });
    let options = GatewayOptions {
        unit_map: job.unit_map.clone(),
        broadcast_reply: job.broadcast_reply,
    };
    let gateway = Gateway::new(options, Arc::clone(&report));
    // Ctrl-C, SIGINT and SIGTERM end the gateway with its summary.
    let (stop, stopped) = mpsc::channel();
    ctrlc::set_handler(move || {
        let _ = stop.send(());
    })
    .map_err(|e| anyhow::anyhow!("cannot catch Ctrl-C: {e}"))?;
    let (line_connector, verbose) = (connector.clone(), settings.output.verbose);
    let mut line = Line::new(
        Box::new(move || {
            let mut master = line_connector
                .connect()
                .map(|connected| connected.master)
                .map_err(|e| e.to_string())?;
            if verbose {
                master.trace(super::shared::tracer(mode));
            }
            Ok(master)
        }),
        mode,
    );
    let mut addresses = Vec::new();
    for (listener, listening) in &listeners {
        let address = match listener {
            Bound::Tcp(listener) => listener.local_addr()?,
            Bound::Udp(socket) => {
                addresses.push(format!("udp://{} (Modbus/UDP)", socket.local_addr()?));
                continue;
            }
        };
        addresses.push(match listening {
            Listening::Secure(_) => format!("tls://{address} (Modbus/TCP Security)"),
            Listening::Plain(Some(role)) => {
                format!("{address} (no certificate: role {})", role.name)
            }
            Listening::Plain(None) => address.to_string(),
        });
    }
    // Said before the first client is taken, so that it is the first line.
    let (serial_line, _) = connector.tried_on(None);
    mbtool::note!(
        "mbtool: gateway on {} to the line {serial_line}; Ctrl-C ends",
        addresses.join(", ")
    );
    for (listener, listening) in listeners {
        let gateway = Arc::clone(&gateway);
        let on_error = Arc::clone(&report);
        std::thread::Builder::new().spawn(move || {
            let told = Arc::new(move |error: io::Error| on_error(Event::ClientClosed(&error)));
            let accepted = match listener {
                Bound::Tcp(listener) => gateway.accept(listener, listening, told),
                Bound::Udp(socket) => gateway.accept_udp(socket),
            };
            if let Err(error) = accepted {
                mbtool::note!("mbtool: stopped listening: {error}");
            }
        })?;
    }
    line.open(&report);
    let working = Arc::clone(&gateway);
    std::thread::Builder::new().spawn(move || working.run(&mut line))?;
    let _ = stopped.recv();
    let summary = gateway.summary();
    let writer = GatewayWriter::new(format, false);
    let mut text = Vec::new();
    writer.summary(&mut text, &summary)?;
    if format == Format::Json && !job.quiet {
        let mut out = io::stdout().lock();
        let _ = out.write_all(&text).and_then(|()| out.flush());
        let mut table = Vec::new();
        GatewayWriter::new(Format::Table, false).summary(&mut table, &summary)?;
        mbtool::note!("{}", String::from_utf8_lossy(&table).trim_end());
    } else {
        mbtool::note!("{}", String::from_utf8_lossy(&text).trim_end());
    }
    Ok(0)
}
