//! A Modbus slave as data: the four tables of each slave id, and the answer to a request.
//! No I/O: `serve` puts it behind a transport, `--port sim` calls it in process.

pub mod datafile;
pub mod faults;
mod identity;
mod model;
pub mod server;
pub mod sim;

use std::collections::BTreeMap;

use crate::codec::function;
use crate::codec::{ExceptionCode, Pdu, PduError, Request, Response};
pub use identity::{parse_object, Identity, DEFAULT_VENDOR, MAX_OBJECT_LEN};
pub use model::{DataModel, FifoData, FileData, TableData};

/// The slave id of the manuals' examples: the built-in slave's, and `serve`'s by default.
pub const EXAMPLE_SLAVE: u8 = 17;

/// The counters of the diagnostics function (08), per slave id, as a device keeps them
/// from its last restart or clearing.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Counters {
    /// Frames seen on the line whose checksum holds, whoever they were for (08/0B).
    pub bus_messages: u16,
    /// Frames seen on the line whose checksum failed (08/0C).
    pub bus_errors: u16,
    /// Exception answers sent (08/0D).
    pub exceptions: u16,
    /// Requests addressed to this slave, broadcasts included (08/0E).
    pub slave_messages: u16,
    /// Requests addressed to this slave that got no answer: broadcasts, and answers
    /// left out on purpose (08/0F).
    pub no_response: u16,
}

impl Counters {
    /// The counter a diagnostics sub-function reads, if it reads one.
    fn read(&self, sub_function: u16) -> Option<u16> {
        Some(match sub_function {
            0x000B => self.bus_messages,
            0x000C => self.bus_errors,
            0x000D => self.exceptions,
            0x000E => self.slave_messages,
            0x000F => self.no_response,
            // NAK, busy and character overrun: a simulated slave has none of them.
            0x0010..=0x0012 => 0,
            _ => return None,
        })
    }
}

fn bump(counter: &mut u16) {
    *counter = counter.wrapping_add(1);
}

/// One or more slave ids, each with its data.
#[derive(Clone, Debug)]
pub struct Slave {
    models: BTreeMap<u8, DataModel>,
    counters: BTreeMap<u8, Counters>,
    /// What every id says about itself.
    pub identity: Identity,
}

impl Slave {
    /// A slave answering for each of `ids`, each with a copy of `model`.
    pub fn new(ids: &[u8], model: DataModel) -> Self {
        Self {
            models: ids.iter().map(|id| (*id, model.clone())).collect(),
            counters: ids.iter().map(|id| (*id, Counters::default())).collect(),
            identity: Identity::default(),
        }
    }

    /// The first slave id it answers for (over TCP, unit ids 0 and 255 mean this one).
    pub fn first_id(&self) -> u8 {
        self.models.keys().next().copied().unwrap_or(1)
    }

    /// Whether `slave` is one of its ids.
    pub fn answers_for(&self, slave: u8) -> bool {
        self.models.contains_key(&slave)
    }

    /// A frame seen on the line: every id's bus message counter, or, when its checksum
    /// failed, its bus error counter, counts it.
    pub fn saw_frame(&mut self, checksum_held: bool) {
        for counters in self.counters.values_mut() {
            bump(if checksum_held {
                &mut counters.bus_messages
            } else {
                &mut counters.bus_errors
            });
        }
    }

    /// An answer to `slave` that was due was left out (`--drop`).
    pub fn left_unanswered(&mut self, slave: u8) {
        if let Some(counters) = self.counters.get_mut(&slave) {
            bump(&mut counters.no_response);
        }
    }

    /// The counters of `slave`.
    pub fn counters(&self, slave: u8) -> Option<Counters> {
        self.counters.get(&slave).copied()
    }

    /// Handles a request addressed to `slave`. `None`: no answer is due (another slave's
    /// request, or a broadcast, which is carried out by every id but answered by none).
    pub fn handle(&mut self, slave: u8, request: &Request) -> Option<Pdu> {
        let ids: Vec<u8> = match slave {
            0 => self.models.keys().copied().collect(),
            id if self.answers_for(id) => vec![id],
            _ => return None,
        };
        let mut answer = None;
        for id in ids {
            if let Some(counters) = self.counters.get_mut(&id) {
                bump(&mut counters.slave_messages);
                if slave == 0 {
                    bump(&mut counters.no_response);
                }
            }
            let pdu = self.answer(id, request);
            if let Some(counters) = self.counters.get_mut(&id) {
                if slave != 0 && matches!(pdu, Pdu::Exception(_)) {
                    bump(&mut counters.exceptions);
                }
                // Clear counters (08/0A) leaves them all at zero once it is done.
                if matches!(
                    request,
                    Request::Diagnostics {
                        sub_function: 0x000A,
                        ..
                    }
                ) {
                    *counters = Counters::default();
                }
            }
            answer = (slave != 0).then_some(pdu);
        }
        answer
    }

    fn answer(&mut self, slave: u8, request: &Request) -> Pdu {
        let counters = self.counters.get(&slave).copied().unwrap_or_default();
        let Some(model) = self.models.get_mut(&slave) else {
            return Pdu::refusal(request, ExceptionCode::SERVER_DEVICE_FAILURE);
        };
        match respond(model, request, &self.identity, slave, counters) {
            Ok(response) => Pdu::Response(response),
            Err(code) => Pdu::refusal(request, code),
        }
    }
}

/// The exception answering `request`; a request of function 80-FF (possible over TCP) is
/// refused as its function 00-7F.
const ILLEGAL_FUNCTION: ExceptionCode = ExceptionCode::ILLEGAL_FUNCTION;

fn respond(
    model: &mut DataModel,
    request: &Request,
    identity: &Identity,
    slave: u8,
    counters: Counters,
) -> Result<Response, ExceptionCode> {
    Ok(match request {
        Request::ReadCoils { address, quantity } => Response::ReadCoils {
            packed: crate::codec::bits::pack(&model.coils.read(*address, *quantity)?),
        },
        Request::ReadDiscreteInputs { address, quantity } => Response::ReadDiscreteInputs {
            packed: crate::codec::bits::pack(&model.discrete_inputs.read(*address, *quantity)?),
        },
        Request::ReadHoldingRegisters { address, quantity } => Response::ReadHoldingRegisters {
            values: model.holding_registers.read(*address, *quantity)?,
        },
        Request::ReadInputRegisters { address, quantity } => Response::ReadInputRegisters {
            values: model.input_registers.read(*address, *quantity)?,
        },
        Request::WriteSingleCoil { address, value } => {
            model.coils.write(*address, &[*value])?;
            Response::WriteSingleCoil {
                address: *address,
                value: *value,
            }
        }
        Request::WriteSingleRegister { address, value } => {
            model.holding_registers.write(*address, &[*value])?;
            Response::WriteSingleRegister {
                address: *address,
                value: *value,
            }
        }
        Request::WriteMultipleCoils { address, values } => {
            model.coils.write(*address, values)?;
            Response::WriteMultipleCoils {
                address: *address,
                quantity: values.len() as u16,
            }
        }
        Request::WriteMultipleRegisters { address, values } => {
            model.holding_registers.write(*address, values)?;
            Response::WriteMultipleRegisters {
                address: *address,
                quantity: values.len() as u16,
            }
        }
        Request::MaskWriteRegister {
            address,
            and_mask,
            or_mask,
        } => {
            let current = model.holding_registers.read(*address, 1)?[0];
            let value = (current & and_mask) | (or_mask & !and_mask);
            model.holding_registers.write(*address, &[value])?;
            Response::MaskWriteRegister {
                address: *address,
                and_mask: *and_mask,
                or_mask: *or_mask,
            }
        }
        Request::ReadWriteMultipleRegisters {
            read_address,
            read_quantity,
            write_address,
            values,
        } => {
            // The write happens before the read, as the specification orders it; both
            // ranges are checked before either is carried out.
            model
                .holding_registers
                .check(*write_address, values.len() as u16, true)?;
            model
                .holding_registers
                .check(*read_address, *read_quantity, false)?;
            model.holding_registers.write(*write_address, values)?;
            Response::ReadWriteMultipleRegisters {
                values: model
                    .holding_registers
                    .read(*read_address, *read_quantity)?,
            }
        }
        Request::ReadFileRecord { groups } => Response::ReadFileRecord {
            groups: groups
                .iter()
                .map(|group| model.files.read(group.file, group.record, group.count))
                .collect::<Result<_, _>>()?,
        },
        Request::WriteFileRecord { groups } => {
            // Every group is checked before any is written.
            for group in groups {
                model
                    .files
                    .check_write(group.file, group.record, &group.values)?;
            }
            for group in groups {
                model.files.write(group.file, group.record, &group.values)?;
            }
            Response::WriteFileRecord {
                groups: groups.clone(),
            }
        }
        Request::ReadFifoQueue { address } => Response::ReadFifoQueue {
            values: model.fifos.read(*address)?,
        },
        Request::ReadExceptionStatus => Response::ReadExceptionStatus { status: 0 },
        Request::Diagnostics { sub_function, data } => Response::Diagnostics {
            sub_function: *sub_function,
            data: diagnostics(*sub_function, data, counters)?,
        },
        Request::ReportServerId => Response::ReportServerId {
            data: identity.server_id(slave),
        },
        Request::ReadDeviceIdentification {
            read_code,
            object_id,
        } => identity.answer(*read_code, *object_id)?,
        // A known function whose request broke its layout: a bad quantity or byte count
        // (03), or, the quantity being good, a range past the last address (02), in the
        // order the specification checks them.
        Request::Other { function, data } if function::has_layout(*function, data) => {
            let pdu = [&[*function], data.as_slice()].concat();
            return Err(match Request::decode(&pdu) {
                Err(PduError::AddressOverflow { .. } | PduError::FileReference(_)) => {
                    ExceptionCode::ILLEGAL_DATA_ADDRESS
                }
                _ => ExceptionCode::ILLEGAL_DATA_VALUE,
            });
        }
        Request::Other { .. } => return Err(ILLEGAL_FUNCTION),
    })
}

/// The diagnostics sub-functions a simple slave keeps: return query data, clear
/// counters, and the counters 0B-12.
fn diagnostics(
    sub_function: u16,
    data: &[u8],
    counters: Counters,
) -> Result<Vec<u8>, ExceptionCode> {
    match sub_function {
        0x0000 | 0x000A => Ok(data.to_vec()),
        _ => counters
            .read(sub_function)
            .map(|value| value.to_be_bytes().to_vec())
            .ok_or(ILLEGAL_FUNCTION),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn counter(slave: &mut Slave, sub_function: u16) -> Vec<u8> {
        let request = Request::Diagnostics {
            sub_function,
            data: vec![0, 0],
        };
        match slave.handle(17, &request) {
            Some(Pdu::Response(Response::Diagnostics { data, .. })) => data,
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn diagnostics_counters_count_what_happened_and_clear() {
        let mut slave = Slave::new(&[17], DataModel::default());
        let write = Request::WriteSingleRegister {
            address: 1,
            value: 2,
        };
        for checksum_held in [true, true, false] {
            slave.saw_frame(checksum_held);
        }
        assert_eq!(slave.handle(0, &write), None);
        slave.handle(
            17,
            &Request::Other {
                function: 0x41,
                data: vec![],
            },
        );
        assert_eq!(counter(&mut slave, 0x000B), [0, 2]);
        assert_eq!(counter(&mut slave, 0x000C), [0, 1]);
        assert_eq!(counter(&mut slave, 0x000D), [0, 1]);
        // The broadcast, the exception, the three counter requests before this one and
        // this one.
        assert_eq!(counter(&mut slave, 0x000E), [0, 6]);
        assert_eq!(counter(&mut slave, 0x000F), [0, 1]);
        assert_eq!(counter(&mut slave, 0x0012), [0, 0]);
        counter(&mut slave, 0x000A);
        assert_eq!(slave.counters(17), Some(Counters::default()));
    }
}
