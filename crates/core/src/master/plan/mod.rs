//! From an operation as the user words it (slave, address, count or values, as typed) to
//! the requests that carry it out, split to the protocol's limits.
//!
//! Every word is checked here, before anything is sent: a plan either holds every request
//! of the operation, or the operation was wrong and nothing happens.

mod error;
mod files;
mod masks;

use crate::codec::{limits, Request};
use crate::input::choice::Choice;
use crate::input::number::{parse_in_range, parse_int};
use crate::model::address::{
    parse_reference_span, parse_span, split_bit, Access, AddressError, Numbering, Span, Table,
};
use crate::model::values::{parse_coil, ByteOrder, ValueType};

pub use error::PlanError;
pub use files::{file_read_requests, parse_file_span};

type Result<T, E = PlanError> = std::result::Result<T, E>;

/// An operation as the user words it.
#[derive(Clone, Copy, Debug)]
pub enum Operation<'a> {
    /// Read `count` items (one value by default) from `address`: of `table`, or, for
    /// `None`, of the table its Modicon reference names.
    Read {
        /// The slave address or unit id as typed.
        slave: &'a str,
        /// The address, Modicon reference or range as typed.
        address: &'a str,
        /// The table the command names, if it names one.
        table: Option<Table>,
        /// How many values, as typed.
        count: Option<&'a str>,
    },
    /// Write `values` from `address`, of `table` or of the table its reference names.
    Write {
        /// The slave address or unit id as typed (0 broadcasts).
        slave: &'a str,
        /// The address, Modicon reference or range as typed.
        address: &'a str,
        /// The table the command names, if it names one.
        table: Option<Table>,
        /// The values as typed, in address order.
        values: &'a [String],
        /// Which write function carries them.
        how: How,
    },
    /// Read records of files (20): `FILE:RECORD COUNT` pairs, as typed.
    ReadFile {
        /// The slave address or unit id as typed.
        slave: &'a str,
        /// `FILE:RECORD` and `COUNT`, in turn.
        groups: &'a [String],
    },
    /// Write records of a file (21) from `FILE:RECORD`.
    WriteFile {
        /// The slave address or unit id as typed (0 broadcasts).
        slave: &'a str,
        /// `FILE:RECORD` as typed.
        place: &'a str,
        /// The values as typed.
        values: &'a [String],
    },
    /// Change bits of a register (22): the AND and OR masks, or `REF.BIT=VALUE`.
    MaskWrite {
        /// The slave address or unit id as typed (0 broadcasts).
        slave: &'a str,
        /// The register, or a bit of it, as typed.
        reference: &'a str,
        /// The AND and OR masks, or a bit's value, as typed.
        masks: &'a [String],
    },
    /// Write registers then read registers in one transaction (23).
    ReadWrite {
        /// The slave address or unit id as typed.
        slave: &'a str,
        /// The first register to read and how many values, as typed.
        read: (&'a str, &'a str),
        /// The first register to write, as typed.
        write: &'a str,
        /// The values to write, as typed.
        values: &'a [String],
    },
    /// Read a FIFO queue (24).
    ReadFifo {
        /// The slave address or unit id as typed.
        slave: &'a str,
        /// The queue's pointer register, as typed.
        reference: &'a str,
    },
    /// Send a PDU given as hex words.
    Raw {
        /// The slave address or unit id as typed.
        slave: &'a str,
        /// The PDU as hex words, function code first.
        pdu: &'a [String],
    },
}

/// Which write function carries the values.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum How {
    /// One request per value (05, 06).
    Single,
    /// As few requests as the limits allow (15, 16).
    Multiple,
    /// One 16-bit register (06): a wider value type is refused.
    OneRegister,
    /// As a function code asks (5, 6, 15, 16), or by the number of values.
    Function(Option<u8>),
}

/// What the options say about addresses, values and request sizes.
#[derive(Clone, Copy, Debug, Default)]
pub struct PlanOptions {
    /// How a bare number given as an address is read.
    pub numbering: Numbering,
    /// How registers are read as values.
    pub value_type: ValueType,
    /// The order of bytes and words in a multi-register value.
    pub order: ByteOrder,
    /// At most this many items per request, below the protocol's limit.
    pub max_per_request: Option<u16>,
    /// Over TCP the unit id is 0-255; on a serial line the slave is 1-247 (0 to broadcast).
    pub tcp: bool,
}

/// The requests of one command, in order, and what they read (to label the answers).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Plan {
    /// The slave every request goes to.
    pub slave: u8,
    /// The requests, in address order.
    pub requests: Vec<Request>,
    /// For reads: the table and first address, so that answers can carry references.
    pub reads: Option<(Table, u16)>,
    /// For a read of bits of registers (`400108.05 3`): which bits of what is read.
    pub bits: Option<RegisterBits>,
}

/// Bits of registers read: `count` bits from bit `first` of the first register read,
/// running on into the registers after it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RegisterBits {
    /// The first bit, 0 the least significant.
    pub first: u8,
    /// How many bits.
    pub count: u32,
}

/// The slave a command addresses: 1-247 on a serial line (0, broadcast, for writes
/// only), any unit id 0-255 over TCP.
pub fn parse_slave(text: &str, is_write: bool, tcp: bool) -> Result<u8> {
    let value = parse_int(text).map_err(PlanError::Slave)?;
    if tcp {
        return u8::try_from(value).map_err(|_| PlanError::UnitId(text.to_string()));
    }
    match value {
        1..=247 => Ok(value as u8),
        0 if is_write => Ok(0),
        0 => Err(PlanError::BroadcastRead),
        248..=255 => Err(PlanError::ReservedSlave(text.to_string())),
        _ => Err(PlanError::SlaveRange(text.to_string())),
    }
}

/// Splits `count` items from `address` into runs of at most `max`, keeping runs a multiple
/// of `unit` so that no value wider than one register is cut in two.
fn runs(address: u16, count: u32, max: u16, unit: u16) -> Vec<(u16, u16)> {
    let step = u32::from(max - max % unit);
    let mut out = Vec::new();
    let mut done = 0u32;
    while done < count {
        let n = step.min(count - done);
        // address + count <= 65536 was checked, so both fit.
        out.push(((u32::from(address) + done) as u16, n as u16));
        done += n;
    }
    out
}

fn check_end(span_text: &str, address: u16, count: u32) -> Result<()> {
    if count == 0 {
        return Err(PlanError::ZeroCount);
    }
    if u32::from(address) + count > 65536 {
        return Err(PlanError::PastEnd {
            span: span_text.to_string(),
            count,
        });
    }
    Ok(())
}

fn per_request(limit: u16, options: PlanOptions, unit: u16) -> Result<u16> {
    let max = options.max_per_request.map_or(limit, |m| m.min(limit));
    if max < unit.max(1) {
        return Err(PlanError::MaxPerRequest(unit.max(1)));
    }
    Ok(max)
}

fn register_type(table: Table, options: PlanOptions) -> Result<ValueType> {
    if table.is_bits() && options.value_type != ValueType::U16 {
        return Err(PlanError::TypeOfBits(table.name()));
    }
    Ok(options.value_type)
}

fn read_plan(
    slave: u8,
    (text, span): (&str, Span),
    count: Option<&str>,
    options: PlanOptions,
) -> Result<Plan> {
    let value_type = register_type(span.table, options)?;
    let width = value_type.width() as u32;
    let items = match (span.count, count) {
        (Some(_), Some(_)) => return Err(PlanError::RangeAndCount),
        (Some(registers), None) => {
            if registers % width != 0 {
                return Err(PlanError::RangeNotWhole { registers, width });
            }
            registers
        }
        (None, Some(text)) => {
            parse_in_range(text, 1, 65536, "COUNT").map_err(PlanError::Count)? as u32 * width
        }
        (None, None) => width,
    };
    check_end(text, span.address, items)?;
    let limit = if span.table.is_bits() {
        limits::MAX_READ_BITS
    } else {
        limits::MAX_READ_REGISTERS
    };
    let max = per_request(limit, options, width as u16)?;
    let requests = runs(span.address, items, max, width as u16)
        .into_iter()
        .map(|(address, quantity)| read_request(span.table, address, quantity))
        .collect();
    Ok(Plan {
        slave,
        requests,
        reads: Some((span.table, span.address)),
        bits: None,
    })
}

/// A read of `count` bits of registers from bit `first` of the register `span` names.
fn bit_read_plan(
    slave: u8,
    (text, span): (&str, Span),
    first: u8,
    count: Option<&str>,
    options: PlanOptions,
) -> Result<Plan> {
    if span.table.is_bits() {
        return Err(AddressError::BitOfBits(format!("{text}.{first:02}")).into());
    }
    let count = match count {
        Some(text) => {
            parse_in_range(text, 1, 65536 * 16, "COUNT").map_err(PlanError::Count)? as u32
        }
        None => 1,
    };
    let registers = (u32::from(first) + count).div_ceil(16);
    check_end(text, span.address, registers)?;
    let max = per_request(limits::MAX_READ_REGISTERS, options, 1)?;
    let requests = runs(span.address, registers, max, 1)
        .into_iter()
        .map(|(address, quantity)| read_request(span.table, address, quantity))
        .collect();
    Ok(Plan {
        slave,
        requests,
        reads: Some((span.table, span.address)),
        bits: Some(RegisterBits { first, count }),
    })
}

/// A write of one bit of a holding register: function 22 (mask write register) changes that
/// bit alone.
fn bit_write_plan(
    slave: u8,
    (text, span): (&str, Span),
    bit: u8,
    values: &[String],
) -> Result<Plan> {
    if span.table.is_bits() {
        return Err(AddressError::BitOfBits(format!("{text}.{bit:02}")).into());
    }
    if !span.table.is_writable() {
        return Err(AddressError::ReadOnly {
            text: text.to_string(),
            table: span.table.a_name(),
        }
        .into());
    }
    let [value] = values else {
        return Err(PlanError::BitWrite);
    };
    let on = parse_coil(value).map_err(|_| PlanError::BitWrite)?;
    let mask = 1u16 << bit;
    Ok(Plan {
        slave,
        requests: vec![Request::MaskWriteRegister {
            address: span.address,
            and_mask: !mask,
            or_mask: if on { mask } else { 0 },
        }],
        reads: None,
        bits: None,
    })
}

/// The request that reads `quantity` items of `table` from `address`.
pub fn read_request(table: Table, address: u16, quantity: u16) -> Request {
    match table {
        Table::Coils => Request::ReadCoils { address, quantity },
        Table::DiscreteInputs => Request::ReadDiscreteInputs { address, quantity },
        Table::InputRegisters => Request::ReadInputRegisters { address, quantity },
        Table::HoldingRegisters => Request::ReadHoldingRegisters { address, quantity },
    }
}

/// Coil values: each on/off/1/0/true/false, or one bit string such as `10110`.
fn parse_coils(values: &[String]) -> Result<Vec<bool>> {
    if let [bits] = values {
        if bits.len() > 1 && bits.bytes().all(|b| b == b'0' || b == b'1') {
            return Ok(bits.bytes().map(|b| b == b'1').collect());
        }
    }
    values
        .iter()
        .map(|v| parse_coil(v).map_err(PlanError::Value))
        .collect()
}

fn parse_registers(values: &[String], options: PlanOptions) -> Result<Vec<u16>> {
    let mut registers = Vec::with_capacity(values.len());
    for value in values {
        registers.extend(
            options
                .value_type
                .parse(value, options.order)
                .map_err(PlanError::Value)?,
        );
    }
    Ok(registers)
}

/// How a write is carried: one value per request (05/06) or many (15/16).
#[derive(Clone, Copy, PartialEq, Eq)]
enum WriteStyle {
    Single,
    Multiple,
}

fn write_plan(
    slave: u8,
    (text, span): (&str, Span),
    values: &[String],
    style: Option<WriteStyle>,
    options: PlanOptions,
) -> Result<Plan> {
    if !span.table.is_writable() {
        return Err(AddressError::ReadOnly {
            text: text.to_string(),
            table: span.table.a_name(),
        }
        .into());
    }
    if values.is_empty() {
        return Err(PlanError::NoValues);
    }
    let requests = if span.table == Table::Coils {
        register_type(span.table, options)?;
        let coils = WriteValues {
            values: parse_coils(values)?,
            unit: 1,
            limit: limits::MAX_WRITE_BITS,
            single: |address, value| Request::WriteSingleCoil { address, value },
            multiple: |address, values| Request::WriteMultipleCoils { address, values },
        };
        coils.requests(text, &span, style, options)?
    } else {
        let registers = WriteValues {
            values: parse_registers(values, options)?,
            unit: options.value_type.width() as u16,
            limit: limits::MAX_WRITE_REGISTERS,
            single: |address, value| Request::WriteSingleRegister { address, value },
            multiple: |address, values| Request::WriteMultipleRegisters { address, values },
        };
        registers.requests(text, &span, style, options)?
    };
    Ok(Plan {
        slave,
        requests,
        reads: None,
        bits: None,
    })
}

/// Values to write to one table, and how that table's write requests are made.
struct WriteValues<T> {
    values: Vec<T>,
    /// Registers per value: a request never cuts a value in two.
    unit: u16,
    limit: u16,
    single: fn(u16, T) -> Request,
    multiple: fn(u16, Vec<T>) -> Request,
}

impl<T: Copy> WriteValues<T> {
    fn requests(
        &self,
        text: &str,
        span: &Span,
        style: Option<WriteStyle>,
        options: PlanOptions,
    ) -> Result<Vec<Request>> {
        let count = self.values.len();
        check_span_count(span, count)?;
        check_end(text, span.address, count as u32)?;
        let single = matches!(style, Some(WriteStyle::Single)) || (style.is_none() && count == 1);
        if single {
            return Ok(self
                .values
                .iter()
                .zip(span.address..=u16::MAX)
                .map(|(value, address)| (self.single)(address, *value))
                .collect());
        }
        let max = per_request(self.limit, options, self.unit)?;
        let mut rest = self.values.as_slice();
        Ok(runs(span.address, count as u32, max, self.unit)
            .into_iter()
            .map(|(address, quantity)| {
                let (chunk, after) = rest.split_at(usize::from(quantity));
                rest = after;
                (self.multiple)(address, chunk.to_vec())
            })
            .collect())
    }
}

/// A range given to a write must hold exactly the values given.
fn check_span_count(span: &Span, values: usize) -> Result<()> {
    match span.count {
        Some(count) if count as usize != values => Err(PlanError::RangeValues { count, values }),
        _ => Ok(()),
    }
}

/// The write style `--function` forces, checked against the table.
fn forced_style(table: Table, function: Option<u8>) -> Result<Option<WriteStyle>> {
    let Some(function) = function else {
        return Ok(None);
    };
    match (table, function) {
        (Table::Coils, 5) | (Table::HoldingRegisters, 6) => Ok(Some(WriteStyle::Single)),
        (Table::Coils, 15) | (Table::HoldingRegisters, 16) => Ok(Some(WriteStyle::Multiple)),
        (Table::Coils, _) => Err(PlanError::CoilFunction),
        _ => Err(PlanError::RegisterFunction),
    }
}

/// Plans an operation.
pub fn plan(operation: &Operation, options: PlanOptions) -> Result<Plan> {
    let span = |address, table: Option<Table>, access| -> Result<(&str, Span)> {
        let span = match table {
            Some(table) => parse_span(address, table, access, options.numbering),
            None => parse_reference_span(address),
        };
        Ok((address, span?))
    };
    match *operation {
        Operation::Read {
            slave,
            address,
            table,
            count,
        } => {
            let slave = parse_slave(slave, false, options.tcp)?;
            match split_bit(address)? {
                (address, Some(first)) => {
                    let span = span(address, table, Access::Read)?;
                    bit_read_plan(slave, span, first, count, options)
                }
                (_, None) => read_plan(slave, span(address, table, Access::Read)?, count, options),
            }
        }
        Operation::Write {
            slave,
            address,
            table,
            values,
            how,
        } => {
            let slave = parse_slave(slave, true, options.tcp)?;
            // A bit may be given its value in place: 400108.05=1.
            let assigned;
            let (address, values) = match address.split_once('=') {
                Some((address, value)) if values.is_empty() => {
                    assigned = [value.to_string()];
                    (address, &assigned[..])
                }
                _ => (address, values),
            };
            if let (address, Some(bit)) = split_bit(address)? {
                if matches!(how, How::Function(Some(function)) if function != 22) {
                    return Err(PlanError::BitWrite);
                }
                let span = span(address, table, Access::WriteOne)?;
                return bit_write_plan(slave, span, bit, values);
            }
            if how == How::Function(Some(22)) {
                return Err(PlanError::Records(
                    "--function 22 writes a bit of a register: give one as 400108.05=1".into(),
                ));
            }
            if how == How::OneRegister {
                let width = options.value_type.width();
                if width > 1 {
                    return Err(PlanError::WideRegister {
                        value_type: options.value_type.name(),
                        width,
                    });
                }
            }
            let access = match how {
                How::Multiple => Access::WriteMany,
                _ => Access::WriteOne,
            };
            let span = span(address, table, access)?;
            let style = match how {
                How::Single | How::OneRegister => Some(WriteStyle::Single),
                How::Multiple => Some(WriteStyle::Multiple),
                How::Function(function) => forced_style(span.1.table, function)?,
            };
            write_plan(slave, span, values, style, options)
        }
        Operation::ReadFile { slave, groups } => {
            files::read_file_plan(parse_slave(slave, false, options.tcp)?, groups, options)
        }
        Operation::WriteFile {
            slave,
            place,
            values,
        } => files::write_file_plan(
            parse_slave(slave, true, options.tcp)?,
            place,
            values,
            options,
        ),
        Operation::ReadFifo { slave, reference } => {
            files::read_fifo_plan(parse_slave(slave, false, options.tcp)?, reference, options)
        }
        Operation::MaskWrite {
            slave,
            reference,
            masks,
        } => masks::mask_write_plan(
            parse_slave(slave, true, options.tcp)?,
            reference,
            masks,
            options,
        ),
        Operation::ReadWrite {
            slave,
            read,
            write,
            values,
        } => masks::read_write_plan(
            parse_slave(slave, false, options.tcp)?,
            read,
            write,
            values,
            options,
        ),
        Operation::Raw { slave, pdu } => {
            let slave = parse_slave(slave, true, options.tcp)?;
            let pdu = crate::input::hexinput::parse_hex_words(pdu).map_err(PlanError::PduHex)?;
            Ok(Plan {
                slave,
                requests: vec![raw_request(&pdu)?],
                reads: None,
                bits: None,
            })
        }
    }
}

/// A raw PDU: typed when it reads as a valid request, otherwise kept as given, so that a
/// device's answer to a malformed request can be tested too.
fn raw_request(pdu: &[u8]) -> Result<Request> {
    let Some((&function, data)) = pdu.split_first() else {
        return Err(PlanError::EmptyPdu);
    };
    if function == 0 || function >= 0x80 {
        return Err(PlanError::NotRequest(function));
    }
    if pdu.len() > limits::MAX_PDU {
        return Err(PlanError::PduTooLong {
            max: limits::MAX_PDU,
            len: pdu.len(),
        });
    }
    Ok(Request::decode(pdu).unwrap_or_else(|_| Request::Other {
        function,
        data: data.to_vec(),
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Words as a command line splits them.
    pub(super) fn words(text: &str) -> Vec<String> {
        text.split_whitespace().map(String::from).collect()
    }

    fn read(address: &str, count: Option<&str>, options: PlanOptions) -> Result<Plan> {
        plan(
            &Operation::Read {
                slave: "17",
                address,
                table: None,
                count,
            },
            options,
        )
    }

    #[test]
    fn a_long_read_is_split_at_the_limit_without_cutting_a_value() {
        let options = PlanOptions {
            value_type: ValueType::F32,
            max_per_request: Some(5),
            ..PlanOptions::default()
        };
        let plan = read("400001", Some("4"), options).unwrap();
        // Four f32 values are eight registers; five per request would cut one in two.
        assert_eq!(
            plan.requests,
            [
                Request::ReadHoldingRegisters {
                    address: 0,
                    quantity: 4
                },
                Request::ReadHoldingRegisters {
                    address: 4,
                    quantity: 4
                },
            ]
        );
        assert_eq!(plan.reads, Some((Table::HoldingRegisters, 0)));
    }

    #[test]
    fn coils_as_a_bit_string_are_one_write() {
        let values = ["10110".to_string()];
        let plan = plan(
            &Operation::Write {
                slave: "0",
                address: "000020",
                table: None,
                values: &values,
                how: How::Function(None),
            },
            PlanOptions::default(),
        )
        .unwrap();
        assert_eq!(plan.slave, 0);
        assert_eq!(
            plan.requests,
            [Request::WriteMultipleCoils {
                address: 19,
                values: vec![true, false, true, true, false]
            }]
        );
    }

    /// The last address of a table is written like any other, one request a value.
    #[test]
    fn the_last_address_can_be_written() {
        for (address, how) in [("465536", How::Single), ("065536", How::Function(None))] {
            let values = ["1".to_string()];
            let plan = plan(
                &Operation::Write {
                    slave: "17",
                    address,
                    table: None,
                    values: &values,
                    how,
                },
                PlanOptions::default(),
            )
            .unwrap();
            assert!(
                matches!(
                    plan.requests[..],
                    [Request::WriteSingleRegister { address: 65535, .. }
                        | Request::WriteSingleCoil { address: 65535, .. }]
                ),
                "{address}: {:?}",
                plan.requests
            );
        }
    }

    #[test]
    fn what_is_wrong_is_said_before_anything_is_sent() {
        let options = PlanOptions::default();
        assert_eq!(
            read("400108", Some("0"), options),
            Err(PlanError::Count("COUNT 0 is out of range 1-65536".into()))
        );
        assert_eq!(
            read("465536", Some("2"), options),
            Err(PlanError::PastEnd {
                span: "465536".into(),
                count: 2
            })
        );
        let broadcast_read = plan(
            &Operation::Read {
                slave: "0",
                address: "400108",
                table: None,
                count: None,
            },
            options,
        );
        assert_eq!(broadcast_read, Err(PlanError::BroadcastRead));
        let raw = plan(
            &Operation::Raw {
                slave: "17",
                pdu: &["83".to_string()],
            },
            options,
        );
        assert_eq!(raw, Err(PlanError::NotRequest(0x83)));
    }

    #[test]
    fn bits_of_registers_read_the_registers_they_run_over_and_write_with_22() {
        let plan = read("400108.14", Some("4"), PlanOptions::default()).unwrap();
        assert_eq!(
            plan.requests,
            [Request::ReadHoldingRegisters {
                address: 107,
                quantity: 2
            }]
        );
        assert_eq!(
            plan.bits,
            Some(RegisterBits {
                first: 14,
                count: 4
            })
        );
        let write = plan_of(&Operation::Write {
            slave: "17",
            address: "400010.03",
            table: None,
            values: &["on".to_string()],
            how: How::Function(None),
        });
        assert_eq!(
            write.unwrap().requests,
            [Request::MaskWriteRegister {
                address: 9,
                and_mask: 0xFFF7,
                or_mask: 0x0008
            }]
        );
        assert!(matches!(
            read("000020.01", None, PlanOptions::default()),
            Err(PlanError::Address(AddressError::BitOfBits(_)))
        ));
        assert!(matches!(
            read("400001.00-400001.07", None, PlanOptions::default()),
            Err(PlanError::Address(AddressError::BitRange(_)))
        ));
    }

    fn plan_of(operation: &Operation) -> Result<Plan> {
        plan(operation, PlanOptions::default())
    }
}
