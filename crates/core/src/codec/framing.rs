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
//! frame before it, and the frame after it starts in step. A frame cut short is kept until
//! bytes show it is no frame, since a USB adapter can pause inside a frame.
//!
//! ASCII: ':' starts a frame and CR LF ends it; up to a second may pass between characters.
//! TCP: the MBAP length alone frames, however the bytes were segmented.

use super::checksum::{crc_holds, crc_matches, lrc};
use super::function::{
    self, ENCAPSULATED_INTERFACE, EXCEPTION_FLAG, MEI_READ_DEVICE_IDENTIFICATION,
};
use super::length::{rtu_frame_length, tcp_frame_length, Length};
use super::limits::{MAX_ASCII_ADU, MAX_RTU_ADU, MAX_TCP_ADU};
use super::{Direction, Mode, Pdu};

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

/// A frame as found in the stream.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Found {
    /// The whole frame as received: envelope, PDU and checksum (CR LF included in ASCII).
    pub bytes: Vec<u8>,
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
    /// An ASCII frame cut off by a new ':' (or by silence) before its CR LF.
    Incomplete,
}

/// Bytes that belong to no frame, in a run.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Noise {
    /// The first [`NOISE_KEPT`] bytes of the run.
    pub kept: Vec<u8>,
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

/// Three answers to "is it so?": the bytes that would tell may not be here yet.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Tell {
    Yes,
    No,
    NotYet,
}

/// One way the bytes at a position read as a frame whose CRC holds.
#[derive(Clone, Copy, Debug)]
struct Candidate {
    len: usize,
    /// `None`: the same length reads both ways.
    direction: Option<Direction>,
    /// Its length came from the function's layout, not from the CRC alone.
    known_layout: bool,
}

/// What the bytes at one position could be.
#[derive(Default)]
struct Candidates {
    /// Lengths whose CRC holds, shortest first.
    valid: Vec<Candidate>,
    /// Directions in which more bytes could still make a frame here, with the length
    /// awaited when the layout tells it.
    pending: Vec<(Direction, Option<usize>)>,
}

impl Candidates {
    fn add(&mut self, len: usize, direction: Direction, known_layout: bool) {
        match self.valid.iter_mut().find(|c| c.len == len) {
            Some(same) if same.direction != Some(direction) => same.direction = None,
            Some(_) => {}
            None => self.valid.push(Candidate {
                len,
                direction: Some(direction),
                known_layout,
            }),
        }
    }
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

fn frame_of(candidate: &Candidate) -> Look {
    Look::Frame {
        len: candidate.len,
        broken: None,
        direction: candidate.direction,
    }
}

/// Finds the frames of one mode in a stream of bytes.
pub struct Framer {
    mode: Mode,
    /// Silence that ends a frame, in microseconds: 3.5 characters in RTU, a second in ASCII.
    silence_us: u64,
    /// One character's time on the wire, in microseconds.
    char_us: f64,
    buffer: Vec<u8>,
    times: Vec<Option<u64>>,
    /// Position in the stream of `buffer[0]`.
    offset: u64,
    /// `buffer[0]` follows a frame, silence, or the start of the stream.
    in_step: bool,
    /// The line has been quiet since the last byte.
    quiet: bool,
    /// No more bytes will come.
    ended: bool,
    noise: Option<Noise>,
    /// The direction the next frame should travel in: a master alternates request and
    /// answer. It settles a frame that reads as valid at two lengths.
    expect: Option<Direction>,
    /// Slave and function of the request whose answer is due: the conversation.
    awaiting: Option<(u8, u8)>,
    /// TCP: a header that is no MBAP header; nothing after it can be framed.
    lost: bool,
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
            times: Vec::with_capacity(1024),
            offset: 0,
            in_step: true,
            quiet: false,
            ended: false,
            noise: None,
            expect: None,
            awaiting: None,
            lost: false,
        }
    }

    /// Bytes without timing (a file, a TCP segment).
    pub fn push(&mut self, bytes: &[u8], out: &mut Vec<Event>) {
        self.quiet = false;
        self.buffer.extend_from_slice(bytes);
        self.times.resize(self.buffer.len(), None);
        self.scan(out);
    }

    /// Bytes read together, the last of them at `time`: earlier ones are placed one
    /// character time apart before it, as they travelled.
    pub fn push_at(&mut self, bytes: &[u8], time: u64, out: &mut Vec<Event>) {
        let Some(last) = bytes.len().checked_sub(1) else {
            return;
        };
        let first_time = time.saturating_sub((last as f64 * self.char_us) as u64);
        self.settle_before(first_time, out);
        for (i, byte) in bytes.iter().enumerate() {
            let back = ((last - i) as f64 * self.char_us) as u64;
            self.buffer.push(*byte);
            self.times.push(Some(time.saturating_sub(back)));
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
        self.quiet = true;
        self.ended = true;
        self.scan(out);
        self.flush_noise(out);
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

    /// Forgets the bytes not yet framed and starts in step, as after silence.
    pub fn clear(&mut self) {
        self.offset += self.buffer.len() as u64;
        self.buffer.clear();
        self.times.clear();
        self.noise = None;
        self.in_step = true;
        self.quiet = false;
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

    /// Whether the line has been silent since the last byte, by `now`.
    fn silent_since_last(&self, now: u64) -> bool {
        match self.times.last() {
            Some(Some(last)) => self.is_silence(*last, now),
            _ => false,
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
        match (
            self.times.get(i).copied().flatten(),
            self.times.get(i + 1).copied().flatten(),
        ) {
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
                Mode::Tcp => self.look_tcp(at),
            };
            match look {
                Look::Frame {
                    len,
                    broken,
                    direction,
                } => {
                    self.flush_noise(out);
                    let found = Found {
                        bytes: self.buffer[at..at + len].to_vec(),
                        offset: self.offset + at as u64,
                        start: self.times[at],
                        end: self.times[at + len - 1],
                        broken,
                        direction,
                    };
                    if broken.is_none() {
                        self.turn(&found);
                    }
                    out.push(Event::Frame(found));
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
        self.times.drain(..at);
        self.offset += at as u64;
        self.in_step = in_step;
        if self.ended {
            self.flush_noise(out);
        }
    }

    /// A frame was taken: the bus's turn passes, and a request awaits its answer.
    fn turn(&mut self, found: &Found) {
        // A frame that reads both ways passes the turn all the same.
        match found.direction.or(self.expect) {
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
        let noise = self.noise.get_or_insert_with(|| Noise {
            kept: Vec::new(),
            len: 0,
            offset: self.offset + at as u64,
            start: self.times[at],
        });
        let room = NOISE_KEPT.saturating_sub(noise.kept.len()).min(count);
        noise.kept.extend_from_slice(&self.buffer[at..at + room]);
        noise.len += count as u64;
    }

    fn flush_noise(&mut self, out: &mut Vec<Event>) {
        if let Some(noise) = self.noise.take() {
            out.push(Event::Noise(noise));
        }
    }

    // ---- RTU ----

    fn look_rtu(&self, at: usize, in_step: bool) -> Look {
        let found = self.candidates(at);
        // A frame cut short may still complete (a USB adapter pauses inside frames), unless
        // silence came and a whole frame of known layout after its start shows it never
        // will.
        let cut_off =
            self.ended || (self.quiet && self.inner_frame_end(at, self.buffer.len()).is_some());
        let may_complete = !found.pending.is_empty() && !cut_off;
        if found.valid.is_empty() {
            if may_complete {
                return Look::NeedMore;
            }
            return self.broken_or_noise(at, in_step);
        }
        // In step, the answer a request awaits stands on its CRC and is complete on its
        // last byte: its length comes from its layout, so neither a reading against the
        // turn nor the silence after it is worth a wait (a master would wait out its
        // silence, or its timeout, for every answer ending in 00).
        if in_step {
            let awaited = found.valid.iter().find(|c| {
                let frame = &self.buffer[at..at + c.len];
                c.known_layout
                    && self.answers_awaited(frame, c.direction)
                    && pdu_reads(frame, Some(Direction::Response), false)
            });
            if let Some(answer) = awaited {
                return frame_of(answer);
            }
        }
        // While a reading that could be preferred may still complete, wait for it, unless
        // silence says no more is coming: one in the direction the bus expects (any, when
        // it expects nothing), or one a byte longer (a frame ending in 00 leaves its prefix
        // valid too).
        let expected = |direction: Option<Direction>| match (self.expect, direction) {
            (Some(expected), Some(direction)) => direction == expected,
            _ => true,
        };
        let waits = match self.expect {
            Some(direction) => {
                found.pending.iter().any(|(d, _)| *d == direction)
                    && !found.valid.iter().any(|c| expected(c.direction))
            }
            None => true,
        } || found
            .pending
            .iter()
            .any(|(_, len)| found.valid.iter().any(|c| Some(c.len + 1) == *len));
        if waits && may_complete && !self.quiet {
            return Look::NeedMore;
        }
        let mut acceptable: Vec<Candidate> = Vec::with_capacity(found.valid.len());
        for candidate in &found.valid {
            // In step with the bus, a frame of known layout on its turn stands on its CRC;
            // one against the turn needs what follows it too. While a request awaits its
            // answer, only that answer is on the turn.
            let frame = &self.buffer[at..at + candidate.len];
            let on_turn = match self.expect {
                Some(Direction::Response) => {
                    candidate.direction != Some(Direction::Request)
                        && (self.awaiting.is_none()
                            || self.answers_awaited(frame, candidate.direction))
                }
                _ => expected(candidate.direction),
            };
            let tell = if in_step && candidate.known_layout && on_turn {
                // One whose PDU does not read is a master's mistake to be shown, or bytes
                // that only happen to pass: what follows must be sound too.
                if pdu_reads(frame, candidate.direction, false) {
                    Tell::Yes
                } else {
                    self.followed_well(at + candidate.len, 1, true, self.asked_by(at, candidate))
                }
            } else {
                self.supported(at, candidate, 1, in_step)
            };
            match tell {
                Tell::Yes => acceptable.push(*candidate),
                Tell::NotYet => return Look::NeedMore,
                Tell::No => {}
            }
        }
        let chosen = match acceptable.as_slice() {
            [] => None,
            [one] => Some(*one),
            several => match self.choose(at, several, expected) {
                Ok(choice) => Some(choice),
                Err(()) => return Look::NeedMore,
            },
        };
        match chosen {
            Some(candidate) => frame_of(&candidate),
            None if may_complete => Look::NeedMore,
            None => self.broken_or_noise(at, in_step),
        }
    }

    /// Of several readings that would all do (shortest first): the one in the direction
    /// the bus expects, unless a shorter one against the turn is followed by a frame and
    /// it is not (the 00 that seemed to end it starts the next frame). Where the turn does
    /// not tell, the shortest right after which a frame or silence follows, then one
    /// followed so past 00 bytes, then the shortest. `Err` while what follows is not here.
    fn choose(
        &self,
        at: usize,
        several: &[Candidate],
        expected: impl Fn(Option<Direction>) -> bool,
    ) -> Result<Candidate, ()> {
        let followed = |candidate: &Candidate, past_runs| {
            self.followed_well(
                at + candidate.len,
                1,
                past_runs,
                self.asked_by(at, candidate),
            )
        };
        let on_turn: Vec<Candidate> = several
            .iter()
            .filter(|c| self.expect.is_some() && c.direction.is_some() && expected(c.direction))
            .copied()
            .collect();
        if let Some(primary) = on_turn.first() {
            let primary_followed = followed(primary, false);
            if primary_followed == Tell::NotYet {
                return Err(());
            }
            if primary_followed == Tell::No {
                for shorter in several.iter().filter(|c| c.len < primary.len) {
                    match followed(shorter, false) {
                        Tell::Yes => return Ok(*shorter),
                        Tell::NotYet => return Err(()),
                        Tell::No => {}
                    }
                }
            }
            return Ok(*primary);
        }
        for past_zeros in [false, true] {
            for candidate in several {
                match followed(candidate, past_zeros) {
                    Tell::Yes => return Ok(*candidate),
                    Tell::NotYet => return Err(()),
                    Tell::No => {}
                }
            }
        }
        Ok(several[0])
    }

    /// The readings of the bytes at `at` whose CRC holds, and the directions still waiting
    /// for bytes.
    fn candidates(&self, at: usize) -> Candidates {
        let data = &self.buffer[at..];
        let mut found = Candidates::default();
        let mut unknown_done = false;
        for direction in [Direction::Request, Direction::Response] {
            match rtu_frame_length(data, direction) {
                Length::Known(len) if (MIN_RTU_FRAME..=MAX_RTU_ADU).contains(&len) => {
                    match data.get(..len) {
                        Some(frame) if crc_holds(frame) => found.add(len, direction, true),
                        Some(_) => {}
                        None => found.pending.push((direction, Some(len))),
                    }
                }
                Length::AtLeast(_) => found.pending.push((direction, None)),
                // The same CRC scan serves both directions.
                Length::Unknown if may_lack_layout(data) && !unknown_done => {
                    unknown_done = true;
                    let (lengths, pending) = self.unknown_lengths(at);
                    for len in lengths {
                        found.add(len, Direction::Request, false);
                        found.add(len, Direction::Response, false);
                    }
                    if pending {
                        found.pending.push((Direction::Request, None));
                        found.pending.push((Direction::Response, None));
                    }
                }
                _ => {}
            }
        }
        found.valid.sort_unstable_by_key(|c| c.len);
        found
    }

    /// A function without a known layout: every length whose CRC holds, save those that
    /// only add 00 bytes to a shorter one (the CRC of a frame and its own CRC is zero). No
    /// length may swallow a whole frame of known layout. Also says whether more bytes could
    /// still give a length.
    fn unknown_lengths(&self, at: usize) -> (Vec<usize>, bool) {
        let data = &self.buffer[at..];
        let reach = data.len().min(MAX_RTU_ADU);
        let inner_end = self.inner_frame_end(at, at + reach);
        let limit = inner_end.map_or(reach, |end| end - at - 1);
        let lengths = crc_matches(data, MIN_RTU_FRAME, limit)
            .into_iter()
            .filter(|len| len - 2 < MIN_RTU_FRAME || data[len - 2..*len] != [0, 0])
            .collect();
        let more_could_come =
            inner_end.is_none() && data.len() < MAX_RTU_ADU && !self.quiet && !self.ended;
        (lengths, more_could_come)
    }

    /// Where the first whole frame of known layout that lies entirely after `at` and
    /// before `end` ends. Only whole frames count, so that the answer depends on the
    /// bytes and not on when they came.
    fn inner_frame_end(&self, at: usize, end: usize) -> Option<usize> {
        let end = end.min(self.buffer.len());
        (at + 1..end.saturating_sub(MIN_RTU_FRAME - 1))
            .filter_map(|inner| self.known_frame_len(inner, end).map(|len| inner + len))
            .min()
    }

    /// The length of the whole frame of known layout, CRC and PDU sound, at `at` and ending
    /// by `end`.
    fn known_frame_len(&self, at: usize, end: usize) -> Option<usize> {
        let data = &self.buffer[at..end.min(self.buffer.len())];
        [Direction::Request, Direction::Response]
            .into_iter()
            .find_map(|direction| match rtu_frame_length(data, direction) {
                Length::Known(len) if (MIN_RTU_FRAME..=MAX_RTU_ADU).contains(&len) => data
                    .get(..len)
                    .filter(|frame| crc_holds(frame) && pdu_reads(frame, Some(direction), true))
                    .map(|_| len),
                _ => None,
            })
    }

    /// Whether what follows the candidate at `at` supports it as a frame. `in_step`: it
    /// follows a frame or silence, so that a frame of known layout needs what stands right
    /// after it, not a frame further on, and one of unknown layout may be followed past a
    /// run of 00 or FF.
    fn supported(&self, at: usize, candidate: &Candidate, depth: u8, in_step: bool) -> Tell {
        let frame = &self.buffer[at..at + candidate.len];
        let end = at + candidate.len;
        // After noise a frame must come from an address a serial line uses (1-247, or 0
        // to broadcast; 248-255 are reserved), and one of known layout must read as a PDU.
        if !in_step && frame.first().is_some_and(|slave| *slave > MAX_SLAVE) {
            return Tell::No;
        }
        if candidate.known_layout && !pdu_reads(frame, candidate.direction, !in_step) {
            return Tell::No;
        }
        let tell = self.followed_or_answered(at, candidate, depth, in_step);
        // Nor may it swallow a whole frame, unless it is the answer awaited. What follows
        // is cheaper to tell, so it is asked first.
        if tell == Tell::Yes
            && candidate.known_layout
            && !in_step
            && !self.answers_awaited(frame, candidate.direction)
            && self.inner_frame_end(at, end).is_some()
        {
            return Tell::No;
        }
        tell
    }

    /// The support of `supported` past the candidate's own bytes: silence, the conversation,
    /// the end of the input, or what follows.
    fn followed_or_answered(
        &self,
        at: usize,
        candidate: &Candidate,
        depth: u8,
        in_step: bool,
    ) -> Tell {
        let frame = &self.buffer[at..at + candidate.len];
        let end = at + candidate.len;
        // A frame of unknown layout may be any length, so that bytes that broke on the way
        // pass their CRC by borrowing the start of the next frame far more often.
        if !candidate.known_layout && !self.silence_after(end - 1) {
            match self.overlapped(at, end) {
                Tell::Yes => return Tell::No,
                Tell::NotYet => return Tell::NotYet,
                Tell::No => {}
            }
        }
        if self.silence_after(end - 1) || self.answers_awaited(frame, candidate.direction) {
            return Tell::Yes;
        }
        if end == self.buffer.len() {
            return if self.ended { Tell::Yes } else { Tell::NotYet };
        }
        // A frame without a known layout must be followed right after it, or past a run of
        // 00 or FF only in step; one of known layout may be followed past such a run, and,
        // after noise, by a frame further on.
        let past_runs = candidate.known_layout || in_step;
        let asked = self.asked_by(at, candidate);
        match self.followed_well(end, depth, past_runs, asked) {
            Tell::No if candidate.known_layout && !in_step => match self.overlapped(at, end) {
                Tell::No => self.frame_further_on(end),
                Tell::Yes => Tell::No,
                Tell::NotYet => Tell::NotYet,
            },
            // A request of unknown layout is supported by its answer further on too, past
            // a run of 00 or FF or a frame that broke on the way.
            Tell::No => match asked {
                Some(asked) if !candidate.known_layout => self.answer_further_on(end, asked),
                _ => Tell::No,
            },
            tell => tell,
        }
    }

    /// Whether a valid frame starts right at `at` (of known layout, the answer to
    /// `asked`, or itself supported), or silence or the end of the input is there.
    /// `past_runs`: after a run of 00 or FF bytes, which is what a line held low or
    /// glitching gives, not data.
    fn followed_well(
        &self,
        at: usize,
        depth: u8,
        past_runs: bool,
        asked: Option<(u8, u8)>,
    ) -> Tell {
        if past_runs {
            let run = line_state_run(&self.buffer[at.min(self.buffer.len())..]);
            if run > 0 {
                // The run's last byte may be the address of a broadcast.
                return match self.followed_well(at + run - 1, depth, false, asked) {
                    Tell::No => self.followed_well(at + run, depth, false, asked),
                    tell => tell,
                };
            }
        }
        if at >= self.buffer.len() {
            return if self.quiet || self.ended {
                Tell::Yes
            } else {
                Tell::NotYet
            };
        }
        if self.silence_after(at - 1) {
            return Tell::Yes;
        }
        let next = self.candidates(at);
        if next.valid.iter().any(|c| c.known_layout)
            || asked.is_some_and(|asked| self.answer_at(at, asked) == Tell::Yes)
        {
            return Tell::Yes;
        }
        if depth > 0 {
            for candidate in &next.valid {
                match self.supported(at, candidate, depth - 1, true) {
                    Tell::Yes => return Tell::Yes,
                    Tell::NotYet => return Tell::NotYet,
                    Tell::No => {}
                }
            }
        }
        if !next.pending.is_empty() && !self.ended && !self.quiet {
            return Tell::NotYet;
        }
        Tell::No
    }

    /// Whether the answer to `asked` starts within the longest frame's reach after `at`,
    /// past 00 or FF bytes.
    fn answer_further_on(&self, at: usize, asked: (u8, u8)) -> Tell {
        let at = after_run(&self.buffer, at);
        let reach = at + MAX_RTU_ADU;
        for p in at..reach.min(self.buffer.len()) {
            match self.answer_at(p, asked) {
                Tell::Yes => return Tell::Yes,
                Tell::NotYet => return Tell::NotYet,
                Tell::No => {}
            }
        }
        if reach > self.buffer.len() && !self.quiet && !self.ended {
            return Tell::NotYet;
        }
        Tell::No
    }

    /// Whether a frame whose CRC holds, with the slave and function `asked` for, starts at
    /// `at`.
    fn answer_at(&self, at: usize, (slave, function): (u8, u8)) -> Tell {
        match self.buffer.get(at..at + 2) {
            Some([s, f]) if *s == slave && f & !EXCEPTION_FLAG == function => {
                let next = self.candidates(at);
                if !next.valid.is_empty() {
                    Tell::Yes
                } else if !next.pending.is_empty() && !self.ended && !self.quiet {
                    Tell::NotYet
                } else {
                    Tell::No
                }
            }
            Some(_) => Tell::No,
            None if self.ended || self.quiet => Tell::No,
            None => Tell::NotYet,
        }
    }

    /// Whether a frame starts inside `at..end` and runs past its end, of known layout, CRC
    /// and PDU sound, or of unknown layout and followed well: then the bytes at `at` make
    /// a frame only by borrowing the start of another.
    fn overlapped(&self, at: usize, end: usize) -> Tell {
        let mut more_could_come = false;
        for inner in at + 1..end {
            if self
                .known_frame_len(inner, self.buffer.len())
                .is_some_and(|len| inner + len > end)
            {
                return Tell::Yes;
            }
            let found = self.candidates(inner);
            more_could_come |= !found.pending.is_empty();
            for candidate in found.valid.iter().filter(|c| inner + c.len > end) {
                if candidate.known_layout {
                    continue;
                }
                let asked = self.asked_by(inner, candidate);
                match self.followed_well(inner + candidate.len, 0, false, asked) {
                    Tell::Yes => return Tell::Yes,
                    Tell::NotYet => more_could_come = true,
                    Tell::No => {}
                }
            }
        }
        if more_could_come && !self.quiet && !self.ended {
            Tell::NotYet
        } else {
            Tell::No
        }
    }

    /// Whether a frame of known layout, CRC and PDU sound, starts within the longest
    /// frame's reach after `at`, past bytes that are no frame.
    fn frame_further_on(&self, at: usize) -> Tell {
        let at = after_run(&self.buffer, at);
        let reach = at + MAX_RTU_ADU;
        if (at..reach.min(self.buffer.len()))
            .any(|p| self.known_frame_len(p, self.buffer.len()).is_some())
        {
            return Tell::Yes;
        }
        if reach > self.buffer.len() && !self.quiet && !self.ended {
            return Tell::NotYet;
        }
        Tell::No
    }

    /// The slave and function a candidate asks for, when it can be a request: a request
    /// is supported by its answer right after it.
    fn asked_by(&self, at: usize, candidate: &Candidate) -> Option<(u8, u8)> {
        match (candidate.direction, self.buffer.get(at..at + 2)) {
            (Some(Direction::Response), _) => None,
            (_, Some([slave, function])) => Some((*slave, function & !EXCEPTION_FLAG)),
            _ => None,
        }
    }

    /// Whether `frame` is the answer the last request awaits: its slave and function.
    fn answers_awaited(&self, frame: &[u8], direction: Option<Direction>) -> bool {
        direction != Some(Direction::Request)
            && matches!((frame, self.awaiting), ([slave, function, ..], Some((s, f)))
                if *slave == s && *function & !EXCEPTION_FLAG == f)
    }

    /// The bytes at `at` as a frame of known layout whose CRC fails, or else as noise. A
    /// broken frame is a request in step with the bus, or the answer a request awaits; it
    /// must end where a frame, silence or the end of the input follows, and hold no valid
    /// frame. Random bytes are noise.
    fn broken_or_noise(&self, at: usize, in_step: bool) -> Look {
        match self.broken(at, in_step) {
            (Tell::Yes, Some((len, direction))) => Look::Frame {
                len,
                broken: Some(Broken::Checksum),
                direction: Some(direction),
            },
            (Tell::NotYet, _) => Look::NeedMore,
            _ => Look::Noise,
        }
    }

    fn broken(&self, at: usize, in_step: bool) -> (Tell, Option<(usize, Direction)>) {
        let data = &self.buffer[at..];
        let mut lengths: Vec<(usize, Direction)> = [Direction::Request, Direction::Response]
            .into_iter()
            .filter_map(|direction| match rtu_frame_length(data, direction) {
                Length::Known(len)
                    if (MIN_RTU_FRAME..=MAX_RTU_ADU).contains(&len) && len <= data.len() =>
                {
                    Some((len, direction))
                }
                _ => None,
            })
            .collect();
        lengths.sort_unstable_by_key(|(len, _)| *len);
        for (len, direction) in lengths {
            let frame = &data[..len];
            let plausible = match direction {
                Direction::Request => in_step,
                Direction::Response => self.answers_awaited(frame, Some(direction)),
            };
            if !plausible {
                continue;
            }
            // What follows first: it is cheaper to tell than what lies inside.
            match self.followed_well(at + len, 0, false, None) {
                Tell::Yes
                    if self.inner_frame_end(at, at + len).is_none()
                        && !self.holds_unknown_frame(at, at + len) =>
                {
                    return (Tell::Yes, Some((len, direction)))
                }
                Tell::NotYet => return (Tell::NotYet, None),
                _ => {}
            }
        }
        (Tell::No, None)
    }

    /// Whether a frame of a function without a known layout, its CRC sound, lies inside
    /// `at..end` after its first byte.
    fn holds_unknown_frame(&self, at: usize, end: usize) -> bool {
        (at + 1..end).any(|inner| {
            let data = &self.buffer[inner..end];
            may_lack_layout(data) && !crc_matches(data, MIN_RTU_FRAME, data.len()).is_empty()
        })
    }

    // ---- ASCII ----

    fn look_ascii(&self, at: usize) -> Look {
        let data = &self.buffer[at..];
        if data[0] != b':' {
            return Look::Noise;
        }
        let incomplete = |len: usize| Look::Frame {
            len,
            broken: Some(Broken::Incomplete),
            direction: None,
        };
        for i in 1..data.len() {
            // A pause longer than the character timeout cuts the frame off.
            if self.silence_after(at + i - 1) {
                return incomplete(i);
            }
            match data[i] {
                b':' => return incomplete(i),
                b'\n' => {
                    let frame = &data[..=i];
                    return Look::Frame {
                        len: i + 1,
                        broken: (!lrc_holds(frame)).then_some(Broken::Checksum),
                        direction: None,
                    };
                }
                _ => {}
            }
        }
        if data.len() >= MAX_ASCII_ADU {
            incomplete(MAX_ASCII_ADU)
        } else if self.quiet || self.ended {
            incomplete(data.len())
        } else {
            Look::NeedMore
        }
    }

    // ---- TCP ----

    fn look_tcp(&self, at: usize) -> Look {
        if self.lost {
            return Look::Lost;
        }
        let data = &self.buffer[at..];
        if let Some([hi, lo]) = data.get(2..4) {
            if [*hi, *lo] != [0, 0] {
                return Look::Lost;
            }
        }
        match tcp_frame_length(data) {
            // Unit id and function at least; at most a whole PDU.
            Length::Known(len) if !(8..=MAX_TCP_ADU).contains(&len) => Look::Lost,
            Length::Known(len) if len <= data.len() => Look::Frame {
                len,
                broken: None,
                direction: None,
            },
            _ if self.ended => Look::Lost,
            _ => Look::NeedMore,
        }
    }
}

/// A function code that may be a frame without a layout the codec knows: user-defined
/// (65-72, 100-110) or an MEI type other than read device identification. Any other code
/// without a layout is no public or user function, and no frame.
fn may_lack_layout(frame: &[u8]) -> bool {
    match (frame.get(1), frame.get(2)) {
        (Some(65..=72 | 100..=110), _) => true,
        (Some(&ENCAPSULATED_INTERFACE), Some(mei)) => *mei != MEI_READ_DEVICE_IDENTIFICATION,
        _ => false,
    }
}

/// Where a frame may start after the run of 00 or FF at `at`: at its last byte, which may
/// be the address of a broadcast.
fn after_run(buffer: &[u8], at: usize) -> usize {
    at + line_state_run(&buffer[at..]).saturating_sub(1)
}

/// How many bytes at the start of `bytes` are a run of 00 or FF: a line held low, or
/// glitching, rather than data.
fn line_state_run(bytes: &[u8]) -> usize {
    match bytes.first() {
        Some(&run @ (0x00 | 0xFF)) => bytes.iter().take_while(|b| **b == run).count(),
        _ => 0,
    }
}

/// Whether the PDU inside an RTU frame reads in `direction` (either, for `None`).
/// `after_noise`: an exception must also answer a defined function with a defined code, as
/// a frame found after noise must, being found among bytes that pass their CRC by chance.
fn pdu_reads(frame: &[u8], direction: Option<Direction>, after_noise: bool) -> bool {
    let Some(pdu) = frame.get(1..frame.len().saturating_sub(2)) else {
        return false;
    };
    let reads = |direction| match Pdu::decode(pdu, direction) {
        Ok(Pdu::Exception(exception)) => {
            !after_noise
                || (exception.code.is_defined() && function::is_defined(exception.function))
        }
        Ok(_) => true,
        Err(_) => false,
    };
    match direction {
        Some(direction) => reads(direction),
        None => reads(Direction::Request) || reads(Direction::Response),
    }
}

/// Whether an ASCII frame (':' hex LRC CR LF) is well formed and its LRC holds.
fn lrc_holds(frame: &[u8]) -> bool {
    let Some(body) = frame
        .strip_prefix(b":")
        .and_then(|b| b.strip_suffix(b"\r\n"))
    else {
        return false;
    };
    if body.len() < 6 || body.len() % 2 != 0 {
        return false;
    }
    let bytes: Option<Vec<u8>> = body
        .chunks_exact(2)
        .map(|pair| {
            std::str::from_utf8(pair)
                .ok()
                .and_then(|s| u8::from_str_radix(s, 16).ok())
        })
        .collect();
    match bytes.as_deref() {
        Some([data @ .., check]) => lrc(data) == *check,
        _ => false,
    }
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
            Event::Frame(found) if found.broken.is_none() => Some(found.bytes),
            _ => None,
        })
        .collect::<Option<_>>()?;
    (frames.len() >= 2).then_some(frames)
}

#[cfg(test)]
mod tests {
    use super::*;

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
    use crate::codec::checksum::crc16;

    const REQUEST: [u8; 8] = [0x11, 0x03, 0x00, 0x6B, 0x00, 0x03, 0x76, 0x87];
    const ANSWER: [u8; 11] = [
        0x11, 0x03, 0x06, 0x02, 0x2B, 0x00, 0x00, 0x00, 0x64, 0xC8, 0xBA,
    ];

    fn rtu(body: &[u8]) -> Vec<u8> {
        let mut frame = body.to_vec();
        frame.extend_from_slice(&crc16(body).to_le_bytes());
        frame
    }

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

    /// The valid frames of `stream`.
    fn frames(stream: &[u8]) -> Vec<Vec<u8>> {
        events(Mode::Rtu, stream)
            .into_iter()
            .filter_map(|e| match e {
                Event::Frame(f) if f.broken.is_none() => Some(f.bytes),
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
    fn byte_by_byte_and_all_at_once_agree() {
        let mut stream = vec![0x00, 0xFE];
        stream.extend_from_slice(&REQUEST);
        stream.extend_from_slice(&ANSWER);
        let whole = events(Mode::Rtu, &stream);
        let mut single = Vec::new();
        let mut framer = framer(Mode::Rtu);
        for byte in &stream {
            framer.push(&[*byte], &mut single);
        }
        framer.finish(&mut single);
        assert_eq!(whole, single);
    }

    #[test]
    fn a_corrupt_request_followed_by_its_answer_is_a_crc_error() {
        let mut bad = REQUEST;
        bad[7] ^= 0xFF;
        let mut stream = bad.to_vec();
        stream.extend_from_slice(&ANSWER);
        let out = events(Mode::Rtu, &stream);
        assert!(
            matches!(&out[0], Event::Frame(f) if f.broken == Some(Broken::Checksum) && f.bytes == bad)
        );
        assert!(matches!(&out[1], Event::Frame(f) if f.broken.is_none() && f.bytes == ANSWER));
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
        assert!(matches!(out.last(), Some(Event::Frame(f)) if f.bytes == REQUEST));
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
        assert!(matches!(&out[0], Event::Noise(n) if n.kept == b"xx"));
        assert!(matches!(&out[1], Event::Frame(f) if f.broken.is_none()));
        assert!(
            matches!(&out[2], Event::Frame(f) if f.broken == Some(Broken::Incomplete) && f.bytes == b":1103006B")
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
