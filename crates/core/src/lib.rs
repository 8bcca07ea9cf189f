//! The Modbus core of mbtool: everything but the command line. It knows nothing of clap
//! or terminals and never prints; results are data, and the binary shows them.
//!
//! - [`codec`]: PDUs, ADUs, checksums, and the framing every receiver shares; pure.
//! - [`address`], [`values`], [`number`], [`duration`], [`hexinput`]: the model: Modicon
//!   references, value types and byte orders, and what users type.
//! - [`transport`]: serial lines, TCP, RTU over TCP, behind one small interface.
//! - [`master`]: one careful transaction.
//! - [`slave`], [`server`], [`sim`]: the data model and the answer path of `serve` and
//!   the built-in simulated slave.
//! - [`sniff`]: pairing, the session of a capture, pcap and timing files.
//! - [`describe`]: what a frame says, as fields.

pub mod address;
pub mod choice;
pub mod codec;
pub mod describe;
pub mod duration;
pub mod hexinput;
pub mod master;
pub mod number;
pub mod server;
pub mod sim;
pub mod slave;
pub mod sniff;
pub mod transport;
pub mod values;
