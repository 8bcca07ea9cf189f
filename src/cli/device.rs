//! The commands about a whole device or line: scan, watch, info, diag, dump, restore.

use clap::{Args, ValueEnum};

use super::options::{left_out::*, more_in_long_help};
use super::options::{
    ExchangeArgs, FormatArgs, LineArgs, MasterArgs, RedundancyArgs, RetriesArgs, SplitArgs,
    TlsArgs, TraceArgs,
};
use super::requests::{ReadByReferenceArgs, RegisterData};
use super::taken::{holds, Before, Options, Taken};
use super::values::whole;

pub(super) const SCAN_ABOUT: &str = "\
Find the slaves on a line: each id is asked once (--probe read: function 03, one register at \
protocol address 0; --probe id: function 17), with the scan's own timeout (--timeout, 100ms \
by default) and no retries, and each id that answers is asked once more to confirm it. A \
slave is there when it answers with a valid frame, an exception included; exception 0A or \
0B (a gateway's 'no such device') counts as absent; bytes that are no valid answer are \
reported as something that answered, maybe at other settings.

A plain scan tries one serial setting, that of --baud and --parity (19200 baud, even \
parity by default). Given as lists (--baud 9600,19200 --parity none,even), they are swept, \
the most common first (19200 even, 9600 none, 9600 even, 19200 none, then the rest), \
stopping at the first settings where a slave answers, unless --all. A pseudo-terminal \
carries any baud and parity, so there the setting that answered is said to be tried, not \
found. --listen 2s first listens at each setting without sending: \
slaves heard answering another master are reported, and that setting is not probed, so a \
live bus gets no extra traffic.

Over TCP the ids are unit ids; when every id answers the same, the device ignores the \
unit id, and mbtool says so instead of listing them all.

On a terminal a progress bar on stderr shows the ids tried, the slaves found and the time \
left. The results are a table, or JSON Lines (one line per slave), then a summary line on \
stderr. Exit status 0 when a slave was found, 3 when none answered. Ctrl-C, SIGTERM or \
SIGHUP ends the scan before the next id, with the slaves found so far, and exit status \
128 + the signal (130 for Ctrl-C, 143 for SIGTERM).";

pub(super) const SUNSPEC_ABOUT: &str = "\
Read a SunSpec device (an inverter, a meter, a battery): the 'SunS' marker is looked for at \
register 40000, then 50000, then 0 (protocol addresses; --base gives another), the chain of \
models after it is walked to its end marker, and each model is read and shown by the \
definition the SunSpec Alliance publishes: every point with its name, value, unit and \
reference, scale factors applied, enums and bitfields named. A point the device marks as not \
implemented (0xFFFF, 0x8000, NaN, empty text) has no value, never a made-up one; a model \
SunSpec has not published (a vendor's own) is named with its place and length.

The registers are read 125 at a time across the models, so a whole device takes a few \
requests; a device that refuses a read past what its chain has shown is read model by model \
from then on. The number of requests is said at the end.

--map-out FILE writes the points found as a CSV map (scale factors as read now) that read \
--map, watch and poll take: 'mbtool read SLAVE --map FILE' shows the same values. Exit \
status 0 when every model was read; 1 when no base holds the marker, or a model was read in \
part, or the chain was cut short (each told on stderr); 3 when the device does not answer; \
10+N when it refused with exception N.";

pub(super) const DUMP_ABOUT: &str = "\
Read ranges of a device's tables (400001-400200 000001-000064) in as few requests as the \
limits allow (--max-per-request lowers them) and write them as a data file that serve \
--data and restore read: one 'REF = values' line per run of addresses, after a comment saying which slave, when, and through which port. The file goes to \
--output FILE, or to standard output.

A request that the device answers with exception 02 is split in halves, down to single \
addresses, so that every address that exists is dumped; only the holes are left out, and \
they are listed on stderr. So serve --data FILE stands in for the device that was dumped, \
holes included.

The file is written whole or not at all: Ctrl-C or SIGTERM ends the dump with nothing \
written (an older file of that name stays as it was), says how much was read, and exits \
128 + the signal (130 for Ctrl-C, 143 for SIGTERM). The requests go one after another: \
another master writing meanwhile can make the dump a picture of several moments.";

pub(super) const RESTORE_ABOUT: &str = "\
Write every coil and holding register of a data file (as dump writes it, or as serve \
--data reads it) to a device, with the fewest requests (05 or 06 for one value, 15 or 16 \
for a run), then read them back and compare. Entries of discrete inputs and input \
registers are skipped, and said so.

Exit status 0 when every value reads back as written, 4 listing the addresses that differ. \
--dry-run prints the frames it would send and sends nothing.";

pub(super) const WATCH_ABOUT: &str = "\
Fill the terminal with a live view of a range (watch 17 400001 10) or of a register map's \
points (watch 17 --map FILE): every point with its value, minimum, maximum, a trend of its \
recent values, and when it last changed (a changed value is highlighted), with the line's \
statistics (answers, timeouts, bad frames, exceptions, response time). --poll sets the \
interval [default: 1s]; a failed read or a dropped connection is shown and polling goes on.

Keys: q or Esc quits, p pauses, r resets minimum, maximum and trends. The terminal is given \
back as it was on q, Ctrl-C, an error or a crash. When standard output is not a terminal, \
watch refuses: read ... --poll INTERVAL -o csv (and --log FILE) is the logger.";

pub(super) const INFO_ABOUT: &str = "\
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

pub(super) const DIAG_ABOUT: &str = "\
A device's health, from the device itself. Times --count round trips of return query data \
(function 08/00; 5 by default: min, mean, max, and whether every echo came back intact), \
reads the diagnostic counters (08/0B-12: bus messages, bus communication errors, bus \
exception errors, slave messages, slave no response, NAK, busy, character overruns) and the \
exception status (07). A counter the device does not keep is shown as such.

--clear then clears the counters (08/0A), the only thing diag ever changes on a device.

Exit status 3 when the device does not answer.";

#[derive(Clone, Debug, Args)]
#[command(after_help = more_in_long_help(&[&[CONNECTION, RS485, TLS]]))]
pub struct ScanArgs {
    /// The ids to ask: ranges and single ids, as 1-247 (the default) or 1-10,17,200
    ///
    /// With --hosts, 0, 1 and 255 are asked first, then these; a connection where none of
    /// those three gets any answer is taken as silent and asked no more, unless --all
    #[arg(long, value_name = "IDS", value_parser = parse_ids)]
    pub ids: Option<Ids>,
    /// Sweep a network for Modbus TCP devices: 10.0.0.0/24,10.0.1.5-20,plc1
    ///
    /// Addresses, IPv4 networks (/16 to /32), ranges of the last byte or of whole
    /// addresses, and names, comma-separated. Politely: --parallel hosts at once, one
    /// connection to a host at a time, --pause between two requests to it, each connection
    /// closed as soon as its host is asked; per host and port whether it takes a
    /// connection, whether Modbus answers, the unit ids that answer, and their
    /// identification (43/14) and server id (17). Port 802 is asked over TLS (Modbus/TCP
    /// Security) with --cert, --key and --ca. No --port
    #[arg(long, value_name = "HOSTS")]
    pub hosts: Option<String>,
    /// With --hosts: the TCP ports asked on each host [default: 502]
    #[arg(long, value_name = "PORTS", value_delimiter = ',', requires = "hosts", value_parser = whole::<u16>(1, 65535))]
    pub tcp_port: Vec<u16>,
    /// With --hosts: how many hosts are asked at once [default: 16]
    #[arg(long, value_name = "N", requires = "hosts", value_parser = whole::<usize>(1, 256))]
    pub parallel: Option<usize>,
    /// With --hosts: the pause between two requests to one host [default: 20ms]
    #[arg(long, value_name = "DURATION", requires = "hosts", value_parser = mbtool_core::input::duration::parse_duration)]
    pub pause: Option<std::time::Duration>,
    /// What each id is asked: read (03, one register at address 0) or id (17)
    #[arg(long, value_enum, default_value_t = ProbeArg::Read)]
    pub probe: ProbeArg,
    /// Listen this long at each setting before sending anything: slaves heard answering
    /// another master are found without adding traffic
    #[arg(long, value_name = "DURATION", value_parser = mbtool_core::input::duration::parse_duration)]
    pub listen: Option<std::time::Duration>,
    /// Try every setting of the sweep, not only up to the first where a slave answers;
    /// with --hosts, ask every id even where 0, 1 and 255 get no answer
    #[arg(long)]
    pub all: bool,
    #[command(flatten)]
    pub line: LineArgs,
    #[command(flatten)]
    pub exchange: ExchangeArgs,
    #[command(flatten)]
    pub trace: TraceArgs,
    #[command(flatten)]
    pub format: FormatArgs,
    #[command(flatten)]
    pub tls: TlsArgs,
}

holds!(ScanArgs: line, exchange, trace, format, tls);

// watch: a range or a map's points, on a screen of its own. A plain comment: a doc
// comment would become the about of watch.
#[derive(Clone, Debug, Args)]
#[command(after_help = more_in_long_help(&[&[CONNECTION, RS485, TLS, REDUNDANCY, ADDRESSES]]))]
pub struct WatchArgs {
    #[command(flatten)]
    pub read: ReadByReferenceArgs,
    /// How often to read [default: 1s]
    #[arg(long, value_name = "INTERVAL", value_parser = mbtool_core::input::duration::parse_duration)]
    pub poll: Option<std::time::Duration>,
    #[command(flatten)]
    pub line: LineArgs,
    #[command(flatten)]
    pub exchange: ExchangeArgs,
    #[command(flatten)]
    pub retries: RetriesArgs,
    #[command(flatten)]
    pub data: RegisterData,
    #[command(flatten)]
    pub redundancy: RedundancyArgs,
    #[command(flatten)]
    pub tls: TlsArgs,
}

impl Options for WatchArgs {
    fn take_before(&mut self, before: &Before) {
        if let Some(poll) = before.poll() {
            self.poll = Some(poll);
        }
        self.line.take_before(before);
        self.exchange.take_before(before);
        self.retries.take_before(before);
        self.data.take_before(before);
        self.redundancy.take_before(before);
        self.tls.take_before(before);
    }

    fn gather<'a>(&'a self, taken: &mut Taken<'a>) {
        taken.poll = self.poll;
        self.line.gather(taken);
        self.exchange.gather(taken);
        self.retries.gather(taken);
        self.data.gather(taken);
        self.redundancy.gather(taken);
        self.tls.gather(taken);
    }
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
            mbtool_core::input::number::parse_in_range(t.trim(), 0, 255, "id").map(|id| id as u8)
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
#[command(after_help = more_in_long_help(&[&[CONNECTION, RS485, TLS, REDUNDANCY, ADDRESSES]]))]
pub struct DumpArgs {
    /// Slave address: 1-247 on serial lines, unit id 0-255 over TCP
    pub slave: String,
    /// References or ranges of references to read (400001-400200 000001-000064)
    ///
    /// Records of a file are FILE:RECORD or FILE:FIRST-LAST (4:0-99, read with function 20),
    /// written to the data file as `file 4 record 0 = ...` lines, which restore writes back
    #[arg(required = true, value_name = "RANGE")]
    pub ranges: Vec<String>,
    /// The data file to write [default: standard output]
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<String>,
    #[command(flatten)]
    pub master: MasterArgs,
    #[command(flatten)]
    pub split: SplitArgs,
    #[command(flatten)]
    pub redundancy: RedundancyArgs,
}

impl Options for DumpArgs {
    fn take_before(&mut self, before: &Before) {
        if let Some(file) = before.output() {
            self.output = Some(file.to_string());
        }
        self.master.take_before(before);
        self.split.take_before(before);
        self.redundancy.take_before(before);
    }

    fn gather<'a>(&'a self, taken: &mut Taken<'a>) {
        taken.file = self.output.as_deref();
        self.master.gather(taken);
        self.split.gather(taken);
        self.redundancy.gather(taken);
    }
}

#[derive(Clone, Debug, Args)]
#[command(after_help = more_in_long_help(&[&[CONNECTION, RS485, TLS, REDUNDANCY, ADDRESSES]]))]
pub struct RestoreArgs {
    /// Slave address: 1-247, or a unit id over TCP
    pub slave: String,
    /// The data file to write back
    ///
    /// Its coils and holding registers (05/06/15/16), and its file records (21); each read
    /// back after
    pub file: std::path::PathBuf,
    /// Print the frames that would be sent, and send nothing
    #[arg(long)]
    pub dry_run: bool,
    #[command(flatten)]
    pub master: MasterArgs,
    #[command(flatten)]
    pub split: SplitArgs,
    #[command(flatten)]
    pub redundancy: RedundancyArgs,
}

holds!(RestoreArgs: master, split, redundancy);

#[derive(Clone, Debug, Args)]
pub struct InfoArgs {
    /// Slave address: 1-247 on serial lines, unit id 0-255 over TCP
    pub slave: String,
    #[command(flatten)]
    pub master: MasterArgs,
    #[command(flatten)]
    pub format: FormatArgs,
}

holds!(InfoArgs: master, format);

#[derive(Clone, Debug, Args)]
pub struct SunspecArgs {
    /// Slave address: 1-247 on serial lines, unit id 0-255 over TCP
    pub slave: String,
    /// Also write the points found as a map (CSV) that read --map, watch and poll take
    #[arg(long, value_name = "FILE")]
    pub map_out: Option<std::path::PathBuf>,
    /// Look for the SunS marker only at this register (0-based) [default: 40000, 50000, 0]
    #[arg(long, value_name = "ADDRESS", value_parser = whole::<u16>(0, 65534))]
    pub base: Option<u16>,
    #[command(flatten)]
    pub master: MasterArgs,
    #[command(flatten)]
    pub format: FormatArgs,
}

holds!(SunspecArgs: master, format);

#[derive(Clone, Debug, Args)]
pub struct DiagArgs {
    /// Slave address: 1-247 on serial lines, unit id 0-255 over TCP
    pub slave: String,
    /// After reading them, clear the device's counters (08/0A)
    #[arg(long)]
    pub clear: bool,
    /// How many round trips of return query data to time [default: 5]
    #[arg(long = "count", id = "poll_count", value_name = "N", value_parser = super::values::whole::<u64>(1, i128::from(u64::MAX)))]
    pub poll_count: Option<u64>,
    #[command(flatten)]
    pub master: MasterArgs,
    #[command(flatten)]
    pub format: FormatArgs,
}

impl Options for DiagArgs {
    fn take_before(&mut self, before: &Before) {
        if let Some(count) = before.count() {
            self.poll_count = Some(count);
        }
        self.master.take_before(before);
        self.format.take_before(before);
    }

    fn gather<'a>(&'a self, taken: &mut Taken<'a>) {
        taken.count = self.poll_count;
        self.master.gather(taken);
        self.format.gather(taken);
    }
}
