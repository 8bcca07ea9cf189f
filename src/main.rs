//! The `mbtool` binary: parses the command line, runs the command, and turns every outcome
//! into one line on stderr and the exit status of CLI.md.

mod cmd;

use std::io;
use std::process::ExitCode;

use clap::error::ErrorKind;
use clap::FromArgMatches;

use mbtool::cli::Cli;

fn main() -> ExitCode {
    let cli = match parse() {
        Ok(cli) => cli,
        Err(code) => return code,
    };
    match cmd::run(cli) {
        Ok(code) => ExitCode::from(code),
        Err(error) => fail(&error),
    }
}

/// Parses the command line. Help and version are printed as clap renders them; every
/// usage error becomes one `mbtool: ` line with exit status 2.
fn parse() -> Result<Cli, ExitCode> {
    let matches = mbtool::docs::command().try_get_matches();
    let result = matches.and_then(|m| Cli::from_arg_matches(&m));
    result.map_err(|error| match error.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => {
            let _ = error.print();
            ExitCode::SUCCESS
        }
        _ => {
            eprintln!("mbtool: {}", one_line_usage_error(&error.to_string()));
            ExitCode::from(2)
        }
    })
}

/// clap's message, its tips and a pointer to --help, on one line.
fn one_line_usage_error(rendered: &str) -> String {
    let mut lines = rendered.lines().map(str::trim).filter(|l| !l.is_empty());
    let first = lines.next().unwrap_or("bad command line");
    let mut message = first.strip_prefix("error: ").unwrap_or(first).to_string();
    // What clap says after its first line that helps: tips, and the values allowed.
    for line in lines {
        let help = line
            .strip_prefix("tip: ")
            .or_else(|| line.strip_prefix('[').and_then(|l| l.strip_suffix(']')));
        if let Some(help) = help {
            message.push_str("; ");
            message.push_str(help);
        }
    }
    let usage = rendered
        .lines()
        .find_map(|l| l.trim().strip_prefix("Usage: "))
        .and_then(|u| u.split(" [").next().map(str::to_string));
    match usage {
        Some(command) if command.starts_with("mbtool ") => {
            message.push_str(&format!(
                " (see '{} --help')",
                command
                    .split_whitespace()
                    .take(2)
                    .collect::<Vec<_>>()
                    .join(" ")
            ));
        }
        _ => message.push_str(" (see 'mbtool --help')"),
    }
    message
}

fn fail(error: &anyhow::Error) -> ExitCode {
    // A closed pipe (`mbtool decode < big | head -1`) is the reader's choice, not a failure.
    let broken_pipe = error
        .chain()
        .filter_map(|cause| cause.downcast_ref::<io::Error>())
        .any(|e| e.kind() == io::ErrorKind::BrokenPipe);
    if broken_pipe {
        return ExitCode::SUCCESS;
    }
    let code = error
        .chain()
        .find_map(|cause| cause.downcast_ref::<mbtool::error::Error>())
        .map_or(1, mbtool::error::Error::exit_code);
    let message = error
        .chain()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join(": ")
        .replace('\n', " ");
    eprintln!("mbtool: {message}");
    ExitCode::from(code)
}
