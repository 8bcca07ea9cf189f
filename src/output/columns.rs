//! Columns of a text line written without the formatter: a sniffer writes millions of
//! lines, and the formatter's widths (`{:<30}`) and machinery cost more than the rest of a
//! line.

/// Blanks to align columns with: pushed as one slice, where the formatter's own widths
/// (`{:<30}`) push a character at a time, which cost a sniffer more than the rest of a line.
pub(crate) const SPACES: &str = "                                        ";

#[derive(Clone, Copy)]
pub(crate) enum Align {
    Left,
    Right,
}

/// Appends `value` to `text` as a column of the line that began at byte `line`, the column
/// ending `stop` characters into the line, as `{:<width$}` or `{:>width$}` would. The
/// columns are ASCII. A value wider than its column pushes the line on only as far as the
/// next column's blanks allow: the stops stay put, so that a frame number past 999999 or
/// the longest function name does not shift every column after it.
pub(crate) fn column(
    text: &mut String,
    line: usize,
    stop: usize,
    align: Align,
    value: impl ColumnText,
) {
    let start = text.len();
    value.push_to(text);
    match align {
        Align::Left => pad_to(text, line, stop),
        Align::Right => {
            let pad = stop.saturating_sub(text.len() - line);
            // A value pushed up to the one before it keeps a blank between them.
            let pad = match pad {
                0 if start > line && !text[..start].ends_with(' ') => 1,
                pad => pad.min(SPACES.len()),
            };
            text.insert_str(start, &SPACES[..pad]);
        }
    }
}

/// What a column holds, pushed onto the line without the formatter where it can be: its
/// machinery cost a sniffer's table more than the rest of a line.
pub(crate) trait ColumnText {
    fn push_to(self, text: &mut String);
}

impl ColumnText for &str {
    fn push_to(self, text: &mut String) {
        text.push_str(self);
    }
}

impl ColumnText for u64 {
    fn push_to(self, text: &mut String) {
        text.push_str(itoa::Buffer::new().format(self));
    }
}

impl ColumnText for u8 {
    fn push_to(self, text: &mut String) {
        text.push_str(itoa::Buffer::new().format(self));
    }
}

impl ColumnText for std::fmt::Arguments<'_> {
    fn push_to(self, text: &mut String) {
        use std::fmt::Write as _;
        let _ = text.write_fmt(self);
    }
}

/// Seconds from microseconds with six decimals, as `{:.6}` writes them.
pub(crate) struct Seconds(pub(crate) u64);

impl ColumnText for Seconds {
    fn push_to(self, text: &mut String) {
        let _ = self.write_to(text);
    }
}

impl Seconds {
    /// Digit by digit: the formatter's machinery cost a sniffer's table a tenth of its time.
    fn write_to(&self, out: &mut impl std::fmt::Write) -> std::fmt::Result {
        let mut digits = itoa::Buffer::new();
        out.write_str(digits.format(self.0 / 1_000_000))?;
        out.write_str(".")?;
        let fraction = digits.format(self.0 % 1_000_000);
        out.write_str(&"00000"[..6 - fraction.len()])?;
        out.write_str(fraction)
    }
}

impl std::fmt::Display for Seconds {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.write_to(f)
    }
}

/// A place in the input, `@offset`, where no time is known.
pub(crate) struct Offset(pub(crate) u64);

impl ColumnText for Offset {
    fn push_to(self, text: &mut String) {
        text.push('@');
        text.push_str(itoa::Buffer::new().format(self.0));
    }
}

/// Blanks up to `stop` characters into the line that began at byte `line`.
pub(crate) fn pad_to(text: &mut String, line: usize, stop: usize) {
    let at = text.len() - line;
    text.push_str(&SPACES[..stop.saturating_sub(at).min(SPACES.len())]);
}
