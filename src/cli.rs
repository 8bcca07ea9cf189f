//! The command line, as clap derives it. `--help`, the man pages and the shell completions
//! are all generated from this one definition.

use clap::{Args, Parser, Subcommand, ValueEnum};

use mbtool_core::codec::{Direction, Mode};
use mbtool_core::master::plan::{How, Operation};
use mbtool_core::model::address::Table;
use mbtool_core::model::choice::Choice;
use mbtool_core::model::values::{ByteOrder, ValueType};
use mbtool_core::transport::serial::Parity;

const ABOUT: &str = "Modbus RTU/ASCII/TCP diagnostics: read, write, decode, encode";

const LONG_ABOUT: &str = "\
Modbus RTU/ASCII/TCP diagnostics: read and write a device's coils and registers, decode \
frames pasted from a log or a datasheet, and build frames by hand.

Addresses: a number of exactly 5 or 6 digits whose first digit is the command's table \
(0 coils, 1 discrete inputs, 3 input registers, 4 holding registers) is a 1-based Modicon \
reference: 400108 and 40108 are both holding register address 107. Any other number is the \
0-based protocol address: 107, 0x6B. --pdu-addresses makes every number a protocol address. \
A range such as 400108-400110 may stand for ADDRESS and COUNT.

Numbers may be decimal, 0x hex or 0b binary.";

/// The top of the command line: `mbtool [OPTIONS] <COMMAND> [ARGS]`.
#[derive(Clone, Debug, Parser)]
#[command(
    name = "mbtool",
    version,
    about = ABOUT,
    long_about = LONG_ABOUT,
    propagate_version = true,
    max_term_width = 100
)]
pub struct Cli {
    #[command(flatten)]
    pub connection: ConnectionArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub data: DataArgs,
    #[command(flatten)]
    pub poll: PollArgs,
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Clone, Debug, Args)]
#[command(next_help_heading = "Connection")]
pub struct ConnectionArgs {
    /// Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare
    /// 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim
    #[arg(
        short,
        long,
        global = true,
        env = "MBTOOL_PORT",
        hide_env_values = true,
        value_name = "PORT"
    )]
    pub port: Option<String>,

    /// Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp://
    /// ports; decode detects it]
    #[arg(
        short,
        long,
        global = true,
        env = "MBTOOL_MODE",
        hide_env_values = true,
        value_enum
    )]
    pub mode: Option<ModeArg>,

    /// Serial speed; scan sweeps a list (9600,19200,38400)
    #[arg(
        short,
        long,
        global = true,
        env = "MBTOOL_BAUD", hide_env_values = true,
        default_value = "19200",
        value_delimiter = ',',
        value_parser = whole::<u32>(50, 12_000_000)
    )]
    pub baud: Vec<u32>,

    /// Serial parity; scan sweeps a list (none,even,odd)
    #[arg(long, global = true, env = "MBTOOL_PARITY", hide_env_values = true, value_delimiter = ',', value_parser = choice::<Parity>(), default_value = Parity::Even.name())]
    pub parity: Vec<Parity>,

    /// Serial data bits [default: 8, 7 in ASCII mode]
    #[arg(long, global = true, env = "MBTOOL_DATA_BITS", hide_env_values = true, value_parser = whole::<u8>(7, 8))]
    pub data_bits: Option<u8>,

    /// Serial stop bits [default: 1 with parity, 2 without]
    #[arg(long, global = true, env = "MBTOOL_STOP_BITS", hide_env_values = true, value_parser = whole::<u8>(1, 2))]
    pub stop_bits: Option<u8>,

    /// Response timeout for a whole answer: 500ms, 1s, 2.5s [default: 1s; 100ms for scan]
    #[arg(long, global = true, env = "MBTOOL_TIMEOUT", hide_env_values = true, value_parser = positive_duration)]
    pub timeout: Option<std::time::Duration>,

    /// Retries after a timeout or a bad answer (never after an exception)
    #[arg(long, global = true, env = "MBTOOL_RETRIES", hide_env_values = true, default_value_t = 0, value_name = "N", allow_negative_numbers = true, value_parser = whole::<u32>(0, 100))]
    pub retries: u32,

    /// Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200
    /// baud]; 0 for gateways and devices that need none
    #[arg(long, global = true, value_name = "DURATION", value_parser = mbtool_core::model::duration::parse_duration)]
    pub frame_gap: Option<std::time::Duration>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ModeArg {
    Rtu,
    Ascii,
    Tcp,
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

#[derive(Clone, Debug, Args)]
#[command(next_help_heading = "Output")]
pub struct OutputArgs {
    /// Output format [default: table]; for dump, the file to write
    #[arg(short, long, global = true, value_name = "FORMAT", value_parser = FormatOrFile)]
    pub output: Option<String>,

    /// The same as --output json
    #[arg(long, global = true)]
    pub json: bool,

    /// Print every frame sent and received, in hex with a timestamp, on stderr
    #[arg(short, long, global = true)]
    pub verbose: bool,
}

/// The value of `--output`: a format (listed in help and completions), or, for dump,
/// a file; which it must be is checked once the command is known.
#[derive(Clone)]
struct FormatOrFile;

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
        Some(Box::new(
            OutputFormat::value_variants()
                .iter()
                .filter_map(ValueEnum::to_possible_value),
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

#[derive(Clone, Debug, Args)]
#[command(next_help_heading = "Addresses and values")]
pub struct DataArgs {
    /// Take every address as a 0-based protocol address, never as a Modicon reference
    #[arg(long, global = true)]
    pub pdu_addresses: bool,

    /// Register value type, for showing values read and for converting values to write
    #[arg(short = 't', long = "type", global = true, value_name = "TYPE", value_parser = choice::<ValueType>(), default_value = ValueType::default().name())]
    pub value_type: ValueType,

    /// Byte order of values wider than 16 bits: A is the most significant byte
    #[arg(long, global = true, value_parser = choice::<ByteOrder>(), default_value = ByteOrder::default().name())]
    pub order: ByteOrder,

    /// Split reads and writes into requests of at most N coils or registers, for devices
    /// that take fewer than the protocol allows
    #[arg(long, global = true, value_name = "N", value_parser = whole::<u16>(1, 2000))]
    pub max_per_request: Option<u16>,
}

#[derive(Clone, Debug, Args)]
#[command(next_help_heading = "Watching")]
pub struct PollArgs {
    /// Repeat a read every INTERVAL (0 for back to back) until Ctrl-C or --count, showing
    /// what changed, with a summary on stderr at the end; a failed read is a row of its
    /// own, and a connection that drops is opened again
    #[arg(long, global = true, value_name = "INTERVAL", value_parser = mbtool_core::model::duration::parse_duration)]
    pub poll: Option<std::time::Duration>,

    /// With --poll: stop after N reads
    #[arg(
        long = "count",
        id = "poll_count",
        global = true,
        value_name = "N",
        value_parser = whole::<u64>(1, i128::from(u64::MAX))
    )]
    pub count: Option<u64>,

    /// With --poll: also append every row, with its time, to FILE: CSV for a .csv name,
    /// JSON Lines for any other
    #[arg(long, global = true, value_name = "FILE")]
    pub log: Option<std::path::PathBuf>,
}

#[derive(Clone, Debug, Subcommand)]
pub enum Command {
    #[command(flatten)]
    Request(RequestCommand),

    /// Find the slaves on a line and the settings they use
    #[command(long_about = SCAN_ABOUT)]
    Scan(ScanArgs),

    /// Watch values live, full screen: min, max, trend, changes
    #[command(long_about = WATCH_ABOUT)]
    Watch(ReadByReferenceArgs),

    /// Ask a device who it is: identification and server id
    #[command(long_about = INFO_ABOUT)]
    Info(InfoArgs),

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
    #[command(long_about = ENCODE_ABOUT)]
    Encode {
        #[command(subcommand)]
        request: RequestCommand,
    },

    /// Watch a bus without transmitting; frames decoded, paired
    #[command(long_about = SNIFF_ABOUT)]
    Sniff(SniffArgs),

    /// Stand in for a slave on a serial line or TCP
    #[command(long_about = SERVE_ABOUT)]
    Serve(ServeArgs),

    /// Write the shell completions and man pages (for packagers and the project's own tree)
    #[command(hide = true)]
    Generate(GenerateArgs),
}

const SCAN_ABOUT: &str = "\
Find the slaves on a line: each id is asked once (--probe read: function 03, one register at \
protocol address 0; --probe id: function 17), with the scan's own timeout (--timeout, 100ms \
by default) and no retries, and each id that answers is asked once more to confirm it. A \
slave is there when it answers with a valid frame, an exception included; exception 0A or \
0B (a gateway's 'no such device') counts as absent; bytes that are no valid answer are \
reported as something that answered, maybe at other settings.

--baud and --parity lists sweep the serial settings, the most common first (19200 even, \
9600 none, 9600 even, 19200 none, then the rest), and stop at the first settings where a \
slave answers, unless --all. --listen 2s first listens at each setting without sending: \
slaves heard answering another master are reported, and that setting is not probed, so a \
live bus gets no extra traffic.

Over TCP the ids are unit ids; when every id answers the same, the device ignores the \
unit id, and mbtool says so instead of listing them all.

On a terminal a progress bar on stderr shows the ids tried, the slaves found and the time \
left. The results are a table, or JSON Lines (one line per slave), then a summary line on \
stderr. Exit status 0 when a slave was found, 3 when none answered.";

const DUMP_ABOUT: &str = "\
Read ranges of a device's tables (400001-400200 000001-000064) in as few requests as the \
limits allow (--max-per-request lowers them) and write them as a data file that serve \
--data and restore read: one 'REF = values' line per run of addresses, after a comment saying which slave, when, and through which port. The file goes to \
--output FILE, or to standard output.

A request that the device answers with exception 02 is split in halves, down to single \
addresses, so that every address that exists is dumped; only the holes are left out, and \
they are listed on stderr. So serve --data FILE stands in for the device that was dumped, \
holes included.";

const RESTORE_ABOUT: &str = "\
Write every coil and holding register of a data file (as dump writes it, or as serve \
--data reads it) to a device, with the fewest requests (05 or 06 for one value, 15 or 16 \
for a run), then read them back and compare. Entries of discrete inputs and input \
registers are skipped, and said so.

Exit status 0 when every value reads back as written, 4 listing the addresses that differ. \
--dry-run prints the frames it would send and sends nothing.";

const WATCH_ABOUT: &str = "\
Fill the terminal with a live view of a range (watch 17 400001 10) or of a register map's \
points (watch 17 --map FILE): every point with its value, minimum, maximum, a trend of its \
recent values, and when it last changed (a changed value is highlighted), with the line's \
statistics (answers, timeouts, bad frames, exceptions, response time). --poll sets the \
interval [default: 1s]; a failed read or a dropped connection is shown and polling goes on.

Keys: q or Esc quits, p pauses, r resets minimum, maximum and trends. The terminal is given \
back as it was on q, Ctrl-C, an error or a crash. When standard output is not a terminal, \
watch refuses: read ... --poll INTERVAL -o csv (and --log FILE) is the logger.";

const INFO_ABOUT: &str = "\
Ask a device who it is. Read device identification (function 43/14) at the basic level, \
then at the regular or extended level when the device says it has one, following 'more \
follows' across as many requests as the objects need; and report server id (function 17): \
the id byte, the run status, and the rest as text where printable, else hex. Objects are \
shown by name (VendorName, ProductCode, MajorMinorRevision, VendorUrl, ProductName, \
ModelName, UserApplicationName), private ones by number (0x80). Text from the device is \
escaped, never printed raw.

A function the device does not have is shown as such, and is no failure as long as the \
other answered. Exit status 3 when neither answered in time; 10+N when the device refused \
both with exception N.";

const DIAG_ABOUT: &str = "\
A device's health, from the device itself. Times --count round trips of return query data \
(function 08/00; 5 by default: min, mean, max, and whether every echo came back intact), \
reads the diagnostic counters (08/0B-12: bus messages, bus communication errors, bus \
exception errors, slave messages, slave no response, NAK, busy, character overruns) and the \
exception status (07). A counter the device does not keep is shown as such.

--clear then clears the counters (08/0A), the only thing diag ever changes on a device.

Exit status 3 when the device does not answer.";

const DECODE_ABOUT: &str = "\
Decode Modbus frames given as arguments, or one per line on standard input.

A frame may be hex bytes in any common spelling (11 03 00 6B 00 03 76 87, 1103006B00037687, \
0x11,0x03,..., 11:03:00:6B as Wireshark copies it, 11-03-00-6B, [11][03]... as libmodbus \
prints it, {0x11, 0x03, ...} from C source), an ASCII frame as text (:1103006B00037E), or \
the hex of an ASCII frame's bytes (3A 31 31 ...).

Lines from logs are read as they are: the frame is the longest run of hex bytes on the line, \
and what stands around it (a time stamp, words such as CRC ok, a # comment) is set aside. A \
direction mark before it (> or TX for a request, < or RX for a response, as in mbtool's own \
-v trace) settles which way it went. A line that starts with # is a comment. Frames glued \
together on one line are split as sniff splits them.

The framing (RTU, ASCII, TCP) is detected unless --mode says; request or response is \
inferred from the bytes, and a frame that reads both ways says so (--direction settles it).

Exit status 4 when any frame fails its checksum or is malformed; 2 when a line is not hex \
(which outranks 4).";

const ENCODE_ABOUT: &str = "\
Print the frame that a request command would send, as spaced upper-case hex (RTU or TCP) or \
as an ASCII line (--mode ascii). A command that needs several requests prints one frame per \
line. --port tcp://... or --mode tcp prints the MBAP frame, transaction ids counting from 1.";

const SNIFF_ABOUT: &str = "\
Watch a bus without ever transmitting: every frame as it passes, with its time, the silence \
before it, slave, function, request or answer, what it says, and its checksum; answers are \
paired with their requests (400108 = 555), requests that get no answer are shown as such, \
and bytes that are no frame are counted as noise. A summary ends the capture (Ctrl-C, or \
the end of --input).

Frames are found by what the bytes say (each frame's length follows from its function code \
and byte count, and its CRC must hold), so bytes glued together by a USB adapter are split \
all the same, and noise or a cut frame never costs the frame after it. Since random bytes \
pass a CRC once in 65,536 tries, a frame found right after noise, or of a function whose \
layout is not known (user-defined 65-72 and 100-110), is only taken when what follows \
supports it: 3.5 characters of silence on a live line, a frame right after it, the end of \
the input, or, for a request, its answer. A frame whose CRC fails is shown as a CRC error \
where the conversation expects a frame (a request in turn, the answer a request awaits); \
elsewhere its bytes are noise. A long run of noise is counted, and only its first 64 bytes \
kept. When bytes arrive in bursts the gaps between frames are not real: mbtool says so once. \
The fix is the adapter's latency timer: \
echo 1 | sudo tee /sys/bus/usb-serial/devices/ttyUSB0/latency_timer, or --low-latency.

--save FILE keeps every byte as received; live, the times the bytes came go to FILE.timing \
beside it (one line per read: '<us> <count>', or '<us> idle' when the line went quiet), and \
--input FILE reads them back when they are there, so that a replay finds the frames the live \
session found.

--pcap writes the frames for Wireshark with link type DLT_USER0 (147). Once, in Wireshark: \
Preferences > Protocols > DLT_USER > Edit, add DLT 147 with payload protocol mbrtu.";

const SERVE_ABOUT: &str = "\
Answer as a simulated slave, for testing masters and HMIs before the device arrives.

--port is a serial device or pseudo-terminal (RTU, or ASCII with --mode ascii), or \
tcp://ADDRESS:PORT (Modbus TCP; tcp://:5020 listens on 127.0.0.1, give 0.0.0.0 to listen on \
every interface), or rtu+tcp://ADDRESS:PORT (RTU frames over TCP, as behind a gateway). Many \
TCP clients are served at once; one that sends what is not Modbus, or nothing for 60 s, or \
does not read its answers for 5 s, is dropped without holding up the others. Past 64 \
connections a new client takes the place of the one silent the longest, if it has been \
silent for 10 s; a busy client is never closed. Requests are framed by \
the MBAP length however the client's bytes are split or delayed, and several in one segment \
are answered in order. On a serial line the slave finds its requests among other slaves' \
traffic, noise and cut frames, as sniff does; an ASCII sender may pause up to a second \
between characters.

Without --data every address of the four tables exists, holding the example values of the \
Modbus manuals (coils 000020-000056 = CD 6B B2 0E 1B, inputs 100197-100218 = AC DB 35, \
300009 = 10, 400108-400110 = 555, 0, 100). A data file holds one entry a line, \
REFERENCE[-REFERENCE] = VALUE... [TYPE [ORDER]], and only the addresses it names exist:

  400108 = 555 0 100
  400001 = 3.14 f32
  400020 = \"PUMP 1\" ascii
  400200-400299 = 0
  000020-000023 = on off on on   # a comment

A range takes one value for each address or one value for all, and each address is named \
once; anything else is refused with the file's line.

The slave answers exception 01 to a function it does not know, 02 for addresses that do not \
exist or are --read-only, 03 for a bad quantity; it is silent for other slave ids and does \
not answer broadcasts, which it carries out. Over TCP, unit ids 0 and 255 address the first \
--slave, and other unit ids get exception 0B, as from a gateway.

It tells who it is as a device does: device identification (43/14; --vendor, \
--product-code and any object with --identity, streamed over as many answers as they \
need) and report server id (17). Its diagnostic counters (08) count what it saw on the \
line, CRC errors included, and 08/0A clears them.

Every request is logged on stderr, one line each (JSON Lines with --json).";

/// The commands that send requests; `encode` takes the same ones.
#[derive(Clone, Debug, Subcommand)]
pub enum RequestCommand {
    /// Read coils (function 01)
    ReadCoils(ReadArgs),
    /// Read discrete inputs (function 02)
    #[command(visible_alias = "read-discrete-inputs")]
    ReadInputs(ReadArgs),
    /// Read holding registers (function 03)
    #[command(visible_alias = "read-holding-registers")]
    ReadHolding(ReadArgs),
    /// Read input registers (function 04)
    #[command(visible_alias = "read-input-regs")]
    ReadInputRegisters(ReadArgs),
    /// Read by reference: its first digit picks the table
    Read(ReadByReferenceArgs),
    /// Write one coil (function 05)
    WriteCoil(WriteCoilArgs),
    /// Write coils (function 15)
    WriteCoils(WriteArgs),
    /// Write one holding register (function 06)
    WriteRegister(WriteRegisterArgs),
    /// Write holding registers (function 16)
    WriteRegisters(WriteArgs),
    /// Write by reference: 05/06 for one value, 15/16 for more
    Write(WriteByReferenceArgs),
    /// Send any PDU and decode the answer
    Raw(RawArgs),
}

impl RequestCommand {
    /// The operation the command asks of the core's planner, its words as typed.
    pub fn operation(&self) -> Operation<'_> {
        use RequestCommand as C;
        fn read(a: &ReadArgs, table: Option<Table>) -> Operation<'_> {
            Operation::Read {
                slave: &a.slave,
                address: &a.address,
                table,
                count: a.count.as_deref(),
            }
        }
        match self {
            C::ReadCoils(a) => read(a, Some(Table::Coils)),
            C::ReadInputs(a) => read(a, Some(Table::DiscreteInputs)),
            C::ReadHolding(a) => read(a, Some(Table::HoldingRegisters)),
            C::ReadInputRegisters(a) => read(a, Some(Table::InputRegisters)),
            C::Read(a) => Operation::Read {
                slave: &a.slave,
                address: a.reference.as_deref().unwrap_or_default(),
                table: None,
                count: a.count.as_deref(),
            },
            C::WriteCoil(a) => Operation::Write {
                slave: &a.slave,
                address: &a.address,
                table: Some(Table::Coils),
                values: std::slice::from_ref(&a.value),
                how: How::Single,
            },
            C::WriteRegister(a) => Operation::Write {
                slave: &a.slave,
                address: &a.address,
                table: Some(Table::HoldingRegisters),
                values: std::slice::from_ref(&a.value),
                how: How::OneRegister,
            },
            C::WriteCoils(a) | C::WriteRegisters(a) => Operation::Write {
                slave: &a.slave,
                address: &a.address,
                table: Some(if matches!(self, C::WriteCoils(_)) {
                    Table::Coils
                } else {
                    Table::HoldingRegisters
                }),
                values: &a.values,
                how: How::Multiple,
            },
            C::Write(a) => Operation::Write {
                slave: &a.slave,
                address: a.reference.as_deref().unwrap_or_default(),
                table: None,
                values: &a.values,
                how: How::Function(a.function.as_deref().and_then(|f| f.parse().ok())),
            },
            C::Raw(a) => Operation::Raw {
                slave: &a.slave,
                pdu: &a.pdu,
            },
        }
    }
}

#[derive(Clone, Debug, Args)]
pub struct ReadArgs {
    /// Slave address: 1-247 on serial lines, unit id 0-255 over TCP
    pub slave: String,
    /// First holding register (400108, 107, 0x6B), an inclusive range (400108-400110), or
    /// a bit of a register (400108.05), COUNT then counting bits
    pub address: String,
    /// How many registers to read [default: 1]; with --type wider than 16 bits, values of
    /// that type
    pub count: Option<String>,
}

#[derive(Clone, Debug, Args)]
pub struct WriteCoilArgs {
    /// Slave address: 1-247, or 0 to broadcast
    pub slave: String,
    /// Coil address (000020, 19)
    pub address: String,
    /// on, off, 1, 0, true or false
    pub value: String,
}

#[derive(Clone, Debug, Args)]
pub struct WriteRegisterArgs {
    /// Slave address: 1-247, or 0 to broadcast
    pub slave: String,
    /// Register address (400002, 1)
    pub address: String,
    /// The value, converted by --type
    #[arg(allow_negative_numbers = true)]
    pub value: String,
}

#[derive(Clone, Debug, Args)]
pub struct WriteArgs {
    /// Slave address: 1-247, or 0 to broadcast
    pub slave: String,
    /// First holding register (400002, 1), or a range that holds exactly the values given
    pub address: String,
    /// The values: registers each converted by --type; coils each 0/1/on/off, or one bit
    /// string such as 10110
    #[arg(required = true, allow_negative_numbers = true)]
    pub values: Vec<String>,
}

#[derive(Clone, Debug, Args)]
pub struct ReadByReferenceArgs {
    /// Slave address: 1-247 on serial lines, unit id 0-255 over TCP
    pub slave: String,
    /// A reference whose first digit picks the table (000020 coils, 100197 discrete
    /// inputs, 300009 input registers, 400108 holding registers), an inclusive range
    /// (400108-400110), or a bit of a register (400108.05), COUNT then counting bits;
    /// with --map, a point's name
    #[arg(required_unless_present = "map", value_name = "REFERENCE")]
    pub reference: Option<String>,
    /// How many values to read [default: 1]; for registers with --type wider than 16
    /// bits, values of that type; with --map, a point's name
    pub count: Option<String>,
    /// With --map: more points' names [default: every point of the map]
    #[arg(value_name = "NAME")]
    pub names: Vec<String>,
    /// Read the points of a register map (CSV, or Home Assistant YAML), by name
    #[arg(long, value_name = "FILE")]
    pub map: Option<std::path::PathBuf>,
}

impl ReadByReferenceArgs {
    /// The names of the points to read by map: every word after SLAVE.
    pub fn point_names(&self) -> Vec<&str> {
        self.reference
            .iter()
            .chain(&self.count)
            .chain(&self.names)
            .map(String::as_str)
            .collect()
    }
}

#[derive(Clone, Debug, Args)]
pub struct WriteByReferenceArgs {
    /// Slave address: 1-247, or 0 to broadcast
    pub slave: String,
    /// A coil (000020) or holding register (400001) reference, a range that holds exactly
    /// the values given, or a bit of a holding register (400001.03), set alone with
    /// function 22; with --map, NAME=VALUE
    #[arg(required_unless_present = "map", value_name = "REFERENCE")]
    pub reference: Option<String>,
    /// The values: registers each converted by --type; coils each 0/1/on/off, or one bit
    /// string such as 10110; with --map, more NAME=VALUE
    #[arg(required_unless_present = "map", allow_negative_numbers = true)]
    pub values: Vec<String>,
    /// Write points of a register map by name: NAME=VALUE, scale and offset taken back out
    #[arg(long, value_name = "FILE")]
    pub map: Option<std::path::PathBuf>,
    /// Force the function: 5 or 15 for coils, 6 or 16 for registers
    #[arg(long, value_name = "CODE", value_parser = ["5", "6", "15", "16"])]
    pub function: Option<String>,
}

impl WriteByReferenceArgs {
    /// The NAME=VALUE words of a write by map.
    pub fn assignments(&self) -> Vec<&str> {
        self.reference
            .iter()
            .chain(&self.values)
            .map(String::as_str)
            .collect()
    }
}

#[derive(Clone, Debug, Args)]
pub struct RawArgs {
    /// Slave address: 1-247, or 0 to broadcast
    pub slave: String,
    /// The PDU in hex, function code first (03 00 6B 00 03)
    #[arg(required = true, num_args = 1.., value_name = "PDU_HEX")]
    pub pdu: Vec<String>,
}

#[derive(Clone, Debug, Args)]
pub struct ScanArgs {
    /// The ids to ask: ranges and single ids, as 1-247 (the default) or 1-10,17,200
    #[arg(long, value_name = "IDS", default_value = "1-247", value_parser = parse_ids)]
    pub ids: Ids,
    /// What each id is asked: read (03, one register at address 0) or id (17)
    #[arg(long, value_enum, default_value_t = ProbeArg::Read)]
    pub probe: ProbeArg,
    /// Listen this long at each setting before sending anything: slaves heard answering
    /// another master are found without adding traffic
    #[arg(long, value_name = "DURATION", value_parser = mbtool_core::model::duration::parse_duration)]
    pub listen: Option<std::time::Duration>,
    /// Try every setting of the sweep, not only up to the first where a slave answers
    #[arg(long)]
    pub all: bool,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ProbeArg {
    /// Read one holding register at protocol address 0 (function 03)
    Read,
    /// Report server id (function 17)
    Id,
}

/// The ids a scan asks, in order, each once.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Ids(pub Vec<u8>);

/// `1-247`, `1-10,17,200`: the ids in the order given, each once.
fn parse_ids(text: &str) -> Result<Ids, String> {
    let mut ids = Vec::new();
    for part in text.split(',').map(str::trim) {
        let (first, last) = part.split_once('-').unwrap_or((part, part));
        let id = |t: &str| {
            mbtool_core::model::number::parse_in_range(t.trim(), 0, 255, "id").map(|id| id as u8)
        };
        let (first, last) = (id(first)?, id(last)?);
        if first > last {
            return Err(format!("{part}: the first id of a range comes first"));
        }
        for id in first..=last {
            if !ids.contains(&id) {
                ids.push(id);
            }
        }
    }
    Ok(Ids(ids))
}

#[derive(Clone, Debug, Args)]
pub struct DumpArgs {
    /// Slave address: 1-247 on serial lines, unit id 0-255 over TCP
    pub slave: String,
    /// References or ranges of references to read (400001-400200 000001-000064)
    #[arg(required = true, value_name = "RANGE")]
    pub ranges: Vec<String>,
}

#[derive(Clone, Debug, Args)]
pub struct RestoreArgs {
    /// Slave address: 1-247, or a unit id over TCP
    pub slave: String,
    /// The data file to write back
    pub file: std::path::PathBuf,
    /// Print the frames that would be sent, and send nothing
    #[arg(long)]
    pub dry_run: bool,
}

#[derive(Clone, Debug, Args)]
pub struct InfoArgs {
    /// Slave address: 1-247 on serial lines, unit id 0-255 over TCP
    pub slave: String,
}

#[derive(Clone, Debug, Args)]
pub struct DiagArgs {
    /// Slave address: 1-247 on serial lines, unit id 0-255 over TCP
    pub slave: String,
    /// After reading them, clear the device's counters (08/0A)
    #[arg(long)]
    pub clear: bool,
}

#[derive(Clone, Debug, Args)]
pub struct DecodeArgs {
    /// Frames to decode; without any, one frame per line of standard input
    pub frames: Vec<String>,
    /// Read every frame as a request or as a response instead of inferring it
    #[arg(long, value_enum)]
    pub direction: Option<DirectionArg>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum DirectionArg {
    Request,
    Response,
}

impl From<DirectionArg> for Direction {
    fn from(direction: DirectionArg) -> Direction {
        match direction {
            DirectionArg::Request => Direction::Request,
            DirectionArg::Response => Direction::Response,
        }
    }
}

#[derive(Clone, Debug, Args)]
pub struct SniffArgs {
    /// Read a raw byte capture instead of the port ('-' for standard input)
    #[arg(long, value_name = "FILE")]
    pub input: Option<std::path::PathBuf>,

    /// Keep every byte seen, exactly as received, to replay it later with --input; live,
    /// their times go to FILE.timing beside it
    #[arg(long, value_name = "FILE")]
    pub save: Option<std::path::PathBuf>,

    /// Also write the frames to a pcap file for Wireshark (link type 147, see above)
    #[arg(long, value_name = "FILE")]
    pub pcap: Option<std::path::PathBuf>,

    /// Show only the frames of this slave; repeatable
    #[arg(long = "slave", value_name = "ID")]
    pub slaves: Vec<u8>,

    /// Show only the frames of this function code (3, 0x10); repeatable
    #[arg(long = "function", value_name = "CODE", value_parser = parse_function)]
    pub functions: Vec<u8>,

    /// Ask the USB serial driver for its lowest latency (the FTDI latency timer to 1 ms), so
    /// that gaps between frames can be seen
    #[arg(long)]
    pub low_latency: bool,
}

fn parse_function(text: &str) -> Result<u8, String> {
    mbtool_core::model::number::parse_in_range(text, 1, 127, "function code").map(|f| f as u8)
}

#[derive(Clone, Debug, Args)]
pub struct ServeArgs {
    /// Answer as this slave id; repeat for several [default: 17]
    #[arg(long = "slave", value_name = "ID", value_parser = clap::value_parser!(u8).range(1..=247))]
    pub slaves: Vec<u8>,

    /// Initial data and the addresses that exist (see above for the format)
    #[arg(long, value_name = "FILE")]
    pub data: Option<std::path::PathBuf>,

    /// Addresses that may not be written (exception 02): a reference or a range; repeatable
    #[arg(long, value_name = "RANGE")]
    pub read_only: Vec<String>,

    /// Wait this long before each answer
    #[arg(long, value_name = "DURATION", value_parser = mbtool_core::model::duration::parse_duration)]
    pub delay: Option<std::time::Duration>,

    /// Leave this share of requests unanswered: 0 to 1, or 5%
    #[arg(long, value_name = "RATE", value_parser = mbtool_core::slave::faults::parse_rate)]
    pub drop: Option<f64>,

    /// Corrupt this share of answers (a bad checksum; over TCP a wrong function): 0 to 1, or 5%
    #[arg(long, value_name = "RATE", value_parser = mbtool_core::slave::faults::parse_rate)]
    pub corrupt: Option<f64>,

    /// Answer exception CODE to every request, or to those touching RANGE (CODE@RANGE, as in
    /// 2@400100-400120); repeatable
    #[arg(long, value_name = "CODE[@RANGE]", value_parser = mbtool_core::slave::faults::InjectedException::parse)]
    pub exception: Vec<mbtool_core::slave::faults::InjectedException>,

    /// Send a few noise bytes (00, FE) before each answer, as a bus being handed over does
    #[arg(long)]
    pub garbage: bool,

    /// Seed for the random choices of --drop, --corrupt and --garbage, to repeat a run
    #[arg(long, value_name = "N")]
    pub seed: Option<u64>,

    /// No log line per request
    #[arg(short, long)]
    pub quiet: bool,

    /// Device identification: vendor name
    #[arg(long, default_value = mbtool_core::slave::DEFAULT_VENDOR)]
    pub vendor: String,

    /// Device identification: product code
    #[arg(long, default_value = "mbtool-sim")]
    pub product_code: String,

    /// Device identification: any object, by name or id (VendorUrl=https://example.com,
    /// ProductName=Pump, 0x80=serial 4711); repeatable
    #[arg(long, value_name = "NAME=VALUE", value_parser = mbtool_core::slave::parse_object)]
    pub identity: Vec<(u8, Vec<u8>)>,
}

#[derive(Clone, Debug, Args)]
pub struct GenerateArgs {
    /// The folder that receives completions/ and man/
    #[arg(long, default_value = ".")]
    pub dir: std::path::PathBuf,
}

/// The parser of a whole number option: any spelling users type (19200, 0x4B00), in
/// `min..=max`, the range said when it is not.
fn whole<T>(min: i128, max: i128) -> impl Fn(&str) -> Result<T, String> + Clone + Send + Sync
where
    T: TryFrom<i128>,
{
    move |text| {
        mbtool_core::model::number::parse_int(text)
            .ok()
            .filter(|value| (min..=max).contains(value))
            .and_then(|value| T::try_from(value).ok())
            .ok_or_else(|| format!("give a whole number from {min} to {max}"))
    }
}

/// A duration that must not be zero: a timeout of 0 would give up before a byte could come.
fn positive_duration(text: &str) -> Result<std::time::Duration, String> {
    match mbtool_core::model::duration::parse_duration(text)? {
        std::time::Duration::ZERO => Err("give a timeout above zero, as 500ms or 1s".into()),
        duration => Ok(duration),
    }
}

/// The parser of a setting the core offers by name: its names, each with its help, are
/// what clap lists in `--help`, the man pages and the completions.
fn choice<T: Choice + Clone + Send + Sync>() -> impl clap::builder::TypedValueParser<Value = T> {
    use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
    PossibleValuesParser::new(T::ALL.iter().map(|choice| {
        let value = PossibleValue::new(choice.name());
        match choice.help() {
            Some(help) => value.help(help),
            None => value,
        }
    }))
    .try_map(|name| T::from_name(&name).ok_or("not one of the possible values"))
}

/// What an argument shared by several commands means in each: (command, argument id,
/// value name, help). The derived definitions above say it for holding registers, and
/// `--count` for polling.
const ARGUMENT_HELP: &[(&str, &str, &str, &str)] = &[
    ("read-coils", "address", "ADDRESS", "First coil (000020, 19) or an inclusive range (000020-000056)"),
    ("read-coils", "count", "COUNT", "How many coils to read [default: 1]"),
    ("read-inputs", "address", "ADDRESS", "First discrete input (100197, 196) or an inclusive range (100197-100218)"),
    ("read-inputs", "count", "COUNT", "How many inputs to read [default: 1]"),
    ("read-input-registers", "address", "ADDRESS", "First input register (300009, 8), an inclusive range (300009-300011), or a bit of a register (300009.00), COUNT then counting bits"),
    ("write-coils", "address", "ADDRESS", "First coil (000020, 19), or a range that holds exactly the values given"),
    ("write-coils", "values", "VALUES", "Each 0/1/on/off, or one bit string such as 10110"),
    ("write-registers", "values", "VALUES", "The values, each converted by --type"),
    ("diag", "poll_count", "N", "How many round trips of return query data to time [default: 5]"),
    ("dump", "output", "FILE", "The data file to write [default: standard output]"),
    ("watch", "map", "FILE", "Watch the points of a register map (CSV, or Home Assistant YAML)"),
    ("watch", "poll", "INTERVAL", "How often to read [default: 1s]"),
];

/// A built command's argument `id` of `command` (also under `encode`), described as
/// [`ARGUMENT_HELP`] says.
pub fn with_argument_help(command: clap::Command) -> clap::Command {
    fn describe(sub: clap::Command) -> clap::Command {
        let name = sub.get_name().to_string();
        sub.mut_args(|arg| {
            let entry = ARGUMENT_HELP
                .iter()
                .find(|(command, id, ..)| *command == name && arg.get_id() == *id);
            match entry {
                Some((_, _, value_name, help)) => arg
                    .value_name(*value_name)
                    .help(*help)
                    .help_heading(None::<&str>)
                    // A file is named, not picked from the formats --output lists elsewhere.
                    .hide_possible_values(*value_name == "FILE"),
                None => arg,
            }
        })
    }
    command.mut_subcommands(|sub| describe(sub).mut_subcommands(describe))
}

/// Whether the command at `path` (`["read-holding"]`, `["encode", "write-coil"]`) takes the
/// global option `id`. The options a command does not take are hidden from its help and
/// refused when typed on its command line; a value from the environment is never refused.
pub fn takes_option(path: &[&str], id: &str) -> bool {
    const LINE: &[&str] = &["port", "mode", "baud", "parity", "data_bits", "stop_bits"];
    const MASTER: &[&str] = &["timeout", "retries", "frame_gap", "verbose"];
    const FORMAT: &[&str] = &["output", "json"];
    const ADDRESSES: &[&str] = &["pdu_addresses"];
    const SPLIT: &[&str] = &["max_per_request"];
    const REGISTERS: &[&str] = &["value_type", "order"];
    const POLL: &[&str] = &["poll", "poll_count", "log"];
    let groups: &[&[&str]] = match path {
        ["decode"] => &[&["mode"], FORMAT, REGISTERS],
        ["encode"] => &[&["port", "mode"], FORMAT, ADDRESSES, SPLIT, REGISTERS],
        ["sniff" | "serve"] => &[LINE, FORMAT],
        ["info"] => &[LINE, MASTER, FORMAT],
        // watch draws the screen: no -v trace, no output format.
        ["watch"] => &[
            LINE,
            &["timeout", "retries", "frame_gap", "poll"],
            ADDRESSES,
            SPLIT,
            REGISTERS,
        ],
        // dump's --output is the file it writes.
        ["dump"] => &[LINE, MASTER, SPLIT, &["output"]],
        ["restore"] => &[LINE, MASTER, SPLIT],
        // A scan has no retries: each id that answers is asked once more instead.
        ["scan"] => &[LINE, &["timeout", "frame_gap", "verbose"], FORMAT],
        ["diag"] => &[LINE, MASTER, FORMAT, &["poll_count"]],
        // What the request command takes, less what only matters on the wire.
        ["encode", request] => {
            let wire = [LINE, MASTER, POLL].concat();
            return ["port", "mode"].contains(&id)
                || (takes_option(&[request], id) && !wire.contains(&id));
        }
        ["read-coils" | "read-inputs"] => &[LINE, MASTER, FORMAT, ADDRESSES, SPLIT, POLL],
        ["read-holding" | "read-input-registers" | "read"] => {
            &[LINE, MASTER, FORMAT, ADDRESSES, SPLIT, REGISTERS, POLL]
        }
        ["write-coil"] => &[LINE, MASTER, FORMAT, ADDRESSES],
        ["write-coils"] => &[LINE, MASTER, FORMAT, ADDRESSES, SPLIT],
        ["write-register"] => &[LINE, MASTER, FORMAT, ADDRESSES, REGISTERS],
        ["write-registers" | "write"] => &[LINE, MASTER, FORMAT, ADDRESSES, SPLIT, REGISTERS],
        // raw decodes the answer: --type shows its registers.
        ["raw"] => &[LINE, MASTER, FORMAT, REGISTERS],
        _ => &[],
    };
    groups.iter().any(|group| group.contains(&id))
}
