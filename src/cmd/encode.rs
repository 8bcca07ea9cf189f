//! `mbtool encode COMMAND ARGS`: the frames a request command would send.

use anyhow::Result;

use mbtool::cli::{Cli, RequestCommand};
use mbtool::connection::{self, Role};
use mbtool::error::Error;
use mbtool::output::{self, encode::write_frame};
use mbtool_core::codec::{Frame, Mode, Pdu};
use mbtool_core::master::plan::{plan, Plan, PlanOptions};
use mbtool_core::transport::Endpoint;

/// The framing: --mode, else TCP for a tcp:// port, else RTU. Unlike a connection, encode
/// accepts --mode tcp without a port.
pub fn mode(cli: &Cli) -> Mode {
    let endpoint = cli
        .connection
        .port
        .as_deref()
        .and_then(|port| Endpoint::parse(port).ok());
    connection::mode(cli, endpoint.as_ref(), Role::Encode).unwrap_or(Mode::Rtu)
}

/// Checks the command line of a request command and plans its requests.
pub fn plan_for(cli: &Cli, request: &RequestCommand) -> Result<Plan, Error> {
    let options = PlanOptions {
        pdu_addresses: cli.data.pdu_addresses,
        value_type: cli.data.value_type,
        order: cli.data.order,
        max_per_request: cli.data.max_per_request,
        tcp: mode(cli) == Mode::Tcp,
    };
    Ok(plan(&request.operation(), options)?)
}

pub fn run(cli: &Cli, request: &RequestCommand) -> Result<u8> {
    let mode = mode(cli);
    let plan = plan_for(cli, request)?;
    let mut frames = Vec::with_capacity(plan.requests.len());
    for (i, request) in plan.requests.iter().enumerate() {
        let frame = Frame {
            mode,
            slave: plan.slave,
            transaction: (i as u16).wrapping_add(1),
            pdu: Pdu::Request(request.clone()),
        };
        let bytes = frame.encode().map_err(|e| Error::usage(e.to_string()))?;
        frames.push((request.function(), bytes));
    }
    let mut out = output::stdout();
    for (function, bytes) in frames {
        write_frame(
            &mut out,
            cli.output.format(),
            mode,
            plan.slave,
            function,
            &bytes,
        )?;
    }
    out.flush()?;
    Ok(0)
}
