//! Bytes as the spaced upper-case hex every frame is shown in.

/// Formats bytes as spaced upper-case hex, the way mbtool prints every frame.
pub fn spaced_hex(bytes: &[u8]) -> String {
    let mut out = String::with_capacity(bytes.len() * 3);
    push_spaced_hex(&mut out, bytes);
    out
}

/// [`spaced_hex`], appended to `out`.
pub fn push_spaced_hex(out: &mut String, bytes: &[u8]) {
    const HEX: &[u8; 16] = b"0123456789ABCDEF";
    out.reserve(bytes.len() * 3);
    for (i, byte) in bytes.iter().enumerate() {
        if i > 0 {
            out.push(' ');
        }
        out.push(char::from(HEX[usize::from(byte >> 4)]));
        out.push(char::from(HEX[usize::from(byte & 0x0F)]));
    }
}
