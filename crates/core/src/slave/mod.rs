//! A Modbus slave as data: the four tables of each slave id, and the answer to a request.
//! No I/O: `serve` puts it behind a transport, `--port sim` calls it in process.

pub mod datafile;
pub mod faults;
mod model;
pub mod server;

use std::collections::BTreeMap;

use crate::codec::function;
use crate::codec::{DeviceIdentification, DeviceObject};
use crate::codec::{Exception, ExceptionCode, Pdu, PduError, Request, Response};
pub use model::{DataModel, TableData};

/// What a slave says about itself (report slave id, device identification).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Identity {
    /// Vendor name: device identification object 0.
    pub vendor: String,
    /// Product code: object 1.
    pub product_code: String,
    /// Major and minor revision: object 2.
    pub revision: String,
}

/// The slave id of the manuals' examples: the built-in slave's, and `serve`'s by default.
pub const EXAMPLE_SLAVE: u8 = 17;

/// The vendor name a simulated slave gives by default.
pub const DEFAULT_VENDOR: &str = "mbtool";

impl Default for Identity {
    fn default() -> Self {
        Self {
            vendor: DEFAULT_VENDOR.into(),
            product_code: "mbtool-sim".into(),
            revision: env!("CARGO_PKG_VERSION").into(),
        }
    }
}

/// Counters of the diagnostics function (08), per slave id.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Counters {
    /// Requests answered (an exception counts).
    pub messages: u16,
    /// Exception answers sent.
    pub exceptions: u16,
    /// Broadcasts carried out, never answered.
    pub broadcasts: u16,
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

    /// Handles a request addressed to `slave`. `None`: no answer is due (another slave's
    /// request, or a broadcast, which is carried out by every id but answered by none).
    pub fn handle(&mut self, slave: u8, request: &Request) -> Option<Pdu> {
        if slave == 0 {
            let ids: Vec<u8> = self.models.keys().copied().collect();
            for id in ids {
                self.answer(id, request);
                if let Some(c) = self.counters.get_mut(&id) {
                    c.broadcasts = c.broadcasts.wrapping_add(1);
                }
            }
            return None;
        }
        if !self.answers_for(slave) {
            return None;
        }
        let answer = self.answer(slave, request);
        if let Some(c) = self.counters.get_mut(&slave) {
            c.messages = c.messages.wrapping_add(1);
            if matches!(answer, Pdu::Exception(_)) {
                c.exceptions = c.exceptions.wrapping_add(1);
            }
        }
        Some(answer)
    }

    fn answer(&mut self, slave: u8, request: &Request) -> Pdu {
        let counters = self.counters.get(&slave).copied().unwrap_or_default();
        let Some(model) = self.models.get_mut(&slave) else {
            return exception(request, ExceptionCode::SERVER_DEVICE_FAILURE);
        };
        match respond(model, request, &self.identity, slave, counters) {
            Ok(response) => Pdu::Response(response),
            Err(code) => exception(request, code),
        }
    }
}

/// The exception answering `request`; a request of function 80-FF (possible over TCP) is
/// refused as its function 00-7F.
fn exception(request: &Request, code: ExceptionCode) -> Pdu {
    Pdu::Exception(Exception {
        function: request.function() & !function::EXCEPTION_FLAG,
        code,
    })
}

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
        Request::ReadExceptionStatus => Response::ReadExceptionStatus { status: 0 },
        Request::Diagnostics { sub_function, data } => Response::Diagnostics {
            sub_function: *sub_function,
            data: diagnostics(*sub_function, data, counters)?,
        },
        Request::ReportServerId => {
            let mut data = vec![slave, 0xFF];
            data.extend_from_slice(
                format!(
                    "{} {} {}",
                    identity.vendor, identity.product_code, identity.revision
                )
                .as_bytes(),
            );
            data.truncate(251);
            Response::ReportServerId { data }
        }
        Request::ReadDeviceIdentification {
            read_code,
            object_id,
        } => device_identification(*read_code, *object_id, identity)?,
        // A known function whose request broke its layout: a bad quantity or byte count
        // (03), or, the quantity being good, a range past the last address (02), in the
        // order the specification checks them.
        Request::Other { function, data } if function::has_layout(*function, data) => {
            let pdu = [&[*function], data.as_slice()].concat();
            return Err(match Request::decode(&pdu) {
                Err(PduError::AddressOverflow { .. }) => ExceptionCode::ILLEGAL_DATA_ADDRESS,
                _ => ExceptionCode::ILLEGAL_DATA_VALUE,
            });
        }
        Request::Other { .. } => return Err(ILLEGAL_FUNCTION),
    })
}

/// The diagnostics sub-functions a simple slave keeps: loopback and its counters. A
/// broadcast is a message it received and did not answer.
fn diagnostics(
    sub_function: u16,
    data: &[u8],
    counters: Counters,
) -> Result<Vec<u8>, ExceptionCode> {
    let counter = |value: u16| Ok(value.to_be_bytes().to_vec());
    let received = counters.messages.wrapping_add(counters.broadcasts);
    match sub_function {
        0x0000 | 0x000A => Ok(data.to_vec()),
        0x000B | 0x000E => counter(received),
        0x000C => counter(0),
        0x000D => counter(counters.exceptions),
        0x000F => counter(counters.broadcasts),
        _ => Err(ILLEGAL_FUNCTION),
    }
}

fn device_identification(
    read_code: u8,
    object_id: u8,
    identity: &Identity,
) -> Result<Response, ExceptionCode> {
    let objects = [
        identity.vendor.as_bytes(),
        identity.product_code.as_bytes(),
        identity.revision.as_bytes(),
    ];
    let chosen: Vec<DeviceObject> = match read_code {
        // Basic stream (1) from object_id; regular (2) and extended (3) have nothing more.
        1..=3 => objects
            .iter()
            .enumerate()
            .skip(usize::from(object_id))
            .map(|(id, value)| DeviceObject {
                id: id as u8,
                value: value.to_vec(),
            })
            .collect(),
        4 => match objects.get(usize::from(object_id)) {
            Some(value) => vec![DeviceObject {
                id: object_id,
                value: value.to_vec(),
            }],
            None => return Err(ExceptionCode::ILLEGAL_DATA_ADDRESS),
        },
        _ => return Err(ExceptionCode::ILLEGAL_DATA_VALUE),
    };
    if chosen.is_empty() && read_code != 4 && usize::from(object_id) >= objects.len() {
        return Err(ExceptionCode::ILLEGAL_DATA_ADDRESS);
    }
    Ok(Response::ReadDeviceIdentification(DeviceIdentification {
        read_code,
        conformity: 0x01,
        more_follows: false,
        next_object_id: 0,
        objects: chosen,
    }))
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
    fn diagnostics_counters_count_answers_exceptions_and_broadcasts() {
        let mut slave = Slave::new(&[17], DataModel::default());
        let write = Request::WriteSingleRegister {
            address: 1,
            value: 2,
        };
        assert_eq!(slave.handle(0, &write), None);
        slave.handle(
            17,
            &Request::Other {
                function: 0x41,
                data: vec![],
            },
        );
        // Bus message count: the broadcast and the exception; a request is counted once
        // it has been answered.
        assert_eq!(counter(&mut slave, 0x000B), [0, 2]);
        assert_eq!(counter(&mut slave, 0x000D), [0, 1]);
        assert_eq!(counter(&mut slave, 0x000F), [0, 1]);
    }
}
