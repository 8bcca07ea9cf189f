//! The framer's memory of questions already answered. The rules look at the same frame
//! from several positions (as what follows the bytes before it, then as itself), and its
//! CRC or PDU need not be checked again each time.

use std::cell::Cell;

/// How many verdicts are kept: a frame is asked about from a few positions at most before
/// it is taken, so a handful of the latest are enough.
const SLOTS: usize = 16;

/// A yes-or-no verdict on the bytes at a position of the stream, by what was asked.
#[derive(Clone, Copy, Default)]
struct Verdict {
    /// Position in the stream, plus one (0: empty).
    position: u64,
    question: u32,
    answer: bool,
}

/// Verdicts on bytes of the stream. Positions are never reused (bytes forgotten move the
/// stream's offset on), so a verdict on a position holds for good.
#[derive(Default)]
pub(super) struct Verdicts {
    slots: [Cell<Verdict>; SLOTS],
}

impl Verdicts {
    /// The answer to `question` about the bytes at `position`, worked out by `work` only
    /// the first time it is asked.
    pub(super) fn get(&self, position: u64, question: u32, work: impl FnOnce() -> bool) -> bool {
        let position = position + 1;
        let slot = &self.slots[(position as usize ^ question as usize) % SLOTS];
        let known = slot.get();
        if known.position == position && known.question == question {
            return known.answer;
        }
        let answer = work();
        slot.set(Verdict {
            position,
            question,
            answer,
        });
        answer
    }
}

/// The question "does the CRC of the `len` bytes here hold?".
pub(super) fn crc_question(len: usize) -> u32 {
    len as u32
}

/// The question "does the PDU of the `len`-byte frame here read in `direction`?", with the
/// stricter reading after noise.
pub(super) fn reads_question(
    len: usize,
    direction: Option<crate::codec::Direction>,
    after_noise: bool,
) -> u32 {
    let direction = match direction {
        None => 1,
        Some(crate::codec::Direction::Request) => 2,
        Some(crate::codec::Direction::Response) => 3,
    };
    (1 << 20) | (u32::from(after_noise) << 18) | (direction << 16) | len as u32
}
