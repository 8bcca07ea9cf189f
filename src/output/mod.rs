//! Rendering results for people and for scripts. Nothing here decides anything about
//! Modbus; it only shows what the logic produced.

pub mod decode;
pub mod encode;
pub mod read;
pub mod serve;
pub mod sniff;

use std::io::{self, IsTerminal, Write};

use comfy_table::{presets, Table};

/// Standard output, buffered unless it is a terminal, where each line shows at once.
pub fn stdout() -> Box<dyn Write> {
    let stdout = io::stdout();
    if stdout.is_terminal() {
        Box::new(stdout.lock())
    } else {
        Box::new(io::BufWriter::with_capacity(1 << 16, stdout.lock()))
    }
}

/// Colour only on a terminal, and never with NO_COLOR set (https://no-color.org).
pub fn colour_wanted() -> bool {
    io::stdout().is_terminal() && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty())
}

/// A table in the house style.
pub fn new_table(colour: bool) -> Table {
    let mut table = Table::new();
    table.load_preset(presets::UTF8_FULL_CONDENSED);
    table.apply_modifier(comfy_table::modifiers::UTF8_ROUND_CORNERS);
    if colour {
        table.enforce_styling();
    } else {
        table.force_no_tty();
    }
    table
}

/// A CSV field, quoted when it needs to be.
pub fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}
