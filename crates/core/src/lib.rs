//! The Modbus core of mbtool: everything but the command line. It knows nothing of clap
//! or terminals and never prints; results are data, and the binary shows them.
//!
//! - [`codec`]: PDUs, ADUs, checksums, and the framing every receiver shares; pure.
//! - [`model`]: Modicon references, value types and byte orders, and what users type.
//! - [`transport`]: serial lines, TCP, RTU over TCP and the in-process sim, behind one
//!   small interface.
//! - [`master`]: one careful transaction.
//! - [`slave`]: the data model, data files, faults, and the answer path of `serve` and of
//!   the sim.
//! - [`sniff`]: pairing, the session of a capture, pcap and timing files.
//! - [`describe`]: what a frame says, as fields.

#![warn(missing_docs, unreachable_pub)]

pub mod codec;
pub mod describe;
pub mod gateway;
pub mod input;
pub mod listener;
pub mod master;
pub mod model;
pub mod slave;
pub mod sniff;
pub mod sunspec;
pub mod transport;
