//! The `mbtool` binary: parses the command line, runs the command, and turns every outcome
//! into one line on stderr and the exit status the README gives it.

// The C runtime calls `main` below directly, not through the standard library's start: see
// `main`. A test build keeps the test harness's own `main`, and leaves the rest unused.
#![cfg_attr(not(test), no_main)]
#![cfg_attr(test, allow(dead_code, unused_imports))]

mod cmd;

use std::io;
use std::os::raw::{c_char, c_int};

use clap::error::{ContextKind, ContextValue, ErrorKind};

use mbtool::cli::Command;
use mbtool::settings::{self, Settings};

/// The process's entry, called by the C runtime. The standard library's own start would
/// also find the main thread's stack by reading `/proc/self/maps`, to name a stack overflow
/// in its message: a tenth of a millisecond, which a one-shot `read-holding` in a script's
/// loop pays every time (the kernel's guard gap below the stack stops an overflow all the
/// same). What mbtool relies on from that start is done here: SIGPIPE ignored, so that
/// writing to a closed pipe is an error the command ends on quietly; descriptors 0 to 2
/// open, so that no file the command opens (a serial port) takes one of their places; a
/// panic's message and exit status 101; and standard output flushed on exit.
#[cfg(not(test))]
#[allow(unsafe_code)]
#[no_mangle]
extern "C" fn main(_argc: c_int, _argv: *const *const c_char) -> c_int {
    // SAFETY: both run before any other thread exists, and touch only process-wide state
    // the standard library's start would set up the same way.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_IGN);
        open_standard_descriptors();
    }
    let code = std::panic::catch_unwind(run).unwrap_or(101);
    // `exit` flushes standard output, as a return from the standard library's start does.
    std::process::exit(code.into())
}

/// Opens /dev/null in the place of a closed standard descriptor.
///
/// # Safety
/// Must run before other threads open files.
#[cfg(not(test))]
#[allow(unsafe_code)]
unsafe fn open_standard_descriptors() {
    let mut fds = [0, 1, 2].map(|fd| libc::pollfd {
        fd,
        events: 0,
        revents: 0,
    });
    if libc::poll(fds.as_mut_ptr(), 3, 0) < 0 {
        return;
    }
    for fd in fds.iter().filter(|fd| fd.revents & libc::POLLNVAL != 0) {
        // The lowest free descriptor is the one closed.
        if libc::open(c"/dev/null".as_ptr(), libc::O_RDWR) != fd.fd {
            libc::abort();
        }
    }
}

/// Parses, runs the command, and gives the exit status.
fn run() -> u8 {
    let (settings, command) = match parse() {
        Ok(parsed) => parsed,
        Err(code) => return code,
    };
    match cmd::run(&settings, command) {
        Ok(code) => code,
        Err(error) => fail(&error),
    }
}

/// Parses the command line and resolves it into settings and the command to run. Help
/// and version are printed as clap renders them; `mbtool` alone prints a short usage with
/// the commands; every other usage error, including an option the command does not take,
/// becomes one `mbtool: ` line. Both end with exit status 2.
fn parse() -> Result<(Settings, Command), u8> {
    let args: Vec<std::ffi::OsString> = std::env::args_os().collect();
    let (mut command, first_args) = mbtool::docs::parser(&args);
    let mut parsed = settings::read(&mut command, &first_args);
    // Read again, as the whole definition reads it: an error, told with every command
    // known; an option typed over a variable of the environment, whose value the whole
    // definition checks all the same; and help, however the line asks for it (`help`,
    // `-vh`), with every command built and its examples.
    let (mut whole, mut help) = (false, false);
    loop {
        command = match &parsed {
            Err(error) if error.kind() == ErrorKind::DisplayHelp && !help => {
                help = true;
                mbtool::docs::command()
            }
            Err(error) if error.kind() == ErrorKind::DisplayVersion => break,
            Err(_) if !whole && !help => {
                whole = true;
                mbtool::docs::whole_parser(&args)
            }
            Ok((_, origins)) if !whole && typed_over_environment(&command, origins) => {
                whole = true;
                mbtool::docs::whole_parser(&args)
            }
            _ => break,
        };
        parsed = settings::read(&mut command, &args);
    }
    let (cli, origins) = parsed.map_err(|error| match error.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => match error.print() {
            // `mbtool --help | head -3` is the reader's choice.
            Err(e) if e.kind() != io::ErrorKind::BrokenPipe => {
                mbtool::note!("mbtool: cannot write standard output: {e}");
                1
            }
            _ => 0,
        },
        ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand | ErrorKind::MissingSubcommand => {
            mbtool::note!("{}", mbtool::docs::short_usage(&command));
            2
        }
        _ => {
            mbtool::note!("mbtool: {}", usage_error(&error, &command));
            2
        }
    })?;
    let resolved = settings::resolve(&cli, &command, &origins);
    // Freed by the exit: freeing it here is a tenth of a one-shot command's instructions,
    // and a trim of the heap.
    std::mem::forget(command);
    match resolved {
        Ok(settings) => Ok((settings, cli.command)),
        Err(message) => {
            mbtool::note!("mbtool: {message}");
            Err(2)
        }
    }
}

/// Whether an option typed on the command line has a variable of the environment set too.
fn typed_over_environment(command: &clap::Command, origins: &settings::Origins) -> bool {
    let Some(leaf) = origins.command_in(command) else {
        return true;
    };
    leaf.get_arguments()
        .filter(|arg| origins.typed_ids().any(|id| arg.get_id() == id))
        .any(|arg| {
            arg.get_env()
                .is_some_and(|name| std::env::var_os(name).is_some())
        })
}

/// A usage error on one line: what is wrong, clap's tips and the values allowed, and where
/// to read more.
fn usage_error(error: &clap::Error, command: &clap::Command) -> String {
    let rendered = error.to_string();
    // The command the error is about, as its usage line names it (`mbtool encode raw`),
    // or, where clap shows no usage (a bad value), as the command line names it.
    let typed = typed_commands(command);
    let path: Vec<&str> = rendered
        .lines()
        .find_map(|l| l.trim().strip_prefix("Usage: "))
        .map(|usage| {
            usage
                .split_whitespace()
                .take_while(|word| !word.starts_with(['[', '<', '-']))
                .collect()
        })
        .unwrap_or_else(|| typed.iter().map(String::as_str).collect());
    let subcommand = path
        .get(1..)
        .map(|words| words.join(" "))
        .unwrap_or_default();
    let mut message = match error.kind() {
        ErrorKind::MissingRequiredArgument => missing(error, &subcommand),
        ErrorKind::InvalidSubcommand => unknown_command(error, command, &path),
        ErrorKind::InvalidUtf8 => {
            not_utf8().unwrap_or_else(|| first_line(&rendered, error, command))
        }
        _ => mbpoll_habit(error).unwrap_or_else(|| first_line(&rendered, error, command)),
    };
    let see = if path.len() > 1 {
        path.join(" ")
    } else {
        "mbtool".into()
    };
    message.push_str(&format!(" (see '{see} --help')"));
    message
}

/// An option of mbpoll or modpoll typed out of habit (`-a 17 -r 1 -c 2`, or `-t 4`, which
/// mbtool's --type takes for a value type), answered with mbtool's spelling.
fn mbpoll_habit(error: &clap::Error) -> Option<String> {
    let args: Vec<String> = words().collect();
    let Some(ContextValue::String(arg)) = error.get(ContextKind::InvalidArg) else {
        return None;
    };
    match error.kind() {
        ErrorKind::UnknownArgument => mbtool::habits::mbpoll_habit(arg, &args),
        ErrorKind::InvalidValue if arg.starts_with("--type") => {
            let Some(ContextValue::String(value)) = error.get(ContextKind::InvalidValue) else {
                return None;
            };
            let table = value.split(':').next().unwrap_or_default();
            ["0", "1", "3", "4"]
                .contains(&table)
                .then(|| mbtool::habits::mbpoll_habit("-t", &args))
                .flatten()
        }
        _ => None,
    }
}

/// Which word of the command line, or which MBTOOL_ variable, is not UTF-8 text.
fn not_utf8() -> Option<String> {
    if let Some((number, word)) = std::env::args_os()
        .enumerate()
        .skip(1)
        .find(|(_, word)| word.to_str().is_none())
    {
        return Some(format!(
            "argument {number} ('{}') is not UTF-8 text: give it in UTF-8",
            word.to_string_lossy()
        ));
    }
    std::env::vars_os()
        .find(|(name, value)| {
            name.to_str()
                .is_some_and(|name| name.starts_with("MBTOOL_"))
                && value.to_str().is_none()
        })
        .map(|(name, _)| {
            format!(
                "the environment variable {} is not UTF-8 text: set it in UTF-8, or unset it",
                name.to_string_lossy()
            )
        })
}

/// The words of the command line, to tell an error by. A word that is not UTF-8 (which clap
/// refuses) is read with U+FFFD in place of its bad bytes, not taken for a panic.
fn words() -> impl Iterator<Item = String> {
    std::env::args_os().map(|word| word.to_string_lossy().into_owned())
}

/// `mbtool` and the command names on the command line: `["mbtool", "encode", "raw"]`.
fn typed_commands(command: &clap::Command) -> Vec<String> {
    let mut path = vec!["mbtool".to_string()];
    let mut level = command;
    for word in words().skip(1) {
        if let Some(sub) = level.find_subcommand(&word) {
            path.push(sub.get_name().to_string());
            level = sub;
        }
    }
    path
}

/// `read-holding needs ADDRESS`.
fn missing(error: &clap::Error, subcommand: &str) -> String {
    let names: Vec<String> = match error.get(ContextKind::InvalidArg) {
        Some(ContextValue::Strings(args)) => args
            .iter()
            .map(|arg| {
                arg.trim_end_matches("...")
                    .trim_matches(['<', '>'])
                    .to_string()
            })
            .collect(),
        _ => Vec::new(),
    };
    let who = if subcommand.is_empty() {
        "mbtool"
    } else {
        subcommand
    };
    match names.split_last() {
        Some((last, [])) if who == "dump" && last == "RANGE" => {
            "dump needs RANGE, the addresses to save: 400001-400100 (or several, 400001-400100 000001-000032)".into()
        }
        Some((last, [])) => format!("{who} needs {last}"),
        Some((last, rest)) => format!("{who} needs {} and {last}", rest.join(", ")),
        None => format!("{who} needs more arguments"),
    }
}

/// An unknown command, and the one nearest to it, by name only: aliases and hidden
/// commands are not offered.
fn unknown_command(error: &clap::Error, command: &clap::Command, path: &[&str]) -> String {
    let Some(ContextValue::String(typed)) = error.get(ContextKind::InvalidSubcommand) else {
        return "unknown command".into();
    };
    // The commands offered where the unknown one stood: under `encode`, its request commands.
    let parent = path
        .iter()
        .skip(1)
        .try_fold(command, |parent, name| parent.find_subcommand(name));
    let nearest = parent.and_then(|parent| {
        let names = parent
            .get_subcommands()
            .filter(|sub| !sub.is_hide_set() && sub.get_name() != "help")
            .map(clap::Command::get_name);
        mbtool::nearest(typed, names)
    });
    match nearest {
        Some(name) => format!("unknown command '{typed}': did you mean '{name}'?"),
        None => format!("unknown command '{typed}'"),
    }
}

/// clap's first line, its tips and the values allowed; a bad value that came from the
/// environment names its variable, not the option.
fn first_line(rendered: &str, error: &clap::Error, command: &clap::Command) -> String {
    let mut lines = rendered.lines().map(str::trim).filter(|l| !l.is_empty());
    let first = lines.next().unwrap_or("bad command line");
    let mut message = first.strip_prefix("error: ").unwrap_or(first).to_string();
    if let Some((variable, option)) = from_environment(error, command) {
        let flag = option.split_whitespace().next().unwrap_or(&option);
        message = message.replace(
            &format!("for '{option}'"),
            &format!("in {variable} (which sets {flag})"),
        );
    }
    for line in lines {
        let help = line
            .strip_prefix("tip: ")
            .or_else(|| line.strip_prefix('[').and_then(|l| l.strip_suffix(']')));
        if let Some(help) = help {
            message.push_str("; ");
            message.push_str(help);
        }
    }
    message
}

/// The environment variable a bad value came from, with the option as clap named it
/// (`--baud <BAUD>`): the option has one, it is set, and the command line does not give
/// the option itself.
fn from_environment(error: &clap::Error, command: &clap::Command) -> Option<(String, String)> {
    let Some(ContextValue::String(option)) = error.get(ContextKind::InvalidArg) else {
        return None;
    };
    let long = option.split_whitespace().next()?.strip_prefix("--")?;
    let arg = command
        .get_arguments()
        .find(|arg| arg.get_long() == Some(long))?;
    let variable = arg.get_env()?.to_string_lossy().into_owned();
    let set = std::env::var_os(&variable)?;
    let flag = format!("--{long}");
    let given = words().any(|word| word == flag || word.starts_with(&format!("{flag}=")))
        || arg
            .get_short()
            .is_some_and(|short| words().any(|word| word.starts_with(&format!("-{short}"))));
    // Typed over a bad variable, which is refused all the same: the value tells which.
    let variable_says_it = match error.get(ContextKind::InvalidValue) {
        Some(ContextValue::String(value)) => {
            *set.to_string_lossy() == **value
                && !words().any(|word| word == *value || word.ends_with(&format!("={value}")))
        }
        _ => false,
    };
    (!given || variable_says_it).then(|| (variable, option.clone()))
}

fn fail(error: &anyhow::Error) -> u8 {
    // A closed pipe (`mbtool decode < big | head -1`) is the reader's choice, not a failure.
    let broken_pipe = error
        .chain()
        .filter_map(|cause| cause.downcast_ref::<io::Error>())
        .any(|e| e.kind() == io::ErrorKind::BrokenPipe);
    if broken_pipe {
        return 0;
    }
    let ours = error
        .chain()
        .find_map(|cause| cause.downcast_ref::<mbtool::error::Error>());
    // The faults of a file, each on a line of its own.
    if let Some(mbtool::error::Error::Faults(faults)) = ours {
        for fault in faults {
            mbtool::note!("mbtool: {fault}");
        }
        return 2;
    }
    let code = ours.map_or(1, mbtool::error::Error::exit_code);
    let message = error
        .chain()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join(": ")
        .replace('\n', " ");
    mbtool::note!("mbtool: {message}");
    code
}
