//! From a request command's arguments to the requests that carry it out.
//!
//! Every argument is checked here, before anything is sent: a plan either holds every
//! request of the command, or the command line was wrong and nothing happens.

use crate::cli::RequestCommand;
use crate::error::{Error, Result};
use mbtool_core::codec::{limits, Request};
use mbtool_core::model::address::{parse_reference_span, parse_span, Span, Table};
use mbtool_core::model::choice::Choice;
use mbtool_core::model::number::{parse_in_range, parse_int};
use mbtool_core::model::values::{parse_coil, ByteOrder, ValueType};

/// What the options say about addresses, values and request sizes.
#[derive(Clone, Copy, Debug, Default)]
pub struct PlanOptions {
    pub pdu_addresses: bool,
    pub value_type: ValueType,
    pub order: ByteOrder,
    pub max_per_request: Option<u16>,
    /// Over TCP the unit id is 0-255; on a serial line the slave is 1-247 (0 to broadcast).
    pub tcp: bool,
}

/// The requests of one command, in order, and what they read (to label the answers).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Plan {
    pub slave: u8,
    pub requests: Vec<Request>,
    /// For reads: the table and first address, so that answers can carry references.
    pub reads: Option<(Table, u16)>,
}

fn parse_slave(text: &str, is_write: bool, options: &PlanOptions) -> Result<u8> {
    let value = parse_int(text).map_err(|e| Error::usage(format!("slave {e}")))?;
    if options.tcp {
        return u8::try_from(value)
            .map_err(|_| Error::usage(format!("unit id {text} is out of range 0-255")));
    }
    match value {
        1..=247 => Ok(value as u8),
        0 if is_write => Ok(0),
        0 => Err(Error::usage(
            "slave 0 is broadcast, which only writes may use: give the slave's address 1-247",
        )),
        248..=255 => Err(Error::usage(format!(
            "slave {text} is reserved on serial lines: give 1-247"
        ))),
        _ => Err(Error::usage(format!("slave {text} is out of range 1-247"))),
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
        return Err(Error::usage("COUNT must be at least 1"));
    }
    if u32::from(address) + count > 65536 {
        return Err(Error::usage(format!(
            "{span_text} with {count} items goes past address 65535"
        )));
    }
    Ok(())
}

fn per_request(limit: u16, options: &PlanOptions, unit: u16) -> Result<u16> {
    let max = options.max_per_request.map_or(limit, |m| m.min(limit));
    if max < unit.max(1) {
        return Err(Error::usage(format!(
            "--max-per-request must be at least {}",
            unit.max(1)
        )));
    }
    Ok(max)
}

fn register_type(table: Table, options: &PlanOptions) -> Result<ValueType> {
    if table.is_bits() && options.value_type != ValueType::U16 {
        return Err(Error::usage(format!(
            "--type applies to registers; {}s are bits",
            table.name()
        )));
    }
    Ok(options.value_type)
}

fn read_plan(slave: u8, span: Span, count: Option<&str>, options: &PlanOptions) -> Result<Plan> {
    let value_type = register_type(span.table, options)?;
    let width = value_type.width() as u32;
    let items = match (span.count, count) {
        (Some(_), Some(_)) => {
            return Err(Error::usage(
                "give either a range (400108-400110) or a COUNT, not both",
            ))
        }
        (Some(registers), None) => {
            if registers % width != 0 {
                return Err(Error::usage(format!(
                    "the range holds {registers} registers, not a whole number of {width}-register values"
                )));
            }
            registers
        }
        (None, Some(text)) => {
            parse_in_range(text, 1, 65536, "COUNT").map_err(Error::Usage)? as u32 * width
        }
        (None, None) => width,
    };
    check_end(&span.to_string(), span.address, items)?;
    let limit = if span.table.is_bits() {
        limits::MAX_READ_BITS
    } else {
        limits::MAX_READ_REGISTERS
    };
    let max = per_request(limit, options, width as u16)?;
    let requests = runs(span.address, items, max, width as u16)
        .into_iter()
        .map(|(address, quantity)| match span.table {
            Table::Coils => Request::ReadCoils { address, quantity },
            Table::DiscreteInputs => Request::ReadDiscreteInputs { address, quantity },
            Table::InputRegisters => Request::ReadInputRegisters { address, quantity },
            Table::HoldingRegisters => Request::ReadHoldingRegisters { address, quantity },
        })
        .collect();
    Ok(Plan {
        slave,
        requests,
        reads: Some((span.table, span.address)),
    })
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
        .map(|v| parse_coil(v).map_err(Error::Usage))
        .collect()
}

fn parse_registers(values: &[String], options: &PlanOptions) -> Result<Vec<u16>> {
    let mut registers = Vec::with_capacity(values.len());
    for value in values {
        registers.extend(
            options
                .value_type
                .parse(value, options.order)
                .map_err(Error::Usage)?,
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
    span: Span,
    values: &[String],
    style: Option<WriteStyle>,
    options: &PlanOptions,
) -> Result<Plan> {
    let what = span.to_string();
    if !span.table.is_writable() {
        return Err(Error::usage(format!(
            "{what} is a {} reference, and that table is read-only: write to coils (0xxxxx) or holding registers (4xxxxx)",
            span.table.name()
        )));
    }
    if values.is_empty() {
        return Err(Error::usage("give at least one VALUE to write"));
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
        coils.requests(&span, style, options)?
    } else {
        let registers = WriteValues {
            values: parse_registers(values, options)?,
            unit: options.value_type.width() as u16,
            limit: limits::MAX_WRITE_REGISTERS,
            single: |address, value| Request::WriteSingleRegister { address, value },
            multiple: |address, values| Request::WriteMultipleRegisters { address, values },
        };
        registers.requests(&span, style, options)?
    };
    Ok(Plan {
        slave,
        requests,
        reads: None,
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
        span: &Span,
        style: Option<WriteStyle>,
        options: &PlanOptions,
    ) -> Result<Vec<Request>> {
        let count = self.values.len();
        check_span_count(span, count)?;
        check_end(&span.to_string(), span.address, count as u32)?;
        let single = matches!(style, Some(WriteStyle::Single)) || (style.is_none() && count == 1);
        if single {
            return Ok(self
                .values
                .iter()
                .zip(span.address..)
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
        Some(count) if count as usize != values => Err(Error::usage(format!(
            "the range holds {count} addresses but {values} values were given"
        ))),
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
        (Table::Coils, _) => Err(Error::usage(
            "coils are written with --function 5 (one at a time) or 15 (several)",
        )),
        _ => Err(Error::usage(
            "registers are written with --function 6 (one at a time) or 16 (several)",
        )),
    }
}

/// Plans a request command.
pub fn plan(command: &RequestCommand, options: &PlanOptions) -> Result<Plan> {
    use RequestCommand as C;
    let table_span = |address: &str, table| parse_span(address, table, options.pdu_addresses);
    match command {
        C::ReadCoils(a) | C::ReadInputs(a) | C::ReadHolding(a) | C::ReadInputRegisters(a) => {
            let table = command.table().unwrap_or(Table::HoldingRegisters);
            let slave = parse_slave(&a.slave, false, options)?;
            read_plan(
                slave,
                table_span(&a.address, table)?,
                a.count.as_deref(),
                options,
            )
        }
        C::Read(a) => {
            let slave = parse_slave(&a.slave, false, options)?;
            read_plan(
                slave,
                parse_reference_span(&a.address)?,
                a.count.as_deref(),
                options,
            )
        }
        C::WriteCoil(a) => {
            let slave = parse_slave(&a.slave, true, options)?;
            let span = table_span(&a.address, Table::Coils)?;
            write_plan(
                slave,
                span,
                std::slice::from_ref(&a.value),
                Some(WriteStyle::Single),
                options,
            )
        }
        C::WriteRegister(a) => {
            let slave = parse_slave(&a.slave, true, options)?;
            let width = options.value_type.width();
            if width > 1 {
                return Err(Error::usage(format!(
                    "write-register writes one 16-bit register and a {} value takes {width}: use write-registers",
                    options.value_type.name()
                )));
            }
            let span = table_span(&a.address, Table::HoldingRegisters)?;
            write_plan(
                slave,
                span,
                std::slice::from_ref(&a.value),
                Some(WriteStyle::Single),
                options,
            )
        }
        C::WriteCoils(a) => {
            let slave = parse_slave(&a.slave, true, options)?;
            let span = table_span(&a.address, Table::Coils)?;
            write_plan(slave, span, &a.values, Some(WriteStyle::Multiple), options)
        }
        C::WriteRegisters(a) => {
            let slave = parse_slave(&a.slave, true, options)?;
            let span = table_span(&a.address, Table::HoldingRegisters)?;
            write_plan(slave, span, &a.values, Some(WriteStyle::Multiple), options)
        }
        C::Write(a) => {
            let slave = parse_slave(&a.write.slave, true, options)?;
            let span = parse_reference_span(&a.write.address)?;
            let function = a.function.as_deref().and_then(|f| f.parse().ok());
            let style = forced_style(span.table, function)?;
            write_plan(slave, span, &a.write.values, style, options)
        }
        C::Raw(a) => {
            let slave = parse_slave(&a.slave, true, options)?;
            let pdu = mbtool_core::model::hexinput::parse_hex_words(&a.pdu)
                .map_err(|e| Error::usage(format!("PDU_HEX: {e}")))?;
            Ok(Plan {
                slave,
                requests: vec![raw_request(&pdu)?],
                reads: None,
            })
        }
    }
}

/// A raw PDU: typed when it reads as a valid request, otherwise kept as given, so that a
/// device's answer to a malformed request can be tested too.
fn raw_request(pdu: &[u8]) -> Result<Request> {
    let Some((&function, data)) = pdu.split_first() else {
        return Err(Error::usage(
            "PDU_HEX is empty: give at least a function code",
        ));
    };
    if function == 0 || function >= 0x80 {
        return Err(Error::usage(format!(
            "function code {function:02X} is not a request: give 01-7F"
        )));
    }
    if pdu.len() > limits::MAX_PDU {
        return Err(Error::usage(format!(
            "a PDU is at most {} bytes; this one has {}",
            limits::MAX_PDU,
            pdu.len()
        )));
    }
    Ok(Request::decode(pdu).unwrap_or_else(|_| Request::Other {
        function,
        data: data.to_vec(),
    }))
}
