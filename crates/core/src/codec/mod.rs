//! The codec: bytes in, typed frames out. No I/O and no clocks; it is the one place that
//! knows frame layouts, and the master, sniffer, simulator and `decode` all go through it.

pub mod adu;
pub mod answer;
pub mod bits;
pub mod checksum;
pub mod error;
pub mod exception;
pub mod framing;
pub mod function;
pub mod length;
pub mod limits;
pub mod pdu;

pub use adu::{Checksum, Envelope, Frame, Mode};
pub use error::{FrameError, PduError};
pub use exception::ExceptionCode;
pub use pdu::{Direction, Exception, Pdu, Reading, Request, Response};
