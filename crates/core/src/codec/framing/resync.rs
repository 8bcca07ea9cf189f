//! The resynchronisation rules: what must support a frame found where the bytes before it
//! made none, since a CRC passes random bytes once in 65,536 tries and a noisy line makes
//! many tries. Each rule answers one condition of a real bus.

use crate::codec::checksum::crc_matches;
use crate::codec::function::{
    self, ENCAPSULATED_INTERFACE, EXCEPTION_FLAG, MEI_READ_DEVICE_IDENTIFICATION,
};
use crate::codec::length::{rtu_frame_length, Length};
use crate::codec::limits::MAX_RTU_ADU;
use crate::codec::pdu::Values;
use crate::codec::{Direction, Pdu};

use super::{Candidate, Framer, MAX_SLAVE, MIN_RTU_FRAME};

/// Three answers to "is it so?": the bytes that would tell may not be here yet.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Tell {
    Yes,
    No,
    NotYet,
}

impl Framer {
    /// Whether what follows the candidate at `at` supports it as a frame. `in_step`: it
    /// follows a frame or silence, so that a frame of known layout needs what stands right
    /// after it, not a frame further on, and one of unknown layout may be followed past a
    /// run of 00 or FF.
    /// Bus: noise, or a frame cut short, just before; the frame after it must not be lost
    /// and no chance CRC match may be taken for a frame.
    pub(super) fn supported(
        &self,
        at: usize,
        candidate: &Candidate,
        depth: u8,
        in_step: bool,
    ) -> Tell {
        let frame = &self.buffer[at..at + candidate.len];
        let end = at + candidate.len;
        // After noise a frame must come from an address a serial line uses (1-247, or 0
        // to broadcast; 248-255 are reserved), unless a request to its address and function
        // awaits an answer: the conversation vouches for the address. One of known layout
        // must read as a PDU.
        if !in_step
            && frame.first().is_some_and(|slave| *slave > MAX_SLAVE)
            && !self.answers_awaited(frame, candidate.direction)
        {
            return Tell::No;
        }
        // Found sound already, as the frame after a glitch byte is: its PDU reads.
        let sound = candidate.known_layout
            && self
                .latest_sound
                .is(self.offset + at as u64, candidate.len, candidate.direction);
        if candidate.known_layout && !sound && !pdu_reads(frame, candidate.direction, !in_step) {
            return self.refused_right_after(end, self.asked_by(at, candidate));
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
    /// Bus: a frame that ends a burst of traffic (silence after it), or a request answered
    /// at once by its slave.
    pub(super) fn followed_or_answered(
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
        // The conversation supports the answer awaited; but where the times tell silences,
        // one whose length only its CRC tells must end where the silence does, since the
        // bytes that go on without a gap are still its own. Unless they came in its read
        // and the read could hide a gap (an adapter gathers what came in its whole period),
        // or it runs across a gap after which no frame starts (`look_rtu` has dropped it
        // otherwise): then the gaps are an adapter's latency timer, and the bytes after it
        // tell nothing either.
        let awaited = self.answers_awaited(frame, candidate.direction);
        let by_conversation = awaited
            && (candidate.known_layout
                || !self.times_tell_silence()
                || self.silence_inside(at, end));
        if self.silence_after(end - 1) || by_conversation {
            return Tell::Yes;
        }
        // A gap the read may hide does not outweigh a silence seen: where a longer
        // reading, its CRC holding, ends at one, that is the answer; while one still may,
        // it is waited for, up to the longest frame.
        if awaited && self.may_hide_silence_after(end - 1) {
            match self.longer_reading_ends_at_silence(at, candidate.len) {
                Tell::No => return Tell::Yes,
                Tell::NotYet => return Tell::NotYet,
                Tell::Yes => {}
            }
        }
        if end == self.buffer.len() {
            return if self.ended { Tell::Yes } else { Tell::NotYet };
        }
        // A frame without a known layout must be followed right after it, or past a run of
        // 00 or FF only in step; one of known layout may be followed past such a run, and
        // by a frame further on (past a cut answer, say): in step, if its PDU reads as
        // strictly as one found after noise must.
        let past_runs = candidate.known_layout || in_step;
        let asked = self.asked_by(at, candidate);
        let further_on =
            candidate.known_layout && (!in_step || pdu_reads(frame, candidate.direction, true));
        match self.followed_well(end, depth, past_runs, asked) {
            Tell::No if further_on => match self.overlapped(at, end) {
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

    /// Whether the bytes at `at` read longer than `len`, their CRC holding, up to a byte
    /// the line's times show silence after; not yet while the bytes may still give one.
    fn longer_reading_ends_at_silence(&self, at: usize, len: usize) -> Tell {
        let data = &self.buffer[at..];
        let longer = crc_matches(data, len + 1, data.len().min(MAX_RTU_ADU));
        if longer
            .iter()
            .any(|longer| self.silence_after(at + longer - 1))
        {
            Tell::Yes
        } else if self.quiet || self.ended || data.len() >= MAX_RTU_ADU {
            Tell::No
        } else {
            Tell::NotYet
        }
    }

    /// Whether a valid frame starts right at `at` (of known layout, the answer to
    /// `asked`, or itself supported), or silence or the end of the input is there.
    /// `past_runs`: after a run of 00 or FF bytes, which is what a line held low or
    /// glitching gives, not data.
    /// Bus: back-to-back traffic of a busy line, where the next frame starts right after.
    pub(super) fn followed_well(
        &self,
        at: usize,
        depth: u8,
        past_runs: bool,
        asked: Option<(u8, u8)>,
    ) -> Tell {
        if past_runs {
            let run = line_state_run(&self.buffer[at.min(self.buffer.len())..]);
            // A frame may start with the run itself (slave 255, or 0 to broadcast), and the
            // run's last byte may be the address of a broadcast.
            if run > 0 {
                let at_run = self.followed_well(at, depth, false, asked);
                if at_run == Tell::Yes {
                    return Tell::Yes;
                }
                // A run of one: its last byte is its first, already asked about.
                let at_last = if run == 1 {
                    at_run
                } else {
                    self.followed_well(at + run - 1, depth, false, asked)
                };
                return match at_last {
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
        // Bytes cut by silence may be a frame's first read from a USB adapter: the frame
        // before them waits for the bytes after it, as they do.
        if !next.pending.is_empty() && self.last_bytes_may_grow() {
            return Tell::NotYet;
        }
        Tell::No
    }

    /// Whether the answer to `asked` starts within the longest frame's reach after `at`,
    /// past 00 or FF bytes.
    /// Bus: a request followed by a glitch or a line held low before its answer.
    pub(super) fn answer_further_on(&self, at: usize, asked: (u8, u8)) -> Tell {
        let at = after_run(&self.buffer, at);
        let reach = at + MAX_RTU_ADU;
        for p in at..reach.min(self.buffer.len()) {
            match self.answer_at(p, asked) {
                Tell::Yes => return Tell::Yes,
                Tell::NotYet => return Tell::NotYet,
                Tell::No => {}
            }
        }
        if reach > self.buffer.len() && self.last_bytes_may_grow() {
            return Tell::NotYet;
        }
        Tell::No
    }

    /// Whether a frame whose CRC holds, with the slave and function `asked` for, starts at
    /// `at`.
    /// Bus: the master-slave conversation, where an answer follows its request.
    pub(super) fn answer_at(&self, at: usize, (slave, function): (u8, u8)) -> Tell {
        match self.buffer.get(at..at + 2) {
            Some([s, f]) if *s == slave && f & !EXCEPTION_FLAG == function => {
                let next = self.candidates(at);
                if !next.valid.is_empty() {
                    Tell::Yes
                } else if !next.pending.is_empty() && self.last_bytes_may_grow() {
                    Tell::NotYet
                } else {
                    Tell::No
                }
            }
            Some(_) => Tell::No,
            None if self.last_bytes_may_grow() => Tell::NotYet,
            None => Tell::No,
        }
    }

    /// Whether the exception answering `asked` starts right at `at`: a request whose PDU
    /// does not read (a coil value of 0004, a byte count its quantity does not give) is the
    /// master's mistake, to be shown, when its slave refuses it at once; noise glued before
    /// it takes away the step that would otherwise vouch for it.
    /// Bus: a master sending a malformed request, and the slave's exception 03.
    pub(super) fn refused_right_after(&self, at: usize, asked: Option<(u8, u8)>) -> Tell {
        match (asked, self.buffer.get(at + 1)) {
            (None, _) => Tell::No,
            (Some(_), Some(function)) if function & EXCEPTION_FLAG == 0 => Tell::No,
            (Some(asked), _) => self.answer_at(at, asked),
        }
    }

    /// Whether a frame starts inside `at..end` and runs past its end, of known layout, CRC
    /// and PDU sound, or of unknown layout and followed well: then the bytes at `at` make
    /// a frame only by borrowing the start of another.
    /// Bus: a frame cut short followed by a whole one; the cut frame may not borrow the
    /// start of the next and hide it.
    pub(super) fn overlapped(&self, at: usize, end: usize) -> Tell {
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
        if more_could_come && self.last_bytes_may_grow() {
            Tell::NotYet
        } else {
            Tell::No
        }
    }

    /// Whether a frame of known layout, CRC and PDU sound, starts within the longest
    /// frame's reach after `at`, past bytes that are no frame.
    /// Bus: noise between two frames, with no silence that the times could show.
    pub(super) fn frame_further_on(&self, at: usize) -> Tell {
        let at = after_run(&self.buffer, at);
        let reach = at + MAX_RTU_ADU;
        // Also not yet while a frame that starts within reach may still complete: a long
        // one is not all here yet when the bytes come a read at a time, though it would be
        // read all at once.
        let mut may_come = reach > self.buffer.len();
        for p in at..reach.min(self.buffer.len()) {
            if self.known_frame_len(p, self.buffer.len()).is_some() {
                return Tell::Yes;
            }
            may_come = may_come || self.known_frame_may_complete(p);
        }
        if may_come && self.last_bytes_may_grow() {
            Tell::NotYet
        } else {
            Tell::No
        }
    }

    /// Whether the bytes at `at` begin a frame of known layout that more bytes may still
    /// complete.
    fn known_frame_may_complete(&self, at: usize) -> bool {
        let data = &self.buffer[at..];
        [Direction::Request, Direction::Response].into_iter().any(
            |direction| match rtu_frame_length(data, direction) {
                Length::Known(len) => {
                    (MIN_RTU_FRAME..=MAX_RTU_ADU).contains(&len) && len > data.len()
                }
                Length::AtLeast(len) => len <= MAX_RTU_ADU,
                Length::Unknown | Length::Never => false,
            },
        )
    }

    /// The slave and function a candidate asks for, when it can be a request: a request
    /// is supported by its answer right after it.
    /// Bus: a request whose answer comes right after it.
    pub(super) fn asked_by(&self, at: usize, candidate: &Candidate) -> Option<(u8, u8)> {
        match (candidate.direction, self.buffer.get(at..at + 2)) {
            (Some(Direction::Response), _) => None,
            (_, Some([slave, function])) => Some((*slave, function & !EXCEPTION_FLAG)),
            _ => None,
        }
    }

    /// Whether `frame` is the answer the last request awaits: its slave and function.
    /// Bus: our own request and its answer, in step.
    pub(super) fn answers_awaited(&self, frame: &[u8], direction: Option<Direction>) -> bool {
        direction != Some(Direction::Request)
            && matches!((frame, self.awaiting), ([slave, function, ..], Some((s, f)))
                if *slave == s && *function & !EXCEPTION_FLAG == f)
    }
}

/// A function code that may be a frame without a layout the codec knows: user-defined
/// (65-72, 100-110) or an MEI type other than read device identification. Any other code
/// without a layout is no public or user function, and no frame.
pub(super) fn may_lack_layout(frame: &[u8]) -> bool {
    match (frame.get(1), frame.get(2)) {
        (Some(65..=72 | 100..=110), _) => true,
        (Some(&ENCAPSULATED_INTERFACE), Some(mei)) => *mei != MEI_READ_DEVICE_IDENTIFICATION,
        _ => false,
    }
}

/// Where a frame may start after the run of 00 or FF at `at`: at its last byte, which may
/// be the address of a broadcast.
pub(super) fn after_run(buffer: &[u8], at: usize) -> usize {
    at + line_state_run(&buffer[at..]).saturating_sub(1)
}

/// How many bytes at the start of `bytes` are a run of 00 or FF: a line held low, or
/// glitching, rather than data.
pub(super) fn line_state_run(bytes: &[u8]) -> usize {
    match bytes.first() {
        Some(&run @ (0x00 | 0xFF)) => bytes.iter().take_while(|b| **b == run).count(),
        _ => 0,
    }
}

/// Whether the PDU inside an RTU frame reads in `direction` (either, for `None`).
/// `after_noise`: an exception must also answer a defined function with a defined code, as
/// a frame found after noise must, being found among bytes that pass their CRC by chance.
pub(super) fn pdu_reads(frame: &[u8], direction: Option<Direction>, after_noise: bool) -> bool {
    let Some(pdu) = frame.get(1..frame.len().saturating_sub(2)) else {
        return false;
    };
    let reads = |direction| match Pdu::read(pdu, direction, Values::Skipped) {
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
