//! The command line, as clap derives it. `--help`, the man pages and the shell completions
//! are all generated from this one definition.

use clap::{Args, Parser, Subcommand};

mod device;
mod gateway;
mod options;
mod requests;
mod serve;
mod traffic;
mod values;

pub use device::*;
pub use gateway::*;
pub use options::*;
pub use requests::*;
pub use serve::*;
pub use traffic::*;

const ABOUT: &str = "Modbus RTU/ASCII/TCP diagnostics: read, write, decode, encode";

const LONG_ABOUT: &str = "\
Modbus RTU/ASCII/TCP diagnostics: read and write a device's coils and registers, decode \
frames pasted from a log or a datasheet, and build frames by hand.

Addresses: a number of exactly 5 or 6 digits whose first digit is the command's table \
(0 coils, 1 discrete inputs, 3 input registers, 4 holding registers) is a 1-based Modicon \
reference: 400108 and 40108 are both holding register address 107. Any other number is the \
0-based protocol address: 107, 0x6B; with --address-base 1 (or MBTOOL_ADDRESS_BASE=1) it \
is the 1-based register number, as manuals and mbpoll count: 108, and the address column \
of what is shown counts from 1 too. --pdu-addresses turns references off: every number is \
then a plain number. \
A range such as 400108-400110 may stand for ADDRESS and COUNT.

Numbers may be decimal, 0x hex or 0b binary.";

/// The widest help is wrapped at, however wide the terminal.
pub const HELP_WIDTH: usize = 100;

/// The help's place of the first of the options every command shares, after any command's
/// own (numbered from 0).
const COMMON_OPTIONS_FIRST_ORDER: usize = 1000;

/// The top of the command line: `mbtool [OPTIONS] <COMMAND> [ARGS]`.
#[derive(Clone, Debug, Parser)]
#[command(
    name = "mbtool",
    version,
    about = ABOUT,
    long_about = LONG_ABOUT,
    propagate_version = true,
    max_term_width = HELP_WIDTH,
    // The options of every command come after a command's own in its help: a command's
    // own arguments are added late (see `docs::parser`), after the common ones are copied
    // in, and number from 0.
    next_display_order = COMMON_OPTIONS_FIRST_ORDER
)]
pub struct Cli {
    #[command(flatten)]
    pub common: Common,
    #[command(subcommand)]
    pub command: Command,
}

impl Cli {
    /// The command line as clap's `matches` hold it, taken out of them. The common options
    /// are read from the command's own matches: clap copies them there from wherever they
    /// were typed, and where the command defines them itself (`docs::parser`) they are
    /// nowhere else.
    pub fn take_from(matches: &mut clap::ArgMatches) -> Result<Cli, clap::Error> {
        let mut leaf = &*matches;
        while let Some((_, sub)) = leaf.subcommand() {
            leaf = sub;
        }
        let common = <Common as clap::FromArgMatches>::from_arg_matches(leaf)?;
        let command = <Command as clap::FromArgMatches>::from_arg_matches_mut(matches)?;
        Ok(Cli { common, command })
    }
}

// The options every command shares (each takes those `takes_option` says), given before
// the command or after it. A plain comment: a doc comment would become the about of the
// top of the command line. A command line is parsed with these and the one command it
// names (`docs::parser`).
#[derive(Clone, Debug, Args)]
pub struct Common {
    #[command(flatten)]
    pub connection: ConnectionArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub data: DataArgs,
    #[command(flatten)]
    pub poll: PollArgs,
    #[command(flatten)]
    pub redundancy: RedundancyArgs,
    #[command(flatten)]
    pub tls: TlsArgs,
}

#[derive(Clone, Debug, Subcommand)]
#[command(defer = true)]
pub enum Command {
    #[command(flatten)]
    Request(RequestCommand),

    /// Find the slaves on a line and the settings they use
    Scan(ScanArgs),

    /// Watch values live, full screen: min, max, trend, changes
    Watch(ReadByReferenceArgs),

    /// Ask a device who it is: identification and server id
    Info(InfoArgs),

    /// A device's health: round trips, counters, status
    Diag(DiagArgs),

    /// Save a device's tables to a data file, holes left out
    Dump(DumpArgs),

    /// Write a data file back to a device, and check it
    Restore(RestoreArgs),

    /// Decode frames given as arguments or on standard input
    Decode(DecodeArgs),

    /// Print the frame a request command would send
    Encode {
        #[command(subcommand)]
        request: RequestCommand,
    },

    /// Watch a bus without transmitting; frames decoded, paired
    Sniff(SniffArgs),

    /// Stand in for a slave on a serial line or TCP
    Serve(ServeArgs),

    /// Bridge Modbus TCP clients to a serial line, shown live
    Gateway(GatewayArgs),

    /// The serial ports here, and which adapter each one is
    Ports(PortsArgs),

    /// Write the shell completions and man pages (for packagers and the project's own tree)
    #[command(hide = true)]
    Generate(GenerateArgs),
}

/// Each command's long help, beside its one-line about. Only the definition that shows
/// help and writes the man pages takes them (`docs::command`): the one a command line is
/// parsed with would copy some 20 KB of text on every start, to show none of it.
const LONG_ABOUTS: &[(&str, &str)] = &[
    ("scan", SCAN_ABOUT),
    ("watch", WATCH_ABOUT),
    ("info", INFO_ABOUT),
    ("diag", DIAG_ABOUT),
    ("dump", DUMP_ABOUT),
    ("restore", RESTORE_ABOUT),
    ("decode", DECODE_ABOUT),
    ("encode", ENCODE_ABOUT),
    ("sniff", SNIFF_ABOUT),
    ("serve", SERVE_ABOUT),
    ("gateway", GATEWAY_ABOUT),
    ("ports", PORTS_ABOUT),
];

/// `command` with each command's long help.
pub fn with_long_abouts(command: clap::Command) -> clap::Command {
    LONG_ABOUTS.iter().fold(command, |command, (name, about)| {
        command.mut_subcommand(*name, |sub| sub.long_about(*about))
    })
}

const PORTS_ABOUT: &str = "\
The serial ports on this machine, one row each: the device to give to --port, its stable \
name under /dev/serial/by-id (the same after replugging, or in another USB socket), the USB \
vendor and product ids, manufacturer, product and serial number of the adapter, the kernel \
driver, and the processes that have it open. On Linux this is read from /sys, /dev and \
/proc; another user's process is seen only by root, or by the lock file it left \
(/var/lock/LCK..ttyUSB0). On Windows and macOS the columns are what the system's port list \
tells.

No port is not an error: an empty table, exit status 0. -o values lists the devices alone, \
for a script's loop; --json gives one object per port with the keys device, by_id, vid, \
pid, manufacturer, product, serial, driver and busy.";

#[derive(Clone, Debug, Args)]
pub struct PortsArgs {
    /// Read sys, dev and proc under DIR instead of / (a copy taken from another machine)
    #[arg(long, value_name = "DIR", default_value = "/")]
    pub root: std::path::PathBuf,
}

#[derive(Clone, Debug, Args)]
pub struct GenerateArgs {
    /// The folder that receives completions/ and man/
    #[arg(long, default_value = ".")]
    pub dir: std::path::PathBuf,
}

/// What an argument shared by several commands means in each: (command, argument id,
/// value name, help). The derived definitions above say it for holding registers, and
/// `--count` for polling.
const ARGUMENT_HELP: &[(&str, &str, &str, &str)] = &[
    ("read-coils", "address", "ADDRESS", "First coil: a reference (000020) or a number (19; counted from 0, or from 1 with --address-base 1), or an inclusive range (000020-000056)"),
    ("read-coils", "count", "COUNT", "How many coils to read [default: 1]"),
    ("read-inputs", "address", "ADDRESS", "First discrete input: a reference (100197) or a number (196; counted from 0, or from 1 with --address-base 1), or an inclusive range (100197-100218)"),
    ("read-inputs", "count", "COUNT", "How many inputs to read [default: 1]"),
    ("read-input-registers", "address", "ADDRESS", "First input register: a reference (300009), a number (8; counted from 0, or from 1 with --address-base 1), an inclusive range (300009-300011), or a bit of a register (300009.00), COUNT then counting bits"),
    ("write-coils", "address", "ADDRESS", "First coil: a reference (000020) or a number (19; counted from 0, or from 1 with --address-base 1), or a range that holds exactly the values given"),
    ("write-coils", "values", "VALUES", "Each 0/1/on/off, or one bit string such as 10110"),
    ("write-registers", "values", "VALUES", "The values, each converted by --type"),
    ("diag", "poll_count", "N", "How many round trips of return query data to time [default: 5]"),
    ("dump", "output", "FILE", "The data file to write [default: standard output]"),
    ("watch", "map", "FILE", "Watch the points of a register map (CSV, or Home Assistant YAML)"),
    ("watch", "poll", "INTERVAL", "How often to read [default: 1s]"),
    ("gateway", "log", "FILE", "Also append every transaction, with its time, to FILE: CSV for a .csv name, JSON Lines for any other"),
];

/// A built command's argument `id` of `command` (also under `encode`), described as
/// [`ARGUMENT_HELP`] says.
pub fn with_argument_help(command: clap::Command) -> clap::Command {
    command.mut_subcommands(|sub| describe(sub).mut_subcommands(describe))
}

/// [`with_argument_help`] for the one command `name` (and the commands under it).
pub fn with_argument_help_of(command: clap::Command, name: &str) -> clap::Command {
    command.mut_subcommand(name, |sub| describe(sub).mut_subcommands(describe))
}

/// A command's arguments described as [`ARGUMENT_HELP`] says.
fn describe(sub: clap::Command) -> clap::Command {
    let name = sub.get_name().to_string();
    sub.mut_args(|arg| {
        let entry = ARGUMENT_HELP
            .iter()
            .find(|(command, id, ..)| *command == name && arg.get_id() == *id);
        match entry {
            Some((_, _, value_name, help)) => {
                let order = arg.get_display_order() % COMMON_OPTIONS_FIRST_ORDER;
                arg.value_name(*value_name)
                    .help(*help)
                    .help_heading(None::<&str>)
                    // Among the command's own options, where the common ones start at 1000.
                    .display_order(order)
                    // A file is named, not picked from the formats --output lists elsewhere.
                    .hide_possible_values(*value_name == "FILE")
            }
            None => arg,
        }
    })
}

/// The commands that hold commands of their own (`encode read-holding`).
pub const COMMANDS_OF_COMMANDS: &[&str] = &["encode"];

// The common options by what they are for: a command takes whole groups of them.
const LINE: &[&str] = &[
    "port",
    "mode",
    "baud",
    "parity",
    "data_bits",
    "stop_bits",
    // sniff never sends: it takes them, so that one line's options serve every
    // command, and leaves RTS alone.
    "rs485",
    "rs485_delay_before",
    "rs485_delay_after",
    "rts_level",
    "rts_toggle",
];
const MASTER: &[&str] = &["timeout", "retries", "frame_gap", "verbose"];
/// For the commands that can send a request that may do more when sent twice.
const REPEAT: &[&str] = &["retry_non_idempotent"];
const FORMAT: &[&str] = &["output", "json"];
const ADDRESSES: &[&str] = &["pdu_addresses", "address_base"];
const SPLIT: &[&str] = &["max_per_request"];
const REGISTERS: &[&str] = &["value_type", "order"];
const POLL: &[&str] = &["poll", "poll_count", "log"];
const TLS: &[&str] = &["cert", "key", "ca", "tls_server_name"];
const REDUNDANCY: &[&str] = &[
    "secondary_port",
    "secondary_baud",
    "secondary_parity",
    "secondary_data_bits",
    "secondary_stop_bits",
    "secondary_mode",
    "switch_on",
    "switch_when",
];
const COMMON_GROUPS: &[&[&str]] = &[
    LINE, MASTER, REPEAT, FORMAT, ADDRESSES, SPLIT, REGISTERS, POLL, TLS, REDUNDANCY,
];

/// Whether `id` is one of the options every command shares ([`Common`]), wherever clap
/// holds it.
pub fn is_common_option(id: &str) -> bool {
    COMMON_GROUPS.iter().any(|group| group.contains(&id))
}

/// Whether the command at `path` (`["read-holding"]`, `["encode", "write-coil"]`) takes the
/// common option `id`. The options a command does not take are hidden from its help and
/// refused when typed on its command line; a value from the environment is never refused.
pub fn takes_option(path: &[&str], id: &str) -> bool {
    let groups: &[&[&str]] = match path {
        ["decode"] => &[&["mode"], FORMAT, REGISTERS],
        ["ports"] => &[FORMAT],
        ["encode"] => &[&["port", "mode"], FORMAT, ADDRESSES, SPLIT, REGISTERS],
        ["sniff"] => &[LINE, FORMAT],
        ["serve"] => &[LINE, FORMAT, TLS],
        ["gateway"] => &[LINE, MASTER, REPEAT, FORMAT, &["log"], TLS],
        ["info"] => &[LINE, MASTER, FORMAT, TLS],
        // watch draws the screen: no -v trace, no output format.
        ["watch"] => &[
            LINE,
            &["timeout", "retries", "frame_gap", "poll"],
            ADDRESSES,
            SPLIT,
            REGISTERS,
            REDUNDANCY,
            TLS,
        ],
        // dump's --output is the file it writes.
        ["dump"] => &[LINE, MASTER, SPLIT, &["output"], REDUNDANCY, TLS],
        ["restore"] => &[LINE, MASTER, SPLIT, REDUNDANCY, TLS],
        // A scan has no retries: each id that answers is asked once more instead.
        ["scan"] => &[LINE, &["timeout", "frame_gap", "verbose"], FORMAT, TLS],
        ["diag"] => &[LINE, MASTER, FORMAT, &["poll_count"], TLS],
        // What the request command takes, less what only matters on the wire.
        ["encode", request] => {
            let wire = [LINE, MASTER, POLL, REDUNDANCY, TLS].concat();
            return ["port", "mode"].contains(&id)
                || (takes_option(&[request], id) && !wire.contains(&id));
        }
        ["read-coils" | "read-inputs"] => &[
            LINE, MASTER, FORMAT, ADDRESSES, SPLIT, POLL, REDUNDANCY, TLS,
        ],
        ["read-holding" | "read-input-registers" | "read"] => &[
            LINE, MASTER, FORMAT, ADDRESSES, SPLIT, REGISTERS, POLL, REDUNDANCY, TLS,
        ],
        ["write-coil"] => &[LINE, MASTER, FORMAT, ADDRESSES, TLS],
        ["write-coils"] => &[LINE, MASTER, FORMAT, ADDRESSES, SPLIT, TLS],
        ["write-register"] => &[LINE, MASTER, REPEAT, FORMAT, ADDRESSES, REGISTERS, TLS],
        ["write-registers"] => &[LINE, MASTER, FORMAT, ADDRESSES, SPLIT, REGISTERS, TLS],
        ["write"] => &[
            LINE, MASTER, REPEAT, FORMAT, ADDRESSES, SPLIT, REGISTERS, TLS,
        ],
        // raw decodes the answer: --type shows its registers.
        ["raw"] => &[LINE, MASTER, REPEAT, FORMAT, REGISTERS, TLS],
        _ => &[],
    };
    groups.iter().any(|group| group.contains(&id))
}
