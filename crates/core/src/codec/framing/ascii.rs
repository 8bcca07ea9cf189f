//! ASCII: ':' starts a frame and CR LF ends it, with an LRC over the bytes.

use super::{Broken, Framer, Look};
use crate::codec::checksum::lrc;
use crate::codec::limits::MAX_ASCII_ADU;

impl Framer {
    pub(super) fn look_ascii(&self, at: usize) -> Look {
        let data = &self.buffer[at..];
        if data[0] != b':' {
            return Look::Noise;
        }
        // Fewer than four characters after the ':' spell no slave and function: a glitch,
        // as a lone byte is in RTU, and not a frame to book to a slave.
        let spells_nothing = |end: usize| {
            data[1..end]
                .iter()
                .filter(|b| !matches!(b, b'\r' | b'\n'))
                .count()
                < 4
        };
        let incomplete = |len: usize| {
            if spells_nothing(len) {
                Look::Noise
            } else {
                Look::Frame {
                    len,
                    broken: Some(Broken::Incomplete),
                    direction: None,
                }
            }
        };
        // The end is looked for within the longest frame only, so that how many bytes have
        // come does not change where a frame ends.
        for i in 1..data.len().min(MAX_ASCII_ADU) {
            // A pause longer than the character timeout cuts the frame off.
            if self.silence_after(at + i - 1) {
                return incomplete(i);
            }
            match data[i] {
                b':' => return incomplete(i),
                b'\n' if spells_nothing(i) => return Look::Noise,
                b'\n' => {
                    let frame = &data[..=i];
                    return Look::Frame {
                        len: i + 1,
                        broken: (!lrc_holds(frame)).then_some(Broken::Checksum),
                        direction: None,
                    };
                }
                _ => {}
            }
        }
        if data.len() >= MAX_ASCII_ADU {
            incomplete(MAX_ASCII_ADU)
        } else if self.quiet || self.ended {
            incomplete(data.len())
        } else {
            Look::NeedMore
        }
    }

    // ---- TCP ----
}

/// Whether an ASCII frame (':' hex LRC CR LF) is well formed and its LRC holds.
pub(super) fn lrc_holds(frame: &[u8]) -> bool {
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
    match bytes.as_deref() {
        Some([data @ .., check]) => lrc(data) == *check,
        _ => false,
    }
}
