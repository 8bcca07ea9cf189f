//! `serve`: standing in for a slave.

use clap::Args;

use super::options::{left_out::*, more_in_long_help};
use super::options::{FormatArgs, LineArgs, TlsArgs};
use super::taken::holds;

pub(super) const SERVE_ABOUT: &str = "\
Answer as a simulated slave, for testing masters and HMIs before the device arrives.

--port is a serial device or pseudo-terminal (RTU, or ASCII with --mode ascii), or \
tcp://ADDRESS:PORT (Modbus TCP; tcp://:5020 listens on 127.0.0.1, give 0.0.0.0 to listen on \
every interface), or rtu+tcp://ADDRESS:PORT (RTU frames over TCP, as behind a gateway), or \
udp://ADDRESS:PORT (Modbus over UDP, each datagram answered to where it came from) or \
rtu+udp://ADDRESS:PORT (RTU frames in datagrams). Many \
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
300009 = 10, 400108-400110 = 555, 0, 100), and every record of every file, records 1-2 of \
file 4 and 9-10 of file 3 and the FIFO queue at 401247 holding the specification's examples. A data file holds one entry a line, \
REFERENCE[-REFERENCE] = VALUE... [TYPE [ORDER]], and only the addresses it names exist:

  400108 = 555 0 100
  400001 = 3.14 f32
  400020 = \"PUMP 1\" ascii
  400200-400299 = 0
  000020-000023 = on off on on   # a comment
  file 4 record 1 = 3582 32       # records of a file (functions 20, 21)
  fifo 401247 = 440 4740          # a FIFO queue, oldest first (function 24)

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

Every request is logged on stderr, one line each (JSON Lines with --json).

Modbus/TCP Security: --port tls://127.0.0.1:8802 with --cert and --key (this server's) and \
--ca (the CAs that sign the clients' certificates) serves Modbus TCP inside TLS 1.2 or 1.3. \
A client must present a certificate signed by --ca. Its role is read from the certificate \
(extension 1.3.6.1.4.1.50316.802.1) and shown in the log; with --role, what each role may do \
is checked, and a client whose certificate carries no role gets --default-role or is \
refused. read covers functions 01-04 (and 07, 08 queries and counters, 0B, 0C, 11, 14, 18, \
2B when alone); write covers 05, 06, 0F, 10, 16, 17 (and 08 restart or clear, 15 when \
alone).";

// What the clients of a tls:// server may do, by the role their certificates carry. A
// plain comment: a doc comment would become the about of the commands that take these.
#[derive(Clone, Debug, Args)]
pub struct RoleArgs {
    /// Over tls://: what clients of role NAME may do, RULES being read and write, each
    /// alone or with a range (operator=read,write:400001-400100); repeatable. A request
    /// its role does not allow gets exception 01
    #[arg(
        long = "role",
        help_heading = "Roles (tls://)",
        hide_short_help = true,
        value_name = "NAME=RULES"
    )]
    pub roles: Vec<String>,

    /// Over tls://: the role of a client whose certificate carries none [default: such a
    /// client is refused, when --role is given]
    #[arg(
        long,
        help_heading = "Roles (tls://)",
        hide_short_help = true,
        value_name = "NAME"
    )]
    pub default_role: Option<String>,

    /// The role of every client of a plain tcp:// listener, which has no certificate to
    /// claim one: with --role, a plain listener is refused without it
    #[arg(
        long,
        help_heading = "Roles (tls://)",
        hide_short_help = true,
        value_name = "NAME"
    )]
    pub plain_role: Option<String>,
}

#[derive(Clone, Debug, Args)]
#[command(after_help = more_in_long_help(&[&[FAULTS, ROLES, IDENTIFICATION, CONNECTION, RS485, TLS]]))]
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
    #[arg(long, value_name = "DURATION", value_parser = mbtool_core::input::duration::parse_duration, help_heading = "Faults", hide_short_help = true)]
    pub delay: Option<std::time::Duration>,

    /// Leave this share of requests unanswered: 0 to 1, or 5%
    #[arg(long, help_heading = "Faults", hide_short_help = true, value_name = "RATE", value_parser = mbtool_core::slave::faults::parse_rate)]
    pub drop: Option<f64>,

    /// Corrupt this share of answers (a bad checksum; over TCP a wrong function): 0 to 1, or 5%
    #[arg(long, help_heading = "Faults", hide_short_help = true, value_name = "RATE", value_parser = mbtool_core::slave::faults::parse_rate)]
    pub corrupt: Option<f64>,

    /// Answer exception CODE to every request, or to those touching RANGE (CODE@RANGE, as in
    /// 2@400100-400120); repeatable
    #[arg(long, help_heading = "Faults", hide_short_help = true, value_name = "CODE[@RANGE]", value_parser = mbtool_core::slave::faults::InjectedException::parse)]
    pub exception: Vec<mbtool_core::slave::faults::InjectedException>,

    /// Send a few noise bytes (00, FE) before each answer, as a bus being handed over does
    #[arg(long, help_heading = "Faults", hide_short_help = true)]
    pub garbage: bool,

    /// Seed for the random choices of --drop, --corrupt and --garbage, to repeat a run
    #[arg(
        long,
        help_heading = "Faults",
        hide_short_help = true,
        value_name = "N"
    )]
    pub seed: Option<u64>,

    /// No log line per request
    #[arg(short, long)]
    pub quiet: bool,

    #[command(flatten)]
    pub roles: RoleArgs,

    /// Device identification: vendor name
    #[arg(long, help_heading = "Identification", hide_short_help = true, default_value = mbtool_core::slave::DEFAULT_VENDOR)]
    pub vendor: String,

    /// Device identification: product code
    #[arg(
        long,
        help_heading = "Identification",
        hide_short_help = true,
        default_value = "mbtool-sim"
    )]
    pub product_code: String,

    /// Device identification: any object, by name or id (VendorUrl=https://example.com,
    /// ProductName=Pump, 0x80=serial 4711); repeatable
    #[arg(long, help_heading = "Identification", hide_short_help = true, value_name = "NAME=VALUE", value_parser = mbtool_core::slave::parse_object)]
    pub identity: Vec<(u8, Vec<u8>)>,

    #[command(flatten)]
    pub line: LineArgs,
    #[command(flatten)]
    pub format: FormatArgs,
    #[command(flatten)]
    pub tls: TlsArgs,
}

holds!(ServeArgs: line, format, tls);
