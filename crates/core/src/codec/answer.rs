//! Whether an answer fits the request it answers: same function, as many values as asked,
//! the echo of a write. A master refuses an answer that does not fit; a sniffer pairs by it.

use thiserror::Error;

use super::function::*;
use super::pdu::file;

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

/// Checks the answer `answer` against the request `request`, both PDUs as they travel
/// (function code first), each read sound in its direction. An exception for the
/// request's function fits. Where either does not read, only [`check_function`] holds.
pub(crate) fn check(request: &[u8], answer: &[u8]) -> Result<(), Mismatch> {
    check_function(request, answer)?;
    if answer.first().is_some_and(|f| f & EXCEPTION_FLAG != 0) {
        return Ok(());
    }
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
    // The fields a check compares sit at the same place in both: a write's answer echoes
    // its address and quantity (or value, or masks), and a read's answer counts its bytes
    // right after the function.
    let echoes = |fields: std::ops::Range<usize>| request.get(fields.clone()) == answer.get(fields);
    let echoes_all = request.get(1..) == answer.get(1..);
    let asked_quantity = usize::from(word_at(request, 3));
    let byte_count = usize::from(answer.get(1).copied().unwrap_or_default());
    match request.first().copied().unwrap_or_default() {
        READ_COILS | READ_DISCRETE_INPUTS => {
            count("bytes of bits", asked_quantity.div_ceil(8), byte_count)
        }
        READ_HOLDING_REGISTERS | READ_INPUT_REGISTERS | READ_WRITE_MULTIPLE_REGISTERS => {
            count("registers", asked_quantity, byte_count / 2)
        }
        WRITE_SINGLE_COIL | WRITE_SINGLE_REGISTER => echo(echoes(1..5), "address or value differs"),
        WRITE_MULTIPLE_COILS | WRITE_MULTIPLE_REGISTERS => {
            echo(echoes(1..5), "address or quantity differs")
        }
        MASK_WRITE_REGISTER => echo(echoes(1..7), "address or masks differ"),
        READ_FILE_RECORD => {
            let asked = file::counts_asked(request);
            let answered = file::counts_answered(answer);
            count(
                "groups of records",
                asked.clone().count(),
                answered.clone().count(),
            )?;
            for (asked, answered) in asked.zip(answered) {
                count("records", usize::from(asked), answered)?;
            }
            Ok(())
        }
        WRITE_FILE_RECORD => echo(echoes_all, "the file records differ"),
        // Return Query Data (00) echoes the query's data; the others answer with their own.
        DIAGNOSTICS if word_at(request, 1) == 0 => {
            echo(echoes_all, "the echo differs from the query")
        }
        DIAGNOSTICS => echo(echoes(1..3), "sub-function differs"),
        _ => Ok(()),
    }
}

/// Checks that `answer` is for the function of `request`, both PDUs as they travel: all
/// that can be checked where either does not read.
pub(crate) fn check_function(request: &[u8], answer: &[u8]) -> Result<(), Mismatch> {
    let asked = request.first().copied().unwrap_or_default();
    let answered = answer.first().copied().unwrap_or_default() & !EXCEPTION_FLAG;
    if asked == answered {
        Ok(())
    } else {
        Err(Mismatch::Function { asked, answered })
    }
}

/// The big-endian word at `at`, 0 where the PDU is too short (it does not read then).
fn word_at(pdu: &[u8], at: usize) -> u16 {
    pdu.get(at..at + 2)
        .map_or(0, |word| u16::from_be_bytes([word[0], word[1]]))
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
    use crate::codec::{Exception, ExceptionCode, FileSpan, Pdu, Request, Response};

    /// `request` and `answer` as they travel, checked.
    fn checked(request: Request, answer: Pdu) -> Result<(), Mismatch> {
        let (mut asked, mut answered) = (Vec::new(), Vec::new());
        Pdu::Request(request).encode(&mut asked).unwrap();
        answer.encode(&mut answered).unwrap();
        check(&asked, &answered)
    }

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
            checked(request.clone(), short.clone()),
            Err(Mismatch::Count {
                what: "bytes of bits",
                asked: 5,
                answered: 4
            })
        );
        let whole = Pdu::Response(Response::ReadCoils {
            packed: vec![0xCD, 0x6B, 0xB2, 0x0E, 0x1B],
        });
        assert_eq!(checked(request.clone(), whole.clone()), Ok(()));
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
            checked(request.clone(), answer.clone()),
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
        assert!(checked(request.clone(), answer.clone()).is_err());
        let exception = Pdu::Exception(Exception {
            function: 3,
            code: ExceptionCode(2),
        });
        assert_eq!(checked(request.clone(), exception.clone()), Ok(()));
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
        assert!(matches!(
            checked(request.clone(), answer.clone()),
            Err(Mismatch::Echo(_))
        ));
    }

    #[test]
    fn a_file_record_answer_is_held_to_the_groups_and_records_asked() {
        let span = |file, count| FileSpan {
            file,
            record: 7,
            count,
        };
        let request = Request::ReadFileRecord {
            groups: vec![span(1, 2), span(4, 1)],
        };
        let answer = |groups: Vec<Vec<u16>>| Pdu::Response(Response::ReadFileRecord { groups });
        assert_eq!(
            checked(request.clone(), answer(vec![vec![1, 2], vec![3]])),
            Ok(())
        );
        assert_eq!(
            checked(request.clone(), answer(vec![vec![1, 2]])),
            Err(Mismatch::Count {
                what: "groups of records",
                asked: 2,
                answered: 1
            })
        );
        assert_eq!(
            checked(request, answer(vec![vec![1, 2], vec![3, 4]])),
            Err(Mismatch::Count {
                what: "records",
                asked: 1,
                answered: 2
            })
        );
    }

    #[test]
    fn echoes_are_held_to_every_field_they_repeat() {
        let write = Request::WriteMultipleRegisters {
            address: 9,
            values: vec![1, 2],
        };
        let echo = |address, quantity| {
            Pdu::Response(Response::WriteMultipleRegisters { address, quantity })
        };
        assert_eq!(checked(write.clone(), echo(9, 2)), Ok(()));
        assert!(matches!(checked(write, echo(9, 3)), Err(Mismatch::Echo(_))));
        let query = |data: Vec<u8>| Request::Diagnostics {
            sub_function: 0,
            data,
        };
        let answer =
            |sub_function, data| Pdu::Response(Response::Diagnostics { sub_function, data });
        assert_eq!(checked(query(vec![1, 2]), answer(0, vec![1, 2])), Ok(()));
        assert!(checked(query(vec![1, 2]), answer(0, vec![1, 2, 3])).is_err());
        assert!(checked(query(vec![1, 2]), answer(1, vec![1, 2])).is_err());
    }

    #[test]
    fn where_either_does_not_read_only_the_function_is_held() {
        // Quantity 0 breaks the request's layout: its exception, or any 03 answer, is
        // its answer; a 04 answer is not.
        let malformed = [0x03, 0x00, 0x00, 0x00, 0x00];
        assert_eq!(check_function(&malformed, &[0x83, 0x03]), Ok(()));
        assert_eq!(
            check_function(&malformed, &[0x03, 0x02, 0x00, 0x01]),
            Ok(())
        );
        assert!(check_function(&malformed, &[0x04, 0x02, 0x00, 0x01]).is_err());
        // Nor does an empty PDU panic.
        assert!(check(&[], &[]).is_ok());
    }
}
