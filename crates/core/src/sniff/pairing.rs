//! Telling requests from answers without a direction line, and pairing each answer with
//! its request. By shape where the bytes decide (an exception has bit 7 set; a 03 request
//! is 8 bytes, its answer 5 + 2n), by the pending request where they do not (05/06 echo,
//! 8-byte 01/02 frames), and saying so when neither settles it. Pairing works on the PDUs'
//! bytes: what they say is read only for the frames shown.

use smallvec::SmallVec;

use crate::codec::answer::{check, check_function};
use crate::codec::function::EXCEPTION_FLAG;
use crate::codec::{Direction, Mismatch, Request, Ways};

/// A request's PDU as it travelled, function code first, and whether it reads: a
/// malformed request waits for its answer too, which is checked against its function
/// alone. Inline up to 16 bytes, as every read's request is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct RequestSent {
    pdu: SmallVec<[u8; 16]>,
    reads: bool,
}

impl RequestSent {
    pub(super) fn new(pdu: &[u8], reads: bool) -> Self {
        Self {
            pdu: SmallVec::from_slice(pdu),
            reads,
        }
    }

    pub(super) fn function(&self) -> u8 {
        self.pdu.first().copied().unwrap_or_default()
    }

    /// How the answer `answer` fits it (`answer_reads`: its PDU reads): where either does
    /// not read, by function alone.
    pub(super) fn fit(&self, answer: &[u8], answer_reads: bool) -> Result<(), Mismatch> {
        if self.reads && answer_reads {
            check(&self.pdu, answer)
        } else {
            check_function(&self.pdu, answer)
        }
    }

    /// The request, read; a malformed one as its function and bytes.
    pub(super) fn request(&self) -> Request {
        let (function, data) = self.pdu.split_first().unwrap_or((&0, &[]));
        let opaque = || Request::Other {
            function: *function,
            data: data.to_vec(),
        };
        match self.reads {
            true => Request::decode(&self.pdu).unwrap_or_else(|_| opaque()),
            false => opaque(),
        }
    }
}

/// A request still waiting for its answer.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct Pending {
    pub slave: u8,
    pub request: RequestSent,
    /// When it was sent (its last byte), in microseconds, when known.
    pub time: Option<u64>,
}

/// What a frame is, once read against the request before it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) enum Role {
    Request,
    /// An answer (or exception), with the request it answers when it follows one.
    Answer {
        to: Option<RequestSent>,
        /// How it does not fit the request of its slave and function that awaited it (a
        /// count or an echo that differs): that request was answered, wrongly.
        mismatch: Option<Mismatch>,
    },
    /// Reads both ways, and nothing before it settles which: the first frame of a capture.
    Unsettled,
    /// The PDU breaks its function's layout either way.
    Malformed,
}

impl Role {
    /// The ways the frame is shown to read.
    pub(super) fn ways(&self) -> Ways {
        match self {
            Role::Request => Ways::Request,
            Role::Answer { .. } => Ways::Answer,
            Role::Unsettled => Ways::Both,
            Role::Malformed => Ways::Neither,
        }
    }
}

#[derive(Default)]
pub(super) struct Pairer {
    pending: Option<Pending>,
    /// Whether any frame came before: after one, a frame that reads both ways and answers
    /// nothing pending is the master's next request.
    seen: bool,
}

/// A request that got no answer, and how long it waited.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct Unanswered {
    pub pending: Pending,
    pub waited: Option<u64>,
    /// The capture ended while it waited.
    pub capture_ended: bool,
}

impl Pairer {
    /// Reads one valid frame of `slave`, its PDU `pdu`, which reads `ways`; `start` and
    /// `end` are the arrival times of its first and last byte. A request that was still
    /// waiting when another came is returned as unanswered.
    pub(super) fn read(
        &mut self,
        slave: u8,
        pdu: &[u8],
        ways: Ways,
        start: Option<u64>,
        end: Option<u64>,
    ) -> (Role, Option<Unanswered>) {
        let first = !std::mem::replace(&mut self.seen, true);
        match ways {
            Ways::Request => {
                let unanswered = self.wait_for(slave, RequestSent::new(pdu, true), start, end);
                (Role::Request, unanswered)
            }
            Ways::Answer => (self.answer(pdu, slave), None),
            Ways::Both => {
                let answers_pending = self
                    .pending
                    .as_ref()
                    .is_some_and(|p| p.slave == slave && p.request.fit(pdu, true).is_ok());
                if answers_pending {
                    return (self.answer(pdu, slave), None);
                }
                let unanswered = self.wait_for(slave, RequestSent::new(pdu, true), start, end);
                match first {
                    true => (Role::Unsettled, unanswered),
                    false => (Role::Request, unanswered),
                }
            }
            Ways::Neither => (Role::Malformed, None),
        }
    }

    /// Which way a frame of `slave` and `function` that reads neither way travels, where
    /// its layout is the same both ways: an answer where a request of that slave and
    /// function waits for one, the master's next request otherwise. `None` for the first
    /// frame of a capture, which nothing before settles.
    pub(super) fn way_of_malformed(&self, slave: u8, function: u8) -> Option<Direction> {
        match (self.seen, self.awaits(slave, function)) {
            (false, _) => None,
            (true, true) => Some(Direction::Response),
            (true, false) => Some(Direction::Request),
        }
    }

    /// A malformed frame of `slave`, its PDU `pdu`, that travels as `direction`, as it is
    /// shown: an answer settles the request that waits for it (it was answered, if not
    /// well); a request is the master's next, and the one still waiting got no answer. A
    /// malformed request waits for its answer as any request does, kept byte for byte: a
    /// device refuses it with an exception, which is paired with it.
    pub(super) fn malformed(
        &mut self,
        slave: u8,
        pdu: &[u8],
        direction: Direction,
        start: Option<u64>,
        end: Option<u64>,
    ) -> Option<Unanswered> {
        self.seen = true;
        let Some(&function) = pdu.first() else {
            return self.give_up(start);
        };
        match direction {
            Direction::Response => {
                if self.awaits(slave, function) {
                    self.pending = None;
                }
                None
            }
            Direction::Request => self.wait_for(slave, RequestSent::new(pdu, false), start, end),
        }
    }

    fn awaits(&self, slave: u8, function: u8) -> bool {
        self.pending
            .as_ref()
            .is_some_and(|p| p.slave == slave && p.request.function() == function & !EXCEPTION_FLAG)
    }

    fn answer(&mut self, pdu: &[u8], slave: u8) -> Role {
        let fit = match &self.pending {
            Some(p) if p.slave == slave => p.request.fit(pdu, true),
            _ => {
                return Role::Answer {
                    to: None,
                    mismatch: None,
                }
            }
        };
        match fit {
            Ok(()) => Role::Answer {
                to: self.pending.take().map(|p| p.request),
                mismatch: None,
            },
            // Another function's answer is not this request's.
            Err(Mismatch::Function { .. }) => Role::Answer {
                to: None,
                mismatch: None,
            },
            Err(mismatch) => {
                self.pending = None;
                Role::Answer {
                    to: None,
                    mismatch: Some(mismatch),
                }
            }
        }
    }

    fn wait_for(
        &mut self,
        slave: u8,
        request: RequestSent,
        start: Option<u64>,
        end: Option<u64>,
    ) -> Option<Unanswered> {
        let previous = self.give_up(start);
        // Broadcasts (slave 0) are never answered, and so never "unanswered".
        if slave != 0 {
            self.pending = Some(Pending {
                slave,
                request,
                time: end,
            });
        }
        previous
    }

    /// The request still waiting, given up on as another request starts at `start`.
    fn give_up(&mut self, start: Option<u64>) -> Option<Unanswered> {
        self.pending.take().map(|pending| Unanswered {
            waited: match (pending.time, start) {
                (Some(sent), Some(now)) => Some(now.saturating_sub(sent)),
                _ => None,
            },
            pending,
            capture_ended: false,
        })
    }

    /// The end of the capture: a request still waiting is unanswered, for as long as the
    /// capture went on after it (no time at all when it ended with the request).
    pub(super) fn finish(&mut self, now: Option<u64>) -> Option<Unanswered> {
        self.pending.take().map(|pending| Unanswered {
            waited: match (pending.time, now) {
                (Some(sent), Some(now)) if now > sent => Some(now - sent),
                _ => None,
            },
            pending,
            capture_ended: true,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_echo_is_the_answer_of_the_request_before_it() {
        let mut pairer = Pairer::default();
        let write = [0x06, 0x00, 0x01, 0x00, 0x03];
        let (first, _) = pairer.read(17, &write, Ways::of(&write), Some(0), Some(1));
        // Nothing came before it: it could be either.
        assert!(matches!(first, Role::Unsettled));
        let (second, _) = pairer.read(17, &write, Ways::of(&write), Some(2), Some(3));
        assert!(matches!(second, Role::Answer { to: Some(_), .. }));
    }

    #[test]
    fn an_eight_byte_coil_frame_is_settled_by_the_pending_request() {
        let mut pairer = Pairer::default();
        let exception = [0x83, 0x02];
        pairer.read(17, &exception, Ways::of(&exception), None, None);
        // Read 10 coils at 0x0300: the bytes 01 03 00 00 0A also read as an answer with
        // 3 bytes of bits. After another frame, it is the master's next request.
        let request = [0x01, 0x03, 0x00, 0x00, 0x0A];
        let (role, _) = pairer.read(17, &request, Ways::of(&request), None, None);
        assert!(matches!(role, Role::Request));
        let answer = [0x01, 0x02, 0xFF, 0x03];
        let (role, _) = pairer.read(17, &answer, Ways::of(&answer), None, None);
        assert!(matches!(role, Role::Answer { to: Some(_), .. }));
    }

    #[test]
    fn an_answer_that_does_not_fit_the_request_awaiting_it_answers_it_and_says_how() {
        let mut pairer = Pairer::default();
        let read_two = [0x03, 0x00, 0x00, 0x00, 0x02];
        pairer.read(17, &read_two, Ways::of(&read_two), None, None);
        // Another function's answer is not its answer: it still waits.
        let coils = [0x01, 0x01, 0x05];
        let (role, _) = pairer.read(17, &coils, Ways::of(&coils), None, None);
        assert!(matches!(
            role,
            Role::Answer {
                to: None,
                mismatch: None,
                ..
            }
        ));
        // One register for two: its answer, which says so.
        let one_register = [0x03, 0x02, 0x00, 0x05];
        let (role, _) = pairer.read(17, &one_register, Ways::of(&one_register), None, None);
        let Role::Answer { to, mismatch, .. } = role else {
            panic!("{role:?}");
        };
        assert_eq!(to, None);
        assert_eq!(
            mismatch.map(|m| m.to_string()).as_deref(),
            Some("answer carries registers: 1, the request asked for 2")
        );
        // Answered: the next request reports none waiting.
        let (_, unanswered) = pairer.read(17, &read_two, Ways::of(&read_two), None, None);
        assert_eq!(unanswered, None);
    }

    #[test]
    fn a_request_after_an_unanswered_one_reports_it() {
        let mut pairer = Pairer::default();
        let read = [0x03, 0x00, 0x6B, 0x00, 0x03];
        pairer.read(17, &read, Ways::of(&read), Some(0), Some(4000));
        let (_, unanswered) = pairer.read(17, &read, Ways::of(&read), Some(104_000), Some(108_000));
        assert_eq!(unanswered.map(|u| u.waited), Some(Some(100_000)));
    }
}
