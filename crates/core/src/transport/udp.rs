//! Modbus over UDP: a frame a datagram, MBAP or RTU. Datagrams from anywhere but the
//! device asked are passed over and counted.

use std::io;
use std::net::{SocketAddr, ToSocketAddrs, UdpSocket};
use std::time::{Duration, Instant};

use super::{time_left, whole_ms, Foreign, Transport};

/// A datagram is at most this long: far more than a Modbus frame, so that a longer
/// one is read whole and found to be no frame.
const MOST: usize = 2048;

/// A UDP socket that talks to one device.
pub struct Udp {
    socket: UdpSocket,
    peer: SocketAddr,
    /// RTU frames: a serial line is behind the device server.
    serial_behind: bool,
    /// The read timeout last set, in whole milliseconds.
    read_timeout_ms: u64,
    /// Datagrams that came from elsewhere than `peer`, and the last one's source.
    foreign: Option<(u64, SocketAddr)>,
}

impl Udp {
    /// A socket for `host`'s first address, bound to an ephemeral port of this machine.
    pub fn connect(host: &str, port: u16, serial_behind: bool) -> io::Result<Udp> {
        let peer = (host, port).to_socket_addrs()?.next().ok_or_else(|| {
            io::Error::new(io::ErrorKind::NotFound, format!("{host} has no address"))
        })?;
        let any: SocketAddr = match peer {
            SocketAddr::V4(_) => (std::net::Ipv4Addr::UNSPECIFIED, 0).into(),
            SocketAddr::V6(_) => (std::net::Ipv6Addr::UNSPECIFIED, 0).into(),
        };
        Ok(Udp {
            socket: UdpSocket::bind(any)?,
            peer,
            serial_behind,
            read_timeout_ms: 0,
            foreign: None,
        })
    }

    /// One datagram from the device into `buf`, before `deadline`; 0 when none came.
    fn receive_one(&mut self, buf: &mut Vec<u8>, deadline: Option<Instant>) -> io::Result<usize> {
        let mut datagram = [0u8; MOST];
        loop {
            match deadline {
                Some(deadline) => {
                    let Some(left) = time_left(deadline) else {
                        return Ok(0);
                    };
                    let left_ms = whole_ms(left);
                    if left_ms != self.read_timeout_ms {
                        self.socket
                            .set_read_timeout(Some(Duration::from_millis(left_ms)))?;
                        self.read_timeout_ms = left_ms;
                    }
                }
                None => self.socket.set_nonblocking(true)?,
            }
            let received = self.socket.recv_from(&mut datagram);
            if deadline.is_none() {
                self.socket.set_nonblocking(false)?;
            }
            match received {
                Ok((n, from)) if from == self.peer => {
                    buf.extend_from_slice(&datagram[..n]);
                    return Ok(n);
                }
                Ok((_, from)) => {
                    let count = self.foreign.map_or(0, |(count, _)| count);
                    self.foreign = Some((count + 1, from));
                }
                Err(e)
                    if matches!(
                        e.kind(),
                        io::ErrorKind::WouldBlock | io::ErrorKind::TimedOut
                    ) =>
                {
                    return Ok(0)
                }
                // An earlier datagram found no one listening: told by the missing answer.
                Err(e)
                    if matches!(
                        e.kind(),
                        io::ErrorKind::Interrupted | io::ErrorKind::ConnectionRefused
                    ) => {}
                Err(e) => return Err(e),
            }
        }
    }
}

/// The next datagram that comes to `socket`, and where from. The errors an earlier
/// datagram's ICMP answer leaves (its sender gone) are no fault of this socket: passed over.
pub fn next_datagram(socket: &UdpSocket, buf: &mut [u8]) -> io::Result<(usize, SocketAddr)> {
    loop {
        match socket.recv_from(buf) {
            Err(e)
                if matches!(
                    e.kind(),
                    io::ErrorKind::Interrupted
                        | io::ErrorKind::ConnectionRefused
                        | io::ErrorKind::ConnectionReset
                ) => {}
            received => return received,
        }
    }
}

impl Transport for Udp {
    fn discard_input(&mut self) -> io::Result<()> {
        let mut scratch = Vec::new();
        while self.receive_one(&mut scratch, None)? > 0 {
            scratch.clear();
        }
        Ok(())
    }

    fn send(&mut self, frame: &[u8]) -> io::Result<()> {
        self.socket.send_to(frame, self.peer).map(|_| ())
    }

    fn receive(&mut self, buf: &mut Vec<u8>, deadline: Instant) -> io::Result<usize> {
        self.receive_one(buf, Some(deadline))
    }

    fn is_serial_line(&self) -> bool {
        self.serial_behind
    }

    fn is_datagram(&self) -> bool {
        true
    }

    fn foreign(&self) -> Option<Foreign> {
        self.foreign.map(|(count, last_from)| Foreign {
            count,
            last_from,
            device: self.peer,
        })
    }
}
