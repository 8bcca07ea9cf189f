//! The command line resolved once into the plain types the commands take: the
//! [`Settings`] they share and each one's [`Job`]. This module and `main.rs` are the only
//! ones that know the clap definition's types; a new option is defined in `cli` and
//! resolved here, nowhere else. Every check of the command line as
//! a whole (an option the command does not take, a sweep outside scan, an `--output` that
//! is no format) is made here, before any command runs.

pub mod job;

use std::path::PathBuf;
use std::time::Duration;

use clap::parser::ValueSource;
use clap::ValueEnum;

use crate::cli::{
    arg_id, AddressBaseArg, Before, Cli, Command, FormatArgs, Options, OutputFormat,
    RedundancyArgs, Rs485Args, SerialLineArgs, Taken, TlsArgs,
};
use crate::output::{colour_wanted, Format, Style};
use job::Job;
use mbtool_core::codec::Mode;
use mbtool_core::master::failover::{SwitchCondition, SwitchRule};
use mbtool_core::master::timeouts;
use mbtool_core::model::address::Numbering;
use mbtool_core::model::line::{DirectionControl, LineSettings, Parity, RtsTiming};
use mbtool_core::model::map::MapConnection;
use mbtool_core::model::values::{ByteOrder, ValueType};
use mbtool_core::transport::tls::TlsFiles;
use mbtool_core::transport::Endpoint;

/// Everything the options say, resolved.
#[derive(Clone, Debug)]
pub struct Settings {
    pub connection: ConnectionSettings,
    pub output: Output,
    pub data: Data,
    pub poll: Poll,
}

/// Where the slave is and how to talk to it.
#[derive(Clone, Debug)]
pub struct ConnectionSettings {
    /// `--port` as given; what it names is read when a command needs it, so that a
    /// missing port is told only to commands that use one.
    pub port: Option<String>,
    /// `--mode`, when given.
    pub mode: Option<Mode>,
    /// The serial speeds given: one, or a list to sweep (scan only).
    pub bauds: Vec<u32>,
    /// Whether `--baud` (or its variable) gave them, rather than the default.
    pub baud_given: bool,
    /// The parities given, as `bauds`.
    pub parities: Vec<Parity>,
    /// Whether `--parity` (or its variable) gave them.
    pub parity_given: bool,
    pub data_bits: Option<u8>,
    pub stop_bits: Option<u8>,
    /// The response timeout: as given, else the command's default.
    pub timeout: Duration,
    /// Whether `--timeout` (or its variable) gave it.
    pub timeout_given: bool,
    /// Retries after a timeout or a bad answer: `--retries`, or over UDP two.
    pub retries: u32,
    /// Whether `--retries` (or its variable) gave them.
    pub retries_given: bool,
    /// `--retry-non-idempotent`: retries of requests that may do more when sent twice.
    pub retry_non_idempotent: bool,
    pub frame_gap: Option<Duration>,
    /// Who switches an RS-485 transceiver: `--rs485`, `--rts-toggle` and their timing.
    pub direction: DirectionControl,
    /// Whether `--rs485` or `--rts-toggle` was typed, not only set in the environment: a
    /// port that is no serial line refuses it then, and ignores the variable.
    pub direction_typed: bool,
    /// `--secondary-port` with its line settings: the other path to the same device.
    pub secondary: Option<Box<ConnectionSettings>>,
    /// When to change between the paths.
    pub switch: SwitchRule,
    /// The certificates for a tls:// port.
    pub tls: TlsFiles,
    /// Whether one of them was typed, not only set in the environment: a port that is
    /// not tls:// refuses it then, and ignores the variable.
    pub tls_typed: bool,
    /// Whether `-v` asks for a TLS connection's version, cipher suite and certificates
    /// to be told.
    pub tell_session: bool,
}

impl ConnectionSettings {
    /// The serial speed; only scan sweeps several, and a list elsewhere is refused.
    pub fn baud(&self) -> u32 {
        self.bauds.first().copied().unwrap_or(19200)
    }

    /// The serial parity, as [`ConnectionSettings::baud`].
    pub fn parity(&self) -> Parity {
        self.parities.first().copied().unwrap_or(Parity::Even)
    }

    /// The serial line settings, defaults filled in as docs/serial-line.md gives them.
    pub fn line(&self, mode: Mode) -> LineSettings {
        self.line_at(mode, self.baud(), self.parity())
    }

    /// The serial line settings at `baud` and `parity` (a step of a scan's sweep), the
    /// data and stop bits as the options give them.
    pub fn line_at(&self, mode: Mode, baud: u32, parity: Parity) -> LineSettings {
        LineSettings {
            baud,
            parity,
            data_bits: self
                .data_bits
                .unwrap_or(if mode == Mode::Ascii { 7 } else { 8 }),
            stop_bits: self
                .stop_bits
                .unwrap_or(if parity == Parity::None { 2 } else { 1 }),
            direction: self.direction,
        }
    }

    /// The connection settings with what a map's file says of its device (a Home Assistant
    /// hub's host and port, or serial device and line) where the command line says nothing.
    pub fn with_map(&self, from_map: Option<&MapConnection>) -> ConnectionSettings {
        let mut options = self.clone();
        let Some(from_map) = from_map.filter(|_| options.port.is_none()) else {
            return options;
        };
        options.port = Some(from_map.port.clone());
        if options.mode.is_none() {
            options.mode = match from_map.mode.as_deref() {
                Some("ascii") => Some(Mode::Ascii),
                Some("rtu") => Some(Mode::Rtu),
                _ => None,
            };
        }
        if let (false, Some(baud)) = (options.baud_given, from_map.baud) {
            options.bauds = vec![baud];
        }
        let parity = match from_map.parity.map(|p| p.to_ascii_uppercase()) {
            Some('E') => Some(Parity::Even),
            Some('O') => Some(Parity::Odd),
            Some('N') => Some(Parity::None),
            _ => None,
        };
        if let (false, Some(parity)) = (options.parity_given, parity) {
            options.parities = vec![parity];
        }
        options.data_bits = options.data_bits.or(from_map.data_bits);
        options.stop_bits = options.stop_bits.or(from_map.stop_bits);
        options
    }
}

/// How results are shown.
#[derive(Clone, Debug)]
pub struct Output {
    pub style: Style,
    pub format: Format,
    /// `-v`: every frame on stderr.
    pub verbose: bool,
    /// The file `dump` writes (its `--output`).
    pub file: Option<PathBuf>,
}

/// How addresses and values are read from the command line.
#[derive(Clone, Copy, Debug)]
pub struct Data {
    pub numbering: Numbering,
    pub value_type: ValueType,
    pub order: ByteOrder,
    pub max_per_request: Option<u16>,
}

/// A read repeated on a schedule.
#[derive(Clone, Debug)]
pub struct Poll {
    /// `--poll`: the interval, when reads repeat.
    pub interval: Option<Duration>,
    /// `--count`: how many reads (for diag, how many round trips).
    pub count: Option<u64>,
    /// `--log`: the file every row is appended to.
    pub log: Option<PathBuf>,
}

/// The command line `args` parsed with the [`definition`](crate::cli::definition): what
/// it says, the values typed before the command's name handed to the command, and where
/// each value came from.
pub fn read(
    definition: &mut clap::Command,
    args: impl IntoIterator<Item = std::ffi::OsString>,
) -> Result<(Cli, Origins), clap::Error> {
    let mut matches = definition.try_get_matches_from_mut(args)?;
    let origins = Origins::of(&matches, definition);
    let mut cli = <Cli as clap::FromArgMatches>::from_arg_matches_mut(&mut matches)?;
    origins.hand_down(&mut cli);
    Ok((cli, origins))
}

/// The command given and where each of its options' values came from, read from clap's
/// matches before they are taken apart into a [`Cli`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Origins {
    /// The names of the command given: `["read-holding"]`, `["encode", "write-coil"]`.
    path: Vec<String>,
    /// Each of the command's options with a value, and whether it was typed (before the
    /// command's name or after it), set in the environment or is the default.
    sources: Vec<(String, ValueSource)>,
    /// At each level before the command (the top, then `encode`), the options typed there
    /// that the command takes and does not type itself.
    before: Vec<Vec<String>>,
    /// The refusal of the first option typed before the command that it does not take.
    untaken: Option<String>,
}

impl Origins {
    fn of(matches: &clap::ArgMatches, definition: &clap::Command) -> Origins {
        let mut levels = vec![(matches, definition)];
        let mut path = Vec::new();
        while let Some(&(matches, command)) = levels.last() {
            let Some((name, sub)) = matches.subcommand() else {
                break;
            };
            let Some(command) = command.find_subcommand(name) else {
                break;
            };
            path.push(name.to_string());
            levels.push((sub, command));
        }
        let (leaf, command) = levels.pop().unwrap_or((matches, definition));
        let typed = |matches: &clap::ArgMatches, id: &str| {
            matches.value_source(id) == Some(ValueSource::CommandLine)
        };
        let mut sources: Vec<(String, ValueSource)> = command
            .get_arguments()
            .filter_map(|arg| {
                let id = arg.get_id().as_str();
                Some((id.to_string(), leaf.value_source(id)?))
            })
            .collect();
        let mut untaken = None;
        let mut before = Vec::new();
        for (matches, level) in levels {
            let mut handed = Vec::new();
            for arg in level.get_arguments() {
                let id = arg.get_id().as_str();
                if !typed(matches, id) {
                    continue;
                }
                if command.get_arguments().all(|own| own.get_id() != id) {
                    untaken = untaken.or_else(|| Some(refusal(&path.join(" "), arg)));
                } else if !typed(leaf, id) {
                    handed.push(id.to_string());
                    sources.retain(|(known, _)| known != id);
                    sources.push((id.to_string(), ValueSource::CommandLine));
                }
            }
            before.push(handed);
        }
        // By name: the first of several is told the same however the line was typed.
        sources.sort_by(|a, b| a.0.cmp(&b.0));
        Origins {
            path,
            sources,
            before,
            untaken,
        }
    }

    /// The values typed before the command's name, handed to the command's groups that
    /// take them and did not have them typed.
    fn hand_down(&self, cli: &mut Cli) {
        let mut levels = Vec::new();
        let mut top = Taken::default();
        cli.before.gather(&mut top);
        levels.push((top, self.before.first().cloned().unwrap_or_default()));
        match &mut cli.command {
            Command::Encode { shared, request } => {
                let mut encode = Taken::default();
                shared.gather(&mut encode);
                levels.push((encode, self.before.get(1).cloned().unwrap_or_default()));
                request.options_mut().take_before(&Before { levels });
            }
            command => command.options_mut().take_before(&Before { levels }),
        }
    }

    /// The names of the command given: `["read-holding"]`, `["encode", "write-coil"]`.
    pub fn path(&self) -> Vec<&str> {
        self.path.iter().map(String::as_str).collect()
    }

    fn source(&self, id: &str) -> Option<ValueSource> {
        self.sources
            .iter()
            .find_map(|(known, source)| (known == id).then_some(*source))
    }

    /// Whether option `id` was typed on the command line.
    fn typed(&self, id: &str) -> bool {
        self.source(id) == Some(ValueSource::CommandLine)
    }

    /// The options typed on the command line.
    fn typed_ids(&self) -> impl Iterator<Item = &str> {
        self.sources
            .iter()
            .filter(|(_, source)| *source == ValueSource::CommandLine)
            .map(|(id, _)| id.as_str())
    }
}

/// The one line that refuses `option` to the command at `path` (`encode write-coil`),
/// which does not take it.
pub fn refusal(path: &str, option: &clap::Arg) -> String {
    let name = match (option.get_long(), option.get_short()) {
        (Some(long), _) => format!("--{long}"),
        (None, Some(short)) => format!("-{short}"),
        (None, None) => option.get_id().to_string(),
    };
    format!("{path} does not take {name} (see 'mbtool {path} --help' for the options it takes)")
}

/// The settings and the job of a parsed command line, or the one-line message that
/// refuses it.
pub fn resolve(mut cli: Cli, origins: &Origins) -> Result<(Settings, Job), String> {
    let settings = settings_of(&mut cli, origins)?;
    Ok((settings, job::of(cli.command)?))
}

fn settings_of(cli: &mut Cli, origins: &Origins) -> Result<Settings, String> {
    let scan = matches!(cli.command, Command::Scan(_));
    let plant = matches!(cli.command, Command::Poll(_));
    let default_timeout = match cli.command {
        Command::Scan(_) => timeouts::SCAN,
        Command::Gateway(_) => timeouts::GATEWAY,
        _ => timeouts::ANSWER,
    };
    let command: &dyn Options = cli.command.options_mut();
    let mut taken = Taken::default();
    command.gather(&mut taken);
    if let Some(message) = untaken_option(origins)
        .or_else(|| sweep_outside_scan(scan, &taken, origins))
        .or_else(|| output_problem(&taken, plant))
    {
        return Err(message);
    }
    // Set in the environment, the RS-485 options are checked for every command, as the
    // environment holds them for every command.
    let rs485 = taken.rs485.unwrap_or(&cli.before.master.line.rs485);
    let (direction, direction_typed) = direction(rs485, origins)?;
    let timeout = taken.exchange.and_then(|e| e.timeout);
    let format = match taken.format {
        Some(FormatArgs { json: true, .. }) => Format::Json,
        Some(FormatArgs {
            output: Some(name), ..
        }) => OutputFormat::from_str(name, true).map_or(Format::Table, format_of),
        _ => Format::Table,
    };
    let serial = taken.serial;
    let bauds = serial.map_or_else(Vec::new, |s| s.baud.clone());
    let parities = serial.map_or_else(Vec::new, |s| s.parity.clone());
    let tls = taken.tls;
    let registers = taken.registers;
    let value_type = registers.map_or_else(ValueType::default, |r| r.value_type);
    let order = registers.map_or_else(ByteOrder::default, |r| r.order);
    let address_base = taken
        .addresses
        .map_or(AddressBaseArg::Zero, |a| a.address_base)
        .into();
    let verbose = taken.trace.is_some_and(|t| t.verbose);
    let mut settings = Settings {
        connection: ConnectionSettings {
            port: taken.port.map(str::to_string),
            mode: taken.mode.map(Mode::from),
            baud_given: !bauds.is_empty(),
            bauds: if bauds.is_empty() { vec![19200] } else { bauds },
            parity_given: !parities.is_empty(),
            parities: if parities.is_empty() {
                vec![Parity::Even]
            } else {
                parities
            },
            data_bits: serial.and_then(|s| s.data_bits),
            stop_bits: serial.and_then(|s| s.stop_bits),
            timeout: timeout.unwrap_or(default_timeout),
            timeout_given: timeout.is_some(),
            retries: taken
                .retries
                .and_then(|r| r.retries)
                .unwrap_or_else(|| default_retries(taken.port)),
            retries_given: taken.retries.and_then(|r| r.retries).is_some(),
            retry_non_idempotent: taken.repeat.is_some_and(|r| r.retry_non_idempotent),
            frame_gap: taken.exchange.and_then(|e| e.frame_gap),
            direction,
            direction_typed,
            secondary: None,
            switch: SwitchRule::default(),
            tls: TlsFiles {
                cert: tls.and_then(|t| t.cert.clone()),
                key: tls.and_then(|t| t.key.clone()),
                ca: tls.and_then(|t| t.ca.clone()),
                server_name: tls.and_then(|t| t.tls_server_name.clone()),
            },
            tls_typed: [
                arg_id!(TlsArgs, cert),
                arg_id!(TlsArgs, key),
                arg_id!(TlsArgs, ca),
                arg_id!(TlsArgs, tls_server_name),
            ]
            .iter()
            .any(|id| origins.typed(id)),
            tell_session: verbose,
        },
        output: Output {
            style: Style {
                format,
                value_type,
                order,
                address_base,
                colour: colour_wanted(),
            },
            format,
            verbose,
            file: taken.file.map(PathBuf::from),
        },
        data: Data {
            numbering: Numbering {
                references: !taken.addresses.is_some_and(|a| a.pdu_addresses),
                base: address_base,
            },
            value_type,
            order,
            max_per_request: taken.split.and_then(|s| s.max_per_request),
        },
        poll: Poll {
            interval: taken.poll,
            count: taken.count,
            log: taken.log.map(PathBuf::from),
        },
    };
    // A command that does not take a second path ignores one set in the environment.
    if let Some(redundancy) = taken.redundancy {
        redundancy_of(redundancy, origins, &mut settings.connection)?;
    }
    Ok(settings)
}

/// `--secondary-port` and its settings, each the primary's where not given, and the rule
/// for changing paths. The other options typed without a secondary port are refused, as
/// they would do nothing.
fn redundancy_of(
    r: &RedundancyArgs,
    origins: &Origins,
    primary: &mut ConnectionSettings,
) -> Result<(), String> {
    let typed_empty = r.secondary_port.as_deref() == Some("")
        && origins.typed(arg_id!(RedundancyArgs, secondary_port));
    if typed_empty {
        return Err(
            "--secondary-port is empty: give the other path to the device, or leave it out".into(),
        );
    }
    let Some(port) = r.secondary_port.clone().filter(|port| !port.is_empty()) else {
        let needing_a_port = [
            arg_id!(RedundancyArgs, secondary_baud),
            arg_id!(RedundancyArgs, secondary_parity),
            arg_id!(RedundancyArgs, secondary_data_bits),
            arg_id!(RedundancyArgs, secondary_stop_bits),
            arg_id!(RedundancyArgs, secondary_mode),
            arg_id!(RedundancyArgs, switch_on),
            arg_id!(RedundancyArgs, switch_when),
        ];
        let typed = origins.typed_ids().find(|id| needing_a_port.contains(id));
        return match typed {
            Some(id) => Err(format!(
                "--{} needs --secondary-port: the other path to the device",
                id.replace('_', "-")
            )),
            None => Ok(()),
        };
    };
    if primary.port.as_deref() == Some(port.as_str()) {
        return Err(format!(
            "--secondary-port {port} is the --port: give the other path to the device"
        ));
    }
    let mut kinds: Vec<std::mem::Discriminant<_>> = Vec::new();
    for condition in &r.switch_on {
        let kind = std::mem::discriminant(condition);
        if kinds.contains(&kind) && !matches!(condition, SwitchCondition::Exception(_)) {
            return Err(
                "--switch-on: give each condition once (timeout:3, not timeout:3,timeout:5)".into(),
            );
        }
        kinds.push(kind);
    }
    // A framing given for a serial primary is no framing for a tcp:// secondary.
    let tcp = matches!(
        Endpoint::parse(&port),
        Ok(Endpoint::Tcp { .. } | Endpoint::Tls { .. })
    );
    let mode = match r.secondary_mode {
        Some(mode) => Some(Mode::from(mode)),
        None if tcp => None,
        None => primary.mode,
    };
    let secondary = ConnectionSettings {
        port: Some(port),
        mode,
        bauds: vec![r.secondary_baud.unwrap_or_else(|| primary.baud())],
        parities: vec![r.secondary_parity.unwrap_or_else(|| primary.parity())],
        data_bits: r.secondary_data_bits.or(primary.data_bits),
        stop_bits: r.secondary_stop_bits.or(primary.stop_bits),
        secondary: None,
        // Checked once against both paths, with the primary's options.
        direction_typed: false,
        ..primary.clone()
    };
    primary.secondary = Some(Box::new(secondary));
    let defaults = SwitchRule::default();
    primary.switch = SwitchRule {
        conditions: match r.switch_on.is_empty() {
            true => defaults.conditions,
            false => r.switch_on.clone(),
        },
        when: r.switch_when.unwrap_or_default(),
    };
    Ok(())
}

/// `--rs485` or `--rts-toggle` with their timing, and whether one of them was typed. What
/// is typed wins over the environment; the timing options typed alone are refused, as
/// they would do nothing.
fn direction(c: &Rs485Args, origins: &Origins) -> Result<(DirectionControl, bool), String> {
    let typed = |id: &str| origins.typed(id);
    let (rs485, rts_toggle) = (arg_id!(Rs485Args, rs485), arg_id!(Rs485Args, rts_toggle));
    let (kernel, toggle) = match (c.rs485 && c.rts_toggle, typed(rs485), typed(rts_toggle)) {
        (false, ..) => (c.rs485, c.rts_toggle),
        (true, true, true) => {
            return Err("--rs485 and --rts-toggle: give one (--rs485 for the kernel's RS-485 mode, --rts-toggle where the driver has none)".into())
        }
        (true, true, false) => (true, false),
        (true, false, true) => (false, true),
        (true, false, false) => {
            return Err("MBTOOL_RS485 and MBTOOL_RTS_TOGGLE are both set: unset one".into())
        }
    };
    let timing = RtsTiming {
        before: Duration::from_millis(c.rs485_delay_before.unwrap_or(0)),
        after: Duration::from_millis(c.rs485_delay_after.unwrap_or(0)),
        sending: c.rts_level.unwrap_or_default(),
    };
    let direction = match (kernel, toggle) {
        (true, _) => DirectionControl::Kernel(timing),
        (false, true) => DirectionControl::Toggle(timing),
        (false, false) => {
            let option = [
                arg_id!(Rs485Args, rs485_delay_before),
                arg_id!(Rs485Args, rs485_delay_after),
                arg_id!(Rs485Args, rts_level),
            ]
            .into_iter()
            .find(|id| typed(id));
            if let Some(id) = option {
                let name = id.replace('_', "-");
                return Err(format!(
                    "--{name} times the RS-485 direction: give --rs485 or --rts-toggle with it"
                ));
            }
            DirectionControl::Automatic
        }
    };
    Ok((direction, typed(rs485) || typed(rts_toggle)))
}

fn format_of(format: OutputFormat) -> Format {
    match format {
        OutputFormat::Table => Format::Table,
        OutputFormat::Json => Format::Json,
        OutputFormat::Values => Format::Values,
        OutputFormat::Csv => Format::Csv,
    }
}

/// An `--output` that names no format, where a format is what it takes; for dump, a
/// format's name, which would name a file by mistake.
fn output_problem(taken: &Taken, plant: bool) -> Option<String> {
    if let Some(name) = taken.file {
        return OutputFormat::from_str(name, true).is_ok().then(|| format!(
            "dump writes a data file: -o {name} would name the file '{name}'; give ./{name} if that is meant"
        ));
    }
    let name = taken.format?.output.as_deref()?;
    match (OutputFormat::from_str(name, true), plant) {
        (Ok(OutputFormat::Values), true) => Some(format!(
            "--output {name}: give a format: table, json, csv or influx"
        )),
        (Ok(_), _) => None,
        (Err(_), true) if name == job::INFLUX => None,
        (Err(_), true) => Some(format!(
            "--output {name}: give a format: table, json, csv or influx"
        )),
        (Err(_), false) if name == job::INFLUX => Some(
            "--output influx is poll's (mbtool poll PLANT -o influx): give table, json, values or csv"
                .to_string(),
        ),
        (Err(_), false) => Some(format!(
            "--output {name}: give a format: table, json, values or csv"
        )),
    }
}

/// A list of baud rates or parities typed for a command that takes one, as a one-line
/// message. A list from the environment (MBTOOL_BAUD=9600,19200, set for scans) gives
/// the other commands its first value.
fn sweep_outside_scan(scan: bool, taken: &Taken, origins: &Origins) -> Option<String> {
    let serial = taken.serial?;
    let typed = |id: &str| origins.typed(id);
    let several = match (serial.baud.len(), serial.parity.len()) {
        _ if scan => return None,
        (2.., _) if typed(arg_id!(SerialLineArgs, baud)) => "baud rates",
        (_, 2..) if typed(arg_id!(SerialLineArgs, parity)) => "parities",
        _ => return None,
    };
    Some(format!("only scan sweeps several {several}: give one"))
}

/// The first option typed before the command's name that the command does not take, as
/// a one-line message: `decode does not take --baud (see 'mbtool decode --help')`.
fn untaken_option(origins: &Origins) -> Option<String> {
    origins.untaken.clone()
}

/// Retries when `--retries` is not given: none, but over UDP, where a datagram lost is no
/// fault of the device, two (of the requests that do no more when sent twice: the others
/// are sent once).
fn default_retries(port: Option<&str>) -> u32 {
    match port.map(Endpoint::parse) {
        Some(Ok(Endpoint::Udp { .. } | Endpoint::RtuOverUdp { .. })) => UDP_RETRIES,
        _ => 0,
    }
}

/// Retries over UDP when `--retries` is not given.
pub const UDP_RETRIES: u32 = 2;
