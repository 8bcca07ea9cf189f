//! The protocol's limits, from the Modbus application protocol specification.

pub const MAX_READ_BITS: u16 = 2000;
pub const MAX_READ_REGISTERS: u16 = 125;
pub const MAX_WRITE_BITS: u16 = 1968;
pub const MAX_WRITE_REGISTERS: u16 = 123;
pub const MAX_RW_READ_REGISTERS: u16 = 125;
pub const MAX_RW_WRITE_REGISTERS: u16 = 121;
/// 2000 bits packed.
pub const MAX_READ_BITS_BYTES: usize = 250;
/// A PDU is at most 253 bytes: 256 bytes of RTU ADU less address and CRC.
pub const MAX_PDU: usize = 253;
pub const MAX_RTU_ADU: usize = 256;
/// ':' + 2 x (1 + 253 + 1) hex characters + CR LF.
pub const MAX_ASCII_ADU: usize = 513;
/// MBAP header (7) + PDU (253).
pub const MAX_TCP_ADU: usize = 260;
