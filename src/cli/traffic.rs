//! The commands about frames and traffic: decode, encode, sniff.

use clap::{Args, ValueEnum};

use mbtool_core::codec::Direction;

use super::options::{FormatArgs, LineArgs, ModeArg, RegisterArgs};
use super::taken::{holds, Before, Options, Taken};

pub(super) const DECODE_ABOUT: &str = "\
Decode Modbus frames given as arguments, or one per line on standard input.

A frame may be hex bytes in any common spelling (11 03 00 6B 00 03 76 87, 1103006B00037687, \
0x11,0x03,..., 11:03:00:6B as Wireshark copies it, 11-03-00-6B, [11][03]... as libmodbus \
prints it, {0x11, 0x03, ...} from C source), an ASCII frame as text (:1103006B00037E), or \
the hex of an ASCII frame's bytes (3A 31 31 ...).

Lines from logs are read as they are: the frame is the longest run of hex bytes on the line, \
and what stands around it (a time stamp, words such as CRC ok, a # comment) is set aside. A \
direction mark before it (> or TX for a request, < or RX for a response, as in mbtool's own \
-v trace) settles which way it went. The traffic logs of Modbus Poll (000000-Tx:01 03 ...), \
QModMaster ([RTU]>Rx > 10:33:38:374 : 01 03 ...), mbpoll -v and libmodbus ([01][03]... sent, \
<01><03>... received) and pymodbus's debug log (SEND: 0x1 0x3 ...) are read with the \
direction they mark; their own messages (Waiting for a confirmation...) are passed over and \
counted. A line that starts with # is a comment. Frames glued together on one line are \
split as sniff splits them. The first line holding a NUL byte (a binary file soon has one) \
or a UTF-16 file ends the run with one message and exit status 2: raw bytes are read by \
sniff --input.

The framing (RTU, ASCII, TCP) is detected unless --mode says; request or response is \
inferred from the bytes, and a frame that reads both ways says so (--direction settles it). \
An answer right after the request it answers is read with that request: its addresses, and \
as many coils or inputs as were asked; alone, a bit answer shows only the bits sure to be \
values (the last byte may end in padding) and max_count.

Exit status 4 when any frame fails its checksum or is malformed; 2 when a line is not hex \
(which outranks 4), or when an argument is empty or the arguments hold only comments. An \
argument of several lines (\"$(cat log.txt)\") is read a line at a time, as standard input \
is. Standard input that holds no frame (empty, blank lines, comments) prints nothing and \
exits 0, as a filter does.";

pub(super) const ENCODE_ABOUT: &str = "\
Print the frame that a request command would send, as spaced upper-case hex (RTU or TCP) or \
as an ASCII line (--mode ascii). A command that needs several requests prints one frame per \
line. --port tcp://... or --mode tcp prints the MBAP frame, transaction ids counting from 1. \
encode opens nothing and sends nothing: --port only chooses the framing (tcp:// gives MBAP, \
any other port, sim or a serial device, RTU unless --mode says otherwise), which is why \
encode takes --port and --mode and no other connection option.";

pub(super) const SNIFF_ABOUT: &str = "\
Watch a bus without ever transmitting: every frame as it passes, with its time, the silence \
before it, slave, function, request or answer, what it says, and its checksum; answers are \
paired with their requests (400108 = 555), an answer that does not fit the request awaiting it \
(another count of values, a write's echo that differs) says how, requests that get no answer are shown as such \
(one still waiting when the capture ends, as having none before the capture ended), \
and bytes that are no frame are counted as noise. A summary ends the capture (Ctrl-C, or \
the end of --input).

Frames are found by what the bytes say (each frame's length follows from its function code \
and byte count, and its CRC must hold), so bytes glued together by a USB adapter are split \
all the same, and noise or a cut frame never costs the frame after it. Since random bytes \
pass a CRC once in 65,536 tries, a frame found right after noise, or of a function whose \
layout is not known (user-defined 65-72 and 100-110), is only taken when what follows \
supports it: 3.5 characters of silence on a live line, a frame right after it, the end of \
the input, or, for a request, its answer. A request whose CRC holds but whose PDU does not \
read (a master's mistake, such as a coil value of 0004) is shown after noise only when its \
slave's exception follows it at once. After noise, a frame from a reserved address \
(248-255) is taken only while a request to that address and function awaits its answer, \
and is then read as a frame from any other address is. A frame whose CRC \
fails is shown as a CRC error where the conversation expects a frame (a request in turn, \
the answer a request awaits), and one whose CRC holds there but whose PDU does not read as \
malformed; elsewhere its bytes are noise. A malformed frame is shown as the request or answer \
it travels as, and what is wrong with it read that way: where its layout is the same both \
ways (a 05 or 06 echo), it is the answer a request of its slave and function awaits, else \
the master's next request; it takes that place in the conversation (as an answer it answers \
the request waiting, as a request it ends the wait of the one before and waits for its own \
answer, the exception a device refuses it with). On a live line (or a replay with its .timing), 3.5 \
characters of silence inside bytes that do not make a whole frame before it end them: they \
are a frame cut short where the conversation expects a frame ([incomplete], counted as a CRC \
error), noise elsewhere, and the frame after the silence starts clean; the answer awaited of \
a user-defined function, whose length only the silence tells, is a CRC error when its CRC \
fails there, and where a shorter reading of it passes its CRC inside a read that could have \
hidden a gap, the reading that ends at the silence seen is taken. This is decided when \
the bytes after the silence come. A USB adapter hands bytes over when its latency timer runs \
out (16 ms by default), so a frame can arrive in two reads a whole period apart that were \
back to back on the wire: where a line's bytes come in bursts (several a read in a quarter or \
more of its latest reads, as an adapter gathers them; a host late now and then does not make \
a line read a byte at a time one read in bursts), a frame whose CRC holds across the gap (of a known layout, or the answer \
awaited where no frame starts after the gap) is taken whole. An adapter's reads end on its \
timer's ticks, so where the frame's two reads are one period apart and the line's latest \
reads sit on that period's grid (each a whole number of periods after the first read of its \
stretch of traffic: all within a thirty-second of a period while the reads are few, three in \
four within a twelfth from 16 reads on), and while such \
frames are more than chance (one in 200 frames or more, the last within 2,000 frames), that \
line's gaps are not taken for silence (a frame cut short is kept until the bytes show it is \
none, as without timing), and on a live line mbtool says so once. A device that pauses inside its frame, \
read where the bytes end, leaves a gap at no period: the line's silences are still believed. A gap longer than 64 ms is more than an adapter makes (reads one latency \
period apart, 32 ms at the longest commonly set, with room for a late read): no frame runs \
across it, however the line is read. Read a byte at a time, a line's gaps are its own: a silence ends a frame \
there as it does for every receiver on the bus, whatever CRC the bytes across it pass (a \
device that pauses inside its frame shows as a frame cut short and the rest). Where the times \
tell silence, a frame of a user-defined function whose CRC is 00 00 runs to the silence, \
though the bytes before the 00 00 pass a CRC too. Bytes a gap \
cuts short, and the frame before them, wait for the bytes \
after the gap. A long run of noise is counted, and only its first 64 bytes \
kept. The fix for gaps that are not real is the adapter's latency timer: \
echo 1 | sudo tee /sys/bus/usb-serial/devices/ttyUSB0/latency_timer, or --low-latency.

--save FILE keeps every byte as received; live, the times the bytes came go to FILE.timing \
beside it (one line per read: '<us> <count>'; '<us> idle' when the line went quiet; '<us> end' \
when the capture ended; and the line itself as '# line: rtu 9600 8N2': mode, speed, data bits, \
parity, stop bits), and --input FILE reads them back when they are there, so that a replay \
finds the frames the live session found. The replay is on the line recorded there, unless an \
option (or its variable) says otherwise (another parity or mode brings its own stop or data \
bits, as on a port), which mbtool then tells on stderr, as it does when the file does not \
record its line and no option gives it. A last line cut off before its end is passed over, \
and said to be.

Modbus TCP: --interface NAME captures live through libpcap (root, or cap_net_raw and \
cap_net_admin), --save FILE keeping the packets as pcapng; --input also reads pcap and \
pcapng files (tcpdump, dumpcap, tshark, Wireshark; \
known by their first bytes, whatever the name): Ethernet with VLAN tags, Linux cooked captures \
(tcpdump -i any), raw IP and loopback. Each connection's two directions are put back in order \
before framing: retransmitted bytes are read once, segments out of order put in order, and \
after a lost segment, or where the capture starts mid-connection, framing picks up at the \
next MBAP header that reads. Port 502 is Modbus unless --tcp-port names others; other \
packets are counted and passed over. Answers are paired with their requests by transaction \
and unit id, with the response time; each line shows the connection, and JSON has client, \
server, transaction, packet (numbered as Wireshark numbers them), and on answers \
request_packet and response_time_us.

--pcap writes the frames shown (--slave and --function filter it too) for Wireshark with \
link type DLT_USER0 (147), a TCP frame as the RTU frame it carries. Once, in Wireshark: Preferences > Protocols > DLT_USER > Edit, add DLT \
147 with payload protocol mbrtu.";

#[derive(Clone, Debug, Args)]
pub struct DecodeArgs {
    /// Frames to decode; without any, one frame per line of standard input
    pub frames: Vec<String>,
    /// Read every frame as a request or as a response instead of inferring it
    #[arg(long, value_enum)]
    pub direction: Option<DirectionArg>,
    /// Framing: rtu, ascii or tcp [default: detected from each frame]
    #[arg(short, long, env = "MBTOOL_MODE", hide_env_values = true, value_enum)]
    pub mode: Option<ModeArg>,
    #[command(flatten)]
    pub format: FormatArgs,
    #[command(flatten)]
    pub registers: RegisterArgs,
}

impl Options for DecodeArgs {
    fn take_before(&mut self, before: &Before) {
        if let Some(mode) = before.mode() {
            self.mode = Some(mode);
        }
        self.format.take_before(before);
        self.registers.take_before(before);
    }

    fn gather<'a>(&'a self, taken: &mut Taken<'a>) {
        taken.mode = self.mode;
        self.format.gather(taken);
        self.registers.gather(taken);
    }
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
    /// Read a capture (pcap, pcapng, a line's raw bytes; - for stdin) instead of the port
    ///
    /// A pcap or pcapng file of Modbus TCP (tcpdump, dumpcap, Wireshark), or the raw bytes of a serial line.
    /// Standard input still open (another program's capture piped in) ends on Ctrl-C or
    /// SIGTERM as a live capture does, its frames and the summary shown. A file of raw bytes
    /// without timing is framed on every core, with the frames found in order
    #[arg(long, value_name = "FILE")]
    pub input: Option<std::path::PathBuf>,

    /// Capture Modbus TCP live from a network interface (eth0, lo)
    ///
    /// Through libpcap; needs capture privileges. With --save FILE the packets are kept as pcapng
    #[arg(long, value_name = "NAME", conflicts_with = "input")]
    pub interface: Option<String>,

    /// The TCP port of the Modbus servers in a capture [default: 502]
    ///
    /// In a pcap or pcapng capture; repeatable. With --mode rtu the streams carry RTU frames (a transparent gateway)
    #[arg(long = "tcp-port", value_name = "PORT", value_parser = clap::value_parser!(u16).range(1..))]
    pub tcp_ports: Vec<u16>,

    /// Keep every byte seen, to replay it later with --input
    ///
    /// Exactly as received; live, their times go to FILE.timing beside it. With --interface, the packets, as pcapng
    #[arg(long, value_name = "FILE")]
    pub save: Option<std::path::PathBuf>,

    /// Also write the frames shown to a pcap file for Wireshark
    ///
    /// Link type 147, see above
    #[arg(long, value_name = "FILE")]
    pub pcap: Option<std::path::PathBuf>,

    /// At the end, statistics per server and unit
    ///
    /// A table (or JSON lines of "type":"stats") per server and unit: requests, answers, exceptions by code, unanswered, and response time min, mean, p95 and max
    #[arg(long)]
    pub stats: bool,

    /// Show only the frames of this slave; repeatable
    #[arg(long = "slave", value_name = "ID")]
    pub slaves: Vec<u8>,

    /// Show only the frames of this function code (3, 0x10); repeatable
    #[arg(long = "function", value_name = "CODE", value_parser = parse_function)]
    pub functions: Vec<u8>,

    /// Ask the USB serial driver for its lowest latency
    ///
    /// The FTDI latency timer to 1 ms, so that gaps between frames can be seen
    #[arg(long)]
    pub low_latency: bool,
    #[command(flatten)]
    pub line: LineArgs,
    #[command(flatten)]
    pub format: FormatArgs,
}

holds!(SniffArgs: line, format);

fn parse_function(text: &str) -> Result<u8, String> {
    mbtool_core::input::number::parse_in_range(text, 1, 127, "function code").map(|f| f as u8)
}
