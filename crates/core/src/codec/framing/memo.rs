//! The framer's memory of the CRCs it checked. The rules look at the same frame from
//! several positions (as what follows the bytes before it, then as itself), and its CRC
//! need not be computed again each time.

use std::cell::Cell;

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
