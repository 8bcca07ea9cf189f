//! `mbtool serve`: a slave behind a transport. Each request goes through the codec, the
//! slave's data model and the faults it was told to make; every request is logged.

use std::io;
use std::net::TcpListener;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use crate::codec::adu::{opaque_request, wrap};
use crate::codec::framing::Found;
use crate::codec::{Direction, ExceptionCode, Frame, FrameError, Mode, Pdu, Request};
use crate::listener::clients::{accept_clients, lock, Accepted, ErrorSink};
use crate::listener::roles::Role;
use crate::listener::{receive_frames, Link, Security};
use crate::slave::faults::FaultInjection;
use crate::slave::Slave;
use crate::transport::tcp::Tcp;
use crate::transport::udp::next_datagram;
use crate::transport::Transport;

/// Who sent a request, as the server knows them.
#[derive(Clone, Copy, Debug)]
pub struct Client<'a> {
    /// The TCP client's address, or the serial port.
    pub peer: &'a str,
    /// The role its certificate claims (over TLS).
    pub role: Option<&'a str>,
    /// What it may do, where roles are checked.
    pub rights: Option<&'a Role>,
}

impl<'a> Client<'a> {
    /// A client known by where it is alone: a serial line, plain TCP, the sim port.
    pub fn at(peer: &'a str) -> Client<'a> {
        Client {
            peer,
            role: None,
            rights: None,
        }
    }
}

/// What became of one request.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// Answered with this PDU (data or an exception).
    Answered(Pdu),
    /// Answered, but the bytes were corrupted on purpose.
    Corrupted(Pdu),
    /// Left unanswered on purpose (`--drop`).
    Dropped,
    /// A broadcast: carried out, not answered.
    Broadcast,
}

/// One logged request.
pub struct LogEntry<'a> {
    /// Time since the server started.
    pub elapsed: Duration,
    /// Who sent the request: the TCP client's address, or the serial port.
    pub peer: &'a str,
    /// The role its certificate claims, over TLS.
    pub role: Option<&'a str>,
    /// The slave id the request was addressed to.
    pub slave: u8,
    /// The request.
    pub request: &'a Request,
    /// What became of it.
    pub outcome: &'a Outcome,
    /// Why the client's role may not make the request, when it was refused for that.
    pub refusal: Option<&'a str>,
}

/// Told of every request the server handles, from any thread.
pub type Logger = Arc<dyn Fn(&LogEntry) + Send + Sync>;

/// A slave behind a transport: takes requests, answers them, makes the faults asked for.
pub struct Server {
    slave: Mutex<Slave>,
    faults: FaultInjection,
    mode: Mode,
    seed: u64,
    started: Instant,
    logger: Option<Logger>,
    security: Option<Security>,
    plain_role: Option<Role>,
}

impl Server {
    /// A server for `slave`, making `faults` with random draws from `seed`, framing as `mode` does, telling `logger` of each request.
    pub fn new(
        slave: Slave,
        faults: FaultInjection,
        mode: Mode,
        seed: u64,
        logger: Option<Logger>,
    ) -> Self {
        Self {
            slave: Mutex::new(slave),
            faults,
            mode,
            seed,
            started: Instant::now(),
            logger,
            security: None,
            plain_role: None,
        }
    }

    /// The server with TCP clients accepted over TLS only, their roles checked.
    pub fn secured(mut self, security: Security) -> Self {
        self.security = Some(security);
        self
    }

    /// The server with every client of a plain listener (or of a serial line) holding
    /// `role`: where roles are checked, one that none may escape.
    pub fn with_plain_role(mut self, role: Role) -> Self {
        self.plain_role = Some(role);
        self
    }

    /// Who a client that comes without a certificate is: where it is, and the plain
    /// role, if one was given.
    pub fn plain_client<'a>(&'a self, peer: &'a str) -> Client<'a> {
        Client {
            peer,
            role: self.plain_role.as_ref().map(|role| role.name.as_str()),
            rights: self.plain_role.as_ref(),
        }
    }

    /// The answer to a frame found on the wire, as bytes to send (`None`: stay silent):
    /// the one answer path of `serve` and of the sim port.
    pub fn answer(
        &self,
        found: &Found,
        client: Client,
        rng: &mut fastrand::Rng,
    ) -> Option<Vec<u8>> {
        // Over TCP everything a server receives is a request, however it reads.
        let answer_on_the_line =
            self.mode != Mode::Tcp && found.direction == Some(Direction::Response);
        lock(&self.slave).saw_frame(found.broken.is_none());
        if found.broken.is_some() || answer_on_the_line {
            return None;
        }
        self.answer_request(&found.bytes, client, rng)
    }

    /// The answer to bytes that are one whole frame, as a transport that delimits frames
    /// itself (the sim port) hands them over: a frame whose PDU is malformed still gets
    /// its exception.
    pub fn answer_frame(
        &self,
        bytes: &[u8],
        peer: &str,
        rng: &mut fastrand::Rng,
    ) -> Option<Vec<u8>> {
        lock(&self.slave).saw_frame(true);
        self.answer_request(bytes, Client::at(peer), rng)
    }

    /// The answer to the bytes of a whole frame, counted already as seen on the line.
    fn answer_request(
        &self,
        bytes: &[u8],
        client: Client,
        rng: &mut fastrand::Rng,
    ) -> Option<Vec<u8>> {
        let frame = request_in(self.mode, bytes)?;
        let Pdu::Request(request) = &frame.pdu else {
            return None;
        };
        self.respond(&frame, request, client, rng)
    }

    /// The answer to one request frame, as bytes to send (`None`: stay silent).
    fn respond(
        &self,
        frame: &Frame,
        request: &Request,
        client: Client,
        rng: &mut fastrand::Rng,
    ) -> Option<Vec<u8>> {
        let mut slave_id = frame.slave;
        let refusal = client.rights.and_then(|rights| rights.refusal(request));
        let outcome = {
            let mut slave = lock(&self.slave);
            // Over TCP, unit ids 0 and 255 mean "the device at this address".
            if self.mode == Mode::Tcp && matches!(slave_id, 0 | 255) {
                slave_id = slave.first_id();
            }
            let known = slave_id == 0 || slave.answers_for(slave_id);
            // On a serial line another slave's request is none of ours; over TCP the
            // server stands where a gateway would, and says the target did not answer.
            if !known && self.mode != Mode::Tcp {
                return None;
            }
            let exception = |code| Some(Pdu::refusal(request, code));
            // A request the client's role does not allow is an illegal function to it.
            let answer = match self.faults.exception_for(request) {
                _ if !known => exception(ExceptionCode::GATEWAY_TARGET_FAILED),
                _ if refusal.is_some() => exception(ExceptionCode::ILLEGAL_FUNCTION),
                Some(code) if slave_id != 0 => exception(code),
                _ => slave.handle(slave_id, request),
            };
            match answer {
                None => Outcome::Broadcast,
                Some(_) if rng.f64() < self.faults.drop => {
                    slave.left_unanswered(slave_id);
                    Outcome::Dropped
                }
                Some(pdu) if rng.f64() < self.faults.corrupt => Outcome::Corrupted(pdu),
                Some(pdu) => Outcome::Answered(pdu),
            }
        };
        if let Some(logger) = &self.logger {
            logger(&LogEntry {
                elapsed: self.started.elapsed(),
                peer: client.peer,
                role: client.role,
                slave: frame.slave,
                request,
                outcome: &outcome,
                refusal: refusal.as_deref(),
            });
        }
        let (pdu, corrupt) = match outcome {
            Outcome::Answered(pdu) => (pdu, false),
            Outcome::Corrupted(pdu) => (pdu, true),
            Outcome::Dropped | Outcome::Broadcast => return None,
        };
        let mut bytes = Vec::new();
        if self.faults.garbage {
            bytes.extend(FaultInjection::noise(rng));
        }
        let start = bytes.len();
        let mut pdu_bytes = Vec::new();
        pdu.encode(&mut pdu_bytes).ok()?;
        wrap(
            self.mode,
            frame.slave,
            frame.transaction,
            &pdu_bytes,
            &mut bytes,
        );
        if corrupt {
            FaultInjection::corrupt(&mut bytes[start..], self.mode == Mode::Tcp, rng);
        }
        if !self.faults.delay.is_zero() {
            std::thread::sleep(self.faults.delay);
        }
        Some(bytes)
    }

    /// Answers the requests that come over `transport` until it fails or closes, or (a
    /// TCP client) stays silent too long, framed as [`receive_frames`] frames them.
    pub fn serve_stream(
        &self,
        transport: &mut dyn Transport,
        client: Client,
        link: &Link,
        rng: &mut fastrand::Rng,
    ) -> io::Result<()> {
        receive_frames(transport, self.mode, link, client.peer, |found| {
            self.answer(found, client, rng)
        })
    }

    /// Answers the datagrams that come to `socket`, each a whole frame, each to where it
    /// came from; a datagram that holds no request is passed over.
    pub fn serve_udp(&self, socket: &std::net::UdpSocket) -> io::Result<()> {
        let mut rng = fastrand::Rng::with_seed(self.seed);
        let mut datagram = [0u8; 2048];
        loop {
            let (len, from) = next_datagram(socket, &mut datagram)?;
            let peer = from.to_string();
            if let Some(answer) = self.answer_frame(&datagram[..len], &peer, &mut rng) {
                // A client that cannot be reached asks again, or gives up: no matter here.
                let _ = socket.send_to(&answer, from);
            }
        }
    }

    /// Accepts TCP clients, each served on its own thread so that none can hold up
    /// another; over TLS, each after its handshake and with the rights of its role.
    pub fn serve_tcp(
        self: Arc<Self>,
        listener: TcpListener,
        on_error: ErrorSink,
    ) -> io::Result<()> {
        let handshakes = self.security.as_ref().map(Security::handshakes);
        accept_clients(
            listener,
            handshakes,
            on_error,
            Arc::new(move |client: Accepted| {
                let mut rng =
                    fastrand::Rng::with_seed(self.seed.wrapping_add(client.number as u64));
                let Some(security) = &self.security else {
                    let mut transport = Tcp::from_shared(client.stream, self.mode != Mode::Tcp)?;
                    let who = self.plain_client(&client.peer);
                    return self.serve_stream(&mut transport, who, &client.link, &mut rng);
                };
                let mut admitted = security.admit(client.stream, &client.peer)?;
                let who = Client {
                    peer: &client.peer,
                    role: admitted.role.as_deref(),
                    rights: admitted.rights.as_ref(),
                };
                self.serve_stream(&mut admitted.stream, who, &client.link, &mut rng)
            }),
        )
    }
}

/// The request a frame found on the line carries, if it is one. A frame whose checksum
/// holds but whose PDU breaks its function's layout is read as an opaque request, to be
/// answered with an exception as a real device does.
fn request_in(mode: Mode, bytes: &[u8]) -> Option<Frame> {
    let tcp = mode == Mode::Tcp;
    match Frame::decode(mode, bytes, Direction::Request) {
        Ok(frame) if tcp && !matches!(frame.pdu, Pdu::Request(_)) => {
            opaque_request(mode, bytes, true).ok()
        }
        Ok(frame) => Some(frame),
        Err(FrameError::Pdu(_)) => opaque_request(mode, bytes, tcp).ok(),
        Err(_) => None,
    }
}
