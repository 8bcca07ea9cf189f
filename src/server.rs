//! `mbtool serve`: a slave behind a transport. Each request goes through the codec, the
//! slave's data model and the faults it was told to make; every request is logged.

use std::io;
use std::net::TcpListener;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use crate::codec::adu::{opaque_request, wrap};
use crate::codec::stream::{Status, StreamDecoder};
use crate::codec::{Direction, Exception, ExceptionCode, Frame, FrameError, Mode, Pdu, Request};
use crate::slave::faults::Faults;
use crate::slave::Slave;
use crate::transport::tcp::Tcp;
use crate::transport::Transport;

/// What became of one request.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Outcome {
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
    pub elapsed: Duration,
    pub peer: &'a str,
    pub slave: u8,
    pub request: &'a Request,
    pub outcome: &'a Outcome,
}

pub type Logger = Arc<dyn Fn(&LogEntry) + Send + Sync>;

/// A TCP client that sends nothing for this long is dropped.
pub const CLIENT_IDLE: Duration = Duration::from_secs(60);
/// More clients than this at once are turned away.
pub const MAX_CLIENTS: usize = 64;

pub struct Server {
    slave: Mutex<Slave>,
    faults: Faults,
    mode: Mode,
    seed: u64,
    started: Instant,
    logger: Option<Logger>,
}

impl Server {
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
            let mut slave = match self.slave.lock() {
                Ok(slave) => slave,
                Err(poisoned) => poisoned.into_inner(),
            };
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
            let exception = |code| {
                Some(Pdu::Exception(Exception {
                    function: request.function(),
                    code,
                }))
            };
            let answer = match self.faults.exception_for(request) {
                _ if !known => exception(ExceptionCode::GATEWAY_TARGET_FAILED),
                Some(code) if slave_id != 0 => exception(code),
                _ => slave.handle(slave_id, request),
            };
            match answer {
                None => Outcome::Broadcast,
                Some(_) if rng.f64() < self.faults.drop => Outcome::Dropped,
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

    /// Answers the requests that come over `transport` until it fails, closes, or (`idle`)
    /// stays silent too long. Over TCP a frame that cannot be read ends the connection; on
    /// a serial line the decoder moves on a byte and looks again.
    pub fn serve_stream(
        &self,
        transport: &mut dyn Transport,
        peer: &str,
        idle: Option<Duration>,
        rng: &mut fastrand::Rng,
    ) -> io::Result<()> {
        let decoder = StreamDecoder::new(self.mode, Direction::Request);
        let mut buffer = Vec::with_capacity(1024);
        loop {
            let mut offset = 0;
            while offset < buffer.len() {
                match decoder.decode(&buffer[offset..]) {
                    Status::Complete { frame, len } => {
                        offset += len;
                        if let Pdu::Request(request) = &frame.pdu {
                            if let Some(answer) = self.respond(&frame, request, peer, rng) {
                                transport.send(&answer)?;
                            }
                        }
                    }
                    Status::Invalid {
                        error: FrameError::Pdu(_),
                        len,
                    } => {
                        // A sound frame with a bad PDU: answered with an exception.
                        let bytes = &buffer[offset..offset + len];
                        offset += len;
                        if let Ok(frame) = opaque_request(self.mode, bytes) {
                            if let Pdu::Request(request) = &frame.pdu {
                                if let Some(answer) = self.respond(&frame, request, peer, rng) {
                                    transport.send(&answer)?;
                                }
                            }
                        }
                    }
                    Status::Invalid { error, len } => {
                        if self.mode == Mode::Tcp {
                            return Err(io::Error::new(
                                io::ErrorKind::InvalidData,
                                format!("{peer} sent what is not Modbus TCP ({error}): connection closed"),
                            ));
                        }
                        // Noise or a broken frame: resynchronise.
                        offset += if self.mode == Mode::Ascii {
                            len.max(1)
                        } else {
                            1
                        };
                    }
                    Status::Partial => break,
                }
            }
            buffer.drain(..offset.min(buffer.len()));
            let wait = idle.unwrap_or(Duration::from_secs(3600));
            // A partial frame followed by silence was broken off: forget it.
            let deadline = if buffer.is_empty() {
                Instant::now() + wait
            } else {
                Instant::now() + Duration::from_millis(100).min(wait)
            };
            match transport.receive(&mut buffer, deadline)? {
                0 if !buffer.is_empty() => buffer.clear(),
                0 if idle.is_some() => {
                    return Err(io::Error::new(
                        io::ErrorKind::TimedOut,
                        format!(
                            "{peer} sent nothing for {} s: connection closed",
                            wait.as_secs()
                        ),
                    ))
                }
                _ => {}
            }
        }
    }

    /// Accepts TCP clients, each served on its own thread so that none can hold up another.
    pub fn serve_tcp(
        self: Arc<Self>,
        listener: TcpListener,
        on_error: Arc<dyn Fn(io::Error) + Send + Sync>,
    ) -> io::Result<()> {
        let clients = Arc::new(AtomicUsize::new(0));
        for (number, stream) in listener.incoming().enumerate() {
            let stream = match stream {
                Ok(stream) => stream,
                Err(error) => {
                    on_error(error);
                    continue;
                }
            };
            if clients.load(Ordering::SeqCst) >= MAX_CLIENTS {
                on_error(io::Error::other(format!(
                    "more than {MAX_CLIENTS} clients: one turned away"
                )));
                continue;
            }
            let peer = stream
                .peer_addr()
                .map_or_else(|_| "?".to_string(), |a| a.to_string());
            let server = Arc::clone(&self);
            let (clients, on_error) = (Arc::clone(&clients), Arc::clone(&on_error));
            clients.fetch_add(1, Ordering::SeqCst);
            std::thread::spawn(move || {
                let mut rng = fastrand::Rng::with_seed(server.seed.wrapping_add(number as u64));
                let served =
                    Tcp::from_stream(stream, server.mode != Mode::Tcp).and_then(|mut transport| {
                        server.serve_stream(&mut transport, &peer, Some(CLIENT_IDLE), &mut rng)
                    });
                if let Err(error) = served {
                    if error.kind() != io::ErrorKind::ConnectionAborted {
                        on_error(error);
                    }
                }
                clients.fetch_sub(1, Ordering::SeqCst);
            });
        }
        Ok(())
    }
}
