//! Requests: each function's request layout, encoded and decoded.

use crate::codec::error::PduError;
use crate::codec::function::*;
use crate::codec::{bits, limits, Direction};

use super::wire::{
    check_layout_length, check_normal_function, check_pdu_len, check_quantity, check_range,
    check_read, coil_from_word, coil_word, counted_exactly, counted_registers, len_u8, quantity_of,
    Reader, Values, Writer,
};
use super::{file, Request};

/// Whether a diagnostic (08) sub-function only reads: return query data (00) and the
/// counters (02, 0B-12); the others restart, clear or silence the device.
pub(crate) fn diagnostic_only_reads(sub_function: u16) -> bool {
    matches!(sub_function, 0x00 | 0x02 | 0x0B..=0x12)
}

/// Whether a function kept as opaque bytes only reads: the event counter and log (0B,
/// 0C), and file record read (14) and the FIFO queue (18) when their fields break their
/// layouts.
pub(crate) fn function_only_reads(function: u8) -> bool {
    matches!(function, 0x0B | 0x0C | 0x14 | 0x18)
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
            Request::ReadFileRecord { .. } => READ_FILE_RECORD,
            Request::WriteFileRecord { .. } => WRITE_FILE_RECORD,
            Request::MaskWriteRegister { .. } => MASK_WRITE_REGISTER,
            Request::ReadWriteMultipleRegisters { .. } => READ_WRITE_MULTIPLE_REGISTERS,
            Request::ReadFifoQueue { .. } => READ_FIFO_QUEUE,
            Request::ReadDeviceIdentification { .. } => ENCAPSULATED_INTERFACE,
            Request::Other { function, .. } => *function,
        }
    }

    /// Whether it may change the device: a write of any kind, a diagnostic that restarts,
    /// clears or silences it, and the functions without a layout here that do not only
    /// read.
    pub fn changes_device(&self) -> bool {
        match self {
            Request::WriteSingleCoil { .. }
            | Request::WriteSingleRegister { .. }
            | Request::WriteMultipleCoils { .. }
            | Request::WriteMultipleRegisters { .. }
            | Request::WriteFileRecord { .. }
            | Request::MaskWriteRegister { .. }
            | Request::ReadWriteMultipleRegisters { .. } => true,
            Request::Diagnostics { sub_function, .. } => !diagnostic_only_reads(*sub_function),
            Request::Other { function, .. } => !function_only_reads(*function),
            _ => false,
        }
    }

    /// Whether sending it a second time, after its answer was lost, may do more than
    /// sending it once: file record writes, mask writes, read/write multiple, and the
    /// functions mbtool has no layout for. A retry of one is asked for explicitly.
    pub fn may_differ_when_repeated(&self) -> bool {
        match self {
            Request::WriteFileRecord { .. }
            | Request::MaskWriteRegister { .. }
            | Request::ReadWriteMultipleRegisters { .. } => true,
            Request::Other { function, .. } => !function_only_reads(*function),
            _ => false,
        }
    }

    /// How many coils or registers a read of one table (01-04) asks for; 0 for any other
    /// request.
    pub fn read_quantity(&self) -> u16 {
        match self {
            Request::ReadCoils { quantity, .. }
            | Request::ReadDiscreteInputs { quantity, .. }
            | Request::ReadHoldingRegisters { quantity, .. }
            | Request::ReadInputRegisters { quantity, .. } => *quantity,
            _ => 0,
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
            Request::ReadFileRecord { groups } => file::write_read_request(&mut w, groups)?,
            Request::WriteFileRecord { groups } => file::write_write_groups(&mut w, groups)?,
            Request::ReadFifoQueue { address } => {
                w.u16(*address);
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
        Self::read(pdu, Values::Kept)
    }

    pub(crate) fn read(pdu: &[u8], values: Values) -> Result<Request, PduError> {
        let mut r = Reader::new(pdu, values)?;
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
                data: {
                    let rest = r.rest();
                    r.owned(rest)
                },
            },
            WRITE_MULTIPLE_COILS => {
                let (address, quantity) = (r.u16()?, r.u16()?);
                check_quantity(quantity, limits::MAX_WRITE_BITS)?;
                check_range(address, quantity)?;
                let packed = counted_exactly(&mut r, usize::from(quantity).div_ceil(8), quantity)?;
                Request::WriteMultipleCoils {
                    address,
                    values: r.bits(packed, usize::from(quantity)),
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
            READ_FILE_RECORD => Request::ReadFileRecord {
                groups: file::read_read_request(&mut r)?,
            },
            WRITE_FILE_RECORD => Request::WriteFileRecord {
                groups: file::read_write_groups(&mut r)?,
            },
            READ_FIFO_QUEUE => Request::ReadFifoQueue { address: r.u16()? },
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
            function => {
                check_layout_length(pdu, Direction::Request)?;
                Request::Other {
                    function,
                    data: {
                        let rest = r.rest();
                        r.owned(rest)
                    },
                }
            }
        };
        r.finish()?;
        check_pdu_len(pdu.len())?;
        Ok(request)
    }
}
