//! mbtool: Modbus diagnostics. The library holds everything but the command-line edge:
//! the pure codec, addresses and value types, request planning, frame reports and their
//! output formats.

pub mod address;
pub mod cli;
pub mod codec;
pub mod connection;
pub mod docs;
pub mod duration;
pub mod error;
pub mod hexinput;
pub mod lines;
pub mod master;
pub mod number;
pub mod output;
pub mod plan;
pub mod poll;
pub mod report;
pub mod server;
pub mod sim;
pub mod slave;
pub mod sniff;
pub mod transport;
pub mod values;
