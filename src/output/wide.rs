//! A poll on the screen, one line a poll: a wide CSV with a time column and a column per
//! value (as Modbus Poll logs), or a table that grows by a row a poll. A poll that failed
//! is a row with no values, a gap, never the last values again.

use std::io::{self, Write};

use super::{csv_field, Format};

/// The narrowest column a value gets, so that a number that grows by a digit keeps its
/// column in line.
const MIN_WIDTH: usize = 6;

/// The rows of a poll whose values are the `columns`, in that order.
pub struct WideRows {
    columns: Vec<String>,
    colour: bool,
    header_written: bool,
    /// The values of the last poll that read, to mark what changed since.
    previous: Option<Vec<Option<String>>>,
    /// Each column's width in the table: its name's or its first value's, whichever is
    /// wider, and wider still where a later value needs it.
    widths: Vec<usize>,
}

impl WideRows {
    pub fn new(columns: Vec<String>, colour: bool) -> Self {
        Self {
            columns,
            colour,
            header_written: false,
            previous: None,
            widths: Vec::new(),
        }
    }

    /// The values' names, in the order of the columns.
    pub fn columns(&self) -> &[String] {
        &self.columns
    }

    /// The rows go on a file that has its CSV header already.
    pub fn continuing(&mut self) {
        self.header_written = true;
    }

    /// One poll: a value (or none, for a value the device did not give) per column, and
    /// what failed, if anything did.
    pub fn row(
        &mut self,
        out: &mut dyn Write,
        format: Format,
        time: &str,
        values: Vec<Option<String>>,
        error: &str,
    ) -> io::Result<()> {
        self.header(out, format, &values)?;
        match format {
            Format::Table => {
                let changed: Vec<bool> = match &self.previous {
                    Some(previous) => values
                        .iter()
                        .zip(previous)
                        .map(|(now, before)| now.is_some() && now != before)
                        .collect(),
                    None => vec![false; values.len()],
                };
                let cells: Vec<(String, bool)> = values
                    .iter()
                    .map(|value| value.clone().unwrap_or_else(|| "-".into()))
                    .zip(changed)
                    .collect();
                self.table_line(out, time, &cells)?;
            }
            _ => {
                let cells: Vec<String> = values
                    .iter()
                    .map(|value| csv_field(value.as_deref().unwrap_or_default()))
                    .collect();
                writeln!(out, "{time},{},{}", cells.join(","), csv_field(error))?;
            }
        }
        self.previous = Some(values);
        Ok(())
    }

    /// A poll that read nothing: a row without values. In the table its error is on
    /// stderr, told by the poll.
    pub fn gap(
        &mut self,
        out: &mut dyn Write,
        format: Format,
        time: &str,
        error: &str,
    ) -> io::Result<()> {
        self.header(out, format, &[])?;
        match format {
            Format::Table => {
                let cells = vec![("-".to_string(), false); self.columns.len()];
                self.table_line(out, time, &cells)
            }
            _ => writeln!(
                out,
                "{time},{}{}",
                ",".repeat(self.columns.len()),
                csv_field(error)
            ),
        }
    }

    /// The header, before the first row (whose `first` values set the columns' widths).
    fn header(
        &mut self,
        out: &mut dyn Write,
        format: Format,
        first: &[Option<String>],
    ) -> io::Result<()> {
        if self.header_written {
            return Ok(());
        }
        self.header_written = true;
        match format {
            Format::Table => {
                self.widths = self
                    .columns
                    .iter()
                    .enumerate()
                    .map(|(i, column)| {
                        let value = first.get(i).and_then(Option::as_deref).unwrap_or("");
                        // A changed value may carry a mark.
                        let value = value.chars().count() + 1;
                        column.chars().count().max(value).max(MIN_WIDTH)
                    })
                    .collect();
                let names: Vec<(String, bool)> =
                    self.columns.iter().map(|c| (c.clone(), false)).collect();
                self.table_line(out, "time", &names)
            }
            _ => {
                let names: Vec<String> = self.columns.iter().map(|c| csv_field(c)).collect();
                writeln!(out, "time,{},error", names.join(","))
            }
        }
    }

    /// A line of the table: the time of day, then each cell in its column, a changed
    /// value in yellow (or marked `*` without colour).
    fn table_line(
        &mut self,
        out: &mut dyn Write,
        time: &str,
        cells: &[(String, bool)],
    ) -> io::Result<()> {
        let time = super::time_of_day(time);
        let mut line = format!("{time:<12}");
        for ((text, changed), width) in cells.iter().zip(self.widths.iter_mut()) {
            let shown = match (changed, self.colour) {
                (true, true) => format!("\x1b[33m{text}\x1b[0m"),
                (true, false) => format!("{text}*"),
                (false, _) => text.clone(),
            };
            let visible = text.chars().count() + usize::from(*changed && !self.colour);
            *width = (*width).max(visible);
            line.push_str("  ");
            line.push_str(&shown);
            line.push_str(&" ".repeat(*width - visible + 1));
        }
        writeln!(out, "{}", line.trim_end())
    }
}
