//! A line without transaction ids (RTU, ASCII) kept in step. An answer that comes after
//! its request's timeout passes every check RTU allows for the next request of the same
//! function to the same slave; so the answers still owed are remembered, paid off when
//! heard, and while one is owed such a request goes only after a diagnostic echo (08/00)
//! with a fresh value has come back: a slave answers in order, so nothing late of its can
//! follow that. A slave that has never answered a check (one that ignores 08, or one
//! frozen since) is taken back in step once nothing has come from it for
//! [`SILENCE_SETTLES`]: one that ignores 08 is not lost for good to one lost answer.

use std::time::{Duration, Instant};

use super::{Master, MasterError, Reply};
use crate::codec::{Mode, Pdu, Request};

/// How long the line must be silent before a check is sent: longer than a USB adapter's
/// 16 ms latency timer, so that an answer being received is not talked over.
const QUIET_BEFORE_CHECK: Duration = Duration::from_millis(20);

/// The most answers remembered as owed by one slave to one function: a dead slave asked
/// for ever adds none past them, and one check settles them all.
const MOST_OWED: usize = 8;

/// How long a slave that has never answered a check must have owed an answer, nothing of
/// it heard, before it is taken back in step without one: a late answer later than that
/// would be from a slave frozen that long, which no master can tell from one that ignores
/// the check.
const SILENCE_SETTLES: Duration = Duration::from_secs(5);

/// The answers owed, one entry each, by slave and function; since when each slave has
/// owed, and the slaves that have answered a check.
#[derive(Debug, Default)]
pub(super) struct Owed {
    owed: Vec<(u8, u8)>,
    since: Vec<(u8, Instant)>,
    answer_checks: Vec<u8>,
}

impl Owed {
    fn owes(&self, slave: u8, function: u8) -> bool {
        self.owed.contains(&(slave, function))
    }

    fn owe(&mut self, slave: u8, function: u8) {
        let owed = self
            .owed
            .iter()
            .filter(|&&o| o == (slave, function))
            .count();
        if owed < MOST_OWED {
            self.owed.push((slave, function));
        }
        if !self.since.iter().any(|&(s, _)| s == slave) {
            self.since.push((slave, Instant::now()));
        }
    }

    /// Nothing more is owed by `slave`: it answered a request sent after all the others.
    fn settle(&mut self, slave: u8) {
        self.owed.retain(|&(s, _)| s != slave);
        self.since.retain(|&(s, _)| s != slave);
    }

    /// `slave` answered a check: from now on only a check brings it back in step.
    fn answered_check(&mut self, slave: u8) {
        if !self.answer_checks.contains(&slave) {
            self.answer_checks.push(slave);
        }
        self.settle(slave);
    }

    /// Whether `slave`, which has never answered a check, has owed long enough for its
    /// silence to settle it.
    fn settled_by_silence(&self, slave: u8) -> bool {
        !self.answer_checks.contains(&slave)
            && self
                .since
                .iter()
                .any(|&(s, since)| s == slave && since.elapsed() >= SILENCE_SETTLES)
    }

    /// An answer heard that was not the one awaited: a late one, if one was owed; whether
    /// it was.
    pub(super) fn pay_off(&mut self, slave: u8, pdu: &Pdu) -> bool {
        let function = match pdu {
            Pdu::Request(_) => return false,
            Pdu::Response(response) => response.function(),
            Pdu::Exception(exception) => exception.function,
        };
        match self.owed.iter().position(|&owed| owed == (slave, function)) {
            Some(at) => {
                self.owed.swap_remove(at);
                if !self.owed.iter().any(|&(s, _)| s == slave) {
                    self.since.retain(|&(s, _)| s != slave);
                }
                true
            }
            None => false,
        }
    }
}

/// The tries of one request so far.
#[derive(Default)]
pub(super) struct Tries {
    /// How many times it went on the wire.
    pub(super) sent: u32,
    /// A try ended without its answer, which may still come.
    pub(super) pending: bool,
}

/// Whether a try that failed so may still be answered: no answer came, or a frame that
/// was not its answer came first (a late answer to an earlier request). A garbled or cut
/// answer was the answer, spoilt: nothing more follows it.
fn may_be_answered_late(error: &MasterError) -> bool {
    use super::BadAnswer;
    match error {
        MasterError::Timeout { .. } | MasterError::Interrupted => true,
        MasterError::BadFrame { reason, .. } => matches!(
            reason,
            BadAnswer::Mismatch(_) | BadAnswer::OtherSlave(_) | BadAnswer::Request
        ),
        MasterError::OutOfStep { .. } | MasterError::Encode(_) | MasterError::Io(_) => false,
    }
}

impl Master {
    /// One try: the request sent, once the slave is in step, and its answer awaited.
    pub(super) fn attempt(
        &mut self,
        slave: u8,
        request: &Request,
        tries: &mut Tries,
    ) -> Result<Reply, MasterError> {
        let function = request.function();
        // A retry needs no check: a late answer to an earlier try of this very request
        // is its answer.
        if tries.sent == 0 && self.owed.owes(slave, function) {
            // An answer on its way now is heard out (and its debt paid) rather than sent
            // over; the check goes only if a late answer could still come.
            let quiet = QUIET_BEFORE_CHECK.max(self.options.silence);
            self.wait_quiet(quiet, self.options.timeout.max(quiet))?;
            if self.owed.settled_by_silence(slave) {
                self.owed.settle(slave);
            }
            if self.owed.owes(slave, function) {
                self.bring_in_step(slave, function)?;
            }
        }
        tries.sent += 1;
        let reply = self.exchange(slave, request);
        if self.is_broadcast(slave) || self.options.mode == Mode::Tcp {
            return reply;
        }
        match &reply {
            // An answer that may be an earlier try's leaves the later tries' to come.
            Ok(_) if tries.pending => {}
            Ok(_) => self.owed.settle(slave),
            Err(error) if may_be_answered_late(error) => {
                tries.pending = true;
                self.owed.owe(slave, function);
            }
            Err(_) => {}
        }
        reply
    }

    /// Brings `slave` back in step before a request of `function`: a diagnostic echo
    /// (08/00) carrying fresh data, whose answer only it can be; the exception 88 of a
    /// slave that does not do diagnostics is as good.
    fn bring_in_step(&mut self, slave: u8, function: u8) -> Result<(), MasterError> {
        let check = Request::Diagnostics {
            sub_function: 0,
            data: fastrand::u16(..).to_be_bytes().to_vec(),
        };
        match self.exchange(slave, &check) {
            Ok(_) => {
                self.owed.answered_check(slave);
                Ok(())
            }
            // A slave silent to the check too is told as any silent slave: no answer.
            Err(
                error @ (MasterError::Io(_)
                | MasterError::Encode(_)
                | MasterError::Interrupted
                | MasterError::Timeout { .. }),
            ) => {
                if matches!(error, MasterError::Timeout { .. }) {
                    self.owed.owe(slave, check.function());
                }
                Err(error)
            }
            Err(error) => {
                self.owed.owe(slave, check.function());
                Err(MasterError::OutOfStep {
                    slave,
                    function,
                    why: error.to_string(),
                })
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::codec::{Exception, ExceptionCode, Response};

    fn answer(function: u8) -> Pdu {
        match function {
            3 => Pdu::Response(Response::ReadHoldingRegisters { values: vec![1] }),
            _ => Pdu::Exception(Exception {
                function,
                code: ExceptionCode::ILLEGAL_FUNCTION,
            }),
        }
    }

    #[test]
    fn each_answer_heard_pays_one_debt_of_its_slave_and_function() {
        let mut owed = Owed::default();
        owed.owe(17, 3);
        owed.owe(17, 3);
        owed.owe(18, 3);
        // Another slave's answer, another function's, and a request pay nothing.
        owed.pay_off(19, &answer(3));
        owed.pay_off(17, &answer(6));
        owed.pay_off(
            17,
            &Pdu::Request(Request::ReadHoldingRegisters {
                address: 0,
                quantity: 1,
            }),
        );
        owed.pay_off(17, &answer(3));
        assert!(owed.owes(17, 3));
        owed.pay_off(17, &answer(3));
        assert!(!owed.owes(17, 3));
        assert!(owed.owes(18, 3));
        // An exception to the function is its answer too.
        owed.owe(18, 8);
        owed.pay_off(18, &answer(8));
        assert!(!owed.owes(18, 8));
        owed.settle(18);
        assert!(!owed.owes(18, 3));
    }

    #[test]
    fn silence_settles_only_a_slave_that_never_answered_a_check() {
        let mut owed = Owed::default();
        owed.owe(17, 3);
        owed.owe(18, 3);
        owed.answered_check(18);
        owed.owe(18, 3);
        let long_ago = Instant::now() - SILENCE_SETTLES;
        for since in &mut owed.since {
            since.1 = long_ago;
        }
        assert!(owed.settled_by_silence(17));
        assert!(!owed.settled_by_silence(18));
        // A debt paid off ends the wait; a new one starts it again.
        owed.pay_off(17, &answer(3));
        owed.owe(17, 3);
        assert!(!owed.settled_by_silence(17));
    }

    #[test]
    fn a_dead_slave_asked_for_ever_owes_a_bounded_number() {
        let mut owed = Owed::default();
        for _ in 0..10_000 {
            owed.owe(5, 3);
        }
        assert_eq!(owed.owed.len(), MOST_OWED);
        owed.settle(5);
        assert!(owed.owed.is_empty() && owed.since.is_empty());
    }
}
