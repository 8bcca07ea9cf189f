//! A serial line's settings: its speed and character frame, and who switches an RS-485
//! transceiver between sending and listening. Shared by the transports that open a line
//! and by the captures that record what line they were taken on.

use std::time::Duration;

use crate::input::choice::Choice;

/// The speeds a serial line is opened at, in bits per second.
pub const BAUDS: std::ops::RangeInclusive<u32> = 50..=12_000_000;
/// The data bits of a character: 8 in RTU, 7 or 8 in ASCII.
pub const DATA_BITS: std::ops::RangeInclusive<u8> = 7..=8;
/// The stop bits of a character.
pub const STOP_BITS: std::ops::RangeInclusive<u8> = 1..=2;

/// Line settings, as the connection options give them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LineSettings {
    /// Bits per second.
    pub baud: u32,
    /// The parity bit, if any.
    pub parity: Parity,
    /// 7 or 8; Modbus RTU uses 8.
    pub data_bits: u8,
    /// 1 or 2.
    pub stop_bits: u8,
    /// Who switches an RS-485 transceiver between sending and listening.
    pub direction: DirectionControl,
}

/// The parity bit of each character.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Parity {
    /// No parity bit; the specification then asks for 2 stop bits.
    None,
    /// Even parity, the specification's default.
    Even,
    /// Odd parity.
    Odd,
}

impl Choice for Parity {
    const ALL: &'static [Self] = &[Parity::None, Parity::Even, Parity::Odd];

    fn name(self) -> &'static str {
        match self {
            Parity::None => "none",
            Parity::Even => "even",
            Parity::Odd => "odd",
        }
    }
}

impl LineSettings {
    /// Bits on the wire per character: start, data, parity, stop.
    pub fn bits_per_character(&self) -> u32 {
        1 + u32::from(self.data_bits)
            + u32::from(self.parity != Parity::None)
            + u32::from(self.stop_bits)
    }

    /// One character's time on the wire, in microseconds.
    pub fn character_us(&self) -> f64 {
        f64::from(self.bits_per_character()) * 1e6 / f64::from(self.baud.max(1))
    }

    /// One character's time on the wire.
    pub fn character_time(&self) -> Duration {
        Duration::from_secs_f64(self.character_us() / 1e6)
    }

    /// The silence that ends an RTU frame: 3.5 character times, and 1.75 ms above 19200
    /// baud, as the Modbus serial line specification fixes it.
    pub fn frame_gap(&self) -> Duration {
        if self.baud > 19200 {
            return Duration::from_micros(1750);
        }
        self.character_time().mul_f64(3.5)
    }
}

/// How the transceiver is switched between driving the line and listening.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DirectionControl {
    /// Nothing to do: the adapter switches its driver itself, or the line is RS-232.
    #[default]
    Automatic,
    /// The kernel's RS-485 mode (the TIOCSRS485 ioctl), set when the port is opened and
    /// put back as it was when it is closed.
    Kernel(RtsTiming),
    /// RTS set before each frame is written and reset once its last byte has left the
    /// UART (tcdrain), for drivers without RS-485 mode.
    Toggle(RtsTiming),
}

impl DirectionControl {
    /// Whether the host leaves the transceiver alone.
    pub fn is_automatic(self) -> bool {
        self == DirectionControl::Automatic
    }
}

/// When and how RTS moves around a frame sent.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RtsTiming {
    /// From RTS set to the first byte.
    pub before: Duration,
    /// From the last byte gone to RTS reset.
    pub after: Duration,
    /// The level of RTS while sending; the other one while listening.
    pub sending: RtsLevel,
}

/// A logical level of RTS, as the kernel's `SER_RS485_RTS_ON_SEND` names it: `High` is
/// RTS asserted.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum RtsLevel {
    /// RTS asserted while sending (the usual wiring: RTS to the driver enable, DE).
    #[default]
    High,
    /// RTS released while sending, for a transceiver wired the other way.
    Low,
}

impl RtsLevel {
    /// Whether RTS is asserted at this level.
    pub fn asserted(self) -> bool {
        self == RtsLevel::High
    }
}

impl Choice for RtsLevel {
    const ALL: &'static [Self] = &[RtsLevel::High, RtsLevel::Low];

    fn name(self) -> &'static str {
        match self {
            RtsLevel::High => "high",
            RtsLevel::Low => "low",
        }
    }
}
