//! The two checksums of serial Modbus: CRC-16/MODBUS for RTU, LRC for ASCII.

/// CRC-16/MODBUS is reflected: its polynomial 0x8005 read from the low bit.
const POLYNOMIAL: u16 = 0xA001;

/// `SLICES[k][b]`: what byte `b` followed by `k` more bytes adds to the CRC register,
/// starting from zero. The CRC is linear, so a run of up to 16 bytes is the XOR of one
/// lookup per byte, all independent: a frame's CRC is a handful of loads side by side
/// rather than a chain of one dependent lookup per byte, and a sniffer checks a CRC for
/// every candidate frame, most of them under 16 bytes.
static SLICES: [[u16; 256]; 16] = slices();

const fn slices() -> [[u16; 256]; 16] {
    let mut tables = [[0u16; 256]; 16];
    let mut byte = 0;
    while byte < 256 {
        let mut crc = byte as u16;
        let mut bit = 0;
        while bit < 8 {
            crc = if crc & 1 != 0 {
                (crc >> 1) ^ POLYNOMIAL
            } else {
                crc >> 1
            };
            bit += 1;
        }
        tables[0][byte] = crc;
        byte += 1;
    }
    let mut distance = 1;
    while distance < 16 {
        let mut byte = 0;
        while byte < 256 {
            let before = tables[distance - 1][byte];
            tables[distance][byte] = (before >> 8) ^ tables[0][(before & 0xFF) as usize];
            byte += 1;
        }
        distance += 1;
    }
    tables
}

/// The register after 2 to 16 `bytes` from `crc`: the register folds into the first two
/// bytes, and each byte adds its slice for the bytes after it.
#[inline(always)]
fn slice(crc: u16, bytes: &[u8]) -> u16 {
    let n = bytes.len();
    let tables = &SLICES[..n];
    let mut out = tables[n - 1][usize::from(bytes[0] ^ crc as u8)]
        ^ tables[n - 2][usize::from(bytes[1] ^ (crc >> 8) as u8)];
    // The third byte takes the table of distance n - 3, the last the table of distance 0.
    for (byte, table) in bytes[2..].iter().zip(tables[..n - 2].iter().rev()) {
        out ^= table[usize::from(*byte)];
    }
    out
}

/// The register after one more byte.
#[inline(always)]
fn step(crc: u16, byte: u8) -> u16 {
    (crc >> 8) ^ SLICES[0][usize::from(crc as u8 ^ byte)]
}

/// CRC-16/MODBUS of `bytes`. On the wire it is sent low byte first.
#[inline]
pub fn crc16(bytes: &[u8]) -> u16 {
    carried(0xFFFF, bytes)
}

/// The register after `bytes`, from `crc`.
#[inline]
fn carried(mut crc: u16, bytes: &[u8]) -> u16 {
    let mut chunks = bytes.chunks_exact(16);
    for chunk in &mut chunks {
        crc = slice(crc, chunk);
    }
    match chunks.remainder() {
        [] => crc,
        [byte] => step(crc, *byte),
        rest => slice(crc, rest),
    }
}

/// `body` with its CRC appended: an RTU frame, for the tests of the framer and the sniffer.
#[cfg(test)]
pub(crate) fn rtu(body: &[u8]) -> Vec<u8> {
    [body, &crc16(body).to_le_bytes()].concat()
}

/// Whether an RTU frame (address, PDU, CRC) ends in the CRC of what comes before it.
#[inline]
pub fn crc_holds(frame: &[u8]) -> bool {
    match frame.len().checked_sub(2) {
        Some(body) if body >= 2 => {
            let (body, crc) = frame.split_at(body);
            crc16(body).to_le_bytes() == crc
        }
        _ => false,
    }
}

/// The lengths in `min_len..=max_len` at which `bytes` ends in its own CRC (low byte
/// first), shortest first: how a frame of a function without a known layout is found.
///
/// The register after a frame and its own CRC is zero, so these are the lengths after
/// which the register is zero. Carried a byte at a time, each byte waits for the lookup of
/// the one before it; a noisy line asks this at every position whose function byte is
/// user-defined, up to 256 bytes on. So the lengths are split into four runs, each
/// started from its own register (carried, sliced, from the run before) and carried in the
/// same loop, whose lookups do not wait for each other.
pub fn crc_matches(bytes: &[u8], min_len: usize, max_len: usize) -> Vec<usize> {
    let max_len = max_len.min(bytes.len());
    let mut matches = Vec::new();
    if min_len < 3 || min_len > max_len {
        return matches;
    }
    let per_run = (max_len + 1 - min_len) / 4;
    let starts: [usize; 4] = std::array::from_fn(|run| min_len + run * per_run);
    let mut registers = [crc16(&bytes[..min_len]); 4];
    for run in 1..4 {
        registers[run] = carried(registers[run - 1], &bytes[starts[run - 1]..starts[run]]);
    }
    // Each run checks its last length after the loop, so that no byte past `max_len` is
    // read. The runs' bytes are walked side by side, without an index to check.
    let run_bytes = |run: usize| &bytes[starts[run]..starts[run] + per_run.saturating_sub(1)];
    let side_by_side = run_bytes(0)
        .iter()
        .zip(run_bytes(1))
        .zip(run_bytes(2))
        .zip(run_bytes(3));
    for (offset, (((a, b), c), d)) in side_by_side.enumerate() {
        let [r0, r1, r2, r3] = registers;
        // Rarely is any register zero: one test for the four.
        if r0.min(r1).min(r2.min(r3)) == 0 {
            for (register, start) in registers.iter().zip(starts) {
                if *register == 0 {
                    matches.push(start + offset);
                }
            }
        }
        registers = [step(r0, *a), step(r1, *b), step(r2, *c), step(r3, *d)];
    }
    // The lengths the runs leave over go on from the register at the last run's end.
    let rest = min_len + 4 * per_run;
    let mut register = registers[3];
    if let Some(last) = per_run.checked_sub(1) {
        for (register, start) in registers.iter().zip(starts) {
            if *register == 0 {
                matches.push(start + last);
            }
        }
        if rest <= max_len {
            register = step(registers[3], bytes[rest - 1]);
        }
    }
    // The few lengths the runs leave over, one after the other.
    if rest <= max_len {
        if register == 0 {
            matches.push(rest);
        }
        for (len, byte) in (rest + 1..=max_len).zip(&bytes[rest..max_len]) {
            register = step(register, *byte);
            if register == 0 {
                matches.push(len);
            }
        }
    }
    // Found run by run, so out of order; rarely more than one.
    matches.sort_unstable();
    matches
}

/// Longitudinal redundancy check: the two's complement of the 8-bit sum of the bytes.
pub fn lrc(bytes: &[u8]) -> u8 {
    bytes
        .iter()
        .fold(0u8, |sum, byte| sum.wrapping_add(*byte))
        .wrapping_neg()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crc_of_the_manual_read_holding_request() {
        // 11 03 00 6B 00 03 -> CRC 0x8776, sent as 76 87.
        assert_eq!(crc16(&[0x11, 0x03, 0x00, 0x6B, 0x00, 0x03]), 0x8776);
    }

    #[test]
    fn a_frame_and_its_trailing_zeros_match_its_crc() {
        let mut frame = vec![0x11, 0x41, 0x01, 0x02, 0x03];
        frame.extend_from_slice(&crc16(&frame).to_le_bytes());
        frame.extend_from_slice(&[0xAA, 0xBB]);
        assert_eq!(crc_matches(&frame, 4, 256), vec![7]);
        assert_eq!(crc_matches(&frame[..6], 4, 256), Vec::<usize>::new());
        // The CRC of a frame and its own CRC is zero, so that a frame followed by 00
        // bytes matches at every longer length: one byte longer as a frame whose CRC is
        // its own CRC's high byte and 00, and further as a frame whose CRC is 00 00.
        frame.truncate(7);
        frame.extend_from_slice(&[0, 0, 0]);
        assert_eq!(crc_matches(&frame, 4, 256), vec![7, 8, 9, 10]);
    }

    /// The reference: the crc crate's CRC-16/MODBUS, a byte at a time.
    fn reference(bytes: &[u8]) -> u16 {
        crc::Crc::<u16, crc::Table<1>>::new(&crc::CRC_16_MODBUS).checksum(bytes)
    }

    proptest::proptest! {
        #[test]
        fn the_sliced_crc_is_the_reference_crc(bytes in proptest::collection::vec(proptest::prelude::any::<u8>(), 0..300)) {
            proptest::prop_assert_eq!(crc16(&bytes), reference(&bytes));
        }
    }

    #[test]
    fn the_sliced_crc_is_the_reference_crc_at_every_length_around_the_slices() {
        let bytes: Vec<u8> = (0u32..100).map(|i| (i * 37 + 11) as u8).collect();
        for len in 0..bytes.len() {
            assert_eq!(
                crc16(&bytes[..len]),
                reference(&bytes[..len]),
                "{len} bytes"
            );
        }
    }

    /// The lengths at which `bytes` ends in its own CRC, one length after the other; none
    /// shorter than three bytes (a CRC and one byte it is of).
    fn matches_one_by_one(bytes: &[u8], min_len: usize, max_len: usize) -> Vec<usize> {
        if min_len < 3 {
            return Vec::new();
        }
        (min_len..=max_len.min(bytes.len()))
            .filter(|len| crc16(&bytes[..len - 2]).to_le_bytes() == bytes[len - 2..*len])
            .collect()
    }

    proptest::proptest! {
        #[test]
        fn crc_matches_finds_the_lengths_one_by_one_would(
            body in proptest::collection::vec(proptest::prelude::any::<u8>(), 0..300),
            cut in 0usize..300,
            min_len in 0usize..12,
            max_len in 0usize..320,
        ) {
            // Frames with their CRC inside, so that there is something to find.
            let mut bytes = body.clone();
            let cut = cut.min(bytes.len());
            let crc = crc16(&bytes[..cut]).to_le_bytes();
            bytes.splice(cut..cut, crc);
            bytes.extend_from_slice(&[0, 0]);
            proptest::prop_assert_eq!(
                crc_matches(&bytes, min_len, max_len),
                matches_one_by_one(&bytes, min_len, max_len)
            );
        }
    }

    #[test]
    fn lrc_of_the_manual_read_holding_request() {
        assert_eq!(lrc(&[0x11, 0x03, 0x00, 0x6B, 0x00, 0x03]), 0x7E);
    }
}
