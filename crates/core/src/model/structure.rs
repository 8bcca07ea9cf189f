//! Python `struct` formats, as Home Assistant's `data_type: custom` takes them in
//! `structure`: the size a format says and the values it unpacks from a run of registers,
//! as Python's `struct.calcsize` and `struct.unpack` give them.

/// One value a format unpacks.
#[derive(Clone, Debug, PartialEq)]
pub enum Unpacked {
    /// `b B h H i I l L q Q n N ?`: a whole number.
    Whole(i128),
    /// `e f d`: a float.
    Float(f64),
    /// `c s p`: bytes.
    Bytes(Vec<u8>),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Code {
    Pad,
    Char,
    Signed(usize),
    Unsigned(usize),
    Bool,
    Float(usize),
    /// `s`: the count is the length of one string.
    Text,
    /// `p`: a length byte, then the string.
    Pascal,
}

/// A parsed format: its byte order, and each code with its count.
#[derive(Clone, Debug, PartialEq)]
pub struct Structure {
    little: bool,
    /// `@` or no prefix: native sizes and alignment (x86-64's).
    aligned: bool,
    items: Vec<(Code, usize)>,
}

impl Structure {
    /// Parses a format such as `>2h`, `<If`, `>10s`; an error says what Python would.
    pub fn parse(format: &str) -> Result<Self, String> {
        let mut chars = format.trim().chars().peekable();
        let (little, aligned) = match chars.peek() {
            Some('<') => (true, false),
            Some('>' | '!') => (false, false),
            Some('=') => (true, false),
            Some('@') => (true, true),
            _ => (true, true),
        };
        if !aligned || format.trim().starts_with('@') {
            chars.next();
        }
        let mut items = Vec::new();
        let mut count: Option<usize> = None;
        for c in chars {
            if c.is_whitespace() {
                continue;
            }
            if let Some(digit) = c.to_digit(10) {
                let next = count
                    .unwrap_or(0)
                    .checked_mul(10)
                    .and_then(|n| n.checked_add(digit as usize))
                    .filter(|n| *n <= 1 << 16)
                    .ok_or("a count in the structure is too large")?;
                count = Some(next);
                continue;
            }
            let code = match c {
                'x' => Code::Pad,
                'c' => Code::Char,
                'b' => Code::Signed(1),
                'B' => Code::Unsigned(1),
                '?' => Code::Bool,
                'h' => Code::Signed(2),
                'H' => Code::Unsigned(2),
                'i' | 'l' => Code::Signed(4),
                'I' | 'L' => Code::Unsigned(4),
                'q' => Code::Signed(8),
                'Q' => Code::Unsigned(8),
                'n' if aligned => Code::Signed(8),
                'N' | 'P' if aligned => Code::Unsigned(8),
                'e' => Code::Float(2),
                'f' => Code::Float(4),
                'd' => Code::Float(8),
                's' => Code::Text,
                'p' => Code::Pascal,
                other => return Err(format!("bad char '{other}' in struct format")),
            };
            items.push((code, count.take().unwrap_or(1)));
        }
        if count.is_some() {
            return Err("repeat count given without format specifier".into());
        }
        Ok(Structure {
            little,
            aligned,
            items,
        })
    }

    /// The bytes it takes, as `struct.calcsize` says.
    pub fn size(&self) -> usize {
        let mut size = 0;
        for (code, count) in &self.items {
            size = self.align(size, *code);
            size += match code {
                Code::Text | Code::Pascal => *count,
                code => code_size(*code) * count,
            };
        }
        size
    }

    fn align(&self, at: usize, code: Code) -> usize {
        let width = code_size(code);
        if self.aligned && width > 1 {
            at.div_ceil(width) * width
        } else {
            at
        }
    }

    /// The values `bytes` holds; `None` when they are not the format's size.
    pub fn unpack(&self, bytes: &[u8]) -> Option<Vec<Unpacked>> {
        if bytes.len() != self.size() {
            return None;
        }
        let mut values = Vec::new();
        let mut at = 0;
        for (code, count) in &self.items {
            at = self.align(at, *code);
            match code {
                Code::Text => {
                    values.push(Unpacked::Bytes(bytes.get(at..at + count)?.to_vec()));
                    at += count;
                }
                Code::Pascal => {
                    let field = bytes.get(at..at + count)?;
                    let length = usize::from(field.first().copied().unwrap_or(0))
                        .min(count.saturating_sub(1));
                    values.push(Unpacked::Bytes(field.get(1..1 + length)?.to_vec()));
                    at += count;
                }
                code => {
                    let width = code_size(*code);
                    for _ in 0..*count {
                        let field = bytes.get(at..at + width)?;
                        at += width;
                        if *code != Code::Pad {
                            values.push(self.value(*code, field));
                        }
                    }
                }
            }
        }
        Some(values)
    }

    fn value(&self, code: Code, field: &[u8]) -> Unpacked {
        let mut wide = [0u8; 8];
        let width = field.len().min(8);
        if self.little {
            wide[..width].copy_from_slice(&field[..width]);
        } else {
            for (i, byte) in field.iter().rev().take(8).enumerate() {
                wide[i] = *byte;
            }
        }
        let unsigned = u64::from_le_bytes(wide);
        match code {
            Code::Char => Unpacked::Bytes(field.to_vec()),
            Code::Bool => Unpacked::Whole(i128::from(unsigned != 0)),
            Code::Signed(width) => {
                let shift = 64 - 8 * width as u32;
                Unpacked::Whole(i128::from(
                    i64::from_ne_bytes((unsigned << shift).to_ne_bytes()) >> shift,
                ))
            }
            Code::Float(2) => Unpacked::Float(half(unsigned as u16)),
            Code::Float(4) => Unpacked::Float(f64::from(f32::from_bits(unsigned as u32))),
            Code::Float(_) => Unpacked::Float(f64::from_bits(unsigned)),
            _ => Unpacked::Whole(i128::from(unsigned)),
        }
    }
}

fn code_size(code: Code) -> usize {
    match code {
        Code::Pad | Code::Char | Code::Bool | Code::Text | Code::Pascal => 1,
        Code::Signed(width) | Code::Unsigned(width) | Code::Float(width) => width,
    }
}

/// An IEEE 754 half, as Python's `e` reads it.
fn half(bits: u16) -> f64 {
    let sign = if bits >> 15 == 1 { -1.0 } else { 1.0 };
    let exponent = i32::from((bits >> 10) & 0x1F);
    let fraction = f64::from(bits & 0x3FF);
    sign * match exponent {
        0 => fraction * 2f64.powi(-24),
        31 if fraction == 0.0 => f64::INFINITY,
        31 => f64::NAN,
        e => (1.0 + fraction / 1024.0) * 2f64.powi(e - 15),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_as_python_gives_them() {
        // struct.calcsize in CPython on x86-64.
        for (format, size) in [
            (">2h", 4),
            (">i", 4),
            ("<If", 8),
            ("hi", 8),
            ("@bq", 16),
            (">10s", 10),
            (">4x2H", 8),
            ("=bq", 9),
            (">e", 2),
        ] {
            assert_eq!(Structure::parse(format).unwrap().size(), size, "{format}");
        }
        assert!(Structure::parse(">2").is_err());
        assert!(Structure::parse(">z").is_err());
        assert!(Structure::parse(">n").is_err());
    }

    #[test]
    fn values_as_python_unpacks_them() {
        let s = Structure::parse(">hHf").unwrap();
        let bytes = [0xFF, 0xFE, 0x00, 0x02, 0x40, 0x49, 0x0F, 0xDB];
        assert_eq!(
            s.unpack(&bytes).unwrap(),
            [
                Unpacked::Whole(-2),
                Unpacked::Whole(2),
                Unpacked::Float(f64::from(std::f32::consts::PI))
            ]
        );
        let little = Structure::parse("<h").unwrap();
        assert_eq!(little.unpack(&[0xFE, 0xFF]).unwrap(), [Unpacked::Whole(-2)]);
        assert_eq!(
            Structure::parse(">e")
                .unwrap()
                .unpack(&[0x3C, 0x00])
                .unwrap(),
            [Unpacked::Float(1.0)]
        );
        assert_eq!(s.unpack(&bytes[..6]), None);
    }
}
