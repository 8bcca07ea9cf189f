//! Framing a long RTU or ASCII stream without timing on several cores. Each block of the stream is
//! framed ahead, from its own first byte, by a framer that knows nothing of the bytes
//! before it, while the framer that has read the stream so far catches up. Once both have
//! taken the same frame and stand after it in the same place in the conversation (the
//! direction expected next, the answer awaited), they decide everything after it alike:
//! without times, a framer's decisions depend on the bytes from where it stands and on
//! that place alone, not on how the bytes were handed to it. From there on the frames found
//! ahead are taken as they are; before it, the catching-up framer's own. Noise has no frame
//! to meet at: there the two also meet where both, standing alike, are about to look at the
//! same byte after noise (noted every 64 bytes), and the run of noise each was in becomes
//! one. The framer ahead starts standing where the catching-up one stood when the block was
//! handed out: on a noisy line that is where it stands at the block's start. Where the two
//! never meet inside the block, it is framed in order: slower, never different.

use super::{Direction, Event, Framer, Mode, Noise, NoiseBytes, NOISE_KEPT};

/// How many bytes the catching-up framer takes first, looking for the frame where it meets
/// the block framed ahead: it meets it within a frame or two on a sound line. Each piece
/// after is twice as long, so that a block it never meets costs few looks.
const CATCH_UP_PIECE: usize = 256;

/// How far apart, in the stream, the places inside noise are where a framer notes where it
/// stands.
const NOISE_MARK_EVERY: u64 = 64;

/// Where a framer stands in the conversation after a frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Standing {
    pub(super) expect: Option<Direction>,
    pub(super) awaiting: Option<(u8, u8)>,
}

/// A place inside noise: the framer, standing so, was about to look at the byte at
/// `position` of the stream after noise; the run of noise before it was to be the event at
/// `run` of those it found.
#[derive(Clone, Copy, Debug)]
struct NoiseMark {
    position: u64,
    standing: Standing,
    run: usize,
}

/// What a framer notes while it frames a block ahead or catches up with one.
#[derive(Default)]
pub(super) struct Notes {
    /// For each frame: its index among the events, and the standing after it.
    frames: Vec<(usize, Standing)>,
    noise: Vec<NoiseMark>,
}

/// A block of the stream framed ahead: what was found in it, where the framer stood after
/// each frame, and the framer itself, holding the bytes at the block's end that make no
/// frame yet.
pub struct Ahead {
    events: Vec<Event>,
    notes: Notes,
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
        // A guess, checked where the two meet: where this framer stands now.
        framer.expect = self.expect;
        framer.awaiting = self.awaiting;
        framer
    }

    /// Frames `block`, the bytes from where this framer starts, ahead of the framer that
    /// reads the stream in order (see [`Framer::catch_up`]). The events are put in
    /// `events`, emptied first: a vector used before has its memory at hand.
    pub fn frame_ahead(mut self, block: &[u8], mut events: Vec<Event>) -> Ahead {
        events.clear();
        self.notes = Some(Notes::default());
        self.push(block, &mut events);
        Ahead {
            notes: self.notes.take().unwrap_or_default(),
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
        let block_offset = self.offset + self.buffer.len() as u64;
        let Ahead {
            events: mut found_ahead,
            notes: noted_ahead,
            framer: mut ahead,
        } = ahead;
        let mut mine = Vec::new();
        self.notes = Some(Notes::default());
        let (mut from, mut piece) = (0, CATCH_UP_PIECE);
        let (mut frames_looked, mut noise_looked) = (0, 0);
        while from < block.len() {
            let to = block.len().min(from + piece);
            self.push(&block[from..to], &mut mine);
            (from, piece) = (to, piece * 2);
            let notes = self.notes.take().unwrap_or_default();
            let met_at_frame =
                notes.frames[frames_looked..]
                    .iter()
                    .find_map(|(index, standing)| {
                        let Event::Frame(frame) = &mine[*index] else {
                            return None;
                        };
                        let at = noted_ahead
                            .frames
                            .binary_search_by_key(&frame.offset, |(there, _)| {
                                offset_of(&found_ahead[*there])
                            })
                            .ok()?;
                        let (there, stood) = noted_ahead.frames[at];
                        (found_ahead[there] == mine[*index] && stood == *standing)
                            .then_some((*index, there))
                    });
            if let Some((mine_to, ahead_from)) = met_at_frame {
                mine.truncate(mine_to + 1);
                out.append(&mut mine);
                *self = ahead;
                // The frame where they met is this framer's own, already in `out`.
                return Some(FoundAhead {
                    events: found_ahead,
                    from: ahead_from + 1,
                });
            }
            let met_in_noise = notes.noise[noise_looked..].iter().find_map(|mark| {
                let at = noted_ahead
                    .noise
                    .binary_search_by_key(&mark.position, |there| there.position)
                    .ok()?;
                let there = noted_ahead.noise[at];
                (there.standing == mark.standing).then_some((*mark, there))
            });
            if let Some((mark, there)) = met_in_noise {
                // This framer's run of noise up to the place: an event found, or still open.
                let mine_run = match mine.get(mark.run) {
                    Some(Event::Noise(run)) => Some(run),
                    _ => self.noise.as_ref(),
                };
                if let Some(before) = mine_run.map(|run| until(run, mark.position)) {
                    mine.truncate(mark.run);
                    out.append(&mut mine);
                    // It goes on in the run ahead at the place (one that ran across it, or
                    // one that starts there), found or still open; else it ends there.
                    match found_ahead.get_mut(there.run) {
                        Some(Event::Noise(after)) => {
                            *after = joined(before, after, mark.position, block, block_offset);
                        }
                        Some(Event::Frame(_)) => out.push(Event::Noise(before)),
                        None => match ahead.noise.as_mut() {
                            Some(after) => {
                                *after = joined(before, after, mark.position, block, block_offset);
                            }
                            None => ahead.noise = Some(before),
                        },
                    }
                    *self = ahead;
                    return Some(FoundAhead {
                        events: found_ahead,
                        from: there.run,
                    });
                }
            }
            (frames_looked, noise_looked) = (notes.frames.len(), notes.noise.len());
            self.notes = Some(notes);
        }
        self.notes = None;
        out.append(&mut mine);
        None
    }

    /// Where the framer stands in the conversation.
    fn standing(&self) -> Standing {
        Standing {
            expect: self.expect,
            awaiting: self.awaiting,
        }
    }

    /// Notes where the framer stands after the frame just handed out, when asked to.
    pub(super) fn note_standing(&mut self, index: usize) {
        let standing = self.standing();
        if let Some(notes) = self.notes.as_mut() {
            notes.frames.push((index, standing));
        }
    }

    /// Notes where the framer stands, about to look at byte `at` of its buffer after noise,
    /// when asked to and the place is one of those noted; `events`: how many events it has
    /// found, the index the run of noise before the place will take.
    #[inline]
    pub(super) fn note_in_noise(&mut self, at: usize, events: usize) {
        let position = self.offset + at as u64;
        if self.notes.is_none() || position % NOISE_MARK_EVERY != 0 {
            return;
        }
        let standing = self.standing();
        if let Some(notes) = self.notes.as_mut() {
            notes.noise.push(NoiseMark {
                position,
                standing,
                run: events,
            });
        }
    }
}

/// Where an event starts in the stream.
fn offset_of(event: &Event) -> u64 {
    match event {
        Event::Frame(found) => found.offset,
        Event::Noise(noise) => noise.offset,
    }
}

/// The run of noise `before` the place at `position` of the stream, and the run `after` it
/// that covers the place or starts there (found by a framer that started later), as one
/// run. `block`: the bytes from `block_offset` on, the place among them.
fn joined(before: Noise, after: &Noise, position: u64, block: &[u8], block_offset: u64) -> Noise {
    let len_after = after.offset + after.len - position;
    let place = (position - block_offset) as usize;
    let room = NOISE_KEPT
        .saturating_sub(before.kept.len())
        .min(len_after as usize);
    let mut joined = before;
    joined.kept.extend_from_slice(&block[place..place + room]);
    joined.len += len_after;
    joined
}

/// The part of a run of noise before `position`.
fn until(run: &Noise, position: u64) -> Noise {
    let len = position - run.offset;
    Noise {
        kept: NoiseBytes::from_slice(&run.kept[..run.kept.len().min(len as usize)]),
        len,
        offset: run.offset,
        start: run.start,
    }
}
