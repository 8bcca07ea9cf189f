//! One module per command: each wires the library's logic to its output.

mod decode;
mod diag;
mod dump;
mod encode;
mod info;
mod map;
mod poll;
mod request;
mod restore;
mod scan;
mod serve;
mod sniff;
mod watch;

use anyhow::Result;

use mbtool::cli::{Cli, Command};
use mbtool::connection::{self, Connection};
use mbtool::error::Error;
use mbtool_core::master::plan::parse_slave;

/// Runs the command; `Ok` carries the exit status of a command that finished its work.
pub fn run(cli: Cli) -> Result<u8> {
    match &cli.command {
        Command::Scan(args) => scan::run(&cli, args),
        Command::Watch(args) => watch::run(&cli, args),
        Command::Info(args) => info::run(&cli, args),
        Command::Dump(args) => dump::run(&cli, args),
        Command::Restore(args) => restore::run(&cli, args),
        Command::Diag(args) => diag::run(&cli, args),
        Command::Decode(args) => decode::run(&cli, args),
        Command::Encode { request } => encode::run(&cli, request),
        Command::Request(request) => request::run(&cli, request),
        Command::Serve(args) => serve::run(&cli, args),
        Command::Sniff(args) => sniff::run(&cli, args),
        Command::Generate(args) => {
            mbtool::docs::generate(&args.dir)?;
            Ok(0)
        }
    }
}

/// A connection to the one slave a device command names: the slave checked before the
/// port is opened, and `-v` showing every frame.
fn connect_to(cli: &Cli, slave: &str) -> Result<(Connection, u8)> {
    let target = connection::target(cli)?;
    let slave = parse_slave(slave, false, target.is_tcp()).map_err(Error::from)?;
    let mut connection = target.connect(cli)?;
    if cli.output.verbose {
        connection.master.trace(request::tracer(connection.mode));
    }
    Ok((connection, slave))
}
