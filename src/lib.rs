//! mbtool's command line: the clap definition, the settings it resolves, the planning of
//! requests from a command's words, the output formats, the docs generator and the exit
//! codes. The Modbus work is done by `mbtool-core`.

pub mod cli;
pub mod connection;
pub mod docs;
pub mod error;
pub mod lines;
pub mod output;
pub mod plan;
pub mod poll;
