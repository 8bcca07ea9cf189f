//! `mbtool serve`: a simulated slave on a serial line or TCP.

use std::io::Write;
use std::sync::Arc;

use anyhow::{Context, Result};

use mbtool::connection::{self, Connector, Role};
use mbtool::error::Error;
use mbtool::output::serve::write_entry;
use mbtool::output::Format;
use mbtool::settings::{job, Settings};
use mbtool_core::listener::Link;
use mbtool_core::model::address::parse_reference_span;
use mbtool_core::slave::server::{Logger, Server};
use mbtool_core::slave::{datafile, DataModel, Slave};
use mbtool_core::transport::Endpoint;

fn data_model(job: &job::Serve) -> Result<DataModel> {
    let mut model = match &job.data {
        // A file that cannot be read is an I/O failure; a bad line in it is bad input.
        Some(path) => datafile::load(path).map_err(Error::from)?,
        None => DataModel::manual_examples(),
    };
    for range in &job.read_only {
        let span = parse_reference_span(range)
            .map_err(|e| Error::usage(format!("--read-only {range}: {e}")))?;
        let start = u32::from(span.address);
        let end = start + span.count.unwrap_or(1);
        match span.table {
            mbtool_core::model::address::Table::Coils => model.coils.protect(start, end),
            mbtool_core::model::address::Table::HoldingRegisters => {
                model.holding_registers.protect(start, end);
            }
            other => {
                return Err(Error::usage(format!(
                    "--read-only {range}: {}s are read-only already",
                    other.name()
                ))
                .into())
            }
        }
    }
    Ok(model)
}

pub fn run(settings: &Settings, job: &job::Serve) -> Result<u8> {
    let connector = Connector::new(&settings.connection, Role::Serve)?;
    let (endpoint, mode) = (&connector.endpoint, connector.mode);
    let security = super::shared::security(settings, &job.roles, endpoint)?;
    let plain = security.is_none().then_some(endpoint);
    let plain_role = super::shared::plain_role(&job.roles, plain, security.is_some())?;
    let ids = if job.slaves.is_empty() {
        vec![mbtool_core::slave::EXAMPLE_SLAVE]
    } else {
        job.slaves.clone()
    };
    let mut slave = Slave::new(&ids, data_model(job)?);
    for (id, value) in &job.identity {
        slave.identity.set(*id, value);
    }
    let logger: Option<Logger> = (!job.quiet).then(|| {
        let json = settings.output.format == Format::Json;
        Arc::new(move |entry: &mbtool_core::slave::server::LogEntry| {
            // One write a line, so that lines from several clients never mix.
            let mut line = Vec::with_capacity(160);
            if write_entry(&mut line, json, entry).is_ok() {
                let _ = std::io::stderr().lock().write_all(&line);
            }
        }) as Logger
    });
    // A stand-in device holds nothing to save: Ctrl-C, SIGINT (even in the background of
    // a script, where it is otherwise ignored), SIGTERM and SIGHUP end it at once.
    ctrlc::set_handler(|| std::process::exit(0))
        .map_err(|e| anyhow::anyhow!("cannot catch Ctrl-C: {e}"))?;
    let seed = job.seed.unwrap_or_else(|| fastrand::u64(..));
    let mut server = Server::new(slave, job.faults.clone(), mode, seed, logger);
    if let Some(role) = &plain_role {
        mbtool::note!(
            "mbtool: every client gets role {} (no certificate)",
            role.name
        );
        server = server.with_plain_role(role.as_ref().clone());
    }
    let ids_text = ids.iter().map(u8::to_string).collect::<Vec<_>>().join(", ");
    match endpoint {
        Endpoint::Serial(path) => {
            let line = connector.line();
            let mut transport = connector.open_serial(&line)?;
            mbtool::note!(
                "mbtool: serving slave {ids_text} on {path} ({mode}, {} baud); Ctrl-C ends",
                line.baud
            );
            let mut rng = fastrand::Rng::with_seed(seed);
            let link = Link::Serial {
                character: line.character_time(),
                silence: line.frame_gap(),
            };
            server
                .serve_stream(&mut transport, server.plain_client(path), &link, &mut rng)
                .with_context(|| format!("serving on {path}"))?;
            Ok(0)
        }
        Endpoint::Tcp { host, port }
        | Endpoint::RtuOverTcp { host, port }
        | Endpoint::Tls { host, port } => {
            let listener = connection::listen(endpoint, host, *port)?;
            let address = listener.local_addr()?;
            let over = match security {
                Some(_) => "Modbus TCP over TLS".to_string(),
                None => mode.to_string(),
            };
            let server = match security {
                Some(security) => server.secured(security),
                None => server,
            };
            mbtool::note!("mbtool: serving slave {ids_text} on {address} ({over}); Ctrl-C ends");
            Arc::new(server)
                .serve_tcp(listener, Arc::new(|error| mbtool::note!("mbtool: {error}")))?;
            Ok(0)
        }
        Endpoint::Udp { host, port } | Endpoint::RtuOverUdp { host, port } => {
            let socket = std::net::UdpSocket::bind((host.as_str(), *port))
                .with_context(|| format!("cannot listen on UDP {host}:{port}"))?;
            let address = socket.local_addr()?;
            let over = match endpoint {
                Endpoint::Udp { .. } => "Modbus/UDP".to_string(),
                _ => format!("{mode} over UDP"),
            };
            mbtool::note!("mbtool: serving slave {ids_text} on {address} ({over}); Ctrl-C ends");
            server.serve_udp(&socket)?;
            Ok(0)
        }
        Endpoint::Sim => Ok(0),
    }
}
