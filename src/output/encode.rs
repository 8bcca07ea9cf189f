//! How `encode` prints frames.

use std::io::{self, Write};

use serde::Serialize;

use super::Format;
use mbtool_core::codec::hex::spaced_hex;
use mbtool_core::codec::Mode;

#[derive(Serialize)]
struct EncodedFrame<'a> {
    mode: &'static str,
    slave: u8,
    function: u8,
    frame: &'a str,
}

/// The text of a frame: an ASCII frame as its characters without CR LF, anything else as
/// spaced upper-case hex.
pub fn frame_text(mode: Mode, bytes: &[u8]) -> String {
    match mode {
        // Escaped: bytes read as ASCII that are not may hold control characters.
        Mode::Ascii => {
            mbtool_core::model::values::escape_text(bytes.strip_suffix(b"\r\n").unwrap_or(bytes))
        }
        Mode::Rtu | Mode::Tcp => spaced_hex(bytes),
    }
}

pub fn write_frame(
    out: &mut dyn Write,
    format: Format,
    mode: Mode,
    slave: u8,
    function: u8,
    bytes: &[u8],
) -> io::Result<()> {
    let text = frame_text(mode, bytes);
    match format {
        Format::Json => {
            let frame = EncodedFrame {
                mode: mode.name(),
                slave,
                function,
                frame: &text,
            };
            serde_json::to_writer(&mut *out, &frame)?;
            writeln!(out)
        }
        Format::Table | Format::Values | Format::Csv => writeln!(out, "{text}"),
    }
}
