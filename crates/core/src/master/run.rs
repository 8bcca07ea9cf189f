//! Carrying out a plan: every request of a split read, the answers put back together; every
//! request of a write; and the tally of a poll.

use std::time::Duration;

use thiserror::Error;

use super::plan::Plan;
use super::{Master, MasterError, Reply};
use crate::codec::function;
use crate::codec::{ExceptionCode, Request, Response};
use crate::model::address::Table;
use crate::model::duration::show;

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
}

/// The coils or registers a read returned.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ReadData {
    /// Register values, as received.
    Registers(Vec<u16>),
    /// Coil or discrete input states, exactly as many as asked for.
    Bits(Vec<bool>),
}

impl ReadData {
    /// How many coils or registers were read.
    pub fn len(&self) -> usize {
        match self {
            ReadData::Registers(registers) => registers.len(),
            ReadData::Bits(bits) => bits.len(),
        }
    }

    /// Nothing was read.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

impl Master {
    /// The answer to one request of `slave`, an exception as an error; `None` for a
    /// broadcast.
    pub fn answer(&mut self, slave: u8, request: &Request) -> Result<Option<Response>, RunError> {
        match self.transact(slave, request)? {
            Reply::Response(response) => Ok(Some(response)),
            Reply::Broadcast => Ok(None),
            Reply::Exception(exception) => Err(RunError::Exception {
                slave,
                function: exception.function,
                code: exception.code,
            }),
        }
    }

    /// Every request of a read plan of `table` from `address`, the answers put together.
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
                    | Response::ReadInputRegisters { values },
                ) => registers.extend(values),
                Some(
                    response @ (Response::ReadCoils { .. } | Response::ReadDiscreteInputs { .. }),
                ) => bits.extend(response.bits(quantity).unwrap_or_default()),
                // The master checked that the answer fits the request.
                _ => {}
            }
        }
        Ok(ReadResult {
            slave: plan.slave,
            function: plan.requests.first().map_or(0, Request::function),
            table,
            address,
            data: if table.is_bits() {
                ReadData::Bits(bits)
            } else {
                ReadData::Registers(registers)
            },
        })
    }

    /// Every request of a write plan; how many coils or registers were written.
    pub fn write(&mut self, plan: &Plan) -> Result<usize, RunError> {
        let mut count = 0;
        for request in &plan.requests {
            self.answer(plan.slave, request)?;
            count += match request {
                Request::WriteMultipleCoils { values, .. } => values.len(),
                Request::WriteMultipleRegisters { values, .. } => values.len(),
                _ => 1,
            };
        }
        Ok(count)
    }
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
            Err(RunError::Master(MasterError::Timeout { .. })) => self.timeouts += 1,
            Err(RunError::Master(MasterError::BadFrame { .. })) => self.bad_frames += 1,
            Err(_) => self.other_errors += 1,
        }
    }

    /// One line: the counts, then min / mean / max response time.
    pub fn summary(&self) -> String {
        let mut line = format!(
            "{} requests, {} answers, {} timeouts, {} bad frames, {} exceptions",
            self.requests, self.answers, self.timeouts, self.bad_frames, self.exceptions
        );
        if self.other_errors > 0 {
            line.push_str(&format!(", {} other errors", self.other_errors));
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
