//! Help examples, man pages and shell completions, all from the clap definition, so that
//! none of them can drift from the command line.

use std::fs;
use std::io::{self, Write};
use std::path::Path;

use clap::CommandFactory;
use clap_complete::Shell;

use crate::cli::{takes_option, Cli};

/// One example: what it does and the command line.
pub struct Example {
    pub what: &'static str,
    pub command: &'static str,
}

const fn ex(what: &'static str, command: &'static str) -> Example {
    Example { what, command }
}

/// Examples by subcommand; `""` is the top-level page.
const EXAMPLES: &[(&str, &[Example])] = &[
    (
        "",
        &[
            ex(
                "Decode a frame copied from a log",
                "mbtool decode 11 03 00 6B 00 03 76 87",
            ),
            ex(
                "Build the request that reads holding registers 400108-400110 of slave 17",
                "mbtool encode read-holding 17 400108 3",
            ),
            ex(
                "The same request as a Modbus ASCII frame",
                "mbtool encode --mode ascii read-holding 17 400108 3",
            ),
        ],
    ),
    (
        "read-coils",
        &[ex(
            "Read coils 000020-000056 of slave 17",
            "mbtool --port /dev/ttyUSB0 read-coils 17 000020 37",
        )],
    ),
    (
        "read-inputs",
        &[ex(
            "Read discrete inputs 100197-100218 of slave 17",
            "mbtool --port /dev/ttyUSB0 read-inputs 17 100197-100218",
        )],
    ),
    (
        "read-holding",
        &[
            ex(
                "Read holding registers 400108-400110 of slave 17",
                "mbtool --port /dev/ttyUSB0 read-holding 17 400108 3",
            ),
            ex(
                "Read two 32-bit floats stored low word first",
                "mbtool --port tcp://10.0.0.5 read-holding 1 400001 2 --type f32 --order CDAB",
            ),
        ],
    ),
    (
        "read-input-registers",
        &[ex(
            "Read input register 300009 of slave 17",
            "mbtool --port /dev/ttyUSB0 read-input-registers 17 300009",
        )],
    ),
    (
        "read",
        &[ex(
            "Read by reference: the 4 picks the holding registers",
            "mbtool --port /dev/ttyUSB0 read 17 400108 3",
        )],
    ),
    (
        "write-coil",
        &[ex(
            "Switch coil 000173 of slave 17 on",
            "mbtool --port /dev/ttyUSB0 write-coil 17 000173 on",
        )],
    ),
    (
        "write-coils",
        &[ex(
            "Write five coils from 000020 as a bit string",
            "mbtool --port /dev/ttyUSB0 write-coils 17 000020 10110",
        )],
    ),
    (
        "write-register",
        &[ex(
            "Write 3 to holding register 400002 of slave 17",
            "mbtool --port /dev/ttyUSB0 write-register 17 400002 3",
        )],
    ),
    (
        "write-registers",
        &[ex(
            "Write 0x000A and 0x0102 to 400002-400003",
            "mbtool --port /dev/ttyUSB0 write-registers 17 400002 0x000A 0x0102",
        )],
    ),
    (
        "write",
        &[
            ex(
                "Write a 32-bit float to 400001-400002",
                "mbtool --port /dev/ttyUSB0 write 17 400001 3.14 --type f32",
            ),
            ex(
                "Write two registers one at a time (function 06)",
                "mbtool --port /dev/ttyUSB0 write 17 400001 1 2 --function 6",
            ),
        ],
    ),
    (
        "raw",
        &[ex(
            "Send function 17 (report slave id) to slave 17",
            "mbtool --port /dev/ttyUSB0 raw 17 11",
        )],
    ),
    (
        "scan",
        &[
            ex(
                "Find the slaves on a line at 19200 baud, even parity",
                "mbtool --port /dev/ttyUSB0 scan",
            ),
            ex(
                "Find a device whose settings are forgotten: sweep baud rates and parities",
                "mbtool --port /dev/ttyUSB0 scan --baud 9600,19200,38400 --parity none,even,odd --ids 1-20",
            ),
            ex(
                "On a bus with a master on it: listen first, send only if nothing is heard",
                "mbtool --port /dev/ttyUSB0 scan --listen 2s",
            ),
            ex(
                "The unit ids behind a TCP gateway, as JSON Lines",
                "mbtool --port tcp://10.0.0.5 scan --ids 1-32 --json",
            ),
        ],
    ),
    (
        "dump",
        &[
            ex(
                "Save the settings of slave 17: holding registers and coils",
                "mbtool --port /dev/ttyUSB0 dump 17 400001-400200 000001-000064 -o pump3.txt",
            ),
            ex(
                "Stand in for the dumped device, holes included",
                "mbtool serve --port tcp://:5020 --data pump3.txt",
            ),
        ],
    ),
    (
        "restore",
        &[
            ex(
                "Clone the settings onto a replacement device, and check them",
                "mbtool --port /dev/ttyUSB0 restore 17 pump3.txt",
            ),
            ex(
                "Only show the frames it would send",
                "mbtool restore 17 pump3.txt --dry-run",
            ),
        ],
    ),
    (
        "watch",
        &[
            ex(
                "Watch the points of a map, twice a second",
                "mbtool --port /dev/ttyUSB0 watch 17 --map pump3.csv --poll 500ms",
            ),
            ex(
                "Watch two floats stored low word first",
                "mbtool --port tcp://10.0.0.5 watch 1 400001 2 --type f32 --order CDAB",
            ),
            ex(
                "Through a gateway, the device's own serial line standing by for when the gateway fails",
                "mbtool --port tcp://10.0.0.5 watch 17 400108 3 --secondary-port /dev/ttyUSB0 --switch-on timeout:3,exception:0B,disconnect",
            ),
        ],
    ),
    (
        "info",
        &[
            ex("Ask slave 17 who it is", "mbtool --port /dev/ttyUSB0 info 17"),
            ex(
                "The same over Modbus TCP, as JSON",
                "mbtool --port tcp://10.0.0.5 info 17 --json",
            ),
        ],
    ),
    (
        "diag",
        &[
            ex(
                "Round trips, counters and exception status of slave 17",
                "mbtool --port /dev/ttyUSB0 diag 17",
            ),
            ex(
                "Time 50 round trips, then clear the counters",
                "mbtool --port /dev/ttyUSB0 diag 17 --count 50 --clear",
            ),
        ],
    ),
    (
        "sniff",
        &[
            ex(
                "Watch an RS-485 line at 9600 baud, no parity, and keep every byte",
                "mbtool sniff --port /dev/ttyUSB0 -b 9600 --parity none --save bus.bin",
            ),
            ex(
                "Replay a capture as JSON Lines, slave 17 only",
                "mbtool sniff --input bus.bin --json --slave 17",
            ),
            ex(
                "Write the frames for Wireshark too",
                "mbtool sniff --port /dev/ttyUSB0 --pcap bus.pcap",
            ),
        ],
    ),
    (
        "serve",
        &[
            ex(
                "Stand in for slave 17 on a serial line",
                "mbtool serve --port /dev/ttyUSB0 --slave 17",
            ),
            ex(
                "Serve Modbus TCP on 127.0.0.1:5020 with the values of a data file",
                "mbtool serve --port tcp://:5020 --data plant.txt",
            ),
            ex(
                "Test a master's error handling: late answers, 5% dropped, exception 02 on 400100-400120",
                "mbtool serve --port tcp://:5020 --delay 200ms --drop 5% --exception 2@400100-400120",
            ),
        ],
    ),
    (
        "gateway",
        &[
            ex(
                "Let Modbus TCP clients reach the RTU devices on a USB adapter, every transaction shown",
                "mbtool gateway --listen tcp://0.0.0.0:502 --port /dev/ttyUSB0 -b 19200",
            ),
            ex(
                "Run as a service: no rows, the transactions logged to a file, retries on a noisy line",
                "mbtool gateway --listen tcp://0.0.0.0:502 --port /dev/ttyUSB0 --retries 2 --quiet --log gateway.jsonl",
            ),
            ex(
                "Watch what a SCADA asks of a Modbus TCP device: point the SCADA at port 1502",
                "mbtool gateway --listen tcp://0.0.0.0:1502 --port tcp://192.168.1.10 -o json",
            ),
            ex(
                "On an industrial PC whose RS-485 transceiver the host switches: the kernel's RS-485 mode",
                "mbtool gateway --listen tcp://0.0.0.0:502 --port /dev/ttyS1 --rs485 --rs485-delay-after 1",
            ),
        ],
    ),
    (
        "ports",
        &[
            ex("Which port is which adapter", "mbtool ports"),
            ex(
                "Each port as a JSON line, for a script to pick an adapter by serial number",
                "mbtool ports --json",
            ),
        ],
    ),
    (
        "decode",
        &[
            ex(
                "Decode an RTU response",
                "mbtool decode 11 03 06 02 2B 00 00 00 64 C8 BA",
            ),
            ex("Decode an ASCII frame", "mbtool decode :1103006B00037E"),
            ex(
                "Decode a log, one frame per line, as JSON Lines",
                "mbtool decode --json < frames.txt",
            ),
        ],
    ),
    (
        "encode",
        &[
            ex(
                "The RTU request for 400108-400110 of slave 17",
                "mbtool encode read-holding 17 400108 3",
            ),
            ex(
                "The same as Modbus TCP",
                "mbtool encode --mode tcp read-holding 17 400108 3",
            ),
            ex(
                "Write coil 000173 on, as ASCII",
                "mbtool encode --mode ascii write-coil 17 000173 on",
            ),
        ],
    ),
];

const EXIT_STATUS: &[(&str, &str)] = &[
    ("0", "success"),
    ("1", "any other failure (port cannot be opened, I/O error)"),
    ("2", "bad command line or bad input, including a frame given to decode that is not hex; nothing was sent"),
    ("3", "no response within the timeout, after all retries"),
    ("4", "a bad frame: CRC/LRC mismatch, malformed or unexpected answer; decode: a frame failed its check"),
    ("10+N", "the slave answered with Modbus exception N: 11 illegal function, 12 illegal data address, 13 illegal data value, 14 slave device failure, ... up to 21"),
];

const ENVIRONMENT: &[(&str, &str)] = &[
    ("MBTOOL_PORT", "the default for --port"),
    ("MBTOOL_MODE", "the default for --mode"),
    ("MBTOOL_BAUD", "the default for --baud"),
    ("MBTOOL_PARITY", "the default for --parity"),
    ("MBTOOL_DATA_BITS", "the default for --data-bits"),
    ("MBTOOL_STOP_BITS", "the default for --stop-bits"),
    ("MBTOOL_TIMEOUT", "the default for --timeout"),
    ("MBTOOL_RETRIES", "the default for --retries"),
    ("NO_COLOR", "when set and not empty, no colour is used"),
];

/// Every example of every help page.
pub fn examples() -> impl Iterator<Item = &'static Example> {
    EXAMPLES.iter().flat_map(|(_, examples)| examples.iter())
}

fn examples_of(name: &str) -> &'static [Example] {
    EXAMPLES
        .iter()
        .find(|(command, _)| *command == name)
        .map_or(&[], |(_, examples)| *examples)
}

fn examples_help(examples: &[Example]) -> String {
    let mut text = String::from("Examples:\n");
    for example in examples {
        text.push_str(&format!("  {}:\n    $ {}\n", example.what, example.command));
    }
    text
}

/// The clap command, built: examples attached to each `--help`, and each command's help
/// showing only the global options it takes.
pub fn command() -> clap::Command {
    let mut command = crate::cli::with_long_abouts(Cli::command())
        .after_long_help(examples_help(examples_of("")));
    for (name, examples) in EXAMPLES.iter().filter(|(name, _)| !name.is_empty()) {
        let help = examples_help(examples);
        command = command.mut_subcommand(*name, |sub| sub.after_long_help(help));
    }
    // Building copies the global options into every subcommand; only then can each copy
    // be hidden where it does not apply.
    command.build();
    hide_untaken_options(crate::cli::with_argument_help(command))
}

/// The definition `args` are parsed with first, and the words to give it: only the
/// command it names, or the top alone when it names none (`mbtool --version`). Every
/// command's arguments are derived only when it is built (clap's `defer`), and before a
/// parse clap copies every global option into every command, and after it copies each
/// option's value between the levels of the matches: all of it costs a one-shot command
/// more than its own work. So the command named is given the common options itself, not
/// as globals, and those typed before its name are moved after it
/// ([`options_after_command`]); where they cannot be, the options stay global on the top.
/// A command line this refuses is parsed again with [`whole_parser`], so the parse and its
/// errors are the same either way, and a call for help with [`command`], which shows it.
pub fn parser(args: &[std::ffi::OsString]) -> (clap::Command, Vec<std::ffi::OsString>) {
    // The commands as derived: names, aliases and help, their arguments deferred.
    let commands = <crate::cli::Command as clap::Subcommand>::augment_subcommands(
        clap::Command::new("mbtool"),
    );
    let named =
        named_command(&commands, args).and_then(|name| commands.find_subcommand(&name).cloned());
    // No command: the version, or a line the whole definition tells what is wrong with.
    let Some(named) = named else {
        return (top_of_parse(), args.to_vec());
    };
    let mut with_options = <crate::cli::Common as clap::Args>::augment_args(named.clone());
    // Global options at the command parsed are still copied between levels of the
    // matches, every one of them each time: they need be global only to reach the commands
    // under.
    if !crate::cli::COMMANDS_OF_COMMANDS.contains(&with_options.get_name()) {
        with_options = with_options.mut_args(|arg| arg.global(false));
    }
    match options_after_command(&with_options, args) {
        Some(moved) => (top_of_parse().subcommand(with_options), moved),
        None => (
            <crate::cli::Common as clap::Args>::augment_args(top_of_parse()).subcommand(named),
            args.to_vec(),
        ),
    }
}

/// `args` with the common options typed before the command moved after its name, so that
/// clap finds them where the command defines them and has nothing to copy between levels;
/// `None` where a word before the command is anything but a plainly spelt common option
/// and its value, or an option typed before is typed after it too (clap keeps the later
/// one; typed twice in one place, it refuses them or adds them up).
fn options_after_command(
    named: &clap::Command,
    args: &[std::ffi::OsString],
) -> Option<Vec<std::ffi::OsString>> {
    let words: Vec<&str> = args.iter().map(|arg| arg.to_str()).collect::<Option<_>>()?;
    let takes_value = |arg: &clap::Arg| arg.get_action().takes_values();
    let mut moved: Vec<&clap::Arg> = Vec::new();
    let mut at = 1;
    while let Some(word) = words.get(at) {
        let option = if let Some(long) = word.strip_prefix("--") {
            let (name, value) = long
                .split_once('=')
                .map_or((long, false), |(name, _)| (name, true));
            let arg = named.get_arguments().find(|arg| has_long(arg, name))?;
            (arg, if takes_value(arg) && !value { 2 } else { 1 })
        } else if let Some(short) = word.strip_prefix('-') {
            let mut chars = short.chars();
            let letter = chars.next()?;
            let arg = named
                .get_arguments()
                .find(|arg| arg.get_short() == Some(letter))?;
            match (takes_value(arg), chars.as_str().is_empty()) {
                (true, true) => (arg, 2),
                (true, false) => (arg, 1),
                (false, true) => (arg, 1),
                // A cluster of flags (-vp).
                (false, false) => return None,
            }
        } else {
            break;
        };
        let (arg, length) = option;
        if length == 2 && words.get(at + 1).is_none_or(|value| value.starts_with('-')) {
            return None;
        }
        moved.push(arg);
        at += length;
    }
    let command = words.get(at)?;
    let mut names = std::iter::once(named.get_name()).chain(named.get_all_aliases());
    if !names.any(|name| name == *command) {
        return None;
    }
    let typed_again = words[at + 1..].iter().any(|word| {
        moved.iter().any(|arg| {
            let long = word
                .strip_prefix("--")
                .and_then(|rest| rest.split('=').next())
                .is_some_and(|name| has_long(arg, name));
            let mut shorts = arg
                .get_short()
                .into_iter()
                .chain(arg.get_all_short_aliases().into_iter().flatten());
            let short = !word.starts_with("--")
                && word.starts_with('-')
                && shorts.any(|short| word.contains(short));
            long || short
        })
    });
    if typed_again {
        return None;
    }
    let mut moved_args = Vec::with_capacity(args.len());
    moved_args.push(args[0].clone());
    moved_args.push(args[at].clone());
    moved_args.extend_from_slice(&args[1..at]);
    moved_args.extend_from_slice(&args[at + 1..]);
    Some(moved_args)
}

/// Whether `--name` spells `arg`, by its name or an alias.
fn has_long(arg: &clap::Arg, name: &str) -> bool {
    arg.get_long() == Some(name)
        || arg
            .get_all_aliases()
            .into_iter()
            .flatten()
            .any(|alias| alias == name)
}

/// The top of the command line as [`Cli`] derives it, less its commands and options: the
/// settings a parse goes by (a test holds them equal).
pub fn top_of_parse() -> clap::Command {
    clap::Command::new("mbtool")
        .version(env!("CARGO_PKG_VERSION"))
        .propagate_version(true)
        .subcommand_required(true)
        .arg_required_else_help(true)
        .max_term_width(crate::cli::HELP_WIDTH)
}

/// Every command, built, the one `args` seem to name given its argument help: for a
/// command line [`parser`] refused, since the word taken for the command may be an
/// option's value (`-o info dump ...`), and an error is told with every command known.
pub fn whole_parser(args: &[std::ffi::OsString]) -> clap::Command {
    let mut command = Cli::command();
    // Arguments are there to describe only once the deferred commands are built.
    command.build();
    match named_command(&command, args) {
        Some(name) => crate::cli::with_argument_help_of(command, &name),
        None => command,
    }
}

/// The first word of `args` that is the name or alias of a command.
fn named_command(command: &clap::Command, args: &[std::ffi::OsString]) -> Option<String> {
    args.iter().skip(1).find_map(|arg| {
        let word = arg.to_str()?;
        command
            .get_subcommands()
            .find(|sub| sub.get_name() == word || sub.get_all_aliases().any(|a| a == word))
            .map(|sub| sub.get_name().to_string())
    })
}

fn hide_untaken_options(command: clap::Command) -> clap::Command {
    each_command(command, &[], &|sub, path| {
        sub.mut_args(|arg| {
            let untaken = arg.is_global_set() && !takes_option(path, arg.get_id().as_str());
            if untaken {
                arg.hide(true)
            } else {
                arg
            }
        })
    })
}

/// `change` applied to every subcommand, at any depth, with its path (`["encode", "raw"]`).
fn each_command(
    command: clap::Command,
    parent: &[String],
    change: &dyn Fn(clap::Command, &[&str]) -> clap::Command,
) -> clap::Command {
    command.mut_subcommands(|sub| {
        let path: Vec<String> = parent
            .iter()
            .cloned()
            .chain([sub.get_name().to_string()])
            .collect();
        let words: Vec<&str> = path.iter().map(String::as_str).collect();
        each_command(change(sub, &words), &path, change)
    })
}

/// What `mbtool` alone prints: the usage line, the commands, and where to go next, as
/// `git` does.
pub fn short_usage(command: &clap::Command) -> String {
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
    let mut text = String::from("Usage: mbtool [OPTIONS] <COMMAND> [ARGS]\n\nCommands:\n");
    for (name, about) in &commands {
        text.push_str(&format!("  {name:width$}  {about}\n"));
    }
    text.push_str(
        "\nTry it without hardware: mbtool --port sim read-holding 17 400108 3\n\
         'mbtool --help' lists the options; 'mbtool <COMMAND> --help' explains a command.",
    );
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
        roff_list(out, "ENVIRONMENT", ENVIRONMENT)?;
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
    let command = command().mut_subcommand("help", |help| help.hide(true));
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

/// The command as the shells complete it. The completion generators offer hidden options
/// too, so here each command is given only the global options it takes, instead of all of
/// them with the others hidden.
fn completion_command() -> clap::Command {
    let top = Cli::command();
    let globals: Vec<clap::Arg> = top
        .get_arguments()
        .filter(|arg| arg.is_global_set())
        .map(|arg| arg.clone().global(false))
        .collect();
    let top = top.mut_args(|arg| arg.global(false));
    let mut command = each_command(top, &[], &|sub, path| {
        let taken = globals
            .iter()
            .filter(|arg| takes_option(path, arg.get_id().as_str()));
        sub.args(taken.cloned())
    });
    command.build();
    crate::cli::with_argument_help(command)
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
