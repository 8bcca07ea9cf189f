//! Where frames go: one small interface, so that the master works the same on a serial
//! line, a TCP socket, a pseudo-terminal in a test, or the built-in simulated slave.

pub mod endpoint;
pub mod ports;
pub mod rs485;
pub mod serial;
pub mod sim;
pub mod tcp;
pub mod tls;

use std::io;
use std::time::Instant;

pub use endpoint::Endpoint;

/// A byte pipe to a slave (or, for a slave, to its master).
pub trait Transport: Send {
    /// Throws away bytes that arrived unasked, such as a late answer to an earlier request.
    fn discard_input(&mut self) -> io::Result<()>;

    /// Sends a whole frame.
    fn send(&mut self, frame: &[u8]) -> io::Result<()>;

    /// Appends to `buf` what arrives before `deadline`, waiting for at least one byte;
    /// returns how many bytes came, 0 when the deadline passed first.
    fn receive(&mut self, buf: &mut Vec<u8>, deadline: Instant) -> io::Result<usize>;

    /// Whether bytes travel on a serial line (directly or through a transparent gateway),
    /// where silence between frames matters.
    fn is_serial_line(&self) -> bool;
}

/// The time left until `deadline`, or `None` when it has passed.
pub(crate) fn time_left(deadline: Instant) -> Option<std::time::Duration> {
    deadline
        .checked_duration_since(Instant::now())
        .filter(|left| !left.is_zero())
}
