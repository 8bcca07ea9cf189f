//! The `mbtool` binary: parses the command line, runs the command, and turns every outcome
//! into one line on stderr and the exit status docs/reading-and-writing.md gives it.

mod cmd;

use std::io;
use std::process::ExitCode;

use clap::error::{ContextKind, ContextValue, ErrorKind};

use mbtool::settings::job::Job;
use mbtool::settings::{self, Settings};

fn main() -> ExitCode {
    let code = match parse() {
        Ok((settings, job)) => match cmd::run(&settings, &job) {
            Ok(code) => code,
            Err(error) => fail(&error),
        },
        Err(code) => code,
    };
    ExitCode::from(code)
}

/// Parses the command line and resolves it into settings and the command to run. Help
/// and version are printed as clap renders them; `mbtool` alone prints a short usage with
/// the commands; every other usage error, including an option the command does not take,
/// becomes one `mbtool: ` line. Both end with exit status 2.
fn parse() -> Result<(Settings, Job), u8> {
    let mut definition = mbtool::cli::definition();
    let (cli, origins) = settings::read(&mut definition, std::env::args_os()).map_err(|error| {
        match error.kind() {
            ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => match error.print() {
                // `mbtool --help | head -3` is the reader's choice.
                Err(e) if e.kind() != io::ErrorKind::BrokenPipe => {
                    mbtool::note!("mbtool: cannot write standard output: {e}");
                    1
                }
                _ => 0,
            },
            ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand | ErrorKind::MissingSubcommand => {
                // `mbtool encode` alone lists the requests it encodes.
                let path = typed_commands(&definition, None);
                let level = path
                    .iter()
                    .skip(1)
                    .try_fold(&definition, |level, name| level.find_subcommand(name))
                    .unwrap_or(&definition);
                mbtool::note!("{}", mbtool::docs::short_usage(level, &path.join(" ")));
                2
            }
            _ => {
                mbtool::note!("mbtool: {}", usage_error(&error, &definition));
                2
            }
        }
    })?;
    match settings::resolve(cli, &origins) {
        Ok(resolved) => Ok(resolved),
        Err(message) => {
            mbtool::note!("mbtool: {message}");
            Err(2)
        }
    }
}

/// A usage error on one line: what is wrong, clap's tips and the values allowed, and where
/// to read more.
fn usage_error(error: &clap::Error, command: &clap::Command) -> String {
    let rendered = error.to_string();
    // The command the error is about: `mbtool encode raw`, as far as the word clap
    // stopped at.
    // A bad value is told of the command whose option it is, as the line names it.
    let stopped_at = match (
        error.get(ContextKind::InvalidSubcommand),
        error.get(ContextKind::InvalidArg),
    ) {
        (Some(ContextValue::String(word)), _) => Some(word.as_str()),
        _ if matches!(
            error.kind(),
            ErrorKind::InvalidValue | ErrorKind::ValueValidation
        ) =>
        {
            None
        }
        // `--port <PORT>`: the option as typed.
        (_, Some(ContextValue::String(arg))) => arg.split_whitespace().next(),
        _ => None,
    };
    let typed = typed_commands(command, stopped_at);
    let path: Vec<&str> = typed.iter().map(String::as_str).collect();
    let subcommand = path
        .get(1..)
        .map(|words| words.join(" "))
        .unwrap_or_default();
    // An option the command does not take is told of the whole command, wherever typed.
    let whole = typed_commands(command, None);
    if let Some(message) = untaken(error, command, &whole[1..].join(" ")) {
        return message;
    }
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

/// An option of another command typed after a command that does not take it, which
/// clap knows only as an argument it did not expect: `decode does not take --baud`. One
/// typed before the command's name is told so by `settings`, in the same words.
fn untaken(error: &clap::Error, command: &clap::Command, subcommand: &str) -> Option<String> {
    if error.kind() != ErrorKind::UnknownArgument || subcommand.is_empty() {
        return None;
    }
    let Some(ContextValue::String(typed)) = error.get(ContextKind::InvalidArg) else {
        return None;
    };
    // mbpoll's -t 4 (a table, not a value type) is told as the habit it is; mbtool's -t
    // with a value type, as an option the command does not take.
    let mbpoll_table = typed == "-t"
        && words()
            .skip_while(|w| w != "-t")
            .nth(1)
            .is_some_and(|value| {
                let table = value.split(':').next().unwrap_or_default();
                ["0", "1", "3", "4"].contains(&table)
            });
    if mbpoll_table || (typed != "-t" && mbpoll_habit(error).is_some()) {
        return None;
    }
    let word = typed.split('=').next().unwrap_or(typed);
    // After `--`, a word that looks like an option is an argument.
    if !words()
        .take_while(|w| w != "--")
        .any(|w| w.starts_with(word))
    {
        return None;
    }
    let option = command.get_arguments().find(|arg| {
        let long = word
            .strip_prefix("--")
            .is_some_and(|long| arg.get_long() == Some(long));
        let short = word.strip_prefix('-').is_some_and(|short| {
            let mut letters = short.chars();
            letters.next() == arg.get_short() && letters.next().is_none()
        });
        long || short
    })?;
    Some(settings::refusal(subcommand, option))
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

/// `mbtool` and the command names on the command line, `["mbtool", "encode", "raw"]`, up
/// to the word `stop` when given. An option's value is passed over, as clap passes it
/// over: `--port scan` names no command.
fn typed_commands(command: &clap::Command, stop: Option<&str>) -> Vec<String> {
    // Every command built: a line refused before the command it names was reached.
    let mut whole = command.clone();
    whole.build();
    let mut path = vec!["mbtool".to_string()];
    let mut level = &whole;
    let mut words = words().skip(1).peekable();
    while let Some(word) = words.next() {
        if let Some(option) = option_named(level, &word) {
            // The option clap stopped at, typed short: `-p` for `--port`.
            let long = option.get_long().map(|long| format!("--{long}"));
            if long.is_some() && long.as_deref() == stop {
                break;
            }
            // `--port sim`, `-p sim`; not `--port=sim` or `-psim`.
            let value_apart = !word.contains('=') && (word.starts_with("--") || word.len() == 2);
            // Unless the word after is the one clap stopped at (`--poll -1`).
            let value_refused = words
                .peek()
                .zip(stop)
                .is_some_and(|(next, stop)| names(next, stop));
            if option.get_action().takes_values() && value_apart && !value_refused {
                words.next();
            }
            continue;
        }
        match level.find_subcommand(&word) {
            // clap's own `help` is no command to point to.
            Some(sub) if sub.get_name() == "help" => break,
            Some(sub) => {
                path.push(sub.get_name().to_string());
                level = sub;
            }
            None if stop.is_some_and(|stop| names(&word, stop)) => break,
            None => {}
        }
    }
    path
}

/// Whether `word` is `typed` (a command or an option) as typed: `--port` or `--port=sim`,
/// `-p` or `-psim`.
fn names(word: &str, typed: &str) -> bool {
    let short = typed.len() == 2 && typed.starts_with('-') && typed != "--";
    match word.strip_prefix(typed) {
        Some(rest) => rest.is_empty() || rest.starts_with('=') || short,
        None => false,
    }
}

/// The option of `command` that `word` (`--port`, `--port=sim`, `-p`, `-psim`) names.
fn option_named<'a>(command: &'a clap::Command, word: &str) -> Option<&'a clap::Arg> {
    let word = word.split('=').next().unwrap_or(word);
    if let Some(long) = word.strip_prefix("--") {
        return command
            .get_arguments()
            .find(|arg| arg.get_long() == Some(long));
    }
    let short = word.strip_prefix('-')?.chars().next()?;
    command
        .get_arguments()
        .find(|arg| arg.get_short() == Some(short))
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
