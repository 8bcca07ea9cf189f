//! Modicon references (`400108`) and protocol addresses (`107`): which table, which address.

use std::fmt;

use thiserror::Error;

use crate::input::number::parse_int;

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

    /// The function that reads this table (01-04).
    pub fn read_function(self) -> u8 {
        match self {
            Table::Coils => 0x01,
            Table::DiscreteInputs => 0x02,
            Table::HoldingRegisters => 0x03,
            Table::InputRegisters => 0x04,
        }
    }

    /// The mbtool command that works on this table as `access` does; `None` for a write to
    /// a read-only table.
    pub fn command(self, access: Access) -> Option<&'static str> {
        Some(match (self, access) {
            (Table::Coils, Access::Read) => "read-coils",
            (Table::DiscreteInputs, Access::Read) => "read-inputs",
            (Table::InputRegisters, Access::Read) => "read-input-registers",
            (Table::HoldingRegisters, Access::Read) => "read-holding",
            (Table::Coils, Access::WriteOne) => "write-coil",
            (Table::Coils, Access::WriteMany) => "write-coils",
            (Table::HoldingRegisters, Access::WriteOne) => "write-register",
            (Table::HoldingRegisters, Access::WriteMany) => "write-registers",
            (Table::DiscreteInputs | Table::InputRegisters, _) => return None,
        })
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

    /// The name with its article, for messages ("an input register").
    pub fn a_name(self) -> &'static str {
        match self {
            Table::Coils => "a coil",
            Table::DiscreteInputs => "a discrete input",
            Table::InputRegisters => "an input register",
            Table::HoldingRegisters => "a holding register",
        }
    }
}

/// The reference of a bit of a register: bit 5 of holding register 107 is `400108.05`.
pub fn bit_reference(table: Table, address: u16, bit: u8) -> String {
    format!("{}.{bit:02}", reference(table, address))
}

/// The 6-digit Modicon reference of a protocol address: holding register 107 is `400108`.
pub fn reference(table: Table, address: u16) -> Reference {
    // Written digit by digit: a sniffer names a reference for nearly every frame, and the
    // formatting machinery costs more than the rest of the description.
    let number = u32::from(address) + 1;
    let mut digits = [b'0' + table.digit(); 6];
    for (digit, power) in digits[1..].iter_mut().zip([10_000, 1_000, 100, 10, 1]) {
        *digit = b'0' + (number / power % 10) as u8;
    }
    Reference(digits)
}

/// A Modicon reference, such as `400108`: always six ASCII digits, kept inline, since a
/// sniffer makes one for nearly every frame.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct Reference([u8; 6]);

impl Reference {
    /// The six digits.
    pub fn as_str(&self) -> &str {
        // Only `reference` makes one, of ASCII digits.
        std::str::from_utf8(&self.0).unwrap_or_default()
    }
}

impl std::ops::Deref for Reference {
    type Target = str;
    fn deref(&self) -> &str {
        self.as_str()
    }
}

impl fmt::Display for Reference {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.as_str())
    }
}

impl fmt::Debug for Reference {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self.as_str(), f)
    }
}

impl PartialEq<&str> for Reference {
    fn eq(&self, other: &&str) -> bool {
        self.as_str() == *other
    }
}

impl From<Reference> for String {
    fn from(reference: Reference) -> String {
        reference.as_str().to_string()
    }
}

impl serde::Serialize for Reference {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(self.as_str())
    }
}

/// Where a bare address number counts from: 0 as the protocol does (`107` is the 108th
/// register), or 1 as register numbers do in many manuals and in mbpoll (`108` is it).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum AddressBase {
    /// Protocol (PDU) addresses, 0-65535.
    #[default]
    Zero,
    /// Register numbers, 1-65536.
    One,
}

impl AddressBase {
    /// The number a protocol address is shown as: 107 is 107 at base 0, 108 at base 1.
    pub fn number(self, address: u16) -> u32 {
        u32::from(address) + self.first()
    }

    /// The smallest number there is: 0 or 1.
    pub fn first(self) -> u32 {
        match self {
            AddressBase::Zero => 0,
            AddressBase::One => 1,
        }
    }

    /// The protocol address a number stands for, if it is one.
    fn address(self, number: u64) -> Option<u16> {
        number
            .checked_sub(u64::from(self.first()))
            .and_then(|address| u16::try_from(address).ok())
    }
}

/// How a bare number given as an address is read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Numbering {
    /// A 5- or 6-digit number of the table is a Modicon reference (`--pdu-addresses` turns
    /// this off, and every number is then counted from `base`).
    pub references: bool,
    /// What any other number counts from.
    pub base: AddressBase,
}

impl Default for Numbering {
    fn default() -> Self {
        Self {
            references: true,
            base: AddressBase::Zero,
        }
    }
}

/// What a command does with a table, which decides the command a wrong reference is sent to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Access {
    /// A read.
    Read,
    /// A write of one coil or register (05, 06).
    WriteOne,
    /// A write of several (15, 16).
    WriteMany,
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
    /// A register number of 0 where numbers count from 1.
    #[error("{0} is no register number: with --address-base 1 they count from 1 (the first register is 1); give --address-base 0 to mean protocol address 0")]
    ZeroNumber(String),
    /// A register number above 65536 where numbers count from 1.
    #[error("register number {0} is out of range 1-65536")]
    NumberOutOfRange(String),
    /// A reference to another table than the command's.
    #[error("{text} is {table} reference: use {command}{hint}")]
    WrongTable {
        /// The reference as typed.
        text: String,
        /// The table it names, with its article.
        table: &'static str,
        /// The command that works on that table as the one given would have.
        command: &'static str,
        /// How to mean a protocol address instead, where the number can be one.
        hint: String,
    },
    /// A reference to item 0 of a table (references count from 1).
    #[error("{text} is not a valid reference: references count from 1 ({digit}00001 is the first){hint}")]
    ZeroReference {
        /// The reference as typed.
        text: String,
        /// Its table's digit.
        digit: u8,
        /// How to mean a plain number instead, where the number can be one.
        hint: String,
    },
    /// A write to a reference of a read-only table.
    #[error("{text} is {table} reference, and that table is read-only: write to coils (0xxxxx) or holding registers (4xxxxx)")]
    ReadOnly {
        /// The reference as typed.
        text: String,
        /// The table it names, with its article.
        table: &'static str,
    },
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
    /// A bit number that is not 00-15.
    #[error("'{0}' names no bit of a register: give .00 to .15, as in 400108.05")]
    BadBit(String),
    /// A bit of a coil or discrete input.
    #[error("{0}: coils and discrete inputs are bits already; a bit reference is of a register (300001.00, 400001.15)")]
    BitOfBits(String),
    /// A range of bit references.
    #[error("{0}: give the first bit and a count instead of a range of bits (400108.05 3)")]
    BitRange(String),
}

/// How to mean `text` as a plain number counted from `base`, where it can be one.
fn pdu_hint(text: &str, base: AddressBase) -> String {
    let meaning = match base {
        AddressBase::Zero => "protocol address",
        AddressBase::One => "register number",
    };
    match numbered_address(text, base) {
        Ok(_) => format!(", or give --pdu-addresses to mean {meaning} {text}"),
        Err(_) => String::new(),
    }
}

/// Splits a bit of a register off an address: `400108.05` is `400108` and bit 5 (bit 0
/// the least significant).
pub fn split_bit(text: &str) -> Result<(&str, Option<u8>), AddressError> {
    let Some((address, bit)) = text.trim().split_once('.') else {
        return Ok((text, None));
    };
    if address.contains('-') || bit.contains('-') {
        return Err(AddressError::BitRange(text.to_string()));
    }
    let number = (1..=2).contains(&bit.len()) && bit.bytes().all(|b| b.is_ascii_digit());
    match bit.parse::<u8>() {
        Ok(bit @ 0..=15) if number => Ok((address, Some(bit))),
        _ => Err(AddressError::BadBit(text.to_string())),
    }
}

/// A 5- or 6-digit decimal Modicon reference: its table and 0-based address; `base` is
/// what a plain number counts from, for the hint of a reference to item 0.
fn as_reference(text: &str, base: AddressBase) -> Option<Result<(Table, u16), AddressError>> {
    let digits = text.trim();
    if !(5..=6).contains(&digits.len()) || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    let first = digits.as_bytes()[0] - b'0';
    let table = Table::from_digit(first)?;
    let number: u32 = digits[1..].parse().ok()?;
    Some(match number {
        0 => Err(AddressError::ZeroReference {
            text: text.to_string(),
            digit: first,
            hint: pdu_hint(text, base),
        }),
        n => u16::try_from(n - 1)
            .map(|address| (table, address))
            .map_err(|_| AddressError::OutOfRange(text.to_string())),
    })
}

/// A bare number counted from `base`, as the protocol address it stands for.
fn numbered_address(text: &str, base: AddressBase) -> Result<u16, AddressError> {
    let value = parse_int(text).map_err(|_| AddressError::NotANumber(text.to_string()))?;
    let number = u64::try_from(value).ok();
    match (number.and_then(|n| base.address(n)), base) {
        (Some(address), _) => Ok(address),
        (None, AddressBase::One) if number == Some(0) => {
            Err(AddressError::ZeroNumber(text.to_string()))
        }
        (None, AddressBase::One) => Err(AddressError::NumberOutOfRange(text.to_string())),
        (None, AddressBase::Zero) => Err(AddressError::OutOfRange(text.to_string())),
    }
}

/// One address for a command that works on `table` as `access` says.
pub fn parse_address(
    text: &str,
    table: Table,
    access: Access,
    numbering: Numbering,
) -> Result<u16, AddressError> {
    if numbering.references {
        if let Some(reference) = as_reference(text, numbering.base) {
            let (found, address) = reference?;
            if found != table {
                let Some(command) = found.command(access) else {
                    return Err(AddressError::ReadOnly {
                        text: text.to_string(),
                        table: found.a_name(),
                    });
                };
                return Err(AddressError::WrongTable {
                    text: text.to_string(),
                    table: found.a_name(),
                    command,
                    hint: pdu_hint(text, numbering.base),
                });
            }
            return Ok(address);
        }
    }
    numbered_address(text, numbering.base)
}

/// One Modicon reference, whose first digit picks the table.
pub fn parse_reference(text: &str) -> Result<(Table, u16), AddressError> {
    as_reference(text, AddressBase::Zero)
        .unwrap_or_else(|| Err(AddressError::NotAReference(text.to_string())))
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
pub fn parse_span(
    text: &str,
    table: Table,
    access: Access,
    numbering: Numbering,
) -> Result<Span, AddressError> {
    parse_range(text, |one| {
        parse_address(one, table, access, numbering).map(|address| (table, address))
    })
}

/// A REFERENCE argument of `read`/`write`: one reference or an inclusive range.
pub fn parse_reference_span(text: &str) -> Result<Span, AddressError> {
    parse_range(text, parse_reference)
}

#[cfg(test)]
mod tests {
    use super::*;

    const STANDARD: Numbering = Numbering {
        references: true,
        base: AddressBase::Zero,
    };
    const PLAIN: Numbering = Numbering {
        references: false,
        base: AddressBase::Zero,
    };
    const FROM_ONE: Numbering = Numbering {
        references: true,
        base: AddressBase::One,
    };

    #[test]
    fn at_base_one_a_bare_number_is_a_register_number() {
        let holding = Table::HoldingRegisters;
        assert_eq!(
            parse_address("108", holding, Access::Read, FROM_ONE),
            Ok(107)
        );
        assert_eq!(
            parse_address("0x6C", holding, Access::Read, FROM_ONE),
            Ok(107)
        );
        assert_eq!(
            parse_address("65536", holding, Access::Read, FROM_ONE),
            Ok(65535)
        );
        // References are 1-based already: the base leaves them alone.
        assert_eq!(
            parse_address("400108", holding, Access::Read, FROM_ONE),
            Ok(107)
        );
        let zero = parse_address("0", holding, Access::Read, FROM_ONE).unwrap_err();
        assert!(zero.to_string().contains("count from 1"), "{zero}");
        let past = parse_address("65537", holding, Access::Read, FROM_ONE).unwrap_err();
        assert_eq!(
            past.to_string(),
            "register number 65537 is out of range 1-65536"
        );
        let span = parse_span("1-10", holding, Access::Read, FROM_ONE).unwrap();
        assert_eq!((span.address, span.count), (0, Some(10)));
        assert_eq!(AddressBase::One.number(107), 108);
        assert_eq!(AddressBase::Zero.number(65535), 65535);
    }

    #[test]
    fn five_and_six_digit_references() {
        let holding = Table::HoldingRegisters;
        assert_eq!(
            parse_address("400108", holding, Access::Read, STANDARD),
            Ok(107)
        );
        assert_eq!(
            parse_address("40108", holding, Access::Read, STANDARD),
            Ok(107)
        );
        assert_eq!(
            parse_address("107", holding, Access::Read, STANDARD),
            Ok(107)
        );
        assert_eq!(
            parse_address("0x6B", holding, Access::Read, STANDARD),
            Ok(107)
        );
        assert_eq!(
            parse_address("000020", Table::Coils, Access::Read, STANDARD),
            Ok(19)
        );
        assert_eq!(
            parse_address("465536", holding, Access::Read, STANDARD),
            Ok(65535)
        );
    }

    #[test]
    fn pdu_addresses_turns_references_off() {
        assert_eq!(
            parse_address("40108", Table::Coils, Access::Read, PLAIN),
            Ok(40108)
        );
    }

    #[test]
    fn a_reference_of_another_table_names_the_right_command() {
        let error = parse_address("400108", Table::Coils, Access::Read, STANDARD).unwrap_err();
        assert!(error.to_string().contains("read-holding"), "{error}");
    }

    #[test]
    fn a_write_names_the_write_command_or_says_the_table_is_read_only() {
        let holding = Table::HoldingRegisters;
        let error = parse_address("400001", Table::Coils, Access::WriteOne, STANDARD).unwrap_err();
        // 400001 is no protocol address (above 65535), so no --pdu-addresses hint.
        assert_eq!(
            error.to_string(),
            "400001 is a holding register reference: use write-register"
        );
        let error = parse_address("000001", holding, Access::WriteMany, STANDARD).unwrap_err();
        assert!(error
            .to_string()
            .starts_with("000001 is a coil reference: use write-coils"));
        let error = parse_address("300009", holding, Access::WriteOne, STANDARD).unwrap_err();
        assert_eq!(
            error.to_string(),
            "300009 is an input register reference, and that table is read-only: write to \
             coils (0xxxxx) or holding registers (4xxxxx)"
        );
    }

    #[test]
    fn reference_zero_offers_the_protocol_address() {
        let error = parse_address("40000", Table::HoldingRegisters, Access::Read, STANDARD);
        assert_eq!(
            error.unwrap_err().to_string(),
            "40000 is not a valid reference: references count from 1 (400001 is the first), \
             or give --pdu-addresses to mean protocol address 40000"
        );
    }

    #[test]
    fn ranges() {
        let span = parse_span(
            "400108-400110",
            Table::HoldingRegisters,
            Access::Read,
            STANDARD,
        )
        .unwrap();
        assert_eq!((span.address, span.count), (107, Some(3)));
        assert!(parse_span(
            "400110-400108",
            Table::HoldingRegisters,
            Access::Read,
            STANDARD
        )
        .is_err());
        assert!(parse_reference_span("400001-300002").is_err());
    }

    #[test]
    fn reference_strings_are_six_digits() {
        assert_eq!(reference(Table::HoldingRegisters, 107), "400108");
        assert_eq!(reference(Table::Coils, 19), "000020");
        assert_eq!(reference(Table::InputRegisters, 65535), "365536");
    }
}
