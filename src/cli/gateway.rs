//! `gateway`: Modbus TCP clients bridged to a serial line.

use clap::Args;

use super::options::{left_out::*, more_in_long_help};
use super::options::{FormatArgs, MasterArgs, RepeatArgs};
use super::taken::{Before, Options, Taken};

use mbtool_core::gateway::UnitMap;

pub(super) const GATEWAY_ABOUT: &str = "\
Bridge Modbus TCP clients (a SCADA, an HMI, a laptop) to the devices on a serial line, and \
show every transaction as it happens.

--listen is where clients connect: tcp://ADDRESS[:PORT] (port 502 when left out; \
tcp://:1502 listens on 127.0.0.1, give 0.0.0.0 for every interface), or udp://ADDRESS[:PORT] \
for Modbus/UDP clients, each source address a client; repeat it for several addresses or \
ports. --port is the line: a serial device with its settings (-b, --parity, \
--mode rtu|ascii), rtu+tcp://HOST:PORT (a transparent serial server), or tcp://HOST:PORT \
(another Modbus TCP server: a proxy that shows the traffic).

Requests go out one at a time, each client's in the order it sent them, the clients taken \
in turn: a client that pipelines a thousand requests delays another's single request by \
one transaction at most. Each is sent as the master commands send it: the gap between \
frames kept, stale bytes thrown away, the answer checked against the request (slave, \
function, length, CRC), --timeout (0.8 s unless given: a client that waits 1 s, as \
mbpoll does, gets its 0B) and --retries per transaction. After a timeout the line \
is brought back in step before a request that a late answer could pass for (a diagnostic \
echo, 08/00, with a fresh value): a client never gets another request's answer. A request \
that may do more when sent twice (22, 23, 21, a user function) is sent once unless \
--retry-non-idempotent. The client gets its answer with its own transaction id and unit \
id, or an exception from the gateway:

  0B  no good answer within the timeout, after the retries
  0A  the line cannot be used (a USB adapter unplugged): answered at once, while the port \
is opened again every 0.1 s to 5 s, the wait growing
  01  a function code that is no request's (0, 128-255), without touching the line
  03  a known function whose fields break its layout, without touching the line

Unit id 0 is a broadcast on a serial line: a write goes to every slave and its client gets \
no answer, or with --broadcast-reply the answer a slave gives to a write; a read to unit 0 \
gets exception 01, as no slave may answer it. --unit-map 1=17,2=18 sends \
unit 1 to slave 17; other unit ids go to the slave of the same number. A client that sends \
what is not Modbus TCP (no MBAP header, a length of 0 or over 254, a protocol id not 0) is \
closed and counted; one that leaves while its request is on the line does not put the line \
out of step (its answer is read and dropped). Idle clients are handled as serve handles \
them: one silent 60 s is closed, past 64 clients one silent 10 s makes room, one that does \
not read its answers for 5 s is dropped.

Every transaction is a row as it completes: time, client, unit, slave, function, the \
request and answer, response time, tries and outcome (answer, exception, refused, timeout, \
bad-frame, line-down, broadcast): a line on a terminal, JSON Lines or CSV with -o, \
--log FILE appended as --poll writes it, none with --quiet. Clients closed by the gateway \
and the line going down and up are told on stderr. Ctrl-C or SIGTERM ends it with a summary per \
client (the connected ones and the 32 that left last, the others in one row) and per unit \
on stderr (and as JSON lines with -o json), exit status 0. It needs no terminal, so it \
runs as a service.

--listen tls://ADDRESS[:PORT] (port 802 when left out) takes clients over Modbus/TCP \
Security, as serve does: --cert and --key are the gateway's, --ca signs its clients' \
certificates, --role and --default-role decide what each role may do (exception 01 \
otherwise, without touching the line; the row says why), and each row shows the client's \
role. With --role, a tcp:// listener beside it needs --plain-role NAME, the role its \
clients get. At most 32 TLS handshakes are under way (16 from one address): past that \
the one least far along is closed, and refusals are told a line a second. The line \
itself is not tls://.";

#[derive(Clone, Debug, Args)]
#[command(after_help = more_in_long_help(&[&[CONNECTION, RS485, TLS, ROLES]]))]
pub struct GatewayArgs {
    /// Where clients connect: tcp://ADDRESS[:PORT], tls://ADDRESS[:PORT] for
    /// Modbus/TCP Security, or udp://ADDRESS[:PORT]; repeatable
    #[arg(long, value_name = "ENDPOINT")]
    pub listen: Vec<String>,

    /// Unit ids mapped to the slave ids they reach on the line: UNIT=SLAVE,...
    #[arg(long, value_name = "MAP", value_parser = |text: &str| UnitMap::parse(text).map_err(|e| e.to_string()))]
    pub unit_map: Option<UnitMap>,

    /// Answer a broadcast (unit 0) as a slave answers a write, for clients that wait for one
    #[arg(long)]
    pub broadcast_reply: bool,

    /// No row per transaction (stderr still tells the line and the clients)
    #[arg(short, long)]
    pub quiet: bool,

    #[command(flatten)]
    pub roles: super::RoleArgs,

    /// Also append every transaction, with its time, to FILE
    ///
    /// CSV for a .csv name, JSON Lines for any other
    #[arg(long, value_name = "FILE")]
    pub log: Option<std::path::PathBuf>,

    #[command(flatten)]
    pub master: MasterArgs,
    #[command(flatten)]
    pub repeat: RepeatArgs,
    #[command(flatten)]
    pub format: FormatArgs,
}

impl Options for GatewayArgs {
    fn take_before(&mut self, before: &Before) {
        if let Some(log) = before.log() {
            self.log = Some(log.to_path_buf());
        }
        self.master.take_before(before);
        self.repeat.take_before(before);
        self.format.take_before(before);
    }

    fn gather<'a>(&'a self, taken: &mut Taken<'a>) {
        taken.log = self.log.as_deref();
        self.master.gather(taken);
        self.repeat.gather(taken);
        self.format.gather(taken);
    }
}
