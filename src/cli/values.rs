//! The parsers of option values: whole numbers in a range, durations, names the core offers.

use mbtool_core::input::choice::Choice;

/// The parser of a whole number option: any spelling users type (19200, 0x4B00), in
/// `min..=max`, the range said when it is not.
pub(super) fn whole<T>(
    min: i128,
    max: i128,
) -> impl Fn(&str) -> Result<T, String> + Clone + Send + Sync
where
    T: TryFrom<i128>,
{
    move |text| {
        mbtool_core::input::number::parse_int(text)
            .ok()
            .filter(|value| (min..=max).contains(value))
            .and_then(|value| T::try_from(value).ok())
            .ok_or_else(|| format!("give a whole number from {min} to {max}"))
    }
}

/// [`whole`], in a range the core fixes (a serial line's speed, its data or stop bits).
pub(super) fn whole_in<T>(
    range: std::ops::RangeInclusive<T>,
) -> impl Fn(&str) -> Result<T, String> + Clone + Send + Sync
where
    T: TryFrom<i128> + Into<i128> + Copy,
{
    whole((*range.start()).into(), (*range.end()).into())
}

/// A duration that must not be zero: a timeout of 0 would give up before a byte could come.
pub(super) fn positive_duration(text: &str) -> Result<std::time::Duration, String> {
    match mbtool_core::input::duration::parse_duration(text)? {
        std::time::Duration::ZERO => Err("give a timeout above zero, as 500ms or 1s".into()),
        duration => Ok(duration),
    }
}

/// The parser of a setting the core offers by name: its names, each with its help, are
/// what clap lists in `--help`, the man pages and the completions.
pub(super) fn choice<T: Choice + Clone + Send + Sync>(
) -> impl clap::builder::TypedValueParser<Value = T> {
    use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
    PossibleValuesParser::new(T::ALL.iter().map(|choice| {
        let value = PossibleValue::new(choice.name()).aliases(choice.aliases().iter().copied());
        match choice.help() {
            Some(help) => value.help(help),
            None => value,
        }
    }))
    .try_map(|name| T::from_name(&name).ok_or("not one of the possible values"))
}

/// A switch set from the environment: `MBTOOL_RS485=1`. Empty, `0`, `false`, `no` or
/// `off` leave it off, as a script that clears the variable means.
pub(super) fn switch(text: &str) -> Result<bool, String> {
    match text.trim().to_ascii_lowercase().as_str() {
        "" | "0" | "false" | "no" | "off" => Ok(false),
        "1" | "true" | "yes" | "on" => Ok(true),
        _ => Err("give 1 to turn it on, 0 (or nothing) to leave it off".into()),
    }
}
