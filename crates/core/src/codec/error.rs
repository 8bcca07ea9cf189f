//! Why a PDU or a frame is not valid. Each message names the field and the numbers involved.

use thiserror::Error;

/// Why a PDU does not follow its function's layout or breaks a protocol limit.
#[derive(Clone, Debug, Error, PartialEq, Eq)]
pub enum PduError {
    /// The PDU holds no bytes at all, not even a function code.
    #[error("empty PDU: no function code")]
    Empty,
    /// The PDU ends before a field its function requires.
    #[error("function {function} needs {needed} PDU bytes, the frame carries {actual}")]
    Truncated {
        /// The function code of the PDU.
        function: u8,
        /// The PDU length, function code included, that the next field needs.
        needed: usize,
        /// The PDU length the frame carries.
        actual: usize,
    },
    /// The PDU is longer or shorter than its layout and byte count say.
    #[error("function {function} carries {expected} PDU bytes, the frame has {actual}")]
    LengthMismatch {
        /// The function code of the PDU.
        function: u8,
        /// The PDU length, function code included, that the layout gives.
        expected: usize,
        /// The PDU length the frame carries.
        actual: usize,
    },
    /// A quantity of coils or registers is 0 or above the function's limit.
    #[error("quantity {quantity} out of range 1-{max}")]
    QuantityOutOfRange {
        /// The quantity the PDU carries.
        quantity: u16,
        /// The function's limit: 2000 or 1968 coils, 125, 123 or 121 registers.
        max: u16,
    },
    /// The addressed range runs past address 65535.
    #[error("address {address} + quantity {quantity} goes past 65535")]
    AddressOverflow {
        /// The first address, 0-based as on the wire.
        address: u16,
        /// The quantity of coils or registers from that address.
        quantity: u16,
    },
    /// The byte count of a write does not fit its quantity of coils or registers.
    #[error("byte count {byte_count} does not match quantity {quantity} (expected {expected})")]
    ByteCountMismatch {
        /// The byte count the PDU carries.
        byte_count: u8,
        /// The quantity of coils or registers the PDU carries.
        quantity: u16,
        /// The byte count that quantity needs: one per 8 coils (rounded up), two per register.
        expected: usize,
    },
    /// The byte count of a response is not one its function allows (0, odd for registers, or
    /// too large).
    #[error("byte count {byte_count} is not valid for function {function}")]
    BadByteCount {
        /// The function code of the PDU.
        function: u8,
        /// The byte count the PDU carries.
        byte_count: u8,
    },
    /// A single-coil value other than FF00 (on) or 0000 (off); carries the value.
    #[error("coil value {0:04X} is neither FF00 (on) nor 0000 (off)")]
    BadCoilValue(u16),
    /// The PDU is longer than the 253 bytes Modbus allows; carries its length in bytes.
    #[error("PDU of {0} bytes is longer than the 253 bytes Modbus allows")]
    TooLong(usize),
    /// A field holds a value the protocol does not allow; carries what is wrong.
    #[error("{0}")]
    BadField(&'static str),
    /// A file record group names no place in a file: a reference type other than 06, file
    /// 0, records past 9999; carries what is wrong.
    #[error("{0}")]
    FileReference(String),
}

/// Why a frame's envelope (address, MBAP header, checksum, ASCII text) or its PDU is not
/// valid.
#[derive(Clone, Debug, Error, PartialEq, Eq)]
pub enum FrameError {
    /// Too few bytes for a slave address, a function code and a checksum (or an MBAP
    /// header); carries the frame's length.
    #[error("frame of {0} bytes is too short to be a Modbus frame")]
    TooShort(usize),
    /// The frame exceeds the longest ADU of its mode.
    #[error("frame of {actual} bytes is longer than the {max} bytes {mode} allows a frame")]
    TooLong {
        /// The mode's name: "RTU", "ASCII" or "TCP".
        mode: &'static str,
        /// The frame's length in bytes.
        actual: usize,
        /// The longest frame the mode allows: 256 (RTU), 513 (ASCII) or 260 (TCP) bytes.
        max: usize,
    },
    /// Shown in wire order (low byte first), as the bytes stand at the end of the frame.
    #[error("CRC mismatch: the frame ends {:02X} {:02X}, its bytes give {:02X} {:02X}", found & 0xFF, found >> 8, expected & 0xFF, expected >> 8)]
    Crc {
        /// The CRC at the end of the frame (sent low byte first).
        found: u16,
        /// The CRC of the frame's address and PDU.
        expected: u16,
    },
    /// The LRC the ASCII frame carries is not the one its bytes give.
    #[error("LRC mismatch: found {found:02X}, expected {expected:02X}")]
    Lrc {
        /// The LRC the frame carries, its last hex pair.
        found: u8,
        /// The LRC of the frame's address and PDU.
        expected: u8,
    },
    /// The ASCII frame does not begin with ':'.
    #[error("ASCII frame must start with ':'")]
    AsciiNoColon,
    /// The ASCII frame was cut off: a new ':' came before its CR LF.
    #[error("ASCII frame cut off: a new ':' came before its CR LF")]
    AsciiNoEnd,
    /// An odd number of hex characters between ':' and CR LF; carries the count.
    #[error("ASCII frame has {0} characters between ':' and CR LF; it needs an even count")]
    AsciiOddLength(usize),
    /// A character of the ASCII frame is not a hex digit; carries the character.
    #[error("ASCII frame holds a character that is not upper- or lower-case hex: {0:?}")]
    AsciiNotHex(char),
    /// The MBAP protocol identifier is not 0 (Modbus); carries the identifier.
    #[error("MBAP protocol id is {0}, not 0 (Modbus)")]
    MbapProtocol(u16),
    /// The MBAP length field is below 2, too few for a unit id and a function code; carries it.
    #[error("MBAP length {0} is too short: it counts the unit id and the PDU, at least 2 bytes")]
    MbapTooShort(usize),
    /// The MBAP length field disagrees with the bytes that follow it.
    #[error("MBAP length says {declared} bytes follow, the frame has {actual}")]
    MbapLength {
        /// The MBAP length field: the unit id and PDU bytes said to follow it.
        declared: usize,
        /// The bytes that do follow it: the unit id and the PDU.
        actual: usize,
    },
    /// The envelope is sound but the PDU inside it is not.
    #[error("{0}")]
    Pdu(#[from] PduError),
}
