//! The fields of a PDU written and read in order, and the protocol limits every encoder
//! and decoder checks.

use crate::codec::error::PduError;
use crate::codec::function::*;
use crate::codec::length::{pdu_length, Length};
use crate::codec::Direction;
use crate::codec::{bits, limits};

#[inline]
pub(super) fn check_quantity(quantity: u16, max: u16) -> Result<(), PduError> {
    if quantity == 0 || quantity > max {
        return Err(PduError::QuantityOutOfRange { quantity, max });
    }
    Ok(())
}

#[inline]
pub(super) fn check_range(address: u16, quantity: u16) -> Result<(), PduError> {
    if u32::from(address) + u32::from(quantity) > 65536 {
        return Err(PduError::AddressOverflow { address, quantity });
    }
    Ok(())
}

#[inline]
pub(super) fn check_read(address: u16, quantity: u16, max: u16) -> Result<(), PduError> {
    check_quantity(quantity, max)?;
    check_range(address, quantity)
}

#[inline]
pub(super) fn coil_word(value: bool) -> u16 {
    if value {
        0xFF00
    } else {
        0x0000
    }
}

#[inline]
pub(super) fn coil_from_word(word: u16) -> Result<bool, PduError> {
    match word {
        0xFF00 => Ok(true),
        0x0000 => Ok(false),
        other => Err(PduError::BadCoilValue(other)),
    }
}

#[inline]
pub(super) fn len_u8(len: usize, max: usize) -> Result<u8, PduError> {
    u8::try_from(len)
        .ok()
        .filter(|_| len <= max)
        .ok_or(PduError::TooLong(len + 2))
}

/// A little writer so that every encoder reads like the layout table of the specification.
pub(super) struct Writer<'a>(pub(super) &'a mut Vec<u8>);

impl Writer<'_> {
    #[inline]
    pub(super) fn u8(&mut self, value: u8) -> &mut Self {
        self.0.push(value);
        self
    }
    #[inline]
    pub(super) fn u16(&mut self, value: u16) -> &mut Self {
        self.0.extend_from_slice(&value.to_be_bytes());
        self
    }
    #[inline]
    pub(super) fn bytes(&mut self, bytes: &[u8]) -> &mut Self {
        self.0.extend_from_slice(bytes);
        self
    }
    #[inline]
    pub(super) fn registers(&mut self, values: &[u16]) -> &mut Self {
        for value in values {
            self.u16(*value);
        }
        self
    }
}

/// What a decode keeps of a PDU's variable parts (registers, bits, data bytes).
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum Values {
    /// All of them: the PDU as it is.
    Kept,
    /// None: every field is read and checked as for `Kept`, and the lists are left empty,
    /// so that asking whether bytes read costs no allocation. Such a PDU is only asked
    /// whether it read, never shown.
    Skipped,
}

/// Reads a PDU's fields in order; running short is an error, never a panic.
pub(super) struct Reader<'a> {
    pub(super) function: u8,
    bytes: &'a [u8],
    pos: usize,
    values: Values,
}

impl<'a> Reader<'a> {
    /// A reader positioned after the function code.
    #[inline]
    pub(super) fn new(pdu: &'a [u8], values: Values) -> Result<Self, PduError> {
        let function = *pdu.first().ok_or(PduError::Empty)?;
        Ok(Self {
            function,
            bytes: pdu,
            pos: 1,
            values,
        })
    }

    /// A reader of `bytes`, a part of a PDU of `function` that holds groups of its own,
    /// keeping the values as its PDU's reader does.
    pub(super) fn new_at(function: u8, bytes: &'a [u8], keeps: bool) -> Self {
        Self {
            function,
            bytes,
            pos: 0,
            values: if keeps { Values::Kept } else { Values::Skipped },
        }
    }

    /// Whether every byte has been read.
    pub(super) fn at_end(&self) -> bool {
        self.pos >= self.bytes.len()
    }

    /// Whether the values read are kept.
    #[inline]
    pub(super) fn keeps(&self) -> bool {
        self.values == Values::Kept
    }

    /// `bytes` as a value of the PDU.
    #[inline]
    pub(super) fn owned(&self, bytes: &[u8]) -> Vec<u8> {
        if self.keeps() {
            bytes.to_vec()
        } else {
            Vec::new()
        }
    }

    /// Big-endian 16-bit words, two bytes each, as values of the PDU.
    #[inline]
    pub(super) fn words(&self, bytes: &[u8]) -> Vec<u16> {
        if !self.keeps() {
            return Vec::new();
        }
        bytes
            .chunks_exact(2)
            .map(|b| u16::from_be_bytes([b[0], b[1]]))
            .collect()
    }

    /// The first `count` bits of `packed` as values of the PDU.
    #[inline]
    pub(super) fn bits(&self, packed: &[u8], count: usize) -> Vec<bool> {
        if self.keeps() {
            bits::unpack(packed, count)
        } else {
            Vec::new()
        }
    }

    #[inline]
    pub(super) fn take(&mut self, n: usize) -> Result<&'a [u8], PduError> {
        let end = self.pos + n;
        let slice = self.bytes.get(self.pos..end).ok_or(PduError::Truncated {
            function: self.function,
            needed: end,
            actual: self.bytes.len(),
        })?;
        self.pos = end;
        Ok(slice)
    }

    #[inline]
    pub(super) fn u8(&mut self) -> Result<u8, PduError> {
        Ok(self.take(1)?[0])
    }

    #[inline]
    pub(super) fn u16(&mut self) -> Result<u16, PduError> {
        let b = self.take(2)?;
        Ok(u16::from_be_bytes([b[0], b[1]]))
    }

    #[inline]
    pub(super) fn registers(&mut self, count: usize) -> Result<Vec<u16>, PduError> {
        let bytes = self.take(count * 2)?;
        Ok(self.words(bytes))
    }

    #[inline]
    pub(super) fn rest(&mut self) -> &'a [u8] {
        let rest = self.bytes.get(self.pos..).unwrap_or_default();
        self.pos = self.bytes.len();
        rest
    }

    /// The PDU must end here: extra bytes mean the frame is not what its function says.
    #[inline]
    pub(super) fn finish(self) -> Result<(), PduError> {
        if self.pos != self.bytes.len() {
            return Err(PduError::LengthMismatch {
                function: self.function,
                expected: self.pos,
                actual: self.bytes.len(),
            });
        }
        Ok(())
    }

    /// A byte count, then that many bytes, which must be the rest of the PDU.
    #[inline]
    pub(super) fn counted_rest(&mut self) -> Result<&'a [u8], PduError> {
        let byte_count = usize::from(self.u8()?);
        let expected = self.pos + byte_count;
        if expected != self.bytes.len() {
            return Err(PduError::LengthMismatch {
                function: self.function,
                expected,
                actual: self.bytes.len(),
            });
        }
        self.take(byte_count)
    }
}

/// Requests and normal responses carry function codes 01-7F; 80-FF mark exceptions.
#[inline]
pub(super) fn check_normal_function(function: u8) -> Result<(), PduError> {
    if function == 0 || function & EXCEPTION_FLAG != 0 {
        return Err(PduError::BadField(
            "function codes 00 and 80-FF are not requests or normal responses",
        ));
    }
    Ok(())
}

/// A function kept byte for byte whose layout still tells its length (11, 12):
/// a PDU of another length is no PDU of that function in `direction`. A Get Comm Event
/// Counter request is its function code alone, and its answer four bytes more.
pub(super) fn check_layout_length(pdu: &[u8], direction: Direction) -> Result<(), PduError> {
    match pdu_length(pdu, direction) {
        Length::Known(expected) if expected != pdu.len() => Err(PduError::LengthMismatch {
            function: pdu.first().copied().unwrap_or_default(),
            expected,
            actual: pdu.len(),
        }),
        // Too short for the byte count its layout reads.
        Length::AtLeast(needed) => Err(PduError::Truncated {
            function: pdu.first().copied().unwrap_or_default(),
            needed,
            actual: pdu.len(),
        }),
        _ => Ok(()),
    }
}

#[inline]
pub(super) fn check_pdu_len(len: usize) -> Result<(), PduError> {
    if len > limits::MAX_PDU {
        return Err(PduError::TooLong(len));
    }
    Ok(())
}

#[inline]
pub(super) fn quantity_of(len: usize, max: u16) -> Result<u16, PduError> {
    let quantity = u16::try_from(len).unwrap_or(u16::MAX);
    check_quantity(quantity, max)?;
    Ok(quantity)
}

/// Reads a byte count that must equal `expected`, then the bytes it counts.
#[inline]
pub(super) fn counted_exactly<'a>(
    r: &mut Reader<'a>,
    expected: usize,
    quantity: u16,
) -> Result<&'a [u8], PduError> {
    let byte_count = r.u8()?;
    if usize::from(byte_count) != expected {
        return Err(PduError::ByteCountMismatch {
            byte_count,
            quantity,
            expected,
        });
    }
    r.take(expected)
}

/// Checks a register byte count (2 per register) without consuming the registers.
#[inline]
pub(super) fn counted_registers(r: &mut Reader<'_>, quantity: u16) -> Result<(), PduError> {
    let byte_count = r.u8()?;
    let expected = usize::from(quantity) * 2;
    if usize::from(byte_count) != expected {
        return Err(PduError::ByteCountMismatch {
            byte_count,
            quantity,
            expected,
        });
    }
    Ok(())
}
