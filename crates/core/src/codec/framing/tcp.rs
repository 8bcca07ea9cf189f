//! TCP: the MBAP header's length frames, however the bytes were segmented.

use super::{Framer, Look};
use crate::codec::length::{tcp_frame_length, Length};
use crate::codec::limits::MAX_TCP_ADU;

impl Framer {
    pub(super) fn look_tcp(&self, at: usize) -> Look {
        if self.lost {
            return Look::Lost;
        }
        let data = &self.buffer[at..];
        if let Some([hi, lo]) = data.get(2..4) {
            if [*hi, *lo] != [0, 0] {
                return Look::Lost;
            }
        }
        match tcp_frame_length(data) {
            // Unit id and function at least; at most a whole PDU.
            Length::Known(len) if !(8..=MAX_TCP_ADU).contains(&len) => Look::Lost,
            Length::Known(len) if len <= data.len() => Look::Frame {
                len,
                broken: None,
                direction: None,
            },
            _ if self.ended => Look::Lost,
            _ => Look::NeedMore,
        }
    }
}
