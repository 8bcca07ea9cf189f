//! Normal responses and exceptions: each function's answer layout, encoded and decoded.

use crate::codec::error::PduError;
use crate::codec::exception::ExceptionCode;
use crate::codec::function::*;
use crate::codec::{bits, limits, Direction};

use super::wire::{
    check_layout_length, check_normal_function, check_pdu_len, check_quantity, check_range,
    coil_from_word, coil_word, len_u8, quantity_of, Reader, Values, Writer,
};
use super::{file, DeviceIdentification, DeviceObject, Exception, Response};

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
            Response::ReadFileRecord { .. } => READ_FILE_RECORD,
            Response::WriteFileRecord { .. } => WRITE_FILE_RECORD,
            Response::MaskWriteRegister { .. } => MASK_WRITE_REGISTER,
            Response::ReadWriteMultipleRegisters { .. } => READ_WRITE_MULTIPLE_REGISTERS,
            Response::ReadFifoQueue { .. } => READ_FIFO_QUEUE,
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
            Response::ReadFileRecord { groups } => file::write_read_answer(&mut w, groups)?,
            Response::WriteFileRecord { groups } => file::write_write_groups(&mut w, groups)?,
            Response::ReadFifoQueue { values } => file::write_fifo_answer(&mut w, values)?,
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
        Self::read(pdu, Values::Kept)
    }

    pub(crate) fn read(pdu: &[u8], values: Values) -> Result<Response, PduError> {
        let mut r = Reader::new(pdu, values)?;
        check_normal_function(r.function)?;
        let response = match r.function {
            READ_COILS | READ_DISCRETE_INPUTS => {
                let packed = r.counted_rest()?;
                if packed.is_empty() || packed.len() > limits::MAX_READ_BITS_BYTES {
                    return Err(PduError::BadByteCount {
                        function: r.function,
                        byte_count: len_u8(packed.len(), 255).unwrap_or(u8::MAX),
                    });
                }
                let packed = r.owned(packed);
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
                let values = r.words(data);
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
                data: {
                    let rest = r.rest();
                    r.owned(rest)
                },
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
            REPORT_SERVER_ID => {
                let data = r.counted_rest()?;
                Response::ReportServerId {
                    data: r.owned(data),
                }
            }
            READ_FILE_RECORD => Response::ReadFileRecord {
                groups: file::read_read_answer(&mut r)?,
            },
            WRITE_FILE_RECORD => Response::WriteFileRecord {
                groups: file::read_write_groups(&mut r)?,
            },
            READ_FIFO_QUEUE => Response::ReadFifoQueue {
                values: file::read_fifo_answer(&mut r)?,
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
                let mut objects = Vec::new();
                for _ in 0..count {
                    let id = r.u8()?;
                    let len = usize::from(r.u8()?);
                    let value = r.take(len)?;
                    if r.keeps() {
                        objects.push(DeviceObject {
                            id,
                            value: value.to_vec(),
                        });
                    }
                }
                Response::ReadDeviceIdentification(DeviceIdentification {
                    read_code,
                    conformity,
                    more_follows,
                    next_object_id,
                    objects,
                })
            }
            function => {
                check_layout_length(pdu, Direction::Response)?;
                Response::Other {
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
        let mut r = Reader::new(pdu, Values::Kept)?;
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
