//! `mbtool decode [FRAME...]`: frames from the arguments or, one per line, from stdin.

use std::io::{self, Write};

use anyhow::Result;

use mbtool::cli::{Cli, DecodeArgs};
use mbtool::lines::{Line, Lines};
use mbtool::output::{self, decode::DecodeWriter};
use mbtool_core::codec::{limits, Direction, Mode};
use mbtool_core::describe::describe_frame;
use mbtool_core::model::hexinput::frame_bytes;

/// Longer lines cannot be a frame: even spaced hex of the longest ASCII frame is shorter.
const MAX_LINE: usize = 4 * limits::MAX_ASCII_ADU;

struct Decoder {
    mode: Option<Mode>,
    direction: Option<Direction>,
    writer: DecodeWriter,
    out: Box<dyn Write>,
    bytes: Vec<u8>,
    frames: u64,
    failed: u64,
    unreadable: u64,
}

impl Decoder {
    /// Decodes one line (or argument); `place` names it in error messages.
    fn line(&mut self, text: &[u8], place: impl Fn() -> String) -> io::Result<()> {
        if text.trim_ascii().is_empty() {
            return Ok(());
        }
        self.bytes.clear();
        if let Err(error) = frame_bytes(text, &mut self.bytes) {
            self.unreadable += 1;
            mbtool::note!("mbtool: {}: {error}", place());
            return Ok(());
        }
        let report = describe_frame(&self.bytes, self.mode, self.direction);
        self.frames += 1;
        self.failed += u64::from(!report.valid);
        self.writer.write(&mut self.out, &self.bytes, &report)
    }

    fn too_long(&mut self, place: String) {
        self.unreadable += 1;
        mbtool::note!(
            "mbtool: {place}: longer than {MAX_LINE} characters, which no Modbus frame is: give one frame per line"
        );
    }
}

pub fn run(cli: &Cli, args: &DecodeArgs) -> Result<u8> {
    let mut decoder = Decoder {
        mode: cli.connection.mode.map(Mode::from),
        direction: args.direction.map(Direction::from),
        writer: DecodeWriter::new(output::Style::of(cli)),
        out: output::stdout(),
        bytes: Vec::with_capacity(limits::MAX_ASCII_ADU),
        frames: 0,
        failed: 0,
        unreadable: 0,
    };
    if args.frames.is_empty() {
        let stdin = io::stdin();
        let mut lines = Lines::new(stdin.lock(), MAX_LINE);
        let mut line = Vec::with_capacity(MAX_LINE);
        let mut number = 0u64;
        while let Some(kind) = lines.next_line(&mut line)? {
            number += 1;
            match kind {
                Line::Complete => decoder.line(&line, || format!("line {number}"))?,
                Line::TooLong => decoder.too_long(format!("line {number}")),
            }
        }
    } else {
        // Arguments: one frame per argument, unless the frame was split into words
        // (`mbtool decode 11 03 00 6B ...`), which is one frame.
        let joined;
        let frames: Vec<&str> = if args.frames.iter().all(|f| f.trim().len() <= 2) {
            joined = args.frames.join(" ");
            vec![joined.as_str()]
        } else {
            args.frames.iter().map(String::as_str).collect()
        };
        for (i, frame) in frames.iter().enumerate() {
            if frame.len() > MAX_LINE {
                decoder.too_long(format!("frame {}", i + 1));
                continue;
            }
            decoder.line(frame.as_bytes(), || format!("frame {}", i + 1))?;
        }
    }
    decoder.out.flush()?;
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
