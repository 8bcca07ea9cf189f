//! mbtool's command line: the clap definition, the settings it resolves, the output
//! formats, the docs generator and the exit codes. The Modbus work is done by
//! `mbtool-core`.

pub mod cli;
pub mod connection;
pub mod docs;
pub mod error;
pub mod lines;
pub mod output;

/// `eprintln!` that never panics: a closed stderr (`mbtool decode 2>&1 | head -1`) ends the
/// line quietly instead of the program.
#[macro_export]
macro_rules! note {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stderr(), $($arg)*);
    }};
}
