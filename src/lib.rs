//! mbtool's command line: the clap definition, the settings it resolves, one module per
//! command, the output formats, the docs generator and the exit codes. The Modbus work is
//! done by `mbtool-core`, re-exported here under its own module names.

pub use mbtool_core::{
    address, codec, describe, duration, hexinput, master, number, server, sim, slave, sniff,
    transport, values,
};

pub mod cli;
pub mod connection;
pub mod docs;
pub mod error;
pub mod lines;
pub mod output;
pub mod plan;
pub mod poll;
