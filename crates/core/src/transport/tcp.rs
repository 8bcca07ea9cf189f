//! A TCP connection carrying MBAP frames, or RTU frames through a transparent gateway.

use std::io::{self, Read, Write};
use std::net::{SocketAddr, TcpStream};
use std::sync::Arc;
use std::time::{Duration, Instant};

use super::tls::looks_like_tls;
use super::{connect_first, receive_timed, TimedRead, Transport, IDLE_CHECK_AFTER};

/// A TCP connection as a transport.
pub struct Tcp {
    /// Shared with whoever else reads, writes or closes it (a server's writing thread, the
    /// clients' registry), so that a connection holds one descriptor.
    stream: Arc<TcpStream>,
    /// The read timeout last set, in whole milliseconds: setting it is a system call, and
    /// most transactions wait with the same one.
    read_timeout_ms: u64,
    /// RTU frames through a gateway: silence between frames still matters on its line.
    serial_behind: bool,
    /// Whom the connection is with, for messages.
    peer: String,
    /// Where a connection this end made goes, and how long connecting may take: a
    /// connection the other end closed while it was idle is made again.
    reconnect: Option<(SocketAddr, Duration)>,
    /// Whether anything has come over this connection: a TLS port tells itself by its
    /// first bytes, where a later answer could begin with the same by chance.
    heard: bool,
    /// When the connection last carried a frame either way.
    last_used: Instant,
}

impl Tcp {
    /// Connects to the first address of `host` that answers within `timeout`.
    pub fn connect(
        host: &str,
        port: u16,
        timeout: Duration,
        serial_behind: bool,
    ) -> io::Result<Tcp> {
        let (stream, address) = connect_first(host, port, timeout)?;
        let mut tcp = Tcp::from_stream(stream, serial_behind)?;
        tcp.reconnect = Some((address, timeout.max(Duration::from_millis(1))));
        Ok(tcp)
    }

    /// A connected stream, as `connect` makes it or a server accepts it.
    pub fn from_stream(stream: TcpStream, serial_behind: bool) -> io::Result<Tcp> {
        Tcp::from_shared(Arc::new(stream), serial_behind)
    }

    /// A connected stream that other handles share: a server's client.
    pub fn from_shared(stream: Arc<TcpStream>, serial_behind: bool) -> io::Result<Tcp> {
        // Frames are small and each waits for an answer: send at once.
        stream.set_nodelay(true)?;
        let peer = stream
            .peer_addr()
            .map_or_else(|_| "the other end".into(), |peer| peer.to_string());
        Ok(Tcp {
            stream,
            peer,
            read_timeout_ms: 0,
            serial_behind,
            reconnect: None,
            heard: false,
            last_used: Instant::now(),
        })
    }

    /// Whether the other end has closed the connection: devices and gateways close one
    /// that has been idle for a while (often 60 s), which is no failure of the path.
    fn closed_while_idle(&mut self) -> io::Result<bool> {
        self.stream.set_nonblocking(true)?;
        let peeked = self.stream.peek(&mut [0u8; 1]);
        self.stream.set_nonblocking(false)?;
        Ok(match peeked {
            Ok(0) => true,
            Ok(_) => false,
            Err(e) => !matches!(
                e.kind(),
                io::ErrorKind::WouldBlock | io::ErrorKind::Interrupted
            ),
        })
    }

    /// Connects again where this end connected before; a connection accepted by a server
    /// is only told closed.
    fn connect_again(&mut self) -> io::Result<()> {
        let Some((address, timeout)) = self.reconnect else {
            return Err(closed(&self.peer));
        };
        let stream = TcpStream::connect_timeout(&address, timeout).map_err(|e| {
            io::Error::new(
                e.kind(),
                format!(
                    "{} closed the connection, and connecting again failed: {e}",
                    self.peer
                ),
            )
        })?;
        stream.set_nodelay(true)?;
        self.stream = Arc::new(stream);
        self.read_timeout_ms = 0;
        self.heard = false;
        Ok(())
    }
}

impl Transport for Tcp {
    fn discard_input(&mut self) -> io::Result<()> {
        self.stream.set_nonblocking(true)?;
        let mut scratch = [0u8; 512];
        let result = loop {
            match (&*self.stream).read(&mut scratch) {
                Ok(0) => break Err(closed(&self.peer)),
                Ok(_) => continue,
                Err(e) if e.kind() == io::ErrorKind::WouldBlock => break Ok(()),
                Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
                Err(e) => break Err(e),
            }
        };
        self.stream.set_nonblocking(false)?;
        match result {
            // Closed while idle: nothing was lost, and a new connection has nothing stale.
            Err(e)
                if matches!(
                    e.kind(),
                    io::ErrorKind::ConnectionAborted | io::ErrorKind::ConnectionReset
                ) && self.reconnect.is_some() =>
            {
                self.connect_again()
            }
            result => result,
        }
    }

    fn send(&mut self, frame: &[u8]) -> io::Result<()> {
        let idle = self.last_used.elapsed() >= IDLE_CHECK_AFTER;
        if idle && self.reconnect.is_some() && self.closed_while_idle()? {
            self.connect_again()?;
        }
        self.last_used = Instant::now();
        (&*self.stream)
            .write_all(frame)
            .map_err(|e| lost(&self.peer, e))
    }

    fn receive(&mut self, buf: &mut Vec<u8>, deadline: Instant) -> io::Result<usize> {
        receive_timed(self, buf, deadline)
    }

    fn is_serial_line(&self) -> bool {
        self.serial_behind
    }
}

impl TimedRead for Tcp {
    fn socket(&self) -> &TcpStream {
        &self.stream
    }

    fn timeout_ms(&mut self) -> &mut u64 {
        &mut self.read_timeout_ms
    }

    fn read_some(&mut self, chunk: &mut [u8]) -> io::Result<usize> {
        let n = (&*self.stream)
            .read(chunk)
            .map_err(|e| lost(&self.peer, e))?;
        let first = !self.heard && !self.serial_behind;
        if n == 0 && first {
            return Err(io::Error::new(
                io::ErrorKind::ConnectionAborted,
                format!(
                    "{} closed the connection without answering (a Modbus/TCP Security port does this to plain Modbus TCP: if it is one, use tls://)",
                    self.peer
                ),
            ));
        }
        if n == 0 {
            return Err(closed(&self.peer));
        }
        if first && looks_like_tls(&chunk[..n]) {
            // A device this end connected to, or a client of a server.
            let what = match self.reconnect {
                Some(_) => "this looks like a Modbus/TCP Security port: use tls://",
                None => {
                    "a Modbus/TCP Security client: it should use tcp://, or be served on tls://"
                }
            };
            return Err(io::Error::new(
                io::ErrorKind::InvalidData,
                format!("{} speaks TLS: {what}", self.peer),
            ));
        }
        self.heard = true;
        self.last_used = Instant::now();
        Ok(n)
    }
}

/// A connection the other end reset or closed under a read or a write, told with its
/// address. Not as a broken pipe, which the binary takes for its own output closed by
/// the reader; other errors (a timeout) keep what they are.
fn lost(peer: &str, error: io::Error) -> io::Error {
    match error.kind() {
        io::ErrorKind::ConnectionReset
        | io::ErrorKind::ConnectionAborted
        | io::ErrorKind::BrokenPipe => io::Error::new(
            io::ErrorKind::ConnectionAborted,
            format!("{peer} dropped the connection (it closed or restarted): {error}"),
        ),
        _ => error,
    }
}

fn closed(peer: &str) -> io::Error {
    io::Error::new(
        io::ErrorKind::ConnectionAborted,
        format!("{peer} closed the connection"),
    )
}
