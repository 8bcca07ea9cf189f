//! Help examples, man pages and shell completions, all from the clap definition, so that
//! none of them can drift from the command line.

use std::fs;
use std::io::{self, Write};
use std::path::Path;

use clap::CommandFactory;
use clap_complete::Shell;

use crate::cli::examples::examples_of;
use crate::cli::Cli;

pub use crate::cli::examples::{examples, Example};

const EXIT_STATUS: &[(&str, &str)] = &[
    ("0", "success"),
    ("1", "any other failure (port cannot be opened, I/O error)"),
    ("2", "bad command line or bad input, including a frame given to decode that is not hex; nothing was sent"),
    ("3", "no response within the timeout, after all retries"),
    ("4", "a bad frame: CRC/LRC mismatch, malformed or unexpected answer; decode: a frame failed its check"),
    ("10+N", "the slave answered with Modbus exception N: 11 illegal function, 12 illegal data address, 13 illegal data value, 14 slave device failure, ... up to 21"),
];

/// The variables of the environment the tool reads: each option's that has one, as the
/// definition names it, and NO_COLOR.
fn environment(command: &clap::Command) -> Vec<(String, String)> {
    let mut variables: Vec<(String, String)> = command
        .get_arguments()
        .filter_map(|arg| {
            let name = arg.get_env()?.to_string_lossy().into_owned();
            let option = arg
                .get_long()
                .map_or_else(|| arg.get_id().to_string(), |l| format!("--{l}"));
            Some((name, format!("the default for {option}")))
        })
        .collect();
    variables.push((
        "NO_COLOR".into(),
        "when set and not empty, no colour is used".into(),
    ));
    variables
}

/// What `mbtool` alone prints (or `mbtool encode` alone, `path`): the usage line, the
/// commands, and where to go next, as `git` does.
pub fn short_usage(command: &clap::Command, path: &str) -> String {
    let commands: Vec<(&str, String)> = command
        .get_subcommands()
        .filter(|sub| !sub.is_hide_set() && sub.get_name() != "help")
        .map(|sub| {
            let about = sub.get_about().map(ToString::to_string).unwrap_or_default();
            (sub.get_name(), about)
        })
        .collect();
    let width = commands
        .iter()
        .map(|(name, _)| name.len())
        .max()
        .unwrap_or(0);
    let mut text = format!("Usage: {path} [OPTIONS] <COMMAND> [ARGS]\n\nCommands:\n");
    for (name, about) in &commands {
        text.push_str(&format!("  {name:width$}  {about}\n"));
    }
    let example = match path {
        "mbtool" => "Try it without hardware: mbtool --port sim read-holding 17 400108 3",
        _ => "Try it: mbtool encode read-holding 17 400108 3",
    };
    text.push_str(&format!(
        "\n{example}\n'{path} --help' lists the options; '{path} <COMMAND> --help' explains a command."
    ));
    text
}

/// Escapes text for roff: hyphens stay hyphens, backslashes stay backslashes, and a line
/// may not start with a control character.
fn roff_text(text: &str) -> String {
    let escaped = text.replace('\\', "\\e").replace('-', "\\-");
    if escaped.starts_with(['.', '\'']) {
        format!("\\&{escaped}")
    } else {
        escaped
    }
}

fn roff_list(out: &mut dyn Write, title: &str, items: &[(&str, &str)]) -> io::Result<()> {
    writeln!(out, ".SH \"{title}\"")?;
    for (term, text) in items {
        writeln!(out, ".TP\n\\fB{}\\fR\n{}", roff_text(term), roff_text(text))?;
    }
    Ok(())
}

/// The SYNOPSIS: every option the command takes with its value placeholder
/// (`[--baud BAUD]`), then its arguments, as `--help`'s usage line gives them.
fn render_synopsis(out: &mut dyn Write, command: &clap::Command) -> io::Result<()> {
    let bold = |text: &str| format!("\\fB{}\\fR", roff_text(text));
    let italic = |text: &str| format!("\\fI{}\\fR", roff_text(text));
    let name = command.get_bin_name().unwrap_or(command.get_name());
    let mut words = vec![bold(name)];
    let visible: Vec<&clap::Arg> = command
        .get_arguments()
        .filter(|arg| !arg.is_hide_set())
        .collect();
    for arg in visible.iter().filter(|arg| !arg.is_positional()) {
        let mut names: Vec<String> = arg
            .get_short()
            .map(|s| bold(&format!("-{s}")))
            .into_iter()
            .collect();
        names.extend(arg.get_long().map(|l| bold(&format!("--{l}"))));
        let takes_value = arg.get_num_args().is_some_and(|n| n.takes_values());
        let value = match arg.get_value_names() {
            Some([value, ..]) if takes_value => format!(" {}", italic(value)),
            _ => String::new(),
        };
        words.push(format!("[{}{value}]", names.join("|")));
    }
    for arg in visible.iter().filter(|arg| arg.is_positional()) {
        let value = arg
            .get_value_names()
            .and_then(|names| names.first())
            .map_or_else(|| arg.get_id().to_string(), ToString::to_string);
        let many = if arg.get_num_args().is_some_and(|n| n.max_values() > 1) {
            "..."
        } else {
            ""
        };
        words.push(if arg.is_required_set() {
            format!("<{}>{many}", italic(&value))
        } else {
            format!("[{}]{many}", italic(&value))
        });
    }
    if command.has_subcommands() {
        words.push(format!("<{}>", italic("COMMAND")));
        words.push(format!("[{}]", italic("ARGS")));
    }
    writeln!(out, ".SH SYNOPSIS\n{}", words.join(" "))
}

fn render_man(
    man: &clap_mangen::Man,
    man_command: &clap::Command,
    name: &str,
    top: bool,
    out: &mut dyn Write,
) -> io::Result<()> {
    man.render_title(out)?;
    man.render_name_section(out)?;
    render_synopsis(out, man_command)?;
    man.render_description_section(out)?;
    man.render_options_section(out)?;
    if top {
        man.render_subcommands_section(out)?;
        let variables = environment(man_command);
        let items: Vec<(&str, &str)> = variables
            .iter()
            .map(|(name, text)| (name.as_str(), text.as_str()))
            .collect();
        roff_list(out, "ENVIRONMENT", &items)?;
    }
    roff_list(out, "EXIT STATUS", EXIT_STATUS)?;
    let examples = examples_of(name);
    if !examples.is_empty() {
        writeln!(out, ".SH EXAMPLES")?;
        for example in examples {
            writeln!(
                out,
                ".PP\n{}:\n.PP\n.RS 4\n.nf\n\\fB{}\\fR\n.fi\n.RE",
                roff_text(example.what),
                roff_text(&format!("$ {}", example.command))
            )?;
        }
    }
    writeln!(out, ".SH \"SEE ALSO\"")?;
    if top {
        writeln!(
            out,
            "mbtool\\-decode(1), mbtool\\-encode(1), mbtool\\-read\\-holding(1)"
        )?;
    } else {
        writeln!(out, "mbtool(1)")?;
    }
    man.render_version_section(out)
}

/// Writes `man/*.1`: one page for mbtool and one per visible subcommand.
pub fn write_man_pages(dir: &Path) -> io::Result<()> {
    fs::create_dir_all(dir)?;
    // `mbtool help COMMAND` is the same as `--help`: no page of its own.
    let mut command = crate::cli::definition();
    command.build();
    let command = command.mut_subcommand("help", |help| help.hide(true));
    let mut page = Vec::new();
    render_man(
        &clap_mangen::Man::new(command.clone()),
        &command,
        "",
        true,
        &mut page,
    )?;
    fs::write(dir.join("mbtool.1"), &page)?;
    for sub in command.get_subcommands().filter(|s| !s.is_hide_set()) {
        let man = clap_mangen::Man::new(sub.clone());
        let mut page = Vec::new();
        render_man(&man, sub, sub.get_name(), false, &mut page)?;
        fs::write(dir.join(man.get_filename()), &page)?;
    }
    Ok(())
}

/// The command as the shells complete it: each command with the options it takes, typed
/// after its name.
fn completion_command() -> clap::Command {
    let mut command = Cli::command();
    command.build();
    command
}

/// Writes `completions/` for bash, zsh, fish, PowerShell and elvish.
pub fn write_completions(dir: &Path) -> io::Result<()> {
    fs::create_dir_all(dir)?;
    for shell in [
        Shell::Bash,
        Shell::Zsh,
        Shell::Fish,
        Shell::PowerShell,
        Shell::Elvish,
    ] {
        clap_complete::generate_to(shell, &mut completion_command(), "mbtool", dir)?;
    }
    Ok(())
}

/// Writes both under `root`: `root/completions` and `root/man`.
pub fn generate(root: &Path) -> io::Result<()> {
    write_completions(&root.join("completions"))?;
    write_man_pages(&root.join("man"))
}
