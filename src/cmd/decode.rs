//! `mbtool decode [FRAME...]`: frames from the arguments or, one per line, from stdin.

use std::borrow::Cow;
use std::io::{self, Write};

use anyhow::Result;

use mbtool::error::Error;
use mbtool::lines::{Line, Lines};
use mbtool::output::{self, decode::DecodeWriter};
use mbtool::settings::{job, Settings};
use mbtool_core::codec::framing::split_glued;
use mbtool_core::codec::{limits, Direction, Mode};
use mbtool_core::describe::{describe_frame, pair_answer, request_made, Asked, FrameReport};
use mbtool_core::input::hexdump::dump_line;
use mbtool_core::input::hexinput::{read_line, HexError};

/// Longer lines cannot be a frame: even spaced hex of the longest ASCII frame is shorter.
const MAX_LINE: usize = 4 * limits::MAX_ASCII_ADU;

struct Decoder {
    mode: Option<Mode>,
    direction: Option<Direction>,
    writer: DecodeWriter,
    out: Box<dyn Write>,
    frames: u64,
    failed: u64,
    unreadable: u64,
    /// Lines of a log that were its own messages, not frames.
    messages: u64,
    /// The request of the frame just shown: the frame after it may be its answer, and then
    /// reads with the request's addresses and quantity.
    asked: Option<Asked>,
    /// The bytes of a hex dump (Wireshark, hexdump -C, xxd, od) so far: its lines make one
    /// frame while each line's offset is the count of bytes before it.
    dump: Option<Vec<u8>>,
}

impl Decoder {
    /// Decodes one line (or argument); `place` names it in error messages. `in_log`: a
    /// line of standard input, where a log's own messages are passed over.
    fn line(&mut self, text: &[u8], in_log: bool, place: impl Fn() -> String) -> io::Result<()> {
        if let Some(line) = dump_line(text) {
            let open = self.dump.as_ref().map(Vec::len);
            match open {
                _ if line.is_at(0) && !line.bytes.is_empty() => {
                    self.end_dump()?;
                    self.dump = Some(line.bytes);
                    return Ok(());
                }
                Some(len) if line.is_at(len) => {
                    match self.dump.as_mut() {
                        Some(bytes) if !line.bytes.is_empty() => bytes.extend(line.bytes),
                        // The dump's length, on its last line: it is whole.
                        _ => self.end_dump()?,
                    }
                    return Ok(());
                }
                _ => {}
            }
        }
        self.end_dump()?;
        let frames = match read_line(text) {
            Ok(frames) => frames,
            Err(HexError::Message) if in_log => {
                self.messages += 1;
                return Ok(());
            }
            Err(error) => {
                self.unreadable += 1;
                mbtool::note!("mbtool: {}: {error}", place());
                return Ok(());
            }
        };
        for frame in frames {
            self.frame(&frame.bytes, frame.direction)?;
        }
        Ok(())
    }

    /// The frame of a dump, once its lines are read.
    fn end_dump(&mut self) -> io::Result<()> {
        match self.dump.take() {
            Some(bytes) => self.frame(&bytes, None),
            None => Ok(()),
        }
    }

    /// A frame's bytes, with the way the log says it went.
    fn frame(&mut self, bytes: &[u8], marked: Option<Direction>) -> io::Result<()> {
        let direction = self.direction.or(marked);
        let mut report = describe_frame(bytes, self.mode, direction);
        // A log's mark is the logger's point of view (Modbus Slave marks what it receives
        // Rx): where the bytes read only the other way, they decide.
        if let (None, Some(marked), false) = (self.direction, marked, report.valid) {
            let other = describe_frame(bytes, self.mode, Some(marked.opposite()));
            if other.valid {
                report = other;
            }
        }
        if !report.valid {
            // A whole packet copied from Wireshark (Ethernet, IP and TCP headers before the
            // Modbus bytes): its TCP payload is the frame.
            if let Some(payload) = tcp_payload(bytes) {
                return self.frame(payload, marked);
            }
            // Frames glued together on one line are shown one by one, as sniff finds them.
            let modes = match self.mode {
                Some(mode) => vec![mode],
                None => vec![Mode::Rtu, Mode::Tcp, Mode::Ascii],
            };
            if let Some((mode, frames)) = modes
                .into_iter()
                .find_map(|mode| split_glued(mode, bytes).map(|frames| (mode, frames)))
            {
                // A mark before the line tells the first frame's way; the others are read
                // for what they are (the answer glued to its request, say).
                for (i, bytes) in frames.iter().enumerate() {
                    let direction = if i == 0 { direction } else { self.direction };
                    self.show(bytes, describe_frame(bytes, Some(mode), direction))?;
                }
                return Ok(());
            }
        }
        self.show(bytes, report)
    }

    fn show(&mut self, bytes: &[u8], mut report: FrameReport) -> io::Result<()> {
        self.frames += 1;
        self.failed += u64::from(!report.valid);
        if let Some(asked) = self.asked.take() {
            pair_answer(&mut report, bytes, &asked);
        }
        self.asked = request_made(bytes, &report);
        self.writer.write(&mut self.out, bytes, &report)
    }

    fn too_long(&mut self, place: String) {
        self.unreadable += 1;
        mbtool::note!(
            "mbtool: {place}: longer than {MAX_LINE} characters, which no Modbus frame is: give one frame per line"
        );
    }
}

/// A line the arguments give, and where it stands, for messages.
struct ArgumentLine<'a> {
    text: Cow<'a, str>,
    /// The argument's number, from 1.
    frame: usize,
    /// The line's number within an argument of several lines.
    line: Option<usize>,
}

impl ArgumentLine<'_> {
    fn place(&self) -> String {
        match self.line {
            Some(line) => format!("frame {}, line {line}", self.frame),
            None => format!("frame {}", self.frame),
        }
    }
}

/// The lines the arguments give: one frame per argument, unless the frame was split into
/// words (`mbtool decode 11 03 00 6B ...`, `mbtool decode TX 11 03 ...`): a lone byte is no
/// frame, so words with one among them are one line. An argument of several lines
/// (`mbtool decode "$(cat log.txt)"`) is read a line at a time, as standard input is.
fn argument_lines(frames: &[String]) -> Vec<ArgumentLine<'_>> {
    let one_per_line = frames.iter().any(|f| f.contains('\n'));
    if !one_per_line && frames.iter().any(|f| f.trim_ascii().len() <= 2) {
        return vec![ArgumentLine {
            text: Cow::Owned(frames.join(" ")),
            frame: 1,
            line: None,
        }];
    }
    frames
        .iter()
        .enumerate()
        .flat_map(|(i, frame)| {
            let several = frame.trim_ascii().contains('\n');
            frame
                .lines()
                .enumerate()
                .map(move |(j, line)| ArgumentLine {
                    text: Cow::Borrowed(line),
                    frame: i + 1,
                    line: several.then_some(j + 1),
                })
        })
        .collect()
}

pub fn run(settings: &Settings, job: &job::Decode) -> Result<u8> {
    let mut decoder = Decoder {
        mode: settings.connection.mode,
        direction: job.direction,
        writer: DecodeWriter::new(settings.output.style),
        out: output::stdout(),
        frames: 0,
        failed: 0,
        unreadable: 0,
        messages: 0,
        asked: None,
        dump: None,
    };
    if job.frames.is_empty() {
        let stdin = io::stdin();
        if std::io::IsTerminal::is_terminal(&stdin) {
            mbtool::note!(
                "mbtool: decode reads frames from standard input, one a line (hex, a log, a hex dump); Ctrl-D ends, or give the frame: mbtool decode 11 03 00 6B 00 03 76 87"
            );
        }
        let mut lines = Lines::new(stdin.lock(), MAX_LINE);
        let mut line = Vec::with_capacity(MAX_LINE);
        let mut number = 0u64;
        while let Some(kind) = lines.next_line(&mut line)? {
            number += 1;
            // Text never holds a NUL byte, and a binary file soon does: one message for
            // the whole file, not one for each of its "lines".
            if line.contains(&0) {
                decoder.out.flush()?;
                let utf16 = (number == 1
                    && matches!(line.get(..2), Some([0xFF, 0xFE] | [0xFE, 0xFF])))
                    || looks_utf16(&line);
                return Err(Error::usage(if utf16 {
                    "the input is UTF-16 text (a Windows \"Unicode\" file): save it as UTF-8 or ASCII".to_string()
                } else {
                    format!("line {number} holds NUL bytes: the input is binary, not frames written as hex (a capture of raw bytes is read by `mbtool sniff --input FILE`)")
                })
                .into());
            }
            match kind {
                Line::Complete => decoder.line(&line, true, || format!("line {number}"))?,
                Line::TooLong => decoder.too_long(format!("line {number}")),
            }
        }
    } else {
        // `mbtool decode "$REQUEST" "$ANSWER"` with a variable unset or blank: a mistake,
        // not a frame to pass over, and it would change how the others are read.
        if let Some(blank) = job.frames.iter().position(|f| f.trim_ascii().is_empty()) {
            return Err(Error::usage(format!(
                "frame {} is empty: give its bytes in hex (mbtool decode 11 03 00 6B 00 03 76 87), or no argument to read frames from standard input",
                blank + 1
            ))
            .into());
        }
        for line in argument_lines(&job.frames) {
            if line.text.len() > MAX_LINE {
                decoder.too_long(line.place());
                continue;
            }
            decoder.line(line.text.as_bytes(), false, || line.place())?;
        }
        // Comments alone are no frames either.
        if decoder.frames == 0 && decoder.unreadable == 0 {
            return Err(Error::usage(
                "the arguments hold no frame, only comments: give a frame's bytes in hex (mbtool decode 11 03 00 6B 00 03 76 87)",
            )
            .into());
        }
    }
    decoder.end_dump()?;
    decoder.out.flush()?;
    if decoder.messages > 0 {
        mbtool::note!(
            "mbtool: {} passed over: words, no frame (a log's own messages)",
            output::plural(decoder.messages as usize, "line")
        );
        // Words alone are no frames: an input of nothing else is a mistake.
        if decoder.frames == 0 {
            decoder.unreadable += 1;
        }
    }
    if decoder.failed > 0 {
        mbtool::note!(
            "mbtool: {} of {} frames failed their check",
            decoder.failed,
            decoder.frames
        );
    }
    Ok(if decoder.unreadable > 0 {
        2
    } else if decoder.failed > 0 {
        4
    } else {
        0
    })
}

/// The TCP payload of a packet given whole, from its Ethernet (or IP) header on.
fn tcp_payload(bytes: &[u8]) -> Option<&[u8]> {
    use mbtool_core::sniff::capture::{segment, Packet};
    const ETHERNET: u32 = 1;
    const RAW_IP: u32 = 101;
    [ETHERNET, RAW_IP].into_iter().find_map(|link| {
        let packet = Packet {
            number: 1,
            time_us: 0,
            link,
            data: bytes,
            original_len: u32::try_from(bytes.len()).ok()?,
        };
        let payload = segment(&packet).ok()?.payload;
        (!payload.is_empty()).then_some(payload)
    })
}

/// Text in UTF-16 without its byte-order mark: printable ASCII with a NUL beside every
/// character, so about as many NULs as characters.
fn looks_utf16(line: &[u8]) -> bool {
    let nuls = line.iter().filter(|b| **b == 0).count();
    let text = line.len() - nuls;
    line.len() >= 4
        && nuls.abs_diff(text) <= 2
        && line
            .iter()
            .all(|b| *b == 0 || b.is_ascii_graphic() || b.is_ascii_whitespace())
}
