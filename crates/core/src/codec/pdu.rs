//! Protocol data units as types: what a request asks, what a response answers.
//!
//! `encode` checks the protocol limits before writing a byte; `decode` checks them again, so
//! a frame from the wire that breaks them is reported, never trusted.

use super::error::PduError;
use super::exception::ExceptionCode;
use super::function::*;
use super::{bits, limits};

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

/// The answer to Read Device Identification (function 43, MEI type 14).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DeviceIdentification {
    /// The read device ID code of the request, echoed.
    pub read_code: u8,
    /// Conformity level: 01 basic, 02 regular, 03 extended identification; 81-83 when
    /// single objects can be read too.
    pub conformity: u8,
    /// More objects remain than this answer holds: ask again from `next_object_id`.
    pub more_follows: bool,
    /// The object to ask for next when `more_follows`; 00 otherwise.
    pub next_object_id: u8,
    /// The objects this answer holds, in order.
    pub objects: Vec<DeviceObject>,
}

/// One identification object.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DeviceObject {
    /// Object id: 00 VendorName, 01 ProductCode, 02 MajorMinorRevision, 03-06 the regular
    /// objects, 80-FF extended (private).
    pub id: u8,
    /// The object's bytes as sent; text for the standard objects.
    pub value: Vec<u8>,
}

/// The names of the standard identification objects 00-06, by id.
const OBJECT_NAMES: [&str; 7] = [
    "VendorName",
    "ProductCode",
    "MajorMinorRevision",
    "VendorUrl",
    "ProductName",
    "ModelName",
    "UserApplicationName",
];

impl DeviceObject {
    /// The name the specification gives object `id`; "reserved" for 07-7F, "private"
    /// for the extended objects 80-FF.
    pub fn name(id: u8) -> &'static str {
        match OBJECT_NAMES.get(usize::from(id)) {
            Some(name) => name,
            None if id < 0x80 => "reserved",
            None => "private",
        }
    }

    /// The id of a standard object by its name, in any case (`VendorUrl`, `vendorurl`).
    pub fn id_named(name: &str) -> Option<u8> {
        OBJECT_NAMES
            .iter()
            .position(|known| known.eq_ignore_ascii_case(name))
            .and_then(|id| u8::try_from(id).ok())
    }
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

/// Which way a PDU travels.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Direction {
    /// Master to slave.
    Request,
    /// Slave to master: a normal or an exception response.
    Response,
}

fn check_quantity(quantity: u16, max: u16) -> Result<(), PduError> {
    if quantity == 0 || quantity > max {
        return Err(PduError::QuantityOutOfRange { quantity, max });
    }
    Ok(())
}

fn check_range(address: u16, quantity: u16) -> Result<(), PduError> {
    if u32::from(address) + u32::from(quantity) > 65536 {
        return Err(PduError::AddressOverflow { address, quantity });
    }
    Ok(())
}

fn check_read(address: u16, quantity: u16, max: u16) -> Result<(), PduError> {
    check_quantity(quantity, max)?;
    check_range(address, quantity)
}

fn coil_word(value: bool) -> u16 {
    if value {
        0xFF00
    } else {
        0x0000
    }
}

fn coil_from_word(word: u16) -> Result<bool, PduError> {
    match word {
        0xFF00 => Ok(true),
        0x0000 => Ok(false),
        other => Err(PduError::BadCoilValue(other)),
    }
}

fn len_u8(len: usize, max: usize) -> Result<u8, PduError> {
    u8::try_from(len)
        .ok()
        .filter(|_| len <= max)
        .ok_or(PduError::TooLong(len + 2))
}

/// A little writer so that every encoder reads like the layout table of the specification.
struct Writer<'a>(&'a mut Vec<u8>);

impl Writer<'_> {
    fn u8(&mut self, value: u8) -> &mut Self {
        self.0.push(value);
        self
    }
    fn u16(&mut self, value: u16) -> &mut Self {
        self.0.extend_from_slice(&value.to_be_bytes());
        self
    }
    fn bytes(&mut self, bytes: &[u8]) -> &mut Self {
        self.0.extend_from_slice(bytes);
        self
    }
    fn registers(&mut self, values: &[u16]) -> &mut Self {
        for value in values {
            self.u16(*value);
        }
        self
    }
}

/// Reads a PDU's fields in order; running short is an error, never a panic.
struct Reader<'a> {
    function: u8,
    bytes: &'a [u8],
    pos: usize,
}

impl<'a> Reader<'a> {
    /// A reader positioned after the function code.
    fn new(pdu: &'a [u8]) -> Result<Self, PduError> {
        let function = *pdu.first().ok_or(PduError::Empty)?;
        Ok(Self {
            function,
            bytes: pdu,
            pos: 1,
        })
    }

    fn take(&mut self, n: usize) -> Result<&'a [u8], PduError> {
        let end = self.pos + n;
        let slice = self.bytes.get(self.pos..end).ok_or(PduError::Truncated {
            function: self.function,
            needed: end,
            actual: self.bytes.len(),
        })?;
        self.pos = end;
        Ok(slice)
    }

    fn u8(&mut self) -> Result<u8, PduError> {
        Ok(self.take(1)?[0])
    }

    fn u16(&mut self) -> Result<u16, PduError> {
        let b = self.take(2)?;
        Ok(u16::from_be_bytes([b[0], b[1]]))
    }

    fn registers(&mut self, count: usize) -> Result<Vec<u16>, PduError> {
        Ok(self
            .take(count * 2)?
            .chunks_exact(2)
            .map(|b| u16::from_be_bytes([b[0], b[1]]))
            .collect())
    }

    fn rest(&mut self) -> &'a [u8] {
        let rest = self.bytes.get(self.pos..).unwrap_or_default();
        self.pos = self.bytes.len();
        rest
    }

    /// The PDU must end here: extra bytes mean the frame is not what its function says.
    fn finish(self) -> Result<(), PduError> {
        if self.pos != self.bytes.len() {
            return Err(PduError::LengthMismatch {
                function: self.function,
                expected: self.pos,
                actual: self.bytes.len(),
            });
        }
        Ok(())
    }

    /// A byte count, then that many bytes, which must be the rest of the PDU.
    fn counted_rest(&mut self) -> Result<&'a [u8], PduError> {
        let byte_count = usize::from(self.u8()?);
        let expected = self.pos + byte_count;
        if expected != self.bytes.len() {
            return Err(PduError::LengthMismatch {
                function: self.function,
                expected,
                actual: self.bytes.len(),
            });
        }
        self.take(byte_count)
    }
}

impl Request {
    /// The function code the request is sent with.
    pub fn function(&self) -> u8 {
        match self {
            Request::ReadCoils { .. } => READ_COILS,
            Request::ReadDiscreteInputs { .. } => READ_DISCRETE_INPUTS,
            Request::ReadHoldingRegisters { .. } => READ_HOLDING_REGISTERS,
            Request::ReadInputRegisters { .. } => READ_INPUT_REGISTERS,
            Request::WriteSingleCoil { .. } => WRITE_SINGLE_COIL,
            Request::WriteSingleRegister { .. } => WRITE_SINGLE_REGISTER,
            Request::ReadExceptionStatus => READ_EXCEPTION_STATUS,
            Request::Diagnostics { .. } => DIAGNOSTICS,
            Request::WriteMultipleCoils { .. } => WRITE_MULTIPLE_COILS,
            Request::WriteMultipleRegisters { .. } => WRITE_MULTIPLE_REGISTERS,
            Request::ReportServerId => REPORT_SERVER_ID,
            Request::MaskWriteRegister { .. } => MASK_WRITE_REGISTER,
            Request::ReadWriteMultipleRegisters { .. } => READ_WRITE_MULTIPLE_REGISTERS,
            Request::ReadDeviceIdentification { .. } => ENCAPSULATED_INTERFACE,
            Request::Other { function, .. } => *function,
        }
    }

    /// Appends the PDU to `out`, after checking every protocol limit.
    pub fn encode(&self, out: &mut Vec<u8>) -> Result<(), PduError> {
        let start = out.len();
        let mut w = Writer(out);
        w.u8(self.function());
        match self {
            Request::ReadCoils { address, quantity }
            | Request::ReadDiscreteInputs { address, quantity } => {
                check_read(*address, *quantity, limits::MAX_READ_BITS)?;
                w.u16(*address).u16(*quantity);
            }
            Request::ReadHoldingRegisters { address, quantity }
            | Request::ReadInputRegisters { address, quantity } => {
                check_read(*address, *quantity, limits::MAX_READ_REGISTERS)?;
                w.u16(*address).u16(*quantity);
            }
            Request::WriteSingleCoil { address, value } => {
                w.u16(*address).u16(coil_word(*value));
            }
            Request::WriteSingleRegister { address, value } => {
                w.u16(*address).u16(*value);
            }
            Request::ReadExceptionStatus | Request::ReportServerId => {}
            Request::Diagnostics { sub_function, data } => {
                len_u8(data.len(), limits::MAX_PDU - 3)?;
                w.u16(*sub_function).bytes(data);
            }
            Request::WriteMultipleCoils { address, values } => {
                let quantity = quantity_of(values.len(), limits::MAX_WRITE_BITS)?;
                check_range(*address, quantity)?;
                let packed = bits::pack(values);
                w.u16(*address)
                    .u16(quantity)
                    .u8(len_u8(packed.len(), 246)?)
                    .bytes(&packed);
            }
            Request::WriteMultipleRegisters { address, values } => {
                let quantity = quantity_of(values.len(), limits::MAX_WRITE_REGISTERS)?;
                check_range(*address, quantity)?;
                w.u16(*address)
                    .u16(quantity)
                    .u8(len_u8(values.len() * 2, 246)?)
                    .registers(values);
            }
            Request::MaskWriteRegister {
                address,
                and_mask,
                or_mask,
            } => {
                w.u16(*address).u16(*and_mask).u16(*or_mask);
            }
            Request::ReadWriteMultipleRegisters {
                read_address,
                read_quantity,
                write_address,
                values,
            } => {
                check_read(*read_address, *read_quantity, limits::MAX_RW_READ_REGISTERS)?;
                let write_quantity = quantity_of(values.len(), limits::MAX_RW_WRITE_REGISTERS)?;
                check_range(*write_address, write_quantity)?;
                w.u16(*read_address)
                    .u16(*read_quantity)
                    .u16(*write_address)
                    .u16(write_quantity)
                    .u8(len_u8(values.len() * 2, 242)?)
                    .registers(values);
            }
            Request::ReadDeviceIdentification {
                read_code,
                object_id,
            } => {
                w.u8(MEI_READ_DEVICE_IDENTIFICATION)
                    .u8(*read_code)
                    .u8(*object_id);
            }
            Request::Other { function, data } => {
                check_normal_function(*function)?;
                w.bytes(data);
            }
        }
        check_pdu_len(out.len() - start)
    }

    /// Reads a request PDU.
    pub fn decode(pdu: &[u8]) -> Result<Request, PduError> {
        let mut r = Reader::new(pdu)?;
        check_normal_function(r.function)?;
        let request = match r.function {
            READ_COILS | READ_DISCRETE_INPUTS => {
                let (address, quantity) = (r.u16()?, r.u16()?);
                check_read(address, quantity, limits::MAX_READ_BITS)?;
                if r.function == READ_COILS {
                    Request::ReadCoils { address, quantity }
                } else {
                    Request::ReadDiscreteInputs { address, quantity }
                }
            }
            READ_HOLDING_REGISTERS | READ_INPUT_REGISTERS => {
                let (address, quantity) = (r.u16()?, r.u16()?);
                check_read(address, quantity, limits::MAX_READ_REGISTERS)?;
                if r.function == READ_HOLDING_REGISTERS {
                    Request::ReadHoldingRegisters { address, quantity }
                } else {
                    Request::ReadInputRegisters { address, quantity }
                }
            }
            WRITE_SINGLE_COIL => Request::WriteSingleCoil {
                address: r.u16()?,
                value: coil_from_word(r.u16()?)?,
            },
            WRITE_SINGLE_REGISTER => Request::WriteSingleRegister {
                address: r.u16()?,
                value: r.u16()?,
            },
            READ_EXCEPTION_STATUS => Request::ReadExceptionStatus,
            REPORT_SERVER_ID => Request::ReportServerId,
            DIAGNOSTICS => Request::Diagnostics {
                sub_function: r.u16()?,
                data: r.rest().to_vec(),
            },
            WRITE_MULTIPLE_COILS => {
                let (address, quantity) = (r.u16()?, r.u16()?);
                check_quantity(quantity, limits::MAX_WRITE_BITS)?;
                check_range(address, quantity)?;
                let packed = counted_exactly(&mut r, usize::from(quantity).div_ceil(8), quantity)?;
                Request::WriteMultipleCoils {
                    address,
                    values: bits::unpack(packed, usize::from(quantity)),
                }
            }
            WRITE_MULTIPLE_REGISTERS => {
                let (address, quantity) = (r.u16()?, r.u16()?);
                check_quantity(quantity, limits::MAX_WRITE_REGISTERS)?;
                check_range(address, quantity)?;
                counted_registers(&mut r, quantity)?;
                Request::WriteMultipleRegisters {
                    address,
                    values: r.registers(usize::from(quantity))?,
                }
            }
            MASK_WRITE_REGISTER => Request::MaskWriteRegister {
                address: r.u16()?,
                and_mask: r.u16()?,
                or_mask: r.u16()?,
            },
            READ_WRITE_MULTIPLE_REGISTERS => {
                let (read_address, read_quantity) = (r.u16()?, r.u16()?);
                let (write_address, write_quantity) = (r.u16()?, r.u16()?);
                check_read(read_address, read_quantity, limits::MAX_RW_READ_REGISTERS)?;
                check_quantity(write_quantity, limits::MAX_RW_WRITE_REGISTERS)?;
                check_range(write_address, write_quantity)?;
                counted_registers(&mut r, write_quantity)?;
                Request::ReadWriteMultipleRegisters {
                    read_address,
                    read_quantity,
                    write_address,
                    values: r.registers(usize::from(write_quantity))?,
                }
            }
            ENCAPSULATED_INTERFACE if pdu.get(1) == Some(&MEI_READ_DEVICE_IDENTIFICATION) => {
                r.u8()?;
                Request::ReadDeviceIdentification {
                    read_code: r.u8()?,
                    object_id: r.u8()?,
                }
            }
            function => Request::Other {
                function,
                data: r.rest().to_vec(),
            },
        };
        r.finish()?;
        check_pdu_len(pdu.len())?;
        Ok(request)
    }
}

/// Requests and normal responses carry function codes 01-7F; 80-FF mark exceptions.
fn check_normal_function(function: u8) -> Result<(), PduError> {
    if function == 0 || function & EXCEPTION_FLAG != 0 {
        return Err(PduError::BadField(
            "function codes 00 and 80-FF are not requests or normal responses",
        ));
    }
    Ok(())
}

fn check_pdu_len(len: usize) -> Result<(), PduError> {
    if len > limits::MAX_PDU {
        return Err(PduError::TooLong(len));
    }
    Ok(())
}

fn quantity_of(len: usize, max: u16) -> Result<u16, PduError> {
    let quantity = u16::try_from(len).unwrap_or(u16::MAX);
    check_quantity(quantity, max)?;
    Ok(quantity)
}

/// Reads a byte count that must equal `expected`, then the bytes it counts.
fn counted_exactly<'a>(
    r: &mut Reader<'a>,
    expected: usize,
    quantity: u16,
) -> Result<&'a [u8], PduError> {
    let byte_count = r.u8()?;
    if usize::from(byte_count) != expected {
        return Err(PduError::ByteCountMismatch {
            byte_count,
            quantity,
            expected,
        });
    }
    r.take(expected)
}

/// Checks a register byte count (2 per register) without consuming the registers.
fn counted_registers(r: &mut Reader<'_>, quantity: u16) -> Result<(), PduError> {
    let byte_count = r.u8()?;
    let expected = usize::from(quantity) * 2;
    if usize::from(byte_count) != expected {
        return Err(PduError::ByteCountMismatch {
            byte_count,
            quantity,
            expected,
        });
    }
    Ok(())
}

impl Response {
    /// The function code of the response.
    pub fn function(&self) -> u8 {
        match self {
            Response::ReadCoils { .. } => READ_COILS,
            Response::ReadDiscreteInputs { .. } => READ_DISCRETE_INPUTS,
            Response::ReadHoldingRegisters { .. } => READ_HOLDING_REGISTERS,
            Response::ReadInputRegisters { .. } => READ_INPUT_REGISTERS,
            Response::WriteSingleCoil { .. } => WRITE_SINGLE_COIL,
            Response::WriteSingleRegister { .. } => WRITE_SINGLE_REGISTER,
            Response::ReadExceptionStatus { .. } => READ_EXCEPTION_STATUS,
            Response::Diagnostics { .. } => DIAGNOSTICS,
            Response::WriteMultipleCoils { .. } => WRITE_MULTIPLE_COILS,
            Response::WriteMultipleRegisters { .. } => WRITE_MULTIPLE_REGISTERS,
            Response::ReportServerId { .. } => REPORT_SERVER_ID,
            Response::MaskWriteRegister { .. } => MASK_WRITE_REGISTER,
            Response::ReadWriteMultipleRegisters { .. } => READ_WRITE_MULTIPLE_REGISTERS,
            Response::ReadDeviceIdentification(_) => ENCAPSULATED_INTERFACE,
            Response::Other { function, .. } => *function,
        }
    }

    /// Appends the PDU to `out`, after checking every protocol limit.
    pub fn encode(&self, out: &mut Vec<u8>) -> Result<(), PduError> {
        let start = out.len();
        let mut w = Writer(out);
        w.u8(self.function());
        match self {
            Response::ReadCoils { packed } | Response::ReadDiscreteInputs { packed } => {
                if packed.is_empty() {
                    return Err(PduError::BadByteCount {
                        function: self.function(),
                        byte_count: 0,
                    });
                }
                w.u8(len_u8(packed.len(), limits::MAX_READ_BITS_BYTES)?)
                    .bytes(packed);
            }
            Response::ReadHoldingRegisters { values }
            | Response::ReadInputRegisters { values }
            | Response::ReadWriteMultipleRegisters { values } => {
                quantity_of(values.len(), limits::MAX_READ_REGISTERS)?;
                w.u8(len_u8(values.len() * 2, 250)?).registers(values);
            }
            Response::WriteSingleCoil { address, value } => {
                w.u16(*address).u16(coil_word(*value));
            }
            Response::WriteSingleRegister { address, value } => {
                w.u16(*address).u16(*value);
            }
            Response::ReadExceptionStatus { status } => {
                w.u8(*status);
            }
            Response::Diagnostics { sub_function, data } => {
                len_u8(data.len(), limits::MAX_PDU - 3)?;
                w.u16(*sub_function).bytes(data);
            }
            Response::WriteMultipleCoils { address, quantity } => {
                check_quantity(*quantity, limits::MAX_WRITE_BITS)?;
                check_range(*address, *quantity)?;
                w.u16(*address).u16(*quantity);
            }
            Response::WriteMultipleRegisters { address, quantity } => {
                check_quantity(*quantity, limits::MAX_WRITE_REGISTERS)?;
                check_range(*address, *quantity)?;
                w.u16(*address).u16(*quantity);
            }
            Response::ReportServerId { data } => {
                w.u8(len_u8(data.len(), limits::MAX_PDU - 2)?).bytes(data);
            }
            Response::MaskWriteRegister {
                address,
                and_mask,
                or_mask,
            } => {
                w.u16(*address).u16(*and_mask).u16(*or_mask);
            }
            Response::ReadDeviceIdentification(id) => {
                w.u8(MEI_READ_DEVICE_IDENTIFICATION)
                    .u8(id.read_code)
                    .u8(id.conformity)
                    .u8(if id.more_follows { 0xFF } else { 0x00 })
                    .u8(id.next_object_id)
                    .u8(len_u8(id.objects.len(), limits::MAX_PDU)?);
                for object in &id.objects {
                    w.u8(object.id)
                        .u8(len_u8(object.value.len(), limits::MAX_PDU)?)
                        .bytes(&object.value);
                }
            }
            Response::Other { function, data } => {
                check_normal_function(*function)?;
                w.bytes(data);
            }
        }
        check_pdu_len(out.len() - start)
    }

    /// Reads a normal response PDU.
    pub fn decode(pdu: &[u8]) -> Result<Response, PduError> {
        let mut r = Reader::new(pdu)?;
        check_normal_function(r.function)?;
        let response = match r.function {
            READ_COILS | READ_DISCRETE_INPUTS => {
                let packed = r.counted_rest()?.to_vec();
                if packed.is_empty() || packed.len() > limits::MAX_READ_BITS_BYTES {
                    return Err(PduError::BadByteCount {
                        function: r.function,
                        byte_count: len_u8(packed.len(), 255).unwrap_or(u8::MAX),
                    });
                }
                if r.function == READ_COILS {
                    Response::ReadCoils { packed }
                } else {
                    Response::ReadDiscreteInputs { packed }
                }
            }
            READ_HOLDING_REGISTERS | READ_INPUT_REGISTERS | READ_WRITE_MULTIPLE_REGISTERS => {
                let function = r.function;
                let data = r.counted_rest()?;
                if data.is_empty() || data.len() % 2 != 0 || data.len() > 250 {
                    return Err(PduError::BadByteCount {
                        function,
                        byte_count: len_u8(data.len(), 255).unwrap_or(u8::MAX),
                    });
                }
                let values = data
                    .chunks_exact(2)
                    .map(|b| u16::from_be_bytes([b[0], b[1]]))
                    .collect();
                match function {
                    READ_HOLDING_REGISTERS => Response::ReadHoldingRegisters { values },
                    READ_INPUT_REGISTERS => Response::ReadInputRegisters { values },
                    _ => Response::ReadWriteMultipleRegisters { values },
                }
            }
            WRITE_SINGLE_COIL => Response::WriteSingleCoil {
                address: r.u16()?,
                value: coil_from_word(r.u16()?)?,
            },
            WRITE_SINGLE_REGISTER => Response::WriteSingleRegister {
                address: r.u16()?,
                value: r.u16()?,
            },
            READ_EXCEPTION_STATUS => Response::ReadExceptionStatus { status: r.u8()? },
            DIAGNOSTICS => Response::Diagnostics {
                sub_function: r.u16()?,
                data: r.rest().to_vec(),
            },
            WRITE_MULTIPLE_COILS | WRITE_MULTIPLE_REGISTERS => {
                let function = r.function;
                let (address, quantity) = (r.u16()?, r.u16()?);
                let max = if function == WRITE_MULTIPLE_COILS {
                    limits::MAX_WRITE_BITS
                } else {
                    limits::MAX_WRITE_REGISTERS
                };
                check_quantity(quantity, max)?;
                check_range(address, quantity)?;
                if function == WRITE_MULTIPLE_COILS {
                    Response::WriteMultipleCoils { address, quantity }
                } else {
                    Response::WriteMultipleRegisters { address, quantity }
                }
            }
            REPORT_SERVER_ID => Response::ReportServerId {
                data: r.counted_rest()?.to_vec(),
            },
            MASK_WRITE_REGISTER => Response::MaskWriteRegister {
                address: r.u16()?,
                and_mask: r.u16()?,
                or_mask: r.u16()?,
            },
            ENCAPSULATED_INTERFACE if pdu.get(1) == Some(&MEI_READ_DEVICE_IDENTIFICATION) => {
                r.u8()?;
                let read_code = r.u8()?;
                let conformity = r.u8()?;
                let more_follows = match r.u8()? {
                    0x00 => false,
                    0xFF => true,
                    _ => return Err(PduError::BadField("'more follows' must be 00 or FF")),
                };
                let next_object_id = r.u8()?;
                let count = r.u8()?;
                let mut objects = Vec::with_capacity(usize::from(count));
                for _ in 0..count {
                    let id = r.u8()?;
                    let len = usize::from(r.u8()?);
                    objects.push(DeviceObject {
                        id,
                        value: r.take(len)?.to_vec(),
                    });
                }
                Response::ReadDeviceIdentification(DeviceIdentification {
                    read_code,
                    conformity,
                    more_follows,
                    next_object_id,
                    objects,
                })
            }
            function => Response::Other {
                function,
                data: r.rest().to_vec(),
            },
        };
        r.finish()?;
        check_pdu_len(pdu.len())?;
        Ok(response)
    }

    /// The bits of a coil or discrete-input answer, cut to the `quantity` that was asked.
    pub fn bits(&self, quantity: usize) -> Option<Vec<bool>> {
        match self {
            Response::ReadCoils { packed } | Response::ReadDiscreteInputs { packed } => {
                Some(bits::unpack(packed, quantity))
            }
            _ => None,
        }
    }
}

impl Exception {
    /// Appends the two PDU bytes (function code with 0x80 set, exception code) to `out`;
    /// the function must be 00-7F (00 only to refuse a request of function 00).
    pub fn encode(&self, out: &mut Vec<u8>) -> Result<(), PduError> {
        if self.function & EXCEPTION_FLAG != 0 {
            return Err(PduError::BadField(
                "an exception answers a function code 00-7F",
            ));
        }
        out.push(self.function | EXCEPTION_FLAG);
        out.push(self.code.0);
        Ok(())
    }

    /// Reads an exception PDU: a function code with 0x80 set, then the exception code.
    pub fn decode(pdu: &[u8]) -> Result<Exception, PduError> {
        let mut r = Reader::new(pdu)?;
        if r.function & EXCEPTION_FLAG == 0 {
            return Err(PduError::BadField(
                "an exception has bit 7 of its function set",
            ));
        }
        let code = ExceptionCode(r.u8()?);
        let function = r.function & !EXCEPTION_FLAG;
        r.finish()?;
        Ok(Exception { function, code })
    }
}

impl Pdu {
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
        let function = *pdu.first().ok_or(PduError::Empty)?;
        match direction {
            Direction::Request => Request::decode(pdu).map(Pdu::Request),
            Direction::Response if function & EXCEPTION_FLAG != 0 => {
                Exception::decode(pdu).map(Pdu::Exception)
            }
            Direction::Response => Response::decode(pdu).map(Pdu::Response),
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
