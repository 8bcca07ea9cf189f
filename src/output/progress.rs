//! A progress line on a terminal: a bar, how many of how many, a message and the time
//! left, drawn over itself on stderr and erased at the end.

use std::io::{self, Write};
use std::time::{Duration, Instant};

/// Cells in the bar, where the terminal is wide enough.
const BAR_WIDTH: usize = 30;
/// The narrowest bar worth drawing.
const MIN_BAR_WIDTH: usize = 8;
/// Redrawn at most this often: a scan asks hundreds of ids a second over TCP.
const REDRAW_EVERY: Duration = Duration::from_millis(50);

/// What a progress line shows, at one moment.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Progress<'a> {
    pub done: u64,
    pub total: u64,
    /// What is counted: `ids asked`.
    pub unit: &'a str,
    pub message: &'a str,
    /// The time left, once there is something to tell it from.
    pub left: Option<Duration>,
}

/// The line for `progress` in `width` characters: the bar narrows to leave the words
/// room, and goes where even a short bar would not fit. Words that still do not fit go
/// whole from the end (the time left, then the message), so that no number is shown cut;
/// the count alone is cut only where it does not fit itself.
pub fn render(progress: &Progress, width: usize) -> String {
    let mut parts = vec![
        format!("{}/{} {}", progress.done, progress.total, progress.unit),
        progress.message.to_string(),
    ];
    if let Some(left) = progress.left {
        parts.push(format!("{} left", human(left)));
    }
    let mut words = parts.join(", ");
    let bar_width = width
        .saturating_sub(words.chars().count() + 1)
        .min(BAR_WIDTH);
    if bar_width >= MIN_BAR_WIDTH {
        let filled = match progress.total {
            0 => bar_width,
            total => (progress.done.min(total) * bar_width as u64 / total) as usize,
        };
        return "█".repeat(filled) + &"░".repeat(bar_width - filled) + " " + &words;
    }
    while words.chars().count() > width && parts.len() > 1 {
        parts.pop();
        words = parts.join(", ");
    }
    words.chars().take(width).collect()
}

/// `7s`, `3m 05s`, `2h 10m`: whole seconds, as a glance at a terminal wants them.
fn human(duration: Duration) -> String {
    let seconds = duration.as_secs();
    match seconds {
        0..60 => format!("{seconds}s"),
        60..3600 => format!("{}m {:02}s", seconds / 60, seconds % 60),
        _ => format!("{}h {:02}m", seconds / 3600, seconds % 3600 / 60),
    }
}

/// The time the rest will take at the pace so far.
fn time_left(done: u64, total: u64, elapsed: Duration) -> Option<Duration> {
    let remaining = total.checked_sub(done)?;
    let per_step = elapsed.checked_div(u32::try_from(done).ok().filter(|&d| d > 0)?)?;
    Some(per_step.saturating_mul(u32::try_from(remaining).unwrap_or(u32::MAX)))
}

/// A progress line on stderr, or nothing at all where it is not to be shown (not a
/// terminal, or a trace on stderr that it would garble).
pub struct ProgressLine {
    shown: bool,
    done: u64,
    total: u64,
    unit: &'static str,
    message: String,
    started: Instant,
    drawn_at: Option<Instant>,
}

impl ProgressLine {
    pub fn new(total: u64, unit: &'static str, shown: bool) -> Self {
        ProgressLine {
            shown,
            done: 0,
            total,
            unit,
            message: String::new(),
            started: Instant::now(),
            drawn_at: None,
        }
    }

    pub fn set_message(&mut self, message: impl Into<String>) {
        self.message = message.into();
        self.draw();
    }

    /// One more done, and what to say now.
    pub fn advance(&mut self, message: impl Into<String>) {
        self.done += 1;
        self.set_message(message);
    }

    /// Erases the line, for what is printed next to take its place.
    pub fn clear(&mut self) {
        if self.shown && self.drawn_at.is_some() {
            let _ = write!(io::stderr(), "\r\x1b[K");
        }
        self.drawn_at = None;
    }

    fn draw(&mut self) {
        let now = Instant::now();
        if !self.shown || self.drawn_at.is_some_and(|at| now - at < REDRAW_EVERY) {
            return;
        }
        self.drawn_at = Some(now);
        let progress = Progress {
            done: self.done,
            total: self.total,
            unit: self.unit,
            message: &self.message,
            left: time_left(self.done, self.total, now - self.started),
        };
        // Three columns short of the width: a line that fills it would wrap on some
        // terminals, as would the `^C` the terminal echoes after it on Ctrl-C, and the
        // next `\r` would then draw on the line below and leave this one standing.
        let width = terminal_size::terminal_size_of(io::stderr())
            .map_or(80, |(terminal_size::Width(width), _)| usize::from(width))
            .saturating_sub(3);
        let _ = write!(io::stderr(), "\r{}\x1b[K", render(&progress, width));
    }
}

/// However the command ends (an error on the way, say), what it prints next starts on a
/// clean line.
impl Drop for ProgressLine {
    fn drop(&mut self) {
        self.clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(done: u64, message: &str, left: Option<u64>) -> Progress<'_> {
        Progress {
            done,
            total: 247,
            unit: "ids asked",
            message,
            left: left.map(Duration::from_secs),
        }
    }

    #[test]
    fn the_line_shows_the_count_the_message_and_the_time_left() {
        let line = render(&at(100, "1 found", Some(185)), 200);
        assert_eq!(
            line,
            format!(
                "{}{} 100/247 ids asked, 1 found, 3m 05s left",
                "█".repeat(12),
                "░".repeat(18)
            )
        );
    }

    #[test]
    fn no_time_left_is_shown_before_there_is_a_pace_to_tell_it_from() {
        let line = render(&at(0, "0 found", None), 200);
        assert!(line.ends_with(" 0/247 ids asked, 0 found"), "{line}");
        assert_eq!(time_left(0, 247, Duration::from_secs(3)), None);
        assert_eq!(
            time_left(10, 30, Duration::from_secs(5)),
            Some(Duration::from_secs(10))
        );
    }

    #[test]
    fn the_bar_narrows_so_that_the_words_fit() {
        let line = render(&at(100, "1 found", Some(185)), 57);
        assert_eq!(
            line,
            format!(
                "{}{} 100/247 ids asked, 1 found, 3m 05s left",
                "█".repeat(6),
                "░".repeat(11)
            )
        );
        assert_eq!(line.chars().count(), 57);
    }

    #[test]
    fn where_no_bar_fits_the_words_are_shown_alone_and_what_does_not_fit_goes_whole() {
        let line = render(&at(12, "0 found", Some(9)), 40);
        assert_eq!(line, "12/247 ids asked, 0 found, 9s left");
        let line = render(&at(6, "0 found", Some(10)), 27);
        assert_eq!(line, "6/247 ids asked, 0 found");
        let line = render(&at(12, "at 19200 8E1", Some(9)), 20);
        assert_eq!(line, "12/247 ids asked");
        let line = render(&at(12, "0 found", None), 10);
        assert_eq!(line, "12/247 ids");
    }

    #[test]
    fn durations_read_at_a_glance() {
        assert_eq!(human(Duration::from_millis(7_900)), "7s");
        assert_eq!(human(Duration::from_secs(3 * 3600 + 59)), "3h 00m");
        assert_eq!(human(Duration::from_secs(61)), "1m 01s");
    }
}
