//! mbtool's command line: the clap definition, the settings it resolves, the output
//! formats, the docs generator and the exit codes. The Modbus work is done by
//! `mbtool-core`.

pub mod cli;
pub mod connection;
pub mod docs;
pub mod error;
pub mod lines;
pub mod output;
