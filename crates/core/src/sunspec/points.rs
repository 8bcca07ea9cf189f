//! A model's registers laid out as its definition says: every point with its place, its
//! registers, its scale factor applied and its symbols named, and a point the device marks
//! as not implemented told as such, never shown as a value. Pure: registers in, points out.

use std::collections::HashMap;

use super::defs::{Count, GroupDef, ModelDef, PointDef, PointType, ScaleFactor};
use crate::master::map::register_value;
use crate::model::address::Table;
use crate::model::map::{Kind, Point};
use crate::model::values::{ByteOrder, Value, ValueType};

/// One point of a model, as read.
#[derive(Clone, Debug, PartialEq)]
pub struct SunSpecPoint {
    /// Its name in a map: the model's name, the group and its instance, the point's
    /// (`mppt.module_2.DCA`).
    pub name: String,
    /// Its name for people.
    pub label: String,
    /// Its SunSpec type.
    pub point_type: PointType,
    /// Its first register, 0-based.
    pub address: u16,
    /// Its registers.
    pub raw: Vec<u16>,
    /// The power of ten applied to it.
    pub scale_factor: Option<i16>,
    /// Its unit.
    pub units: String,
    /// Whether the definition lets it be written.
    pub writable: bool,
    /// Its value, scaled, or why it has none.
    pub value: Result<Value, NoValue>,
    /// The name of an enum's value, or of the bits of a bitfield that are set.
    pub meaning: Option<String>,
}

/// Why a point has no value.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NoValue {
    /// The device marks it as not implemented (0xFFFF, 0x8000, NaN, an empty text...).
    NotImplemented,
    /// Its scale factor is not implemented, not in the model, or outside -10..10.
    ScaleFactor(String),
    /// The device refused to read its registers, with this exception.
    Refused(String),
}

impl SunSpecPoint {
    /// The point as a map line reads it (`None` for the types a map has no type for: IP
    /// and MAC addresses), so that `read --map` shows what the scan showed.
    pub fn map_point(&self) -> Option<Point> {
        let kind = map_kind(self.point_type, self.raw.len())?;
        let scale = self
            .scale_factor
            .map_or(1.0, |power| format!("1e{power}").parse().unwrap_or(1.0));
        Some(Point {
            name: self.name.clone(),
            table: Table::HoldingRegisters,
            address: self.address,
            bit: None,
            kind,
            order: ByteOrder::Abcd,
            scale,
            offset: 0.0,
            unit: self.units.clone(),
            writable: self.writable,
            slave: None,
            description: self.label.clone(),
            line: 0,
            shown: None,
            structure: None,
            nan_value: nan_value(self.point_type),
        })
    }
}

/// The raw value SunSpec marks a number of this type as not implemented with, as a map
/// carries it; `None` where the mark is no single number (NaN, empty text).
fn nan_value(point_type: PointType) -> Option<i128> {
    match point_type {
        PointType::Int16 | PointType::Sunssf => Some(i128::from(i16::MIN)),
        PointType::Int32 => Some(i128::from(i32::MIN)),
        PointType::Int64 => Some(i128::from(i64::MIN)),
        PointType::Uint16 | PointType::Count | PointType::Enum16 | PointType::Bitfield16 => {
            Some(i128::from(u16::MAX))
        }
        PointType::Uint32 | PointType::Enum32 | PointType::Bitfield32 => Some(i128::from(u32::MAX)),
        PointType::Uint64 => Some(i128::from(u64::MAX)),
        PointType::Acc16 | PointType::Acc32 | PointType::Acc64 => Some(0),
        _ => None,
    }
}

/// What a map holds a SunSpec type as.
fn map_kind(point_type: PointType, size: usize) -> Option<Kind> {
    let number = |value_type| Some(Kind::Number(value_type));
    match point_type {
        PointType::Int16 | PointType::Sunssf => number(ValueType::I16),
        PointType::Uint16
        | PointType::Count
        | PointType::Acc16
        | PointType::Enum16
        | PointType::Bitfield16
        | PointType::Pad => number(ValueType::U16),
        PointType::Int32 => number(ValueType::I32),
        PointType::Uint32 | PointType::Acc32 | PointType::Enum32 | PointType::Bitfield32 => {
            number(ValueType::U32)
        }
        PointType::Int64 => number(ValueType::I64),
        PointType::Uint64 | PointType::Acc64 => number(ValueType::U64),
        PointType::Float32 => number(ValueType::F32),
        PointType::Float64 => number(ValueType::F64),
        PointType::String => Some(Kind::Text(u16::try_from(size).ok()?)),
        PointType::Ipaddr | PointType::Ipv6addr | PointType::Eui48 => None,
    }
}

/// Whether `raw` is the value SunSpec marks a point of this type as not implemented with.
fn not_implemented(point_type: PointType, raw: &[u16]) -> bool {
    let all = |word: u16| raw.iter().all(|r| *r == word);
    let first_then_zero = raw.first() == Some(&0x8000) && raw[1..].iter().all(|r| *r == 0);
    match point_type {
        PointType::Int16 | PointType::Sunssf | PointType::Int32 | PointType::Int64 => {
            first_then_zero
        }
        PointType::Uint16
        | PointType::Count
        | PointType::Enum16
        | PointType::Bitfield16
        | PointType::Uint32
        | PointType::Enum32
        | PointType::Bitfield32
        | PointType::Uint64 => all(0xFFFF),
        PointType::Acc16
        | PointType::Acc32
        | PointType::Acc64
        | PointType::Ipaddr
        | PointType::Ipv6addr
        | PointType::String => all(0),
        PointType::Eui48 => all(0) || all(0xFFFF),
        PointType::Float32 => {
            raw.len() == 2 && f32::from_bits(u32::from(raw[0]) << 16 | u32::from(raw[1])).is_nan()
        }
        PointType::Float64 => {
            let bits = raw.iter().fold(0u64, |bits, r| bits << 16 | u64::from(*r));
            raw.len() == 4 && f64::from_bits(bits).is_nan()
        }
        PointType::Pad => false,
    }
}

/// Why a model's points are not all there.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LayoutProblem(pub String);

/// A group instance's points by name, for the scale factors and counts of the points and
/// groups under it.
type Scope = HashMap<String, Vec<u16>>;

struct Layout<'a> {
    registers: &'a [u16],
    /// The protocol address of `registers[0]` (the model's ID).
    address: u16,
    points: Vec<SunSpecPoint>,
    problems: Vec<String>,
}

/// Lays out a model: `registers` are its ID, its length and its `length` registers, read
/// from `address`; `prefix` names its points in a map. Points that would lie past the
/// model's registers are left out, and the problem told.
pub fn lay_out(
    def: &ModelDef,
    prefix: &str,
    address: u16,
    registers: &[u16],
) -> (Vec<SunSpecPoint>, Option<LayoutProblem>) {
    let mut layout = Layout {
        registers,
        address,
        points: Vec::new(),
        problems: Vec::new(),
    };
    let end = layout.group(&def.group, prefix, 0, &mut Vec::new());
    if end != registers.len() && layout.problems.is_empty() {
        layout.problems.push(format!(
            "its definition takes {} registers, the device says {}",
            end.saturating_sub(2),
            registers.len().saturating_sub(2)
        ));
    }
    let problem = (!layout.problems.is_empty()).then(|| LayoutProblem(layout.problems.join("; ")));
    (layout.points, problem)
}

impl Layout<'_> {
    /// Lays out one instance of `group` from `offset`; returns the offset after it.
    fn group(
        &mut self,
        group: &GroupDef,
        prefix: &str,
        mut offset: usize,
        scopes: &mut Vec<Scope>,
    ) -> usize {
        let first = self.points.len();
        let mut scope = Scope::new();
        for point in &group.points {
            let size = usize::from(point.size);
            let Some(raw) = self.registers.get(offset..offset + size) else {
                // A pad left out at the end (a common model of 65) loses nothing.
                if point.point_type != PointType::Pad {
                    self.problems.push(format!(
                        "{prefix}.{} lies past the model's length",
                        point.name
                    ));
                }
                // The points before it are the device's, and have their values.
                scopes.push(scope);
                self.settle(group, first, scopes);
                scopes.pop();
                return self.registers.len();
            };
            scope.insert(point.name.clone(), raw.to_vec());
            if point.point_type != PointType::Pad {
                self.points.push(self.point(point, prefix, offset, raw));
            }
            offset += size;
        }
        scopes.push(scope);
        self.settle(group, first, scopes);
        for inner in &group.groups {
            let count = match self.count(inner, offset, scopes) {
                Ok(count) => count,
                Err(problem) => {
                    self.problems
                        .push(format!("{prefix}.{}: {problem}", inner.name));
                    scopes.pop();
                    return self.registers.len();
                }
            };
            for index in 1..=count {
                let name = match inner.count {
                    Some(_) => format!("{prefix}.{}_{index}", inner.name),
                    None => format!("{prefix}.{}", inner.name),
                };
                offset = self.group(inner, &name, offset, scopes);
            }
        }
        scopes.pop();
        offset
    }

    fn point(&self, def: &PointDef, prefix: &str, offset: usize, raw: &[u16]) -> SunSpecPoint {
        let implemented = !not_implemented(def.point_type, raw);
        SunSpecPoint {
            name: format!("{prefix}.{}", def.name),
            label: def.label.clone().unwrap_or_default(),
            point_type: def.point_type,
            address: self.address.wrapping_add(offset as u16),
            raw: raw.to_vec(),
            scale_factor: match def.sf {
                Some(ScaleFactor::Fixed(power)) => Some(power),
                _ => None,
            },
            units: def.units.clone().unwrap_or_default(),
            writable: def.access.as_deref() == Some("RW"),
            // Settled by `settle`, once the group's scale factors are known.
            value: Err(NoValue::NotImplemented),
            meaning: implemented.then(|| meaning(def, raw)).flatten(),
        }
    }

    /// Gives each implemented point of the group instance just laid out its value, its
    /// scale factor found in the instance, then in the groups around it.
    fn settle(&mut self, group: &GroupDef, first: usize, scopes: &[Scope]) {
        let defs = group
            .points
            .iter()
            .filter(|p| p.point_type != PointType::Pad);
        for (point, def) in self.points[first..].iter_mut().zip(defs) {
            if not_implemented(def.point_type, &point.raw) {
                continue;
            }
            let scaled = match &def.sf {
                Some(ScaleFactor::Point(name)) => {
                    let found = scopes.iter().rev().find_map(|scope| scope.get(name));
                    match found.map(|raw| {
                        raw.first()
                            .map_or(-0x8000, |r| i16::from_be_bytes(r.to_be_bytes()))
                    }) {
                        Some(-0x8000) => Err(format!("its scale factor {name} is not implemented")),
                        Some(power) if (-10..=10).contains(&power) => {
                            point.scale_factor = Some(power);
                            Ok(())
                        }
                        Some(power) => Err(format!(
                            "its scale factor {name} is {power}, outside -10..10"
                        )),
                        None => Err(format!("its scale factor {name} is not in the model")),
                    }
                }
                _ => Ok(()),
            };
            let settled = scaled.map(|()| value(point)).map_err(NoValue::ScaleFactor);
            point.value = settled;
        }
    }

    /// How many times `group` repeats from `offset`.
    fn count(&self, group: &GroupDef, offset: usize, scopes: &[Scope]) -> Result<usize, String> {
        match &group.count {
            None => Ok(1),
            Some(Count::Fixed(0)) => {
                // Repeated to the model's end: what is left after it, divided by its length.
                let length = static_length(group)
                    .filter(|length| *length > 0)
                    .ok_or("its length depends on the device, so its repeats are unknown")?;
                let left = self.registers.len().saturating_sub(offset);
                if left % length != 0 {
                    return Err(format!(
                        "the {left} registers left are no whole number of its {length}"
                    ));
                }
                Ok(left / length)
            }
            Some(Count::Fixed(count)) => Ok(usize::from(*count)),
            Some(Count::Point(name)) => {
                let raw = scopes
                    .iter()
                    .rev()
                    .find_map(|scope| scope.get(name))
                    .ok_or_else(|| format!("its count {name} is not in the model"))?;
                match raw.first() {
                    Some(0xFFFF) | None => Err(format!("its count {name} is not implemented")),
                    Some(count) => Ok(usize::from(*count)),
                }
            }
        }
    }
}

/// The registers one instance of a group takes, where its definition alone says.
fn static_length(group: &GroupDef) -> Option<usize> {
    let points: usize = group.points.iter().map(|p| usize::from(p.size)).sum();
    group.groups.iter().try_fold(points, |length, inner| {
        let times = match inner.count {
            None => 1,
            Some(Count::Fixed(count)) if count > 0 => usize::from(count),
            _ => return None,
        };
        Some(length + times * static_length(inner)?)
    })
}

/// A point's value: as a map line of it reads it, or for the types a map has none for
/// (addresses), as text.
fn value(point: &SunSpecPoint) -> Value {
    match point.map_point() {
        Some(map_point) => register_value(&map_point, &point.raw),
        None => Value::Text(address_text(point.point_type, &point.raw)),
    }
}

fn address_text(point_type: PointType, raw: &[u16]) -> String {
    let bytes: Vec<u8> = raw.iter().flat_map(|r| r.to_be_bytes()).collect();
    match point_type {
        PointType::Ipaddr => bytes
            .iter()
            .map(u8::to_string)
            .collect::<Vec<_>>()
            .join("."),
        PointType::Eui48 => bytes
            .iter()
            .skip(bytes.len().saturating_sub(6))
            .map(|b| format!("{b:02X}"))
            .collect::<Vec<_>>()
            .join(":"),
        _ => raw
            .iter()
            .map(|r| format!("{r:x}"))
            .collect::<Vec<_>>()
            .join(":"),
    }
}

/// The name of an enum's value, or the names of a bitfield's bits that are set.
fn meaning(def: &PointDef, raw: &[u16]) -> Option<String> {
    if def.symbols.is_empty() {
        return None;
    }
    let number = raw.iter().fold(0u64, |n, r| n << 16 | u64::from(*r));
    let named = |value: u64| {
        def.symbols
            .iter()
            .find(|symbol| symbol.value == value)
            .map(|symbol| symbol.name.clone())
    };
    match def.point_type {
        PointType::Bitfield16 | PointType::Bitfield32 => {
            let set: Vec<String> = (0..64)
                .filter(|bit| number >> bit & 1 == 1)
                .map(|bit| named(bit).unwrap_or_else(|| format!("bit {bit}")))
                .collect();
            Some(set.join(","))
        }
        _ => named(number),
    }
}

#[cfg(test)]
mod tests;
