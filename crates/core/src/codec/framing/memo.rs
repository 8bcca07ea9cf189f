//! The framer's memory of the CRCs it checked. The rules look at the same frame from
//! several positions (as what follows the bytes before it, then as itself), and its CRC
//! need not be computed again each time.

use std::cell::Cell;

use crate::codec::Direction;

/// How many verdicts are kept: a frame is asked about from a few positions at most before
/// it is taken, so a handful of the latest are enough.
const SLOTS: usize = 16;

/// Whether the CRC of the frame of `len` bytes at `position` in the stream holds.
#[derive(Clone, Copy, Default)]
struct Verdict {
    /// Position in the stream, plus one (0: empty).
    position: u64,
    len: usize,
    holds: bool,
}

/// CRC verdicts on frames of the stream. Positions are never reused (bytes forgotten move
/// the stream's offset on), so a verdict on a position holds for good.
#[derive(Default)]
pub(super) struct CrcVerdicts {
    slots: [Cell<Verdict>; SLOTS],
}

impl CrcVerdicts {
    /// Whether the CRC of the `len` bytes at `position` holds, worked out by `check` only
    /// the first time it is asked.
    pub(super) fn get(&self, position: u64, len: usize, check: impl FnOnce() -> bool) -> bool {
        let position = position + 1;
        let slot = &self.slots[(position as usize ^ len) % SLOTS];
        let known = slot.get();
        if known.position == position && known.len == len {
            return known.holds;
        }
        let holds = check();
        slot.set(Verdict {
            position,
            len,
            holds,
        });
        holds
    }
}

/// The latest frame of known layout found sound, CRC and PDU, at its position in the
/// stream: a glitch byte is told from the frame right after it by that frame's soundness,
/// and the look at the frame itself then asks whether its PDU reads once more.
#[derive(Default)]
pub(super) struct LatestSound {
    /// Position in the stream plus one (0: none), length, and the direction it read in.
    frame: Cell<(u64, usize, Option<Direction>)>,
}

impl LatestSound {
    pub(super) fn found(&self, position: u64, len: usize, direction: Direction) {
        self.frame.set((position + 1, len, Some(direction)));
    }

    /// Whether the frame of `len` bytes at `position` is the latest found sound, in
    /// `direction` (either, for `None`).
    pub(super) fn is(&self, position: u64, len: usize, direction: Option<Direction>) -> bool {
        let (at, sound_len, sound_direction) = self.frame.get();
        at == position + 1
            && sound_len == len
            && direction.is_none_or(|direction| Some(direction) == sound_direction)
    }
}
