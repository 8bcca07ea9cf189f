//! mbtool's command line: the clap definition, the settings it resolves, the output
//! formats, the docs generator and the exit codes. The Modbus work is done by
//! `mbtool-core`.

pub mod cli;
pub mod connection;
pub mod docs;
pub mod error;
pub mod habits;
pub mod lines;
pub mod output;
pub mod settings;
pub mod sink;
pub mod stdin;

/// `eprintln!` that never panics: a closed stderr (`mbtool decode 2>&1 | head -1`) ends the
/// line quietly instead of the program.
#[macro_export]
macro_rules! note {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stderr(), $($arg)*);
    }};
}

/// The candidate nearest to a name typed wrong, when one is near enough to be what was
/// meant (`read-holdin` is `read-holding`).
pub fn nearest<'a>(typed: &str, candidates: impl Iterator<Item = &'a str>) -> Option<&'a str> {
    candidates
        .map(|candidate| (strsim::jaro_winkler(typed, candidate), candidate))
        .filter(|(likeness, _)| *likeness > 0.8)
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, candidate)| candidate)
}
