//! The master side of a transaction: send a request, wait for the answer that belongs to
//! it, check it, and retry what is worth retrying.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use thiserror::Error;

use crate::codec::adu::wrapped;
use crate::codec::answer::{check, Mismatch};
use crate::codec::framing::{Event, Framer};
use crate::codec::{
    Direction, Envelope, Exception, Frame, FrameError, Mode, Pdu, Request, Response,
};
use crate::input::duration::show;
use crate::transport::Transport;

pub mod backup;
pub mod device;
pub mod failover;
pub mod hosts;
pub mod map;
pub mod open;
pub mod plan;
pub mod plant;
pub mod poll;
pub mod range;
pub mod run;
pub mod scan;
mod step;
pub mod timeouts;

/// How the master behaves; the connection options fill it in.
#[derive(Clone, Copy, Debug)]
pub struct MasterOptions {
    /// The framing on the wire: RTU, ASCII, TCP or RTU over TCP.
    pub mode: Mode,
    /// For the whole answer, from the end of sending; under a millisecond counts as one.
    pub timeout: Duration,
    /// After a timeout or a bad answer; never after an exception.
    pub retries: u32,
    /// Retries of a request that may do more when sent twice
    /// ([`Request::may_differ_when_repeated`]) too; without it such a request is sent once.
    pub retry_non_idempotent: bool,
    /// Silence kept between transactions on a serial line, counted from the last byte
    /// received.
    pub frame_gap: Duration,
    /// One character's time on a serial line (zero over TCP), and the silence that ends a
    /// frame there: how the answer is framed.
    pub character: Duration,
    /// The silence that ends a frame on a serial line (3.5 characters, or as set).
    pub silence: Duration,
    /// How long a broadcast waits for the slaves to act before the next request.
    pub turnaround: Duration,
}

/// What came back.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Reply {
    /// The slave's answer to the request.
    Response(Response),
    /// The slave refused the request with an exception code.
    Exception(Exception),
    /// A broadcast: no answer is given.
    Broadcast,
}

/// Why a transaction gave no answer.
#[derive(Debug, Error)]
pub enum MasterError {
    /// Nothing that answers the request came in time, after every retry.
    #[error("no answer from slave {slave} within {}", show(*.timeout))]
    Timeout {
        /// The slave asked.
        slave: u8,
        /// How long the master waited.
        timeout: Duration,
    },
    /// What came back was not the answer, after every retry.
    #[error("bad answer from slave {slave}: {reason}")]
    BadFrame {
        /// The slave asked.
        slave: u8,
        /// What was wrong.
        reason: BadAnswer,
    },
    /// On a line without transaction ids, a late answer to an earlier request of the same
    /// function may still come, and the check that would have told it apart (08/00) got
    /// something else than its answer: the request was not sent.
    #[error(
        "slave {slave} did not answer the check sent before the request (08/00: {why}): \
         an earlier function {function} request's answer could still come and pass for this one's, so it was not sent"
    )]
    OutOfStep {
        /// The slave asked.
        slave: u8,
        /// The function whose late answer could be taken for this request's.
        function: u8,
        /// What came of the check.
        why: String,
    },
    /// The request does not fit in a PDU.
    #[error("request cannot be encoded: {0}")]
    Encode(#[from] crate::codec::PduError),
    /// The transport failed: the port went away or the connection closed.
    #[error(transparent)]
    Io(#[from] std::io::Error),
    /// A stop was asked (see [`Master::stop_on`]) while the master waited for an answer.
    #[error("interrupted while waiting for an answer")]
    Interrupted,
}

/// What was wrong with what came back instead of the answer.
#[derive(Debug, Error)]
pub enum BadAnswer {
    /// The bytes are no valid frame (bad checksum, cut short, garbled).
    #[error(transparent)]
    Frame(#[from] FrameError),
    /// A frame of the right slave that does not answer the request.
    #[error(transparent)]
    Mismatch(#[from] Mismatch),
    /// A whole frame from another slave, on a line where only ours should answer.
    #[error("the answer came from slave {0}")]
    OtherSlave(u8),
    /// A frame that reads as a request: another master on the line, or an echo.
    #[error("the answer reads as a request")]
    Request,
    /// Over TCP, bytes with no MBAP header.
    #[error("{len} bytes that are no Modbus TCP frame ({shown})")]
    NotTcp {
        /// How many bytes came.
        len: u64,
        /// The first of them, in hex.
        shown: String,
    },
    /// Part of a frame, then nothing until the timeout.
    #[error("incomplete answer: {len} bytes ({shown}) and then silence")]
    Incomplete {
        /// How many bytes came.
        len: usize,
        /// The bytes, in hex.
        shown: String,
    },
}

/// What the master saw, for `-v`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Traffic {
    /// Bytes the master sent.
    Sent,
    /// Bytes the master received.
    Received,
}

/// Sees every byte sent and received, for `-v`.
pub type Tracer = Box<dyn FnMut(Traffic, &[u8]) + Send>;

/// After a frame that is wrong, wait this long for more bytes (the right answer after
/// noise, say) before giving up: longer than a USB adapter's 16 ms latency timer.
const SETTLE: Duration = Duration::from_millis(50);

/// How often a wait for an answer looks whether a stop was asked (see [`Master::stop_on`]).
const STOP_CHECK: Duration = Duration::from_millis(50);

/// The shortest timeout honoured: below it a deadline would pass before a byte could come.
const MIN_TIMEOUT: Duration = Duration::from_millis(1);

/// A master on one transport: one transaction at a time, with retries.
pub struct Master {
    transport: Box<dyn Transport>,
    options: MasterOptions,
    last_traffic: Option<Instant>,
    transaction: u16,
    tracer: Option<Tracer>,
    /// Frames the answers; over TCP it keeps what arrived after an answer (a duplicate,
    /// say) for the next transaction to pass over.
    framer: Framer,
    /// When the framer's clock started: it takes times in microseconds from here.
    started: Instant,
    /// The last transaction ended on a whole answer, so nothing stale can be waiting
    /// on a TCP connection but whole frames with other transaction ids.
    in_step: bool,
    /// A second path to the device, and when to change to it.
    failover: Option<Box<failover::Failover>>,
    /// Set (by a signal handler) to end a wait for an answer at once.
    stop: Option<Arc<AtomicBool>>,
    /// On a line without transaction ids (RTU, ASCII), the answers that may still be on
    /// their way, by slave and function, one entry each: a try ended without its answer.
    /// Such a late answer would pass every check for the next request of the same
    /// function to the same slave, so that request waits until the slave is back in step;
    /// one heard meanwhile is paid off.
    owed: step::Owed,
    /// The requests that change the device and were sent more than once, for the
    /// command to tell.
    resent: Vec<run::Resent>,
    /// Over TCP, the latest transactions sent and when: an answer that comes after its
    /// request timed out is told with how long it took.
    sent: std::collections::VecDeque<(u16, Instant)>,
    /// The last transaction ended on its timeout with nothing else received: over TCP its
    /// answer may still come, whole, and is heard rather than thrown away.
    timed_out: bool,
    /// Answers heard after their request timed out, over TCP, not yet taken.
    late: Vec<LateAnswer>,
}

/// An answer that came over TCP after its request had timed out.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LateAnswer {
    /// The unit id that answered.
    pub slave: u8,
    /// A device answered (a response, or an exception other than a gateway's 0A or 0B).
    pub present: bool,
    /// How long after its request it came.
    pub after: Duration,
}

/// How many transactions sent are remembered for [`LateAnswer::after`].
const TRANSACTIONS_REMEMBERED: usize = 64;

/// What the bytes received so far came to.
#[derive(Default)]
struct Heard {
    answer: Option<Pdu>,
    /// What was wrong with the first frame that was not the answer.
    problem: Option<BadAnswer>,
    /// Bytes of whole frames that belong to other transactions: not this one's fault.
    stale_bytes: usize,
}

impl Master {
    /// A master on `transport`; nothing is sent until the first transaction.
    pub fn new(transport: Box<dyn Transport>, options: MasterOptions) -> Self {
        let framer = Framer::new(
            options.mode,
            options.character.as_secs_f64() * 1e6,
            options.silence.as_micros() as u64,
        );
        Self {
            transport,
            options,
            last_traffic: None,
            transaction: 0,
            tracer: None,
            framer,
            started: Instant::now(),
            in_step: false,
            failover: None,
            stop: None,
            owed: step::Owed::default(),
            resent: Vec::new(),
            sent: std::collections::VecDeque::new(),
            timed_out: false,
            late: Vec::new(),
        }
    }

    /// The datagrams that came from elsewhere than the device (over UDP), passed over.
    pub fn foreign(&self) -> Option<crate::transport::Foreign> {
        self.transport.foreign()
    }

    /// The answers heard over TCP after their request had timed out, since last asked.
    pub fn take_late_answers(&mut self) -> Vec<LateAnswer> {
        std::mem::take(&mut self.late)
    }

    /// Ends a wait for an answer as soon as `stop` is set, with
    /// [`MasterError::Interrupted`], rather than at the answer's timeout, where nothing is
    /// left behind: over Modbus TCP the answer goes to a connection that closes with the
    /// process. On a serial line (or one behind a gateway) the wait goes on to its answer
    /// or its timeout all the same: an answer still on its way would be taken by the next
    /// command for the answer to its own request, a value shown that was never asked.
    pub fn stop_on(&mut self, stop: Arc<AtomicBool>) {
        self.stop = Some(stop);
    }

    fn stopped(&self) -> bool {
        self.stop
            .as_ref()
            .is_some_and(|stop| stop.load(Ordering::SeqCst))
    }

    /// The transport's `receive` until `until`, in slices short enough to notice a stop
    /// asked meanwhile: then an error of kind `Interrupted`.
    fn receive(&mut self, chunk: &mut Vec<u8>, until: Instant) -> std::io::Result<usize> {
        if self.stop.is_none() || self.transport.is_serial_line() {
            return self.transport.receive(chunk, until);
        }
        loop {
            if self.stopped() {
                return Err(std::io::Error::new(
                    std::io::ErrorKind::Interrupted,
                    "interrupted",
                ));
            }
            let slice = until.min(Instant::now() + STOP_CHECK);
            let received = self.transport.receive(chunk, slice)?;
            if received > 0 || Instant::now() >= until {
                return Ok(received);
            }
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

    /// Listens for `duration` without sending anything, and returns the slave ids whose
    /// answers were heard on the line, in the order first heard: the slaves another master
    /// is talking to.
    pub fn listen(&mut self, duration: Duration) -> std::io::Result<Vec<u8>> {
        self.hear_line(Instant::now() + duration, None)
    }

    /// Waits, sending nothing, until the line has been quiet for `quiet` (for `at_most`
    /// at the longest), and returns the slave ids whose answers were heard meanwhile:
    /// answers that came after their request's timeout.
    pub fn wait_quiet(&mut self, quiet: Duration, at_most: Duration) -> std::io::Result<Vec<u8>> {
        self.hear_line(Instant::now() + at_most, Some(quiet))
    }

    /// Hears the line until `end`, or until it has been quiet for `quiet`; the slave ids
    /// of the answers heard, in the order first heard.
    fn hear_line(&mut self, end: Instant, quiet: Option<Duration>) -> std::io::Result<Vec<u8>> {
        let mut framer = Framer::new(
            self.options.mode,
            self.options.character.as_secs_f64() * 1e6,
            self.options.silence.as_micros() as u64,
        );
        let mut chunk = Vec::with_capacity(512);
        let mut events = Vec::new();
        let mut heard = Vec::new();
        loop {
            let until = match quiet {
                Some(quiet) => end.min(Instant::now() + quiet),
                None => end,
            };
            chunk.clear();
            let received = self.receive(&mut chunk, until)?;
            if received == 0 {
                framer.finish(&mut events);
            } else {
                self.note(Traffic::Received, &chunk);
                framer.push_at(
                    &chunk,
                    self.started.elapsed().as_micros() as u64,
                    &mut events,
                );
            }
            let mode = self.options.mode;
            for event in events.drain(..) {
                let Event::Frame(found) = event else { continue };
                // An answer, where its layout tells; else what reads only as one.
                let answer = found.broken.is_none()
                    && match found.direction {
                        Some(direction) => direction == Direction::Response,
                        None => Frame::decode(mode, &found.bytes, Direction::Request).is_err(),
                    };
                let frame = Frame::decode(mode, &found.bytes, Direction::Response);
                if let (true, Ok(frame)) = (answer, frame) {
                    self.owed.pay_off(frame.slave, &frame.pdu);
                    // Over TCP, a gateway's word that it has no such device is no one heard.
                    let present = match mode {
                        Mode::Tcp => self.heard_late(&frame),
                        _ => true,
                    };
                    if present && !heard.contains(&frame.slave) {
                        heard.push(frame.slave);
                    }
                }
            }
            if received == 0 {
                self.last_traffic = Some(Instant::now());
                return Ok(heard);
            }
        }
    }

    /// The requests that change the device and were sent more than once since last
    /// asked: each may have been carried out more than once.
    pub fn take_resent(&mut self) -> Vec<run::Resent> {
        std::mem::take(&mut self.resent)
    }

    /// The time an answer is waited for.
    pub fn timeout(&self) -> Duration {
        self.options.timeout
    }

    /// Waits `timeout` for answers from now on.
    pub fn set_timeout(&mut self, timeout: Duration) {
        self.options.timeout = timeout;
    }

    /// One request, with its retries.
    pub fn transact(&mut self, slave: u8, request: &Request) -> Result<Reply, MasterError> {
        self.transact_counted(slave, request).0
    }

    /// One request, with its retries, and how many times it was sent (0 when it never
    /// was: the slave was not brought back in step).
    pub fn transact_counted(
        &mut self,
        slave: u8,
        request: &Request,
    ) -> (Result<Reply, MasterError>, u32) {
        let mut tries = step::Tries::default();
        let mut outcome = self.transact_here(slave, request, &mut tries);
        let mut asked = 1;
        loop {
            match self.weigh(&outcome, true) {
                // Asked again on the other path, as a retry would be; counted there, but
                // no change back within one request.
                failover::Weighed::Switched => {
                    // Nothing of the other path's can be late on this one.
                    tries.pending = false;
                    let again = self.transact_here(slave, request, &mut tries);
                    self.weigh(&again, false);
                    return (again, tries.sent);
                }
                failover::Weighed::Counted if self.asks_again(asked) => {
                    asked += 1;
                    outcome = self.transact_here(slave, request, &mut tries);
                }
                _ => return (outcome, tries.sent),
            }
        }
    }

    /// One request, with its retries, on the path in use.
    fn transact_here(
        &mut self,
        slave: u8,
        request: &Request,
        tries: &mut step::Tries,
    ) -> Result<Reply, MasterError> {
        let retries = if request.may_differ_when_repeated() && !self.options.retry_non_idempotent {
            0
        } else {
            self.options.retries
        };
        let mut here = 0;
        loop {
            here += 1;
            match self.attempt(slave, request, tries) {
                Err(
                    MasterError::Timeout { .. }
                    | MasterError::BadFrame { .. }
                    | MasterError::OutOfStep { .. },
                ) if here <= retries => {}
                result => return result,
            }
        }
    }

    fn is_broadcast(&self, slave: u8) -> bool {
        slave == 0 && self.options.mode != Mode::Tcp
    }

    /// Sends a request, after the line's silence and with stale bytes thrown away, and
    /// waits for its answer.
    fn exchange(&mut self, slave: u8, request: &Request) -> Result<Reply, MasterError> {
        if self.transport.is_serial_line() {
            if let Some(last) = self.last_traffic {
                let quiet_until = last + self.options.frame_gap;
                if let Some(wait) = quiet_until.checked_duration_since(Instant::now()) {
                    std::thread::sleep(wait);
                }
            }
        }
        // On a serial line noise can arrive at any time; over TCP a late answer can only
        // follow a transaction that failed (and would be told by its transaction id):
        // after a plain timeout it is whole and heard, after anything else thrown away.
        let tcp_late_whole = self.options.mode == Mode::Tcp && self.timed_out;
        if self.transport.is_serial_line() || (!self.in_step && !tcp_late_whole) {
            self.transport.discard_input()?;
            self.framer.clear();
        }
        self.in_step = false;
        self.timed_out = false;
        self.transaction = self.transaction.wrapping_add(1);
        if self.options.mode == Mode::Tcp {
            if self.sent.len() == TRANSACTIONS_REMEMBERED {
                self.sent.pop_front();
            }
            self.sent.push_back((self.transaction, Instant::now()));
        }
        // The request's PDU, which its answer is checked against, and its frame.
        let mut asked = Vec::new();
        request.encode(&mut asked)?;
        let bytes = wrapped(self.options.mode, slave, self.transaction, &asked);
        self.note(Traffic::Sent, &bytes);
        if self.options.mode != Mode::Tcp {
            self.framer.await_answer(slave, request.function());
        }
        self.transport.send(&bytes)?;
        self.last_traffic = Some(Instant::now());
        if self.is_broadcast(slave) {
            std::thread::sleep(self.options.turnaround);
            return Ok(Reply::Broadcast);
        }
        match self.await_answer(slave, &asked)? {
            Pdu::Exception(exception) => Ok(Reply::Exception(exception)),
            Pdu::Response(response) => Ok(Reply::Response(response)),
            Pdu::Request(_) => Err(MasterError::BadFrame {
                slave,
                reason: BadAnswer::Request,
            }),
        }
    }

    /// A frame over TCP with an earlier transaction id: an answer that came after its
    /// request timed out. Whether a device answered it (not a gateway's 0A or 0B).
    fn heard_late(&mut self, frame: &Frame) -> bool {
        let gateway_has_none = matches!(
            &frame.pdu,
            Pdu::Exception(e) if matches!(
                e.code,
                crate::codec::ExceptionCode::GATEWAY_PATH_UNAVAILABLE
                    | crate::codec::ExceptionCode::GATEWAY_TARGET_FAILED
            )
        );
        if let Some((_, sent)) = self
            .sent
            .iter()
            .find(|(transaction, _)| *transaction == frame.transaction)
        {
            self.late.push(LateAnswer {
                slave: frame.slave,
                present: !gateway_has_none,
                after: sent.elapsed(),
            });
        }
        !gateway_has_none
    }

    /// Whether a whole, valid frame, `frame` read from its PDU `answer`, is the answer to
    /// the request whose PDU is `asked`.
    fn belongs(
        &self,
        frame: &Frame,
        answer: &[u8],
        slave: u8,
        asked: &[u8],
    ) -> Result<(), Option<BadAnswer>> {
        if self.options.mode == Mode::Tcp && frame.transaction != self.transaction {
            // A late or repeated answer to an earlier request: not ours, and no fault of
            // this one.
            return Err(None);
        }
        if frame.slave != slave {
            return Err(Some(BadAnswer::OtherSlave(frame.slave)));
        }
        check(asked, answer).map_err(|mismatch| Some(mismatch.into()))
    }

    /// Reads what the framer found, in order, until the answer.
    fn hear(&mut self, events: &mut Vec<Event>, heard: &mut Heard, slave: u8, asked: &[u8]) {
        for event in events.drain(..) {
            if heard.answer.is_some() {
                // Whatever follows the answer is for later transactions.
                continue;
            }
            match event {
                Event::Frame(found) => {
                    let opened = Envelope::open(self.options.mode, &found.bytes);
                    let read = opened.and_then(|envelope| {
                        Frame::read(&envelope, Direction::Response).map(|frame| (frame, envelope))
                    });
                    match read {
                        Ok((frame, envelope)) => {
                            match self.belongs(&frame, &envelope.pdu, slave, asked) {
                                Ok(()) => heard.answer = Some(frame.pdu),
                                Err(None) => {
                                    heard.stale_bytes += found.bytes.len();
                                    self.heard_late(&frame);
                                }
                                Err(Some(reason)) => {
                                    // A late answer the slave asked owed is no fault of this
                                    // request; another slave's is still told (a scan learns
                                    // of a late slave by it).
                                    let owed = self.owed.pay_off(frame.slave, &frame.pdu);
                                    if owed && frame.slave == slave {
                                        heard.stale_bytes += found.bytes.len();
                                    } else {
                                        heard.problem.get_or_insert(reason);
                                    }
                                }
                            }
                        }
                        Err(error) => {
                            heard.problem.get_or_insert(error.into());
                        }
                    }
                }
                Event::Noise(noise) if self.options.mode == Mode::Tcp => {
                    heard.problem.get_or_insert(BadAnswer::NotTcp {
                        len: noise.len,
                        shown: crate::codec::hex::spaced_hex(
                            &noise.kept[..noise.kept.len().min(12)],
                        ),
                    });
                }
                // Noise on a serial line: the answer may still stand after it.
                Event::Noise(_) => {}
            }
        }
    }

    fn await_answer(&mut self, slave: u8, asked: &[u8]) -> Result<Pdu, MasterError> {
        let deadline = Instant::now() + self.options.timeout.max(MIN_TIMEOUT);
        let timed = self.options.mode != Mode::Tcp;
        // Modbus/UDP: a datagram a frame. RTU in datagrams is read as the stream a serial
        // server packs them from, which may cut a frame in two.
        let whole_datagrams = self.transport.is_datagram() && self.options.mode == Mode::Tcp;
        let mut received = Vec::new();
        let mut chunk = Vec::with_capacity(512);
        let mut events = Vec::new();
        let mut heard = Heard::default();
        // Bytes have come that the framer may only decide on silence (a frame found after
        // noise, a function without a layout): the silence is waited for, not the timeout.
        let mut undecided = false;
        let mut held_after_silence = false;
        let frame_end = match self.options.mode {
            Mode::Rtu => self.options.silence + self.options.character,
            _ => Duration::ZERO,
        };
        let outcome = loop {
            self.hear(&mut events, &mut heard, slave, asked);
            if heard.answer.is_some() {
                break Ok(());
            }
            if self.framer.is_lost() {
                break Err(None);
            }
            // After a frame that is wrong, wait a little for the right one (behind noise,
            // say) before giving up; after bytes that the silence did not make a frame of
            // (a corrupted answer), a little for the rest of them: a line does not pause
            // inside a frame for longer than a USB adapter's latency timer.
            let give_up = match (&heard.problem, held_after_silence) {
                (Some(_), _) => deadline.min(Instant::now() + SETTLE),
                (None, true) => {
                    let last = self.last_traffic.unwrap_or_else(Instant::now);
                    deadline.min(last + SETTLE)
                }
                (None, false) => deadline,
            };
            let silence_at = Instant::now() + frame_end;
            let wait_until = if undecided {
                give_up.min(silence_at)
            } else {
                give_up
            };
            chunk.clear();
            match self.receive(&mut chunk, wait_until) {
                Ok(0) if undecided && Instant::now() < give_up => {
                    undecided = false;
                    let now = self.started.elapsed().as_micros() as u64;
                    self.framer.idle(now, &mut events);
                    held_after_silence = true;
                }
                Ok(0) => {
                    // No more is awaited: what is held is decided now.
                    self.framer.finish(&mut events);
                    self.hear(&mut events, &mut heard, slave, asked);
                    break if heard.answer.is_some() {
                        Ok(())
                    } else {
                        Err(None)
                    };
                }
                Ok(_) => {
                    self.last_traffic = Some(Instant::now());
                    received.extend_from_slice(&chunk);
                    if whole_datagrams {
                        // Each datagram its own line of the trace, when it came.
                        self.note(Traffic::Received, &chunk);
                    }
                    if whole_datagrams && Envelope::open(Mode::Tcp, &chunk).is_err() {
                        // Modbus/UDP is one frame a datagram: one that is not (cut, two
                        // frames, bytes after one) is no answer, whatever it starts with.
                        heard.stale_bytes += chunk.len();
                        heard.problem.get_or_insert(BadAnswer::NotTcp {
                            len: chunk.len() as u64,
                            shown: crate::codec::hex::spaced_hex(&chunk[..chunk.len().min(12)]),
                        });
                        continue;
                    }
                    if timed {
                        let now = self.started.elapsed().as_micros() as u64;
                        self.framer.push_at(&chunk, now, &mut events);
                        undecided = self.options.mode == Mode::Rtu;
                    } else {
                        self.framer.push(&chunk, &mut events);
                    }
                    if whole_datagrams {
                        // A datagram's end ends the frame it carries.
                        self.framer.gap(0, &mut events);
                    }
                }
                Err(error) => break Err(Some(error)),
            }
        };
        if !received.is_empty() && !whole_datagrams {
            self.note(Traffic::Received, &received);
        }
        match (outcome, heard.answer) {
            (Ok(()), Some(pdu)) => {
                self.in_step = true;
                Ok(pdu)
            }
            (Err(Some(_)), _) if self.stopped() => Err(MasterError::Interrupted),
            (Err(Some(io_error)), _) => Err(MasterError::Io(io_error)),
            _ => {
                let unexplained = received.len().saturating_sub(heard.stale_bytes);
                Err(match heard.problem {
                    Some(reason) => MasterError::BadFrame { slave, reason },
                    None if unexplained > 0 => {
                        let shown =
                            crate::codec::hex::spaced_hex(&received[..received.len().min(32)]);
                        MasterError::BadFrame {
                            slave,
                            reason: BadAnswer::Incomplete {
                                len: received.len(),
                                shown: if received.len() > 32 {
                                    format!("{shown} ...")
                                } else {
                                    shown
                                },
                            },
                        }
                    }
                    None => {
                        self.timed_out = unexplained == 0;
                        MasterError::Timeout {
                            slave,
                            timeout: self.options.timeout,
                        }
                    }
                })
            }
        }
    }
}
