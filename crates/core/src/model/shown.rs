//! A value as Home Assistant shows it once read: scale and offset applied, then its
//! `min_value` and `max_value`, `zero_suppress` and `precision`, and a raw value equal to
//! `nan_value` (or a float NaN) shown as unknown.

use super::structure::Unpacked;
use super::values::Value;

/// The keys of a Home Assistant entity that change how its value is shown.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Shown {
    /// The decimals shown: Home Assistant's `precision`, 0 for whole-number types and 2
    /// for floats where it is not given.
    pub precision: u8,
    /// A value below is shown as this.
    pub min: Option<f64>,
    /// A value above is shown as this.
    pub max: Option<f64>,
    /// A raw value equal to this or to its negative means "no value" (0 is no marker).
    pub nan: Option<i128>,
    /// A value at most this far from 0 is shown as 0.
    pub zero_suppress: Option<f64>,
    /// The states a raw value stands for, for an entity that is on or off, open or closed.
    pub states: Option<States>,
    /// What a switch kept in a register is written to turn it on and off
    /// (`command_on`, `command_off`).
    pub commands: Option<[u16; 2]>,
}

/// What Home Assistant names the states of an entity that has states, not a number.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum States {
    /// A binary sensor, switch, light or fan: on for one of `on`, off for one of `off`.
    OnOff {
        /// The values that are on.
        on: Vec<i64>,
        /// The values that are off.
        off: Vec<i64>,
    },
    /// A cover: open, closed, opening, closing for these values.
    Cover {
        /// The values of open, closed, opening and closing, in that order.
        values: [i64; 4],
    },
}

impl States {
    /// The state a raw value stands for; `unknown` for one that stands for none.
    pub fn state(&self, raw: u64) -> Value {
        let raw = i64::try_from(raw).unwrap_or(i64::MAX);
        let name = match self {
            States::OnOff { on, .. } if on.contains(&raw) => "on",
            States::OnOff { off, .. } if off.contains(&raw) => "off",
            States::Cover { values } => match values.iter().position(|value| *value == raw) {
                Some(0) => "open",
                Some(1) => "closed",
                Some(2) => "opening",
                Some(3) => "closing",
                _ => UNKNOWN,
            },
            States::OnOff { .. } => UNKNOWN,
        };
        Value::Text(name.into())
    }
}

/// What a value the device marks as none is shown as: Home Assistant's state for it.
pub const UNKNOWN: &str = "unknown";

impl Shown {
    /// The value shown for a raw number.
    pub fn number(&self, scale: f64, offset: f64, raw: f64) -> Value {
        let marked = self
            .nan
            .filter(|nan| *nan != 0)
            .is_some_and(|nan| raw == nan as f64 || raw == -(nan as f64));
        if marked || raw.is_nan() {
            return Value::Text(UNKNOWN.into());
        }
        let mut value = scale * raw + offset;
        if let Some(min) = self.min.filter(|min| value < *min) {
            value = min;
        }
        if let Some(max) = self.max.filter(|max| value > *max) {
            value = max;
        }
        if self.zero_suppress.is_some_and(|zero| value.abs() <= zero) {
            return Value::Unsigned(0);
        }
        match self.precision {
            0 => {
                let whole = value.round_ties_even();
                if whole.abs() < 9.0e18 {
                    Value::Signed(whole as i64)
                } else {
                    // Every digit, as Python's round() gives a whole number of any size.
                    Value::Decimal(whole, 0)
                }
            }
            places => Value::Decimal(value, places),
        }
    }

    /// The values of a custom structure, as Home Assistant joins them: each shown as a
    /// number is, text as it is, a value without one as 0.
    pub fn unpacked(&self, scale: f64, offset: f64, values: &[Unpacked]) -> Value {
        let shown: Vec<String> = values
            .iter()
            .map(|value| match value {
                Unpacked::Whole(whole) => self.number(scale, offset, *whole as f64),
                Unpacked::Float(float) => self.number(scale, offset, *float),
                Unpacked::Bytes(bytes) => Value::Text(super::values::escape_text(bytes)),
            })
            .map(|value| match value {
                Value::Text(text) if text == UNKNOWN => "0".to_string(),
                value => value.to_string(),
            })
            .collect();
        match shown.as_slice() {
            [one] => Value::Text(one.clone()),
            _ => Value::Text(shown.join(",")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn as_home_assistant_shows_it() {
        let plain = Shown::default();
        // Whole types default to no decimals: 0.1 x 2305 is 230 (round half to even).
        assert_eq!(plain.number(0.1, 0.0, 2305.0).to_string(), "230");
        assert_eq!(plain.number(1.0, 0.0, 2.5).to_string(), "2");
        let two = Shown {
            precision: 2,
            ..Shown::default()
        };
        assert_eq!(two.number(1.0, 0.0, 230.5).to_string(), "230.50");
        let clamped = Shown {
            max: Some(50.0),
            min: Some(-10.0),
            ..Shown::default()
        };
        assert_eq!(clamped.number(1.0, 0.0, 100.0).to_string(), "50");
        assert_eq!(clamped.number(1.0, 0.0, -100.0).to_string(), "-10");
        let marked = Shown {
            nan: Some(0x7FFF),
            zero_suppress: Some(0.5),
            ..Shown::default()
        };
        assert_eq!(marked.number(1.0, 0.0, 32767.0).to_string(), UNKNOWN);
        assert_eq!(marked.number(1.0, 0.0, -32767.0).to_string(), UNKNOWN);
        assert_eq!(marked.number(0.1, 0.0, 3.0).to_string(), "0");
        assert_eq!(plain.number(1.0, 0.0, f64::NAN).to_string(), UNKNOWN);
    }

    #[test]
    fn states_as_home_assistant_names_them() {
        let switch = States::OnOff {
            on: vec![1, 2, 3],
            off: vec![0],
        };
        let named: Vec<String> = (0..5).map(|raw| switch.state(raw).to_string()).collect();
        assert_eq!(named, ["off", "on", "on", "on", UNKNOWN]);
        let cover = States::Cover {
            values: [1, 0, 2, 3],
        };
        let named: Vec<String> = (0..5).map(|raw| cover.state(raw).to_string()).collect();
        assert_eq!(named, ["closed", "open", "opening", "closing", UNKNOWN]);
    }
}
