//! Why a PDU or a frame is not valid. Each message names the field and the numbers involved.

use thiserror::Error;

#[derive(Clone, Debug, Error, PartialEq, Eq)]
pub enum PduError {
    #[error("empty PDU: no function code")]
    Empty,
    #[error("function {function:02X} needs {needed} PDU bytes, the frame carries {actual}")]
    Truncated {
        function: u8,
        needed: usize,
        actual: usize,
    },
    #[error("function {function:02X} carries {expected} PDU bytes, the frame has {actual}")]
    LengthMismatch {
        function: u8,
        expected: usize,
        actual: usize,
    },
    #[error("quantity {quantity} out of range 1-{max}")]
    QuantityOutOfRange { quantity: u16, max: u16 },
    #[error("address {address} + quantity {quantity} goes past 65535")]
    AddressOverflow { address: u16, quantity: u16 },
    #[error("byte count {byte_count} does not match quantity {quantity} (expected {expected})")]
    ByteCountMismatch {
        byte_count: u8,
        quantity: u16,
        expected: usize,
    },
    #[error("byte count {byte_count} is not valid for function {function:02X}")]
    BadByteCount { function: u8, byte_count: u8 },
    #[error("coil value {0:04X} is neither FF00 (on) nor 0000 (off)")]
    BadCoilValue(u16),
    #[error("PDU of {0} bytes is longer than the 253 bytes Modbus allows")]
    TooLong(usize),
    #[error("{0}")]
    BadField(&'static str),
}

#[derive(Clone, Debug, Error, PartialEq, Eq)]
pub enum FrameError {
    #[error("frame of {0} bytes is too short to be a Modbus frame")]
    TooShort(usize),
    #[error("frame of {actual} bytes is longer than the {max} bytes a {mode} frame may have")]
    TooLong {
        mode: &'static str,
        actual: usize,
        max: usize,
    },
    /// Shown in wire order (low byte first), as the bytes stand at the end of the frame.
    #[error("CRC mismatch: the frame ends {:02X} {:02X}, its bytes give {:02X} {:02X}", found & 0xFF, found >> 8, expected & 0xFF, expected >> 8)]
    Crc { found: u16, expected: u16 },
    #[error("LRC mismatch: found {found:02X}, expected {expected:02X}")]
    Lrc { found: u8, expected: u8 },
    #[error("ASCII frame must start with ':'")]
    AsciiNoColon,
    #[error("ASCII frame cut off: a new ':' came before its CR LF")]
    AsciiNoEnd,
    #[error("ASCII frame has {0} characters between ':' and CR LF; it needs an even count")]
    AsciiOddLength(usize),
    #[error("ASCII frame holds a character that is not upper- or lower-case hex: {0:?}")]
    AsciiNotHex(char),
    #[error("MBAP protocol id is {0}, not 0 (Modbus)")]
    MbapProtocol(u16),
    #[error("MBAP length {0} is too short: it counts the unit id and the PDU, at least 2 bytes")]
    MbapTooShort(usize),
    #[error("MBAP length says {declared} bytes follow, the frame has {actual}")]
    MbapLength { declared: usize, actual: usize },
    #[error("{0}")]
    Pdu(#[from] PduError),
}
