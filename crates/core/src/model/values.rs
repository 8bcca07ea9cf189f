//! Register value types (`--type`) and the byte order of wide values (`--order`), for showing
//! what was read and for turning what the user typed into registers to write.

use std::fmt;

use serde::Serialize;

use crate::input::choice::Choice;
use crate::input::number::parse_int;

/// How registers are read as values, and values written as registers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum ValueType {
    /// One register, unsigned.
    #[default]
    U16,
    /// One register, two's complement.
    I16,
    /// Two registers, unsigned.
    U32,
    /// Two registers, two's complement.
    I32,
    /// Two registers, an IEEE 754 single.
    F32,
    /// Four registers, unsigned.
    U64,
    /// Four registers, two's complement.
    I64,
    /// Four registers, an IEEE 754 double.
    F64,
    /// One register, shown as hex.
    Hex,
    /// One register, shown as 16 binary digits.
    Bin,
    /// One register, shown as its two bytes as characters, high byte first.
    Ascii,
}

/// Byte order of a value wider than one register, A being the most significant byte.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum ByteOrder {
    /// Big-endian: high word first, high byte first.
    #[default]
    Abcd,
    /// Low word first (word swap), as many PLCs store 32-bit values.
    Cdab,
    /// High word first, bytes swapped within each word.
    Badc,
    /// Little-endian.
    Dcba,
}

impl Choice for ValueType {
    const ALL: &'static [Self] = &[
        ValueType::U16,
        ValueType::I16,
        ValueType::U32,
        ValueType::I32,
        ValueType::F32,
        ValueType::U64,
        ValueType::I64,
        ValueType::F64,
        ValueType::Hex,
        ValueType::Bin,
        ValueType::Ascii,
    ];

    fn name(self) -> &'static str {
        match self {
            ValueType::U16 => "u16",
            ValueType::I16 => "i16",
            ValueType::U32 => "u32",
            ValueType::I32 => "i32",
            ValueType::F32 => "f32",
            ValueType::U64 => "u64",
            ValueType::I64 => "i64",
            ValueType::F64 => "f64",
            ValueType::Hex => "hex",
            ValueType::Bin => "bin",
            ValueType::Ascii => "ascii",
        }
    }

    /// The names of other tools: Home Assistant's and pymodbus's (`float32`, `int16`), the
    /// IEC 61131 types of PLCs (`REAL`, `DINT`, `WORD`), C's and mbpoll's (`float`, `int`).
    fn aliases(self) -> &'static [&'static str] {
        match self {
            ValueType::U16 => &["uint16", "uint", "word", "ushort", "unsigned"],
            ValueType::I16 => &["int16", "int", "short", "signed"],
            ValueType::U32 => &["uint32", "dword", "udint", "ulong"],
            ValueType::I32 => &["int32", "dint", "long"],
            ValueType::F32 => &["float32", "float", "real", "single"],
            ValueType::U64 => &["uint64", "ulint"],
            ValueType::I64 => &["int64", "lint"],
            ValueType::F64 => &["float64", "double", "lreal"],
            ValueType::Ascii => &["string", "text"],
            ValueType::Hex | ValueType::Bin => &[],
        }
    }
}

impl Choice for ByteOrder {
    const ALL: &'static [Self] = &[
        ByteOrder::Abcd,
        ByteOrder::Cdab,
        ByteOrder::Badc,
        ByteOrder::Dcba,
    ];

    fn name(self) -> &'static str {
        match self {
            ByteOrder::Abcd => "ABCD",
            ByteOrder::Cdab => "CDAB",
            ByteOrder::Badc => "BADC",
            ByteOrder::Dcba => "DCBA",
        }
    }

    fn help(self) -> Option<&'static str> {
        Some(match self {
            ByteOrder::Abcd => "Big-endian: high word first, high byte first",
            ByteOrder::Cdab => "Low word first (word swap), as many PLCs store 32-bit values",
            ByteOrder::Badc => "High word first, bytes swapped within each word",
            ByteOrder::Dcba => "Little-endian",
        })
    }
}

/// A coil value as people write it: on/off, 1/0, true/false, in any case.
pub fn parse_coil(word: &str) -> Result<bool, String> {
    match word.to_ascii_lowercase().as_str() {
        "1" | "on" | "true" => Ok(true),
        "0" | "off" | "false" => Ok(false),
        _ => Err(format!(
            "'{word}' is not a coil value: give on, off, 1, 0, true or false"
        )),
    }
}

/// A value read from registers, ready to be shown.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Value {
    /// An unsigned whole number.
    Unsigned(u64),
    /// A signed whole number.
    Signed(i64),
    /// Kept as f32, so that 3.14 shows as 3.14 and not as its nearest f64.
    Float32(f32),
    /// A double.
    Float(f64),
    /// A number shown with this many decimals (`230.50`), a number in JSON.
    #[serde(serialize_with = "decimal")]
    Decimal(f64, u8),
    /// Hex, binary or ASCII text.
    Text(String),
}

// serde's `serialize_with` hands a variant's fields by reference.
#[allow(clippy::trivially_copy_pass_by_ref)]
fn decimal<S: serde::Serializer>(
    value: &f64,
    places: &u8,
    serializer: S,
) -> Result<S::Ok, S::Error> {
    let rounded: f64 = format!("{value:.*}", usize::from(*places))
        .parse()
        .unwrap_or(*value);
    serializer.serialize_f64(rounded)
}

impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Value::Unsigned(v) => write!(f, "{v}"),
            Value::Signed(v) => write!(f, "{v}"),
            Value::Float32(v) => show_float(f, f64::from(*v), *v),
            Value::Float(v) => show_float(f, *v, *v),
            Value::Decimal(v, places) => write!(f, "{v:.*}", usize::from(*places)),
            Value::Text(v) => f.write_str(v),
        }
    }
}

/// A float in its shortest form that reads back the same, with an exponent when it is
/// very small or very large (`2.2869e-41`, not 41 zeros).
fn show_float<T: fmt::Display + fmt::LowerExp>(
    f: &mut fmt::Formatter<'_>,
    magnitude: f64,
    value: T,
) -> fmt::Result {
    let size = magnitude.abs();
    if size != 0.0 && size.is_finite() && !(1e-4..1e15).contains(&size) {
        write!(f, "{value:e}")
    } else {
        write!(f, "{value}")
    }
}

impl ValueType {
    /// How many registers one value takes.
    pub fn width(self) -> usize {
        match self {
            ValueType::U32 | ValueType::I32 | ValueType::F32 => 2,
            ValueType::U64 | ValueType::I64 | ValueType::F64 => 4,
            _ => 1,
        }
    }

    /// The values a whole-number type holds, signed or not as its name says.
    pub fn strict_range(self) -> (i128, i128) {
        let bits = 16 * self.width() as u32;
        match self {
            ValueType::I16 | ValueType::I32 | ValueType::I64 => {
                (-(1i128 << (bits - 1)), (1i128 << (bits - 1)) - 1)
            }
            _ => (0, (1i128 << bits) - 1),
        }
    }

    /// The values a whole-number type takes when written. An unsigned type takes negative
    /// values too, stored as two's complement, as a register holds no sign of its own.
    fn range(self) -> (i128, i128) {
        let bits = 16 * self.width() as u32;
        match self {
            ValueType::I16 | ValueType::I32 | ValueType::I64 => {
                (-(1i128 << (bits - 1)), (1i128 << (bits - 1)) - 1)
            }
            _ => (-(1i128 << (bits - 1)), (1i128 << bits) - 1),
        }
    }

    /// Reads one value from exactly `self.width()` registers.
    pub fn read(self, registers: &[u16], order: ByteOrder) -> Value {
        let mut bytes = [0u8; 8];
        let len = registers.len().min(4) * 2;
        for (pair, register) in bytes.chunks_exact_mut(2).zip(registers) {
            pair.copy_from_slice(&register.to_be_bytes());
        }
        reorder(&mut bytes[..len], order);
        let mut wide = [0u8; 8];
        wide[8 - len..].copy_from_slice(&bytes[..len]);
        let unsigned = u64::from_be_bytes(wide);
        match self {
            ValueType::U16 | ValueType::U32 | ValueType::U64 => Value::Unsigned(unsigned),
            ValueType::I16 => Value::Signed(i64::from(i16::from_be_bytes(
                (unsigned as u16).to_be_bytes(),
            ))),
            ValueType::I32 => Value::Signed(i64::from(i32::from_be_bytes(
                (unsigned as u32).to_be_bytes(),
            ))),
            ValueType::I64 => Value::Signed(i64::from_be_bytes(wide)),
            ValueType::F32 => Value::Float32(f32::from_bits(unsigned as u32)),
            ValueType::F64 => Value::Float(f64::from_bits(unsigned)),
            ValueType::Hex => Value::Text(format!("0x{unsigned:04X}")),
            ValueType::Bin => Value::Text(format!("0b{unsigned:016b}")),
            ValueType::Ascii => Value::Text(escape_text(&bytes[..len])),
        }
    }

    /// Reads every value of `registers`; a short tail that fills no whole value is left out.
    /// ASCII is one string of all the registers.
    pub fn read_all(self, registers: &[u16], order: ByteOrder) -> Vec<Value> {
        if self == ValueType::Ascii {
            return vec![text(registers, order)];
        }
        registers
            .chunks_exact(self.width())
            .map(|chunk| self.read(chunk, order))
            .collect()
    }

    /// Turns a value typed by the user into registers; `Err` says why it does not fit.
    pub fn parse(self, text: &str, order: ByteOrder) -> Result<Vec<u16>, String> {
        let bytes: Vec<u8> = match self {
            ValueType::F32 => {
                let value = parse_float(text, "f32")?;
                let single = value as f32;
                if !single.is_finite() {
                    return Err(format!(
                        "{text} does not fit in f32: give at most ±{:e} in size (or --type f64)",
                        f32::MAX
                    ));
                }
                single.to_be_bytes().to_vec()
            }
            ValueType::F64 => parse_float(text, "f64")?.to_be_bytes().to_vec(),
            ValueType::Ascii => {
                if !text.is_ascii() {
                    return Err(format!("'{text}' has characters outside ASCII"));
                }
                let mut bytes = text.as_bytes().to_vec();
                if bytes.len() % 2 == 1 {
                    bytes.push(0);
                }
                bytes
            }
            integer => {
                let bits = 16 * integer.width() as u32;
                let value = parse_int(text).map_err(|_| not_whole(text, integer))?;
                let (min, max) = integer.range();
                if value < min || value > max {
                    return Err(out_of_range(text, integer));
                }
                let raw = (value as u64) & (u64::MAX >> (64 - bits));
                raw.to_be_bytes()[(8 - bits as usize / 8)..].to_vec()
            }
        };
        let mut bytes = bytes;
        if self == ValueType::Ascii {
            // A string is a run of 16-bit words: only the swap within a word applies.
            if matches!(order, ByteOrder::Badc | ByteOrder::Dcba) {
                reorder(&mut bytes, ByteOrder::Badc);
            }
        } else {
            reorder(&mut bytes, order);
        }
        Ok(bytes
            .chunks_exact(2)
            .map(|pair| u16::from_be_bytes([pair[0], pair[1]]))
            .collect())
    }
}

/// A finite number for a float type, in decimal (`-2.5`, `1e-3`) or as a whole number in
/// any spelling.
fn parse_float(text: &str, type_name: &str) -> Result<f64, String> {
    let value = text
        .trim()
        .parse::<f64>()
        .ok()
        .or_else(|| parse_int(text).ok().map(|v| v as f64))
        .ok_or_else(|| format!("'{text}' is not a number for type {type_name}"))?;
    if value.is_finite() {
        Ok(value)
    } else {
        Err(format!(
            "'{text}' is not a finite number: {type_name} values must be"
        ))
    }
}

/// Why `text` is no value of the whole-number type `value_type`.
fn not_whole(text: &str, value_type: ValueType) -> String {
    let name = value_type.name();
    if text.trim().parse::<f64>().is_ok() {
        format!("'{text}' is not a whole number, which {name} takes: give --type f32 or f64 for it")
    } else {
        format!("'{text}' is not a number: write it in decimal, 0x hex or 0b binary")
    }
}

/// Why `text` is out of the range of the whole-number type `value_type`, and what would take it.
fn out_of_range(text: &str, value_type: ValueType) -> String {
    let name = value_type.name();
    let (min, max) = value_type.range();
    if max < -min {
        // A signed type: its unsigned twin takes the upper half.
        let unsigned = max * 2 + 1;
        format!("{text} does not fit in {name}: give {min} to {max} (or an unsigned --type for 0 to {unsigned})")
    } else {
        format!("{text} does not fit in {name}: give 0 to {max} (or {min} to -1, stored as two's complement)")
    }
}

/// Puts bytes in wire order `order` into big-endian order, or back: each order is its own
/// inverse. One register is never reordered by the word orders.
/// Puts `bytes`, registers high byte first, in `order`.
pub fn reorder(bytes: &mut [u8], order: ByteOrder) {
    match order {
        ByteOrder::Abcd => {}
        ByteOrder::Dcba => bytes.reverse(),
        ByteOrder::Badc => bytes.chunks_exact_mut(2).for_each(|pair| pair.swap(0, 1)),
        ByteOrder::Cdab => {
            let words = bytes.len() / 2;
            for i in 0..words / 2 {
                let (a, b) = (2 * i, 2 * (words - 1 - i));
                bytes.swap(a, b);
                bytes.swap(a + 1, b + 1);
            }
        }
    }
}

/// The text that `registers` hold, two characters each, high byte first (BADC and DCBA swap
/// the two); the NULs and spaces a device pads a string with are left out.
pub fn text(registers: &[u16], order: ByteOrder) -> Value {
    let mut bytes: Vec<u8> = registers.iter().flat_map(|r| r.to_be_bytes()).collect();
    if matches!(order, ByteOrder::Badc | ByteOrder::Dcba) {
        reorder(&mut bytes, ByteOrder::Badc);
    }
    let end = bytes
        .iter()
        .rposition(|b| *b != 0 && *b != b' ')
        .map_or(0, |last| last + 1);
    Value::Text(escape_text(&bytes[..end]))
}

/// Text from a device, safe to print: control and non-ASCII bytes become escapes, so a
/// device can never move the cursor or change the colours of the terminal.
pub fn escape_text(bytes: &[u8]) -> String {
    let mut out = String::with_capacity(bytes.len());
    for byte in bytes {
        match byte {
            b'\\' => out.push_str("\\\\"),
            0x20..=0x7E => out.push(char::from(*byte)),
            0 => out.push_str("\\0"),
            b'\n' => out.push_str("\\n"),
            b'\r' => out.push_str("\\r"),
            b'\t' => out.push_str("\\t"),
            other => out.push_str(&format!("\\x{other:02X}")),
        }
    }
    out
}

/// The coils or registers a read returned.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ReadData {
    /// Register values, as received.
    Registers(Vec<u16>),
    /// Coil or discrete input states, exactly as many as asked for.
    Bits(Vec<bool>),
}

impl ReadData {
    /// How many coils or registers were read.
    pub fn len(&self) -> usize {
        match self {
            ReadData::Registers(registers) => registers.len(),
            ReadData::Bits(bits) => bits.len(),
        }
    }

    /// Nothing was read.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn f32_in_every_order_round_trips() {
        for order in [
            ByteOrder::Abcd,
            ByteOrder::Cdab,
            ByteOrder::Badc,
            ByteOrder::Dcba,
        ] {
            let registers = ValueType::F32.parse("-1234.5", order).unwrap();
            assert_eq!(
                ValueType::F32.read(&registers, order),
                Value::Float32(-1234.5)
            );
            assert_eq!(
                ValueType::F32.read(&registers, order).to_string(),
                "-1234.5"
            );
        }
    }

    #[test]
    fn f32_shows_as_typed() {
        let registers = ValueType::F32.parse("3.14", ByteOrder::Abcd).unwrap();
        assert_eq!(
            ValueType::F32.read(&registers, ByteOrder::Abcd).to_string(),
            "3.14"
        );
    }

    #[test]
    fn f32_orders_on_the_wire() {
        // 3.14f32 = 0x4048F5C3
        assert_eq!(
            ValueType::F32.parse("3.14", ByteOrder::Abcd),
            Ok(vec![0x4048, 0xF5C3])
        );
        assert_eq!(
            ValueType::F32.parse("3.14", ByteOrder::Cdab),
            Ok(vec![0xF5C3, 0x4048])
        );
        assert_eq!(
            ValueType::F32.parse("3.14", ByteOrder::Badc),
            Ok(vec![0x4840, 0xC3F5])
        );
        assert_eq!(
            ValueType::F32.parse("3.14", ByteOrder::Dcba),
            Ok(vec![0xC3F5, 0x4840])
        );
    }

    #[test]
    fn negative_values_are_twos_complement() {
        assert_eq!(
            ValueType::I16.parse("-1", ByteOrder::Abcd),
            Ok(vec![0xFFFF])
        );
        assert_eq!(
            ValueType::U16.parse("-2", ByteOrder::Abcd),
            Ok(vec![0xFFFE])
        );
        assert_eq!(
            ValueType::I16.read(&[0xFFFE], ByteOrder::Abcd),
            Value::Signed(-2)
        );
        assert!(ValueType::U16.parse("65536", ByteOrder::Abcd).is_err());
        assert!(ValueType::U16.parse("-32769", ByteOrder::Abcd).is_err());
    }

    #[test]
    fn a_value_outside_its_type_is_refused_naming_the_range() {
        let refused =
            |value_type: ValueType, text| value_type.parse(text, ByteOrder::Abcd).unwrap_err();
        assert_eq!(
            refused(ValueType::I16, "40000"),
            "40000 does not fit in i16: give -32768 to 32767 (or an unsigned --type for 0 to 65535)"
        );
        assert_eq!(
            refused(ValueType::U16, "70000"),
            "70000 does not fit in u16: give 0 to 65535 (or -32768 to -1, stored as two's complement)"
        );
        assert_eq!(
            refused(ValueType::F32, "1e39"),
            "1e39 does not fit in f32: give at most ±3.4028235e38 in size (or --type f64)"
        );
        assert_eq!(
            refused(ValueType::U16, "3.7"),
            "'3.7' is not a whole number, which u16 takes: give --type f32 or f64 for it"
        );
        assert_eq!(
            refused(ValueType::F64, "inf"),
            "'inf' is not a finite number: f64 values must be"
        );
        assert_eq!(
            ValueType::I32.parse("-1", ByteOrder::Abcd),
            Ok(vec![0xFFFF, 0xFFFF])
        );
        assert!(ValueType::I16.parse("32768", ByteOrder::Abcd).is_err());
    }

    #[test]
    fn u64_word_swap() {
        let registers = ValueType::U64
            .parse("0x0102030405060708", ByteOrder::Cdab)
            .unwrap();
        assert_eq!(registers, [0x0708, 0x0506, 0x0304, 0x0102]);
    }

    #[test]
    fn floats_show_in_their_shortest_form() {
        assert_eq!(Value::Float32(2.1).to_string(), "2.1");
        assert_eq!(
            Value::Float32(f32::from_bits(0x3FC2)).to_string(),
            "2.2872e-41"
        );
        assert_eq!(Value::Float(1e20).to_string(), "1e20");
        assert_eq!(Value::Float(-0.5).to_string(), "-0.5");
        assert_eq!(Value::Float(0.0).to_string(), "0");
    }

    #[test]
    fn ascii_is_one_string_without_its_padding() {
        let registers = [0x5055, 0x4D50, 0x2031, 0x0000];
        assert_eq!(
            ValueType::Ascii.read_all(&registers, ByteOrder::Abcd),
            [Value::Text("PUMP 1".into())]
        );
        assert_eq!(
            text(&[0x5550, 0x504D], ByteOrder::Badc),
            Value::Text("PUMP".into())
        );
    }

    #[test]
    fn a_string_in_swapped_bytes_and_padded_with_spaces() {
        // "PUMP 1  " as a device that stores each register's bytes swapped sends it.
        let registers: Vec<u16> = [*b"UP", *b"PM", *b"1 ", *b"  "]
            .iter()
            .map(|pair| u16::from_be_bytes(*pair))
            .collect();
        assert_eq!(
            text(&registers, ByteOrder::Badc),
            Value::Text("PUMP 1".into())
        );
        assert_eq!(
            ValueType::Ascii.parse("PUMP 1", ByteOrder::Badc),
            Ok(registers[..3].to_vec())
        );
    }

    #[test]
    fn device_text_is_escaped() {
        assert_eq!(escape_text(b"PLC\x1b[2J\n"), "PLC\\x1B[2J\\n");
    }
}
