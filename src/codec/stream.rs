//! Incremental decoding of a byte stream, in the manner of httparse: feed what has arrived,
//! get a complete frame with its length, an invalid one with its length, or "need more".
//! Feeding a stream byte by byte or all at once gives the same frames.

use super::adu::{Frame, Mode};
use super::checksum::shortest_crc_match;
use super::error::FrameError;
use super::length::{rtu_frame_length, tcp_frame_length, Length};
use super::limits;
use super::pdu::Direction;

#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Status {
    /// A whole, valid frame occupies the first `len` bytes.
    Complete { frame: Frame, len: usize },
    /// The first `len` bytes are a frame (or a run of noise) that is not valid.
    Invalid { error: FrameError, len: usize },
    /// Not enough bytes yet.
    Partial,
}

/// Decodes frames of one mode travelling in one direction.
#[derive(Clone, Copy, Debug)]
pub struct StreamDecoder {
    pub mode: Mode,
    pub direction: Direction,
}

impl StreamDecoder {
    pub fn new(mode: Mode, direction: Direction) -> Self {
        Self { mode, direction }
    }

    /// Looks at the start of `buf` for one frame.
    pub fn decode(&self, buf: &[u8]) -> Status {
        match self.mode {
            Mode::Rtu => self.rtu(buf),
            Mode::Ascii => self.ascii(buf),
            Mode::Tcp => self.tcp(buf),
        }
    }

    fn whole(&self, frame: &[u8]) -> Status {
        match Frame::decode(self.mode, frame, self.direction) {
            Ok(decoded) => Status::Complete {
                frame: decoded,
                len: frame.len(),
            },
            Err(error) => Status::Invalid {
                error,
                len: frame.len(),
            },
        }
    }

    fn rtu(&self, buf: &[u8]) -> Status {
        match rtu_frame_length(buf, self.direction) {
            Length::Known(len) if len > limits::MAX_RTU_ADU => Status::Invalid {
                error: FrameError::TooLong {
                    mode: "RTU",
                    actual: len,
                    max: limits::MAX_RTU_ADU,
                },
                len: buf.len(),
            },
            Length::Known(len) => match buf.get(..len) {
                Some(frame) => self.whole(frame),
                None => Status::Partial,
            },
            Length::AtLeast(_) => Status::Partial,
            Length::Never => Status::Invalid {
                error: FrameError::Pdu(crate::codec::PduError::BadField(
                    "no frame in this direction has this function code",
                )),
                len: 1,
            },
            // A function code without a known layout: the shortest prefix whose CRC holds.
            Length::Unknown => match shortest_crc_match(buf, 4, limits::MAX_RTU_ADU) {
                Some(len) => self.whole(&buf[..len]),
                None if buf.len() >= limits::MAX_RTU_ADU => Status::Invalid {
                    error: FrameError::TooLong {
                        mode: "RTU",
                        actual: buf.len(),
                        max: limits::MAX_RTU_ADU,
                    },
                    len: buf.len(),
                },
                None => Status::Partial,
            },
        }
    }

    fn ascii(&self, buf: &[u8]) -> Status {
        let Some(&first) = buf.first() else {
            return Status::Partial;
        };
        if first != b':' {
            let len = buf.iter().position(|b| *b == b':').unwrap_or(buf.len());
            return Status::Invalid {
                error: FrameError::AsciiNoColon,
                len,
            };
        }
        // A new ':' before the line end means this frame was cut off.
        let end = buf.iter().skip(1).position(|b| matches!(b, b'\n' | b':'));
        match end.map(|i| i + 1) {
            Some(i) if buf[i] == b':' => Status::Invalid {
                error: FrameError::AsciiNoEnd,
                len: i,
            },
            Some(i) => self.whole(&buf[..=i]),
            None if buf.len() >= limits::MAX_ASCII_ADU => Status::Invalid {
                error: FrameError::TooLong {
                    mode: "ASCII",
                    actual: buf.len(),
                    max: limits::MAX_ASCII_ADU,
                },
                len: buf.len(),
            },
            None => Status::Partial,
        }
    }

    fn tcp(&self, buf: &[u8]) -> Status {
        match tcp_frame_length(buf) {
            Length::Known(len) if !(8..=limits::MAX_TCP_ADU).contains(&len) => Status::Invalid {
                error: FrameError::MbapLength {
                    declared: len.saturating_sub(6),
                    actual: buf.len().saturating_sub(6),
                },
                len: buf.len(),
            },
            Length::Known(len) => match buf.get(..len) {
                Some(frame) => self.whole(frame),
                None => Status::Partial,
            },
            _ => Status::Partial,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const ANSWER: [u8; 11] = [
        0x11, 0x03, 0x06, 0x02, 0x2B, 0x00, 0x00, 0x00, 0x64, 0xC8, 0xBA,
    ];

    #[test]
    fn partial_until_the_last_byte_then_complete() {
        let decoder = StreamDecoder::new(Mode::Rtu, Direction::Response);
        for end in 0..ANSWER.len() {
            assert_eq!(decoder.decode(&ANSWER[..end]), Status::Partial, "at {end}");
        }
        assert!(matches!(
            decoder.decode(&ANSWER),
            Status::Complete { len: 11, .. }
        ));
    }

    #[test]
    fn ascii_frame_cut_off_by_a_new_colon_is_invalid_up_to_the_colon() {
        let decoder = StreamDecoder::new(Mode::Ascii, Direction::Request);
        let status = decoder.decode(b":1103006B:1103006B00037E\r\n");
        assert_eq!(
            status,
            Status::Invalid {
                error: FrameError::AsciiNoEnd,
                len: 9
            }
        );
    }
}
