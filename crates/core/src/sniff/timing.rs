//! The timing kept beside a saved capture, so that a replay frames it exactly as the live
//! session did. `sniff --save FILE` writes the bytes, as received, to FILE and this record
//! to FILE.timing; `sniff --input FILE` replays FILE with it when it is there.
//!
//! One line per event, times in microseconds from the start of the capture:
//! - `<us> <count>`: the next `count` bytes of the capture were read together, the last
//!   of them at `<us>`;
//! - `<us> idle`: the line had been quiet until `<us>`.
//!
//! Lines starting with `#` are comments.

use std::fmt;

/// The first line of a timing file.
pub const HEADER: &str = "# mbtool sniff timing: '<us> <count>' = count bytes read together, the last at <us>; '<us> idle' = quiet until <us>";

/// The latest time a timing file may give: 2^53 microseconds, 285 years, and every time up
/// to it is exact as the seconds shown. Later ones are no capture's, and the largest would
/// read as a byte without a time.
pub const MAX_TIME_US: u64 = 1 << 53;

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
}

impl Event {
    /// When it happened, in microseconds.
    pub fn time(&self) -> u64 {
        match *self {
            Event::Bytes { time, .. } | Event::Idle { time } => time,
        }
    }
}

impl fmt::Display for Event {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Event::Bytes { time, count } => write!(f, "{time} {count}"),
            Event::Idle { time } => write!(f, "{time} idle"),
        }
    }
}

/// Reads one line; `Ok(None)` for a comment or a blank line.
pub fn parse(line: &str) -> Result<Option<Event>, String> {
    let line = line.trim();
    if line.is_empty() || line.starts_with('#') {
        return Ok(None);
    }
    let bad = || format!("'{line}' is neither '<us> <count>' nor '<us> idle'");
    let (time, what) = line.split_once(' ').ok_or_else(bad)?;
    let time = time.parse::<u64>().map_err(|_| bad())?;
    if time > MAX_TIME_US {
        return Err(format!(
            "{time} us is past any capture's times (at most 2^53 us, 285 years)"
        ));
    }
    match what.trim() {
        "idle" => Ok(Some(Event::Idle { time })),
        count => count
            .parse::<usize>()
            .map(|count| Some(Event::Bytes { time, count }))
            .map_err(|_| bad()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_time_past_285_years_is_refused() {
        assert!(parse(&format!("{MAX_TIME_US} 8")).is_ok());
        for line in ["9007199254740993 8", "18446744073709551615 idle"] {
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
        ] {
            assert_eq!(parse(&event.to_string()), Ok(Some(event)));
        }
        assert_eq!(parse(HEADER), Ok(None));
        assert!(parse("12 many").is_err());
    }
}
