//! Lines of a stream, ended by LF, CR LF or CR alone, each at most a bounded length, so that
//! a huge file, or one without line ends, is read in constant memory.

use std::io::{self, BufRead};

/// One line's outcome.
#[derive(Debug, PartialEq, Eq)]
pub enum Line {
    /// The line is in the buffer, without its ending.
    Complete,
    /// The line was longer than the limit; it was skipped to its end.
    TooLong,
}

pub struct Lines<R> {
    reader: R,
    max: usize,
    /// The last line ended in CR: an LF right after it belongs to that ending.
    after_cr: bool,
}

impl<R: BufRead> Lines<R> {
    pub fn new(reader: R, max: usize) -> Self {
        Self {
            reader,
            max,
            after_cr: false,
        }
    }

    /// Reads the next line into `line` (cleared first); `None` at the end of the stream.
    pub fn next_line(&mut self, line: &mut Vec<u8>) -> io::Result<Option<Line>> {
        line.clear();
        let mut too_long = false;
        let mut seen_any = false;
        loop {
            let buf = match self.reader.fill_buf() {
                Ok(buf) => buf,
                Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
                Err(e) => return Err(e),
            };
            if buf.is_empty() {
                return Ok(seen_any.then_some(if too_long {
                    Line::TooLong
                } else {
                    Line::Complete
                }));
            }
            let mut start = 0;
            if self.after_cr && buf[0] == b'\n' {
                start = 1;
            }
            self.after_cr = false;
            let rest = &buf[start..];
            match rest.iter().position(|b| *b == b'\n' || *b == b'\r') {
                Some(end) => {
                    if !too_long {
                        if line.len() + end > self.max {
                            too_long = true;
                        } else {
                            line.extend_from_slice(&rest[..end]);
                        }
                    }
                    self.after_cr = rest[end] == b'\r';
                    self.reader.consume(start + end + 1);
                    return Ok(Some(if too_long {
                        Line::TooLong
                    } else {
                        Line::Complete
                    }));
                }
                None => {
                    seen_any |= !rest.is_empty();
                    if !too_long {
                        if line.len() + rest.len() > self.max {
                            too_long = true;
                            line.clear();
                        } else {
                            line.extend_from_slice(rest);
                        }
                    }
                    let used = buf.len();
                    self.reader.consume(used);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn all(input: &[u8], max: usize) -> Vec<(Line, Vec<u8>)> {
        let mut lines = Lines::new(io::BufReader::with_capacity(4, input), max);
        let mut out = Vec::new();
        let mut line = Vec::new();
        while let Some(kind) = lines.next_line(&mut line).unwrap() {
            out.push((kind, line.clone()));
        }
        out
    }

    #[test]
    fn every_line_ending() {
        let got = all(b"a\nbb\r\nccc\rdd", 100);
        let texts: Vec<&[u8]> = got.iter().map(|(_, l)| l.as_slice()).collect();
        assert_eq!(texts, [&b"a"[..], b"bb", b"ccc", b"dd"]);
    }

    #[test]
    fn a_long_line_is_skipped_to_its_end() {
        let got = all(b"0123456789\nab\n", 5);
        assert_eq!(got[0].0, Line::TooLong);
        assert_eq!(got[1], (Line::Complete, b"ab".to_vec()));
    }
}
