//! Numbers as users type them: decimal, `0x` hex or `0b` binary, optionally negative.

use thiserror::Error;

/// Text that is no whole number.
#[derive(Clone, Debug, Error, PartialEq, Eq)]
#[error("'{text}' is not a number: write it in decimal, 0x hex or 0b binary")]
pub struct NumberError {
    /// The text as typed.
    pub text: String,
}

/// Parses a whole number; `_` may separate digits.
pub fn parse_int(text: &str) -> Result<i128, NumberError> {
    let error = || NumberError {
        text: text.to_string(),
    };
    let trimmed = text.trim();
    let (negative, body) = match trimmed.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, trimmed.strip_prefix('+').unwrap_or(trimmed)),
    };
    let lower = body.to_ascii_lowercase();
    let (radix, digits) = if let Some(hex) = lower.strip_prefix("0x") {
        (16, hex)
    } else if let Some(bin) = lower.strip_prefix("0b") {
        (2, bin)
    } else {
        (10, lower.as_str())
    };
    let digits: String = digits.chars().filter(|c| *c != '_').collect();
    if digits.is_empty() || digits.starts_with(['+', '-']) {
        return Err(error());
    }
    let magnitude = i128::from_str_radix(&digits, radix).map_err(|_| error())?;
    Ok(if negative { -magnitude } else { magnitude })
}

/// Parses a whole number that must lie in `min..=max`; `what` names it in the message.
pub fn parse_in_range(text: &str, min: i128, max: i128, what: &str) -> Result<i128, String> {
    let value = parse_int(text).map_err(|e| e.to_string())?;
    if value < min || value > max {
        return Err(format!("{what} {text} is out of range {min}-{max}"));
    }
    Ok(value)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_three_spellings() {
        assert_eq!(parse_int("107"), Ok(107));
        assert_eq!(parse_int("0x6B"), Ok(107));
        assert_eq!(parse_int("0b1101011"), Ok(107));
        assert_eq!(parse_int("-0x10"), Ok(-16));
        assert!(parse_int("0x").is_err());
        assert!(parse_int("12a").is_err());
        assert!(parse_int("--1").is_err());
    }
}
