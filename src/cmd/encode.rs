//! `mbtool encode COMMAND ARGS`: the frames a request command would send.

use anyhow::Result;

use mbtool::cli::RequestCommand;
use mbtool::connection::{self, Role};
use mbtool::error::Error;
use mbtool::output::{self, encode::write_frame};
use mbtool::settings::Settings;
use mbtool_core::codec::{Frame, Mode, Pdu, Request};
use mbtool_core::master::plan::{plan, Plan, PlanOptions};
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
        pdu_addresses: settings.data.pdu_addresses,
        value_type: settings.data.value_type,
        order: settings.data.order,
        max_per_request: settings.data.max_per_request,
        tcp: mode(settings) == Mode::Tcp,
    }
}

/// Checks the command line of a request command and plans its requests.
pub fn plan_for(settings: &Settings, request: &RequestCommand) -> Result<Plan, Error> {
    Ok(plan(&request.operation(), plan_options(settings))?)
}

pub fn run(settings: &Settings, request: &RequestCommand) -> Result<u8> {
    let mode = mode(settings);
    let requests: Vec<(u8, Request)> = match super::request::by_map(settings, request)? {
        Some(by_map) => by_map.requests(settings),
        None => {
            let plan = plan_for(settings, request)?;
            plan.requests.into_iter().map(|r| (plan.slave, r)).collect()
        }
    };
    let mut frames = Vec::with_capacity(requests.len());
    for (i, (slave, request)) in requests.iter().enumerate() {
        let frame = Frame {
            mode,
            slave: *slave,
            transaction: (i as u16).wrapping_add(1),
            pdu: Pdu::Request(request.clone()),
        };
        let bytes = frame.encode().map_err(|e| Error::usage(e.to_string()))?;
        frames.push((*slave, request.function(), bytes));
    }
    let mut out = output::stdout();
    for (slave, function, bytes) in frames {
        write_frame(
            &mut out,
            settings.output.format,
            mode,
            slave,
            function,
            &bytes,
        )?;
    }
    out.flush()?;
    Ok(0)
}
