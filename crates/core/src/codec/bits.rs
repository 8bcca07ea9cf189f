//! Bit packing as the Modbus manuals give it: the first coil in the low bit of the first
//! byte, and the unused high bits of the last byte zero.

/// Packs `bits` into bytes, first bit in the least significant bit of the first byte.
pub fn pack(bits: &[bool]) -> Vec<u8> {
    let mut bytes = vec![0u8; bits.len().div_ceil(8)];
    for (byte, chunk) in bytes.iter_mut().zip(bits.chunks(8)) {
        for (i, bit) in chunk.iter().enumerate() {
            if *bit {
                *byte |= 1 << i;
            }
        }
    }
    bytes
}

/// Unpacks the first `count` bits of `bytes`; bits past the end of `bytes` are not invented.
pub fn unpack(bytes: &[u8], count: usize) -> Vec<bool> {
    bytes
        .iter()
        .flat_map(|byte| (0..8).map(move |i| byte & (1 << i) != 0))
        .take(count)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coils_20_to_27_from_the_manual() {
        // 0xCD = 1100 1101: coil 20 is the low bit.
        let bits = unpack(&[0xCD], 8);
        assert_eq!(bits, [true, false, true, true, false, false, true, true]);
        assert_eq!(pack(&bits), [0xCD]);
    }

    #[test]
    fn unused_high_bits_are_zero() {
        assert_eq!(pack(&[true; 9]), [0xFF, 0x01]);
    }
}
