//! Value layouts: what a run of registers reads as in every type and byte order, and
//! which layouts give a value the user knows the device holds (229 V on the meter's
//! display), nearest first: the answer to "is this float CDAB or ABCD".

use super::values::{text, ByteOrder, Value, ValueType};
use crate::input::choice::Choice;

/// A type and a byte order: how a value lies in registers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layout {
    /// The type.
    pub value_type: ValueType,
    /// The order of its bytes and words.
    pub order: ByteOrder,
}

/// The orders that differ for a value `width` registers wide: one register has its two
/// bytes in order or swapped.
fn orders(width: usize) -> &'static [ByteOrder] {
    match width {
        1 => &[ByteOrder::Abcd, ByteOrder::Badc],
        _ => &[
            ByteOrder::Abcd,
            ByteOrder::Cdab,
            ByteOrder::Badc,
            ByteOrder::Dcba,
        ],
    }
}

/// Every numeric layout, the simplest first (the order of the value types): where two
/// layouts give the same value, the simpler is the likelier.
pub fn numeric_layouts() -> Vec<Layout> {
    ValueType::ALL
        .iter()
        .filter(|value_type| {
            !matches!(
                value_type,
                ValueType::Hex | ValueType::Bin | ValueType::Ascii
            )
        })
        .flat_map(|&value_type| {
            orders(value_type.width())
                .iter()
                .map(move |&order| Layout { value_type, order })
        })
        .collect()
}

/// What registers read as in one layout.
#[derive(Clone, Debug, PartialEq)]
pub struct Reading {
    /// The first register it takes, counted from the first read.
    pub offset: usize,
    /// The layout.
    pub layout: Layout,
    /// The registers it takes.
    pub registers: Vec<u16>,
    /// The value.
    pub value: Value,
}

/// Every layout read from the first register: each numeric type the registers are wide
/// enough for, in each order, then all the registers as text, bytes in order and swapped.
pub fn at_start(registers: &[u16]) -> Vec<Reading> {
    let mut readings: Vec<Reading> = numeric_layouts()
        .into_iter()
        .filter_map(|layout| reading(registers, 0, layout))
        .collect();
    if !registers.is_empty() {
        for order in [ByteOrder::Abcd, ByteOrder::Badc] {
            readings.push(Reading {
                offset: 0,
                layout: Layout {
                    value_type: ValueType::Ascii,
                    order,
                },
                registers: registers.to_vec(),
                value: text(registers, order),
            });
        }
    }
    readings
}

fn reading(registers: &[u16], offset: usize, layout: Layout) -> Option<Reading> {
    let taken = registers.get(offset..offset + layout.value_type.width())?;
    Some(Reading {
        offset,
        layout,
        registers: taken.to_vec(),
        value: layout.value_type.read(taken, layout.order),
    })
}

/// The value the user expects: about a number, or within a range.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Expected {
    /// About this number: within 1% of it (0.01 of 0).
    About(f64),
    /// Between these, both included.
    Within(f64, f64),
}

impl Expected {
    /// `229.0`, or a range `228..231`.
    pub fn parse(text: &str) -> Result<Expected, String> {
        let number = |word: &str| {
            word.trim()
                .parse::<f64>()
                .ok()
                .filter(|n| n.is_finite())
                .ok_or_else(|| {
                    format!("--expect {text}: give a number (229.0) or a range (228..231)")
                })
        };
        match text.split_once("..") {
            Some((low, high)) => {
                let (low, high) = (number(low)?, number(high)?);
                if low > high {
                    return Err(format!(
                        "--expect {text}: the lower end of a range comes first"
                    ));
                }
                Ok(Expected::Within(low, high))
            }
            None => Ok(Expected::About(number(text)?)),
        }
    }

    /// How far `value` is from what is expected, 0 inside a range; `None` when too far.
    fn distance(self, value: f64) -> Option<f64> {
        match self {
            Expected::About(expected) => {
                let distance = (value - expected).abs();
                (distance <= (expected.abs() * 0.01).max(0.01)).then_some(distance)
            }
            Expected::Within(low, high) => (low..=high).contains(&value).then_some(0.0),
        }
    }
}

impl std::fmt::Display for Expected {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Expected::About(value) => write!(f, "{value}"),
            Expected::Within(low, high) => write!(f, "{low} to {high}"),
        }
    }
}

/// A layout that gives the value expected, and how far from it.
#[derive(Clone, Debug, PartialEq)]
pub struct Candidate {
    /// What the registers read as in it.
    pub reading: Reading,
    /// How far its value is from the one expected.
    pub distance: f64,
}

fn as_number(value: &Value) -> Option<f64> {
    let number = match value {
        Value::Unsigned(v) => *v as f64,
        Value::Signed(v) => *v as f64,
        Value::Float32(v) => f64::from(*v),
        Value::Float(v) | Value::Decimal(v, _) => *v,
        Value::Text(_) => return None,
    };
    number.is_finite().then_some(number)
}

/// The numeric layouts, at every register read, that give the value expected. Those that
/// give it exactly (a range: anywhere in it) come first; then the nearer the first register read, then the simpler
/// layout, then the nearer the value. A float made of the high word of one value and the
/// low word of the next can come near a number by chance; the register the user named is
/// the likelier place.
pub fn rank(registers: &[u16], expected: Expected) -> Vec<Candidate> {
    let layouts = numeric_layouts();
    let mut candidates: Vec<(usize, Candidate)> = Vec::new();
    for offset in 0..registers.len() {
        for (simplicity, layout) in layouts.iter().enumerate() {
            let Some(reading) = reading(registers, offset, *layout) else {
                continue;
            };
            let Some(distance) = as_number(&reading.value).and_then(|v| expected.distance(v))
            else {
                continue;
            };
            candidates.push((simplicity, Candidate { reading, distance }));
        }
    }
    // Exact as far as the layout holds the number: an f32 keeps 7 digits.
    let scale = match expected {
        Expected::About(value) => value.abs(),
        Expected::Within(..) => 0.0,
    };
    let exact = |c: &Candidate| c.distance <= scale * 1e-6;
    candidates.sort_by(|(a_simple, a), (b_simple, b)| {
        exact(b)
            .cmp(&exact(a))
            .then(a.reading.offset.cmp(&b.reading.offset))
            .then(a_simple.cmp(b_simple))
            .then(a.distance.total_cmp(&b.distance))
    });
    candidates.into_iter().map(|(_, c)| c).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `value` in `layout`, as registers.
    fn laid(value: &str, layout: Layout) -> Vec<u16> {
        layout.value_type.parse(value, layout.order).unwrap()
    }

    #[test]
    fn a_value_in_any_layout_ranks_that_layout_first() {
        let values = [
            (ValueType::U16, "51234"),
            (ValueType::I16, "-1234"),
            (ValueType::U32, "3000000000"),
            (ValueType::I32, "-123456789"),
            (ValueType::F32, "229.01"),
            (ValueType::U64, "12345678901234567890"),
            (ValueType::I64, "-1234567890123"),
            (ValueType::F64, "-1234.5678"),
        ];
        for (value_type, value) in values {
            for &order in orders(value_type.width()) {
                let layout = Layout { value_type, order };
                // Surrounded by other registers, as a read of a block finds it.
                let registers = [&[0x1234, 0x0001][..], &laid(value, layout), &[0xFFFF]].concat();
                let expected = Expected::parse(value).unwrap();
                let best = &rank(&registers, expected)[0];
                assert_eq!(
                    (best.reading.layout, best.reading.offset),
                    (layout, 2),
                    "{value} as {value_type:?} {order:?}"
                );
            }
        }
    }

    #[test]
    fn the_thingsboard_case_is_told_apart() {
        // 229.01 as f32 CDAB, read as ABCD, is 2.4e-41: --expect 229 finds CDAB.
        let registers = laid(
            "229.01",
            Layout {
                value_type: ValueType::F32,
                order: ByteOrder::Cdab,
            },
        );
        let best = &rank(&registers, Expected::parse("228..230").unwrap())[0];
        assert_eq!(best.reading.layout.order, ByteOrder::Cdab);
        assert!(Expected::parse("230..228").is_err());
        assert!(Expected::parse("volts").is_err());
        assert_eq!(at_start(&registers).len(), 2 + 2 + 4 + 4 + 4 + 2);
    }
}
