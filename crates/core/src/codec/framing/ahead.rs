//! Framing a long RTU or ASCII stream without timing on several cores. Each block of the stream is
//! framed ahead, from its own first byte, by a framer that knows nothing of the bytes
//! before it, while the framer that has read the stream so far catches up. Once both have
//! taken the same frame and stand after it in the same place in the conversation (the
//! direction expected next, the answer awaited), they decide everything after it alike:
//! without times, a framer's decisions depend on the bytes from where it stands and on
//! that place alone, not on how the bytes were handed to it. From there on the frames found
//! ahead are taken as they are; before it, the catching-up framer's own. Where the two never
//! meet inside the block, it is framed in order: slower, never different.

use super::{Direction, Event, Framer, Mode};

/// How many bytes the catching-up framer takes first, looking for the frame where it meets
/// the block framed ahead: it meets it within a frame or two on a sound line. Each piece
/// after is twice as long, so that a block it never meets costs few looks.
const CATCH_UP_PIECE: usize = 256;

/// Where a framer stands in the conversation after a frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Standing {
    pub(super) expect: Option<Direction>,
    pub(super) awaiting: Option<(u8, u8)>,
}

/// A block of the stream framed ahead: what was found in it, where the framer stood after
/// each frame, and the framer itself, holding the bytes at the block's end that make no
/// frame yet.
pub struct Ahead {
    events: Vec<Event>,
    /// For each frame among `events`: its index there and the standing after it.
    standings: Vec<(usize, Standing)>,
    framer: Framer,
}

/// The frames of a block framed ahead that follow where the catching-up framer met them:
/// `events[from..]`. `events` is the vector the block was framed into, to be used again.
pub struct FoundAhead {
    /// The events framed ahead.
    pub events: Vec<Event>,
    /// The first of them that follows the meeting.
    pub from: usize,
}

impl Framer {
    /// A framer for the bytes of the same stream from `offset` on, framed without the bytes
    /// before them, as after noise: to frame a block ahead with [`Framer::frame_ahead`].
    pub fn starting_at(&self, offset: u64) -> Framer {
        let mut framer = Framer::new(self.mode, self.char_us, self.silence_us);
        framer.ends_cut_frames = self.ends_cut_frames;
        framer.resync = self.resync;
        framer.offset = offset;
        framer.in_step = false;
        framer
    }

    /// Frames `block`, the bytes from where this framer starts, ahead of the framer that
    /// reads the stream in order (see [`Framer::catch_up`]). The events are put in
    /// `events`, emptied first: a vector used before has its memory at hand.
    pub fn frame_ahead(mut self, block: &[u8], mut events: Vec<Event>) -> Ahead {
        events.clear();
        self.standings = Some(Vec::new());
        self.push(block, &mut events);
        Ahead {
            standings: self.standings.take().unwrap_or_default(),
            events,
            framer: self,
        }
    }

    /// Frames `block`, the bytes that follow those given so far, which `ahead` framed from
    /// its own start: in order until this framer meets the frames found ahead, then as they
    /// were found. The events, those [`Framer::push`] would give, are added to `out` up to
    /// where the two met, and the rest, found ahead, returned to follow them: handed on as
    /// they are, not copied. `None`: the two never met, and the block was framed in order.
    pub fn catch_up(
        &mut self,
        block: &[u8],
        ahead: Ahead,
        out: &mut Vec<Event>,
    ) -> Option<FoundAhead> {
        // Only bytes without times are framed alike however they are handed over; and a
        // TCP receiver that lost its step tells the rest as noise a piece at a time.
        if !self.times.is_empty() || self.mode == Mode::Tcp {
            self.push(block, out);
            return None;
        }
        let Ahead {
            events: found_ahead,
            standings: stood_ahead,
            framer: ahead,
        } = ahead;
        let offset_of = |index: usize| match &found_ahead[index] {
            Event::Frame(found) => found.offset,
            Event::Noise(noise) => noise.offset,
        };
        let mut mine = Vec::new();
        self.standings = Some(Vec::new());
        let (mut from, mut piece) = (0, CATCH_UP_PIECE);
        while from < block.len() {
            let to = block.len().min(from + piece);
            let looked = self.standings.as_ref().map_or(0, Vec::len);
            self.push(&block[from..to], &mut mine);
            (from, piece) = (to, piece * 2);
            let standings = self.standings.as_deref().unwrap_or_default();
            let met = standings[looked..].iter().find_map(|(index, standing)| {
                let Event::Frame(frame) = &mine[*index] else {
                    return None;
                };
                let at = stood_ahead
                    .binary_search_by_key(&frame.offset, |(there, _)| offset_of(*there))
                    .ok()?;
                let (there, stood) = stood_ahead[at];
                (found_ahead[there] == mine[*index] && stood == *standing)
                    .then_some((*index, there))
            });
            if let Some((mine_to, ahead_from)) = met {
                mine.truncate(mine_to + 1);
                out.append(&mut mine);
                *self = ahead;
                // The frame where they met is this framer's own, already in `out`.
                return Some(FoundAhead {
                    events: found_ahead,
                    from: ahead_from + 1,
                });
            }
        }
        self.standings = None;
        out.append(&mut mine);
        None
    }

    /// Notes where the framer stands after the frame just handed out, when asked to.
    pub(super) fn note_standing(&mut self, index: usize) {
        let standing = Standing {
            expect: self.expect,
            awaiting: self.awaiting,
        };
        if let Some(standings) = self.standings.as_mut() {
            standings.push((index, standing));
        }
    }
}
