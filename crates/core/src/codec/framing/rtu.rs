//! RTU: a frame's length from its function code and byte count, its CRC, and what the
//! bytes at a position could be when they make no frame yet.

use smallvec::SmallVec;

use crate::codec::checksum::crc_matches;
use crate::codec::length::{rtu_frame_length, sized, Length};
use crate::codec::limits::MAX_RTU_ADU;
use crate::codec::Direction;

use super::resync::Tell;
use super::resync::{may_lack_layout, pdu_reads};
use super::{Broken, Candidate, Framer, Look, MAX_SLAVE, MIN_RTU_FRAME};

/// What the bytes at one position could be.
#[derive(Default)]
pub(super) struct Candidates {
    /// Lengths whose CRC holds, shortest first. Inline: a position is looked at several
    /// times for every frame, and rarely holds more than two readings.
    pub(super) valid: SmallVec<[Candidate; 2]>,
    /// Directions in which more bytes could still make a frame here, with the length
    /// awaited when the layout tells it.
    pub(super) pending: SmallVec<[(Direction, Option<usize>); 2]>,
}

impl Candidates {
    pub(super) fn add(&mut self, len: usize, direction: Direction, known_layout: bool) {
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

pub(super) fn frame_of(candidate: &Candidate) -> Look {
    Look::Frame {
        len: candidate.len,
        broken: None,
        direction: candidate.direction,
    }
}

impl Framer {
    pub(super) fn look_rtu(&self, at: usize, in_step: bool) -> Look {
        let mut found = Candidates::default();
        self.find_candidates(at, &mut found);
        // A reading across a silence is the times lying (a USB adapter's latency timer),
        // unless a whole frame starts right after the silence: then the silence was real
        // and the reading borrowed that frame's first bytes.
        let silence = self.silence_within(at);
        if let Some(end) = silence {
            if found.valid.iter().any(|c| at + c.len > end) {
                match self.frame_starts(end) {
                    Tell::Yes => found.valid.retain(|c| at + c.len <= end),
                    Tell::NotYet => return Look::NeedMore,
                    Tell::No => {}
                }
            }
        }
        // A frame cut short may still complete (a USB adapter pauses inside frames), unless
        // silence came and a whole frame of known layout after its start shows it never
        // will.
        let cut_off =
            self.ended || (self.quiet && self.inner_frame_end(at, self.buffer.len()).is_some());
        let may_complete = !found.pending.is_empty() && !cut_off;
        if found.valid.is_empty() {
            if let Some(end) = silence {
                match self.ended_by_silence(at, end, may_complete) {
                    Tell::Yes => return self.cut_short(at, end, in_step),
                    Tell::NotYet => return Look::NeedMore,
                    Tell::No => {}
                }
            }
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
        let mut acceptable: SmallVec<[Candidate; 4]> = SmallVec::new();
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
    pub(super) fn choose(
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
        let on_turn = several
            .iter()
            .find(|c| self.expect.is_some() && c.direction.is_some() && expected(c.direction));
        if let Some(primary) = on_turn {
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
                // A frame ending in 00 leaves its prefix valid too: where the silence falls
                // after the longer reading and not after the one on the turn, the longer
                // one is the frame (an answer whose request was lost, say); unless the one
                // on the turn is answered past that 00, a turnaround glitch. So too where a
                // frame follows right after the longer one: the one on the turn is then
                // bytes of it that pass a CRC by chance (the start of a long request).
                let mut longer = None;
                for candidate in several.iter().filter(|c| c.len > primary.len) {
                    let ends_well = if self.silence_after(at + candidate.len - 1) {
                        Tell::Yes
                    } else {
                        followed(candidate, false)
                    };
                    match ends_well {
                        Tell::Yes => {
                            longer = Some(candidate);
                            break;
                        }
                        Tell::NotYet => return Err(()),
                        Tell::No => {}
                    }
                }
                if let Some(longer) = longer {
                    match self.asked_by(at, primary) {
                        Some(asked) => match self.answer_further_on(at + primary.len, asked) {
                            Tell::Yes => {}
                            Tell::NotYet => return Err(()),
                            Tell::No => return Ok(*longer),
                        },
                        None => return Ok(*longer),
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
    #[inline(always)]
    pub(super) fn candidates(&self, at: usize) -> Candidates {
        let mut found = Candidates::default();
        self.find_candidates(at, &mut found);
        found
    }

    /// [`Self::candidates`], written where the caller keeps them. Returned, they were
    /// copied from one place on the stack to another right after being written field by
    /// field, and the copy's wide loads waited on those narrow stores: about an eighth of
    /// the time of the thread framing ahead.
    #[inline(always)]
    pub(super) fn find_candidates(&self, at: usize, found: &mut Candidates) {
        let data = &self.buffer[at..];
        // Most bytes of a noisy line begin no frame either way: told by one lookup.
        if data.get(1).is_some_and(|function| !sized(*function)) && !may_lack_layout(data) {
            return;
        }
        let mut unknown_done = false;
        for direction in [Direction::Request, Direction::Response] {
            match rtu_frame_length(data, direction) {
                Length::Known(len) if (MIN_RTU_FRAME..=MAX_RTU_ADU).contains(&len) => {
                    match data.get(..len) {
                        Some(_) if self.crc_holds_at(at, len) => found.add(len, direction, true),
                        Some(_) => {}
                        None => found.pending.push((direction, Some(len))),
                    }
                }
                // An answer whose length is still being told (a device identification's
                // objects) waits for more bytes only while it may still fit a frame.
                Length::AtLeast(len) if len <= MAX_RTU_ADU => found.pending.push((direction, None)),
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
        // Read a byte at a time, a line's silences are its own (no adapter gathers its
        // bytes), and a silence ends a frame as it does for every receiver on the bus: no
        // reading runs across one, whatever CRC its bytes pass. Nor, however the line is
        // read, across a gap longer than an adapter makes.
        if !self.times.is_empty() {
            found
                .valid
                .retain(|c| !self.crosses_silence(at, at + c.len));
        }
        found.valid.sort_unstable_by_key(|c| c.len);
    }

    /// A function without a known layout: every length whose CRC holds, save those that
    /// only add 00 bytes to a shorter one (the CRC of a frame and its own CRC is zero),
    /// unless the line's times show its silence after the 00 bytes and not before them:
    /// then they are the frame's own (its data ends with the CRC of what precedes it). No
    /// length may swallow a whole frame of known layout. Also says whether more bytes could
    /// still give a length.
    pub(super) fn unknown_lengths(&self, at: usize) -> (Vec<usize>, bool) {
        let data = &self.buffer[at..];
        let reach = data.len().min(MAX_RTU_ADU);
        // One pass finds the lengths whose CRC holds; the frames inside, which cost a CRC
        // at every position, are looked for only where they can change the answer.
        let matches = crc_matches(data, MIN_RTU_FRAME, reach);
        let could_grow = data.len() < MAX_RTU_ADU && self.last_bytes_may_grow();
        // A frame inside that ends after the longest length whose CRC holds removes none of
        // them: where no more bytes can give a length, none is looked for past it.
        let inner_end = match (matches.last(), could_grow) {
            (_, true) => self.inner_frame_end(at, at + reach),
            (Some(longest), false) => self.inner_frame_end(at, at + longest),
            (None, false) => None,
        };
        let limit = inner_end.map_or(reach, |end| end - at - 1);
        let lengths = matches
            .into_iter()
            .filter(|len| *len <= limit)
            .filter(|len| {
                len - 2 < MIN_RTU_FRAME
                    || data[len - 2..*len] != [0, 0]
                    || self.zeros_end_it(at, *len)
            })
            .collect();
        (lengths, could_grow && inner_end.is_none())
    }

    /// Whether the frame of `len` bytes at `at`, its last two 00, ends where the line's
    /// silence says: silence after the two 00 bytes and none before them, whether the line
    /// is read a byte at a time or a frame a read. Not after a third 00: a longer run of
    /// them is a line held low after the frame, not its CRC.
    fn zeros_end_it(&self, at: usize, len: usize) -> bool {
        self.times_tell_silence()
            && self.buffer[at + len - 3] != 0
            && self.silence_after(at + len - 1)
            && !self.silence_after(at + len - 3)
    }

    /// Where the first whole frame of known layout that lies entirely after `at` and
    /// before `end` ends. Only whole frames count, so that the answer depends on the
    /// bytes and not on when they came.
    pub(super) fn inner_frame_end(&self, at: usize, end: usize) -> Option<usize> {
        let mut end = end.min(self.buffer.len());
        let mut first_end = None;
        let mut inner = at + 1;
        // Once a frame is found, one that ends sooner must end by its end, and so start
        // at least MIN_RTU_FRAME bytes before it: each CRC a user-defined frame's lengths
        // cost here is one more per byte it holds.
        while inner + MIN_RTU_FRAME <= end {
            if let Some(len) = self.known_frame_len(inner, end) {
                end = inner + len;
                first_end = Some(end);
            }
            inner += 1;
        }
        first_end
    }

    /// The length of the whole frame of known layout, CRC and PDU sound, at `at` and ending
    /// by `end`.
    pub(super) fn known_frame_len(&self, at: usize, end: usize) -> Option<usize> {
        let data = &self.buffer[at..end.min(self.buffer.len())];
        if data.get(1).is_some_and(|function| !sized(*function)) {
            return None;
        }
        [Direction::Request, Direction::Response]
            .into_iter()
            .find_map(|direction| match rtu_frame_length(data, direction) {
                Length::Known(len)
                    if (MIN_RTU_FRAME..=MAX_RTU_ADU).contains(&len)
                        && len <= data.len()
                        && self.crc_holds_at(at, len)
                        && pdu_reads(&data[..len], Some(direction), true) =>
                {
                    self.latest_sound
                        .found(self.offset + at as u64, len, direction);
                    Some(len)
                }
                _ => None,
            })
    }

    /// Whether a whole frame starts at `at`, right after a silence: of known layout, CRC and
    /// PDU sound, or one whose CRC holds and that what follows supports. A CRC alone passes
    /// by chance too often to outweigh a frame that runs across the silence.
    fn frame_starts(&self, at: usize) -> Tell {
        if self.known_frame_len(at, self.buffer.len()).is_some() {
            return Tell::Yes;
        }
        let found = self.candidates(at);
        for candidate in &found.valid {
            match self.supported(at, candidate, 0, true) {
                Tell::No => {}
                tell => return tell,
            }
        }
        if self.last_bytes_may_grow() && !found.pending.is_empty() {
            Tell::NotYet
        } else {
            Tell::No
        }
    }

    /// Whether the bytes from `at`, which make no frame, were ended by the silence before
    /// `end`. Not when their layout's length ends right there (a CRC error, told as such),
    /// nor when a frame starts among them and runs whole across the silence, of known
    /// layout or followed well (the gap was an adapter's, not the line's). Not yet while
    /// their length, or such a frame, may still come, unless a whole frame starts right
    /// after the silence.
    fn ended_by_silence(&self, at: usize, end: usize, may_complete: bool) -> Tell {
        let data = &self.buffer[at..end];
        // The answer awaited is read as an answer only, anything else as a request: a
        // broken answer is told only where it is awaited.
        let directions: &[Direction] = if self.answers_awaited(data, None) {
            &[Direction::Response]
        } else {
            &[Direction::Request]
        };
        if directions
            .iter()
            .any(|d| matches!(rtu_frame_length(data, *d), Length::Known(len) if len == data.len()))
        {
            return Tell::No;
        }
        let open = self.last_bytes_may_grow();
        let mut crossing_may_come = false;
        for inner in at + 1..end {
            let found = self.candidates(inner);
            for crossing in found.valid.iter().filter(|c| inner + c.len > end) {
                let followed = || {
                    let asked = self.asked_by(inner, crossing);
                    self.followed_well(inner + crossing.len, 0, false, asked)
                };
                if crossing.known_layout || followed() == Tell::Yes {
                    return Tell::No;
                }
            }
            crossing_may_come |= open && !found.pending.is_empty();
        }
        match self.frame_starts(end) {
            Tell::Yes => Tell::Yes,
            Tell::NotYet => Tell::NotYet,
            Tell::No if open && (may_complete || crossing_may_come) => Tell::NotYet,
            Tell::No => Tell::Yes,
        }
    }

    /// The bytes from `at` to `end`, where silence ended them before they made a frame: a
    /// frame cut short where the bus expects a frame to start (in step: the answer awaited,
    /// or a request while no answer is awaited) and no whole frame lies inside them; else
    /// noise, a byte at a time, so that a frame inside them is still found.
    pub(super) fn cut_short(&self, at: usize, end: usize, in_step: bool) -> Look {
        let bytes = &self.buffer[at..end];
        // Whether the bytes begin a frame of that direction that they are too short for.
        let begins = |direction| match rtu_frame_length(bytes, direction) {
            Length::Known(len) => len > bytes.len(),
            Length::AtLeast(_) => true,
            _ => false,
        };
        // The answer awaited of a function without a known layout ends at the silence, its
        // length told by nothing else: whole but for its CRC when it is long enough to hold
        // one, else cut short.
        let unknown_answer = self.answers_awaited(bytes, None) && may_lack_layout(bytes);
        // A lone byte tells no function: a glitch, not a frame.
        let direction = if bytes.len() < 2 || !in_step {
            None
        } else if unknown_answer
            || (self.answers_awaited(bytes, None) && begins(Direction::Response))
        {
            Some(Direction::Response)
        } else if self.awaiting.is_none()
            && self.expect != Some(Direction::Response)
            && bytes[0] <= MAX_SLAVE
            && begins(Direction::Request)
        {
            Some(Direction::Request)
        } else {
            None
        };
        let whole_inside =
            || self.inner_frame_end(at, end).is_some() || self.holds_unknown_frame(at, end);
        match direction {
            Some(direction) if !whole_inside() => match self.refused_request_ends(at, end) {
                Tell::No => Look::Frame {
                    len: end - at,
                    broken: Some(if unknown_answer && bytes.len() >= MIN_RTU_FRAME {
                        Broken::Checksum
                    } else {
                        Broken::Incomplete
                    }),
                    direction: Some(direction),
                },
                Tell::NotYet => Look::NeedMore,
                Tell::Yes => Look::Noise,
            },
            _ => Look::Noise,
        }
    }

    /// Whether a request of known layout, its CRC sound but its PDU not, starts after `at`
    /// and ends at `end`, and its slave refuses it right after: then the bytes before it are
    /// noise glued to it, not the start of a frame cut short.
    fn refused_request_ends(&self, at: usize, end: usize) -> Tell {
        for inner in at + 1..end.saturating_sub(MIN_RTU_FRAME - 1) {
            let len = end - inner;
            let request = &self.buffer[inner..end];
            if rtu_frame_length(request, Direction::Request) == Length::Known(len)
                && self.crc_holds_at(inner, len)
                && !pdu_reads(request, Some(Direction::Request), true)
            {
                let asked = (request[0], request[1]);
                match self.refused_right_after(end, Some(asked)) {
                    Tell::No => {}
                    tell => return tell,
                }
            }
        }
        Tell::No
    }

    /// The bytes at `at` as a frame of known layout whose CRC fails, or else as noise. A
    /// broken frame is a request in step with the bus, or the answer a request awaits; it
    /// must end where a frame, silence or the end of the input follows, and hold no valid
    /// frame. Random bytes are noise.
    pub(super) fn broken_or_noise(&self, at: usize, in_step: bool) -> Look {
        // After noise, only the answer awaited may be a broken frame: elsewhere the bytes
        // before this one say it is noise, and nothing after it need be asked (a noisy
        // line is mostly such bytes).
        if !in_step && !self.answers_awaited(&self.buffer[at..], Some(Direction::Response)) {
            return Look::Noise;
        }
        // A sound frame right after this byte settles it: a broken frame from here would
        // hold that frame or run into it, and neither is taken. Far cheaper to ask than
        // the search, and the common case (a glitch byte at a turnaround). Not where the
        // times show a gap inside them, which the rules about silence decide.
        // So does the answer awaited right after it, of its layout's length and its CRC
        // sound, even where its PDU does not read: it is shown as the sender's mistake,
        // not swallowed into a CRC error that starts at this byte.
        let sound_next = self
            .known_frame_len(at + 1, self.buffer.len())
            .or_else(|| self.awaited_answer_len(at + 1))
            .is_some_and(|len| !(at..at + len).any(|i| self.timed_gap_after(i)));
        if sound_next {
            return Look::Noise;
        }
        match self.broken(at, in_step) {
            // Where its CRC holds after all, no rule above took it because its PDU does
            // not read: a sender's mistake, and no CRC error (those are the line's faults).
            (Tell::Yes, Some((len, direction))) => Look::Frame {
                len,
                broken: Some(if self.crc_holds_at(at, len) {
                    Broken::Malformed
                } else {
                    Broken::Checksum
                }),
                direction: Some(direction),
            },
            (Tell::NotYet, _) => Look::NeedMore,
            _ => Look::Noise,
        }
    }

    /// The length of the answer awaited at `at`, when its layout tells it, its bytes are
    /// all here and its CRC holds, whether or not its PDU reads.
    fn awaited_answer_len(&self, at: usize) -> Option<usize> {
        let data = self.buffer.get(at..)?;
        if !self.answers_awaited(data, Some(Direction::Response)) {
            return None;
        }
        match rtu_frame_length(data, Direction::Response) {
            Length::Known(len)
                if (MIN_RTU_FRAME..=MAX_RTU_ADU).contains(&len)
                    && len <= data.len()
                    && self.crc_holds_at(at, len) =>
            {
                Some(len)
            }
            _ => None,
        }
    }

    pub(super) fn broken(&self, at: usize, in_step: bool) -> (Tell, Option<(usize, Direction)>) {
        let data = &self.buffer[at..];
        let mut lengths: SmallVec<[(usize, Direction); 2]> =
            [Direction::Request, Direction::Response]
                .into_iter()
                .filter_map(|direction| match rtu_frame_length(data, direction) {
                    // Nor does a broken frame run across a silence that ends frames.
                    Length::Known(len)
                        if (MIN_RTU_FRAME..=MAX_RTU_ADU).contains(&len)
                            && len <= data.len()
                            && !self.crosses_silence(at, at + len) =>
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
            // What follows first: it is cheaper to tell than what lies inside. Nor may a
            // frame start inside it and run whole past its end: then the silence after it
            // was an adapter's, and its bytes are noise and that frame's start. The answer
            // awaited may be followed by a frame that needs support of its own (a function
            // without a known layout): the conversation vouches for the answer's place. A
            // request in step has no such voucher, and a few bytes of noise read as one.
            let depth = u8::from(direction == Direction::Response);
            // The answer awaited whose layout ends right where the times tell a silence
            // has the conversation and the line both for it: bytes inside it that pass a
            // CRC as a function without a known layout are chance.
            let fills_its_turn = direction == Direction::Response
                && self.times_tell_silence()
                && self.silence_after(at + len - 1);
            match self.followed_well(at + len, depth, false, None) {
                Tell::Yes
                    if self.inner_frame_end(at, at + len).is_none()
                        && (fills_its_turn || !self.holds_unknown_frame(at, at + len)) =>
                {
                    match self.overlapped(at, at + len) {
                        Tell::No => return (Tell::Yes, Some((len, direction))),
                        Tell::NotYet => return (Tell::NotYet, None),
                        Tell::Yes => {}
                    }
                }
                Tell::NotYet => return (Tell::NotYet, None),
                _ => {}
            }
        }
        (Tell::No, None)
    }

    /// Whether a frame of a function without a known layout, its CRC sound, lies inside
    /// `at..end` after its first byte.
    pub(super) fn holds_unknown_frame(&self, at: usize, end: usize) -> bool {
        (at + 1..end).any(|inner| {
            let data = &self.buffer[inner..end];
            may_lack_layout(data) && !crc_matches(data, MIN_RTU_FRAME, data.len()).is_empty()
        })
    }

    // ---- ASCII ----
}
