//! TCP: the MBAP header's length frames, however the bytes were segmented. A receiver on
//! its own connection gives up at a header that is no MBAP header; a capture seen from
//! outside ([`Framer::resynchronising`]) looks for the next header that reads instead.

use super::{Broken, Framer, Look};
use crate::codec::length::{tcp_frame_length, Length};
use crate::codec::limits::MAX_TCP_ADU;

/// What the bytes at a position say of an MBAP header there.
enum Header {
    /// It reads, as far as the bytes go: the whole ADU is this long, when told.
    Reads(Option<usize>),
    /// It cannot be one.
    Not,
}

/// Protocol id 0, and a length that holds a unit id and a function at least and at most a
/// whole PDU. Out of step, seen from outside, also a function code that exists (1-127, or
/// an exception's 129-255), so that data is not taken for a header; in step, the MBAP
/// header frames whatever function follows it, 00 included, as a server frames it to
/// answer it exception 01.
fn header(data: &[u8], outside: bool) -> Header {
    if let Some([hi, lo]) = data.get(2..4) {
        if [*hi, *lo] != [0, 0] {
            return Header::Not;
        }
    }
    if outside && matches!(data.get(7), Some(0 | 0x80)) {
        return Header::Not;
    }
    match tcp_frame_length(data) {
        Length::Known(len) if !(8..=MAX_TCP_ADU).contains(&len) => Header::Not,
        Length::Known(len) => Header::Reads(Some(len)),
        _ => Header::Reads(None),
    }
}

impl Framer {
    /// A framer of a TCP capture seen from outside: a header that is no MBAP header (a
    /// capture that starts mid-connection, bytes lost) is passed over as noise, and the
    /// framer picks up again at the first header that reads and that a header, or the end
    /// of what has come, follows.
    pub fn resynchronising(mut self) -> Self {
        self.resync = true;
        self
    }

    pub(super) fn look_tcp(&self, at: usize, in_step: bool) -> Look {
        if self.lost {
            return Look::Lost;
        }
        let data = &self.buffer[at..];
        let unread = |len| Look::Frame {
            len,
            broken: None,
            direction: None,
        };
        match header(data, self.resync && !in_step) {
            Header::Not if self.resync => Look::Noise,
            Header::Not => Look::Lost,
            Header::Reads(Some(len)) if len <= data.len() => {
                // Out of step, a header that reads could be data: what follows must read too.
                let followed = match header(&data[len..], true) {
                    _ if len == data.len() => true,
                    Header::Reads(_) => true,
                    Header::Not => false,
                };
                match in_step || !self.resync || followed {
                    true => unread(len),
                    false => Look::Noise,
                }
            }
            // The stream ends, or bytes are missing, inside a frame begun in step.
            Header::Reads(Some(_)) if self.ended && self.resync && in_step => Look::Frame {
                len: data.len(),
                broken: Some(Broken::Incomplete),
                direction: None,
            },
            _ if self.ended && self.resync => Look::Noise,
            _ if self.ended => Look::Lost,
            _ => Look::NeedMore,
        }
    }
}
