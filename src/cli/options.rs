//! The option groups commands share. A command takes a group by holding it as a field
//! (`#[command(flatten)]`): what a command takes is said by its type, and nowhere else.
//!
//! Each option's first paragraph is its line in `-h`; the rest is in `--help` and the man
//! pages. Options a reader seldom needs are left out of `-h` (`hide_short_help`), and
//! `-h` names their groups instead (`docs::point_to_long_help`).

use clap::{Args, ValueEnum};

use mbtool_core::codec::Mode;
use mbtool_core::input::choice::Choice;
use mbtool_core::master::failover::{SwitchCondition, SwitchWhen};
use mbtool_core::model::address::AddressBase;
use mbtool_core::model::line::RtsLevel;
use mbtool_core::model::line::{Parity, BAUDS, DATA_BITS, STOP_BITS};
use mbtool_core::model::values::{ByteOrder, ValueType};

use super::values::{choice, positive_duration, switch, whole, whole_in};

/// The headings of the options `-h` leaves out, by group.
pub mod left_out {
    pub const CONNECTION: &str = "Connection";
    pub const RS485: &str = "RS-485";
    pub const TLS: &str = "Modbus/TCP Security (tls://)";
    pub const WATCHING: &str = "Watching";
    pub const REDUNDANCY: &str = "Redundancy";
    pub const ADDRESSES: &str = "Addresses and values";
    pub const ROLES: &str = "Roles (tls://)";
    pub const FAULTS: &str = "Faults";
    pub const IDENTIFICATION: &str = "Identification";
    pub const MQTT: &str = "MQTT";
}

/// A group of options, and the headings of those of its options that `-h` leaves out.
pub trait ShortHelp {
    const LEFT_OUT: &'static [&'static str];
}

/// What `-h` says after the options it shows: the groups it left out, to be read in
/// `--help`.
pub fn more_in_long_help(groups: &[&[&str]]) -> String {
    let mut headings: Vec<&str> = Vec::new();
    for heading in groups.iter().flat_map(|group| group.iter()) {
        if !headings.contains(heading) {
            headings.push(heading);
        }
    }
    match headings.is_empty() {
        true => String::new(),
        false => format!("More options in --help: {}.", headings.join(", ")),
    }
}

// Where the slave is, and how its frames are wrapped.
#[derive(Clone, Debug, Args)]
#[command(next_help_heading = "Connection")]
pub struct EndpointArgs {
    /// Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim
    ///
    /// Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or
    /// HOST:PORT is Modbus TCP too), tls://HOST[:PORT] (Modbus/TCP Security, port 802),
    /// rtu+tcp://HOST:PORT, udp://HOST[:PORT] (Modbus over UDP, port 502), rtu+udp://HOST:PORT,
    /// or sim, the built-in slave
    #[arg(
        short,
        long,
        env = "MBTOOL_PORT",
        hide_env_values = true,
        value_name = "PORT"
    )]
    pub port: Option<String>,

    /// Framing
    ///
    /// rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports]
    #[arg(short, long, env = "MBTOOL_MODE", hide_env_values = true, value_enum)]
    pub mode: Option<ModeArg>,
}

// A serial line's settings.
#[derive(Clone, Debug, Args)]
#[command(next_help_heading = "Connection")]
pub struct SerialLineArgs {
    /// Serial speed [default: 19200]
    ///
    /// scan takes a list to sweep (9600,19200,38400), else tries this one
    #[arg(
        short,
        long,
        env = "MBTOOL_BAUD", hide_env_values = true,
        value_delimiter = ',',
        value_parser = whole_in(BAUDS)
    )]
    pub baud: Vec<u32>,

    /// Parity [default: even]
    ///
    /// scan takes a list to sweep (none,even,odd), else tries this one
    #[arg(long, env = "MBTOOL_PARITY", hide_env_values = true, value_delimiter = ',', value_parser = choice::<Parity>())]
    pub parity: Vec<Parity>,

    /// Serial data bits [default: 8, 7 in ASCII mode]
    #[arg(long, env = "MBTOOL_DATA_BITS", hide_env_values = true, hide_short_help = true, value_parser = whole_in(DATA_BITS))]
    pub data_bits: Option<u8>,

    /// Serial stop bits [default: 1 with parity, 2 without]
    #[arg(long, env = "MBTOOL_STOP_BITS", hide_env_values = true, hide_short_help = true, value_parser = whole_in(STOP_BITS))]
    pub stop_bits: Option<u8>,
}

// Who switches an RS-485 transceiver between sending and listening.
#[derive(Clone, Debug, Args)]
#[command(next_help_heading = "RS-485")]
pub struct Rs485Args {
    /// RS-485 direction by the kernel's RS-485 mode (Linux): the UART driver raises RTS
    /// while sending, for transceivers that need the host to switch them
    #[arg(long, env = "MBTOOL_RS485", hide_env_values = true, hide_short_help = true, value_parser = switch)]
    pub rs485: bool,

    /// Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle
    #[arg(long, env = "MBTOOL_RS485_DELAY_BEFORE", hide_env_values = true, hide_short_help = true, value_name = "MS", allow_negative_numbers = true, value_parser = whole::<u64>(0, 100))]
    pub rs485_delay_before: Option<u64>,

    /// Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle
    #[arg(long, env = "MBTOOL_RS485_DELAY_AFTER", hide_env_values = true, hide_short_help = true, value_name = "MS", allow_negative_numbers = true, value_parser = whole::<u64>(0, 100))]
    pub rs485_delay_after: Option<u64>,

    /// The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted)
    /// [default: high]
    #[arg(long, env = "MBTOOL_RTS_LEVEL", hide_env_values = true, hide_short_help = true, value_name = "LEVEL", value_parser = choice::<RtsLevel>())]
    pub rts_level: Option<RtsLevel>,

    /// RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped
    /// once its last byte has left (tcdrain), for drivers without RS-485 mode
    #[arg(long, env = "MBTOOL_RTS_TOGGLE", hide_env_values = true, hide_short_help = true, value_parser = switch)]
    pub rts_toggle: bool,
}

// The line a command listens or talks on: where, its serial settings, its RS-485
// direction.
#[derive(Clone, Debug, Args)]
#[command(after_help = more_in_long_help(&[Self::LEFT_OUT]))]
pub struct LineArgs {
    #[command(flatten)]
    pub endpoint: EndpointArgs,
    #[command(flatten)]
    pub serial: SerialLineArgs,
    #[command(flatten)]
    pub rs485: Rs485Args,
}

// How long an answer is waited for, and the silence between transactions.
#[derive(Clone, Debug, Args)]
#[command(next_help_heading = "Connection")]
pub struct ExchangeArgs {
    /// Response timeout: 500ms, 1s [default: 1s]
    ///
    /// For a whole answer: 500ms, 1s, 2.5s; a bare number is seconds, up to 60 [default: 1s; 100ms for scan, 800ms for
    /// gateway]
    #[arg(long, env = "MBTOOL_TIMEOUT", hide_env_values = true, value_parser = positive_duration)]
    pub timeout: Option<std::time::Duration>,

    /// Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200
    /// baud]; 0 for gateways and devices that need none
    #[arg(long, hide_short_help = true, value_name = "DURATION", value_parser = mbtool_core::input::duration::parse_duration)]
    pub frame_gap: Option<std::time::Duration>,
}

// Retries after a timeout or a bad answer.
#[derive(Clone, Debug, Args)]
#[command(next_help_heading = "Connection")]
pub struct RetriesArgs {
    /// Retries after a timeout or a bad answer
    ///
    /// Never after an exception
    #[arg(long, env = "MBTOOL_RETRIES", hide_env_values = true, value_name = "N", allow_negative_numbers = true, value_parser = whole::<u32>(0, 100))]
    pub retries: Option<u32>,
}

// Retries of requests that may do more when sent twice, for the commands that can send
// one.
#[derive(Clone, Debug, Args)]
#[command(next_help_heading = "Connection")]
pub struct RepeatArgs {
    /// With --retries, retry a request that may do more when sent twice too: mask write
    /// (22), read/write multiple (23), file record write (21), user-defined functions
    #[arg(long, hide_short_help = true)]
    pub retry_non_idempotent: bool,
}

// Every frame on stderr.
#[derive(Clone, Debug, Args)]
#[command(next_help_heading = "Output")]
pub struct TraceArgs {
    /// Print every frame sent and received, in hex with a timestamp, on stderr
    #[arg(short, long)]
    pub verbose: bool,
}

// What a command that talks to a slave takes: the line, the wait, the retries, the
// trace, and Modbus/TCP Security.
#[derive(Clone, Debug, Args)]
#[command(after_help = more_in_long_help(&[Self::LEFT_OUT]))]
pub struct MasterArgs {
    #[command(flatten)]
    pub line: LineArgs,
    #[command(flatten)]
    pub exchange: ExchangeArgs,
    #[command(flatten)]
    pub retries: RetriesArgs,
    #[command(flatten)]
    pub trace: TraceArgs,
    #[command(flatten)]
    pub tls: TlsArgs,
}

// The certificates of Modbus/TCP Security (tls:// ports).
#[derive(Clone, Debug, Args)]
#[command(next_help_heading = "Modbus/TCP Security (tls://)")]
pub struct TlsArgs {
    /// This end's certificate (PEM), for tls:// ports; a client's carries its role
    #[arg(
        long,
        env = "MBTOOL_CERT",
        hide_env_values = true,
        hide_short_help = true,
        value_name = "FILE"
    )]
    pub cert: Option<std::path::PathBuf>,

    /// The private key of --cert (PEM: PKCS#8, RSA or EC)
    #[arg(
        long,
        env = "MBTOOL_KEY",
        hide_env_values = true,
        hide_short_help = true,
        value_name = "FILE"
    )]
    pub key: Option<std::path::PathBuf>,

    /// The CA certificates (PEM) that sign the other end's certificate: the device's for a
    /// master, the clients' for serve and gateway
    #[arg(
        long,
        env = "MBTOOL_CA",
        hide_env_values = true,
        hide_short_help = true,
        value_name = "FILE"
    )]
    pub ca: Option<std::path::PathBuf>,

    /// The name the device's certificate must hold [default: the host of --port], for a
    /// device addressed by IP whose certificate names something else
    #[arg(
        long,
        env = "MBTOOL_TLS_SERVER_NAME",
        hide_env_values = true,
        hide_short_help = true,
        value_name = "NAME"
    )]
    pub tls_server_name: Option<String>,
}

// A second path to the device and when to change to it.
#[derive(Clone, Debug, Args)]
#[command(next_help_heading = "Redundancy")]
pub struct RedundancyArgs {
    /// A second path to the same device (any --port), used when the --switch-on
    /// conditions hold on the one in use; its line settings are the primary's unless
    /// given below
    #[arg(
        long,
        env = "MBTOOL_SECONDARY_PORT",
        hide_env_values = true,
        hide_short_help = true,
        value_name = "PORT"
    )]
    pub secondary_port: Option<String>,

    /// Serial speed of the secondary path [default: --baud]
    #[arg(long, env = "MBTOOL_SECONDARY_BAUD", hide_env_values = true, hide_short_help = true, value_name = "BAUD", value_parser = whole_in(BAUDS))]
    pub secondary_baud: Option<u32>,

    /// Serial parity of the secondary path [default: --parity]
    #[arg(long, env = "MBTOOL_SECONDARY_PARITY", hide_env_values = true, hide_short_help = true, value_name = "PARITY", value_parser = choice::<Parity>())]
    pub secondary_parity: Option<Parity>,

    /// Serial data bits of the secondary path [default: --data-bits]
    #[arg(long, env = "MBTOOL_SECONDARY_DATA_BITS", hide_env_values = true, hide_short_help = true, value_name = "BITS", value_parser = whole_in(DATA_BITS))]
    pub secondary_data_bits: Option<u8>,

    /// Serial stop bits of the secondary path [default: --stop-bits]
    #[arg(long, env = "MBTOOL_SECONDARY_STOP_BITS", hide_env_values = true, hide_short_help = true, value_name = "BITS", value_parser = whole_in(STOP_BITS))]
    pub secondary_stop_bits: Option<u8>,

    /// Framing of the secondary path [default: --mode, tcp for tcp:// ports]
    #[arg(
        long,
        env = "MBTOOL_SECONDARY_MODE",
        hide_env_values = true,
        hide_short_help = true,
        value_name = "MODE",
        value_enum
    )]
    pub secondary_mode: Option<ModeArg>,

    /// When to change paths, counted since the path's last good answer:
    /// timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default:
    /// timeout:3,disconnect]
    #[arg(long, env = "MBTOOL_SWITCH_ON", hide_env_values = true, hide_short_help = true, value_name = "CONDITIONS", value_delimiter = ',', value_parser = SwitchCondition::parse)]
    pub switch_on: Vec<SwitchCondition>,

    /// Whether any of the --switch-on conditions changes paths, or only all of them
    /// together [default: any]
    #[arg(long, env = "MBTOOL_SWITCH_WHEN", hide_env_values = true, hide_short_help = true, value_name = "WHEN", value_parser = choice::<SwitchWhen>())]
    pub switch_when: Option<SwitchWhen>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ModeArg {
    Rtu,
    Ascii,
    Tcp,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum AddressBaseArg {
    /// Protocol addresses, 0-65535
    #[value(name = "0")]
    Zero,
    /// Register numbers, 1-65536
    #[value(name = "1")]
    One,
}

impl From<AddressBaseArg> for AddressBase {
    fn from(base: AddressBaseArg) -> AddressBase {
        match base {
            AddressBaseArg::Zero => AddressBase::Zero,
            AddressBaseArg::One => AddressBase::One,
        }
    }
}

impl From<ModeArg> for Mode {
    fn from(mode: ModeArg) -> Mode {
        match mode {
            ModeArg::Rtu => Mode::Rtu,
            ModeArg::Ascii => Mode::Ascii,
            ModeArg::Tcp => Mode::Tcp,
        }
    }
}

// How results are shown.
#[derive(Clone, Debug, Args)]
#[command(next_help_heading = "Output")]
pub struct FormatArgs {
    /// Output format [default: table]
    #[arg(short, long, value_name = "FORMAT", value_parser = FormatOrFile::default())]
    pub output: Option<String>,

    /// The same as --output json
    #[arg(long)]
    pub json: bool,
}

/// The value of `--output`: a format (listed in help and completions). It is read as
/// text and checked once the command is known, as `dump`'s `--output` of the same name is
/// a file, and an `--output` typed before the command name may be either.
#[derive(Clone, Default)]
pub struct FormatOrFile {
    /// `poll`'s formats: InfluxDB line protocol beside the others, no bare values.
    pub plant: bool,
}

impl clap::builder::TypedValueParser for FormatOrFile {
    type Value = String;

    fn parse_ref(
        &self,
        _: &clap::Command,
        _: Option<&clap::Arg>,
        value: &std::ffi::OsStr,
    ) -> Result<String, clap::Error> {
        Ok(value.to_string_lossy().into_owned())
    }

    fn possible_values(
        &self,
    ) -> Option<Box<dyn Iterator<Item = clap::builder::PossibleValue> + '_>> {
        let plant = self.plant;
        let influx = plant.then(|| {
            clap::builder::PossibleValue::new("influx")
                .help("InfluxDB line protocol, for Telegraf's execd and exec inputs")
        });
        Some(Box::new(
            OutputFormat::value_variants()
                .iter()
                .filter(move |format| !(plant && **format == OutputFormat::Values))
                .filter_map(ValueEnum::to_possible_value)
                .chain(influx),
        ))
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum OutputFormat {
    /// A table for people
    Table,
    /// One JSON object per line
    Json,
    /// Only the values, one per line, for $(...) in scripts
    Values,
    /// Comma-separated values with a header line
    Csv,
}

// How addresses typed and shown are counted.
#[derive(Clone, Debug, Args)]
#[command(next_help_heading = "Addresses and values")]
pub struct AddressArgs {
    /// Take every address as a plain number, never as a Modicon reference
    ///
    /// 40001 is then protocol address 40001 (register number 40001 with --address-base 1)
    #[arg(long, hide_short_help = true)]
    pub pdu_addresses: bool,

    /// What a bare address counts from: 0 (protocol address) or 1 (register number)
    ///
    /// In what is typed and in the address column shown: 0, the protocol address (107 is
    /// 400108), or 1, the register number as manuals and mbpoll count (108 is 400108).
    /// References (400108) are the same either way; decode, sniff and serve show a frame's
    /// address field as it is on the wire
    #[arg(
        long,
        env = "MBTOOL_ADDRESS_BASE",
        hide_env_values = true,
        hide_short_help = true,
        value_name = "BASE",
        value_enum,
        default_value = "0"
    )]
    pub address_base: AddressBaseArg,
}

// The largest request a device takes.
#[derive(Clone, Debug, Args)]
#[command(next_help_heading = "Addresses and values")]
pub struct SplitArgs {
    /// Split reads and writes into requests of at most N coils or registers
    ///
    /// For devices that take fewer than the protocol allows; for read-file and dump, records
    /// of files a request
    #[arg(long, hide_short_help = true, value_name = "N", value_parser = whole::<u16>(1, 2000))]
    pub max_per_request: Option<u16>,
}

// How the words of registers are read as values.
#[derive(Clone, Debug, Args)]
#[command(next_help_heading = "Addresses and values")]
pub struct RegisterArgs {
    /// Register value type, for values read and values to write
    #[arg(short = 't', long = "type", value_name = "TYPE", value_parser = choice::<ValueType>(), default_value = ValueType::default().name())]
    pub value_type: ValueType,

    /// Byte order of values wider than 16 bits (A: the most significant byte)
    #[arg(long, value_parser = choice::<ByteOrder>(), default_value = ByteOrder::default().name())]
    pub order: ByteOrder,
}

// A read repeated on a schedule.
#[derive(Clone, Debug, Args)]
#[command(next_help_heading = "Watching")]
pub struct PollArgs {
    /// Repeat the read every INTERVAL until Ctrl-C or --count
    ///
    /// 0 for back to back. Each poll is one line: its time and a column a value (CSV with
    /// -o csv, as Modbus Poll logs), what changed marked, with a summary on stderr at the
    /// end; a failed read is a line without values, a range with holes is read around them
    /// (each hole without a value, named in the error column), and a connection that drops
    /// is opened again
    #[arg(long, hide_short_help = true, value_name = "INTERVAL", value_parser = mbtool_core::input::duration::parse_duration)]
    pub poll: Option<std::time::Duration>,

    /// With --poll: stop after N reads
    #[arg(
        long = "count",
        hide_short_help = true,
        value_name = "N",
        value_parser = whole::<u64>(1, i128::from(u64::MAX))
    )]
    pub poll_count: Option<u64>,

    /// With --poll: also append every poll, with its time, to FILE
    ///
    /// The same rows as -o csv for a .csv name, as -o json for any other
    #[arg(long, hide_short_help = true, value_name = "FILE")]
    pub log: Option<std::path::PathBuf>,
}

impl ShortHelp for LineArgs {
    const LEFT_OUT: &'static [&'static str] = &[left_out::CONNECTION, left_out::RS485];
}

impl ShortHelp for MasterArgs {
    const LEFT_OUT: &'static [&'static str] =
        &[left_out::CONNECTION, left_out::RS485, left_out::TLS];
}

impl ShortHelp for EndpointArgs {
    const LEFT_OUT: &'static [&'static str] = &[];
}

// Every option a command can take, at the top of the command line: typed before the
// command's name, each is the command's where it takes it and does not type it again.
#[derive(Clone, Debug, Args)]
pub struct EveryOption {
    #[command(flatten)]
    pub master: MasterArgs,
    #[command(flatten)]
    pub repeat: RepeatArgs,
    #[command(flatten)]
    pub format: FormatArgs,
    #[command(flatten)]
    pub addresses: AddressArgs,
    #[command(flatten)]
    pub split: SplitArgs,
    #[command(flatten)]
    pub registers: RegisterArgs,
    #[command(flatten)]
    pub poll: PollArgs,
    #[command(flatten)]
    pub redundancy: RedundancyArgs,
}

// What every request `encode` builds may take, typed before the request's name
// (`mbtool encode --mode tcp read-holding 17 400108 3`).
#[derive(Clone, Debug, Args)]
pub struct EncodeOptions {
    #[command(flatten)]
    pub endpoint: EndpointArgs,
    #[command(flatten)]
    pub format: FormatArgs,
    #[command(flatten)]
    pub addresses: AddressArgs,
    #[command(flatten)]
    pub split: SplitArgs,
    #[command(flatten)]
    pub registers: RegisterArgs,
    #[command(flatten)]
    pub repeat: RepeatArgs,
}
