//! The timing kept beside a saved capture, so that a replay frames it exactly as the live
//! session did. `sniff --save FILE` writes the bytes, as received, to FILE and this record
//! to FILE.timing; `sniff --input FILE` replays FILE with it when it is there.
//!
//! One line per event, times in microseconds from the start of the capture:
//! - `<us> <count>`: the next `count` bytes of the capture were read together, the last
//!   of them at `<us>`;
//! - `<us> idle`: the line had been quiet until `<us>`;
//! - `<us> end`: the capture ended at `<us>` (Ctrl-C), the last line: a request still
//!   waiting then had waited until there.
//!
//! Lines starting with `#` are comments, save one: `# line: rtu 9600 8N2`, the line the
//! capture was taken on (its mode, speed, data bits, parity and stop bits), which sets what
//! a silence is on the replay as it was live.

use std::fmt;
use std::io::{self, BufRead, Read, Write};

use crate::codec::Mode;
use crate::model::line::{LineSettings, Parity, BAUDS, DATA_BITS, STOP_BITS};

/// The first line of a timing file.
pub const HEADER: &str = "# mbtool sniff timing: '<us> <count>' = count bytes read together, the last at <us>; '<us> idle' = quiet until <us>; '<us> end' = the capture ended at <us>";

/// The latest time a timing file may give: 2^53 microseconds, 285 years, and every time up
/// to it is exact as the seconds shown. Later ones are no capture's, and the largest would
/// read as a byte without a time.
pub const MAX_TIME_US: u64 = 1 << 53;

/// The word after `#` that makes a comment the record of the line a capture was taken on.
const LINE_MARK: &str = "line:";

/// The line a capture was taken on, as its timing file records it: a character's time and
/// the silence that ends a frame follow from it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RecordedLine {
    /// RTU or ASCII.
    pub mode: Mode,
    /// Bits per second.
    pub baud: u32,
    /// 7 or 8.
    pub data_bits: u8,
    /// The parity bit, if any.
    pub parity: Parity,
    /// 1 or 2.
    pub stop_bits: u8,
}

impl RecordedLine {
    /// The line of a live session in `mode` on a port with `line`'s settings.
    pub fn of(mode: Mode, line: &LineSettings) -> Self {
        Self {
            mode,
            baud: line.baud,
            data_bits: line.data_bits,
            parity: line.parity,
            stop_bits: line.stop_bits,
        }
    }

    /// The line of a timing file that records it: `# line: rtu 9600 8N2`.
    pub fn as_comment(&self) -> String {
        format!("# {LINE_MARK} {self}")
    }

    /// Reads the text after `# line:`, as [`fmt::Display`] writes it.
    fn parse(text: &str) -> Result<Self, String> {
        let bad = || {
            format!(
                "{} is no line a capture was taken on, such as '# {LINE_MARK} rtu 9600 8E1'",
                quoted(&format!("# {LINE_MARK}{text}"))
            )
        };
        let mut words = text.split_ascii_whitespace();
        let (Some(mode), Some(baud), Some(character), None) =
            (words.next(), words.next(), words.next(), words.next())
        else {
            return Err(bad());
        };
        let mode = match mode.to_ascii_lowercase().as_str() {
            "rtu" => Mode::Rtu,
            "ascii" => Mode::Ascii,
            _ => return Err(bad()),
        };
        let baud = baud
            .parse::<u32>()
            .ok()
            .filter(|baud| BAUDS.contains(baud))
            .ok_or_else(bad)?;
        let [data_bits, parity, stop_bits] = character.as_bytes() else {
            return Err(bad());
        };
        let digit = |byte: &u8| byte.is_ascii_digit().then(|| byte - b'0');
        let data_bits = digit(data_bits)
            .filter(|bits| DATA_BITS.contains(bits))
            .ok_or_else(bad)?;
        let stop_bits = digit(stop_bits)
            .filter(|bits| STOP_BITS.contains(bits))
            .ok_or_else(bad)?;
        let parity = match parity.to_ascii_uppercase() {
            b'N' => Parity::None,
            b'E' => Parity::Even,
            b'O' => Parity::Odd,
            _ => return Err(bad()),
        };
        Ok(Self {
            mode,
            baud,
            data_bits,
            parity,
            stop_bits,
        })
    }
}

impl fmt::Display for RecordedLine {
    /// `rtu 9600 8N2`: the mode, then the speed and the character as a serial line's
    /// settings are written (8 data bits, no parity, 2 stop bits).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let parity = match self.parity {
            Parity::None => 'N',
            Parity::Even => 'E',
            Parity::Odd => 'O',
        };
        write!(
            f,
            "{} {} {}{parity}{}",
            self.mode.name(),
            self.baud,
            self.data_bits,
            self.stop_bits
        )
    }
}

/// The name of the timing file kept beside a capture.
pub fn beside(capture: &std::path::Path) -> std::path::PathBuf {
    let mut name = capture.as_os_str().to_owned();
    name.push(".timing");
    name.into()
}

/// One line of a timing file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Event {
    /// Bytes read together.
    Bytes {
        /// When the last of them was read, in microseconds.
        time: u64,
        /// How many bytes.
        count: usize,
    },
    /// The line had been quiet.
    Idle {
        /// Until when, in microseconds.
        time: u64,
    },
    /// The capture ended: nothing follows.
    End {
        /// When, in microseconds.
        time: u64,
    },
}

impl Event {
    /// When it happened, in microseconds.
    pub fn time(&self) -> u64 {
        match *self {
            Event::Bytes { time, .. } | Event::Idle { time } | Event::End { time } => time,
        }
    }
}

impl fmt::Display for Event {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Event::Bytes { time, count } => write!(f, "{time} {count}"),
            Event::Idle { time } => write!(f, "{time} idle"),
            Event::End { time } => write!(f, "{time} end"),
        }
    }
}

/// Reads one line; `Ok(None)` for a comment or a blank line.
fn parse(line: &str) -> Result<Option<Event>, String> {
    let line = line.trim();
    if line.is_empty() || line.starts_with('#') {
        return Ok(None);
    }
    let bad = || {
        format!(
            "{} is none of '<us> <count>', '<us> idle' and '<us> end'",
            quoted(line)
        )
    };
    // Spaces or tabs between the two words, as a hand edit leaves them.
    let mut words = line.split_ascii_whitespace();
    let (Some(time), Some(what), None) = (words.next(), words.next(), words.next()) else {
        return Err(bad());
    };
    let past =
        |time: &str| format!("{time} us is past any capture's times (at most 2^53 us, 285 years)");
    let time = match time.parse::<u64>() {
        Ok(time) if time > MAX_TIME_US => return Err(past(&time.to_string())),
        Ok(time) => time,
        // Digits all the same: a number too large for any time.
        Err(_) if time.bytes().all(|b| b.is_ascii_digit()) => return Err(past(&quoted(time))),
        Err(_) => return Err(bad()),
    };
    match what {
        "idle" => Ok(Some(Event::Idle { time })),
        "end" => Ok(Some(Event::End { time })),
        count => count
            .parse::<usize>()
            .map(|count| Some(Event::Bytes { time, count }))
            .map_err(|_| bad()),
    }
}

/// The longest line a timing file may hold: its lines are some thirty characters, and a
/// file without line ends (not a timing file at all) must not be read whole to find one.
const MAX_LINE: u64 = 4096;

/// What is wrong with a timing file.
#[derive(Debug, thiserror::Error)]
pub enum TimingError {
    /// It could not be read.
    #[error(transparent)]
    Io(io::Error),
    /// It is not UTF-8 text.
    #[error("not text")]
    NotText,
    /// A line is not an event, or does not follow from those before it.
    #[error("line {line}: {message}")]
    Line {
        /// Its number, from 1.
        line: usize,
        /// What is wrong with it.
        message: String,
    },
}

/// Reads the events of a timing file in order, a line at a time: a day of a line read a
/// byte a read is millions of lines, and holding them costs more than the capture. Each
/// event is checked against those before it: the times may not go back, and the reads may
/// not come to more than the capture's bytes.
pub struct Reader<R> {
    input: R,
    line: String,
    number: usize,
    last_time: Option<u64>,
    covered: u64,
    capture_len: u64,
    recorded: Option<RecordedLine>,
    ended: bool,
    cut_off: Option<usize>,
}

impl<R: BufRead> Reader<R> {
    /// Reads `input`, the timing of a capture of `capture_len` bytes.
    pub fn new(input: R, capture_len: u64) -> Self {
        Self {
            input,
            line: String::new(),
            number: 0,
            last_time: None,
            covered: 0,
            capture_len,
            recorded: None,
            ended: false,
            cut_off: None,
        }
    }

    /// The number of the last line, when it was cut off before its end and passed over.
    pub fn cut_off(&self) -> Option<usize> {
        self.cut_off
    }

    /// The line the capture was taken on, once the line that records it has been read.
    pub fn recorded_line(&self) -> Option<RecordedLine> {
        self.recorded
    }

    /// How many bytes of the capture the reads so far cover.
    pub fn covered(&self) -> u64 {
        self.covered
    }

    /// The time of the last event read.
    pub fn last_time(&self) -> Option<u64> {
        self.last_time
    }

    /// The next event; `Ok(None)` at the end of the file.
    pub fn next_event(&mut self) -> Result<Option<Event>, TimingError> {
        loop {
            self.line.clear();
            let read = (&mut self.input)
                .take(MAX_LINE + 1)
                .read_line(&mut self.line);
            match read {
                Ok(0) => return Ok(None),
                Ok(_) => self.number += 1,
                Err(error) if error.kind() == io::ErrorKind::InvalidData => {
                    return Err(TimingError::NotText)
                }
                Err(error) => return Err(TimingError::Io(error)),
            }
            let fault = |message| TimingError::Line {
                line: self.number,
                message,
            };
            if self.line.len() as u64 > MAX_LINE {
                return Err(fault(format!(
                    "longer than {MAX_LINE} characters, no line of a timing file"
                )));
            }
            // A byte order mark, as some editors write at the start of a file, is no text
            // of it.
            let text = match self.number {
                1 => self.line.strip_prefix('\u{feff}').unwrap_or(&self.line),
                _ => &self.line,
            };
            // The last line, cut off before its end (the capture was stopped as it was
            // written), is passed over if it does not read: the lines before it stand.
            let cut_off = !self.line.ends_with('\n');
            if let Some(record) = line_record(text) {
                let line = match RecordedLine::parse(record) {
                    Ok(line) => line,
                    Err(_) if cut_off => {
                        self.cut_off = Some(self.number);
                        return Ok(None);
                    }
                    Err(message) => return Err(fault(message)),
                };
                if self.recorded.is_some_and(|before| before != line) {
                    return Err(fault(format!(
                        "{} records another line than the one above it",
                        quoted(text.trim_end())
                    )));
                }
                self.recorded = Some(line);
                continue;
            }
            let event = match parse(text) {
                Ok(Some(event)) => event,
                Ok(None) => continue,
                Err(_) if cut_off => {
                    self.cut_off = Some(self.number);
                    return Ok(None);
                }
                Err(message) => return Err(fault(message)),
            };
            if self.ended {
                return Err(fault(format!(
                    "{} comes after the line that ends the capture",
                    quoted(text.trim())
                )));
            }
            self.ended = matches!(event, Event::End { .. });
            if let Some(before) = self.last_time.filter(|before| event.time() < *before) {
                return Err(fault(format!(
                    "{} us comes before the line above it ({before} us): the times must not go back",
                    event.time()
                )));
            }
            if let Event::Bytes { count, .. } = event {
                match self.covered.checked_add(count as u64) {
                    Some(covered) if covered <= self.capture_len => self.covered = covered,
                    _ => {
                        return Err(fault(format!(
                            "the reads come to more than the capture's {} bytes",
                            self.capture_len
                        )))
                    }
                }
            }
            self.last_time = Some(event.time());
            return Ok(Some(event));
        }
    }
}

/// The text after `# line:` on a line that records the line a capture was taken on, in
/// any case and indented as a hand edit may leave it.
fn line_record(text: &str) -> Option<&str> {
    // `#line:` and `#  line:` too: a record that is mistyped must be told, not passed over
    // as a comment.
    let text = text.trim().strip_prefix('#')?.trim_start();
    text.get(..LINE_MARK.len())
        .filter(|mark| mark.eq_ignore_ascii_case(LINE_MARK))
        .map(|_| &text[LINE_MARK.len()..])
}

/// A line as a message quotes it: its start only, when it is too long for one line.
fn quoted(line: &str) -> String {
    const SHOWN: usize = 40;
    match line.char_indices().nth(SHOWN) {
        Some((end, _)) => format!(
            "'{}...' ({} characters)",
            &line[..end],
            line.chars().count()
        ),
        None => format!("'{line}'"),
    }
}

/// `--save`: the bytes of a line as received and, captured live, their timing beside them.
pub struct Saver {
    bytes: Box<dyn Write + Send>,
    timing: Option<Box<dyn Write + Send>>,
}

impl Saver {
    /// Keeps the bytes in `bytes` and, given, their timing in `timing`, a capture of a line
    /// taken on `line`: its header is written at once.
    pub fn new(
        bytes: Box<dyn Write + Send>,
        timing: Option<(Box<dyn Write + Send>, RecordedLine)>,
    ) -> io::Result<Saver> {
        let timing = match timing {
            Some((mut file, line)) => {
                writeln!(file, "{HEADER}\n{}", line.as_comment())?;
                Some(file)
            }
            None => None,
        };
        Ok(Saver { bytes, timing })
    }

    /// `bytes` received, at `time` when the capture is live.
    pub fn bytes(&mut self, bytes: &[u8], time: Option<u64>) -> io::Result<()> {
        self.bytes.write_all(bytes)?;
        match (self.timing.as_mut(), time) {
            (Some(timing), Some(time)) => writeln!(
                timing,
                "{}",
                Event::Bytes {
                    time,
                    count: bytes.len()
                }
            ),
            _ => Ok(()),
        }
    }

    /// The line was silent at `time`, and the framer was told.
    pub fn idle(&mut self, time: u64) -> io::Result<()> {
        match self.timing.as_mut() {
            Some(timing) => writeln!(timing, "{}", Event::Idle { time }),
            None => Ok(()),
        }
    }

    /// The capture ended at `time`: a request still waiting had waited until then.
    pub fn end(&mut self, time: u64) -> io::Result<()> {
        match self.timing.as_mut() {
            Some(timing) => writeln!(timing, "{}", Event::End { time }),
            None => Ok(()),
        }
    }

    /// Writes out what is buffered.
    pub fn flush(&mut self) -> io::Result<()> {
        self.bytes.flush()?;
        match self.timing.as_mut() {
            Some(timing) => timing.flush(),
            None => Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_time_past_285_years_is_refused() {
        assert!(parse(&format!("{MAX_TIME_US} 8")).is_ok());
        for line in [
            "9007199254740993 8",
            "18446744073709551615 idle",
            "99999999999999999999 8",
        ] {
            let error = parse(line).unwrap_err();
            assert!(error.contains("past any capture's times"), "{error}");
        }
    }

    #[test]
    fn lines_read_back_as_written() {
        for event in [
            Event::Bytes {
                time: 2005,
                count: 8,
            },
            Event::Idle { time: 4100 },
            Event::End { time: 5000 },
        ] {
            assert_eq!(parse(&event.to_string()), Ok(Some(event)));
        }
        assert_eq!(parse(HEADER), Ok(None));
        assert!(parse("12 many").is_err());
        assert_eq!(
            parse("12\t8"),
            Ok(Some(Event::Bytes { time: 12, count: 8 }))
        );
        assert!(parse("12 8 9").is_err());
    }

    /// Every event of `text`, or the first fault.
    fn read_all(text: &[u8], capture_len: u64) -> Result<Vec<Event>, TimingError> {
        let mut reader = Reader::new(text, capture_len);
        let mut events = Vec::new();
        while let Some(event) = reader.next_event()? {
            events.push(event);
        }
        Ok(events)
    }

    #[test]
    fn a_file_is_read_an_event_at_a_time_and_checked_against_what_came_before() {
        let text = format!("{HEADER}\n\n2005 8\n# edited\n4100 idle\n9000 11");
        let events = read_all(text.as_bytes(), 19).unwrap();
        assert_eq!(
            events,
            [
                Event::Bytes {
                    time: 2005,
                    count: 8
                },
                Event::Idle { time: 4100 },
                Event::Bytes {
                    time: 9000,
                    count: 11
                }
            ]
        );
        let fault = |text: &str, capture_len| match read_all(text.as_bytes(), capture_len) {
            Err(TimingError::Line { line, message }) => (line, message),
            other => panic!("{other:?}"),
        };
        let (line, message) = fault("9000 8\n1000 11\n", 19);
        assert!(
            line == 2 && message.contains("must not go back"),
            "{message}"
        );
        let (line, message) = fault("9000 8\n9100 end\n9200 11\n", 19);
        assert!(
            line == 3 && message.contains("after the line that ends"),
            "{message}"
        );
        let (line, message) = fault("9000 8\n9500 18446744073709551615\n", 19);
        assert!(line == 2 && message.contains("come to more"), "{message}");
        let (line, _) = fault(&"9".repeat(10_000), 19);
        assert_eq!(line, 1);
        // A last line cut off before its end is passed over, and said to be; one that ends
        // is a fault all the same.
        for cut in ["9000 8\n17", "9000 8\n# line: rtu 96"] {
            let mut reader = Reader::new(cut.as_bytes(), 19);
            assert!(reader.next_event().unwrap().is_some());
            assert!(reader.next_event().unwrap().is_none());
            assert_eq!(reader.cut_off(), Some(2));
        }
        let (line, _) = fault("9000 8\n17\n", 19);
        assert_eq!(line, 2);
        assert!(matches!(
            read_all(&[0xFF, 0xFE, b'\n'], 19),
            Err(TimingError::NotText)
        ));
        assert_eq!(read_all("\u{feff}12 1\n".as_bytes(), 1).unwrap().len(), 1);
    }

    fn recorded_line() -> impl proptest::strategy::Strategy<Value = RecordedLine> {
        use proptest::prelude::*;
        (
            prop_oneof![Just(Mode::Rtu), Just(Mode::Ascii)],
            BAUDS,
            DATA_BITS,
            prop_oneof![Just(Parity::None), Just(Parity::Even), Just(Parity::Odd)],
            STOP_BITS,
        )
            .prop_map(|(mode, baud, data_bits, parity, stop_bits)| RecordedLine {
                mode,
                baud,
                data_bits,
                parity,
                stop_bits,
            })
    }

    proptest::proptest! {
        #[test]
        fn a_recorded_line_reads_back_as_written(line in recorded_line()) {
            let text = format!("{HEADER}\n{}\n10 1\n", line.as_comment());
            let mut reader = Reader::new(text.as_bytes(), 1);
            while reader.next_event().unwrap().is_some() {}
            proptest::prop_assert_eq!(reader.recorded_line(), Some(line));
        }

        #[test]
        fn any_text_after_the_line_mark_is_read_or_told_never_panicked_on(text in ".{0,40}") {
            let _ = RecordedLine::parse(&text);
        }
    }

    #[test]
    fn a_line_record_that_is_no_line_or_says_another_is_told() {
        let fault = |text: &str| {
            let mut reader = Reader::new(text.as_bytes(), 1);
            loop {
                match reader.next_event() {
                    Ok(Some(_)) => {}
                    Ok(None) => panic!("{text:?} read without a fault"),
                    Err(TimingError::Line { line, message }) => return (line, message),
                    Err(other) => panic!("{other:?}"),
                }
            }
        };
        for bad in [
            "# line: tcp 9600 8N1",
            "# line: rtu 49 8N1",
            "# line: rtu 9600 8X1",
            "# line: rtu 9600 6N1",
            "# line: rtu 9600 8N3",
            "# line: rtu 9600",
            "# line: rtu 9600 8N1 extra",
        ] {
            let (line, message) = fault(&format!("{bad}\n10 1\n"));
            assert!(
                line == 1 && message.contains("no line a capture"),
                "{message}"
            );
        }
        let (line, message) = fault("# line: rtu 9600 8N2\n# line: rtu 19200 8E1\n");
        assert!(line == 2 && message.contains("another line"), "{message}");
        // The same record twice, as a hand edit may leave it, is one record.
        let mut reader = Reader::new(
            "# line: rtu 9600 8N2\n# line:  rtu 9600 8N2 \n".as_bytes(),
            0,
        );
        assert!(reader.next_event().unwrap().is_none());
        assert_eq!(reader.recorded_line().map(|l| l.baud), Some(9600));
        // As a hand edit may leave it: indented, in capitals, ended CR LF, without a space.
        for text in ["  # LINE: RTU 19200 8e1\r\n", "#line:rtu 19200 8E1\n"] {
            let mut reader = Reader::new(text.as_bytes(), 0);
            assert!(reader.next_event().unwrap().is_none());
            assert_eq!(
                reader.recorded_line().map(|l| l.to_string()),
                Some("rtu 19200 8E1".to_string())
            );
        }
        // Any other comment is a comment.
        let mut reader = Reader::new("# lines: whatever\n".as_bytes(), 0);
        assert!(reader.next_event().unwrap().is_none());
        assert_eq!(reader.recorded_line(), None);
    }

    #[test]
    fn a_long_bad_line_is_quoted_by_its_start() {
        let line = "7".repeat(100_000) + " x";
        let error = parse(&line).unwrap_err();
        assert!(error.len() < 140, "{error}");
        assert!(error.contains("100000 characters"), "{error}");
        let line = "8 x".to_string() + &"7".repeat(100_000);
        let error = parse(&line).unwrap_err();
        assert!(error.len() < 140, "{error}");
        assert!(error.contains("100003 characters"), "{error}");
    }
}
