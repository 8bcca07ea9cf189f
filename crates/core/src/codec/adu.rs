//! Application data units: the PDU wrapped for RTU (address + CRC), ASCII (':' hex LRC CR LF)
//! or TCP (MBAP header).

use std::borrow::Cow;
use std::fmt;

use super::checksum::{crc16, crc_holds, lrc};
use super::error::{FrameError, PduError};
use super::limits;
use super::pdu::{Direction, Pdu};

/// How PDUs are framed on the line or the connection.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Mode {
    /// Binary on a serial line: slave address, PDU, CRC-16 sent low byte first.
    Rtu,
    /// Text on a serial line: ':', address, PDU and LRC as hex pairs, then CR LF.
    Ascii,
    /// Modbus TCP: the MBAP header (transaction, protocol 0, length, unit id), then the PDU;
    /// no checksum.
    Tcp,
}

impl Mode {
    /// The lower-case name ("rtu", "ascii", "tcp") that reports give; `Display` writes capitals.
    pub fn name(self) -> &'static str {
        match self {
            Mode::Rtu => "rtu",
            Mode::Ascii => "ascii",
            Mode::Tcp => "tcp",
        }
    }

    /// Guesses the framing of a whole frame: ASCII by its colon, RTU when its CRC holds,
    /// TCP when the MBAP header is consistent, and otherwise RTU (whose CRC will then fail).
    pub fn detect(frame: &[u8]) -> Mode {
        if let [b':', rest @ ..] = frame {
            if rest
                .iter()
                .all(|b| b.is_ascii_hexdigit() || matches!(b, b'\r' | b'\n'))
            {
                return Mode::Ascii;
            }
        }
        if crc_holds(frame) {
            return Mode::Rtu;
        }
        if let [_, _, 0, 0, hi, lo, _, _, ..] = frame {
            if usize::from(u16::from_be_bytes([*hi, *lo])) + 6 == frame.len() {
                return Mode::Tcp;
            }
        }
        Mode::Rtu
    }
}

impl fmt::Display for Mode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Mode::Rtu => "RTU",
            Mode::Ascii => "ASCII",
            Mode::Tcp => "TCP",
        })
    }
}

/// The checksum a frame carried, against the one its bytes give.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Checksum {
    /// An RTU frame's CRC-16.
    Crc {
        /// The CRC at the end of the frame (sent low byte first).
        found: u16,
        /// The CRC of the frame's address and PDU.
        expected: u16,
    },
    /// An ASCII frame's LRC.
    Lrc {
        /// The LRC the frame carries, its last hex pair.
        found: u8,
        /// The LRC of the frame's address and PDU.
        expected: u8,
    },
    /// TCP frames carry none.
    None,
}

impl Checksum {
    /// The error a mismatch makes: `FrameError::Crc` or `FrameError::Lrc`; `None` when the
    /// checksum holds or there is none.
    pub fn error(self) -> Option<FrameError> {
        match self {
            Checksum::Crc { found, expected } if found != expected => {
                Some(FrameError::Crc { found, expected })
            }
            Checksum::Lrc { found, expected } if found != expected => {
                Some(FrameError::Lrc { found, expected })
            }
            _ => None,
        }
    }
}

/// A frame's envelope taken off, its PDU not yet interpreted. A checksum mismatch is kept
/// here rather than failing, so that a diagnostic tool can still show what the frame says.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Envelope<'a> {
    /// The framing the frame was opened in.
    pub mode: Mode,
    /// The slave address (RTU, ASCII) or unit identifier (TCP).
    pub slave: u8,
    /// The MBAP transaction identifier; 0 on serial lines.
    pub transaction: u16,
    /// The PDU bytes, function code first: borrowed from an RTU or TCP frame, decoded from
    /// hex for ASCII.
    pub pdu: Cow<'a, [u8]>,
    /// The checksum found against the one computed; a mismatch is kept here, not raised.
    pub checksum: Checksum,
}

impl<'a> Envelope<'a> {
    /// Takes the envelope off a whole frame in the given mode.
    pub fn open(mode: Mode, frame: &'a [u8]) -> Result<Envelope<'a>, FrameError> {
        match mode {
            Mode::Rtu => open_rtu(frame, false),
            Mode::Ascii => open_ascii(frame),
            Mode::Tcp => open_tcp(frame),
        }
    }

    /// As [`Envelope::open`], for a frame whose checksum is already known to hold (the
    /// framer checked it to find the frame): an RTU CRC is not computed again, and is
    /// given as found.
    pub fn open_sound(mode: Mode, frame: &'a [u8]) -> Result<Envelope<'a>, FrameError> {
        match mode {
            Mode::Rtu => open_rtu(frame, true),
            _ => Self::open(mode, frame),
        }
    }
}

/// An RTU frame opened; `sound`: its CRC is known to hold, and is not computed again.
fn open_rtu(frame: &[u8], sound: bool) -> Result<Envelope<'_>, FrameError> {
    if frame.len() > limits::MAX_RTU_ADU {
        return Err(FrameError::TooLong {
            mode: "RTU",
            actual: frame.len(),
            max: limits::MAX_RTU_ADU,
        });
    }
    match frame {
        [slave, pdu @ .., crc_lo, crc_hi] if !pdu.is_empty() => {
            let found = u16::from_le_bytes([*crc_lo, *crc_hi]);
            let expected = match sound {
                true => found,
                false => crc16(&frame[..frame.len() - 2]),
            };
            Ok(Envelope {
                mode: Mode::Rtu,
                slave: *slave,
                transaction: 0,
                pdu: Cow::Borrowed(pdu),
                checksum: Checksum::Crc { found, expected },
            })
        }
        _ => Err(FrameError::TooShort(frame.len())),
    }
}

/// The value of a hex digit, in either case.
pub(crate) fn hex_digit(c: u8) -> Option<u8> {
    char::from(c).to_digit(16).map(|d| d as u8)
}

fn hex_value(c: u8) -> Result<u8, FrameError> {
    hex_digit(c).ok_or(FrameError::AsciiNotHex(char::from(c)))
}

/// Opens ':' hex LRC, with or without its CR LF (a line-oriented input has removed it).
fn open_ascii(frame: &[u8]) -> Result<Envelope<'static>, FrameError> {
    if frame.len() > limits::MAX_ASCII_ADU {
        return Err(FrameError::TooLong {
            mode: "ASCII",
            actual: frame.len(),
            max: limits::MAX_ASCII_ADU,
        });
    }
    let body = frame.strip_prefix(b":").ok_or(FrameError::AsciiNoColon)?;
    let body = body
        .strip_suffix(b"\r\n")
        .or_else(|| body.strip_suffix(b"\n"))
        .or_else(|| body.strip_suffix(b"\r"))
        .unwrap_or(body);
    if body.len() % 2 != 0 {
        return Err(FrameError::AsciiOddLength(body.len()));
    }
    let mut bytes = Vec::with_capacity(body.len() / 2);
    for pair in body.chunks_exact(2) {
        bytes.push(hex_value(pair[0])? << 4 | hex_value(pair[1])?);
    }
    match bytes.as_slice() {
        [slave, pdu @ .., found] if !pdu.is_empty() => {
            let expected = lrc(&bytes[..bytes.len() - 1]);
            Ok(Envelope {
                mode: Mode::Ascii,
                slave: *slave,
                transaction: 0,
                checksum: Checksum::Lrc {
                    found: *found,
                    expected,
                },
                pdu: Cow::Owned(pdu.to_vec()),
            })
        }
        _ => Err(FrameError::TooShort(frame.len())),
    }
}

fn open_tcp(frame: &[u8]) -> Result<Envelope<'_>, FrameError> {
    if frame.len() > limits::MAX_TCP_ADU {
        return Err(FrameError::TooLong {
            mode: "TCP",
            actual: frame.len(),
            max: limits::MAX_TCP_ADU,
        });
    }
    match frame {
        [t_hi, t_lo, p_hi, p_lo, l_hi, l_lo, unit, pdu @ ..] => {
            let protocol = u16::from_be_bytes([*p_hi, *p_lo]);
            if protocol != 0 {
                return Err(FrameError::MbapProtocol(protocol));
            }
            let declared = usize::from(u16::from_be_bytes([*l_hi, *l_lo]));
            if declared < 2 {
                return Err(FrameError::MbapTooShort(declared));
            }
            if declared != pdu.len() + 1 {
                return Err(FrameError::MbapLength {
                    declared,
                    actual: pdu.len() + 1,
                });
            }
            Ok(Envelope {
                mode: Mode::Tcp,
                slave: *unit,
                transaction: u16::from_be_bytes([*t_hi, *t_lo]),
                pdu: Cow::Borrowed(pdu),
                checksum: Checksum::None,
            })
        }
        _ => Err(FrameError::TooShort(frame.len())),
    }
}

/// PDU bytes in the envelope of `mode`: a whole frame.
pub(crate) fn wrapped(mode: Mode, slave: u8, transaction: u16, pdu: &[u8]) -> Vec<u8> {
    // Room for the longest envelope: ASCII, two characters a byte.
    let mut out = Vec::with_capacity(pdu.len() * 2 + 9);
    wrap(mode, slave, transaction, pdu, &mut out);
    out
}

/// Wraps PDU bytes in the envelope of `mode`, appending to `out`.
pub(crate) fn wrap(mode: Mode, slave: u8, transaction: u16, pdu: &[u8], out: &mut Vec<u8>) {
    match mode {
        Mode::Rtu => {
            let start = out.len();
            out.push(slave);
            out.extend_from_slice(pdu);
            let crc = crc16(&out[start..]);
            out.extend_from_slice(&crc.to_le_bytes());
        }
        Mode::Ascii => {
            const HEX: &[u8; 16] = b"0123456789ABCDEF";
            let push_hex = |out: &mut Vec<u8>, byte: u8| {
                out.push(HEX[usize::from(byte >> 4)]);
                out.push(HEX[usize::from(byte & 0x0F)]);
            };
            out.push(b':');
            push_hex(out, slave);
            for byte in pdu {
                push_hex(out, *byte);
            }
            let sum = lrc(&[slave]).wrapping_add(lrc(pdu));
            push_hex(out, sum);
            out.extend_from_slice(b"\r\n");
        }
        Mode::Tcp => {
            // The length counts the unit id and the PDU; a PDU is at most 253 bytes.
            let length = u16::try_from(pdu.len() + 1).unwrap_or(u16::MAX);
            out.extend_from_slice(&transaction.to_be_bytes());
            out.extend_from_slice(&[0, 0]);
            out.extend_from_slice(&length.to_be_bytes());
            out.push(slave);
            out.extend_from_slice(pdu);
        }
    }
}

/// A whole frame: envelope fields and a typed PDU.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Frame {
    /// The framing the frame travels in.
    pub mode: Mode,
    /// The slave address (RTU, ASCII; 0 broadcasts) or unit identifier (TCP).
    pub slave: u8,
    /// The MBAP transaction identifier; 0 on serial lines.
    pub transaction: u16,
    /// The typed PDU: a request, a normal response or an exception.
    pub pdu: Pdu,
}

impl Frame {
    /// The bytes on the wire. Fails only when the PDU breaks a protocol limit.
    pub fn encode(&self) -> Result<Vec<u8>, PduError> {
        let mut pdu = Vec::with_capacity(limits::MAX_PDU);
        self.pdu.encode(&mut pdu)?;
        Ok(wrapped(self.mode, self.slave, self.transaction, &pdu))
    }

    /// Reads a whole frame whose mode and direction are known; a bad checksum is an error.
    pub fn decode(mode: Mode, bytes: &[u8], direction: Direction) -> Result<Frame, FrameError> {
        Self::read(&Envelope::open(mode, bytes)?, direction)
    }

    /// The frame inside an envelope already opened, travelling in `direction`; a bad
    /// checksum is an error.
    pub fn read(envelope: &Envelope, direction: Direction) -> Result<Frame, FrameError> {
        if let Some(error) = envelope.checksum.error() {
            return Err(error);
        }
        Ok(Frame {
            mode: envelope.mode,
            slave: envelope.slave,
            transaction: envelope.transaction,
            pdu: Pdu::decode(&envelope.pdu, direction)?,
        })
    }
}

/// Reads a request whose envelope and checksum are sound but whose PDU breaks its
/// function's layout (quantity 0, say) as an opaque request, so that a slave can answer it
/// with an exception as a real device does, rather than stay silent. Function codes 00 and
/// 80-FF are taken only with `any_function`: over TCP everything a server receives is a
/// request, while on a serial line such a frame is another slave's answer.
pub(crate) fn opaque_request(
    mode: Mode,
    bytes: &[u8],
    any_function: bool,
) -> Result<Frame, FrameError> {
    let envelope = Envelope::open(mode, bytes)?;
    if let Some(error) = envelope.checksum.error() {
        return Err(error);
    }
    match envelope.pdu.split_first() {
        Some((&function, data))
            if any_function
                || (function != 0 && function & super::function::EXCEPTION_FLAG == 0) =>
        {
            Ok(Frame {
                mode,
                slave: envelope.slave,
                transaction: envelope.transaction,
                pdu: Pdu::Request(super::pdu::Request::Other {
                    function,
                    data: data.to_vec(),
                }),
            })
        }
        _ => Err(FrameError::Pdu(PduError::BadField(
            "function codes 00 and 80-FF are not requests",
        ))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ascii_wrap_gives_the_corrected_manual_frame() {
        let mut out = Vec::new();
        wrap(
            Mode::Ascii,
            0x11,
            0,
            &[0x03, 0x00, 0x6B, 0x00, 0x03],
            &mut out,
        );
        assert_eq!(out, b":1103006B00037E\r\n");
    }

    #[test]
    fn detect_tells_the_three_framings_apart() {
        assert_eq!(Mode::detect(b":1103006B00037E"), Mode::Ascii);
        assert_eq!(
            Mode::detect(&[0x11, 0x03, 0x00, 0x6B, 0x00, 0x03, 0x76, 0x87]),
            Mode::Rtu
        );
        assert_eq!(
            Mode::detect(&[0, 1, 0, 0, 0, 6, 0x11, 0x03, 0x00, 0x6B, 0x00, 0x03]),
            Mode::Tcp
        );
    }
}
