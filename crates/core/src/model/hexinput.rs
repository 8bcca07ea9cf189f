//! Frames as people paste them: `11 03 00 6B`, `1103006B`, `0x11,0x03`, `\x11\x03`, or an
//! ASCII frame as text (`:1103006B00037E`).

use thiserror::Error;

use crate::codec::adu::hex_digit;

/// Why pasted text is no run of hex bytes.
#[derive(Clone, Debug, Error, PartialEq, Eq)]
pub enum HexError {
    /// Nothing but separators.
    #[error("empty: no hex digits")]
    Empty,
    /// A word whose hex digits do not pair into bytes.
    #[error("odd number of hex digits in '{0}': every byte takes two")]
    OddDigits(String),
    /// A `0x` or `\x` prefix with nothing after it.
    #[error("'{0}' has no hex digits after its prefix")]
    NoDigits(String),
    /// A character that is no hex digit, with its column (1-based).
    #[error("'{0}' at column {1} is not a hex digit")]
    NotHex(String, usize),
}

fn is_separator(b: u8) -> bool {
    b.is_ascii_whitespace() || matches!(b, b',' | b';')
}

/// Shows a byte of the input in an error message without printing it raw.
fn shown(text: &[u8], at: usize) -> String {
    let rest = text.get(at..).unwrap_or_default();
    match std::str::from_utf8(rest)
        .ok()
        .and_then(|s| s.chars().next())
    {
        Some(c) if !c.is_control() => c.to_string(),
        _ => format!("\\x{:02X}", rest.first().copied().unwrap_or_default()),
    }
}

/// Appends the bytes that the hex `text` spells to `out`.
pub fn parse_hex(text: &[u8], out: &mut Vec<u8>) -> Result<(), HexError> {
    let start = out.len();
    let mut i = 0;
    while i < text.len() {
        if is_separator(text[i]) {
            i += 1;
            continue;
        }
        // One token: an optional 0x or \x prefix, then hex digits up to a separator.
        let prefixed = matches!(
            text.get(i..i + 2),
            Some([b'0', b'x' | b'X'] | [b'\\', b'x'])
        );
        let token_start = i;
        if prefixed {
            i += 2;
        }
        let digits_start = i;
        while i < text.len() && !is_separator(text[i]) {
            if text[i] == b'\\' && text.get(i + 1) == Some(&b'x') {
                break;
            }
            if hex_digit(text[i]).is_none() {
                return Err(HexError::NotHex(shown(text, i), i + 1));
            }
            i += 1;
        }
        let digits = &text[digits_start..i];
        match digits.len() {
            0 => {
                let token = String::from_utf8_lossy(&text[token_start..i]);
                return Err(HexError::NoDigits(token.into_owned()));
            }
            1 if prefixed => out.push(hex_digit(digits[0]).unwrap_or_default()),
            n if n % 2 == 1 => {
                let token = String::from_utf8_lossy(&text[token_start..i]);
                return Err(HexError::OddDigits(token.chars().take(40).collect()));
            }
            _ => out.extend(digits.chunks_exact(2).map(|pair| {
                hex_digit(pair[0]).unwrap_or_default() << 4 | hex_digit(pair[1]).unwrap_or_default()
            })),
        }
    }
    if out.len() == start {
        return Err(HexError::Empty);
    }
    Ok(())
}

/// Hex given as several command-line words.
pub fn parse_hex_words(words: &[String]) -> Result<Vec<u8>, HexError> {
    let mut out = Vec::new();
    for word in words {
        parse_hex(word.as_bytes(), &mut out)?;
    }
    if out.is_empty() {
        return Err(HexError::Empty);
    }
    Ok(out)
}

/// The bytes of one frame as written on a line: an ASCII frame as its own characters,
/// anything else as hex.
pub fn frame_bytes(line: &[u8], out: &mut Vec<u8>) -> Result<(), HexError> {
    let line = line.trim_ascii();
    if line.first() == Some(&b':') {
        out.extend_from_slice(line);
        return Ok(());
    }
    parse_hex(line, out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hex(text: &str) -> Result<Vec<u8>, HexError> {
        let mut out = Vec::new();
        parse_hex(text.as_bytes(), &mut out).map(|()| out)
    }

    #[test]
    fn the_common_spellings() {
        let want = vec![0x11, 0x03, 0x00, 0x6B];
        assert_eq!(hex("11 03 00 6B"), Ok(want.clone()));
        assert_eq!(hex("1103006b"), Ok(want.clone()));
        assert_eq!(hex("0x11,0x03,0x00,0x6B"), Ok(want.clone()));
        assert_eq!(hex("0x11, 0x3, 0x0, 0x6b"), Ok(want.clone()));
        assert_eq!(hex("\\x11\\x03\\x00\\x6B"), Ok(want));
    }

    #[test]
    fn bad_spellings_say_why() {
        assert!(matches!(hex("110"), Err(HexError::OddDigits(_))));
        assert!(matches!(hex("11 0G"), Err(HexError::NotHex(c, 5)) if c == "G"));
        assert_eq!(hex("  "), Err(HexError::Empty));
        assert!(matches!(hex("11 é"), Err(HexError::NotHex(c, _)) if c == "é"));
        assert!(matches!(hex("0x"), Err(HexError::NoDigits(_))));
    }
}
