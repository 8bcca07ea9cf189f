//! The line behind the gateway: one transaction at a time, as the careful master sends it
//! (the gap between frames, stale bytes thrown away, the answer checked against the
//! request, retries), opened again with the poll's back-off when it goes away.

use std::time::Instant;

use crate::codec::adu::opaque_request;
use crate::codec::{Direction, ExceptionCode, Frame, FrameError, Mode, Pdu, PduError};
use crate::codec::{Request, Response};
use crate::master::poll::Backoff;
use crate::master::{Master, MasterError, Reply};

use super::{Event, GatewayOptions, Job, Outcome, Report, Transaction};

/// Opens the line: the master on the port, or why it cannot be had.
pub type Connect = Box<dyn FnMut() -> Result<Master, String> + Send>;

/// The line, open or waiting to be opened again.
pub struct Line {
    connect: Connect,
    master: Option<Master>,
    backoff: Backoff,
    /// Whether a unit id 0 is a broadcast there (a serial line, not a TCP server).
    broadcasts: bool,
    /// The line has been told down and not yet up again.
    told_down: bool,
}

impl Line {
    /// A line opened by `connect` when it is first needed, and again after it fails.
    /// `mode` is its framing: on RTU and ASCII lines unit 0 is a broadcast.
    pub fn new(connect: Connect, mode: Mode) -> Line {
        Line {
            connect,
            master: None,
            backoff: Backoff::new(),
            broadcasts: mode != Mode::Tcp,
            told_down: false,
        }
    }

    /// Opens the line now, if it can be: at the start, so that a port that is not there
    /// is told at once.
    pub fn open(&mut self, report: &Report) {
        self.master_now(report);
    }

    /// The master, opened again if it is time to try; `None` while the line is down.
    fn master_now(&mut self, report: &Report) -> Option<&mut Master> {
        if self.master.is_none() && Instant::now() >= self.backoff.next_attempt {
            match (self.connect)() {
                Ok(master) => {
                    self.master = Some(master);
                    self.backoff = Backoff::new();
                    if self.told_down {
                        self.told_down = false;
                        report(Event::LineUp);
                    }
                }
                Err(why) => self.down(why, report),
            }
        }
        self.master.as_mut()
    }

    fn down(&mut self, why: String, report: &Report) {
        self.master = None;
        if !self.told_down || why != self.backoff.last_error {
            report(Event::LineDown(&why));
        }
        self.told_down = true;
        self.backoff.failed(why);
    }

    /// One client request carried out: on the line, or answered by the gateway itself
    /// when it does not read or the line is down.
    pub(super) fn carry(
        &mut self,
        job: &Job,
        options: &GatewayOptions,
        report: &Report,
    ) -> Transaction {
        let started = Instant::now();
        let (unit, transaction) = (job.frame.get(6).copied().unwrap_or(0), mbap_id(&job.frame));
        let slave = options.unit_map.slave_for(unit);
        let done = |request: Request, answer: Option<Pdu>, tries, outcome| Transaction {
            client: job.client.clone(),
            role: job.role.clone(),
            unit,
            slave,
            transaction,
            request,
            answer,
            queued: started.duration_since(job.arrived),
            response_time: started.elapsed(),
            tries,
            outcome,
            delivered: false,
        };
        let request = match read_request(&job.frame) {
            Ok(request) => request,
            Err((request, code)) => {
                let answer = Pdu::refusal(&request, code);
                return done(request, Some(answer), 0, Outcome::Exception);
            }
        };
        if let Some(why) = job.rights.as_ref().and_then(|r| r.refusal(&request)) {
            // Not for this client's role: an illegal function to it, as the specification
            // has it, the line untouched.
            let answer = Pdu::refusal(&request, ExceptionCode::ILLEGAL_FUNCTION);
            return done(request, Some(answer), 0, Outcome::Refused(why));
        }
        let broadcast = slave == 0 && self.broadcasts;
        if broadcast && !broadcastable(&request) {
            // A read sent to every slave has no answer to give: refused, not sent.
            let answer = Pdu::refusal(&request, ExceptionCode::ILLEGAL_FUNCTION);
            return done(request, Some(answer), 0, Outcome::Exception);
        }
        let Some(master) = self.master_now(report) else {
            let why = self.backoff.last_error.clone();
            let answer = Pdu::refusal(&request, ExceptionCode::GATEWAY_PATH_UNAVAILABLE);
            return done(request, Some(answer), 0, Outcome::LineDown(why));
        };
        let (result, tries) = master.transact_counted(slave, &request);
        let failed =
            |request: &Request| Pdu::refusal(request, ExceptionCode::GATEWAY_TARGET_FAILED);
        match result {
            Ok(Reply::Response(response)) => done(
                request,
                Some(Pdu::Response(response)),
                tries,
                Outcome::Answer,
            ),
            Ok(Reply::Exception(refused)) => done(
                request,
                Some(Pdu::Exception(refused)),
                tries,
                Outcome::Exception,
            ),
            Ok(Reply::Broadcast) => {
                let echo = (options.broadcast_reply && broadcast).then(|| echo(&request));
                done(request, echo, tries, Outcome::Broadcast)
            }
            // The gateway's master is given no stop, so no wait is cut short; one that
            // were would be no answer all the same.
            Err(
                MasterError::Timeout { .. }
                | MasterError::OutOfStep { .. }
                | MasterError::Interrupted,
            ) => {
                let answer = failed(&request);
                done(request, Some(answer), tries, Outcome::Timeout)
            }
            Err(MasterError::BadFrame { reason, .. }) => {
                let answer = failed(&request);
                done(
                    request,
                    Some(answer),
                    tries,
                    Outcome::BadFrame(reason.to_string()),
                )
            }
            Err(MasterError::Encode(_)) => {
                // A request that read but cannot be sent again as read: the client's mistake.
                let answer = Pdu::refusal(&request, ExceptionCode::ILLEGAL_DATA_VALUE);
                done(request, Some(answer), 0, Outcome::Exception)
            }
            Err(MasterError::Io(error)) => {
                let why = format!("the line failed: {error}");
                self.down(why.clone(), report);
                let answer = Pdu::refusal(&request, ExceptionCode::GATEWAY_PATH_UNAVAILABLE);
                done(request, Some(answer), tries, Outcome::LineDown(why))
            }
        }
    }
}

/// The MBAP frame's transaction id.
fn mbap_id(frame: &[u8]) -> u16 {
    match frame {
        [high, low, ..] => u16::from_be_bytes([*high, *low]),
        _ => 0,
    }
}

/// The request of a client's MBAP frame, or, when its PDU does not read, the request as
/// opaque bytes with the exception it gets: 01 for a function code that is no request's,
/// 03 for a known function whose fields break its layout. File records that are no place
/// in a file go to the device as they are.
fn read_request(frame: &[u8]) -> Result<Request, (Request, ExceptionCode)> {
    let opaque = || match opaque_request(Mode::Tcp, frame, true) {
        Ok(Frame {
            pdu: Pdu::Request(request),
            ..
        }) => request,
        _ => Request::Other {
            function: frame.get(7).copied().unwrap_or(0),
            data: frame.get(8..).unwrap_or_default().to_vec(),
        },
    };
    match Frame::decode(Mode::Tcp, frame, Direction::Request) {
        Ok(Frame {
            pdu: Pdu::Request(request),
            ..
        }) if is_request_function(request.function()) => Ok(request),
        Ok(_) => Err((opaque(), ExceptionCode::ILLEGAL_FUNCTION)),
        // Records that are no place in a file (file 0, past record 9999): the layout holds,
        // and what the device has is the device's to say.
        Err(FrameError::Pdu(PduError::FileReference(_))) => Ok(opaque()),
        Err(FrameError::Pdu(_)) => {
            let request = opaque();
            let code = if is_request_function(request.function()) {
                ExceptionCode::ILLEGAL_DATA_VALUE
            } else {
                ExceptionCode::ILLEGAL_FUNCTION
            };
            Err((request, code))
        }
        Err(_) => Err((opaque(), ExceptionCode::ILLEGAL_FUNCTION)),
    }
}

/// Whether a request may go to every slave at once: writes and diagnostics, and functions
/// whose layout mbtool does not know (the user's call); reads may not.
fn broadcastable(request: &Request) -> bool {
    matches!(
        request,
        Request::WriteSingleCoil { .. }
            | Request::WriteSingleRegister { .. }
            | Request::WriteMultipleCoils { .. }
            | Request::WriteMultipleRegisters { .. }
            | Request::MaskWriteRegister { .. }
            | Request::Diagnostics { .. }
            | Request::Other { .. }
    )
}

/// Function codes 1-127 name requests; 0 and 128-255 (exceptions) do not.
fn is_request_function(function: u8) -> bool {
    (1..0x80).contains(&function)
}

/// What a broadcast's client is sent with `--broadcast-reply`: the answer a slave gives
/// to a write (the echo of the request, or of its address and quantity), or else (a
/// diagnostic, a function of unknown layout) the request itself.
fn echo(request: &Request) -> Pdu {
    match request.clone() {
        Request::WriteSingleCoil { address, value } => {
            Pdu::Response(Response::WriteSingleCoil { address, value })
        }
        Request::WriteSingleRegister { address, value } => {
            Pdu::Response(Response::WriteSingleRegister { address, value })
        }
        Request::WriteMultipleCoils { address, values } => {
            Pdu::Response(Response::WriteMultipleCoils {
                address,
                quantity: values.len() as u16,
            })
        }
        Request::WriteMultipleRegisters { address, values } => {
            Pdu::Response(Response::WriteMultipleRegisters {
                address,
                quantity: values.len() as u16,
            })
        }
        Request::MaskWriteRegister {
            address,
            and_mask,
            or_mask,
        } => Pdu::Response(Response::MaskWriteRegister {
            address,
            and_mask,
            or_mask,
        }),
        other => Pdu::Request(other),
    }
}

/// The MBAP frame that carries `pdu` to the client, with its unit and transaction id.
pub(super) fn mbap(unit: u8, transaction: u16, pdu: &Pdu) -> Vec<u8> {
    let frame = Frame {
        mode: Mode::Tcp,
        slave: unit,
        transaction,
        pdu: pdu.clone(),
    };
    // A PDU the gateway holds always encodes: it was decoded from bytes or built here.
    frame.encode().unwrap_or_default()
}
