//! The server side of a connection, shared by `serve` and `gateway`: TCP clients accepted
//! without letting any hold up another (`clients`), and the frames a stream carries found
//! by the codec's framer, as every receiver of mbtool finds them.

pub mod clients;
pub mod handshakes;
pub mod roles;

use std::io;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use crate::codec::framing::Event;
use crate::codec::framing::{Found, Framer, ASCII_CHARACTER_TIMEOUT_US};
use crate::codec::Mode;
use crate::transport::tls::{RoleClaim, Tls, TlsServer};
use crate::transport::Transport;
use handshakes::Handshakes;
use roles::{Role, Roles};

/// Modbus/TCP Security for a server: its TLS end, what each client role may do, and the
/// handshakes under way.
#[derive(Clone, Debug)]
pub struct Security {
    /// The certificate, key and client CAs.
    pub tls: TlsServer,
    /// The roles given; without any, every client may do anything.
    pub roles: Roles,
    handshakes: Arc<Handshakes>,
}

/// A client let in over TLS.
pub struct Admitted {
    /// Its connection, handshake done.
    pub stream: Tls,
    /// The role it has: the one its certificate claims, or the default one.
    pub role: Option<String>,
    /// What it may do, where roles are checked.
    pub rights: Option<Role>,
}

impl Security {
    /// The handshakes under way, for the room-making of the listener.
    pub fn handshakes(&self) -> Arc<Handshakes> {
        Arc::clone(&self.handshakes)
    }

    /// A server's TLS end with its roles.
    pub fn new(tls: TlsServer, roles: Roles) -> Security {
        Security {
            tls,
            roles,
            handshakes: Arc::default(),
        }
    }

    /// Makes the handshake with a client just accepted and finds its role; a client
    /// without a certificate signed by the CAs, or without a role the roles allow, is
    /// refused (`PermissionDenied`, saying why). Handshakes under way are bounded
    /// ([`handshakes`]): one cut short to make room is refused, saying so.
    pub fn admit(&self, stream: Arc<std::net::TcpStream>, peer: &str) -> io::Result<Admitted> {
        let ticket = self.handshakes.begin(&stream);
        let accepted = self
            .tls
            .accept(stream, ticket.deadline, &ticket.progress.heard)
            .map_err(|error| {
                if ticket.progress.evicted.load(Ordering::Relaxed) {
                    io::Error::new(
                        io::ErrorKind::PermissionDenied,
                        format!(
                            "{peer} refused: its TLS handshake was cut short to make room for others \
                             ({} may be under way at once, {} from one address)",
                            handshakes::MAX_PENDING,
                            handshakes::MAX_PENDING_PER_ADDRESS
                        ),
                    )
                } else {
                    error
                }
            })?;
        drop(ticket);
        let refused = |why: String| {
            io::Error::new(
                io::ErrorKind::PermissionDenied,
                format!("{peer} ({}) refused: {why}", accepted.subject),
            )
        };
        let claimed = match &accepted.role {
            RoleClaim::Named(role) => Some(role.clone()),
            RoleClaim::Absent => None,
            RoleClaim::Unreadable => {
                return Err(refused(
                    "its role extension is no UTF8String of printable characters".into(),
                ))
            }
        };
        let rights = self
            .roles
            .for_client(claimed.as_deref())
            .map_err(refused)?
            .cloned();
        Ok(Admitted {
            role: rights.as_ref().map(|role| role.name.clone()).or(claimed),
            rights,
            stream: accepted.stream,
        })
    }
}

/// RTU over TCP has no line to time; a gateway passes each frame whole, so the pause that
/// ends a frame is taken to be that of a line at 19200 baud (11 bits a character).
const RTU_OVER_TCP_CHARACTER: Duration = Duration::from_micros(573);
const RTU_OVER_TCP_SILENCE: Duration = Duration::from_micros(1750);

/// How a stream reaches the server.
pub enum Link {
    /// A serial line, or RTU/ASCII through a gateway: silence matters.
    Serial {
        /// One character's time on the line.
        character: Duration,
        /// The silence that ends a frame.
        silence: Duration,
    },
    /// A TCP client, dropped after `idle` without a byte; `activity` is when it last
    /// sent one, in milliseconds.
    Tcp {
        /// How long a silent client is kept.
        idle: Duration,
        /// When the client last sent a byte, in milliseconds since the Unix epoch.
        activity: Arc<AtomicU64>,
    },
}

/// Hands `on_frame` every frame that arrives over `transport` until it fails or closes,
/// or (a TCP client) stays silent too long, and sends what `on_frame` returns. On a serial
/// line noise and other slaves' traffic are passed over and silence ends a frame; over TCP
/// the MBAP length frames, and what is not Modbus TCP ends the connection
/// (`InvalidData`).
pub fn receive_frames(
    transport: &mut dyn Transport,
    mode: Mode,
    link: &Link,
    peer: &str,
    mut on_frame: impl FnMut(&Found) -> Option<Vec<u8>>,
) -> io::Result<()> {
    let (character, silence) = match link {
        Link::Serial { character, silence } => (*character, *silence),
        Link::Tcp { .. } if mode != Mode::Tcp => (RTU_OVER_TCP_CHARACTER, RTU_OVER_TCP_SILENCE),
        Link::Tcp { .. } => (Duration::ZERO, Duration::ZERO),
    };
    // Modbus TCP is framed by the MBAP length alone; RTU and ASCII by their bytes and
    // the pauses between them, over TCP too.
    let timed = mode != Mode::Tcp;
    let mut framer = Framer::new(
        mode,
        character.as_secs_f64() * 1e6,
        silence.as_micros() as u64,
    );
    // What ends a frame on this line: 3.5 characters in RTU, a second in ASCII.
    let frame_end = match mode {
        Mode::Ascii => Duration::from_micros(ASCII_CHARACTER_TIMEOUT_US),
        _ => silence + character,
    };
    let started = Instant::now();
    let mut chunk = Vec::with_capacity(512);
    let mut events = Vec::new();
    // Something waits for the silence after the last byte to be decided.
    let mut undecided = false;
    loop {
        for event in events.drain(..) {
            match event {
                Event::Frame(found) => {
                    if let Some(answer) = on_frame(&found) {
                        transport.send(&answer)?;
                        framer.answered();
                    }
                }
                Event::Noise(noise) if mode == Mode::Tcp => {
                    return Err(io::Error::new(
                        io::ErrorKind::InvalidData,
                        format!(
                            "{peer} sent what is not Modbus TCP ({}): connection closed",
                            crate::codec::hex::spaced_hex(&noise.kept[..noise.kept.len().min(12)])
                        ),
                    ));
                }
                // Noise on a serial line: the next frame may stand right after it.
                Event::Noise(_) => {}
            }
        }
        let deadline = match link {
            _ if undecided => Instant::now() + frame_end,
            Link::Serial { .. } => Instant::now() + Duration::from_secs(3600),
            Link::Tcp { idle, .. } => Instant::now() + *idle,
        };
        chunk.clear();
        let received = transport.receive(&mut chunk, deadline)?;
        let now = started.elapsed().as_micros() as u64;
        match (received, link) {
            (0, _) if undecided => {
                framer.idle(now, &mut events);
                undecided = false;
            }
            (0, Link::Serial { .. }) => {}
            (0, Link::Tcp { idle, .. }) => {
                return Err(io::Error::new(
                    io::ErrorKind::TimedOut,
                    format!(
                        "{peer} sent nothing for {} s: connection closed",
                        idle.as_secs()
                    ),
                ))
            }
            (_, link) => {
                if let Link::Tcp { activity, .. } = link {
                    activity.store(clients::now_ms(), Ordering::Relaxed);
                }
                if timed {
                    framer.push_at(&chunk, now, &mut events);
                    undecided = true;
                } else {
                    framer.push(&chunk, &mut events);
                }
            }
        }
    }
}
