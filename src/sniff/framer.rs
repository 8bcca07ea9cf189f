//! Finding frames in a passive capture: bytes (with arrival times when known) in, frames and
//! noise out. Pure: no I/O, no clock; times are what the caller says they were.
//!
//! USB adapters deliver bytes in bursts, request and answer glued together, so frames are
//! found by what the bytes say: each frame's length is predicted from its function code and
//! byte count, and a frame is accepted when its checksum holds; otherwise the framer moves
//! on one byte and looks again. Bytes that are no frame are reported as noise, with their
//! count; no byte is dropped and no frame is reported twice. Silence (3.5 character times)
//! ends a frame that was broken off, when the timing can be trusted.

use crate::codec::checksum::{crc16, lrc, shortest_crc_match};
use crate::codec::length::{rtu_frame_length, Length};
use crate::codec::{limits, Direction, Mode};

/// A frame as found on the line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Found {
    pub bytes: Vec<u8>,
    /// Position of the first byte in the whole capture.
    pub offset: u64,
    /// Arrival time of the first and of the last byte, in microseconds, when known.
    pub start: Option<u64>,
    pub end: Option<u64>,
    /// Why the frame is not valid: a checksum mismatch, or an ASCII frame cut off.
    pub broken: Option<Broken>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Broken {
    /// The frame has the length its bytes predict, but its checksum fails.
    Checksum,
    /// An ASCII frame cut off by a new ':' (or by silence) before its CR LF.
    Incomplete,
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Event {
    Frame(Found),
    /// Bytes that belong to no frame, in a run.
    Noise {
        bytes: Vec<u8>,
        offset: u64,
        start: Option<u64>,
    },
}

/// What the bytes at one position could be, by their CRC.
struct Candidates {
    /// Lengths whose CRC holds, with the direction each reads in (`None`: either), ascending.
    valid: Vec<(usize, Option<Direction>)>,
    /// Lengths predicted whose bytes are not all here yet.
    waiting: Vec<usize>,
    /// More bytes could still make a frame.
    need_more: bool,
}

/// What the start of the buffer holds.
enum Look {
    Frame(usize, Option<Broken>),
    NeedMore,
    Noise,
}

pub struct Framer {
    mode: Mode,
    /// Silence that ends a frame (3.5 character times), in microseconds.
    silence_us: u64,
    /// One character's time on the wire, in microseconds.
    char_us: f64,
    buffer: Vec<u8>,
    times: Vec<Option<u64>>,
    /// Position in the capture of `buffer[0]`.
    offset: u64,
    noise: Vec<u8>,
    noise_offset: u64,
    noise_start: Option<u64>,
    /// The direction the next frame should travel in: a master alternates request and
    /// answer. It settles the rare frame that reads as valid at two lengths, as a frame
    /// that ends in 00 does (its prefix one byte shorter reads as valid too).
    expect: Option<Direction>,
}

impl Framer {
    /// `char_us`: one character's time (11 bits at the baud rate, say); silence is 3.5 of
    /// them, and 1750 us above 19200 baud.
    pub fn new(mode: Mode, char_us: f64, silence_us: u64) -> Self {
        Self {
            mode,
            silence_us,
            char_us,
            buffer: Vec::with_capacity(4096),
            times: Vec::with_capacity(4096),
            offset: 0,
            noise: Vec::new(),
            noise_offset: 0,
            noise_start: None,
            expect: None,
        }
    }

    /// Bytes from a file: no timing.
    pub fn push(&mut self, bytes: &[u8], out: &mut Vec<Event>) {
        self.buffer.extend_from_slice(bytes);
        self.times.resize(self.buffer.len(), None);
        self.scan(false, out);
    }

    /// Bytes read together, the last of them at `time`: earlier ones are placed one
    /// character time apart before it.
    pub fn push_at(&mut self, bytes: &[u8], time: u64, out: &mut Vec<Event>) {
        let n = bytes.len();
        for (i, byte) in bytes.iter().enumerate() {
            let back = ((n - 1 - i) as f64 * self.char_us) as u64;
            self.buffer.push(*byte);
            self.times.push(Some(time.saturating_sub(back)));
        }
        self.scan(false, out);
    }

    /// One byte at a known time (a timed capture).
    pub fn push_byte_at(&mut self, byte: u8, time: u64, out: &mut Vec<Event>) {
        self.buffer.push(byte);
        self.times.push(Some(time));
        self.scan(false, out);
    }

    /// The line has been quiet until `now`: a frame broken off before it is given up.
    pub fn idle(&mut self, now: u64, out: &mut Vec<Event>) {
        let quiet = match self.times.last() {
            Some(Some(last)) => now.saturating_sub(*last) >= self.silence_us,
            _ => false,
        };
        if quiet {
            self.scan(true, out);
        }
    }

    /// The end of the capture: what is left is given up.
    pub fn finish(&mut self, out: &mut Vec<Event>) {
        self.scan(true, out);
        self.flush_noise(out);
    }

    /// Whether there is silence after byte `i` of the buffer (known only with timing).
    fn silence_after(&self, i: usize) -> bool {
        match (
            self.times.get(i).copied().flatten(),
            self.times.get(i + 1).copied().flatten(),
        ) {
            (Some(a), Some(b)) => {
                b.saturating_sub(a) as f64 - self.char_us >= self.silence_us as f64
            }
            _ => false,
        }
    }

    fn scan(&mut self, at_end: bool, out: &mut Vec<Event>) {
        let mut at = 0;
        while at < self.buffer.len() {
            let look = match self.mode {
                Mode::Ascii => self.look_ascii(at, at_end),
                _ => self.look_rtu(at, at_end),
            };
            match look {
                Look::Frame(len, broken) => {
                    self.flush_noise(out);
                    out.push(Event::Frame(Found {
                        bytes: self.buffer[at..at + len].to_vec(),
                        offset: self.offset + at as u64,
                        start: self.times[at],
                        end: self.times[at + len - 1],
                        broken,
                    }));
                    at += len;
                }
                Look::Noise => {
                    if self.noise.is_empty() {
                        self.noise_offset = self.offset + at as u64;
                        self.noise_start = self.times[at];
                    }
                    self.noise.push(self.buffer[at]);
                    at += 1;
                }
                Look::NeedMore => break,
            }
        }
        self.buffer.drain(..at);
        self.times.drain(..at);
        self.offset += at as u64;
    }

    fn flush_noise(&mut self, out: &mut Vec<Event>) {
        if !self.noise.is_empty() {
            out.push(Event::Noise {
                bytes: std::mem::take(&mut self.noise),
                offset: self.noise_offset,
                start: self.noise_start,
            });
        }
    }

    /// What the bytes at `at` could be, in either direction.
    fn crc_lengths(&self, at: usize) -> Candidates {
        let data = &self.buffer[at..];
        let mut need_more = false;
        let mut waiting = Vec::new();
        let mut lengths: Vec<(usize, Option<Direction>)> = Vec::with_capacity(2);
        for direction in [Direction::Request, Direction::Response] {
            let found = match rtu_frame_length(data, direction) {
                Length::Known(len) if !(4..=limits::MAX_RTU_ADU).contains(&len) => None,
                Length::Never => None,
                Length::Known(len) => match data.get(..len) {
                    Some(frame) if crc_holds(frame) => Some(len),
                    Some(_) => None,
                    None => {
                        need_more = true;
                        waiting.push(len);
                        None
                    }
                },
                Length::AtLeast(_) => {
                    need_more = true;
                    None
                }
                Length::Unknown => {
                    // No layout known: the shortest prefix whose CRC holds.
                    let found = shortest_crc_match(data, 4, limits::MAX_RTU_ADU);
                    need_more |= found.is_none() && data.len() < limits::MAX_RTU_ADU;
                    found
                }
            };
            if let Some(len) = found {
                match lengths.iter_mut().find(|(l, _)| *l == len) {
                    Some(same) => same.1 = None,
                    None => lengths.push((len, Some(direction))),
                }
            }
        }
        lengths.sort_unstable_by_key(|(len, _)| *len);
        Candidates {
            valid: lengths,
            waiting,
            need_more,
        }
    }

    /// The valid frame at `at`: its length and direction; `Err` if more bytes are needed to
    /// tell. A decision is only made on bytes that are here, so that a stream fed byte by
    /// byte and all at once gives the same frames.
    fn valid_rtu(&self, at: usize, at_end: bool) -> Result<Option<(usize, Option<Direction>)>, ()> {
        let Candidates {
            valid: lengths,
            waiting,
            need_more,
        } = self.crc_lengths(at);
        let settled = at_end || self.silence_after(self.buffer.len() - 1);
        match lengths.as_slice() {
            [] if need_more && !settled => Err(()),
            [] => Ok(None),
            // A frame that ends in 00 leaves its prefix one byte shorter valid too, and a
            // frame followed by a 00 reads as valid one byte longer: wait for that byte.
            [(len, _)] if waiting.contains(&(len + 1)) && !settled => Err(()),
            [one] => Ok(Some(*one)),
            // Valid at two lengths: the direction the bus expects next, else the reading
            // after which the bytes go on as frames do, else the shorter.
            [shortest, ..] => {
                if let Some(expected) = self
                    .expect
                    .and_then(|d| lengths.iter().find(|(_, dir)| *dir == Some(d)))
                {
                    return Ok(Some(*expected));
                }
                for (len, direction) in &lengths {
                    let next = at + len;
                    if next == self.buffer.len() {
                        if at_end {
                            return Ok(Some((*len, *direction)));
                        }
                        // What follows is not here yet.
                        return Err(());
                    }
                    if self.silence_after(next - 1) {
                        return Ok(Some((*len, *direction)));
                    }
                    let after = self.crc_lengths(next);
                    if !after.valid.is_empty() {
                        return Ok(Some((*len, *direction)));
                    }
                    if after.need_more && !settled {
                        // Whether a frame follows is not known yet.
                        return Err(());
                    }
                }
                Ok(Some(*shortest))
            }
        }
    }

    fn look_rtu(&mut self, at: usize, at_end: bool) -> Look {
        match self.valid_rtu(at, at_end) {
            Ok(Some((len, direction))) => {
                self.expect = match (direction, self.expect) {
                    (Some(Direction::Request), _) => Some(Direction::Response),
                    (Some(Direction::Response), _) => Some(Direction::Request),
                    // Reads both ways: the turn passes all the same.
                    (None, Some(Direction::Request)) => Some(Direction::Response),
                    (None, Some(Direction::Response)) => Some(Direction::Request),
                    (None, None) => None,
                };
                Look::Frame(len, None)
            }
            Err(()) => Look::NeedMore,
            Ok(None) => match self.broken_rtu(at, at_end) {
                Some(len) => Look::Frame(len, Some(Broken::Checksum)),
                None => Look::Noise,
            },
        }
    }

    /// A frame of the predicted length whose CRC fails, told apart from noise by what
    /// follows it (a valid frame, silence, or the end of the capture) and by what it holds:
    /// no valid frame may start inside it, or the first byte was noise before that frame.
    fn broken_rtu(&self, at: usize, at_end: bool) -> Option<usize> {
        let data = &self.buffer[at..];
        let mut lengths: Vec<usize> = [Direction::Request, Direction::Response]
            .iter()
            .filter_map(|d| match rtu_frame_length(data, *d) {
                Length::Known(len)
                    if (4..=limits::MAX_RTU_ADU).contains(&len) && len <= data.len() =>
                {
                    Some(len)
                }
                _ => None,
            })
            .collect();
        lengths.sort_unstable();
        lengths.into_iter().find(|len| {
            let next = at + len;
            let ends_well = (next == self.buffer.len() && at_end)
                || self.silence_after(next - 1)
                || matches!(self.valid_rtu(next, at_end), Ok(Some(_)));
            ends_well
                && !(at + 1..next).any(|inner| matches!(self.valid_rtu(inner, true), Ok(Some(_))))
        })
    }

    fn look_ascii(&mut self, at: usize, at_end: bool) -> Look {
        let data = &self.buffer[at..];
        if data[0] != b':' {
            return Look::Noise;
        }
        let end = data.iter().skip(1).position(|b| matches!(b, b'\n' | b':'));
        match end.map(|i| i + 1) {
            Some(i) if data[i] == b':' => Look::Frame(i, Some(Broken::Incomplete)),
            Some(i) => {
                let frame = &data[..=i];
                let broken = (!lrc_holds(frame)).then_some(Broken::Checksum);
                Look::Frame(i + 1, broken)
            }
            None if data.len() >= limits::MAX_ASCII_ADU
                || at_end
                || self.silence_after(self.buffer.len() - 1) =>
            {
                Look::Frame(
                    data.len().min(limits::MAX_ASCII_ADU),
                    Some(Broken::Incomplete),
                )
            }
            None => Look::NeedMore,
        }
    }
}

fn crc_holds(frame: &[u8]) -> bool {
    let (body, crc) = frame.split_at(frame.len() - 2);
    crc16(body).to_le_bytes() == crc
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
    match bytes {
        Some(bytes) => lrc(&bytes[..bytes.len() - 1]) == bytes[bytes.len() - 1],
        None => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frames(events: &[Event]) -> Vec<Vec<u8>> {
        events
            .iter()
            .filter_map(|e| match e {
                Event::Frame(f) => Some(f.bytes.clone()),
                Event::Noise { .. } => None,
            })
            .collect()
    }

    const REQUEST: [u8; 8] = [0x11, 0x03, 0x00, 0x6B, 0x00, 0x03, 0x76, 0x87];
    const ANSWER: [u8; 11] = [
        0x11, 0x03, 0x06, 0x02, 0x2B, 0x00, 0x00, 0x00, 0x64, 0xC8, 0xBA,
    ];

    #[test]
    fn glued_frames_with_noise_between_them() {
        let mut framer = Framer::new(Mode::Rtu, 573.0, 2005);
        let mut stream = REQUEST.to_vec();
        stream.push(0x00);
        stream.extend_from_slice(&ANSWER);
        stream.push(0xFE);
        let mut out = Vec::new();
        framer.push(&stream, &mut out);
        framer.finish(&mut out);
        assert_eq!(frames(&out), [REQUEST.to_vec(), ANSWER.to_vec()]);
        let noise: Vec<&Event> = out
            .iter()
            .filter(|e| matches!(e, Event::Noise { .. }))
            .collect();
        assert_eq!(noise.len(), 2);
    }

    #[test]
    fn byte_by_byte_and_all_at_once_agree() {
        let mut stream = vec![0x00, 0xFE];
        stream.extend_from_slice(&REQUEST);
        stream.extend_from_slice(&ANSWER);
        let mut whole = Vec::new();
        let mut framer = Framer::new(Mode::Rtu, 573.0, 2005);
        framer.push(&stream, &mut whole);
        framer.finish(&mut whole);
        let mut single = Vec::new();
        let mut framer = Framer::new(Mode::Rtu, 573.0, 2005);
        for byte in &stream {
            framer.push(&[*byte], &mut single);
        }
        framer.finish(&mut single);
        assert_eq!(whole, single);
    }

    #[test]
    fn a_corrupt_frame_followed_by_a_good_one_is_a_crc_error() {
        let mut bad = REQUEST;
        bad[7] ^= 0xFF;
        let mut stream = bad.to_vec();
        stream.extend_from_slice(&ANSWER);
        let mut out = Vec::new();
        let mut framer = Framer::new(Mode::Rtu, 573.0, 2005);
        framer.push(&stream, &mut out);
        framer.finish(&mut out);
        assert!(
            matches!(&out[0], Event::Frame(f) if f.broken == Some(Broken::Checksum) && f.bytes == bad)
        );
        assert!(matches!(&out[1], Event::Frame(f) if f.broken.is_none() && f.bytes == ANSWER));
    }

    #[test]
    fn ascii_frames_noise_and_a_cut_frame() {
        let stream = b"xx:1103006B00037E\r\n:1103006B:110306022B0000006455\r\n";
        let mut out = Vec::new();
        let mut framer = Framer::new(Mode::Ascii, 573.0, 2005);
        framer.push(stream, &mut out);
        framer.finish(&mut out);
        assert!(matches!(&out[0], Event::Noise { bytes, .. } if bytes == b"xx"));
        assert!(matches!(&out[1], Event::Frame(f) if f.broken.is_none()));
        assert!(
            matches!(&out[2], Event::Frame(f) if f.broken == Some(Broken::Incomplete) && f.bytes == b":1103006B")
        );
        assert!(matches!(&out[3], Event::Frame(f) if f.broken.is_none()));
    }
}
