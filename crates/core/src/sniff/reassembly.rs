//! One direction of a TCP connection put back in order from the segments a capture saw:
//! retransmitted and duplicated bytes kept once, segments out of order put in order, and a
//! lost segment told as a gap of so many bytes, so that the framer after it picks up at the
//! next frame instead of losing the rest of the connection.

use std::collections::BTreeMap;

/// At most this many bytes wait for a segment that has not come; past it, that segment is
/// taken as lost. Memory stays bounded whatever the capture holds.
const MOST_WAITING: usize = 256 * 1024;

/// At most this many segments wait: a capture of one direction alone has no
/// acknowledgements to tell a lost segment by.
const MOST_SEGMENTS_WAITING: usize = 64;

/// The most bytes a sender may have in flight that the capture has not seen: an
/// acknowledgement further ahead of what was seen is a corrupt number, and a hole wider is
/// a jump of the sequence numbers, not bytes that were sent.
const MOST_UNSEEN: u64 = 64 * 1024;

/// How long, in capture time, a segment waits for the hole before it to fill: a
/// retransmission comes within it, and a corrupt sequence number holds nothing back longer.
const PATIENCE_US: u64 = 2_000_000;

/// When and in which packet a segment was captured: microseconds since 1970, and the
/// packet's number.
pub type At = (u64, u64);

/// What comes out of a stream, in order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Piece {
    /// Bytes in order, from one segment.
    Bytes {
        /// The bytes.
        data: Vec<u8>,
        /// When their segment was captured, in microseconds since 1970, and its packet.
        at: At,
    },
    /// Bytes that never came.
    Gap(u64),
}

/// One direction of a connection.
#[derive(Debug, Default)]
pub struct Stream {
    /// Where the next byte in order is, counted on 64 bits from the first sequence number
    /// seen; `None` before the first segment.
    next: Option<u64>,
    /// The first sequence number seen, which positions count from.
    first: u32,
    /// Segments ahead of `next`, by position: their bytes, and when they came.
    waiting: BTreeMap<u64, (Vec<u8>, At)>,
    waiting_bytes: usize,
    /// Bytes seen again (retransmitted or duplicated), kept once.
    pub repeated: u64,
    /// Bytes that never came.
    pub missing: u64,
    /// Jumps of the sequence numbers wider than a sender could have in flight (a corrupt
    /// number, or a capture that lost much), and acknowledgements of bytes never sent:
    /// passed over, and no bytes counted missing for them.
    pub jumps: u64,
    /// Where the last segment framed on its own, for a number far off, ended: the next
    /// that starts there shows the stream has moved.
    far_end: Option<u32>,
    /// Bytes of segments framed on their own that may be the stream's next, their number
    /// alone corrupt: what comes after them, or an acknowledgement of them, is no hole.
    unplaced: u64,
    /// Where the sender's FIN stands: the other side acknowledges it as one more
    /// sequence number, which is no byte.
    fin: Option<u64>,
}

impl Stream {
    /// A segment whose first byte has sequence number `sequence` (after its SYN, when it
    /// has one), captured `at`; the `cut` bytes after `payload` were not captured.
    pub fn segment(
        &mut self,
        sequence: u32,
        syn: bool,
        (payload, cut): (&[u8], u32),
        at: At,
        out: &mut Vec<Piece>,
    ) {
        let start = sequence.wrapping_add(u32::from(syn));
        let next = match self.next {
            Some(next) => next,
            None => {
                self.first = start;
                self.next = Some(0);
                0
            }
        };
        if payload.is_empty() {
            return;
        }
        // A number further from the stream than a sender could have in flight is corrupt,
        // or the capture lost much: the segment is framed on its own, the stream left as
        // it is, until a second segment follows it on, and the stream goes on from there.
        let near = self
            .position(start, next)
            .filter(|position| position.abs_diff(self.seen_end()) <= MOST_UNSEEN);
        let position = match near {
            Some(position) => position,
            None if self.far_end == Some(start) => {
                self.finish(out);
                self.first = start.wrapping_sub(self.next.unwrap_or(0) as u32);
                self.jumps += 1;
                self.next.unwrap_or(0)
            }
            None => {
                self.jumps += 1;
                out.extend([
                    Piece::Gap(0),
                    Piece::Bytes {
                        data: payload.to_vec(),
                        at,
                    },
                    Piece::Gap(0),
                ]);
                self.far_end = Some(start.wrapping_add(payload.len() as u32));
                self.unplaced += payload.len() as u64;
                return;
            }
        };
        self.far_end = None;
        // The stream goes on after bytes framed on their own: they were its next.
        if self.unplaced > 0 && position > next && position - next <= self.unplaced {
            self.next = Some(position);
            self.release(Some(at), out);
        }
        self.unplaced = 0;
        let end = position + payload.len() as u64;
        self.take(position, payload, at, out);
        if cut > 0 && self.next == Some(end) {
            out.push(Piece::Gap(u64::from(cut)));
            self.missing += u64::from(cut);
            self.next = Some(end + u64::from(cut));
            self.release(Some(at), out);
        }
        while self.waiting_bytes > MOST_WAITING || self.waiting.len() > MOST_SEGMENTS_WAITING {
            self.skip_hole(out);
        }
        self.expire(at.0, out);
    }

    /// Holes that segments have waited behind for longer than [`PATIENCE_US`] by `now` are
    /// taken as lost.
    fn expire(&mut self, now: u64, out: &mut Vec<Piece>) {
        while self
            .waiting
            .first_key_value()
            .is_some_and(|(_, (_, at))| now.saturating_sub(at.0) > PATIENCE_US)
        {
            self.skip_hole(out);
        }
    }

    /// Where the sender has sent up to, as far as the capture saw.
    fn seen_end(&self) -> u64 {
        let waiting = self
            .waiting
            .last_key_value()
            .map_or(0, |(at, (data, _))| at + data.len() as u64);
        self.next.unwrap_or(0).max(waiting)
    }

    /// The sender is done: its FIN has sequence number `sequence`.
    pub fn fin(&mut self, sequence: u32) {
        if let Some(next) = self.next {
            self.fin = self.position(sequence, next);
        }
    }

    /// The other side acknowledged every byte before `acknowledgement`: bytes before it that
    /// never came were lost to the capture, not to the connection, and will not come.
    pub fn acknowledged(&mut self, acknowledgement: u32, now: At, out: &mut Vec<Piece>) {
        let Some(next) = self.next else {
            return;
        };
        let Some(until) = self.position(acknowledgement, next) else {
            return;
        };
        let until = self.fin.map_or(until, |fin| until.min(fin));
        if until > self.seen_end() + MOST_UNSEEN {
            // More than could be in flight unseen: a corrupt number, not lost bytes.
            self.jumps += 1;
            return;
        }
        while self
            .waiting
            .first_key_value()
            .is_some_and(|(at, _)| *at < until)
        {
            self.skip_hole(out);
        }
        let next = self.next.unwrap_or(0);
        if until > next {
            // Bytes framed on their own for a corrupt number are those acknowledged.
            let placed = (until - next).min(self.unplaced);
            self.unplaced -= placed;
            if until - next > placed {
                self.hole(until - next - placed, out);
            }
            self.next = Some(until);
            self.release(Some(now), out);
        }
        self.expire(now.0, out);
    }

    /// A hole of `size` bytes the framer is told of: missing bytes, or a jump when wider
    /// than a sender could have in flight.
    fn hole(&mut self, size: u64, out: &mut Vec<Piece>) {
        out.push(Piece::Gap(size));
        if size > MOST_UNSEEN {
            self.jumps += 1;
        } else {
            self.missing += size;
        }
    }

    /// The position nearest to `next` that the 32-bit sequence number `sequence` can stand
    /// for: up to half the sequence space ahead, or behind.
    fn position(&self, sequence: u32, next: u64) -> Option<u64> {
        let ahead = sequence.wrapping_sub(self.first).wrapping_sub(next as u32);
        match ahead < 1 << 31 {
            true => next.checked_add(u64::from(ahead)),
            false => next.checked_sub(u64::from(ahead.wrapping_neg())),
        }
    }

    /// The connection ends: what waits behind a hole comes out after it.
    pub fn finish(&mut self, out: &mut Vec<Piece>) {
        while !self.waiting.is_empty() {
            self.skip_hole(out);
        }
    }

    /// A segment that waited behind a hole now taken as lost: it, and those that waited
    /// behind it, come out as they came.
    fn take_as_came(&mut self, position: u64, payload: &[u8], at: At, out: &mut Vec<Piece>) {
        if self.put(position, payload, at, out) {
            self.release(None, out);
        }
    }

    /// Bytes at `position`: those in order go out, with what waited behind them; those
    /// ahead wait; those already out are counted as repeated.
    fn take(&mut self, position: u64, payload: &[u8], at: At, out: &mut Vec<Piece>) {
        if self.put(position, payload, at, out) {
            self.release(Some(at), out);
        }
    }

    /// `take` but for what waited: whether bytes went out.
    fn put(&mut self, position: u64, payload: &[u8], at: At, out: &mut Vec<Piece>) -> bool {
        let next = self.next.unwrap_or(0);
        let end = position + payload.len() as u64;
        if end <= next {
            self.repeated += payload.len() as u64;
            return false;
        }
        if position > next {
            let kept = self
                .waiting
                .entry(position)
                .or_insert_with(|| (Vec::new(), at));
            if kept.0.len() < payload.len() {
                self.waiting_bytes += payload.len() - kept.0.len();
                self.repeated += kept.0.len() as u64;
                *kept = (payload.to_vec(), at);
            } else {
                self.repeated += payload.len() as u64;
            }
            return false;
        }
        let skip = (next - position) as usize;
        self.repeated += skip as u64;
        out.push(Piece::Bytes {
            data: payload[skip..].to_vec(),
            at,
        });
        self.next = Some(end);
        true
    }

    /// What waited behind the bytes out so far, now that they reach it: it comes out
    /// `now`, with the segment that let it; or, after a hole taken as lost, each segment
    /// as it came (`None`).
    fn release(&mut self, now: Option<At>, out: &mut Vec<Piece>) {
        while let Some(entry) = self.waiting.first_entry() {
            if *entry.key() > self.next.unwrap_or(0) {
                break;
            }
            let (position, (data, came)) = entry.remove_entry();
            self.waiting_bytes -= data.len();
            self.take(position, &data, now.unwrap_or(came), out);
        }
    }

    /// The first segment waiting is taken as following a hole: the gap, then it, as it
    /// came (it was whole then; only the hole was not known to be one).
    fn skip_hole(&mut self, out: &mut Vec<Piece>) {
        let Some((position, (data, at))) = self.waiting.pop_first() else {
            return;
        };
        self.waiting_bytes -= data.len();
        let next = self.next.unwrap_or(0);
        if position > next {
            self.hole(position - next, out);
            self.next = Some(position);
        }
        self.take_as_came(position, &data, at, out);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bytes_of(pieces: &[Piece]) -> Vec<u8> {
        pieces
            .iter()
            .flat_map(|p| match p {
                Piece::Bytes { data, .. } => data.clone(),
                Piece::Gap(_) => b"|".to_vec(),
            })
            .collect()
    }

    #[test]
    fn out_of_order_repeated_and_lost_segments() {
        let mut stream = Stream::default();
        let mut out = Vec::new();
        stream.segment(u32::MAX - 1, true, (b"", 0), (0, 0), &mut out);
        // Across the wrap of the sequence numbers.
        stream.segment(u32::MAX, false, (b"abc", 0), (1, 0), &mut out);
        stream.segment(5, false, (b"gh", 0), (3, 0), &mut out);
        stream.segment(2, false, (b"def", 0), (2, 0), &mut out);
        stream.segment(2, false, (b"def", 0), (4, 0), &mut out);
        stream.segment(1, false, (b"cde", 0), (4, 0), &mut out);
        // Acknowledged by the other side: the bytes before 12 were lost to the capture.
        stream.segment(12, false, (b"ij", 0), (5, 0), &mut out);
        stream.acknowledged(12, (5, 0), &mut out);
        assert_eq!(String::from_utf8(bytes_of(&out)).unwrap(), "abcdefgh|ij");
        stream.acknowledged(16, (5, 0), &mut out);
        assert_eq!(String::from_utf8(bytes_of(&out)).unwrap(), "abcdefgh|ij|");
        // A packet the snap length cut: its last 4 bytes are a gap at once.
        stream.segment(16, false, (b"z", 4), (6, 0), &mut out);
        stream.segment(21, false, (b"w", 0), (7, 0), &mut out);
        stream.finish(&mut out);
        assert_eq!(
            String::from_utf8(bytes_of(&out)).unwrap(),
            "abcdefgh|ij|z|w"
        );
        assert_eq!(stream.missing, 11);
        assert_eq!(stream.repeated, 6);
    }

    #[test]
    fn corrupt_numbers_hold_back_nothing_for_long_and_claim_no_bytes() {
        let mut stream = Stream::default();
        let mut out = Vec::new();
        stream.segment(1000, false, (b"abc", 0), (0, 1), &mut out);
        // An acknowledgement a billion bytes ahead is a corrupt number: the next segment
        // in order is still taken, and nothing is counted missing.
        stream.acknowledged(1_001_000_000, (1, 2), &mut out);
        stream.segment(1003, false, (b"de", 0), (2, 3), &mut out);
        assert_eq!(String::from_utf8(bytes_of(&out)).unwrap(), "abcde");
        assert_eq!((stream.missing, stream.jumps), (0, 1));
        // A segment whose number is corrupt (a bit flipped, 2^31 off) is framed on its own,
        // and the stream goes on in order after it.
        stream.segment(1005 ^ (1 << 30), false, (b"X", 0), (3, 4), &mut out);
        stream.segment(
            1005u32.wrapping_sub(1 << 31),
            false,
            (b"Y", 0),
            (4, 5),
            &mut out,
        );
        stream.segment(1005, false, (b"f", 0), (5, 6), &mut out);
        assert_eq!(String::from_utf8(bytes_of(&out)).unwrap(), "abcde|X||Y|f");
        assert_eq!((stream.missing, stream.jumps), (0, 3));
        // Bytes framed on their own for a corrupt number are the stream's next: their
        // acknowledgement, or the segment after them, is no hole.
        let mut lone = Stream::default();
        let mut pieces = Vec::new();
        lone.segment(0, false, (b"ab", 0), (0, 1), &mut pieces);
        lone.segment(2 ^ (1 << 30), false, (b"cd", 0), (1, 2), &mut pieces);
        lone.acknowledged(4, (2, 3), &mut pieces);
        lone.segment(4 ^ (1 << 29), false, (b"ef", 0), (3, 4), &mut pieces);
        lone.segment(6, false, (b"gh", 0), (4, 5), &mut pieces);
        assert_eq!(
            String::from_utf8(bytes_of(&pieces)).unwrap(),
            "ab|cd||ef|gh"
        );
        assert_eq!(lone.missing, 0);
        // Numbers that jump and go on from there are a stream that moved (a capture that
        // lost much): it goes on from the second segment.
        stream.segment(900_000, false, (b"p", 0), (6, 7), &mut out);
        stream.segment(900_001, false, (b"q", 0), (7, 8), &mut out);
        stream.segment(900_002, false, (b"r", 0), (8, 9), &mut out);
        assert_eq!(
            String::from_utf8(bytes_of(&out)).unwrap(),
            "abcde|X||Y|f|p|qr"
        );
        assert_eq!((stream.missing, stream.jumps), (0, 5));
        // A hole a retransmission could fill waits, and is then lost, as it came.
        let mut stream = Stream::default();
        let mut out = Vec::new();
        stream.segment(0, false, (b"a", 0), (0, 1), &mut out);
        stream.segment(5, false, (b"f", 0), (10, 2), &mut out);
        stream.segment(6, false, (b"g", 0), (20, 3), &mut out);
        stream.segment(1, false, (b"bcde", 0), (30, 4), &mut out);
        assert_eq!(String::from_utf8(bytes_of(&out)).unwrap(), "abcdefg");
        stream.segment(9, false, (b"j", 0), (40, 5), &mut out);
        stream.segment(10, false, (b"k", 0), (2_000_050, 6), &mut out);
        let times: Vec<u64> = out
            .iter()
            .filter_map(|p| match p {
                Piece::Bytes { at, .. } => Some(at.1),
                Piece::Gap(_) => None,
            })
            .collect();
        // j waited past the patience: the hole before it is lost, and j came in packet 5.
        assert_eq!(String::from_utf8(bytes_of(&out)).unwrap(), "abcdefg|jk");
        assert_eq!(times[times.len() - 2..], [5, 6]);
        assert_eq!(stream.missing, 2);
    }
}
