//! The codec: bytes in, typed frames out. No I/O and no clocks; it is the one place that
//! knows frame layouts, and the master, sniffer, simulator and `decode` all go through it.

pub(crate) mod adu;
pub(crate) mod answer;
pub mod bits;
pub mod checksum;
mod direction;
mod error;
mod exception;
pub mod framing;
pub mod function;
pub mod hex;
pub(crate) mod length;
pub mod limits;
mod pdu;

pub use adu::{Checksum, Envelope, Frame, Mode};
pub use answer::Mismatch;
pub use error::{FrameError, PduError};
pub use exception::ExceptionCode;
pub use pdu::file;
pub(crate) use pdu::{diagnostic_only_reads, function_only_reads};
pub use pdu::{
    DeviceIdentification, DeviceObject, Direction, Exception, FileRecords, FileSpan, Pdu, Reading,
    Request, Response, Ways,
};
