//! The command line, as clap derives it. `--help`, the man pages and the shell completions
//! are all generated from this one definition.

use clap::{Args, Parser, Subcommand};

mod device;
pub mod examples;
mod gateway;
mod options;
mod plant;
mod requests;
mod serve;
mod taken;
mod traffic;
mod values;

pub use device::*;
pub use gateway::*;
pub use options::*;
pub use plant::*;
pub use requests::*;
pub use serve::*;
pub(crate) use taken::arg_id;
pub use taken::{Before, Options, Taken};
pub use traffic::*;

use clap::CommandFactory;
use taken::holds;

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

/// The top of the command line: `mbtool [OPTIONS] <COMMAND> [ARGS]`. Each command's
/// arguments hold the groups of options it takes; [`definition`] lets them be typed before
/// the command's name too.
#[derive(Clone, Debug, Parser)]
#[command(
    name = "mbtool",
    version,
    about = ABOUT,
    long_about = LONG_ABOUT,
    propagate_version = true,
    max_term_width = HELP_WIDTH,
    subcommand_required = true,
    arg_required_else_help = true
)]
pub struct Cli {
    #[command(flatten)]
    pub before: EveryOption,
    #[command(subcommand)]
    pub command: Command,
}

// Each command's arguments are derived when it is used (`defer`), so that a command
// line builds no other command's.
#[derive(Clone, Debug, Subcommand)]
#[command(defer = true)]
pub enum Command {
    #[command(flatten)]
    Request(RequestCommand<OnTheBus>),

    /// Find the slaves on a line and the settings they use
    #[command(long_about = SCAN_ABOUT)]
    Scan(ScanArgs),

    /// Watch values live, full screen: min, max, trend, changes
    #[command(long_about = WATCH_ABOUT)]
    Watch(WatchArgs),

    /// Ask a device who it is: identification and server id
    #[command(long_about = INFO_ABOUT)]
    Info(InfoArgs),

    /// Read a SunSpec device's models: points named, scaled
    #[command(long_about = SUNSPEC_ABOUT)]
    Sunspec(SunspecArgs),

    /// A device's health: round trips, counters, status
    #[command(long_about = DIAG_ABOUT)]
    Diag(DiagArgs),

    /// Save a device's tables to a data file, holes left out
    #[command(long_about = DUMP_ABOUT)]
    Dump(DumpArgs),

    /// Write a data file back to a device, and check it
    #[command(long_about = RESTORE_ABOUT)]
    Restore(RestoreArgs),

    /// Decode frames given as arguments or on standard input
    #[command(long_about = DECODE_ABOUT)]
    Decode(DecodeArgs),

    /// Print the frame a request command would send
    #[command(
        long_about = ENCODE_ABOUT,
        after_help = more_in_long_help(&[&[left_out::CONNECTION, left_out::ADDRESSES]]),
        // Each request's own -h says the rest; the list of requests fits a screen.
        disable_help_subcommand = true,
        disable_version_flag = true
    )]
    Encode {
        #[command(flatten)]
        shared: EncodeOptions,
        #[command(subcommand)]
        request: RequestCommand<Encoded>,
    },

    /// Watch a bus without transmitting; frames decoded, paired
    #[command(long_about = SNIFF_ABOUT)]
    Sniff(SniffArgs),

    /// Stand in for a slave on a serial line or TCP
    #[command(long_about = SERVE_ABOUT)]
    Serve(ServeArgs),

    /// Bridge Modbus TCP clients to a serial line, shown live
    #[command(long_about = GATEWAY_ABOUT)]
    Gateway(GatewayArgs),

    /// Keep a plant's devices read, each at its rate
    #[command(long_about = PLANT_ABOUT)]
    Poll(PlantArgs),

    /// The serial ports here, and which adapter each one is
    #[command(long_about = PORTS_ABOUT)]
    Ports(PortsArgs),

    /// Write the shell completions and man pages (for packagers and the project's own tree)
    #[command(hide = true)]
    Generate(GenerateArgs),
}

impl Command {
    /// The command's arguments, as the groups of options they hold.
    pub fn options_mut(&mut self) -> &mut dyn Options {
        match self {
            Command::Request(request) => request.options_mut(),
            Command::Encode { request, .. } => request.options_mut(),
            Command::Scan(args) => args,
            Command::Watch(args) => args,
            Command::Info(args) => args,
            Command::Sunspec(args) => args,
            Command::Diag(args) => args,
            Command::Dump(args) => args,
            Command::Restore(args) => args,
            Command::Decode(args) => args,
            Command::Sniff(args) => args,
            Command::Serve(args) => args,
            Command::Gateway(args) => args,
            Command::Poll(args) => args,
            Command::Ports(args) => args,
            Command::Generate(args) => args,
        }
    }
}

/// The whole command line: [`Cli`], the options that may be typed before the command's
/// name left out of `mbtool -h` (each command's own help shows those it takes), and
/// listed in `mbtool --help` and the man page.
pub fn definition() -> clap::Command {
    let command = Cli::command()
        .mut_args(|arg| arg.hide_short_help(true))
        .after_help(
            "A command's options may be typed before its name too; 'mbtool --help' lists them \
             all, 'mbtool <COMMAND> -h' those the command takes.",
        );
    examples::with_examples(command)
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
    #[command(flatten)]
    pub format: FormatArgs,
}

holds!(PortsArgs: format);

#[derive(Clone, Debug, Args)]
pub struct GenerateArgs {
    /// The folder that receives completions/ and man/
    #[arg(long, default_value = ".")]
    pub dir: std::path::PathBuf,
}

impl Options for GenerateArgs {
    fn gather<'a>(&'a self, _: &mut Taken<'a>) {}
    fn take_before(&mut self, _: &Before) {}
}
