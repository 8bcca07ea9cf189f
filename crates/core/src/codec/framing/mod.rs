//! Finding frames in a stream of bytes: the one framing discipline of mbtool. The master,
//! the slave (`serve` and the sim port) and the sniffer all hand what they receive to a
//! [`Framer`], so the same bytes are framed the same way everywhere. Pure: bytes (with
//! their arrival times, when known) in, frames and noise out; no I/O and no clock.
//!
//! RTU. A frame's length is told by its function code and byte count, and its CRC must
//! hold; where the bytes at a position make no frame, the framer moves on one byte and
//! looks again, so that noise or another slave's traffic never costs the frame after it.
//! A CRC-16 passes random bytes once in 65,536 tries and a noisy stream makes many tries,
//! so wherever a frame could be chance it must have more than its CRC:
//! - a frame found right after noise (a resynchronisation) must read as a well-formed PDU
//!   and be supported by what follows: silence, the end of the input, a valid frame (right
//!   after it or past some noise), or the conversation (it answers the request before it);
//! - a function without a known layout (the user-defined codes 65-72 and 100-110, and MEI
//!   types other than 14) is found by its CRC alone, so it always needs support, and of the
//!   strict kind: silence, the end, a valid frame right after it, or the conversation; it
//!   may not swallow a frame of known layout that starts inside it;
//! - a frame followed by 00 bytes passes its CRC at longer lengths too (the CRC of a frame
//!   and its own CRC is zero): those lengths are never taken over the frame itself.
//!
//! Silence (3.5 character times) counts where the times can be trusted: it supports the
//! frame before it, and the frame after it starts in step. For a sniffer it also ends
//! bytes that do not make a whole frame before it: they are a frame cut short (the answer
//! awaited, or a request in step) or noise, and the frame after the silence starts clean;
//! this is decided when the bytes after the silence come, so that a frame whose rest comes
//! after a gap is still taken whole, and a frame followed by such bytes waits for them too.
//! Frames that did (their CRC holding across the gap: of known layout, or the answer
//! awaited when no frame starts right after the gap) show that the gaps lie, where the
//! bytes come in bursts, the frame's two reads are one period apart on a line whose latest
//! reads sit on that period's grid (`cadence`), and such frames are no rarity (one in 200
//! frames or more, the last within 2,000 frames): a USB adapter hands bytes over when its
//! latency timer runs out, so its reads end on the timer's ticks and a frame straddling a
//! tick arrives in two reads a whole period apart. A device that pauses inside its frame,
//! read where the bytes end, leaves a gap at no period; a CRC holding by chance across a
//! real silence is far rarer; neither must cost the rest of a capture its silences.
//! Meanwhile the
//! times are not taken for silence (nor is the quiet they told), and a frame cut short is
//! kept until bytes show it is no frame, as without timing. No frame runs across a gap
//! longer than an adapter's reads explain (64 ms, `ADAPTER_GAP_MAX_US`), however the line
//! is read. Bytes read one at a time come through no such adapter (a host late now and then,
//! reading two together, does not change that: bursts are a quarter or more of the latest
//! reads): a line's silences are its own, and one ends a frame as it does for every
//! receiver on the bus, whatever CRC the bytes across it pass (a device that pauses inside
//! its frame sends two pieces, a frame cut short and the rest).
//!
//! ASCII: ':' starts a frame and CR LF ends it; up to a second may pass between characters.
//! TCP: the MBAP length alone frames, however the bytes were segmented.

use super::checksum::crc_holds;
use super::function::EXCEPTION_FLAG;
use super::limits::MAX_RTU_ADU;
use super::{Direction, Mode};
use ahead::Notes;
pub use ahead::{Ahead, FoundAhead};
use cadence::ReadCadence;
use memo::{CrcVerdicts, LatestSound};

mod ahead;
mod ascii;
mod cadence;
mod memo;
mod resync;
mod rtu;
mod tcp;

/// How many bytes of a run of noise are kept to be shown; the rest are only counted, so
/// that a line held in break for hours costs no memory.
pub const NOISE_KEPT: usize = 64;

/// The longest pause between the characters of an ASCII frame (the specification's
/// default inter-character timeout).
pub const ASCII_CHARACTER_TIMEOUT_US: u64 = 1_000_000;

/// The shortest RTU frame: address, function, CRC.
const MIN_RTU_FRAME: usize = 4;

/// The highest slave address on a serial line; 248-255 are reserved.
const MAX_SLAVE: u8 = 247;

/// The bytes of a frame found.
pub type FrameBytes = smallvec::SmallVec<[u8; 32]>;

/// The bytes kept of a run of noise: inline up to 16, as long as a `Vec`, since nearly
/// every frame of a busy line with turnaround glitches is followed by a byte or two.
pub type NoiseBytes = smallvec::SmallVec<[u8; 16]>;

/// A frame as found in the stream.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Found {
    /// The whole frame as received: envelope, PDU and checksum (CR LF included in ASCII).
    /// Inline up to 32 bytes, as most frames are: no allocation per frame.
    pub bytes: FrameBytes,
    /// Position of the first byte in the whole stream.
    pub offset: u64,
    /// Arrival time of the first and of the last byte, in microseconds, when known.
    pub start: Option<u64>,
    /// Arrival time of the last byte, in microseconds, when known.
    pub end: Option<u64>,
    /// Why the frame is not valid: a checksum mismatch, or an ASCII frame cut off.
    pub broken: Option<Broken>,
    /// The way the frame travels, when its layout tells (RTU); `None` when it reads both
    /// ways or the layout does not say.
    pub direction: Option<Direction>,
}

/// Why a frame found in the stream is not valid.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Broken {
    /// The frame has the length its bytes predict, but its checksum fails.
    Checksum,
    /// A frame cut off before its end: an ASCII frame by a new ':' (or by silence) before
    /// its CR LF, an RTU frame by silence before its length was reached.
    Incomplete,
    /// Where the conversation awaits a frame, one of the length its bytes predict whose
    /// checksum holds but whose PDU does not follow its layout: a sender's mistake, not the
    /// line's. The turn does not pass, as for a frame whose checksum fails.
    Malformed,
}

/// Bytes that belong to no frame, in a run.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Noise {
    /// The first [`NOISE_KEPT`] bytes of the run.
    pub kept: NoiseBytes,
    /// How many bytes the run holds.
    pub len: u64,
    /// Position of the run's first byte in the whole stream.
    pub offset: u64,
    /// Arrival time of the first byte, when known.
    pub start: Option<u64>,
}

/// What a [`Framer`] hands out, in stream order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Event {
    /// A frame, valid or broken.
    Frame(Found),
    /// A run of bytes that belong to no frame.
    Noise(Noise),
}

/// A frame across a gap once in this many frames is more than chance: a CRC holding by
/// chance across a real silence is far rarer, and an adapter's latency timer splits a frame
/// whenever one straddles its tick.
const CROSSINGS_PER_ADAPTER: u64 = 200;

/// Without a frame across a gap in this many frames, a line's gaps are believed again:
/// a device that paused inside its frames, or a CRC that held by chance, early in a
/// capture, does not cost the silences of the rest of it.
const LYING_FOR_FRAMES: u64 = 2_000;

/// The longest gap inside a frame that a USB adapter's reads explain. An adapter hands
/// bytes over when its latency timer runs out, so a frame that straddles a tick arrives in
/// reads one period apart: 16 ms by default, 1 ms at `--low-latency`, 32 ms at the longest
/// commonly set; twice that leaves room for a busy host's late read. A longer gap is the
/// line's own silence however its bytes were read, and no frame runs across it.
const ADAPTER_GAP_MAX_US: u64 = 64_000;

/// A time not known (the byte came without one).
const UNTIMED: u64 = u64::MAX;

/// One way the bytes at a position read as a frame whose CRC holds.
#[derive(Clone, Copy, Debug)]
struct Candidate {
    len: usize,
    /// `None`: the same length reads both ways.
    direction: Option<Direction>,
    /// Its length came from the function's layout, not from the CRC alone.
    known_layout: bool,
}

/// What the start of the unread bytes holds.
enum Look {
    Frame {
        len: usize,
        broken: Option<Broken>,
        direction: Option<Direction>,
    },
    Noise,
    NeedMore,
    /// TCP: no MBAP header here, so the stream cannot be framed from here on.
    Lost,
}

/// Finds the frames of one mode in a stream of bytes.
pub struct Framer {
    mode: Mode,
    /// Silence that ends a frame, in microseconds: 3.5 characters in RTU, a second in ASCII.
    silence_us: u64,
    /// One character's time on the wire, in microseconds.
    char_us: f64,
    buffer: Vec<u8>,
    /// The arrival time of each byte of `buffer` ([`UNTIMED`] where not known); empty
    /// while no byte has a time, so that a file framed without timing costs nothing here.
    times: Vec<u64>,
    /// Beside `times`: whether each byte was the first of its read. The times of a read's
    /// bytes are placed one character apart before it, so a gap the line had inside a read
    /// does not show; where the read could hold one is told from the gap before it.
    read_starts: Vec<bool>,
    /// The CRCs checked lately.
    crc_verdicts: CrcVerdicts,
    latest_sound: LatestSound,
    /// When the latest reads ended: whether they keep an adapter's period.
    cadence: ReadCadence,
    /// The time of the latest byte placed.
    latest_time: u64,
    /// How many valid frames had been taken when the last frame came whole across a gap
    /// its times showed as silence, on a line read in bursts, while such frames were more
    /// than chance: see [`Framer::gaps_lie`].
    lying_since: Option<u64>,
    /// Which of the latest reads (up to 64, the latest in the lowest bit) brought several
    /// bytes at once, and how many reads there were: see [`Framer::read_in_bursts`].
    several_a_read: u64,
    reads: u32,
    /// Valid frames taken, and how many of them ran whole across a silence.
    frames_taken: u64,
    crossings: u64,
    /// Silence ends a frame cut short: a sniffer's rule (see [`Framer::end_cut_frames`]).
    ends_cut_frames: bool,
    /// Position in the stream of `buffer[0]`.
    offset: u64,
    /// `buffer[0]` follows a frame, silence, or the start of the stream.
    in_step: bool,
    /// The line has been quiet since the last byte.
    quiet: bool,
    /// No more bytes will come.
    ended: bool,
    /// The times told a silence after the last bytes before the stream ended: they are
    /// ended by it, as bytes a silence ends before others come.
    silent_at_end: bool,
    noise: Option<Noise>,
    /// The direction the next frame should travel in: a master alternates request and
    /// answer. It settles a frame that reads as valid at two lengths.
    expect: Option<Direction>,
    /// Slave and function of the request whose answer is due: the conversation.
    awaiting: Option<(u8, u8)>,
    /// TCP: a header that is no MBAP header; nothing after it can be framed.
    lost: bool,
    /// TCP seen from outside: look for the next header that reads instead of giving up.
    resync: bool,
    /// Where the framer stood after each frame it handed out and at places inside noise,
    /// while it frames a block ahead or catches up with one (see `ahead`).
    notes: Option<Notes>,
}

impl Framer {
    /// `char_us`: one character's time (11 bits at the baud rate, say); `silence_us`: the
    /// gap that ends an RTU frame (3.5 characters, 1750 us above 19200 baud). ASCII uses
    /// its own one-second limit, and TCP no timing at all.
    pub fn new(mode: Mode, char_us: f64, silence_us: u64) -> Self {
        Self {
            mode,
            silence_us: match mode {
                Mode::Ascii => ASCII_CHARACTER_TIMEOUT_US,
                _ => silence_us,
            },
            char_us,
            buffer: Vec::with_capacity(1024),
            times: Vec::new(),
            read_starts: Vec::new(),
            crc_verdicts: CrcVerdicts::default(),
            latest_sound: LatestSound::default(),
            cadence: ReadCadence::default(),
            latest_time: 0,
            lying_since: None,
            several_a_read: 0,
            reads: 0,
            frames_taken: 0,
            crossings: 0,
            ends_cut_frames: false,
            offset: 0,
            in_step: true,
            quiet: false,
            ended: false,
            silent_at_end: false,
            noise: None,
            expect: None,
            awaiting: None,
            lost: false,
            resync: false,
            notes: None,
        }
    }

    /// Lets silence end bytes that do not make a whole frame before it (RTU, with timing):
    /// the rule of a sniffer, which must show every frame of both sides in its place. A
    /// master or a slave keeps bytes until they show they are no frame: a slow device may
    /// pause inside its frame, and the answer awaited is worth the wait.
    pub fn end_cut_frames(&mut self) {
        self.ends_cut_frames = true;
    }

    /// Bytes without timing (a file, a TCP segment).
    pub fn push(&mut self, bytes: &[u8], out: &mut Vec<Event>) {
        self.quiet = false;
        self.buffer.extend_from_slice(bytes);
        if !self.times.is_empty() {
            self.times.resize(self.buffer.len(), UNTIMED);
            self.read_starts.resize(self.buffer.len(), true);
        }
        self.scan(out);
    }

    /// Bytes read together, the last of them at `time`: earlier ones are placed one
    /// character time apart before it, as they travelled.
    pub fn push_at(&mut self, bytes: &[u8], time: u64, out: &mut Vec<Event>) {
        let Some(last) = bytes.len().checked_sub(1) else {
            return;
        };
        self.several_a_read = self.several_a_read << 1 | u64::from(last > 0);
        self.reads = self.reads.saturating_add(1);
        self.cadence.record(time);
        let first_time = time.saturating_sub((last as f64 * self.char_us) as u64);
        self.settle_before(first_time, out);
        self.times.resize(self.buffer.len(), UNTIMED);
        self.read_starts.resize(self.buffer.len(), true);
        // A read placed back over the one before it (reads stamped alike, a clock that
        // stepped) starts where that one ended: times never go back.
        self.buffer.extend_from_slice(bytes);
        self.read_starts.push(true);
        self.read_starts.resize(self.buffer.len(), false);
        let (char_us, latest) = (self.char_us, &mut self.latest_time);
        self.times.extend((0..=last).rev().map(|back| {
            *latest = time
                .saturating_sub((back as f64 * char_us) as u64)
                .max(*latest);
            *latest
        }));
        self.scan(out);
    }

    /// One byte at a known time (a timed capture).
    pub fn push_byte_at(&mut self, byte: u8, time: u64, out: &mut Vec<Event>) {
        self.push_at(&[byte], time, out);
    }

    /// The line has been quiet until `now`: the last frame is followed by silence. Returns
    /// whether that was news (a replay that repeats the call gives the same frames).
    pub fn idle(&mut self, now: u64, out: &mut Vec<Event>) -> bool {
        if self.quiet || !self.silent_since_last(now) {
            return false;
        }
        self.quiet = true;
        self.scan(out);
        true
    }

    /// The end of the stream: what is left is decided.
    pub fn finish(&mut self, out: &mut Vec<Event>) {
        self.silent_at_end = self.quiet;
        self.quiet = true;
        self.ended = true;
        self.scan(out);
        self.flush_noise(out);
    }

    /// `missing` bytes of the stream never came (a lost segment, a packet cut short by the
    /// capture): what is buffered is decided now, a frame begun shown as cut off, and the
    /// framer picks up again at the next frame.
    pub fn gap(&mut self, missing: u64, out: &mut Vec<Event>) {
        self.quiet = true;
        self.ended = true;
        self.scan(out);
        self.flush_noise(out);
        self.ended = false;
        self.clear();
        self.offset += missing;
        // A gap ends where a captured segment begins, which is where a sender starts a
        // frame: a header there is taken; one that does not read sends the framer hunting.
        self.in_step = true;
    }

    /// A master has sent a request to `slave` with `function`: the next frame should be
    /// its answer. What came before is forgotten.
    pub fn await_answer(&mut self, slave: u8, function: u8) {
        self.clear();
        self.expect = Some(Direction::Response);
        self.awaiting = Some((slave, function & !EXCEPTION_FLAG));
    }

    /// A slave has answered the request just framed: the next frame is a request.
    pub fn answered(&mut self) {
        self.expect = Some(Direction::Request);
        self.awaiting = None;
    }

    /// Forgets the bytes not yet framed and starts in step, as after silence: a stream
    /// that goes on, even after [`Framer::finish`] (a master's next transaction).
    pub fn clear(&mut self) {
        self.offset += self.buffer.len() as u64;
        self.buffer.clear();
        self.times.clear();
        self.read_starts.clear();
        self.noise = None;
        self.in_step = true;
        self.quiet = false;
        self.ended = false;
        self.silent_at_end = false;
        self.lost = false;
    }

    /// Bytes received but not framed yet.
    pub fn unread(&self) -> &[u8] {
        &self.buffer
    }

    /// TCP: a header was no MBAP header, so the connection cannot be trusted any more.
    pub fn is_lost(&self) -> bool {
        self.lost
    }

    /// When byte `i` of the buffer arrived, when known.
    fn time(&self, i: usize) -> Option<u64> {
        self.times.get(i).copied().filter(|time| *time != UNTIMED)
    }

    /// Whether the RTU frame of `len` bytes at `at` ends in its CRC.
    fn crc_holds_at(&self, at: usize, len: usize) -> bool {
        self.crc_verdicts.get(self.offset + at as u64, len, || {
            crc_holds(&self.buffer[at..at + len])
        })
    }

    /// Whether this line's times do not tell its silences: frames have come whole across
    /// gaps its times showed as silence, where a USB adapter's latency timer makes them
    /// (between two reads one period apart, on a line whose reads sit on its grid), more
    /// often than chance (one in 200 frames or more) and lately (within 2,000 frames). A
    /// device that paused inside a frame leaves a gap at no period; a CRC that held by
    /// chance costs the silences of the frames after it for a while at most.
    pub fn gaps_lie(&self) -> bool {
        self.lying_since
            .is_some_and(|since| self.frames_taken - since < LYING_FOR_FRAMES)
    }

    /// Whether the line is read several bytes at a time: a quarter or more of its latest
    /// reads brought several bytes at once. It may be behind an adapter that gathers what
    /// arrives until its latency timer runs out, whose reads make gaps that are no silence.
    /// Read a byte at a time (a UART, a capture timed byte by byte), a line's gaps are its
    /// own, and a host that now and then reads two bytes together, being late, does not
    /// change that: no frame runs across a silence there.
    fn read_in_bursts(&self) -> bool {
        let latest = self.reads.min(u64::BITS);
        self.several_a_read.count_ones() * 4 >= latest && latest > 0
    }

    /// Whether the times of the bytes tell the line's silences, for a sniffer's rules: it
    /// has times, and they are believed (see [`Framer::gaps_lie`]).
    fn times_tell_silence(&self) -> bool {
        self.ends_cut_frames && !self.times.is_empty() && !self.gaps_lie()
    }

    /// Where the first silence inside the bytes from `at` ends (the index of the byte
    /// after it), up to the longest frame's reach; the silence after the last byte is not
    /// counted, since more bytes may still come to decide them, unless the times told it
    /// before the stream ended.
    fn silence_within(&self, at: usize) -> Option<usize> {
        if !self.times_tell_silence() {
            return None;
        }
        let last = self.buffer.len().min(at + MAX_RTU_ADU);
        let told_to_the_end = self.ended && self.silent_at_end && last == self.buffer.len();
        let searched = if told_to_the_end {
            last
        } else {
            last.saturating_sub(1)
        };
        (at..searched)
            .find(|i| self.silence_after(*i))
            .map(|i| i + 1)
    }

    /// Whether the last bytes, which make no frame yet, may still grow into one. A master or
    /// a slave decides at the silence after them; for a sniffer silence alone does not end
    /// them, the bytes after the silence tell (see `silence_within`).
    fn last_bytes_may_grow(&self) -> bool {
        !self.ended && (self.ends_cut_frames || !self.quiet)
    }

    /// Whether silence follows any byte of `at..end` but the last: a frame there crosses it.
    fn silence_inside(&self, at: usize, end: usize) -> bool {
        (at..end - 1).any(|i| self.silence_after(i))
    }

    /// Whether bytes over `at..end` run across a silence that ends a frame, for a sniffer's
    /// rules: any silence the times tell, where the line is read a byte at a time (no
    /// adapter gathers its bytes); a gap longer than an adapter's reads explain, however
    /// the line is read.
    fn crosses_silence(&self, at: usize, end: usize) -> bool {
        if !self.ends_cut_frames || self.times.is_empty() {
            return false;
        }
        if !self.read_in_bursts() && self.times_tell_silence() {
            return self.silence_inside(at, end);
        }
        (at..end - 1).any(|i| match (self.time(i), self.time(i + 1)) {
            (Some(a), Some(b)) => b.saturating_sub(a) > ADAPTER_GAP_MAX_US,
            _ => false,
        })
    }

    /// Whether the line has been silent since the last byte, by `now`.
    fn silent_since_last(&self, now: u64) -> bool {
        if self.gaps_lie() {
            return false;
        }
        match self.buffer.len().checked_sub(1).and_then(|i| self.time(i)) {
            Some(last) => self.is_silence(last, now),
            None => false,
        }
    }

    /// Silence from the character that started at `from` to the one that starts at `to`.
    fn is_silence(&self, from: u64, to: u64) -> bool {
        to.saturating_sub(from) as f64 - self.char_us >= self.silence_us as f64
    }

    /// New bytes after silence: what was waiting is decided as `idle` would have decided
    /// it, so that a live session and a replay of its bytes agree.
    fn settle_before(&mut self, first_new: u64, out: &mut Vec<Event>) {
        self.quiet = false;
        if !self.buffer.is_empty() && self.silent_since_last(first_new) {
            self.quiet = true;
            self.scan(out);
            self.quiet = false;
        }
    }

    /// Whether silence follows byte `i` of the buffer.
    fn silence_after(&self, i: usize) -> bool {
        if i + 1 == self.buffer.len() {
            return self.quiet;
        }
        !self.gaps_lie() && self.timed_gap_after(i)
    }

    /// Whether the line may have been silent between byte `i` and the byte after it though
    /// the times show no gap: both came in one read, and the time before that read was
    /// long enough to hold the read's bytes and a silence (an adapter gathering what came
    /// in its whole period). A UART read at the line's pace leaves no such room.
    fn may_hide_silence_after(&self, i: usize) -> bool {
        if self.read_starts.get(i + 1) != Some(&false) {
            return false;
        }
        match (0..=i).rev().find(|j| self.read_starts[*j]) {
            Some(0) | None => true,
            Some(first) => self.timed_gap_after(first - 1),
        }
    }

    /// Whether bytes over `at..end` run across a gap their times show as silence where an
    /// adapter's latency timer makes one: between two reads one period apart, on a line
    /// whose latest reads sit on its grid. A device that paused inside its frame, read
    /// where the bytes end, leaves a gap at no period.
    fn crosses_a_tick(&self, at: usize, end: usize) -> bool {
        let Some(gap) = (at..end - 1).find(|i| self.timed_gap_after(*i)) else {
            return false;
        };
        let next_read = (gap + 2..self.buffer.len())
            .find(|j| self.read_starts.get(*j) == Some(&true))
            .unwrap_or(self.buffer.len());
        match (self.time(gap), self.time(next_read - 1)) {
            (Some(before), Some(after)) => self.cadence.keeps_period(after.saturating_sub(before)),
            _ => false,
        }
    }

    /// Whether the times of byte `i` and the byte after it, both in the buffer, are a
    /// silence apart, whether or not this line's gaps are believed.
    fn timed_gap_after(&self, i: usize) -> bool {
        match (self.time(i), self.time(i + 1)) {
            (Some(a), Some(b)) => self.is_silence(a, b),
            _ => false,
        }
    }

    fn scan(&mut self, out: &mut Vec<Event>) {
        let mut at = 0;
        let mut in_step = self.in_step;
        while at < self.buffer.len() {
            in_step |= at > 0 && self.silence_after(at - 1);
            if !in_step {
                self.note_in_noise(at, out.len());
            }
            // No frame starts with 00 00 (there is no function 00): a line held low for
            // hours is passed over a run at a time.
            let zeros = match self.mode {
                Mode::Rtu => self.buffer[at..].iter().take_while(|b| **b == 0).count(),
                _ => 0,
            };
            if zeros > 1 {
                self.add_noise(at, zeros - 1);
                at += zeros - 1;
                in_step = false;
                continue;
            }
            let look = match self.mode {
                Mode::Rtu => self.look_rtu(at, in_step),
                Mode::Ascii => self.look_ascii(at),
                Mode::Tcp => self.look_tcp(at, in_step),
            };
            match look {
                Look::Frame {
                    len,
                    broken,
                    direction,
                } => {
                    self.flush_noise(out);
                    let found = Found {
                        bytes: FrameBytes::from_slice(&self.buffer[at..at + len]),
                        offset: self.offset + at as u64,
                        start: self.time(at),
                        end: self.time(at + len - 1),
                        broken,
                        direction,
                    };
                    if broken.is_none() {
                        self.turn(&found);
                        // Whole across a gap its times show as silence, on a line read in
                        // bursts: while such frames are more than chance, the times do not
                        // tell this line's silences (they are kept all the same, to be
                        // shown). Counted from the times themselves, so that the count
                        // goes on while the gaps are not believed.
                        self.frames_taken += 1;
                        if self.ends_cut_frames
                            && self.mode == Mode::Rtu
                            && self.read_in_bursts()
                            && self.crosses_a_tick(at, at + len)
                        {
                            self.crossings += 1;
                            if self.crossings * CROSSINGS_PER_ADAPTER >= self.frames_taken {
                                self.lying_since = Some(self.frames_taken);
                                // The quiet the times told was a lie too, unless the input
                                // ended.
                                self.quiet = self.ended;
                            }
                        }
                    }
                    out.push(Event::Frame(found));
                    self.note_standing(out.len() - 1);
                    at += len;
                    in_step = true;
                }
                Look::Noise => {
                    self.add_noise(at, 1);
                    at += 1;
                    in_step = false;
                }
                Look::NeedMore => break,
                Look::Lost => {
                    self.lost = true;
                    self.add_noise(at, self.buffer.len() - at);
                    at = self.buffer.len();
                    self.flush_noise(out);
                }
            }
        }
        self.buffer.drain(..at);
        self.times.drain(..at.min(self.times.len()));
        self.read_starts.drain(..at.min(self.read_starts.len()));
        self.offset += at as u64;
        self.in_step = in_step;
        if self.ended {
            self.flush_noise(out);
        }
    }

    /// A frame was taken: the bus's turn passes, and a request awaits its answer.
    fn turn(&mut self, found: &Found) {
        // A frame that reads both ways passes the turn all the same, and is the answer
        // only if it answers the request awaited: else a request after one unanswered.
        let direction = found.direction.or(match self.expect {
            Some(Direction::Response) if !self.answers_awaited(&found.bytes, None) => {
                Some(Direction::Request)
            }
            expect => expect,
        });
        match direction {
            // A broadcast is not answered: another request comes next.
            Some(Direction::Request) if found.bytes.first() == Some(&0) => {
                self.expect = Some(Direction::Request);
                self.awaiting = None;
            }
            Some(Direction::Request) => {
                self.expect = Some(Direction::Response);
                self.awaiting = match found.bytes.as_slice() {
                    [slave, function, ..] => Some((*slave, *function)),
                    _ => None,
                };
            }
            Some(Direction::Response) => {
                self.expect = Some(Direction::Request);
                self.awaiting = None;
            }
            None => {}
        }
    }

    /// Counts `count` bytes from `at` as noise, keeping the first of a run.
    fn add_noise(&mut self, at: usize, count: usize) {
        match &mut self.noise {
            Some(noise) => {
                // Past the bytes kept, a long run is only counted.
                let room = NOISE_KEPT.saturating_sub(noise.kept.len()).min(count);
                if room > 0 {
                    noise.kept.extend_from_slice(&self.buffer[at..at + room]);
                }
                noise.len += count as u64;
            }
            // Most runs are a byte or two: made whole at once.
            None => {
                self.noise = Some(Noise {
                    kept: NoiseBytes::from_slice(&self.buffer[at..at + count.min(NOISE_KEPT)]),
                    len: count as u64,
                    offset: self.offset + at as u64,
                    start: self.time(at),
                });
            }
        }
    }

    fn flush_noise(&mut self, out: &mut Vec<Event>) {
        if let Some(noise) = self.noise.take() {
            out.push(Event::Noise(noise));
        }
    }

    // ---- RTU ----
}

/// The frames of bytes given whole and without timing, such as a line of a log that holds
/// a request and its answer glued together: `Some` when the bytes are two or more valid
/// frames of `mode` end to end and nothing else.
pub fn split_glued(mode: Mode, bytes: &[u8]) -> Option<Vec<Vec<u8>>> {
    let mut framer = Framer::new(mode, 0.0, 0);
    let mut events = Vec::new();
    framer.push(bytes, &mut events);
    framer.finish(&mut events);
    let frames: Vec<Vec<u8>> = events
        .into_iter()
        .map(|event| match event {
            Event::Frame(found) if found.broken.is_none() => Some(found.bytes.into_vec()),
            _ => None,
        })
        .collect::<Option<_>>()?;
    (frames.len() >= 2).then_some(frames)
}

#[cfg(test)]
mod tests;
