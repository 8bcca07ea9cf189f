//! Whether an answer fits the request it answers: same function, as many values as asked,
//! the echo of a write. A master refuses an answer that does not fit; a sniffer pairs by it.

use thiserror::Error;

use super::pdu::{Pdu, Request, Response};

/// Why an answer does not fit the request it answers.
#[derive(Clone, Debug, Error, PartialEq, Eq)]
pub enum Mismatch {
    /// The answer is for another function than the request.
    #[error("answer is for function {answered:02X}, the request was {asked:02X}")]
    Function {
        /// The request's function code.
        asked: u8,
        /// The answer's function code, without the exception flag.
        answered: u8,
    },
    /// The answer carries more or fewer values than the request asked for.
    #[error("answer carries {what}: {answered}, the request asked for {asked}")]
    Count {
        /// What was counted: "registers", or "bytes of bits" for coils and discrete inputs.
        what: &'static str,
        /// How many the request asked for (for bits, the quantity over 8, rounded up).
        asked: usize,
        /// How many the answer carries.
        answered: usize,
    },
    /// The answer to a write does not echo the request; carries which fields differ.
    #[error("answer does not echo the write request ({0})")]
    Echo(&'static str),
}

/// Checks `answer` against `request`. An exception for the request's function fits.
pub(crate) fn check(request: &Request, answer: &Pdu) -> Result<(), Mismatch> {
    let asked = request.function();
    let answered = match answer {
        Pdu::Request(r) => r.function(),
        Pdu::Response(r) => r.function(),
        Pdu::Exception(e) => e.function,
    };
    if asked != answered {
        return Err(Mismatch::Function { asked, answered });
    }
    let Pdu::Response(response) = answer else {
        return Ok(());
    };
    let count = |what, asked: usize, answered: usize| {
        if asked == answered {
            Ok(())
        } else {
            Err(Mismatch::Count {
                what,
                asked,
                answered,
            })
        }
    };
    match (request, response) {
        (Request::ReadCoils { quantity, .. }, Response::ReadCoils { packed })
        | (Request::ReadDiscreteInputs { quantity, .. }, Response::ReadDiscreteInputs { packed }) => {
            count(
                "bytes of bits",
                usize::from(*quantity).div_ceil(8),
                packed.len(),
            )
        }
        (
            Request::ReadHoldingRegisters { quantity, .. },
            Response::ReadHoldingRegisters { values },
        )
        | (Request::ReadInputRegisters { quantity, .. }, Response::ReadInputRegisters { values })
        | (
            Request::ReadWriteMultipleRegisters {
                read_quantity: quantity,
                ..
            },
            Response::ReadWriteMultipleRegisters { values },
        ) => count("registers", usize::from(*quantity), values.len()),
        (
            Request::WriteSingleCoil { address, value },
            Response::WriteSingleCoil {
                address: a,
                value: v,
            },
        ) => echo(address == a && value == v, "address or value differs"),
        (
            Request::WriteSingleRegister { address, value },
            Response::WriteSingleRegister {
                address: a,
                value: v,
            },
        ) => echo(address == a && value == v, "address or value differs"),
        (
            Request::WriteMultipleCoils { address, values },
            Response::WriteMultipleCoils {
                address: a,
                quantity,
            },
        ) => echo(
            *address == *a && values.len() == usize::from(*quantity),
            "address or quantity differs",
        ),
        (
            Request::WriteMultipleRegisters { address, values },
            Response::WriteMultipleRegisters {
                address: a,
                quantity,
            },
        ) => echo(
            *address == *a && values.len() == usize::from(*quantity),
            "address or quantity differs",
        ),
        (
            Request::MaskWriteRegister {
                address,
                and_mask,
                or_mask,
            },
            Response::MaskWriteRegister {
                address: a,
                and_mask: and,
                or_mask: or,
            },
        ) => echo(
            address == a && and_mask == and && or_mask == or,
            "address or masks differ",
        ),
        (Request::ReadFileRecord { groups }, Response::ReadFileRecord { groups: answered }) => {
            count("groups of records", groups.len(), answered.len())?;
            for (asked, values) in groups.iter().zip(answered) {
                count("records", usize::from(asked.count), values.len())?;
            }
            Ok(())
        }
        (Request::WriteFileRecord { groups }, Response::WriteFileRecord { groups: echoed }) => {
            echo(groups == echoed, "the file records differ")
        }
        // Return Query Data (00) echoes the query's data; the others answer with their own.
        (
            Request::Diagnostics {
                sub_function: 0,
                data,
            },
            Response::Diagnostics {
                sub_function: s,
                data: d,
            },
        ) => echo(*s == 0 && data == d, "the echo differs from the query"),
        (
            Request::Diagnostics { sub_function, .. },
            Response::Diagnostics {
                sub_function: s, ..
            },
        ) => echo(sub_function == s, "sub-function differs"),
        _ => Ok(()),
    }
}

fn echo(same: bool, what: &'static str) -> Result<(), Mismatch> {
    if same {
        Ok(())
    } else {
        Err(Mismatch::Echo(what))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::codec::{Exception, ExceptionCode};

    #[test]
    fn a_coil_answer_with_fewer_bytes_than_asked_is_refused() {
        let request = Request::ReadCoils {
            address: 19,
            quantity: 37,
        };
        let short = Pdu::Response(Response::ReadCoils {
            packed: vec![0xCD, 0x6B, 0xB2, 0x0E],
        });
        assert_eq!(
            check(&request, &short),
            Err(Mismatch::Count {
                what: "bytes of bits",
                asked: 5,
                answered: 4
            })
        );
        let whole = Pdu::Response(Response::ReadCoils {
            packed: vec![0xCD, 0x6B, 0xB2, 0x0E, 0x1B],
        });
        assert_eq!(check(&request, &whole), Ok(()));
    }

    #[test]
    fn an_answer_for_another_function_is_refused() {
        let request = Request::ReadHoldingRegisters {
            address: 107,
            quantity: 3,
        };
        let answer = Pdu::Response(Response::ReadInputRegisters {
            values: vec![1, 2, 3],
        });
        assert_eq!(
            check(&request, &answer),
            Err(Mismatch::Function {
                asked: 3,
                answered: 4
            })
        );
    }

    #[test]
    fn fewer_registers_than_asked_is_refused_and_an_exception_fits() {
        let request = Request::ReadHoldingRegisters {
            address: 107,
            quantity: 3,
        };
        let answer = Pdu::Response(Response::ReadHoldingRegisters {
            values: vec![555, 0],
        });
        assert!(check(&request, &answer).is_err());
        let exception = Pdu::Exception(Exception {
            function: 3,
            code: ExceptionCode(2),
        });
        assert_eq!(check(&request, &exception), Ok(()));
    }

    #[test]
    fn a_write_echo_that_differs_is_refused() {
        let request = Request::WriteSingleRegister {
            address: 1,
            value: 3,
        };
        let answer = Pdu::Response(Response::WriteSingleRegister {
            address: 1,
            value: 4,
        });
        assert!(matches!(check(&request, &answer), Err(Mismatch::Echo(_))));
    }
}
