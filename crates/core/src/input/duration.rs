//! Durations as users type them: `500ms`, `1s`, `2.5s`, `250us`, `1m`.

use std::time::Duration;

/// The largest bare number taken as seconds: a bare 500 is far more often milliseconds
/// meant (as Modbus Poll and most device manuals count) than eight minutes.
const BARE_SECONDS_MAX: f64 = 60.0;

/// Parses a duration; a bare number is seconds, up to 60.
pub fn parse_duration(text: &str) -> Result<Duration, String> {
    let text = text.trim();
    let split = text
        .find(|c: char| !(c.is_ascii_digit() || c == '.'))
        .unwrap_or(text.len());
    let (number, unit) = text.split_at(split);
    let value: f64 = number
        .parse()
        .map_err(|_| format!("'{text}' is not a duration: write 500ms, 1s or 2.5s"))?;
    let seconds = match unit.trim() {
        "" if value > BARE_SECONDS_MAX => {
            return Err(format!(
                "'{text}' without a unit would be {text} seconds: give {text}ms, or {text}s if seconds are meant"
            ))
        }
        "" | "s" => value,
        "ms" => value / 1e3,
        "us" | "µs" => value / 1e6,
        "m" | "min" => value * 60.0,
        other => {
            return Err(format!(
                "'{other}' is not a unit of time: use us, ms, s or m"
            ))
        }
    };
    Duration::try_from_secs_f64(seconds).map_err(|_| format!("'{text}' is out of range"))
}

/// A duration for messages and summaries: `850 us`, `1.25 ms`, `2.00 s`.
pub fn show(duration: Duration) -> String {
    let ms = duration.as_secs_f64() * 1e3;
    if ms < 1.0 {
        format!("{:.0} us", ms * 1e3)
    } else if ms < 1000.0 {
        format!("{ms:.2} ms")
    } else {
        format!("{:.2} s", ms / 1e3)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spellings() {
        assert_eq!(parse_duration("500ms"), Ok(Duration::from_millis(500)));
        assert_eq!(parse_duration("1s"), Ok(Duration::from_secs(1)));
        assert_eq!(parse_duration("2.5s"), Ok(Duration::from_millis(2500)));
        assert_eq!(parse_duration("0"), Ok(Duration::ZERO));
        assert_eq!(parse_duration("60"), Ok(Duration::from_secs(60)));
        assert_eq!(
            parse_duration("500"),
            Err("'500' without a unit would be 500 seconds: give 500ms, or 500s if seconds are meant".into())
        );
        assert_eq!(parse_duration("500s"), Ok(Duration::from_secs(500)));
        assert!(parse_duration("fast").is_err());
        assert!(parse_duration("5 parsecs").is_err());
    }
}
