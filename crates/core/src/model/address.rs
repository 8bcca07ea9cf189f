//! Modicon references (`400108`) and protocol addresses (`107`): which table, which address.

use std::fmt;

use thiserror::Error;

use crate::model::number::parse_int;

/// The four data tables of Modbus.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Table {
    /// Read-write bits: references 0xxxxx.
    Coils,
    /// Read-only bits: references 1xxxxx.
    DiscreteInputs,
    /// Read-only 16-bit registers: references 3xxxxx.
    InputRegisters,
    /// Read-write 16-bit registers: references 4xxxxx.
    HoldingRegisters,
}

impl Table {
    /// The first digit of the table's Modicon references.
    pub fn digit(self) -> u8 {
        match self {
            Table::Coils => 0,
            Table::DiscreteInputs => 1,
            Table::InputRegisters => 3,
            Table::HoldingRegisters => 4,
        }
    }

    /// The table whose Modicon references start with `digit` (0, 1, 3 or 4).
    pub fn from_digit(digit: u8) -> Option<Table> {
        match digit {
            0 => Some(Table::Coils),
            1 => Some(Table::DiscreteInputs),
            3 => Some(Table::InputRegisters),
            4 => Some(Table::HoldingRegisters),
            _ => None,
        }
    }

    /// The mbtool command that reads this table.
    pub fn read_command(self) -> &'static str {
        match self {
            Table::Coils => "read-coils",
            Table::DiscreteInputs => "read-inputs",
            Table::InputRegisters => "read-input-registers",
            Table::HoldingRegisters => "read-holding",
        }
    }

    /// Coils and discrete inputs hold bits; the other two hold registers.
    pub fn is_bits(self) -> bool {
        matches!(self, Table::Coils | Table::DiscreteInputs)
    }

    /// Coils and holding registers can be written.
    pub fn is_writable(self) -> bool {
        matches!(self, Table::Coils | Table::HoldingRegisters)
    }

    /// The table a read or write function code works on.
    pub fn of_function(function: u8) -> Option<Table> {
        use crate::codec::function::*;
        match function {
            READ_COILS | WRITE_SINGLE_COIL | WRITE_MULTIPLE_COILS => Some(Table::Coils),
            READ_DISCRETE_INPUTS => Some(Table::DiscreteInputs),
            READ_INPUT_REGISTERS => Some(Table::InputRegisters),
            READ_HOLDING_REGISTERS
            | WRITE_SINGLE_REGISTER
            | WRITE_MULTIPLE_REGISTERS
            | MASK_WRITE_REGISTER
            | READ_WRITE_MULTIPLE_REGISTERS => Some(Table::HoldingRegisters),
            _ => None,
        }
    }

    /// The table's name for one item, as messages use it ("holding register").
    pub fn name(self) -> &'static str {
        match self {
            Table::Coils => "coil",
            Table::DiscreteInputs => "discrete input",
            Table::InputRegisters => "input register",
            Table::HoldingRegisters => "holding register",
        }
    }
}

/// The 6-digit Modicon reference of a protocol address: holding register 107 is `400108`.
pub fn reference(table: Table, address: u16) -> String {
    format!("{}{:05}", table.digit(), u32::from(address) + 1)
}

/// A run of addresses in one table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Span {
    /// The table the addresses are in.
    pub table: Table,
    /// The first address, 0-based.
    pub address: u16,
    /// Given by a range (`400108-400110`); otherwise the COUNT argument decides.
    pub count: Option<u32>,
}

impl fmt::Display for Span {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", reference(self.table, self.address))
    }
}

/// Why an address or range as typed names no addresses.
#[derive(Clone, Debug, Error, PartialEq, Eq)]
pub enum AddressError {
    /// Neither a reference nor a number.
    #[error("'{0}' is not an address: give a Modicon reference (400108) or a protocol address (107, 0x6B)")]
    NotANumber(String),
    /// A reference to another table than the command's.
    #[error("{text} is a {table} reference: use {command}{hint}")]
    WrongTable {
        /// The reference as typed.
        text: String,
        /// The table it names.
        table: &'static str,
        /// The command that reads that table.
        command: &'static str,
        /// How to mean a protocol address instead, where the number can be one.
        hint: String,
    },
    /// A reference to item 0 of a table (references count from 1).
    #[error("{0} is not a valid reference: references count from 1 ({1}00001 is the first)")]
    ZeroReference(String, u8),
    /// A protocol address above 65535.
    #[error("address {0} is out of range 0-65535")]
    OutOfRange(String),
    /// A number that should be a reference and is not one: no table digit, or too many digits.
    #[error("'{0}' is not a Modicon reference: give 5 or 6 digits whose first is 0 (coils), 1 (discrete inputs), 3 (input registers) or 4 (holding registers)")]
    NotAReference(String),
    /// A range whose end comes before its start.
    #[error("range {0} ends before it starts")]
    BackwardRange(String),
    /// A range whose ends are in different tables.
    #[error("range {0} spans two tables")]
    MixedRange(String),
}

/// A 5- or 6-digit decimal Modicon reference: its table and 0-based address.
fn as_reference(text: &str) -> Option<Result<(Table, u16), AddressError>> {
    let digits = text.trim();
    if !(5..=6).contains(&digits.len()) || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    let first = digits.as_bytes()[0] - b'0';
    let table = Table::from_digit(first)?;
    let number: u32 = digits[1..].parse().ok()?;
    Some(match number {
        0 => Err(AddressError::ZeroReference(text.to_string(), first)),
        n => u16::try_from(n - 1)
            .map(|address| (table, address))
            .map_err(|_| AddressError::OutOfRange(text.to_string())),
    })
}

fn protocol_address(text: &str) -> Result<u16, AddressError> {
    let value = parse_int(text).map_err(|_| AddressError::NotANumber(text.to_string()))?;
    u16::try_from(value).map_err(|_| AddressError::OutOfRange(text.to_string()))
}

/// One address for a command that works on `table`.
pub fn parse_address(text: &str, table: Table, pdu_addresses: bool) -> Result<u16, AddressError> {
    if !pdu_addresses {
        if let Some(reference) = as_reference(text) {
            let (found, address) = reference?;
            if found != table {
                let hint = match protocol_address(text) {
                    Ok(_) => format!(", or --pdu-addresses to mean protocol address {text}"),
                    Err(_) => String::new(),
                };
                return Err(AddressError::WrongTable {
                    text: text.to_string(),
                    table: found.name(),
                    command: found.read_command(),
                    hint,
                });
            }
            return Ok(address);
        }
    }
    protocol_address(text)
}

/// One Modicon reference, whose first digit picks the table.
pub fn parse_reference(text: &str) -> Result<(Table, u16), AddressError> {
    as_reference(text).unwrap_or_else(|| Err(AddressError::NotAReference(text.to_string())))
}

/// `first-last` as a start and an inclusive count, both ends parsed by `one`.
fn parse_range<F>(text: &str, one: F) -> Result<Span, AddressError>
where
    F: Fn(&str) -> Result<(Table, u16), AddressError>,
{
    match text.split_once('-') {
        Some((first, last)) if !first.is_empty() => {
            let (table, start) = one(first)?;
            let (end_table, end) = one(last)?;
            if end_table != table {
                return Err(AddressError::MixedRange(text.to_string()));
            }
            let span = end
                .checked_sub(start)
                .ok_or_else(|| AddressError::BackwardRange(text.to_string()))?;
            Ok(Span {
                table,
                address: start,
                count: Some(u32::from(span) + 1),
            })
        }
        _ => one(text).map(|(table, address)| Span {
            table,
            address,
            count: None,
        }),
    }
}

/// An ADDRESS argument of a table command: one address or an inclusive range.
pub fn parse_span(text: &str, table: Table, pdu_addresses: bool) -> Result<Span, AddressError> {
    parse_range(text, |one| {
        parse_address(one, table, pdu_addresses).map(|address| (table, address))
    })
}

/// A REFERENCE argument of `read`/`write`: one reference or an inclusive range.
pub fn parse_reference_span(text: &str) -> Result<Span, AddressError> {
    parse_range(text, parse_reference)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn five_and_six_digit_references() {
        let holding = Table::HoldingRegisters;
        assert_eq!(parse_address("400108", holding, false), Ok(107));
        assert_eq!(parse_address("40108", holding, false), Ok(107));
        assert_eq!(parse_address("107", holding, false), Ok(107));
        assert_eq!(parse_address("0x6B", holding, false), Ok(107));
        assert_eq!(parse_address("000020", Table::Coils, false), Ok(19));
        assert_eq!(parse_address("465536", holding, false), Ok(65535));
    }

    #[test]
    fn pdu_addresses_turns_references_off() {
        assert_eq!(parse_address("40108", Table::Coils, true), Ok(40108));
    }

    #[test]
    fn a_reference_of_another_table_names_the_right_command() {
        let error = parse_address("400108", Table::Coils, false).unwrap_err();
        assert!(error.to_string().contains("read-holding"), "{error}");
    }

    #[test]
    fn ranges() {
        let span = parse_span("400108-400110", Table::HoldingRegisters, false).unwrap();
        assert_eq!((span.address, span.count), (107, Some(3)));
        assert!(parse_span("400110-400108", Table::HoldingRegisters, false).is_err());
        assert!(parse_reference_span("400001-300002").is_err());
    }

    #[test]
    fn reference_strings_are_six_digits() {
        assert_eq!(reference(Table::HoldingRegisters, 107), "400108");
        assert_eq!(reference(Table::Coils, 19), "000020");
        assert_eq!(reference(Table::InputRegisters, 65535), "365536");
    }
}
