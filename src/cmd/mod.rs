//! One module per command: each wires the library's logic to its output.

mod decode;
mod diag;
mod dump;
mod encode;
mod gateway;
mod info;
mod map;
mod poll;
mod ports;
mod request;
mod restore;
mod scan;
mod serve;
mod shared;
mod sniff;
mod watch;

use anyhow::Result;

use mbtool::cli::Command;
use mbtool::settings::Settings;

/// Runs the command; `Ok` carries the exit status of a command that finished its work.
pub fn run(settings: &Settings, command: Command) -> Result<u8> {
    match &command {
        Command::Scan(args) => scan::run(settings, args),
        Command::Watch(args) => watch::run(settings, &args.read),
        Command::Info(args) => info::run(settings, args),
        Command::Dump(args) => dump::run(settings, args),
        Command::Restore(args) => restore::run(settings, args),
        Command::Diag(args) => diag::run(settings, args),
        Command::Decode(args) => decode::run(settings, args),
        Command::Encode { request, .. } => encode::run(settings, request),
        Command::Request(request) => request::run(settings, request),
        Command::Serve(args) => serve::run(settings, args),
        Command::Gateway(args) => gateway::run(settings, args),
        Command::Sniff(args) => sniff::run(settings, args),
        Command::Ports(args) => ports::run(settings, args),
        Command::Generate(args) => {
            mbtool::docs::generate(&args.dir)?;
            Ok(0)
        }
    }
}
