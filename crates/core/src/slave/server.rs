//! `mbtool serve`: a slave behind a transport. Each request goes through the codec, the
//! slave's data model and the faults it was told to make; every request is logged.

use std::io;
use std::net::{Shutdown, TcpListener, TcpStream};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant, SystemTime, UNIX_EPOCH};

use crate::codec::adu::{opaque_request, wrap};
use crate::codec::framing::{Event, Found, Framer, ASCII_CHARACTER_TIMEOUT_US};
use crate::codec::{Direction, ExceptionCode, Frame, FrameError, Mode, Pdu, Request};
use crate::slave::faults::Faults;
use crate::slave::Slave;
use crate::transport::tcp::Tcp;
use crate::transport::Transport;

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
    /// The slave id the request was addressed to.
    pub slave: u8,
    /// The request.
    pub request: &'a Request,
    /// What became of it.
    pub outcome: &'a Outcome,
}

/// Told of every request the server handles, from any thread.
pub type Logger = Arc<dyn Fn(&LogEntry) + Send + Sync>;

/// RTU over TCP has no line to time; a gateway passes each frame whole, so the pause that
/// ends a frame is taken to be that of a line at 19200 baud (11 bits a character).
const RTU_OVER_TCP_CHARACTER: Duration = Duration::from_micros(573);
const RTU_OVER_TCP_SILENCE: Duration = Duration::from_micros(1750);

/// A TCP client that sends nothing for this long is dropped.
pub const CLIENT_IDLE: Duration = Duration::from_secs(60);
/// Past this many clients, a new one takes the place of the one silent the longest, if
/// that one is idle; a busy client is never closed, so a busy server serves any number.
pub const MAX_CLIENTS: usize = 64;
/// How often running out of file descriptors is told while it lasts.
const RETELL_AFTER: Duration = Duration::from_secs(10);
/// A client silent this long is idle: it may make room for a new one.
pub const IDLE_FOR_ROOM: Duration = Duration::from_secs(10);
/// A client that has not taken its answers within this time is dropped: it holds a
/// thread and the answers that wait for it.
pub const WRITE_DEADLINE: Duration = Duration::from_secs(5);

/// A slave behind a transport: takes requests, answers them, makes the faults asked for.
pub struct Server {
    slave: Mutex<Slave>,
    faults: Faults,
    mode: Mode,
    seed: u64,
    started: Instant,
    logger: Option<Logger>,
}

impl Server {
    /// A server for `slave`, making `faults` with random draws from `seed`, framing as `mode` does, telling `logger` of each request.
    pub fn new(
        slave: Slave,
        faults: Faults,
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
        }
    }

    /// The answer to a frame found on the wire, as bytes to send (`None`: stay silent):
    /// the one answer path of `serve` and of the sim port.
    pub fn answer(&self, found: &Found, peer: &str, rng: &mut fastrand::Rng) -> Option<Vec<u8>> {
        // Over TCP everything a server receives is a request, however it reads.
        let answer_on_the_line =
            self.mode != Mode::Tcp && found.direction == Some(Direction::Response);
        lock(&self.slave).saw_frame(found.broken.is_none());
        if found.broken.is_some() || answer_on_the_line {
            return None;
        }
        self.answer_request(&found.bytes, peer, rng)
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
        self.answer_request(bytes, peer, rng)
    }

    /// The answer to the bytes of a whole frame, counted already as seen on the line.
    fn answer_request(&self, bytes: &[u8], peer: &str, rng: &mut fastrand::Rng) -> Option<Vec<u8>> {
        let frame = request_in(self.mode, bytes)?;
        let Pdu::Request(request) = &frame.pdu else {
            return None;
        };
        self.respond(&frame, request, peer, rng)
    }

    /// The answer to one request frame, as bytes to send (`None`: stay silent).
    fn respond(
        &self,
        frame: &Frame,
        request: &Request,
        peer: &str,
        rng: &mut fastrand::Rng,
    ) -> Option<Vec<u8>> {
        let mut slave_id = frame.slave;
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
            let exception = |code| Some(super::exception(request, code));
            let answer = match self.faults.exception_for(request) {
                _ if !known => exception(ExceptionCode::GATEWAY_TARGET_FAILED),
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
                peer,
                slave: frame.slave,
                request,
                outcome: &outcome,
            });
        }
        let (pdu, corrupt) = match outcome {
            Outcome::Answered(pdu) => (pdu, false),
            Outcome::Corrupted(pdu) => (pdu, true),
            Outcome::Dropped | Outcome::Broadcast => return None,
        };
        let mut bytes = Vec::new();
        if self.faults.garbage {
            bytes.extend(Faults::noise(rng));
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
            Faults::corrupt(&mut bytes[start..], self.mode == Mode::Tcp, rng);
        }
        if !self.faults.delay.is_zero() {
            std::thread::sleep(self.faults.delay);
        }
        Some(bytes)
    }

    /// Answers the requests that come over `transport` until it fails or closes, or (a
    /// TCP client) stays silent too long. Bytes are framed as every receiver of mbtool
    /// frames them: on a serial line noise and other slaves' traffic are passed over and
    /// silence ends a frame; over TCP the MBAP length frames, and what is not Modbus TCP
    /// ends the connection.
    pub fn serve_stream(
        &self,
        transport: &mut dyn Transport,
        peer: &str,
        link: &Link,
        rng: &mut fastrand::Rng,
    ) -> io::Result<()> {
        let (character, silence) = match link {
            Link::Serial { character, silence } => (*character, *silence),
            Link::Tcp { .. } if self.mode != Mode::Tcp => {
                (RTU_OVER_TCP_CHARACTER, RTU_OVER_TCP_SILENCE)
            }
            Link::Tcp { .. } => (Duration::ZERO, Duration::ZERO),
        };
        // Modbus TCP is framed by the MBAP length alone; RTU and ASCII by their bytes and
        // the pauses between them, over TCP too.
        let timed = self.mode != Mode::Tcp;
        let mut framer = Framer::new(
            self.mode,
            character.as_secs_f64() * 1e6,
            silence.as_micros() as u64,
        );
        // What ends a frame on this line: 3.5 characters in RTU, a second in ASCII.
        let frame_end = match self.mode {
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
                        if let Some(answer) = self.answer(&found, peer, rng) {
                            transport.send(&answer)?;
                            framer.answered();
                        }
                    }
                    Event::Noise(noise) if self.mode == Mode::Tcp => {
                        return Err(io::Error::new(
                            io::ErrorKind::InvalidData,
                            format!(
                                "{peer} sent what is not Modbus TCP ({}): connection closed",
                                crate::describe::spaced_hex(
                                    &noise.kept[..noise.kept.len().min(12)]
                                )
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
                        activity.store(now_ms(), Ordering::Relaxed);
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

    /// Accepts TCP clients, each served on its own thread so that none can hold up
    /// another. When all places are taken, the client silent the longest gives way.
    pub fn serve_tcp(
        self: Arc<Self>,
        listener: TcpListener,
        on_error: Arc<dyn Fn(io::Error) + Send + Sync>,
    ) -> io::Result<()> {
        let clients: Arc<Mutex<Vec<Client>>> = Arc::new(Mutex::new(Vec::new()));
        // When running out of file descriptors was last told: not at every refused accept.
        let mut told_out_of_descriptors: Option<Instant> = None;
        let mut tell_out_of_descriptors = |connected: usize| {
            if told_out_of_descriptors.is_none_or(|at| at.elapsed() >= RETELL_AFTER) {
                told_out_of_descriptors = Some(Instant::now());
                on_error(out_of_descriptors_error(connected));
            }
        };
        for (number, stream) in listener.incoming().enumerate() {
            let stream = match stream {
                Ok(stream) => stream,
                Err(error) if is_out_of_descriptors(&error) => {
                    let mut clients = lock(&clients);
                    if !close_idlest(&mut clients, &on_error, "no file descriptor was left") {
                        let connected = clients.len();
                        drop(clients);
                        tell_out_of_descriptors(connected);
                        // The waiting client stays in the listen queue; try again soon.
                        std::thread::sleep(Duration::from_millis(20));
                    }
                    continue;
                }
                Err(error) => {
                    on_error(error);
                    continue;
                }
            };
            let peer = stream
                .peer_addr()
                .map_or_else(|_| "?".to_string(), |a| a.to_string());
            let activity = Arc::new(AtomicU64::new(now_ms()));
            let registered = stream.try_clone().map(|handle| Client {
                number,
                handle,
                activity: Arc::clone(&activity),
            });
            match registered {
                Ok(client) => make_room_and_add(&clients, client, &on_error),
                // Without a second handle the client cannot be closed to make room, but it
                // is served all the same.
                Err(error) if is_out_of_descriptors(&error) => {
                    let connected = lock(&clients).len();
                    tell_out_of_descriptors(connected);
                }
                Err(error) => {
                    on_error(error);
                    continue;
                }
            }
            let server = Arc::clone(&self);
            let (clients_left, on_error_there) = (Arc::clone(&clients), Arc::clone(&on_error));
            let spawned = std::thread::Builder::new().spawn(move || {
                let (clients, on_error) = (clients_left, on_error_there);
                let mut rng = fastrand::Rng::with_seed(server.seed.wrapping_add(number as u64));
                let link = Link::Tcp {
                    idle: CLIENT_IDLE,
                    activity,
                };
                // A client that does not read its answers is dropped, not waited for.
                let served = stream
                    .set_write_timeout(Some(WRITE_DEADLINE))
                    .and_then(|()| Tcp::from_stream(stream, server.mode != Mode::Tcp))
                    .and_then(|mut transport| {
                        server.serve_stream(&mut transport, &peer, &link, &mut rng)
                    });
                if let Err(error) = served {
                    let quiet = matches!(
                        error.kind(),
                        io::ErrorKind::ConnectionAborted
                            | io::ErrorKind::ConnectionReset
                            | io::ErrorKind::NotConnected
                    );
                    if !quiet {
                        on_error(match error.kind() {
                            io::ErrorKind::WouldBlock | io::ErrorKind::TimedOut
                                if error.get_ref().is_none() =>
                            {
                                io::Error::other(format!(
                                    "{peer} did not read its answers for {} s: connection closed",
                                    WRITE_DEADLINE.as_secs()
                                ))
                            }
                            _ => error,
                        });
                    }
                }
                lock(&clients).retain(|c| c.number != number);
            });
            if let Err(error) = spawned {
                // No thread for it: the client is closed rather than left unanswered.
                let mut clients = lock(&clients);
                if let Some(index) = clients.iter().position(|c| c.number == number) {
                    let client = clients.swap_remove(index);
                    let _ = client.handle.shutdown(Shutdown::Both);
                }
                on_error(io::Error::other(format!(
                    "no thread for another client ({} connected): {error}",
                    clients.len()
                )));
            }
        }
        Ok(())
    }
}

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

/// A connected TCP client, as the accepting thread sees it.
struct Client {
    number: usize,
    /// Another handle on the client's socket, to close it when it must give way.
    handle: TcpStream,
    activity: Arc<AtomicU64>,
}

fn lock<T>(mutex: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    match mutex.lock() {
        Ok(guard) => guard,
        Err(poisoned) => poisoned.into_inner(),
    }
}

/// Adds a client; past [`MAX_CLIENTS`], the one silent the longest is closed first if it
/// is idle.
fn make_room_and_add(
    clients: &Mutex<Vec<Client>>,
    client: Client,
    on_error: &Arc<dyn Fn(io::Error) + Send + Sync>,
) {
    let mut clients = lock(clients);
    if clients.len() >= MAX_CLIENTS {
        let why = format!("{} clients were connected", clients.len());
        close_idlest(&mut clients, on_error, &why);
    }
    clients.push(client);
}

/// Closes the client silent the longest, if it has been silent for [`IDLE_FOR_ROOM`]; says
/// so with `why`, and whether one was closed.
fn close_idlest(
    clients: &mut Vec<Client>,
    on_error: &Arc<dyn Fn(io::Error) + Send + Sync>,
    why: &str,
) -> bool {
    let now = now_ms();
    let idle_ms = IDLE_FOR_ROOM.as_millis() as u64;
    let idlest = (0..clients.len())
        .min_by_key(|&i| clients[i].activity.load(Ordering::Relaxed))
        .filter(|&i| now.saturating_sub(clients[i].activity.load(Ordering::Relaxed)) >= idle_ms);
    let Some(index) = idlest else {
        return false;
    };
    let idlest = clients.swap_remove(index);
    let _ = idlest.handle.shutdown(Shutdown::Both);
    let silent = now.saturating_sub(idlest.activity.load(Ordering::Relaxed)) / 1000;
    on_error(io::Error::other(format!(
        "{why}: {}, silent for {silent} s, was closed to make room",
        idlest
            .handle
            .peer_addr()
            .map_or_else(|_| "?".to_string(), |a| a.to_string())
    )));
    true
}

/// What the server says when the file descriptors run out with `connected` clients.
fn out_of_descriptors_error(connected: usize) -> io::Error {
    io::Error::other(format!(
        "no file descriptor left for another client ({connected} connected): \
         new clients wait until one leaves; 'ulimit -n' raises the limit"
    ))
}

/// Whether accepting failed because the process or the system has no file descriptor left.
fn is_out_of_descriptors(error: &io::Error) -> bool {
    // EMFILE and ENFILE on Linux and the BSDs alike.
    matches!(error.raw_os_error(), Some(23 | 24))
}

/// Milliseconds since 1970, for telling which client has been silent the longest.
fn now_ms() -> u64 {
    SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_millis() as u64)
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
