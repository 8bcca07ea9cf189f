//! Where frames go: one small interface, so that the master works the same on a serial
//! line, a TCP socket, a pseudo-terminal in a test, or the built-in simulated slave.

pub mod endpoint;
pub mod ports;
pub mod rs485;
pub mod serial;
pub mod tcp;
pub mod tls;
pub mod udp;

use std::io;
use std::time::Instant;

pub use endpoint::Endpoint;

/// How long a connection goes unused before a master checks, as it sends, whether the
/// other end has closed it: devices close idle connections (some gateways after every
/// answer, which reaches here within a millisecond), and a master asking back to back
/// saves the check's system calls.
pub(crate) const IDLE_CHECK_AFTER: std::time::Duration = std::time::Duration::from_millis(5);

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

    /// Whether each receive is one datagram, whose end ends what it carries.
    fn is_datagram(&self) -> bool {
        false
    }

    /// The datagrams that came from elsewhere than the device asked, passed over.
    fn foreign(&self) -> Option<Foreign> {
        None
    }
}

/// Datagrams that came from elsewhere than the device asked, and were passed over.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Foreign {
    /// How many.
    pub count: u64,
    /// Where the last came from.
    pub last_from: std::net::SocketAddr,
    /// The device asked.
    pub device: std::net::SocketAddr,
}

/// A TCP connection to the first address of `host` that answers within `timeout`, and
/// that address.
pub(crate) fn connect_first(
    host: &str,
    port: u16,
    timeout: std::time::Duration,
) -> io::Result<(std::net::TcpStream, std::net::SocketAddr)> {
    use std::net::ToSocketAddrs;
    let timeout = timeout.max(std::time::Duration::from_millis(1));
    let mut last_error = None;
    for address in (host, port).to_socket_addrs()? {
        match std::net::TcpStream::connect_timeout(&address, timeout) {
            Ok(stream) => return Ok((stream, address)),
            Err(error) => last_error = Some(error),
        }
    }
    Err(last_error.unwrap_or_else(|| {
        io::Error::new(io::ErrorKind::NotFound, format!("{host} has no address"))
    }))
}

/// The time left until `deadline`, or `None` when it has passed.
pub(crate) fn time_left(deadline: Instant) -> Option<std::time::Duration> {
    deadline
        .checked_duration_since(Instant::now())
        .filter(|left| !left.is_zero())
}

/// The value behind `mutex`, even if a thread panicked while it held it: what it guards
/// (a connection's TLS state, a server's data) stays usable.
pub(crate) fn lock<T>(mutex: &std::sync::Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    match mutex.lock() {
        Ok(guard) => guard,
        Err(poisoned) => poisoned.into_inner(),
    }
}

/// A socket's read timeout for `left`: rounded up to whole milliseconds, so that it is
/// rarely changed; never 0, which would mean no timeout at all.
pub(crate) fn whole_ms(left: std::time::Duration) -> u64 {
    (left.as_micros().div_ceil(1000) as u64).max(1)
}

/// A socket read whose wait is bounded by a read timeout: TCP and TLS alike.
pub(crate) trait TimedRead {
    /// The socket whose read timeout bounds the wait.
    fn socket(&self) -> &std::net::TcpStream;
    /// The read timeout last set, in whole milliseconds: setting it is a system call,
    /// and most transactions wait with the same one.
    fn timeout_ms(&mut self) -> &mut u64;
    /// Reads what the socket has, as the transport reads it; 0 bytes is an error there.
    fn read_some(&mut self, chunk: &mut [u8]) -> io::Result<usize>;
}

/// [`Transport::receive`] over a [`TimedRead`]: appends to `buf` what arrives before
/// `deadline`, 0 when the deadline passed first.
pub(crate) fn receive_timed(
    reader: &mut impl TimedRead,
    buf: &mut Vec<u8>,
    deadline: Instant,
) -> io::Result<usize> {
    let mut chunk = [0u8; 512];
    loop {
        let Some(left) = time_left(deadline) else {
            return Ok(0);
        };
        let left_ms = whole_ms(left);
        if left_ms != *reader.timeout_ms() {
            reader
                .socket()
                .set_read_timeout(Some(std::time::Duration::from_millis(left_ms)))?;
            *reader.timeout_ms() = left_ms;
        }
        match reader.read_some(&mut chunk) {
            Ok(n) => {
                buf.extend_from_slice(&chunk[..n]);
                return Ok(n);
            }
            Err(e)
                if matches!(
                    e.kind(),
                    io::ErrorKind::WouldBlock | io::ErrorKind::TimedOut
                ) =>
            {
                return Ok(0)
            }
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        }
    }
}
