//! What each command is asked to do, in plain types: its own words and flags, resolved
//! from the clap definition's arguments once. The options a command shares with others
//! (the connection, the output, addresses and values, polling) are in
//! [`Settings`](super::Settings); a command receives both and never sees clap.

use std::path::PathBuf;
use std::time::Duration;

use mbtool_core::codec::Direction;
use mbtool_core::gateway::UnitMap;
use mbtool_core::master::plan::{How, Operation};
use mbtool_core::master::scan::Probe;
use mbtool_core::model::address::{Access, Table};
use mbtool_core::slave::faults::FaultInjection;

use crate::cli::{self, Command, ProbeArg, RequestArgs, RequestCommand, Wire};
use crate::sink::mqtt::MqttSettings;
use mbtool_core::model::layouts::Expected;

/// `-o influx`: the output format `poll` alone has.
pub const INFLUX: &str = "influx";

/// The command to run, with what it alone takes.
#[derive(Clone, Debug)]
pub enum Job {
    /// A read, write or raw request on the bus.
    Request(RequestWords),
    /// The frames a request would send.
    Encode(RequestWords),
    Scan(Scan),
    /// A full screen of values: a read by reference or a map's points.
    Watch(RequestWords),
    Info(Device),
    Sunspec(Sunspec),
    Diag(Diag),
    Dump(Dump),
    Restore(Restore),
    Decode(Decode),
    Sniff(Sniff),
    Serve(Serve),
    Gateway(Gateway),
    Plant(Plant),
    Ports(Ports),
    /// The completions and man pages, written under `dir`.
    Generate {
        dir: PathBuf,
    },
}

/// A request's words: addresses and values as typed, or points of a register map by name.
#[derive(Clone, Debug)]
pub enum RequestWords {
    Typed(TypedWords),
    ByMap(MapWords),
}

/// A request's words as typed, which the core's planner reads.
#[derive(Clone, Debug)]
pub enum TypedWords {
    /// Read `count` values (one when left out) from `address`: of `table`, or of the
    /// table its reference names.
    Read {
        slave: String,
        address: String,
        table: Option<Table>,
        count: Option<String>,
        /// `read --layouts` or `--expect`: every layout of the registers read.
        layouts: Option<Layouts>,
    },
    /// Write `values` from `address`, of `table` or of the table its reference names.
    Write {
        slave: String,
        address: String,
        table: Option<Table>,
        values: Vec<String>,
        how: How,
    },
    /// Read records of files: `FILE:RECORD COUNT` pairs.
    ReadFile { slave: String, groups: Vec<String> },
    /// Write records of a file from `FILE:RECORD`.
    WriteFile {
        slave: String,
        place: String,
        values: Vec<String>,
    },
    /// Change bits of a register: AND and OR masks, or a bit's value.
    MaskWrite {
        slave: String,
        reference: String,
        masks: Vec<String>,
    },
    /// Write registers, then read registers, in one transaction.
    ReadWrite {
        slave: String,
        read: String,
        count: String,
        write: String,
        values: Vec<String>,
    },
    /// Read a FIFO queue.
    ReadFifo { slave: String, reference: String },
    /// Send a PDU typed as hex words.
    Raw { slave: String, pdu: Vec<String> },
}

impl TypedWords {
    /// The operation the core's planner checks and plans.
    pub fn operation(&self) -> Operation<'_> {
        match self {
            TypedWords::Read {
                slave,
                address,
                table,
                count,
                ..
            } => Operation::Read {
                slave,
                address,
                table: *table,
                count: count.as_deref(),
            },
            TypedWords::Write {
                slave,
                address,
                table,
                values,
                how,
            } => Operation::Write {
                slave,
                address,
                table: *table,
                values,
                how: *how,
            },
            TypedWords::ReadFile { slave, groups } => Operation::ReadFile { slave, groups },
            TypedWords::WriteFile {
                slave,
                place,
                values,
            } => Operation::WriteFile {
                slave,
                place,
                values,
            },
            TypedWords::MaskWrite {
                slave,
                reference,
                masks,
            } => Operation::MaskWrite {
                slave,
                reference,
                masks,
            },
            TypedWords::ReadWrite {
                slave,
                read,
                count,
                write,
                values,
            } => Operation::ReadWrite {
                slave,
                read: (read, count),
                write,
                values,
            },
            TypedWords::ReadFifo { slave, reference } => Operation::ReadFifo { slave, reference },
            TypedWords::Raw { slave, pdu } => Operation::Raw { slave, pdu },
        }
    }
}

/// What `read --layouts` and `read --expect` ask of the registers read.
#[derive(Clone, Debug)]
pub enum Layouts {
    /// Every layout from the first register.
    All,
    /// The layouts that give this value, nearest first.
    Expect(Expected),
}

/// `read --map` or `write --map`: a map's points by name.
#[derive(Clone, Debug)]
pub struct MapWords {
    /// The map's file.
    pub file: PathBuf,
    /// The slave typed; left out, the map's own.
    pub slave: Option<String>,
    /// A read's point names (none: every point), or a write's `NAME=VALUE` words.
    pub words: Vec<String>,
    /// [`Access::Read`] or [`Access::WriteOne`].
    pub access: Access,
}

#[derive(Clone, Debug)]
pub struct Scan {
    /// `--hosts`: a network swept instead of a line.
    pub hosts: Option<HostSweep>,
    /// The ids asked, in order, each once.
    pub ids: Vec<u8>,
    pub probe: Probe,
    /// How long to listen at each setting before sending anything.
    pub listen: Option<Duration>,
    /// Every setting of the sweep, not only up to the first where a slave answers.
    pub all: bool,
}

/// `scan --hosts`: the hosts and ports asked, and how politely.
#[derive(Clone, Debug)]
pub struct HostSweep {
    pub hosts: Vec<mbtool_core::input::hosts::Host>,
    pub ports: Vec<u16>,
    /// Hosts asked at once.
    pub parallel: usize,
    /// The pause between two requests to one host.
    pub pause: Duration,
}

/// Hosts a sweep asks at once unless `--parallel` says.
pub const DEFAULT_PARALLEL: usize = 16;
/// The pause between two requests to one host unless `--pause` says.
pub const DEFAULT_PAUSE: Duration = Duration::from_millis(20);

/// A command about one device: `info`.
#[derive(Clone, Debug)]
pub struct Device {
    /// The slave as typed, checked once the framing is known.
    pub slave: String,
}

/// `sunspec`: where the marker is looked for, and where the map goes.
#[derive(Clone, Debug)]
pub struct Sunspec {
    pub slave: String,
    /// The one base to look at; the usual ones when `None`.
    pub base: Option<u16>,
    pub map_out: Option<PathBuf>,
}

#[derive(Clone, Debug)]
pub struct Diag {
    pub slave: String,
    /// Clear the counters (08/0A) after reading them.
    pub clear: bool,
}

#[derive(Clone, Debug)]
pub struct Dump {
    pub slave: String,
    /// The ranges to save, as typed (400001-400100).
    pub ranges: Vec<String>,
}

#[derive(Clone, Debug)]
pub struct Restore {
    pub slave: String,
    /// The data file to write back.
    pub file: PathBuf,
    /// Say what would be written, and write nothing.
    pub dry_run: bool,
}

#[derive(Clone, Debug)]
pub struct Decode {
    /// The frames typed; none: standard input.
    pub frames: Vec<String>,
    /// Whether the frames are requests or responses, when the user says.
    pub direction: Option<Direction>,
}

#[derive(Clone, Debug)]
pub struct Sniff {
    /// A capture to read instead of the port (`-` for standard input).
    pub input: Option<PathBuf>,
    /// A network interface to capture Modbus TCP from.
    pub interface: Option<String>,
    /// The servers' TCP ports, when given.
    pub tcp_ports: Vec<u16>,
    /// Where every byte (or packet) seen is kept.
    pub save: Option<PathBuf>,
    /// Where the frames shown are written as pcap.
    pub pcap: Option<PathBuf>,
    /// Statistics per server and unit at the end.
    pub stats: bool,
    /// The slaves whose frames are shown (all when empty).
    pub slaves: Vec<u8>,
    /// The functions whose frames are shown (all when empty).
    pub functions: Vec<u8>,
    /// Ask the USB serial driver for its lowest latency.
    pub low_latency: bool,
}

/// Who may do what over Modbus/TCP Security.
#[derive(Clone, Debug)]
pub struct RoleSettings {
    /// `NAME=RULES` as typed.
    pub rules: Vec<String>,
    /// The role of a client whose certificate carries none.
    pub default_role: Option<String>,
    /// The role of every client of a plain tcp:// listener.
    pub plain_role: Option<String>,
}

#[derive(Clone, Debug)]
pub struct Serve {
    /// The slave ids answered.
    pub slaves: Vec<u8>,
    /// The data file the tables are loaded from.
    pub data: Option<PathBuf>,
    /// Ranges written to get exception 02.
    pub read_only: Vec<String>,
    pub faults: FaultInjection,
    /// The seed of the faults' chances; left out, one of its own.
    pub seed: Option<u64>,
    /// No line per request.
    pub quiet: bool,
    pub roles: RoleSettings,
    /// The identification objects (43/14) beyond the defaults, vendor and product first.
    pub identity: Vec<(u8, Vec<u8>)>,
}

#[derive(Clone, Debug)]
pub struct Gateway {
    /// Where clients connect, as typed.
    pub listen: Vec<String>,
    pub unit_map: UnitMap,
    /// Answer a broadcast as a slave answers a write.
    pub broadcast_reply: bool,
    /// No row per transaction.
    pub quiet: bool,
    pub roles: RoleSettings,
}

/// `poll`: a plant's devices kept read.
#[derive(Clone, Debug)]
pub struct Plant {
    /// The plant files.
    pub files: Vec<PathBuf>,
    /// How long to poll; left out, until stopped.
    pub duration: Option<Duration>,
    /// Rows as InfluxDB line protocol (`-o influx`).
    pub influx: bool,
    /// An InfluxDB server every row is written to too.
    pub influx_server: Option<crate::sink::influx::InfluxServer>,
    /// Rows kept for a server that is down.
    pub buffer: usize,
    /// Where Prometheus metrics are served: `127.0.0.1:9502`.
    pub metrics: Option<String>,
    /// The MQTT broker every value is published to.
    pub mqtt: Option<MqttSettings>,
    /// Files every row is appended to: CSV for a `.csv` name, JSON Lines else.
    pub logs: Vec<PathBuf>,
}

#[derive(Clone, Debug)]
pub struct Ports {
    /// Where sys, dev and proc are read from.
    pub root: PathBuf,
}

/// The job of a parsed command, or the one line that refuses a command line whose words
/// do not go together.
pub fn of(command: Command) -> Result<Job, String> {
    Ok(match command {
        Command::Request(request) => Job::Request(request_of(request)?),
        Command::Encode { request, .. } => Job::Encode(request_of(request)?),
        Command::Scan(a) => Job::Scan(Scan {
            hosts: match &a.hosts {
                Some(text) => Some(HostSweep {
                    hosts: mbtool_core::input::hosts::parse_hosts(text)?,
                    ports: match a.tcp_port.is_empty() {
                        true => vec![mbtool_core::transport::endpoint::MODBUS_TCP_PORT],
                        false => {
                            // Each port once, in the order given.
                            let mut ports = a.tcp_port.clone();
                            let mut seen = std::collections::HashSet::new();
                            ports.retain(|port| seen.insert(*port));
                            ports
                        }
                    },
                    parallel: a.parallel.unwrap_or(DEFAULT_PARALLEL),
                    pause: a.pause.unwrap_or(DEFAULT_PAUSE),
                }),
                None => None,
            },
            ids: match (&a.hosts, a.ids) {
                // The ids devices answer by default first, then those asked.
                (Some(_), ids) => {
                    let mut all = vec![0, 1, 255];
                    for id in ids.map(|ids| ids.0).unwrap_or_default() {
                        if !all.contains(&id) {
                            all.push(id);
                        }
                    }
                    all
                }
                (None, Some(ids)) => ids.0,
                (None, None) => (1..=247).collect(),
            },
            probe: match a.probe {
                ProbeArg::Read => Probe::Read,
                ProbeArg::Id => Probe::Id,
            },
            listen: a.listen,
            all: a.all,
        }),
        Command::Watch(a) => Job::Watch(read_by_reference(a.read, "watch")?),
        Command::Info(a) => Job::Info(Device { slave: a.slave }),
        Command::Sunspec(a) => Job::Sunspec(Sunspec {
            slave: a.slave,
            base: a.base,
            map_out: a.map_out,
        }),
        Command::Diag(a) => Job::Diag(Diag {
            slave: a.slave,
            clear: a.clear,
        }),
        Command::Dump(a) => Job::Dump(Dump {
            slave: a.slave,
            ranges: a.ranges,
        }),
        Command::Restore(a) => Job::Restore(Restore {
            slave: a.slave,
            file: a.file,
            dry_run: a.dry_run,
        }),
        Command::Decode(a) => Job::Decode(Decode {
            frames: a.frames,
            direction: a.direction.map(Direction::from),
        }),
        Command::Sniff(a) => Job::Sniff(Sniff {
            input: a.input,
            interface: a.interface,
            tcp_ports: a.tcp_ports,
            save: a.save,
            pcap: a.pcap,
            stats: a.stats,
            slaves: a.slaves,
            functions: a.functions,
            low_latency: a.low_latency,
        }),
        Command::Serve(a) => Job::Serve(serve(a)),
        Command::Gateway(a) => Job::Gateway(Gateway {
            listen: a.listen,
            unit_map: a.unit_map.unwrap_or_default(),
            broadcast_reply: a.broadcast_reply,
            quiet: a.quiet,
            roles: roles(a.roles),
        }),
        Command::Poll(a) => {
            let influx_server = match &a.influx {
                Some(url) => Some(crate::sink::influx::server(
                    url,
                    std::env::var("INFLUX_TOKEN").ok(),
                )?),
                None => None,
            };
            let mqtt = match &a.mqtt {
                Some(url) => {
                    let (host, port, tls) = crate::sink::mqtt::parse_url(url)?;
                    if a.mqtt_ca.is_some() && !tls {
                        return Err(format!(
                            "--mqtt-ca is for a broker over TLS: give --mqtt mqtts://{host}:{port}"
                        ));
                    }
                    let prefix = a.mqtt_prefix.trim_end_matches('/');
                    if prefix.is_empty() || prefix.contains(['+', '#']) {
                        return Err(format!(
                            "--mqtt-prefix '{}': give topic levels without + or #, as plant/line1",
                            a.mqtt_prefix
                        ));
                    }
                    let password = std::env::var("MBTOOL_MQTT_PASSWORD").ok();
                    if password.is_some() && a.mqtt_user.is_none() {
                        return Err(
                            "MBTOOL_MQTT_PASSWORD is set without a user: give --mqtt-user USER"
                                .into(),
                        );
                    }
                    Some(MqttSettings {
                        host,
                        port,
                        tls,
                        ca: a.mqtt_ca,
                        prefix: prefix.to_string(),
                        retain: a.mqtt_retain,
                        discovery: a.mqtt_discovery,
                        user: a.mqtt_user,
                        password,
                    })
                }
                None => None,
            };
            Job::Plant(Plant {
                mqtt,
                logs: a.log,
                influx: a.format.output.as_deref() == Some(INFLUX),
                influx_server,
                buffer: a.buffer as usize,
                metrics: a.metrics,
                files: a.files,
                duration: a.duration,
            })
        }
        Command::Ports(a) => Job::Ports(Ports { root: a.root }),
        Command::Generate(a) => Job::Generate { dir: a.dir },
    })
}

fn serve(a: cli::ServeArgs) -> Serve {
    let mut identity = vec![
        (0x00, a.vendor.into_bytes()),
        (0x01, a.product_code.into_bytes()),
    ];
    identity.extend(a.identity);
    Serve {
        slaves: match a.slaves.is_empty() {
            true => vec![mbtool_core::slave::EXAMPLE_SLAVE],
            false => a.slaves,
        },
        data: a.data,
        read_only: a.read_only,
        faults: FaultInjection {
            delay: a.delay.unwrap_or_default(),
            drop: a.drop.unwrap_or(0.0),
            corrupt: a.corrupt.unwrap_or(0.0),
            exceptions: a.exception,
            garbage: a.garbage,
        },
        seed: a.seed,
        quiet: a.quiet,
        roles: roles(a.roles),
        identity,
    }
}

fn roles(a: cli::RoleArgs) -> RoleSettings {
    RoleSettings {
        rules: a.roles,
        default_role: a.default_role,
        plain_role: a.plain_role,
    }
}

fn request_of<W: Wire>(command: RequestCommand<W>) -> Result<RequestWords, String> {
    use RequestCommand as C;
    fn read<T: cli::Words>(a: cli::ReadArgs<T>) -> RequestWords {
        RequestWords::Typed(TypedWords::Read {
            slave: a.slave,
            address: a.address,
            table: Some(T::TABLE),
            count: a.count,
            layouts: None,
        })
    }
    fn write<T: cli::Words>(a: cli::WriteArgs<T>) -> RequestWords {
        RequestWords::Typed(TypedWords::Write {
            slave: a.slave,
            address: a.address,
            table: Some(T::TABLE),
            values: a.values,
            how: How::Multiple,
        })
    }
    Ok(match command {
        C::ReadCoils(RequestArgs { args, .. }) => read(args),
        C::ReadInputs(RequestArgs { args, .. }) => read(args),
        C::ReadHolding(RequestArgs { args, .. }) => read(args),
        C::ReadInputRegisters(RequestArgs { args, .. }) => read(args),
        C::Read(RequestArgs { args, .. }) => {
            let layouts = match (args.layouts, args.expect) {
                (_, Some(expect)) => Some(Layouts::Expect(Expected::parse(&expect)?)),
                (true, None) => Some(Layouts::All),
                (false, None) => None,
            };
            match read_by_reference(args.read, "read")? {
                RequestWords::Typed(TypedWords::Read {
                    slave,
                    address,
                    table,
                    count,
                    ..
                }) => RequestWords::Typed(TypedWords::Read {
                    slave,
                    address,
                    table,
                    count,
                    layouts,
                }),
                words => words,
            }
        }
        C::WriteCoil(RequestArgs { args: a, .. }) => RequestWords::Typed(TypedWords::Write {
            slave: a.slave,
            address: a.address,
            table: Some(Table::Coils),
            values: vec![a.value],
            how: How::Single,
        }),
        C::WriteRegister(RequestArgs { args: a, .. }) => RequestWords::Typed(TypedWords::Write {
            slave: a.slave,
            address: a.address,
            table: Some(Table::HoldingRegisters),
            values: vec![a.value],
            how: How::OneRegister,
        }),
        C::WriteCoils(RequestArgs { args, .. }) => write(args),
        C::WriteRegisters(RequestArgs { args, .. }) => write(args),
        C::Write(RequestArgs { args, .. }) => write_by_reference(args)?,
        C::ReadFile(RequestArgs { args: a, .. }) => RequestWords::Typed(TypedWords::ReadFile {
            slave: a.slave,
            groups: a.groups,
        }),
        C::WriteFile(RequestArgs { args: a, .. }) => RequestWords::Typed(TypedWords::WriteFile {
            slave: a.slave,
            place: a.place,
            values: a.values,
        }),
        C::MaskWrite(RequestArgs { args: a, .. }) => RequestWords::Typed(TypedWords::MaskWrite {
            slave: a.slave,
            reference: a.reference,
            masks: a.masks,
        }),
        C::ReadWrite(RequestArgs { args: a, .. }) => RequestWords::Typed(TypedWords::ReadWrite {
            slave: a.slave,
            read: a.read,
            count: a.count,
            write: a.write,
            values: a.values,
        }),
        C::ReadFifo(RequestArgs { args: a, .. }) => RequestWords::Typed(TypedWords::ReadFifo {
            slave: a.slave,
            reference: a.reference,
        }),
        C::Raw(RequestArgs { args: a, .. }) => RequestWords::Typed(TypedWords::Raw {
            slave: a.slave,
            pdu: a.pdu,
        }),
    })
}

/// `read` or `watch`: a reference, or with `--map` the points named. A first word that is
/// no slave id is a point's name, SLAVE left out.
fn read_by_reference(a: cli::ReadByReferenceArgs, command: &str) -> Result<RequestWords, String> {
    let Some(file) = a.map else {
        if !a.names.is_empty() {
            return Err(match command {
                "watch" => {
                    "watch takes SLAVE REFERENCE [COUNT]; point names come with --map FILE".into()
                }
                _ => format!(
                    "{command} takes SLAVE REFERENCE [COUNT]; '{}' is one word too many (point names come with --map FILE)",
                    a.names.join(" ")
                ),
            });
        }
        return Ok(RequestWords::Typed(TypedWords::Read {
            slave: a.slave.unwrap_or_default(),
            address: a.reference.unwrap_or_default(),
            table: None,
            count: a.count,
            layouts: None,
        }));
    };
    let (slave, first) = split_slave(a.slave);
    let words = first
        .into_iter()
        .chain(a.reference)
        .chain(a.count)
        .chain(a.names)
        .collect();
    Ok(RequestWords::ByMap(MapWords {
        file,
        slave,
        words,
        access: Access::Read,
    }))
}

/// `write`: a reference and values, or with `--map` the `NAME=VALUE` words. A first word
/// that is no slave id is an assignment, SLAVE left out.
fn write_by_reference(a: cli::WriteByReferenceArgs) -> Result<RequestWords, String> {
    let Some(file) = a.map else {
        let reference = a.reference.as_deref().unwrap_or_default();
        if a.values.is_empty() && !reference.contains('=') {
            return Err(format!(
                "write needs VALUES after {reference}, or a bit given its value in place (400108.05=1)"
            ));
        }
        return Ok(RequestWords::Typed(TypedWords::Write {
            slave: a.slave,
            address: a.reference.unwrap_or_default(),
            table: None,
            values: a.values,
            how: How::Function(a.function.as_deref().and_then(|f| f.parse().ok())),
        }));
    };
    if a.function.is_some() {
        return Err(
            "--function chooses how values are written by reference; a map writes each point as its type needs".into(),
        );
    }
    let (slave, first) = split_slave(Some(a.slave));
    let words = first
        .into_iter()
        .chain(a.reference)
        .chain(a.values)
        .collect();
    Ok(RequestWords::ByMap(MapWords {
        file,
        slave,
        words,
        access: Access::WriteOne,
    }))
}

/// The first word of a map command: the slave when it reads as a number, else the first
/// of the other words.
fn split_slave(first: Option<String>) -> (Option<String>, Option<String>) {
    let is_slave = |word: &str| mbtool_core::input::number::parse_int(word).is_ok();
    match first {
        Some(word) if is_slave(&word) => (Some(word), None),
        word => (None, word),
    }
}
