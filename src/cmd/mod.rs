//! One module per command: each wires the library's logic to its output.

mod decode;
mod encode;

use anyhow::Result;

use mbtool::cli::{Cli, Command};

/// Runs the command; `Ok` carries the exit status of a command that finished its work.
pub fn run(cli: Cli) -> Result<u8> {
    match &cli.command {
        Command::Decode(args) => decode::run(&cli, args),
        Command::Encode { request } => encode::run(&cli, request),
        Command::Request(request) => {
            // The whole command line is checked before any connection is thought of.
            encode::plan_for(&cli, request)?;
            Err(mbtool::error::Error::usage(format!(
                "{name} needs a connection to a slave, which this build of mbtool cannot open yet; `mbtool encode {name} ...` prints the frame it would send",
                name = request_name(request),
            ))
            .into())
        }
        Command::Generate(args) => {
            mbtool::docs::generate(&args.dir)?;
            Ok(0)
        }
    }
}

fn request_name(request: &mbtool::cli::RequestCommand) -> String {
    format!("{request:?}")
        .split('(')
        .next()
        .unwrap_or_default()
        .chars()
        .enumerate()
        .flat_map(|(i, c)| {
            let lower = c.to_ascii_lowercase();
            if c.is_ascii_uppercase() && i > 0 {
                vec!['-', lower]
            } else {
                vec![lower]
            }
        })
        .collect()
}
