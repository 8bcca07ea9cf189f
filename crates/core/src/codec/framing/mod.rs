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
use ahead::Standing;
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
    /// Where the framer stood after each frame it handed out, while it frames a block
    /// ahead or catches up with one (see `ahead`).
    standings: Option<Vec<(usize, Standing)>>,
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
            standings: None,
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
        for (i, byte) in bytes.iter().enumerate() {
            let back = ((last - i) as f64 * self.char_us) as u64;
            self.latest_time = time.saturating_sub(back).max(self.latest_time);
            self.buffer.push(*byte);
            self.times.push(self.latest_time);
            self.read_starts.push(i == 0);
        }
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
                let room = NOISE_KEPT.saturating_sub(noise.kept.len()).min(count);
                noise.kept.extend_from_slice(&self.buffer[at..at + room]);
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
mod tests {
    use super::*;
    use crate::codec::limits::{MAX_ASCII_ADU, MAX_RTU_ADU};

    #[test]
    fn frames_glued_on_one_line_are_split_and_nothing_else_is() {
        let request = [0x11, 0x03, 0x00, 0x6B, 0x00, 0x03, 0x76, 0x87];
        let response = [
            0x11, 0x03, 0x06, 0x02, 0x2B, 0x00, 0x00, 0x00, 0x64, 0xC8, 0xBA,
        ];
        let glued = [&request[..], &response[..]].concat();
        assert_eq!(
            split_glued(Mode::Rtu, &glued),
            Some(vec![request.to_vec(), response.to_vec()])
        );
        assert_eq!(split_glued(Mode::Rtu, &request), None);
        let mut bad = glued.clone();
        bad[12] ^= 1;
        assert_eq!(split_glued(Mode::Rtu, &bad), None);
        assert_eq!(
            split_glued(Mode::Rtu, &[&glued[..], &[0xFF][..]].concat()),
            None
        );
    }
    use crate::codec::checksum::{crc16, rtu};

    const REQUEST: [u8; 8] = [0x11, 0x03, 0x00, 0x6B, 0x00, 0x03, 0x76, 0x87];
    const ANSWER: [u8; 11] = [
        0x11, 0x03, 0x06, 0x02, 0x2B, 0x00, 0x00, 0x00, 0x64, 0xC8, 0xBA,
    ];

    fn framer(mode: Mode) -> Framer {
        Framer::new(mode, 573.0, 2005)
    }

    /// Every event of `stream` fed all at once, then finished.
    fn events(mode: Mode, stream: &[u8]) -> Vec<Event> {
        let mut framer = framer(mode);
        let mut out = Vec::new();
        framer.push(stream, &mut out);
        framer.finish(&mut out);
        out
    }

    /// Every event of `stream` fed a byte at a time, then finished.
    fn events_byte_by_byte(mode: Mode, stream: &[u8]) -> Vec<Event> {
        let mut framer = framer(mode);
        let mut out = Vec::new();
        for byte in stream {
            framer.push(&[*byte], &mut out);
        }
        framer.finish(&mut out);
        out
    }

    /// The valid frames of `stream`.
    fn frames(stream: &[u8]) -> Vec<Vec<u8>> {
        frames_that(stream, true)
    }

    /// The frames of `stream` that are valid, or (`valid` false) broken.
    fn frames_that(stream: &[u8], valid: bool) -> Vec<Vec<u8>> {
        events(Mode::Rtu, stream)
            .into_iter()
            .filter_map(|e| match e {
                Event::Frame(f) if f.broken.is_none() == valid => Some(f.bytes.to_vec()),
                _ => None,
            })
            .collect()
    }

    #[test]
    fn glued_frames_with_noise_between_them() {
        let mut stream = REQUEST.to_vec();
        stream.push(0x00);
        stream.extend_from_slice(&ANSWER);
        stream.push(0xFE);
        let out = events(Mode::Rtu, &stream);
        assert_eq!(frames(&stream), [REQUEST.to_vec(), ANSWER.to_vec()]);
        let noise = out.iter().filter(|e| matches!(e, Event::Noise(_))).count();
        assert_eq!(noise, 2);
    }

    #[test]
    fn the_answer_awaited_from_a_reserved_address_after_noise_is_taken() {
        // A request to 250 (248-255 are reserved, but a device may use them), a glitch
        // byte, then its answer with its CRC sound: the conversation vouches for it, and a
        // frame whose CRC holds is never a CRC error.
        let functions: [&[u8]; 4] = [
            &[0xFA, 0x07],
            &[0xFA, 0x03, 0x00, 0x00, 0x00, 0x01],
            &[0xFA, 0x06, 0x00, 0x01, 0x12, 0x34],
            &[0xFA, 0x41, 0x01, 0x02],
        ];
        let answers: [&[u8]; 4] = [
            &[0xFA, 0x07, 0x29],
            &[0xFA, 0x03, 0x02, 0x00, 0x2A],
            &[0xFA, 0x06, 0x00, 0x01, 0x12, 0x34],
            &[0xFA, 0x41, 0x07],
        ];
        for (request, answer) in functions.iter().zip(answers) {
            // An echoed write, or a function without a known layout, reads both ways: only
            // a conversation already followed tells that it is a request, and what answer
            // it awaits.
            let both_ways = request == &answer || resync::may_lack_layout(request);
            let before: &[&[u8]] = if both_ways {
                &[&[&REQUEST[..], &ANSWER].concat()]
            } else {
                &[&[], &[&REQUEST[..], &ANSWER].concat()]
            };
            for (before, glitch) in before
                .iter()
                .flat_map(|before| [(before, &[0xFF][..]), (before, &[0x55, 0x55])])
            {
                let stream = [before, &rtu(request)[..], glitch, &rtu(answer)].concat();
                let mut expected = frames(before);
                expected.extend([rtu(request), rtu(answer)]);
                assert_eq!(frames(&stream), expected, "{stream:02X?}");
                assert!(frames_that(&stream, false).is_empty(), "{stream:02X?}");
            }
        }
    }

    /// Every frame of `stream`, valid or not, with why it is not.
    fn frames_as_found(stream: &[u8]) -> Vec<(Vec<u8>, Option<Broken>)> {
        frames_of(events(Mode::Rtu, stream))
    }

    /// The frames among `events`, valid or not, with why they are not.
    fn frames_of(events: Vec<Event>) -> Vec<(Vec<u8>, Option<Broken>)> {
        events
            .into_iter()
            .filter_map(|event| match event {
                Event::Frame(found) => Some((found.bytes.to_vec(), found.broken)),
                Event::Noise(_) => None,
            })
            .collect()
    }

    #[test]
    fn a_malformed_answer_after_noise_whose_crc_holds_is_no_crc_error() {
        // Byte count 5 for function 3: a device's mistake, read as a frame with its CRC
        // sound whether noise comes before it or not.
        let malformed = rtu(&[0x11, 0x03, 0x05, 0x01, 0x02, 0x03, 0x04, 0x05]);
        for glitch in [&[][..], &[0xFF]] {
            let stream = [&REQUEST[..], glitch, &malformed, &REQUEST].concat();
            let found = frames_as_found(&stream);
            assert_eq!(found.len(), 3, "{stream:02X?}: {found:02X?}");
            assert_eq!(found[1].0, malformed, "{stream:02X?}");
            assert!(
                matches!(found[1].1, None | Some(Broken::Malformed)),
                "{stream:02X?}: {found:02X?}"
            );
        }
        // Write multiple coils answered with a quantity of 0: a glitch byte before it reads,
        // with its first bytes, as a request in step (slave 9A, function 0F). It must not
        // swallow the answer awaited into a CRC error.
        let request = rtu(&[0x0F, 0x0F, 0xD3, 0xCF, 0x00, 0x10, 0x02, 0x11, 0x37]);
        let answer = rtu(&[0x0F, 0x0F, 0xD3, 0xCF, 0x00, 0x00]);
        for glitch in [0x9A, 0xFF] {
            let stream = [&request[..], &[glitch], &answer].concat();
            let found = frames_as_found(&stream);
            assert_eq!(
                found,
                [
                    (request.clone(), None),
                    (answer.clone(), Some(Broken::Malformed))
                ],
                "{stream:02X?}"
            );
        }
    }

    #[test]
    fn byte_by_byte_and_all_at_once_agree() {
        let mut stream = vec![0x00, 0xFE];
        stream.extend_from_slice(&REQUEST);
        stream.extend_from_slice(&ANSWER);
        assert_eq!(
            events(Mode::Rtu, &stream),
            events_byte_by_byte(Mode::Rtu, &stream)
        );
    }

    #[test]
    fn a_corrupt_request_followed_by_its_answer_is_a_crc_error() {
        let mut bad = REQUEST;
        bad[7] ^= 0xFF;
        let mut stream = bad.to_vec();
        stream.extend_from_slice(&ANSWER);
        let out = events(Mode::Rtu, &stream);
        assert!(
            matches!(&out[0], Event::Frame(f) if f.broken == Some(Broken::Checksum) && f.bytes[..] == bad[..])
        );
        assert!(
            matches!(&out[1], Event::Frame(f) if f.broken.is_none() && f.bytes[..] == ANSWER[..])
        );
    }

    #[test]
    fn a_corrupt_answer_before_a_frame_without_a_known_layout_is_a_crc_error() {
        // The answer awaited, its CRC broken, then function 65 asked and answered: the
        // conversation vouches for the answer's place, though what follows it needs
        // support of its own. Four bytes that read as a request in step, before the same
        // frames, are still noise: nothing vouches for them.
        let mut bad = ANSWER;
        bad[10] ^= 0xFF;
        let user_request = rtu(&[0x09, 0x41, 0x01, 0x02, 0x03]);
        let user_answer = rtu(&[0x09, 0x41, 0x04, 0x05]);
        let broken = |stream: &[u8]| frames_that(stream, false);
        let stream = [&REQUEST[..], &bad, &user_request, &user_answer].concat();
        assert_eq!(broken(&stream), [bad.to_vec()]);
        assert_eq!(
            frames(&stream),
            [REQUEST.to_vec(), user_request.clone(), user_answer.clone()]
        );
        let noise = [0xAA, 0x0B, 0xE7, 0x20];
        let stream = [&REQUEST[..], &ANSWER, &noise, &user_request, &user_answer].concat();
        assert_eq!(broken(&stream), Vec::<Vec<u8>>::new());
    }

    #[test]
    fn the_start_of_a_long_request_passing_a_crc_as_an_answer_is_not_taken_for_one() {
        // A write of 1,036 coils, after a read that awaits its answer: its first eight
        // bytes read as a function 15 answer whose CRC holds, by chance. That answer is on
        // the turn but followed by nothing sound; the whole request is followed by a frame
        // right after it.
        let read = rtu(&[0x01, 0x01, 0x00, 0x00, 0x00, 0x01]);
        let mut packed = vec![0u8; 130];
        packed[0] = 0x5A;
        packed[128] = 0x02;
        let write = rtu(&[&[0x71, 0x0F, 0xC9, 0xD6, 0x04, 0x0C, 0x82][..], &packed].concat());
        assert!(crc16(&write[..8]) == 0, "the chance this test is about");
        let next = rtu(&[0x07, 0x01, 0x25, 0x3E, 0x06, 0xA0]);
        let stream = [&read[..], &write, &next].concat();
        assert_eq!(frames(&stream), [read, write, next]);
    }

    #[test]
    fn a_request_supported_by_a_long_frame_further_on_is_found_read_a_byte_at_a_time_too() {
        // After noise, a request whose answer is cut short and followed by a line held
        // high: only a frame further on supports it, a write of 1,839 coils that starts
        // within the longest frame's reach but ends past it. Read all at once it is whole;
        // read a byte at a time it is not, until it is.
        let request = rtu(&[0x09, 0x02, 0x6D, 0x50, 0x00, 0xB4]);
        let cut_answer = &rtu(&[&[0x09, 0x02, 0x17][..], &[0x5A; 23]].concat())[..9];
        let mut coils = vec![0x11, 0x0F, 0x80, 0xE6, 0x07, 0x2F, 0xE6];
        coils.extend((0..230).map(|i| (i * 37 % 256) as u8));
        let write = rtu(&coils);
        let stream = [
            &[0x44, 0x64, 0x01][..],
            &request,
            cut_answer,
            &[0xFF; 76],
            &write,
            &REQUEST,
        ]
        .concat();
        assert_eq!(
            events_byte_by_byte(Mode::Rtu, &stream),
            events(Mode::Rtu, &stream)
        );
        assert_eq!(frames(&stream), [request, write, REQUEST.to_vec()]);
    }

    #[test]
    fn an_unknown_function_before_a_request_does_not_swallow_it() {
        // 01 41: a byte whose next byte is a user-defined function.
        let mut stream = vec![0x01, 0x41];
        stream.extend_from_slice(&REQUEST);
        stream.extend_from_slice(&ANSWER);
        assert_eq!(frames(&stream), [REQUEST.to_vec(), ANSWER.to_vec()]);
    }

    #[test]
    fn a_request_after_noise_is_taken_at_the_silence_after_it() {
        let mut framer = framer(Mode::Rtu);
        let mut out = Vec::new();
        let mut stream = vec![0x01, 0x41, 0x7F];
        stream.extend_from_slice(&REQUEST);
        framer.push_at(&stream, 10_000, &mut out);
        assert!(!out.iter().any(|e| matches!(e, Event::Frame(_))));
        assert!(!framer.idle(10_500, &mut out), "not silent yet");
        assert!(framer.idle(13_000, &mut out));
        assert!(matches!(out.last(), Some(Event::Frame(f)) if f.bytes[..] == REQUEST[..]));
    }

    #[test]
    fn user_defined_functions_need_support_and_keep_a_crc_ending_in_00() {
        // Find a user-function frame whose CRC ends in 00, so that its prefix one byte
        // shorter passes the CRC too.
        let ends_in_00 = (0u16..)
            .map(|n| rtu(&[0x05, 0x41, (n >> 8) as u8, n as u8, 0x10]))
            .find(|f| f.last() == Some(&0))
            .unwrap();
        let answer = rtu(&[0x05, 0x41, 0x99]);
        let mut stream = ends_in_00.clone();
        stream.extend_from_slice(&answer);
        stream.extend_from_slice(&REQUEST);
        assert_eq!(frames(&stream), [ends_in_00, answer, REQUEST.to_vec()]);
    }

    #[test]
    fn trailing_zeros_never_lengthen_a_frame() {
        let user = rtu(&[0x05, 0x42, 0x01, 0x02]);
        let mut stream = user.clone();
        stream.extend_from_slice(&[0, 0, 0, 0]);
        stream.extend_from_slice(&REQUEST);
        assert_eq!(frames(&stream), [user, REQUEST.to_vec()]);
    }

    #[test]
    fn a_frame_in_two_pieces_is_whole_after_a_finished_transaction() {
        // A master finishes a transaction that got no answer, then awaits the next answer,
        // which a USB adapter delivers in two reads.
        let mut framer = framer(Mode::Rtu);
        let mut out = Vec::new();
        framer.await_answer(0x11, 0x03);
        framer.push_at(&ANSWER[..4], 1_000, &mut out);
        framer.finish(&mut out);
        framer.await_answer(0x11, 0x03);
        out.clear();
        framer.push_at(&ANSWER[..5], 100_000, &mut out);
        assert!(out.is_empty(), "{out:?}");
        framer.push_at(&ANSWER[5..], 104_000, &mut out);
        assert!(
            matches!(out.as_slice(), [Event::Frame(f)] if f.bytes[..] == ANSWER[..] && f.broken.is_none())
        );
    }

    /// Feeds `pieces` as reads at their times (microseconds), each read's bytes one
    /// character apart before it; returns the frames, valid or not.
    fn timed_frames(pieces: &[(&[u8], u64)]) -> Vec<(Vec<u8>, Option<Broken>)> {
        let mut framer = framer(Mode::Rtu);
        framer.end_cut_frames();
        let mut out = Vec::new();
        for (bytes, time) in pieces {
            framer.push_at(bytes, *time, &mut out);
        }
        framer.finish(&mut out);
        frames_of(out)
    }

    #[test]
    fn a_gap_a_read_may_hide_does_not_cut_the_answer_awaited_where_a_longer_reading_ends_at_silence(
    ) {
        // The answer to a user-defined request (function 41), 12 bytes whose first four
        // pass a CRC too, read as 9 bytes and 3, back to back, then silence. The 9 came in a
        // read long after the one before, which could have hidden a gap after the fourth
        // byte; the silence seen after the twelfth tells the answer's length.
        let answer = [
            0xF7, 0x41, 0x87, 0xB0, 0x54, 0x98, 0x1E, 0xA7, 0xAF, 0x00, 0xE6, 0x33,
        ];
        assert!(crc_holds(&answer[..4]) && crc_holds(&answer));
        let reads: [(&[u8], u64); 8] = [
            (&[0x01, 0x01, 0x01, 0x5B, 0x10, 0x73], 10_000),
            (&[0xF7, 0x41, 0xC0, 0xF0], 23_066),
            (&[0x32], 23_639),
            (&answer[..9], 43_862),
            (&answer[9..], 45_581),
            (&[0x2A, 0x05, 0x0F, 0x0A, 0x00], 63_389),
            (&[0x00, 0xE8], 64_535),
            (&[0xC7], 65_108),
        ];
        let frames = timed_frames(&reads);
        assert_eq!(
            frames.get(2),
            Some(&(answer.to_vec(), None)),
            "{frames:02X?}"
        );
        assert_eq!(frames.len(), 4, "{frames:02X?}");
    }

    #[test]
    fn silence_ends_a_frame_cut_short_and_the_next_starts_clean() {
        // The answer cut one byte short, then silence, then a request that starts with the
        // missing byte: read together, the cut answer and that byte pass the CRC.
        let cut = &ANSWER[..10];
        let mut request = vec![ANSWER[10]];
        request.extend_from_slice(&[0x03, 0x00, 0x01, 0x00, 0x01]);
        let request = rtu(&request);
        let out = timed_frames(&[(&REQUEST, 10_000), (cut, 20_000), (&request, 40_000)]);
        assert_eq!(
            out,
            [
                (REQUEST.to_vec(), None),
                (cut.to_vec(), Some(Broken::Incomplete)),
                (request, None)
            ]
        );
    }

    #[test]
    fn a_host_late_now_and_then_leaves_a_line_read_a_byte_at_a_time() {
        // Read a byte a read, but the host once late: the request's first two bytes came in
        // one read. A device then pauses 5 ms inside its answer: on this line that is a
        // silence, and the answer is cut there, though its CRC holds across it.
        let mut time = 2 * 573;
        let mut reads: Vec<(&[u8], u64)> = vec![(&REQUEST[..2], time)];
        for (bytes, silence_before) in [
            (&REQUEST[2..], 0),
            (&ANSWER[..6], 5_000),
            (&ANSWER[6..], 5_000),
        ] {
            time += silence_before;
            for byte in bytes {
                time += 573;
                reads.push((std::slice::from_ref(byte), time));
            }
        }
        let frames = timed_frames(&reads);
        assert_eq!(
            frames,
            [
                (REQUEST.to_vec(), None),
                (ANSWER[..6].to_vec(), Some(Broken::Incomplete))
            ]
        );
    }

    #[test]
    fn a_request_cut_short_by_silence_at_the_end_of_a_capture_is_cut_as_anywhere_else() {
        // A transaction, then a request cut after four bytes and a silence the times told:
        // the same [incomplete] as before a later frame. Without the silence told, the
        // capture itself may have cut it: noise.
        let ended = |silence_told: bool| {
            let mut framer = framer(Mode::Rtu);
            framer.end_cut_frames();
            let mut out = Vec::new();
            framer.push_at(&REQUEST, 10_000, &mut out);
            framer.push_at(&ANSWER, 20_000, &mut out);
            framer.push_at(&REQUEST[..4], 40_000, &mut out);
            if silence_told {
                assert!(framer.idle(140_000, &mut out));
            }
            framer.finish(&mut out);
            out.into_iter().last()
        };
        assert!(
            matches!(ended(true), Some(Event::Frame(f)) if f.bytes[..] == REQUEST[..4] && f.broken == Some(Broken::Incomplete))
        );
        assert!(matches!(ended(false), Some(Event::Noise(n)) if n.len == 4));
    }

    #[test]
    fn a_frame_whose_rest_comes_after_a_gap_is_whole_and_then_gaps_are_not_silence() {
        // A USB adapter's latency timer: the answer in two reads 16 ms apart.
        let out = timed_frames(&[
            (&REQUEST, 10_000),
            (&ANSWER[..4], 16_000),
            (&ANSWER[4..], 32_000),
        ]);
        assert_eq!(out, [(REQUEST.to_vec(), None), (ANSWER.to_vec(), None)]);
        // Once the reads have shown the adapter's period, such a frame tells that the gaps
        // lie: from then on a request cut short by a gap is kept, as without timing.
        let mut framer = framer(Mode::Rtu);
        framer.end_cut_frames();
        let mut out = Vec::new();
        let mut ticks = (1..).map(|tick| tick * 16_000);
        for piece in [&REQUEST[..], &ANSWER[..]].repeat(5) {
            framer.push_at(piece, ticks.next().unwrap(), &mut out);
        }
        framer.push_at(&REQUEST, ticks.next().unwrap(), &mut out);
        assert!(!framer.gaps_lie());
        framer.push_at(&ANSWER[..4], ticks.next().unwrap(), &mut out);
        framer.push_at(&ANSWER[4..], ticks.next().unwrap(), &mut out);
        assert!(framer.gaps_lie());
        framer.push_at(&REQUEST[..5], ticks.next().unwrap(), &mut out);
        framer.push_at(&REQUEST[5..], ticks.next().unwrap(), &mut out);
        assert!(matches!(out.last(), Some(Event::Frame(f)) if f.bytes[..] == REQUEST[..]));
    }

    #[test]
    fn a_frame_across_a_gap_at_no_period_of_the_reads_leaves_the_gaps_believed() {
        // The same answer in two reads 16 ms apart, on a line whose reads come where the
        // bytes end (a frame a read, 5 ms of silence after each): a device that paused
        // inside its frame, not an adapter's tick. The frame is taken whole, and a request
        // cut short later is still ended by its silence.
        let mut pieces = exchanges(50);
        pieces.extend([
            (&REQUEST[..], 5_000),
            (&ANSWER[..4], 16_000 - 7 * 573),
            (&ANSWER[4..], 5_000),
        ]);
        pieces.extend(exchanges(30));
        pieces.extend([(&REQUEST[..6], 5_000), (&REQUEST[..], 5_000)]);
        let out = read_at_their_ends(&pieces);
        assert_eq!(out[101], (ANSWER.to_vec(), None));
        assert_ends_with_a_cut_request_told(&out);
    }

    #[test]
    fn a_gap_longer_than_an_adapter_makes_ends_a_frame_on_a_line_read_in_bursts() {
        // The answer's last byte comes 200 ms after the rest, and no frame after it: an
        // adapter's latency timer splits a frame into reads one period apart, never that far.
        let after = [ANSWER[10], 0xF3, 0x7A];
        let out = timed_frames(&[
            (&REQUEST, 10_000),
            (&ANSWER[..10], 20_000),
            (&after, 220_000),
        ]);
        assert_eq!(
            out,
            [
                (REQUEST.to_vec(), None),
                (ANSWER[..10].to_vec(), Some(Broken::Incomplete))
            ]
        );
        // 16 ms apart, the two reads are one answer.
        let out = timed_frames(&[
            (&REQUEST, 10_000),
            (&ANSWER[..10], 20_000),
            (&ANSWER[10..], 36_000),
        ]);
        assert_eq!(out, [(REQUEST.to_vec(), None), (ANSWER.to_vec(), None)]);
    }

    #[test]
    fn behind_an_adapter_the_answer_awaited_is_taken_with_bytes_after_it_in_its_read() {
        // A user-defined answer and three bytes of noise in one read: an adapter gathers
        // whatever came in its period, so no gap can show between them, and the answer
        // stands on the conversation as it does without timing.
        let request = rtu(&[0x48, 0x46, 0xD4, 0xB7, 0xC2]);
        let answer = rtu(&[0x48, 0x46, 0x5D, 0x86, 0x90]);
        let read = [&answer[..], &[0x2A, 0x43, 0x5F]].concat();
        let out = timed_frames(&[
            (&REQUEST, 10_000),
            (&ANSWER, 20_000),
            (&request, 40_000),
            (&read, 56_000),
            (&REQUEST, 80_000),
            (&ANSWER, 90_000),
        ]);
        let valid: Vec<Vec<u8>> = out
            .into_iter()
            .filter(|(_, broken)| broken.is_none())
            .map(|(bytes, _)| bytes)
            .collect();
        assert_eq!(
            valid,
            [
                REQUEST.to_vec(),
                ANSWER.to_vec(),
                request,
                answer,
                REQUEST.to_vec(),
                ANSWER.to_vec()
            ]
        );
    }

    /// The frames of pieces read one a read, each read at its last byte (one character a
    /// byte at 19200 8E1), with the silence after it in us: a line read a frame at a time.
    fn read_at_their_ends(pieces: &[(&[u8], u64)]) -> Vec<(Vec<u8>, Option<Broken>)> {
        let mut time = 0;
        let reads: Vec<(&[u8], u64)> = pieces
            .iter()
            .map(|(bytes, silence)| {
                time += 573 * bytes.len() as u64;
                let read_at = time;
                time += silence;
                (*bytes, read_at)
            })
            .collect();
        timed_frames(&reads)
    }

    /// Feeds `pieces` (bytes, then the silence after them in microseconds) a byte a read,
    /// one character apart: a line no adapter gathers; returns the frames, valid or not.
    fn read_a_byte_at_a_time(pieces: &[(&[u8], u64)]) -> Vec<(Vec<u8>, Option<Broken>)> {
        let mut time = 0;
        let mut reads: Vec<(&[u8], u64)> = Vec::new();
        for (bytes, silence) in pieces {
            for byte in *bytes {
                time += 573;
                reads.push((std::slice::from_ref(byte), time));
            }
            time += silence;
        }
        timed_frames(&reads)
    }

    #[test]
    fn read_a_byte_at_a_time_a_cut_request_that_reads_as_an_answer_is_no_crc_error_across_its_silence(
    ) {
        // Read Input Registers cut two bytes short: its first six bytes read as an answer of
        // one byte, a length that ends at the silence. No request awaits that answer, so
        // they are a request cut short, not the start of one running across the silence.
        let request = rtu(&[0x11, 0x04, 0x01, 0x35, 0x00, 0x0C]);
        let out = read_a_byte_at_a_time(&[
            (&REQUEST, 5_000),
            (&ANSWER, 5_000),
            (&request[..6], 133_000),
            (&[0x11, 0x17], 250_000),
            (&request, 5_000),
        ]);
        assert_eq!(
            out,
            [
                (REQUEST.to_vec(), None),
                (ANSWER.to_vec(), None),
                (request[..6].to_vec(), Some(Broken::Incomplete)),
                (vec![0x11, 0x17], Some(Broken::Incomplete)),
                (request, None),
            ]
        );
    }

    #[test]
    fn the_awaited_answer_that_fills_its_turn_is_a_crc_error_whatever_passes_a_crc_inside() {
        // The answer to Read Input Registers x6, corrupted; its last seven bytes pass a CRC
        // as a frame of user-defined function 65, which the silence after it would support.
        let request = rtu(&[0x11, 0x04, 0x00, 0x00, 0x00, 0x06]);
        let mut answer = vec![0x11, 0x04, 0x0C, 0x10, 0x20, 0x30, 0x40, 0x50, 0x60, 0x70];
        answer.extend_from_slice(&rtu(&[0x05, 0x41, 0xAA, 0xBB, 0xCC]));
        assert!(!crc_holds(&answer));
        let out = read_a_byte_at_a_time(&[(&request, 5_000), (&answer, 5_000), (&REQUEST, 5_000)]);
        assert_eq!(
            out,
            [
                (request, None),
                (answer, Some(Broken::Checksum)),
                (REQUEST.to_vec(), None)
            ]
        );
    }

    #[test]
    fn read_a_byte_at_a_time_the_broken_answer_of_a_user_defined_function_ends_at_its_silence() {
        // Function 67 has no layout: its answer's length is where the silence falls. Bytes
        // of the slave and function awaited, up to the silence, are that answer: a CRC
        // error, or cut short when too few to hold a CRC; not noise.
        let request = rtu(&[0x11, 0x43]);
        for broken in [
            &[0x11, 0x43, 0xF4, 0x48, 0x8A, 0x46, 0x5D, 0xD2, 0x0C, 0xA2][..],
            &[0x11, 0x43, 0xF4][..],
        ] {
            // After an exchange, so that the frame of function 67 is read as a request.
            let out = read_a_byte_at_a_time(&[
                (&REQUEST, 5_000),
                (&ANSWER, 5_000),
                (&request, 5_000),
                (broken, 5_000),
                (&REQUEST, 5_000),
                (&ANSWER, 5_000),
            ]);
            let expected = match broken.len() {
                3 => Broken::Incomplete,
                _ => Broken::Checksum,
            };
            assert_eq!(
                out,
                [
                    (REQUEST.to_vec(), None),
                    (ANSWER.to_vec(), None),
                    (request.clone(), None),
                    (broken.to_vec(), Some(expected)),
                    (REQUEST.to_vec(), None),
                    (ANSWER.to_vec(), None)
                ]
            );
        }
    }

    /// The exchanges of a busy line, each frame followed by 5 ms of silence.
    fn exchanges(count: usize) -> Vec<(&'static [u8], u64)> {
        [(&REQUEST[..], 5_000), (&ANSWER[..], 5_000)].repeat(count)
    }

    /// Asserts that `out` ends with a request cut short and ended by its silence, then the
    /// request whole: the line's silences are believed.
    fn assert_ends_with_a_cut_request_told(out: &[(Vec<u8>, Option<Broken>)]) {
        assert!(
            out.ends_with(&[
                (REQUEST[..6].to_vec(), Some(Broken::Incomplete)),
                (REQUEST.to_vec(), None),
            ]),
            "{:?}",
            &out[out.len().saturating_sub(4)..]
        );
    }

    #[test]
    fn one_frame_by_chance_across_a_silence_in_many_does_not_make_the_gaps_lie() {
        // A line read a frame at a time (a UART with a FIFO, an adapter that hands bytes
        // over when the line goes quiet): 300 frames, then the answer cut one byte short,
        // silence, and a piece whose first byte passes the answer's CRC with it. One such
        // frame in 300 is chance, not an adapter's latency timer: a request cut short later
        // is still ended by the silence after it.
        let mut pieces = exchanges(150);
        pieces.extend([
            (&REQUEST[..], 5_000),
            (&ANSWER[..10], 5_000),
            (&[ANSWER[10], 0x03, 0x00][..], 5_000),
            (&REQUEST[..6], 5_000),
            (&REQUEST[..], 5_000),
        ]);
        let out = read_at_their_ends(&pieces);
        assert_ends_with_a_cut_request_told(&out);
    }

    #[test]
    fn a_device_that_paused_once_inside_its_first_frame_leaves_the_later_silences_believed() {
        // Read a frame at a time: the first answer with a 4 ms pause inside it, taken whole
        // across it; then 2,200 frames; then a request cut short and ended by silence.
        let mut pieces = vec![
            (&REQUEST[..], 5_000),
            (&ANSWER[..6], 4_000),
            (&ANSWER[6..], 5_000),
        ];
        pieces.extend(exchanges(1_100));
        pieces.extend([(&REQUEST[..6], 5_000), (&REQUEST[..], 5_000)]);
        let out = read_at_their_ends(&pieces);
        assert_eq!(out[1], (ANSWER.to_vec(), None));
        assert_ends_with_a_cut_request_told(&out);
    }

    #[test]
    fn behind_a_usb_adapter_the_gaps_stay_unbelieved_past_two_thousand_frames() {
        // Every answer split by a 16 ms tick, for 6,000 frames: once the reads have shown
        // their period, the frames across gaps go on being counted while the gaps are not
        // believed, so the line stays an adapter's.
        let mut framer = framer(Mode::Rtu);
        framer.end_cut_frames();
        let mut out = Vec::new();
        let mut tick = 0;
        for exchange in 0..3_000 {
            for piece in [&REQUEST[..], &ANSWER[..4], &ANSWER[4..]] {
                tick += 16_000;
                framer.push_at(piece, tick, &mut out);
            }
            assert!(
                framer.gaps_lie() || exchange < 3,
                "gaps believed at exchange {exchange}"
            );
        }
        let whole = out
            .iter()
            .filter(|event| matches!(event, Event::Frame(f) if f.broken.is_none()))
            .count();
        assert_eq!(whole, 6_000);
    }

    #[test]
    fn read_a_byte_at_a_time_a_cut_answer_and_the_next_byte_are_no_frame_by_their_crc() {
        // The answer awaited, cut one byte short; silence; then a request cut short whose
        // first byte happens to be the answer's missing last byte, and silence again.
        // Read together the answer passes its CRC, but on a line read a byte at a time the
        // silence is real: the answer was cut, and no frame is made up across the silence.
        let out = read_a_byte_at_a_time(&[
            (&REQUEST, 5_000),
            (&ANSWER[..10], 5_000),
            (&[ANSWER[10], 0x03, 0x00], 5_000),
            (&REQUEST, 5_000),
        ]);
        assert!(
            !out.contains(&(ANSWER.to_vec(), None)),
            "a frame made up across the silence: {out:?}"
        );
        assert_eq!(out[1], (ANSWER[..10].to_vec(), Some(Broken::Incomplete)));
        assert_eq!(out.last(), Some(&(REQUEST.to_vec(), None)));
    }

    #[test]
    fn a_malformed_request_after_glued_noise_is_shown_when_its_exception_follows() {
        // Noise glued before a request whose CRC holds but whose PDU does not read (a coil
        // value of 0004; function 15 with a byte count of 2 for one coil), then the slave's
        // exception. The second noise starts as a request of function 21 would, so that the
        // bytes up to the silence also look like a frame cut short.
        let coil = rtu(&[0x11, 0x05, 0x01, 0x69, 0x00, 0x04]);
        let coil_refused = rtu(&[0x11, 0x85, 0x03]);
        let coils = rtu(&[0x03, 0x0F, 0x00, 0x01, 0x00, 0x01, 0x02, 0x00, 0x00]);
        let coils_refused = rtu(&[0x03, 0x8F, 0x04]);
        let first_noise = [0x8D, 0xB8, 0x0A, 0xD7, 0x97, 0x59];
        let second_noise = [0x44, 0x15, 0x95, 0xCE, 0x7F, 0x52];
        let lines: [&[u8]; 8] = [
            &REQUEST,
            &ANSWER,
            &[&first_noise[..], &coil].concat(),
            &coil_refused,
            &[&second_noise[..], &coils].concat(),
            &coils_refused,
            &REQUEST,
            &ANSWER,
        ];
        let shown = |out: &[(Vec<u8>, Option<Broken>)]| {
            out.iter()
                .filter(|(_, broken)| broken.is_none())
                .map(|(bytes, _)| bytes.clone())
                .collect::<Vec<_>>()
        };
        let expected = [
            REQUEST.to_vec(),
            ANSWER.to_vec(),
            coil.clone(),
            coil_refused.clone(),
            coils.clone(),
            coils_refused.clone(),
            REQUEST.to_vec(),
            ANSWER.to_vec(),
        ];
        // The bytes alone, and each byte read alone with a silence after every line.
        let all_at_once: Vec<(Vec<u8>, Option<Broken>)> = frames(&lines.concat())
            .into_iter()
            .map(|f| (f, None))
            .collect();
        assert_eq!(shown(&all_at_once), expected);
        let timed = read_a_byte_at_a_time(&lines.map(|line| (line, 5_000)));
        assert_eq!(shown(&timed), expected, "{timed:?}");
        assert!(
            timed.iter().all(|(_, broken)| broken.is_none()),
            "{timed:?}"
        );
    }

    #[test]
    fn a_user_defined_frame_ending_in_00_00_ends_at_its_silence() {
        // An answer of function 65 whose data ends with the CRC of the bytes before it, so
        // that its own CRC is 00 00 and the bytes before those pass a CRC too. From the
        // bytes alone the shorter frame is taken; read a byte at a time, or a frame a read,
        // the silence comes after the 00 00 and not before: they are the answer's own.
        let request = rtu(&[0x01, 0x41, 0x01, 0x02]);
        let answer = rtu(&rtu(&[0x01, 0x41, 0xAA, 0xBB]));
        assert_eq!(answer[6..], [0, 0]);
        let lines: [&[u8]; 4] = [&request, &answer, &REQUEST, &ANSWER];
        assert_eq!(frames(&lines.concat())[1], answer[..6].to_vec());
        let found = |lines: &[&[u8]], byte_a_read: bool| -> Vec<Vec<u8>> {
            let pieces: Vec<(&[u8], u64)> = lines.iter().map(|line| (*line, 3_000)).collect();
            let out = if byte_a_read {
                read_a_byte_at_a_time(&pieces)
            } else {
                read_at_their_ends(&pieces)
            };
            out.into_iter().map(|(frame, _)| frame).collect()
        };
        for byte_a_read in [true, false] {
            assert_eq!(found(&lines, byte_a_read), lines.map(<[u8]>::to_vec));
            // A longer run of 00 after a frame, up to the silence, is a line held low after
            // it, not its CRC.
            let held_low = [&answer[..6], &[0; 5][..]].concat();
            let lines: [&[u8]; 4] = [&request, &held_low, &REQUEST, &ANSWER];
            assert_eq!(
                found(&lines, byte_a_read),
                [
                    request.clone(),
                    answer[..6].to_vec(),
                    REQUEST.to_vec(),
                    ANSWER.to_vec()
                ]
            );
        }
    }

    #[test]
    fn read_a_byte_at_a_time_a_silence_inside_a_frame_ends_it() {
        // A device pauses 3 ms inside its answer; later, a frame of function 72 followed by
        // silence and a frame cut short. Each byte is read alone, one character apart, so
        // no adapter gathered them: the pause is the line's own, and ends the answer for
        // every receiver on the bus, though the bytes across it pass their CRC. The gaps
        // after it still end what they cut.
        let user = rtu(&[0x85, 0x48, 0xA3, 0x7F, 0x4F, 0x50, 0x82, 0x7F, 0xD2, 0x0F]);
        let cut = [0x85, 0x48, 0xDB];
        let next = rtu(&[0x6F, 0x03, 0xAB, 0xAA, 0x00, 0x27]);
        let mut reads = Vec::new();
        let mut time = 0;
        let mut line = |bytes: &[u8], pause_after: Option<usize>| {
            for (i, byte) in bytes.iter().enumerate() {
                time += 573;
                reads.push((vec![*byte], time));
                if pause_after == Some(i) {
                    time += 3_000;
                }
            }
            time += 3_000;
        };
        line(&REQUEST, None);
        line(&ANSWER, Some(6));
        line(&user, None);
        line(&cut, None);
        line(&next, None);
        let pieces: Vec<(&[u8], u64)> = reads.iter().map(|(b, t)| (&b[..], *t)).collect();
        let mut framer = Framer::new(Mode::Rtu, 573.0, 2005);
        framer.end_cut_frames();
        let mut events = Vec::new();
        for (bytes, time) in &pieces {
            framer.push_at(bytes, *time, &mut events);
        }
        framer.finish(&mut events);
        let shown: Vec<(Vec<u8>, Option<Broken>)> = events
            .into_iter()
            .map(|event| match event {
                Event::Frame(found) => (found.bytes.to_vec(), found.broken),
                Event::Noise(noise) => (noise.kept.to_vec(), None),
            })
            .collect();
        assert_eq!(
            shown,
            [
                (REQUEST.to_vec(), None),
                // The answer's first 7 bytes, cut by the pause; its last 4 bytes are noise.
                (ANSWER[..7].to_vec(), Some(Broken::Incomplete)),
                (ANSWER[7..].to_vec(), None),
                (user, None),
                // The slave and function the frame before asked, cut by the silence: its
                // answer cut short, though a function without a layout tells no length.
                (cut.to_vec(), Some(Broken::Incomplete)),
                (next, None),
            ]
        );
        // In reads of several bytes the same gap is an adapter's: see
        // a_frame_whose_rest_comes_after_a_gap_is_whole_and_then_gaps_are_not_silence.
    }

    #[test]
    fn an_answer_without_a_known_layout_across_a_usb_tick_is_taken_whole() {
        // Function 72, request and answer, then noise and a request, in the reads of a USB
        // adapter's 16 ms latency timer at 19200 baud: the answer crosses a tick before any
        // frame of known layout has shown that the gaps lie.
        let mut stream = Vec::new();
        crate::model::hexinput::parse_hex(
            b"110fa6a300040125229e110fa6a3000484324494f7486d132cded6237b2eb3bcf748d91e3f72\
              1fcb197121b0d654af4d11174ef80012d0ed00060c34c36030beaa31e220251e8461ef",
            &mut stream,
        )
        .unwrap();
        let answer = &stream[32..44];
        let out = timed_frames(&[
            (&stream[..18], 16_000),
            (&stream[18..34], 32_000),
            (&stream[34..52], 48_000),
            (&stream[52..], 64_000),
        ]);
        assert!(out.contains(&(answer.to_vec(), None)), "{out:?}");
    }

    #[test]
    fn a_frame_whose_answer_a_usb_tick_cuts_waits_for_the_rest() {
        // After noise, a request whose answer's first bytes end a read, the adapter's read
        // timing out (told as quiet) before the tick brings the rest.
        let mut framer = framer(Mode::Rtu);
        framer.end_cut_frames();
        let mut out = Vec::new();
        framer.push_at(
            &[&[0x7F, 0xFE][..], &REQUEST, &ANSWER[..2]].concat(),
            16_000,
            &mut out,
        );
        framer.idle(24_000, &mut out);
        framer.push_at(&ANSWER[2..], 32_000, &mut out);
        framer.finish(&mut out);
        let frames: Vec<&[u8]> = out
            .iter()
            .filter_map(|event| match event {
                Event::Frame(found) if found.broken.is_none() => Some(&found.bytes[..]),
                _ => None,
            })
            .collect();
        assert_eq!(frames, [&REQUEST[..], &ANSWER[..]]);
    }

    #[test]
    fn noise_before_a_frame_that_a_usb_tick_splits_is_noise_not_a_broken_frame() {
        // Six bytes of noise, then a request whose last four bytes come a tick later: read
        // as function 15, noise and the request's first four bytes make a broken frame
        // that the gap seems to end; the request runs whole across that gap.
        let stream = [
            &[0x81, 0x0F, 0xD4, 0x5A, 0xE2, 0xCC][..],
            &rtu(&[0x01, 0x03, 0x00, 0x00, 0x00, 0x02]),
        ]
        .concat();
        let out = timed_frames(&[(&stream[..10], 10_000), (&stream[10..], 26_000)]);
        assert_eq!(out, [(stream[6..].to_vec(), None)]);
    }

    #[test]
    fn a_user_defined_frame_after_a_glitch_byte_across_a_usb_tick_is_whole() {
        // A glitch byte and the first byte of a function 102 frame end a read: they begin a
        // function 3 frame that the gap seems to cut short.
        let user = rtu(&[0x03, 0x66, 0x58, 0x59, 0xD8, 0x32, 0x44, 0xE3, 0x25, 0x01]);
        let stream = [&[0xD3][..], &user].concat();
        let out = timed_frames(&[(&stream[..2], 10_192), (&stream[2..], 26_192)]);
        assert_eq!(out, [(user, None)]);
    }

    #[test]
    fn a_long_answer_in_a_usb_adapters_reads_is_whole_from_its_first_two_bytes() {
        // A capture that starts with an answer of 89 bytes (function 23), its first two
        // bytes alone in the first read; each read seems to end at a silence.
        let mut body = vec![0x11, 0x17, 84];
        body.extend((0..84u8).map(|i| i.wrapping_mul(97).wrapping_add(13)));
        let answer = rtu(&body);
        let reads: Vec<(&[u8], u64)> = [0, 2, 22, 42, 62, 82]
            .iter()
            .zip([2, 22, 42, 62, 82, answer.len()])
            .zip([10_000, 26_000, 42_000, 58_000, 74_000, 90_000])
            .map(|((from, to), time)| (&answer[*from..to], time))
            .collect();
        assert_eq!(timed_frames(&reads), [(answer.clone(), None)]);
    }

    #[test]
    fn a_request_against_the_turn_then_a_cut_answer_is_supported_by_a_frame_further_on() {
        // A request nobody answers; after a gap, another slave's request, its answer cut
        // short, and a request again, in one read: the second request stands on the frame
        // further on, as it would after noise.
        let other = rtu(&[0x03, 0x0C]);
        let cut = [
            0x03, 0x0C, 0x25, 0x00, 0x00, 0x1A, 0x02, 0x2B, 0x0E, 0x03, 0x80,
        ];
        let read = [&other[..], &cut, &REQUEST].concat();
        let out = timed_frames(&[(&REQUEST, 10_000), (&read, 40_000)]);
        let valid: Vec<Vec<u8>> = out
            .into_iter()
            .filter(|(_, broken)| broken.is_none())
            .map(|(bytes, _)| bytes)
            .collect();
        assert_eq!(valid, [REQUEST.to_vec(), other, REQUEST.to_vec()]);
    }

    #[test]
    fn an_answer_ending_in_00_whose_request_was_lost_runs_to_the_silence() {
        // After an answer the bus expects a request, and the 8 bytes before the 00 that
        // ends this answer read as one; the silence falls after the 00.
        let request = rtu(&[0x01, 0x03, 0x00, 0x00, 0x00, 0x02]);
        let answer = rtu(&[0x01, 0x03, 0x04, 0x00, 0x01, 0x00, 0x02]);
        let ends_in_00 = rtu(&[0x01, 0x03, 0x04, 0x00, 0x00, 0x05, 0x84]);
        assert_eq!(ends_in_00.last(), Some(&0x00));
        let out = timed_frames(&[(&request, 5_000), (&answer, 15_000), (&ends_in_00, 30_000)]);
        assert_eq!(out, [(request, None), (answer, None), (ends_in_00, None)]);
    }

    #[test]
    fn a_device_that_pauses_inside_its_answer_has_it_taken_whole() {
        // The first byte after the pause comes alone: too soon to tell.
        let out = timed_frames(&[
            (&REQUEST, 10_000),
            (&ANSWER[..3], 20_000),
            (&ANSWER[3..4], 30_000),
            (&ANSWER[4..], 34_000),
        ]);
        assert_eq!(out, [(REQUEST.to_vec(), None), (ANSWER.to_vec(), None)]);
    }

    #[test]
    fn a_frame_cut_short_before_a_user_defined_one_that_completes_its_crc_is_cut() {
        // A request cut one byte short, silence, then a frame of function 70 from the
        // slave whose address is the missing byte: read together, the cut request passes.
        let whole = rtu(&[0x01, 0x07]);
        let user = rtu(&[whole[3], 0x46, 0x10, 0x20, 0x30]);
        let out = timed_frames(&[(&whole[..3], 10_000), (&user, 20_000)]);
        assert_eq!(
            out,
            [
                (whole[..3].to_vec(), Some(Broken::Incomplete)),
                (user, None)
            ]
        );
    }

    #[test]
    fn a_request_that_reads_both_ways_after_an_unanswered_one_awaits_its_own_answer() {
        // 02 04 03 8C 00 0E is a read of input registers, and as long as an answer of 3
        // bytes: after a request nobody answered, it is the next request, not that answer.
        let unanswered = rtu(&[0x3A, 0x04, 0x1B, 0x69, 0x00, 0x0E]);
        let request = rtu(&[0x02, 0x04, 0x03, 0x8C, 0x00, 0x0E]);
        let mut body = vec![0x02, 0x04, 28];
        body.extend((0..28u8).map(|i| i.wrapping_mul(37)));
        let answer = rtu(&body);
        let stream = [&unanswered[..], &request, &answer, &[0xA1, 0xB2, 0xC3]].concat();
        assert_eq!(frames(&stream), [unanswered, request, answer]);
    }

    #[test]
    fn random_bytes_are_noise() {
        let mut rng = 0x2545_F491_4F6C_DD1Du64;
        let stream: Vec<u8> = (0..200_000)
            .map(|_| {
                rng ^= rng << 13;
                rng ^= rng >> 7;
                rng ^= rng << 17;
                rng as u8
            })
            .collect();
        // The very first position is in step and may be taken on its CRC alone; nothing
        // after it may.
        let found = frames(&stream);
        assert!(found.len() <= 1, "{} frames in random bytes", found.len());
    }

    #[test]
    fn a_long_run_of_one_byte_is_counted_not_kept() {
        let mut framer = framer(Mode::Rtu);
        let mut out = Vec::new();
        for _ in 0..1000 {
            framer.push(&[0u8; 1000], &mut out);
            assert!(framer.unread().len() <= MAX_RTU_ADU);
        }
        framer.finish(&mut out);
        match out.as_slice() {
            [Event::Noise(noise)] => {
                assert_eq!(noise.len, 1_000_000);
                assert_eq!(noise.kept.len(), NOISE_KEPT);
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn ascii_frames_noise_a_cut_frame_and_a_slow_sender() {
        let stream = b"xx:1103006B00037E\r\n:1103006B:110306022B0000006455\r\n";
        let out = events(Mode::Ascii, stream);
        assert!(matches!(&out[0], Event::Noise(n) if n.kept[..] == b"xx"[..]));
        assert!(matches!(&out[1], Event::Frame(f) if f.broken.is_none()));
        assert!(
            matches!(&out[2], Event::Frame(f) if f.broken == Some(Broken::Incomplete) && f.bytes[..] == b":1103006B"[..])
        );
        assert!(matches!(&out[3], Event::Frame(f) if f.broken.is_none()));

        // Half a second between characters is within the one-second limit.
        let mut framer = framer(Mode::Ascii);
        let mut out = Vec::new();
        for (i, byte) in b":1103006B00037E\r\n".iter().enumerate() {
            framer.push_byte_at(*byte, i as u64 * 500_000, &mut out);
            framer.idle(i as u64 * 500_000 + 499_000, &mut out);
        }
        assert!(matches!(out.as_slice(), [Event::Frame(f)] if f.broken.is_none()));
    }

    #[test]
    fn an_ascii_frame_too_short_to_spell_a_slave_and_function_is_noise() {
        let out = events(Mode::Ascii, b":F\r\n:11\r\n:1103006B00037E\r\n:1");
        assert!(matches!(&out[0], Event::Noise(n) if n.len == 9), "{out:?}");
        assert!(matches!(&out[1], Event::Frame(f) if f.broken.is_none()));
        assert!(matches!(&out[2], Event::Noise(n) if n.len == 2));
        assert_eq!(out.len(), 3);
    }

    #[test]
    fn an_ascii_line_longer_than_a_frame_is_cut_alike_however_it_comes() {
        let mut stream = b":".to_vec();
        stream.extend([b'0'; 1200]);
        stream.extend(b"\r\n:1103006B00037E\r\n");
        let whole = events(Mode::Ascii, &stream);
        assert!(
            matches!(&whole[0], Event::Frame(f) if f.broken == Some(Broken::Incomplete) && f.bytes.len() == MAX_ASCII_ADU)
        );
        assert!(matches!(whole.last(), Some(Event::Frame(f)) if f.broken.is_none()));
        assert_eq!(events_byte_by_byte(Mode::Ascii, &stream), whole);
    }

    #[test]
    fn tcp_frames_by_the_mbap_length_however_split() {
        let frame = [0, 1, 0, 0, 0, 6, 0x11, 0x03, 0x00, 0x6B, 0x00, 0x03];
        let mut stream = frame.to_vec();
        stream.extend_from_slice(&frame);
        let mut framer = framer(Mode::Tcp);
        let mut out = Vec::new();
        for byte in &stream {
            framer.push(&[*byte], &mut out);
        }
        assert_eq!(out.len(), 2);
        // Protocol id 99: no MBAP header, and nothing after it can be trusted.
        framer.push(&[0, 2, 0, 99, 0, 6, 0x11], &mut out);
        assert!(matches!(out.last(), Some(Event::Noise(n)) if n.len == 7));
        assert!(framer.is_lost());
    }
}
