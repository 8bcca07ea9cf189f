//! Carrying out a plan: every request of a split read, the answers put back together; every
//! request of a write; and the tally of a poll.

use std::time::Duration;

use thiserror::Error;

use super::failover::Left;
use super::plan::{Plan, RegisterBits};
use super::{Master, MasterError, Reply};
use crate::codec::function;
use crate::codec::{ExceptionCode, FileRecords, Request, Response};
use crate::input::duration::show;
use crate::model::address::Table;
use crate::model::values::ReadData;

/// Why a request of a plan got no answer to use.
#[derive(Debug, Error)]
pub enum RunError {
    /// No answer, or no usable one.
    #[error(transparent)]
    Master(#[from] MasterError),
    /// The slave answered with an exception.
    #[error("slave {slave} answered exception {code} to function {function} ({})", function::name(*function))]
    Exception {
        /// The slave that answered.
        slave: u8,
        /// The function code of the request.
        function: u8,
        /// Why the slave refused.
        code: ExceptionCode,
    },
    /// A request that changes the device was sent and no answer told whether it was
    /// carried out.
    #[error("{error}; the request was sent {} and may have been carried out all the same", times(*.sent))]
    Unconfirmed {
        /// Why no answer was taken.
        error: MasterError,
        /// How many times it went on the wire.
        sent: u32,
    },
}

/// `once`, `2 times`.
pub fn times(n: u32) -> String {
    match n {
        1 => "once".to_string(),
        n => format!("{n} times"),
    }
}

/// A request that changes the device, sent more than once before an answer came: the
/// answers to the earlier tries were lost, and the device may have carried out each.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Resent {
    /// The slave asked.
    pub slave: u8,
    /// Its function code.
    pub function: u8,
    /// How many times it went on the wire.
    pub sent: u32,
}

/// What one read returned, all requests of a split read put together.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ReadResult {
    /// The slave read.
    pub slave: u8,
    /// The read function used (01-04).
    pub function: u8,
    /// The table read.
    pub table: Table,
    /// The first address read, 0-based.
    pub address: u16,
    /// The values, in address order.
    pub data: ReadData,
    /// For bits of registers: the first bit of the register at `address` that `data`'s
    /// bits start from.
    pub first_bit: Option<u8>,
}

impl ReadResult {
    /// The bits of registers a plan asked for, taken out of the registers read.
    fn into_register_bits(mut self, bits: RegisterBits) -> ReadResult {
        if let ReadData::Registers(registers) = &self.data {
            self.data = ReadData::Bits(register_bits(registers, bits.first, bits.count));
            self.first_bit = Some(bits.first);
        }
        self
    }
}

impl Master {
    /// What `slave` gave back to one request, told as it happened: a request that changes
    /// the device and got no answer is [`RunError::Unconfirmed`] (it may have been
    /// carried out), and one sent more than once before its answer is kept for
    /// [`Master::take_resent`].
    pub fn reply(&mut self, slave: u8, request: &Request) -> Result<Reply, RunError> {
        let (outcome, sent) = self.transact_counted(slave, request);
        let reply = match outcome {
            Err(error @ (MasterError::Timeout { .. } | MasterError::BadFrame { .. }))
                if sent > 0 && request.changes_device() && slave != 0 =>
            {
                return Err(RunError::Unconfirmed { error, sent });
            }
            outcome => outcome?,
        };
        if sent > 1 && request.changes_device() {
            self.resent.push(Resent {
                slave,
                function: request.function(),
                sent,
            });
        }
        Ok(reply)
    }

    /// The answer to one request of `slave`, an exception as an error; `None` for a
    /// broadcast.
    pub fn answer(&mut self, slave: u8, request: &Request) -> Result<Option<Response>, RunError> {
        match self.reply(slave, request)? {
            Reply::Response(response) => Ok(Some(response)),
            Reply::Broadcast => Ok(None),
            Reply::Exception(exception) => Err(RunError::Exception {
                slave,
                function: exception.function,
                code: exception.code,
            }),
        }
    }

    /// Every request of a read plan of `table` from `address`, the answers put together;
    /// for bits of registers, those bits.
    pub fn read(
        &mut self,
        plan: &Plan,
        table: Table,
        address: u16,
    ) -> Result<ReadResult, RunError> {
        let mut registers = Vec::new();
        let mut bits = Vec::new();
        for request in &plan.requests {
            let response = self.answer(plan.slave, request)?;
            let quantity = match request {
                Request::ReadCoils { quantity, .. }
                | Request::ReadDiscreteInputs { quantity, .. } => usize::from(*quantity),
                _ => 0,
            };
            match response {
                Some(
                    Response::ReadHoldingRegisters { values }
                    | Response::ReadInputRegisters { values }
                    | Response::ReadWriteMultipleRegisters { values },
                ) => registers.extend(values),
                Some(
                    response @ (Response::ReadCoils { .. } | Response::ReadDiscreteInputs { .. }),
                ) => bits.extend(response.bits(quantity).unwrap_or_default()),
                // The master checked that the answer fits the request.
                _ => {}
            }
        }
        let result = ReadResult {
            slave: plan.slave,
            function: plan.requests.first().map_or(0, Request::function),
            table,
            address,
            data: if table.is_bits() {
                ReadData::Bits(bits)
            } else {
                ReadData::Registers(registers)
            },
            first_bit: None,
        };
        Ok(match plan.bits {
            Some(bits) => result.into_register_bits(bits),
            None => result,
        })
    }

    /// Every request of a write plan. A mask write (22) the slave does not know
    /// (exception 01) is done as it would do it: the register read (03), the bits
    /// changed, the register written (06).
    pub fn write(&mut self, plan: &Plan) -> Result<Written, RunError> {
        let mut written = Written::default();
        for request in &plan.requests {
            match (self.answer(plan.slave, request), request) {
                (
                    Err(RunError::Exception { code, .. }),
                    &Request::MaskWriteRegister {
                        address,
                        and_mask,
                        or_mask,
                    },
                ) if code == ExceptionCode::ILLEGAL_FUNCTION => {
                    let read = Request::ReadHoldingRegisters {
                        address,
                        quantity: 1,
                    };
                    let current = match self.answer(plan.slave, &read)? {
                        Some(Response::ReadHoldingRegisters { values }) => {
                            values.first().copied().unwrap_or_default()
                        }
                        // The master checked that the answer fits the request.
                        _ => 0,
                    };
                    let value = (current & and_mask) | (or_mask & !and_mask);
                    self.answer(plan.slave, &Request::WriteSingleRegister { address, value })?;
                    written.mask_write_emulated = true;
                }
                (result, _) => {
                    result?;
                }
            }
            written.count += match request {
                Request::WriteMultipleCoils { values, .. } => values.len(),
                Request::WriteMultipleRegisters { values, .. } => values.len(),
                Request::WriteFileRecord { groups } => groups.iter().map(|g| g.values.len()).sum(),
                _ => 1,
            };
        }
        Ok(written)
    }

    /// Every request of a file record read plan: the records of each group asked, the
    /// groups a long run was cut into put back together.
    pub fn read_files(&mut self, plan: &Plan) -> Result<Vec<FileRecords>, RunError> {
        let mut read: Vec<FileRecords> = Vec::new();
        for request in &plan.requests {
            let (
                Request::ReadFileRecord { groups: asked },
                Some(Response::ReadFileRecord { groups }),
            ) = (request, self.answer(plan.slave, request)?)
            else {
                continue;
            };
            // The master checked that the answer holds a group for each asked.
            for (span, values) in asked.iter().zip(groups) {
                match read.last_mut() {
                    Some(last)
                        if last.file == span.file
                            && usize::from(last.record) + last.values.len()
                                == usize::from(span.record) =>
                    {
                        last.values.extend(values);
                    }
                    _ => read.push(FileRecords {
                        file: span.file,
                        record: span.record,
                        values,
                    }),
                }
            }
        }
        Ok(read)
    }

    /// The FIFO queue a plan's one request reads: its registers, oldest first.
    pub fn read_fifo(&mut self, plan: &Plan) -> Result<Vec<u16>, RunError> {
        let mut values = Vec::new();
        for request in &plan.requests {
            if let Some(Response::ReadFifoQueue { values: queue }) =
                self.answer(plan.slave, request)?
            {
                values = queue;
            }
        }
        Ok(values)
    }
}

/// What a write plan did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Written {
    /// How many coils or registers were written.
    pub count: usize,
    /// A mask write (22) was refused as unknown and done with 03 and 06 instead.
    pub mask_write_emulated: bool,
}

/// `count` bits of `registers` from bit `first` of the first, running on into the next
/// registers; bit 0 is the least significant.
pub fn register_bits(registers: &[u16], first: u8, count: u32) -> Vec<bool> {
    (0..count as usize)
        .map_while(|i| {
            let at = usize::from(first) + i;
            registers
                .get(at / 16)
                .map(|register| register >> (at % 16) & 1 == 1)
        })
        .collect()
}

/// What a poll saw, for the summary at its end.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct PollStats {
    /// Reads made, one per poll.
    pub requests: u64,
    /// Reads answered.
    pub answers: u64,
    /// Reads that got no answer in time, retries included.
    pub timeouts: u64,
    /// Reads answered only with wrong or garbled frames.
    pub bad_frames: u64,
    /// Reads answered with an exception.
    pub exceptions: u64,
    /// Reads that failed otherwise (the transport, say).
    pub other_errors: u64,
    /// Polls without a connection to read from (a failed attempt to connect, or the
    /// wait before the next one).
    pub disconnected: u64,
    /// Changes from one path to the other.
    pub switches: u64,
    fastest: Option<Duration>,
    slowest: Duration,
    total: Duration,
}

impl PollStats {
    /// Counts one read and how it ended; answered reads count toward the response times.
    pub fn record(&mut self, outcome: Result<(), &RunError>, elapsed: Duration) {
        self.requests += 1;
        match outcome {
            Ok(()) => {
                self.answers += 1;
                self.fastest = Some(self.fastest.map_or(elapsed, |f| f.min(elapsed)));
                self.slowest = self.slowest.max(elapsed);
                self.total += elapsed;
            }
            Err(RunError::Exception { .. }) => self.exceptions += 1,
            Err(RunError::Master(MasterError::Timeout { .. } | MasterError::OutOfStep { .. })) => {
                self.timeouts += 1;
            }
            Err(RunError::Master(MasterError::BadFrame { .. })) => self.bad_frames += 1,
            Err(_) => self.other_errors += 1,
        }
    }

    /// Counts how a request ended on the path it left, before it was asked again on the
    /// other: a failure as the poll's rows tell it, though the poll got its answer.
    pub fn record_left(&mut self, left: Left) {
        match left {
            Left::Timeout => self.timeouts += 1,
            Left::BadFrame => self.bad_frames += 1,
            Left::Exception => self.exceptions += 1,
            Left::Disconnected => self.other_errors += 1,
        }
    }

    /// One line: the counts, then min / mean / max response time.
    pub fn summary(&self) -> String {
        let count =
            |n: u64, one: &str, many: &str| format!("{n} {}", if n == 1 { one } else { many });
        let mut line = [
            count(self.requests, "request", "requests"),
            count(self.answers, "answer", "answers"),
            count(self.timeouts, "timeout", "timeouts"),
            count(self.bad_frames, "bad frame", "bad frames"),
            count(self.exceptions, "exception", "exceptions"),
        ]
        .join(", ");
        if self.other_errors > 0 {
            line.push_str(&format!(
                ", {}",
                count(self.other_errors, "other error", "other errors")
            ));
        }
        if self.disconnected > 0 {
            line.push_str(&format!(", {} polls while disconnected", self.disconnected));
        }
        if self.switches > 0 {
            line.push_str(&format!(
                ", {}",
                count(self.switches, "change of path", "changes of path")
            ));
        }
        if let Some(fastest) = self.fastest {
            let mean = self.total / u32::try_from(self.answers.max(1)).unwrap_or(u32::MAX);
            line.push_str(&format!(
                "; response time min {} / mean {} / max {}",
                show(fastest),
                show(mean),
                show(self.slowest)
            ));
        }
        line
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bits_run_on_into_the_next_register() {
        // 0x8000 has bit 15 set, 0x0001 bit 0.
        assert_eq!(
            register_bits(&[0x8000, 0x0001], 14, 4),
            [false, true, true, false]
        );
        assert_eq!(register_bits(&[0x022B], 0, 4), [true, true, false, true]);
    }
}
