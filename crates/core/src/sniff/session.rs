//! A sniffing session: frames found, read as requests and answers, paired, filtered and
//! counted. Pure, like the framer it drives.

use std::cell::{OnceCell, RefCell};
use std::net::SocketAddr;

use serde::Serialize;

use super::pairing::{Pairer, Role, Unanswered};
use crate::codec::framing::{Ahead, Broken, Event, Found, FoundAhead, Framer, Noise, NoiseBytes};
use crate::codec::{Direction, Envelope, Mismatch, Mode, Request, Ways};
use crate::describe::{
    describe_as, describe_frame, describe_reading, locate_answer, FrameReport, Kind,
};

/// The error of an ASCII frame that ended in LF without its CR: its LRC may hold, so that
/// only this tells why it is not valid.
pub const ENDS_WITHOUT_CR: &str = "the frame ends in LF without the CR before it";

/// What a session found in the bytes, in the order it happened.
#[derive(Clone, Debug, PartialEq)]
// A frame record is large beside the others, but not boxed: the records of a push are
// written and dropped together, and a box cost an allocation a frame.
#[allow(clippy::large_enum_variant)]
pub enum Record {
    /// A frame, valid or broken.
    Frame(FrameRecord),
    /// A run of bytes that belong to no frame.
    Noise {
        /// The first bytes of the run (`codec::framing::NOISE_KEPT`).
        kept: NoiseBytes,
        /// How many bytes the run holds.
        len: u64,
        /// Where the run starts, in bytes from the start of the capture.
        offset: u64,
        /// When the first byte arrived, when known.
        time: Option<u64>,
        /// `time`, or without timing where the bytes stand at the line's speed.
        at: u64,
    },
    /// A request that no answer followed before the next request.
    Unanswered {
        /// The slave asked.
        slave: u8,
        /// The request.
        request: Request,
        /// Microseconds from the end of the request until the next frame (or the end of the
        /// capture), when known and more than none.
        waited: Option<u64>,
        /// The capture ended while the request waited: the capture, not the slave, may be
        /// why no answer was seen.
        capture_ended: bool,
        /// In a TCP capture: its connection and packet, and its transaction id.
        tcp: Option<(TcpPlace, u16)>,
    },
}

/// Where a frame of a TCP capture was.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TcpPlace {
    /// The client's address and port.
    pub client: SocketAddr,
    /// The server's: the side on a Modbus port.
    pub server: SocketAddr,
    /// The frames travel in UDP datagrams (Modbus/UDP), not a TCP stream.
    pub udp: bool,
    /// The frame went from the client to the server.
    pub from_client: bool,
    /// The packet its last byte came in, numbered from 1 as Wireshark numbers them.
    pub packet: u64,
    /// When that packet was captured, in microseconds since 1970.
    pub time_us: u64,
    /// For an answer: the packet of the request it answers.
    pub request_packet: Option<u64>,
    /// For an answer: microseconds from its request's packet to its own.
    pub response_time: Option<u64>,
}

/// A frame as a session shows it.
#[derive(Clone, Debug)]
pub struct FrameRecord {
    /// Its number in the capture, from 1, counting the frames a filter hides.
    pub number: u64,
    /// The bytes, where they were and when, and what is broken.
    pub found: Found,
    /// Microseconds from the start of the capture: when the first byte arrived, or, without
    /// timing, where the frame stands at the line's speed.
    pub at: u64,
    /// What the frame says: see [`FrameRecord::report`]. Boxed: a record is written by the
    /// session and read by the writer, every frame of a busy line, and a report is most of
    /// its size.
    report: OnceCell<Box<FrameReport>>,
    /// How the session read a valid frame, until its report is worked out from it.
    reading: RefCell<Option<SessionReading>>,
    /// Silence before the frame since the end of the previous one, in microseconds.
    pub gap: Option<u64>,
    /// An answer that follows its request.
    pub paired: bool,
    /// An answer that follows a request of its slave and function but does not fit it:
    /// how (a count or an echo that differs).
    pub mismatch: Option<Mismatch>,
    /// In a TCP capture: where the frame was.
    pub tcp: Option<TcpPlace>,
}

/// How the session read a valid frame's PDU, and the request it answers: all its report
/// is made from.
#[derive(Clone, Debug)]
struct SessionReading {
    mode: Mode,
    /// The ways its PDU is read.
    ways: Ways,
    /// The request a read answer answers, which gives its addresses.
    answers: Option<Request>,
}

impl FrameRecord {
    /// A frame and its report.
    pub fn new(number: u64, found: Found, at: u64, report: FrameReport) -> Self {
        Self {
            number,
            found,
            at,
            report: OnceCell::from(Box::new(report)),
            reading: RefCell::new(None),
            gap: None,
            paired: false,
            mismatch: None,
            tcp: None,
        }
    }

    /// A valid frame whose report is worked out when first asked for: its PDU read the
    /// `ways` it was found to read, and a read answer given the addresses of the request
    /// it `answers`.
    pub(super) fn read(
        number: u64,
        found: Found,
        at: u64,
        mode: Mode,
        ways: Ways,
        answers: Option<Request>,
    ) -> Self {
        let reading = SessionReading {
            mode,
            ways,
            answers,
        };
        Self {
            number,
            found,
            at,
            report: OnceCell::new(),
            reading: RefCell::new(Some(reading)),
            gap: None,
            paired: false,
            mismatch: None,
            tcp: None,
        }
    }

    /// What the frame says, field by field. A valid frame's is worked out the first time it
    /// is asked for, on the thread that asks: the one that shows the frame, not the one
    /// that finds it, so that a capture is framed and described side by side.
    pub fn report(&self) -> &FrameReport {
        self.report.get_or_init(|| Box::new(self.work_out_report()))
    }

    /// The report of [`FrameRecord::report`], from the reading the session kept.
    fn work_out_report(&self) -> FrameReport {
        let bytes = &self.found.bytes;
        let Some(read) = self.reading.borrow_mut().take() else {
            // Every record has its report or its reading; this is a description all
            // the same, from the bytes alone.
            return describe_frame(bytes, None, None);
        };
        let Ok(envelope) = Envelope::open_sound(read.mode, bytes) else {
            return describe_frame(bytes, Some(read.mode), None);
        };
        let mut report = describe_reading(read.mode, &envelope, read.ways.read(&envelope.pdu));
        if let Some(request) = &read.answers {
            locate_answer(&mut report, request, &envelope.pdu);
        }
        report
    }
}

impl PartialEq for FrameRecord {
    fn eq(&self, other: &Self) -> bool {
        self.number == other.number
            && self.found == other.found
            && self.at == other.at
            && self.gap == other.gap
            && self.paired == other.paired
            && self.mismatch == other.mismatch
            && self.tcp == other.tcp
            && self.report() == other.report()
    }
}

/// The tally of one slave address.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct SlaveCounts {
    /// Valid requests.
    pub requests: u64,
    /// Valid answers, exceptions included.
    pub answers: u64,
    /// Exception answers.
    pub exceptions: u64,
    /// Requests no answer followed.
    pub unanswered: u64,
    /// Frames whose checksum failed.
    pub crc_errors: u64,
}

/// The tally of a whole session, and of each slave address.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Counts {
    /// Frames, valid or broken.
    pub frames: u64,
    /// Valid requests.
    pub requests: u64,
    /// Valid answers, exceptions included.
    pub answers: u64,
    /// Exception answers.
    pub exceptions: u64,
    /// Requests no answer followed.
    pub unanswered: u64,
    /// Answers that do not fit the request they follow (a count or an echo that differs).
    pub mismatched: u64,
    /// Frames whose checksum failed.
    pub crc_errors: u64,
    /// Frames with a good checksum whose PDU reads as no request or answer.
    pub malformed: u64,
    /// Bytes that belong to no frame.
    pub noise_bytes: u64,
    /// The same per slave address.
    pub slaves: PerSlave,
}

/// Tallies by slave address, in a table the address indexes, so that counting a frame
/// is no search; listed, and serialized, as a map of the addresses seen, lowest first.
#[derive(Clone, PartialEq, Eq)]
pub struct PerSlave {
    seen: [bool; 256],
    tallies: Box<[SlaveCounts; 256]>,
}

impl Default for PerSlave {
    fn default() -> Self {
        Self {
            seen: [false; 256],
            tallies: Box::new([SlaveCounts::default(); 256]),
        }
    }
}

impl PerSlave {
    /// The tally of `slave`, which is now among those seen.
    pub fn entry(&mut self, slave: u8) -> &mut SlaveCounts {
        self.seen[usize::from(slave)] = true;
        &mut self.tallies[usize::from(slave)]
    }

    /// The tally of `slave`, when seen.
    pub fn get(&self, slave: u8) -> Option<&SlaveCounts> {
        self.seen[usize::from(slave)].then(|| &self.tallies[usize::from(slave)])
    }

    /// The addresses seen, lowest first, with their tallies.
    pub fn iter(&self) -> impl Iterator<Item = (u8, &SlaveCounts)> {
        (0..=u8::MAX).filter_map(|slave| Some((slave, self.get(slave)?)))
    }
}

impl std::fmt::Debug for PerSlave {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_map().entries(self.iter()).finish()
    }
}

impl Serialize for PerSlave {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_map(self.iter())
    }
}

impl Counts {
    /// A frame, told by what it says.
    pub(super) fn frame(&mut self, report: &FrameReport) {
        self.tell(report.slave, report.valid.then_some(report.kind));
    }

    /// A frame of `slave`: what it is, or `None` when it is not valid.
    pub(super) fn tell(&mut self, slave: u8, kind: Option<Kind>) {
        self.frames += 1;
        let slave = self.slaves.entry(slave);
        let Some(kind) = kind else {
            return;
        };
        match kind {
            Kind::Request => {
                self.requests += 1;
                slave.requests += 1;
            }
            Kind::Response => {
                self.answers += 1;
                slave.answers += 1;
            }
            Kind::Exception => {
                self.answers += 1;
                self.exceptions += 1;
                slave.answers += 1;
                slave.exceptions += 1;
            }
        }
    }

    /// A request of `slave` that got no answer.
    pub(super) fn unanswered(&mut self, slave: u8) {
        self.unanswered += 1;
        self.slaves.entry(slave).unanswered += 1;
    }
}

/// Which frames to show: by slave and by function; empty shows all.
#[derive(Clone, Debug, Default)]
pub struct Filter {
    /// Show only these slave addresses.
    pub slaves: Vec<u8>,
    /// Show only these function codes (an exception counts as its function).
    pub functions: Vec<u8>,
}

impl Filter {
    pub(super) fn shows(&self, slave: u8, function: u8) -> bool {
        (self.slaves.is_empty() || self.slaves.contains(&slave))
            && (self.functions.is_empty() || self.functions.contains(&(function & 0x7F)))
    }

    pub(super) fn is_empty(&self) -> bool {
        self.slaves.is_empty() && self.functions.is_empty()
    }
}

/// A sniffing session: frames a stream of bytes, pairs requests with answers, and keeps the tally.
pub struct Session {
    mode: Mode,
    framer: Framer,
    pairer: Pairer,
    filter: Filter,
    counts: Counts,
    char_us: f64,
    last_end: Option<u64>,
    /// Where the last timed bytes stood, and when they came: bytes without a time after
    /// them (a `.timing` file shorter than its capture) go on from there at the line's
    /// speed, so that times never go back.
    clock: Option<(u64, u64)>,
    numbered: u64,
    events: Vec<Event>,
    /// The line's reads come on a USB adapter's latency timer: its gaps are not its
    /// silences (see [`Framer::gaps_lie`]).
    pub behind_latency_timer: bool,
}

impl Session {
    /// `char_us`: one character's time on the wire; `silence_us`: the gap that ends a frame.
    pub fn new(mode: Mode, char_us: f64, silence_us: u64, filter: Filter) -> Self {
        let mut framer = Framer::new(mode, char_us, silence_us);
        framer.end_cut_frames();
        Self {
            mode,
            framer,
            pairer: Pairer::default(),
            filter,
            counts: Counts::default(),
            char_us,
            last_end: None,
            clock: None,
            numbered: 0,
            events: Vec::new(),
            behind_latency_timer: false,
        }
    }

    /// The tally so far.
    pub fn counts(&self) -> &Counts {
        &self.counts
    }

    /// Bytes of a capture file, without timing.
    pub fn push(&mut self, bytes: &[u8], out: &mut Vec<Record>) {
        let mut events = std::mem::take(&mut self.events);
        self.framer.push(bytes, &mut events);
        self.read_framed(events.drain(..), out);
        self.events = events;
    }

    /// A framer for the bytes of the capture from `offset` on, to frame them ahead on
    /// another core (see [`Framer::frame_ahead`]) while this session reads what comes
    /// before them.
    pub fn framer_ahead(&self, offset: u64) -> Framer {
        self.framer.starting_at(offset)
    }

    /// Bytes of a capture file without timing, the block after those pushed so far, which
    /// `ahead` framed from its own start: their frames, the same as [`Session::push`]
    /// would find, are `events` and then those returned, to be read in that order with
    /// [`Session::read_framed`]. `None` when the frames found ahead were never met: the
    /// block was framed in order, and framing ahead did not pay.
    pub fn catch_up(
        &mut self,
        block: &[u8],
        ahead: Ahead,
        events: &mut Vec<Event>,
    ) -> Option<FoundAhead> {
        self.framer.catch_up(block, ahead, events)
    }

    /// Bytes read together from a port, the last at `time` microseconds.
    pub fn push_at(&mut self, bytes: &[u8], time: u64, out: &mut Vec<Record>) {
        let mut events = std::mem::take(&mut self.events);
        self.framer.push_at(bytes, time, &mut events);
        self.behind_latency_timer |= self.framer.gaps_lie();
        self.read_framed(events.drain(..), out);
        self.events = events;
    }

    /// One byte at a known time.
    pub fn push_byte_at(&mut self, byte: u8, time: u64, out: &mut Vec<Record>) {
        let mut events = std::mem::take(&mut self.events);
        self.framer.push_byte_at(byte, time, &mut events);
        self.read_framed(events.drain(..), out);
        self.events = events;
    }

    /// The line has been quiet until `now`. Returns whether that was news to the framer:
    /// a replay must repeat exactly those calls to find the same frames.
    pub fn idle(&mut self, now: u64, out: &mut Vec<Record>) -> bool {
        let mut events = std::mem::take(&mut self.events);
        let news = self.framer.idle(now, &mut events);
        self.read_framed(events.drain(..), out);
        self.events = events;
        news
    }

    /// The end of the capture, at `now` when known.
    pub fn finish(&mut self, now: Option<u64>, out: &mut Vec<Record>) {
        let mut events = std::mem::take(&mut self.events);
        self.framer.finish(&mut events);
        self.read_framed(events.drain(..), out);
        if let Some(unanswered) = self.pairer.finish(now.or(self.last_end)) {
            self.unanswered(unanswered, out);
        }
    }

    /// Reads frames and noise the framer found: those of [`Session::catch_up`], and of
    /// every push.
    pub fn read_framed(&mut self, events: impl IntoIterator<Item = Event>, out: &mut Vec<Record>) {
        for event in events {
            match event {
                Event::Noise(Noise {
                    kept,
                    len,
                    offset,
                    start,
                }) => {
                    self.counts.noise_bytes += len;
                    self.note_time(start, offset);
                    if self.filter.is_empty() {
                        let at = self.at(start, offset);
                        out.push(Record::Noise {
                            kept,
                            len,
                            offset,
                            time: start,
                            at,
                        });
                    }
                }
                Event::Frame(found) => self.frame(found, out),
            }
        }
    }

    /// Bytes at `offset` came at `time`, when known: bytes after them without a time go on
    /// from there. Noted for every frame and noise, shown or not, so that a filter does not
    /// change the times of what it shows.
    fn note_time(&mut self, time: Option<u64>, offset: u64) {
        if let Some(time) = time {
            self.clock = Some((offset, time));
        }
    }

    /// The time of bytes at `offset`, noted with [`Session::note_time`]: as they arrived,
    /// or at the line's speed from the last bytes that had a time (from the start, when
    /// none had). Worked out only for what is shown.
    fn at(&self, time: Option<u64>, offset: u64) -> u64 {
        match (time, self.clock) {
            (Some(time), _) => time,
            (None, Some((from, then))) if offset >= from => {
                then + ((offset - from) as f64 * self.char_us).round() as u64
            }
            (None, _) => (offset as f64 * self.char_us).round() as u64,
        }
    }

    fn unanswered(&mut self, unanswered: Unanswered, out: &mut Vec<Record>) {
        let slave = unanswered.pending.slave;
        self.counts.unanswered(slave);
        if self
            .filter
            .shows(slave, unanswered.pending.request.function())
        {
            out.push(Record::Unanswered {
                slave,
                request: unanswered.pending.request.request(),
                waited: unanswered.waited,
                capture_ended: unanswered.capture_ended,
                tcp: None,
            });
        }
    }

    fn frame(&mut self, found: Found, out: &mut Vec<Record>) {
        let gap = match (self.last_end, found.start) {
            (Some(end), Some(start)) => Some(start.saturating_sub(end + self.char_us as u64)),
            _ => None,
        };
        self.last_end = found.end.or(self.last_end);
        self.numbered += 1;
        self.note_time(found.start, found.offset);
        let number = self.numbered;
        let shown = match found.broken {
            Some(broken) => {
                let mut report = self.describe_invalid(&found, found.direction);
                if broken == Broken::Incomplete {
                    report.error = Some("incomplete: the frame was cut off before its end".into());
                } else if self.mode == Mode::Ascii && !found.bytes.ends_with(b"\r\n") {
                    // Its LRC may hold, and the reading show it so: the end is what broke.
                    report.error = Some(ENDS_WITHOUT_CR.into());
                }
                if broken == Broken::Malformed {
                    self.counts.malformed += 1;
                    // Its checksum holds: it opens.
                    let envelope = Envelope::open_sound(self.mode, &found.bytes);
                    if let (Some(direction), Ok(envelope)) = (found.direction, envelope) {
                        self.pair_malformed(&envelope, direction, &found, out);
                    }
                } else {
                    // A frame cut short fails its checksum as much as one that broke.
                    self.counts.crc_errors += 1;
                    self.counts.slaves.entry(report.slave).crc_errors += 1;
                }
                self.counts.frame(&report);
                self.filter.shows(report.slave, report.function).then(|| {
                    let at = self.at(found.start, found.offset);
                    FrameRecord::new(number, found, at, report)
                })
            }
            None => self.valid_frame(number, found, out),
        };
        if let Some(mut record) = shown {
            record.gap = gap;
            out.push(Record::Frame(record));
        }
    }

    /// A frame that is not valid, read the way it travels (a cut answer is an answer, a
    /// malformed one too), its CRC where the framer found it.
    fn describe_invalid(&self, found: &Found, direction: Option<Direction>) -> FrameReport {
        let mut report = describe_as(&found.bytes, self.mode, direction);
        report.valid = false;
        // Too short to read, it is still what the framer found it to be.
        if let Some(direction) = direction {
            report.kind = Kind::travelling(direction, report.function);
        }
        report
    }

    /// A malformed frame in the conversation as it is shown: an answer settles the request
    /// awaiting it, a request gives up on the one still waiting and waits in its place.
    fn pair_malformed(
        &mut self,
        envelope: &Envelope,
        direction: Direction,
        found: &Found,
        out: &mut Vec<Record>,
    ) {
        let unanswered = self.pairer.malformed(
            envelope.slave,
            &envelope.pdu,
            direction,
            found.start,
            found.end,
        );
        if let Some(unanswered) = unanswered {
            self.unanswered(unanswered, out);
        }
    }

    /// A frame whose checksum holds: paired and counted now, described when shown.
    fn valid_frame(
        &mut self,
        number: u64,
        found: Found,
        out: &mut Vec<Record>,
    ) -> Option<FrameRecord> {
        let Ok(envelope) = Envelope::open_sound(self.mode, &found.bytes) else {
            let report = describe_frame(&found.bytes, Some(self.mode), None);
            self.counts.frame(&report);
            return self.filter.shows(report.slave, report.function).then(|| {
                let at = self.at(found.start, found.offset);
                FrameRecord::new(number, found, at, report)
            });
        };
        let function = envelope.pdu.first().copied().unwrap_or_default();
        // Paired by which ways its bytes read; what they say is read only if it is shown.
        let ways = Ways::of(&envelope.pdu);
        // A malformed frame is read the way it travels: as the framer found it, or, where
        // its layout is the same both ways (a 05 or 06 echo), as the conversation before
        // it has it.
        let malformed_travels = match ways {
            Ways::Neither => found
                .direction
                .or_else(|| self.pairer.way_of_malformed(envelope.slave, function)),
            _ => None,
        };
        let (role, unanswered) =
            self.pairer
                .read(envelope.slave, &envelope.pdu, ways, found.start, found.end);
        if let Some(unanswered) = unanswered {
            self.unanswered(unanswered, out);
        }
        if let Some(direction) = malformed_travels {
            self.pair_malformed(&envelope, direction, &found, out);
        }
        let kind = match &role {
            Role::Request | Role::Unsettled => Some(Kind::Request),
            Role::Answer { .. } => Some(Kind::travelling(Direction::Response, function)),
            Role::Malformed => None,
        };
        self.counts.tell(envelope.slave, kind);
        self.counts.malformed += u64::from(kind.is_none());
        self.counts.mismatched += u64::from(matches!(
            role,
            Role::Answer {
                mismatch: Some(_),
                ..
            }
        ));
        if !self.filter.shows(envelope.slave, function) {
            return None;
        }
        let ways = role.ways();
        let (answers, paired, mismatch) = match role {
            Role::Answer { to, mismatch } => {
                let paired = to.is_some();
                // Only a read's answer takes its addresses from the request.
                let answers = to.filter(|_| kind == Some(Kind::Response));
                (answers.map(|to| to.request()), paired, mismatch)
            }
            // Where it is known which way it travels, it is read that way and told what is
            // wrong with it as that, as it is after noise.
            Role::Malformed if malformed_travels.is_some() => {
                let report = self.describe_invalid(&found, malformed_travels);
                let at = self.at(found.start, found.offset);
                return Some(FrameRecord::new(number, found, at, report));
            }
            _ => (None, false, None),
        };
        let mode = self.mode;
        let at = self.at(found.start, found.offset);
        let mut record = FrameRecord::read(number, found, at, mode, ways, answers);
        record.paired = paired;
        record.mismatch = mismatch;
        Some(record)
    }
}

#[cfg(test)]
mod tests;
