//! The protocol's limits, from the Modbus application protocol specification.

/// The most coils or discrete inputs one read (functions 01, 02) may ask for.
pub const MAX_READ_BITS: u16 = 2000;
/// The most registers one read (functions 03, 04) may ask for.
pub const MAX_READ_REGISTERS: u16 = 125;
/// The most coils one Write Multiple Coils (15) may carry.
pub const MAX_WRITE_BITS: u16 = 1968;
/// The most registers one Write Multiple Registers (16) may carry.
pub const MAX_WRITE_REGISTERS: u16 = 123;
/// The most registers the read part of Read/Write Multiple Registers (23) may ask for.
pub const MAX_RW_READ_REGISTERS: u16 = 125;
/// The most registers the write part of Read/Write Multiple Registers (23) may carry.
pub const MAX_RW_WRITE_REGISTERS: u16 = 121;
/// 2000 bits packed.
pub const MAX_READ_BITS_BYTES: usize = 250;
/// A PDU is at most 253 bytes: 256 bytes of RTU ADU less address and CRC.
pub const MAX_PDU: usize = 253;
/// The longest RTU frame: slave address (1) + PDU (253) + CRC (2).
pub const MAX_RTU_ADU: usize = 256;
/// ':' + 2 x (1 + 253 + 1) hex characters + CR LF.
pub const MAX_ASCII_ADU: usize = 513;
/// MBAP header (7) + PDU (253).
pub const MAX_TCP_ADU: usize = 260;
