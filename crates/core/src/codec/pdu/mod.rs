//! Protocol data units as types: what a request asks, what a response answers.
//!
//! `encode` checks the protocol limits before writing a byte; `decode` checks them again, so
//! a frame from the wire that breaks them is reported, never trusted.

use super::error::PduError;
use super::exception::ExceptionCode;
use super::function::*;

pub mod file;
mod identification;
mod request;
mod response;
mod wire;

pub use super::direction::Direction;
pub use file::{FileRecords, FileSpan};
pub use identification::{DeviceIdentification, DeviceObject};
pub(crate) use request::{diagnostic_only_reads, function_only_reads};
pub(crate) use wire::Values;

/// A request as a master sends it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Request {
    /// Function 1: read coils.
    ReadCoils {
        /// First coil address, 0-based as on the wire.
        address: u16,
        /// How many coils, 1-2000.
        quantity: u16,
    },
    /// Function 2: read discrete inputs.
    ReadDiscreteInputs {
        /// First input address, 0-based as on the wire.
        address: u16,
        /// How many inputs, 1-2000.
        quantity: u16,
    },
    /// Function 3: read holding registers.
    ReadHoldingRegisters {
        /// First register address, 0-based as on the wire.
        address: u16,
        /// How many registers, 1-125.
        quantity: u16,
    },
    /// Function 4: read input registers.
    ReadInputRegisters {
        /// First register address, 0-based as on the wire.
        address: u16,
        /// How many registers, 1-125.
        quantity: u16,
    },
    /// Function 5: set one coil.
    WriteSingleCoil {
        /// Coil address, 0-based as on the wire.
        address: u16,
        /// On (sent as FF00) or off (0000).
        value: bool,
    },
    /// Function 6: write one holding register.
    WriteSingleRegister {
        /// Register address, 0-based as on the wire.
        address: u16,
        /// The value to write.
        value: u16,
    },
    /// Function 7: read the eight exception status outputs (serial lines).
    ReadExceptionStatus,
    /// Function 8: a serial-line diagnostic, picked by its sub-function.
    Diagnostics {
        /// Which test or counter: 0000 returns the query data, for one.
        sub_function: u16,
        /// The data after the sub-function, byte for byte; its meaning depends on the sub-function.
        data: Vec<u8>,
    },
    /// Function 15: write consecutive coils.
    WriteMultipleCoils {
        /// First coil address, 0-based as on the wire.
        address: u16,
        /// The coil states, first address first; the quantity is their count, 1-1968.
        values: Vec<bool>,
    },
    /// Function 16: write consecutive holding registers.
    WriteMultipleRegisters {
        /// First register address, 0-based as on the wire.
        address: u16,
        /// The register values, first address first; the quantity is their count, 1-123.
        values: Vec<u16>,
    },
    /// Function 17: ask a serial-line device for its server ID and run status.
    ReportServerId,
    /// Function 20: read records of files, one group a file and run of records.
    ReadFileRecord {
        /// The runs of records asked, in order; the answer holds a group for each.
        groups: Vec<FileSpan>,
    },
    /// Function 21: write records of files.
    WriteFileRecord {
        /// The runs of records and their values, in order.
        groups: Vec<FileRecords>,
    },
    /// Function 22: change bits of one holding register. The register becomes
    /// (current AND `and_mask`) OR (`or_mask` AND NOT `and_mask`).
    MaskWriteRegister {
        /// Register address, 0-based as on the wire.
        address: u16,
        /// Bits set here keep their current value.
        and_mask: u16,
        /// Bits to set among those the AND mask clears.
        or_mask: u16,
    },
    /// Function 23: write holding registers, then read holding registers, in one transaction.
    ReadWriteMultipleRegisters {
        /// First register to read, 0-based as on the wire.
        read_address: u16,
        /// How many registers to read, 1-125.
        read_quantity: u16,
        /// First register to write, 0-based as on the wire; the write comes before the read.
        write_address: u16,
        /// The values to write, first address first; 1-121 of them.
        values: Vec<u16>,
    },
    /// Function 24: read a FIFO queue: its count and up to 31 registers.
    ReadFifoQueue {
        /// The FIFO pointer address, 0-based as on the wire.
        address: u16,
    },
    /// Function 43, MEI type 14: read device identification objects.
    ReadDeviceIdentification {
        /// Read device ID code: 01 basic, 02 regular, 03 extended (streamed), 04 one object.
        read_code: u8,
        /// The object to start from (00 for the first), or with code 04 the one object to read.
        object_id: u8,
    },
    /// Any function code without a layout of its own: kept byte for byte.
    Other {
        /// The function code, 01-7F.
        function: u8,
        /// The bytes after the function code.
        data: Vec<u8>,
    },
}

/// A normal (non-exception) response. Bit answers keep their packed bytes, because the
/// number of bits asked for is known only from the request.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Response {
    /// Function 1: the coils read.
    ReadCoils {
        /// Coil states packed 8 to a byte, the first in the low bit of the first byte; the byte
        /// count is the length. Unused high bits of the last byte are padding.
        packed: Vec<u8>,
    },
    /// Function 2: the discrete inputs read.
    ReadDiscreteInputs {
        /// Input states packed 8 to a byte, the first in the low bit of the first byte; the byte
        /// count is the length. Unused high bits of the last byte are padding.
        packed: Vec<u8>,
    },
    /// Function 3: the holding registers read.
    ReadHoldingRegisters {
        /// The register values, first address first.
        values: Vec<u16>,
    },
    /// Function 4: the input registers read.
    ReadInputRegisters {
        /// The register values, first address first.
        values: Vec<u16>,
    },
    /// Function 5: the echo of the request.
    WriteSingleCoil {
        /// Coil address, 0-based as on the wire.
        address: u16,
        /// The state written: on (FF00) or off (0000).
        value: bool,
    },
    /// Function 6: the echo of the request.
    WriteSingleRegister {
        /// Register address, 0-based as on the wire.
        address: u16,
        /// The value written.
        value: u16,
    },
    /// Function 7: the exception status outputs.
    ReadExceptionStatus {
        /// Eight status outputs, one per bit; their meaning is device-specific.
        status: u8,
    },
    /// Function 8: the diagnostic's answer.
    Diagnostics {
        /// The sub-function, echoed.
        sub_function: u16,
        /// The data after the sub-function, byte for byte (for 0000, the query data echoed).
        data: Vec<u8>,
    },
    /// Function 15: which coils were written.
    WriteMultipleCoils {
        /// First coil address, 0-based as on the wire.
        address: u16,
        /// How many coils were written.
        quantity: u16,
    },
    /// Function 16: which registers were written.
    WriteMultipleRegisters {
        /// First register address, 0-based as on the wire.
        address: u16,
        /// How many registers were written.
        quantity: u16,
    },
    /// Function 17: the device's identity.
    ReportServerId {
        /// The bytes after the byte count: server ID, run indicator (00 off, FF on) and any
        /// device-specific data; the layout is the device's.
        data: Vec<u8>,
    },
    /// Function 20: the records read, a group for each group asked, in order.
    ReadFileRecord {
        /// Each group's registers, first record first.
        groups: Vec<Vec<u16>>,
    },
    /// Function 21: the echo of the request.
    WriteFileRecord {
        /// The runs of records written and their values.
        groups: Vec<FileRecords>,
    },
    /// Function 22: the echo of the request.
    MaskWriteRegister {
        /// Register address, 0-based as on the wire.
        address: u16,
        /// The AND mask applied.
        and_mask: u16,
        /// The OR mask applied.
        or_mask: u16,
    },
    /// Function 23: the registers read, after the write.
    ReadWriteMultipleRegisters {
        /// The register values read, first address first.
        values: Vec<u16>,
    },
    /// Function 24: the FIFO queue's registers, oldest first (their count is at most 31).
    ReadFifoQueue {
        /// The queued registers.
        values: Vec<u16>,
    },
    /// Function 43, MEI type 14: identification objects.
    ReadDeviceIdentification(DeviceIdentification),
    /// Any function code without a layout of its own: kept byte for byte.
    Other {
        /// The function code, 01-7F.
        function: u8,
        /// The bytes after the function code.
        data: Vec<u8>,
    },
}

/// An exception response: the function that failed (without the 0x80 flag) and why.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Exception {
    /// The function code that failed, without the 0x80 flag.
    pub function: u8,
    /// Why it failed.
    pub code: ExceptionCode,
}

/// Any PDU, with its direction.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Pdu {
    /// A request, master to slave.
    Request(Request),
    /// A normal response, slave to master.
    Response(Response),
    /// An exception response: the function code with 0x80 set, then the exception code.
    Exception(Exception),
}

impl Pdu {
    /// Exception `code` in answer to `request`: what a slave, or a gateway in its place,
    /// sends back when it will not carry the request out.
    pub fn refusal(request: &Request, code: ExceptionCode) -> Pdu {
        Pdu::Exception(Exception {
            function: request.function() & !EXCEPTION_FLAG,
            code,
        })
    }

    /// The function code as on the wire: an exception's has 0x80 set.
    pub fn function(&self) -> u8 {
        match self {
            Pdu::Request(request) => request.function(),
            Pdu::Response(response) => response.function(),
            Pdu::Exception(exception) => exception.function | EXCEPTION_FLAG,
        }
    }

    /// Appends the PDU to `out`, after checking every protocol limit.
    pub fn encode(&self, out: &mut Vec<u8>) -> Result<(), PduError> {
        match self {
            Pdu::Request(request) => request.encode(out),
            Pdu::Response(response) => response.encode(out),
            Pdu::Exception(exception) => exception.encode(out),
        }
    }

    /// Reads a PDU travelling in a known direction. An exception is always a response.
    pub fn decode(pdu: &[u8], direction: Direction) -> Result<Pdu, PduError> {
        Self::read(pdu, direction, Values::Kept)
    }

    /// Whether `pdu` reads travelling in `direction`, as [`Pdu::decode`] would find,
    /// without taking its values.
    pub fn reads(pdu: &[u8], direction: Direction) -> bool {
        Self::read(pdu, direction, Values::Skipped).is_ok()
    }

    /// `decode`, keeping of the values only what `values` says.
    pub(crate) fn read(pdu: &[u8], direction: Direction, values: Values) -> Result<Pdu, PduError> {
        let function = *pdu.first().ok_or(PduError::Empty)?;
        match direction {
            Direction::Request => Request::read(pdu, values).map(Pdu::Request),
            Direction::Response if function & EXCEPTION_FLAG != 0 => {
                Exception::decode(pdu).map(Pdu::Exception)
            }
            Direction::Response => Response::read(pdu, values).map(Pdu::Response),
        }
    }
}

/// What the bytes of a PDU say when nobody has said which way it travelled.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Reading {
    /// Only one direction fits.
    One(Pdu),
    /// Both fit, as an 8-byte function 01 frame whose third byte is 3 does.
    Both {
        /// The bytes read as a request.
        request: Request,
        /// The same bytes read as a response.
        response: Response,
    },
    /// Neither fits; the errors of both readings.
    Neither {
        /// Why the bytes are no request.
        as_request: PduError,
        /// Why they are no response.
        as_response: PduError,
    },
}

impl Reading {
    /// Infers the direction from the bytes alone.
    pub fn infer(pdu: &[u8]) -> Reading {
        if pdu.first().is_some_and(|f| f & EXCEPTION_FLAG != 0) {
            return match Exception::decode(pdu) {
                Ok(exception) => Reading::One(Pdu::Exception(exception)),
                Err(error) => Reading::Neither {
                    as_request: PduError::BadField("function codes 80-FF are not requests"),
                    as_response: error,
                },
            };
        }
        match (Request::decode(pdu), Response::decode(pdu)) {
            (Ok(request), Ok(response)) => Reading::Both { request, response },
            (Ok(request), Err(_)) => Reading::One(Pdu::Request(request)),
            (Err(_), Ok(response)) => Reading::One(Pdu::Response(response)),
            (Err(as_request), Err(as_response)) => Reading::Neither {
                as_request,
                as_response,
            },
        }
    }
}

/// Which ways the bytes of a PDU read by their function's layouts, their values left
/// unread: what a conversation is followed by, before anyone asks what the PDU says.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ways {
    /// As a request only.
    Request,
    /// As an answer only: a normal response or an exception.
    Answer,
    /// As either.
    Both,
    /// As neither.
    Neither,
}

impl Ways {
    /// Which ways `pdu` reads, as [`Reading::infer`] would find, without taking its values.
    pub fn of(pdu: &[u8]) -> Ways {
        if pdu.first().is_some_and(|f| f & EXCEPTION_FLAG != 0) {
            return match Exception::decode(pdu) {
                Ok(_) => Ways::Answer,
                Err(_) => Ways::Neither,
            };
        }
        let as_request = Request::read(pdu, Values::Skipped).is_ok();
        let as_response = Response::read(pdu, Values::Skipped).is_ok();
        match (as_request, as_response) {
            (true, true) => Ways::Both,
            (true, false) => Ways::Request,
            (false, true) => Ways::Answer,
            (false, false) => Ways::Neither,
        }
    }

    /// `pdu` read these ways, values and all: one way, both, or neither with why not.
    pub fn read(self, pdu: &[u8]) -> Reading {
        let read = match self {
            Ways::Request => Pdu::decode(pdu, Direction::Request).map(Reading::One),
            Ways::Answer => Pdu::decode(pdu, Direction::Response).map(Reading::One),
            Ways::Both => Request::decode(pdu).and_then(|request| {
                Ok(Reading::Both {
                    request,
                    response: Response::decode(pdu)?,
                })
            }),
            Ways::Neither => return Reading::infer(pdu),
        };
        // Bytes that do not read the ways they were said to are read as they are.
        read.unwrap_or_else(|_| Reading::infer(pdu))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::collection::vec;
    use proptest::prelude::*;

    /// The PDUs whose values a decode keeps in lists, encoded, in both directions.
    fn listing_pdu() -> impl Strategy<Value = Vec<u8>> {
        let words = || vec(any::<u16>(), 1..8);
        let bytes = || vec(any::<u8>(), 0..8);
        let address = || 0u16..16;
        let pdu = prop_oneof![
            (address(), vec(any::<bool>(), 1..20)).prop_map(|(address, values)| Pdu::Request(
                Request::WriteMultipleCoils { address, values }
            )),
            (address(), words()).prop_map(|(address, values)| Pdu::Request(
                Request::WriteMultipleRegisters { address, values }
            )),
            (address(), 1u16..8, address(), words()).prop_map(
                |(read_address, read_quantity, write_address, values)| {
                    Pdu::Request(Request::ReadWriteMultipleRegisters {
                        read_address,
                        read_quantity,
                        write_address,
                        values,
                    })
                }
            ),
            (any::<u16>(), bytes()).prop_map(|(sub_function, data)| Pdu::Request(
                Request::Diagnostics { sub_function, data }
            )),
            vec(any::<u8>(), 1..4).prop_map(|packed| Pdu::Response(Response::ReadCoils { packed })),
            words().prop_map(|values| Pdu::Response(Response::ReadHoldingRegisters { values })),
            words()
                .prop_map(|values| Pdu::Response(Response::ReadWriteMultipleRegisters { values })),
            bytes().prop_map(|data| Pdu::Response(Response::ReportServerId { data })),
            (any::<u16>(), bytes()).prop_map(|(sub_function, data)| Pdu::Response(
                Response::Diagnostics { sub_function, data }
            )),
            vec((any::<u8>(), bytes()), 0..3).prop_map(|objects| {
                Pdu::Response(Response::ReadDeviceIdentification(DeviceIdentification {
                    read_code: 1,
                    conformity: 1,
                    more_follows: false,
                    next_object_id: 0,
                    objects: objects
                        .into_iter()
                        .map(|(id, value)| DeviceObject { id, value })
                        .collect(),
                }))
            }),
        ];
        pdu.prop_map(|pdu| {
            let mut bytes = Vec::new();
            pdu.encode(&mut bytes).map(|()| bytes).unwrap_or_default()
        })
    }

    /// A PDU that reads, or one byte of it changed, or cut, or lengthened.
    fn near_pdu() -> impl Strategy<Value = Vec<u8>> {
        (
            listing_pdu(),
            any::<prop::sample::Index>(),
            any::<u8>(),
            0..4u8,
        )
            .prop_map(|(mut pdu, at, byte, change)| {
                if !pdu.is_empty() {
                    let at = at.index(pdu.len());
                    match change {
                        1 => pdu[at] = byte,
                        2 => pdu.truncate(at),
                        3 => pdu.push(byte),
                        _ => {}
                    }
                }
                pdu
            })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(3000))]

        /// The ways a PDU reads, its values unread, are the ways it is read with them; and
        /// read those ways, it is what reading it from scratch finds.
        #[test]
        fn the_ways_a_pdu_reads_are_the_reading_of_it(
            pdu in prop_oneof![near_pdu(), vec(any::<u8>(), 0..300)],
        ) {
            let reading = Reading::infer(&pdu);
            let ways = Ways::of(&pdu);
            let expected = match &reading {
                Reading::One(Pdu::Request(_)) => Ways::Request,
                Reading::One(_) => Ways::Answer,
                Reading::Both { .. } => Ways::Both,
                Reading::Neither { .. } => Ways::Neither,
            };
            prop_assert_eq!(ways, expected);
            prop_assert_eq!(ways.read(&pdu), reading);
        }

        /// Reading without keeping the values says what decoding says, error for error.
        #[test]
        fn skipping_the_values_reads_as_decoding_does(
            pdu in prop_oneof![near_pdu(), vec(any::<u8>(), 0..300)],
        ) {
            for direction in [Direction::Request, Direction::Response] {
                let skipped = Pdu::read(&pdu, direction, Values::Skipped).map(|p| p.function());
                let decoded = Pdu::decode(&pdu, direction).map(|p| p.function());
                prop_assert_eq!(skipped, decoded);
            }
        }
    }
}
