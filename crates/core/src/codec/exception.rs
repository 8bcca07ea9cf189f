//! Exception codes 01-0B by name; other codes are kept as they came.

use std::fmt;

/// The code of an exception response: why the device refused a request. The inner byte is
/// the code as it came on the wire, defined or not.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ExceptionCode(pub u8);

impl ExceptionCode {
    /// 01: the device does not support the function code.
    pub const ILLEGAL_FUNCTION: Self = Self(0x01);
    /// 02: the address, or address plus quantity, falls outside what the device has.
    pub const ILLEGAL_DATA_ADDRESS: Self = Self(0x02);
    /// 03: a value in the request is not allowed, such as a quantity out of range.
    pub const ILLEGAL_DATA_VALUE: Self = Self(0x03);
    /// 04: an unrecoverable error happened while the device carried out the request.
    pub const SERVER_DEVICE_FAILURE: Self = Self(0x04);
    /// 0A: a gateway has no path to the target device.
    pub const GATEWAY_PATH_UNAVAILABLE: Self = Self(0x0A);
    /// 0B: a gateway got no response from the target device.
    pub const GATEWAY_TARGET_FAILED: Self = Self(0x0B);

    /// Whether the specification defines the code (01-08, 0A, 0B).
    pub fn is_defined(self) -> bool {
        matches!(self.0, 0x01..=0x08 | 0x0A | 0x0B)
    }

    /// The specification's name for the code, in lower case; "unknown exception" for
    /// codes it does not define.
    pub fn name(self) -> &'static str {
        match self.0 {
            0x01 => "illegal function",
            0x02 => "illegal data address",
            0x03 => "illegal data value",
            0x04 => "slave device failure",
            0x05 => "acknowledge",
            0x06 => "slave device busy",
            0x07 => "negative acknowledge",
            0x08 => "memory parity error",
            0x0A => "gateway path unavailable",
            0x0B => "gateway target device failed to respond",
            _ => "unknown exception",
        }
    }
}

impl fmt::Display for ExceptionCode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:02X} {}", self.0, self.name())
    }
}
