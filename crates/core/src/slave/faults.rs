//! FaultInjection a simulated slave can be told to make, for testing masters: late, missing,
//! corrupt or noisy answers, and exceptions on chosen addresses.

use std::time::Duration;

use crate::codec::{ExceptionCode, Request};
use crate::input::number::parse_int;
use crate::model::address::{parse_reference_span, Table};

/// An exception to answer instead of the data, for every request or for those that touch
/// a range.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InjectedException {
    /// The exception code answered.
    pub code: ExceptionCode,
    /// `None`: every request. Otherwise the table and the addresses `[start, end)`.
    pub range: Option<(Table, u32, u32)>,
}

impl InjectedException {
    /// `CODE` or `CODE@RANGE`: `4`, `2@400100-400120`, `0x0B@000001`.
    pub fn parse(text: &str) -> Result<Self, String> {
        let (code, range) = match text.split_once('@') {
            Some((code, range)) => (code, Some(range)),
            None => (text, None),
        };
        let code = parse_int(code)
            .ok()
            .and_then(|c| u8::try_from(c).ok())
            .filter(|c| *c > 0)
            .ok_or_else(|| {
                format!("--exception {text}: the code is 1-255, as in 2 or 2@400100-400120")
            })?;
        let range = match range {
            None => None,
            Some(range) => {
                let span =
                    parse_reference_span(range).map_err(|e| format!("--exception {text}: {e}"))?;
                let start = u32::from(span.address);
                Some((span.table, start, start + span.count.unwrap_or(1)))
            }
        };
        Ok(Self {
            code: ExceptionCode(code),
            range,
        })
    }

    fn applies_to(&self, request: &Request) -> bool {
        match self.range {
            None => true,
            Some((table, start, end)) => touched(request)
                .iter()
                .any(|(t, s, e)| *t == table && *s < end && start < *e),
        }
    }
}

/// The addresses a request reads or writes, per table.
fn touched(request: &Request) -> Vec<(Table, u32, u32)> {
    let run = |table, address: &u16, count: usize| {
        let start = u32::from(*address);
        (table, start, start + count as u32)
    };
    match request {
        Request::ReadCoils { address, quantity } => {
            vec![run(Table::Coils, address, usize::from(*quantity))]
        }
        Request::ReadDiscreteInputs { address, quantity } => {
            vec![run(Table::DiscreteInputs, address, usize::from(*quantity))]
        }
        Request::ReadHoldingRegisters { address, quantity } => {
            vec![run(
                Table::HoldingRegisters,
                address,
                usize::from(*quantity),
            )]
        }
        Request::ReadInputRegisters { address, quantity } => {
            vec![run(Table::InputRegisters, address, usize::from(*quantity))]
        }
        Request::WriteSingleCoil { address, .. } => vec![run(Table::Coils, address, 1)],
        Request::WriteMultipleCoils { address, values } => {
            vec![run(Table::Coils, address, values.len())]
        }
        Request::WriteSingleRegister { address, .. }
        | Request::MaskWriteRegister { address, .. } => {
            vec![run(Table::HoldingRegisters, address, 1)]
        }
        Request::WriteMultipleRegisters { address, values } => {
            vec![run(Table::HoldingRegisters, address, values.len())]
        }
        Request::ReadWriteMultipleRegisters {
            read_address,
            read_quantity,
            write_address,
            values,
        } => vec![
            run(
                Table::HoldingRegisters,
                read_address,
                usize::from(*read_quantity),
            ),
            run(Table::HoldingRegisters, write_address, values.len()),
        ],
        _ => Vec::new(),
    }
}

/// Every fault the slave is told to make.
#[derive(Clone, Debug, Default)]
pub struct FaultInjection {
    /// Wait this long before each answer.
    pub delay: Duration,
    /// Share of requests left unanswered, 0 to 1.
    pub drop: f64,
    /// Share of answers corrupted on the wire, 0 to 1.
    pub corrupt: f64,
    /// Exceptions to answer instead of the data; the first that applies wins.
    pub exceptions: Vec<InjectedException>,
    /// Noise bytes before each answer.
    pub garbage: bool,
}

impl FaultInjection {
    /// The exception to give instead of an answer, if one is injected for this request.
    pub fn exception_for(&self, request: &Request) -> Option<ExceptionCode> {
        self.exceptions
            .iter()
            .find(|e| e.applies_to(request))
            .map(|e| e.code)
    }

    /// Corrupts an answer so that a master must refuse it: on a serial line a flipped bit
    /// (the checksum fails); over TCP, whose frames carry no checksum, a function code
    /// that is not the request's.
    pub fn corrupt(answer: &mut [u8], tcp: bool, rng: &mut fastrand::Rng) {
        if tcp {
            if let Some(function) = answer.get_mut(7) {
                *function ^= 0x01;
            }
        } else if !answer.is_empty() {
            let at = rng.usize(..answer.len());
            answer[at] ^= 1 << rng.u8(..8);
        }
    }

    /// Noise as a bus hands it over: a few bytes of 00 and FE.
    pub fn noise(rng: &mut fastrand::Rng) -> Vec<u8> {
        (0..rng.usize(1..=3))
            .map(|_| if rng.bool() { 0x00 } else { 0xFE })
            .collect()
    }
}

/// A share given on the command line: 0 to 1, or a percentage (`5%`).
pub fn parse_rate(text: &str) -> Result<f64, String> {
    let (number, scale) = match text.strip_suffix('%') {
        Some(number) => (number, 100.0),
        None => (text, 1.0),
    };
    number
        .trim()
        .parse::<f64>()
        .ok()
        .map(|v| v / scale)
        .filter(|v| (0.0..=1.0).contains(v))
        .ok_or_else(|| format!("'{text}' is not a rate: give 0 to 1, or a percentage such as 5%"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exceptions_apply_to_the_requests_that_touch_their_range() {
        let injected = InjectedException::parse("2@400100-400120").unwrap();
        let inside = Request::ReadHoldingRegisters {
            address: 110,
            quantity: 1,
        };
        let overlapping = Request::ReadHoldingRegisters {
            address: 90,
            quantity: 20,
        };
        let outside = Request::ReadHoldingRegisters {
            address: 0,
            quantity: 10,
        };
        let other_table = Request::ReadInputRegisters {
            address: 110,
            quantity: 1,
        };
        assert!(injected.applies_to(&inside));
        assert!(injected.applies_to(&overlapping));
        assert!(!injected.applies_to(&outside));
        assert!(!injected.applies_to(&other_table));
        assert!(InjectedException::parse("4").unwrap().applies_to(&outside));
        assert!(InjectedException::parse("0").is_err());
        assert!(InjectedException::parse("2@x").is_err());
    }

    #[test]
    fn rates() {
        assert_eq!(parse_rate("0.25"), Ok(0.25));
        assert_eq!(parse_rate("5%"), Ok(0.05));
        assert!(parse_rate("2").is_err());
    }
}
