//! The master side of a transaction: send a request, wait for the answer that belongs to
//! it, check it, and retry what is worth retrying.

use std::time::{Duration, Instant};

use thiserror::Error;

use crate::codec::answer::check;
use crate::codec::stream::{Status, StreamDecoder};
use crate::codec::{Direction, Exception, Frame, Mode, Pdu, Request, Response};
use crate::duration::show;
use crate::transport::Transport;

/// How the master behaves; the connection options fill it in.
#[derive(Clone, Copy, Debug)]
pub struct MasterOptions {
    pub mode: Mode,
    /// For the whole answer, from the end of sending.
    pub timeout: Duration,
    /// After a timeout or a bad answer; never after an exception.
    pub retries: u32,
    /// Silence kept between transactions on a serial line, counted from the last byte
    /// received.
    pub frame_gap: Duration,
    /// How long a broadcast waits for the slaves to act before the next request.
    pub turnaround: Duration,
}

/// What came back.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Reply {
    Response(Response),
    Exception(Exception),
    /// A broadcast: no answer is given.
    Broadcast,
}

#[derive(Debug, Error)]
pub enum MasterError {
    #[error("no answer from slave {slave} within {}", show(*.timeout))]
    Timeout { slave: u8, timeout: Duration },
    #[error("bad answer from slave {slave}: {reason}")]
    BadFrame { slave: u8, reason: String },
    #[error("request cannot be encoded: {0}")]
    Encode(#[from] crate::codec::PduError),
    #[error(transparent)]
    Io(#[from] std::io::Error),
}

/// What the master saw, for `-v`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Traffic {
    Sent,
    Received,
}

pub type Tracer = Box<dyn FnMut(Traffic, &[u8]) + Send>;

/// After a frame that is wrong, wait this long for more bytes (the right answer after
/// noise, say) before giving up: longer than a USB adapter's 16 ms latency timer.
const SETTLE: Duration = Duration::from_millis(50);

pub struct Master {
    transport: Box<dyn Transport>,
    options: MasterOptions,
    last_traffic: Option<Instant>,
    transaction: u16,
    tracer: Option<Tracer>,
    buffer: Vec<u8>,
    /// The last transaction ended on a whole answer, so nothing stale can be waiting
    /// on a TCP connection.
    in_step: bool,
}

impl Master {
    pub fn new(transport: Box<dyn Transport>, options: MasterOptions) -> Self {
        Self {
            transport,
            options,
            last_traffic: None,
            transaction: 0,
            tracer: None,
            buffer: Vec::with_capacity(512),
            in_step: false,
        }
    }

    /// Shows every frame sent and received.
    pub fn trace(&mut self, tracer: Tracer) {
        self.tracer = Some(tracer);
    }

    fn note(&mut self, traffic: Traffic, bytes: &[u8]) {
        if let Some(tracer) = self.tracer.as_mut() {
            tracer(traffic, bytes);
        }
    }

    /// One request, with its retries.
    pub fn transact(&mut self, slave: u8, request: &Request) -> Result<Reply, MasterError> {
        let mut retries_left = self.options.retries;
        loop {
            match self.attempt(slave, request) {
                Err(MasterError::Timeout { .. } | MasterError::BadFrame { .. })
                    if retries_left > 0 =>
                {
                    retries_left -= 1;
                }
                result => return result,
            }
        }
    }

    fn is_broadcast(&self, slave: u8) -> bool {
        slave == 0 && self.options.mode != Mode::Tcp
    }

    fn attempt(&mut self, slave: u8, request: &Request) -> Result<Reply, MasterError> {
        if self.transport.is_serial_line() {
            if let Some(last) = self.last_traffic {
                let quiet_until = last + self.options.frame_gap;
                if let Some(wait) = quiet_until.checked_duration_since(Instant::now()) {
                    std::thread::sleep(wait);
                }
            }
        }
        // On a serial line noise can arrive at any time; over TCP a late answer can only
        // follow a transaction that failed (and would be told by its transaction id).
        if self.transport.is_serial_line() || !self.in_step {
            self.transport.discard_input()?;
        }
        self.in_step = false;
        self.transaction = self.transaction.wrapping_add(1);
        let frame = Frame {
            mode: self.options.mode,
            slave,
            transaction: self.transaction,
            pdu: Pdu::Request(request.clone()),
        };
        let bytes = frame.encode()?;
        self.note(Traffic::Sent, &bytes);
        self.transport.send(&bytes)?;
        self.last_traffic = Some(Instant::now());
        if self.is_broadcast(slave) {
            std::thread::sleep(self.options.turnaround);
            return Ok(Reply::Broadcast);
        }
        match self.await_answer(slave, request)? {
            Pdu::Exception(exception) => Ok(Reply::Exception(exception)),
            Pdu::Response(response) => Ok(Reply::Response(response)),
            Pdu::Request(_) => Err(MasterError::BadFrame {
                slave,
                reason: "the answer reads as a request".into(),
            }),
        }
    }

    /// Whether a whole, valid frame is the answer to this request.
    fn belongs(&self, frame: &Frame, slave: u8, request: &Request) -> Result<(), Option<String>> {
        if self.options.mode == Mode::Tcp && frame.transaction != self.transaction {
            // A late answer to an earlier request: not ours, and no fault of this one.
            return Err(None);
        }
        if frame.slave != slave {
            return Err(Some(format!("the answer came from slave {}", frame.slave)));
        }
        check(request, &frame.pdu).map_err(|mismatch| Some(mismatch.to_string()))
    }

    fn await_answer(&mut self, slave: u8, request: &Request) -> Result<Pdu, MasterError> {
        let decoder = StreamDecoder::new(self.options.mode, Direction::Response);
        let deadline = Instant::now() + self.options.timeout;
        let mut buffer = std::mem::take(&mut self.buffer);
        buffer.clear();
        let mut problem: Option<String> = None;
        let outcome = loop {
            // The answer may stand after noise: look for it at every offset.
            let mut offset = 0;
            let mut found = None;
            while offset < buffer.len() {
                match decoder.decode(&buffer[offset..]) {
                    Status::Complete { frame, len } => match self.belongs(&frame, slave, request) {
                        Ok(()) => {
                            found = Some(frame.pdu);
                            break;
                        }
                        Err(reason) => {
                            problem = problem.or(reason);
                            offset += len;
                        }
                    },
                    Status::Invalid { error, .. } => {
                        // What is wrong with the answer is said by its first bytes; later
                        // offsets are only attempts to find it behind noise.
                        if offset == 0 {
                            problem = problem.or(Some(error.to_string()));
                        }
                        if self.options.mode == Mode::Tcp {
                            // A TCP stream that lost its framing cannot be trusted further.
                            break;
                        }
                        offset += 1;
                    }
                    Status::Partial => offset += 1,
                }
            }
            if let Some(pdu) = found {
                break Ok(pdu);
            }
            if problem.is_some() && self.options.mode == Mode::Tcp {
                break Err(None);
            }
            let wait_until = match problem {
                Some(_) => deadline.min(Instant::now() + SETTLE),
                None => deadline,
            };
            match self.transport.receive(&mut buffer, wait_until) {
                Ok(0) => break Err(None),
                Ok(_) => self.last_traffic = Some(Instant::now()),
                Err(error) => break Err(Some(error)),
            }
        };
        if !buffer.is_empty() {
            self.note(Traffic::Received, &buffer);
        }
        let received = buffer.len();
        let shown = crate::report::spaced_hex(&buffer[..received.min(32)]);
        self.buffer = buffer;
        match outcome {
            Ok(pdu) => {
                self.in_step = true;
                Ok(pdu)
            }
            Err(Some(io_error)) => Err(MasterError::Io(io_error)),
            Err(None) => Err(match problem {
                Some(reason) => MasterError::BadFrame { slave, reason },
                None if received > 0 => MasterError::BadFrame {
                    slave,
                    reason: format!(
                        "incomplete answer: {received} bytes ({shown}{}) and then silence",
                        if received > 32 { " ..." } else { "" }
                    ),
                },
                None => MasterError::Timeout {
                    slave,
                    timeout: self.options.timeout,
                },
            }),
        }
    }
}
