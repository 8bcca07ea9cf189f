//! Why an operation cannot be planned.

use thiserror::Error;

use crate::input::hexinput::HexError;
use crate::input::number::NumberError;
use crate::model::address::AddressError;

/// Why an operation cannot be planned: what the user gave is wrong, and nothing is sent.
#[derive(Debug, Error, PartialEq, Eq)]
pub enum PlanError {
    /// The address or range does not read as a reference.
    #[error(transparent)]
    Address(#[from] AddressError),
    /// The slave as typed is no number.
    #[error("slave {0}")]
    Slave(NumberError),
    /// Over TCP, a unit id above 255.
    #[error("unit id {0} is out of range 0-255")]
    UnitId(String),
    /// A read addressed to slave 0, which no slave answers.
    #[error("slave 0 is broadcast, which only writes may use: give the slave's address 1-247")]
    BroadcastRead,
    /// On a serial line, one of the reserved addresses 248-255.
    #[error("slave {0} is reserved on serial lines: give 1-247")]
    ReservedSlave(String),
    /// On a serial line, a slave above 255.
    #[error("slave {0} is out of range 1-247")]
    SlaveRange(String),
    /// A count of zero items.
    #[error("COUNT must be at least 1")]
    ZeroCount,
    /// The count as typed was no number in range.
    #[error("{0}")]
    Count(String),
    /// The items asked for run past the last address of the table.
    #[error("{span} with {count} items goes past the end of the table, which holds 65536")]
    PastEnd {
        /// The address or range as typed.
        span: String,
        /// How many items were asked for.
        count: u32,
    },
    /// `--max-per-request` is below what one value needs (the value's width in registers).
    #[error("--max-per-request must be at least {0}")]
    MaxPerRequest(u16),
    /// A value type other than u16 for coils or discrete inputs.
    #[error("--type applies to registers; {0}s are bits")]
    TypeOfBits(&'static str),
    /// Both a range and a count: one of them says how many.
    #[error("give either a range (400108-400110) or a COUNT, not both")]
    RangeAndCount,
    /// A range that cuts the last multi-register value in two.
    #[error(
        "the range holds {registers} registers, not a whole number of {width}-register values"
    )]
    RangeNotWhole {
        /// Registers in the range.
        registers: u32,
        /// Registers per value of the value type.
        width: u32,
    },
    /// A write with nothing to write.
    #[error("give at least one VALUE to write")]
    NoValues,
    /// A write of a bit of a register with other than one value, or a forced function.
    #[error("a bit of a register takes one value, 1/0/on/off, written with function 22")]
    BitWrite,
    /// A value as typed does not read as the table's or the value type's.
    #[error("{0}")]
    Value(String),
    /// A range whose length differs from the number of values given.
    #[error("the range holds {count} addresses but {values} values were given")]
    RangeValues {
        /// Addresses in the range.
        count: u32,
        /// Values given.
        values: usize,
    },
    /// `--function` names a register write for coils.
    #[error("coils are written with --function 5 (one at a time) or 15 (several)")]
    CoilFunction,
    /// `--function` names a coil write for registers.
    #[error("registers are written with --function 6 (one at a time) or 16 (several)")]
    RegisterFunction,
    /// `write-register` with a value type wider than one register.
    #[error("write-register writes one 16-bit register and a {value_type} value takes {width}: use write-registers")]
    WideRegister {
        /// The value type's name.
        value_type: &'static str,
        /// Registers one value of that type takes.
        width: usize,
    },
    /// The raw PDU is not hex.
    #[error("PDU_HEX: {0}")]
    PduHex(HexError),
    /// The raw PDU has no bytes.
    #[error("PDU_HEX is empty: give at least a function code")]
    EmptyPdu,
    /// A file record or FIFO command's words that break the specification's limits.
    #[error("{0}")]
    Records(String),
    /// The raw PDU's first byte has the exception bit set, so no slave would take it.
    #[error("function code {0:02X} is not a request: give 01-7F")]
    NotRequest(u8),
    /// The raw PDU is longer than a PDU may be.
    #[error("a PDU is at most {max} bytes; this one has {len}")]
    PduTooLong {
        /// The longest PDU the protocol allows.
        max: usize,
        /// The length given.
        len: usize,
    },
}
