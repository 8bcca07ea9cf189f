//! Register maps: a device's points by name, each with its reference, type, byte order,
//! scale, offset, unit and access, read from a CSV file with a header row or from a Home
//! Assistant `modbus:` configuration. A map is checked whole, every line of it, before it
//! is used.

use std::collections::HashMap;
use std::fmt;

use thiserror::Error;

use super::address::{bit_reference, parse_reference, reference, split_bit, Table};
use super::faults::{told, Faults};
use super::shown::Shown;
use super::structure::Structure;
use super::values::{ByteOrder, ValueType};
use crate::input::choice::Choice;

/// What a point holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A coil, a discrete input, or a bit of a register.
    Bool,
    /// A number of a value type.
    Number(ValueType),
    /// Text in N registers, two characters each.
    Text(u16),
    /// Values packed in N registers as the point's `structure` says (Home Assistant's
    /// `data_type: custom`); read-only.
    Packed(u16),
}

impl Kind {
    /// Registers (or bits, for coils and inputs) the point takes.
    pub fn width(self) -> u16 {
        match self {
            Kind::Bool => 1,
            Kind::Number(value_type) => value_type.width() as u16,
            Kind::Text(registers) | Kind::Packed(registers) => registers,
        }
    }

    /// Its name in a map's `type` column: `u16`, `bool`, `string:8`.
    pub fn name(self) -> String {
        match self {
            Kind::Bool => "bool".into(),
            Kind::Number(value_type) => value_type.name().into(),
            Kind::Text(registers) => format!("string:{registers}"),
            Kind::Packed(registers) => format!("custom:{registers}"),
        }
    }
}

/// One named point of a device.
#[derive(Clone, Debug, PartialEq)]
pub struct Point {
    /// Its name, unique in the map.
    pub name: String,
    /// The table it is in.
    pub table: Table,
    /// Its first address, 0-based.
    pub address: u16,
    /// For a bit of a register, which bit (0 the least significant).
    pub bit: Option<u8>,
    /// What it holds.
    pub kind: Kind,
    /// The byte order of a value wider than a register.
    pub order: ByteOrder,
    /// The value shown is raw x scale + offset.
    pub scale: f64,
    /// See `scale`.
    pub offset: f64,
    /// Shown after the value.
    pub unit: String,
    /// Whether it may be written.
    pub writable: bool,
    /// Its own slave id, where the command's is not its.
    pub slave: Option<u8>,
    /// Free text.
    pub description: String,
    /// The line of the file it was read from.
    pub line: usize,
    /// How its value is shown, where its file says as Home Assistant does (precision,
    /// limits, a marker of no value); `None` shows raw x scale + offset as it is.
    pub shown: Option<Shown>,
    /// For `Kind::Packed`, the layout of its values.
    pub structure: Option<Structure>,
    /// A raw value that stands for no value (SunSpec's 0xFFFF, 0x8000 and the like): read
    /// as `unknown`, never as a measurement.
    pub nan_value: Option<i128>,
}

impl Point {
    /// Its reference as the map gives it: `400001`, `400108.05`.
    pub fn reference(&self) -> String {
        match self.bit {
            Some(bit) => bit_reference(self.table, self.address, bit),
            None => reference(self.table, self.address).into(),
        }
    }

    /// The addresses it takes, `[start, end)`.
    pub fn span(&self) -> (u32, u32) {
        let start = u32::from(self.address);
        (start, start + u32::from(self.kind.width()))
    }

    /// Whether raw values are shown as they are.
    pub fn is_unscaled(&self) -> bool {
        self.scale == 1.0 && self.offset == 0.0
    }
}

/// A device's points, in the order of the file.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RegisterMap {
    /// The points.
    pub points: Vec<Point>,
    /// Where the device is, when the file says (a Home Assistant hub).
    pub connection: Option<MapConnection>,
    /// A Home Assistant configuration's hubs, each with its points: the devices `poll`
    /// reads from one file.
    pub hubs: Vec<MapHub>,
    /// Why the file's place for the device is not known (a secret not found), for a
    /// command that needs it.
    pub unknown_place: Option<String>,
    /// What a reader of the file would warn of (`file:line: ...`): entries left out as
    /// their own tool leaves them out.
    pub warnings: Vec<String>,
    /// The slave of a point that gives none, where the file's format says one (Home
    /// Assistant's 1) and the command line gives none.
    pub default_slave: Option<u8>,
}

/// A hub of a Home Assistant configuration: where its device is, and its points with the
/// rate Home Assistant reads each at.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MapHub {
    /// Its name.
    pub name: String,
    /// Where it is, or why that is not known (a kind of hub mbtool does not open, a secret
    /// not found).
    pub place: Result<MapConnection, String>,
    /// Its points, as indices into the map's points, each with its `scan_interval` where
    /// given (0: Home Assistant does not poll it).
    pub points: Vec<(usize, Option<std::time::Duration>)>,
}

/// Where a map's device is, as its file says; what the command line gives wins.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct MapConnection {
    /// The hub's name, for messages.
    pub hub: String,
    /// The port as `--port` takes it: `tcp://HOST:PORT`, `rtu+tcp://HOST:PORT`, or a
    /// serial device.
    pub port: String,
    /// `rtu` or `ascii`, for a serial line.
    pub mode: Option<String>,
    /// The serial speed.
    pub baud: Option<u32>,
    /// The serial parity: `E`, `O` or `N`.
    pub parity: Option<char>,
    /// The serial data bits.
    pub data_bits: Option<u8>,
    /// The serial stop bits.
    pub stop_bits: Option<u8>,
}

/// Why a map cannot be used.
#[derive(Clone, Debug, Error, PartialEq, Eq)]
pub enum MapError {
    /// The file cannot be read.
    #[error("{file}: cannot read it: {error}")]
    Unreadable {
        /// The file as named.
        file: String,
        /// Why.
        error: String,
    },
    /// What is wrong on a line of it.
    #[error("{file}:{line}: {error}")]
    At {
        /// The file as named.
        file: String,
        /// The line, 1-based.
        line: usize,
        /// What is wrong.
        error: String,
    },
    /// What is wrong on several lines: each, in the order of the file, at most
    /// [`MOST_TOLD`](super::faults::MOST_TOLD), and how many more there are. Shown one a
    /// line.
    #[error("{}", told(.errors, *.more))]
    Several {
        /// The first errors.
        errors: Vec<MapError>,
        /// How many more there are.
        more: usize,
    },
}

pub(crate) fn at(file: &str, line: usize, error: impl fmt::Display) -> MapError {
    MapError::At {
        file: file.to_string(),
        line: line.max(1),
        error: error.to_string(),
    }
}

/// The columns of a CSV map.
const COLUMNS: [&str; 11] = [
    "name",
    "ref",
    "type",
    "order",
    "scale",
    "offset",
    "unit",
    "access",
    "slave",
    "description",
    "nan_value",
];

/// The fields of one line of a CSV map, honouring double quotes (`"a, b"`, `""`).
fn csv_fields(line: &str) -> Result<Vec<String>, String> {
    let mut fields = Vec::new();
    let mut field = String::new();
    let mut quoted = false;
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match (c, quoted) {
            ('"', true) if chars.peek() == Some(&'"') => {
                chars.next();
                field.push('"');
            }
            ('"', true) => quoted = false,
            ('"', false) if field.trim().is_empty() => {
                field.clear();
                quoted = true;
            }
            (',', false) => fields.push(std::mem::take(&mut field)),
            (c, _) => field.push(c),
        }
    }
    if quoted {
        return Err("a quoted field is not closed".into());
    }
    fields.push(field);
    Ok(fields.into_iter().map(|f| f.trim().to_string()).collect())
}

/// A point's kind from its `type` column; whether it fits its table is `checked`'s to say.
fn kind_of(text: &str, table: Table, bit: Option<u8>) -> Result<Kind, String> {
    let bits = table.is_bits() || bit.is_some();
    Ok(match text.to_ascii_lowercase().as_str() {
        "" if bits => Kind::Bool,
        "" => Kind::Number(ValueType::U16),
        "bool" => Kind::Bool,
        other => match other.strip_prefix("string:") {
            Some(count) => match count.parse::<u16>() {
                Ok(n @ 1..=125) => Kind::Text(n),
                _ => return Err(format!("string:{count}: give string:N with N registers, 1 to 125")),
            },
            None => Kind::Number(ValueType::from_name(other).filter(|t| {
                !matches!(t, ValueType::Hex | ValueType::Bin | ValueType::Ascii)
            }).ok_or_else(|| {
                format!("type '{text}': give u16, i16, u32, i32, f32, u64, i64, f64, bool or string:N")
            })?),
        },
    })
}

/// The longest name a point may have. Longer is a mistake (a shifted column, a paste gone
/// wrong), and no table could show it.
pub const LONGEST_NAME: usize = 128;
/// The longest unit a point may have.
pub const LONGEST_UNIT: usize = 32;

fn too_long(text: &str, most: usize) -> bool {
    text.len() > most && text.chars().nth(most).is_some()
}

/// A point's name as every map must give it, checked before anything else of its line so
/// that no message repeats a name that is not one.
pub(crate) fn check_name(name: &str) -> Result<(), String> {
    if name.is_empty() {
        return Err("a point needs a name".into());
    }
    if too_long(name, LONGEST_NAME) {
        return Err(format!(
            "a name of {} characters: give one of at most {LONGEST_NAME}",
            name.chars().count()
        ));
    }
    if name.chars().any(char::is_control) {
        return Err("a name may not hold control characters (tabs, line breaks)".into());
    }
    Ok(())
}

/// The rules every point obeys, whichever file it was read from: a unit of sensible
/// length, a kind that fits its table, a value that ends by the last address, and a scale
/// and offset that are numbers (a scale not 0). The message leaves out the point's name;
/// the reader puts it in front.
pub(crate) fn checked(point: Point) -> Result<Point, String> {
    if too_long(&point.unit, LONGEST_UNIT) {
        return Err(format!(
            "a unit of {} characters: give one of at most {LONGEST_UNIT}",
            point.unit.chars().count()
        ));
    }
    let bits = point.table.is_bits() || point.bit.is_some();
    match (point.kind, bits) {
        (Kind::Bool, true) | (Kind::Number(_) | Kind::Text(_) | Kind::Packed(_), false) => {}
        (Kind::Bool, false) => {
            return Err(format!(
                "type bool is for coils, discrete inputs and bits of registers, not {}s",
                point.table.name()
            ))
        }
        (kind, true) => {
            return Err(format!(
                "type {} does not fit in {}: it is one bit",
                kind.name(),
                if point.bit.is_some() {
                    "a bit of a register".to_string()
                } else {
                    format!("a {}", point.table.name())
                }
            ))
        }
    }
    if point.span().1 > 65536 {
        return Err(format!(
            "a {} at {} runs past the last address",
            point.kind.name(),
            point.reference()
        ));
    }
    if !point.scale.is_finite() {
        return Err(format!("scale {}: give a finite number", point.scale));
    }
    if point.scale == 0.0 {
        return Err("scale 0 would show every value as the offset".into());
    }
    if !point.offset.is_finite() {
        return Err(format!("offset {}: give a finite number", point.offset));
    }
    if let Some(nan) = point.nan_value {
        check_nan_value(point.kind, nan)?;
    }
    Ok(point)
}

/// A `nan_value` the point's raw value can be: a whole number in its type's range, as the
/// registers read (-32768 for an i16's 0x8000).
fn check_nan_value(kind: Kind, nan: i128) -> Result<(), String> {
    let range = match kind {
        Kind::Number(ValueType::U16) => (0, i128::from(u16::MAX)),
        Kind::Number(ValueType::U32) => (0, i128::from(u32::MAX)),
        Kind::Number(ValueType::U64) => (0, i128::from(u64::MAX)),
        Kind::Number(ValueType::I16) => (i128::from(i16::MIN), i128::from(i16::MAX)),
        Kind::Number(ValueType::I32) => (i128::from(i32::MIN), i128::from(i32::MAX)),
        Kind::Number(ValueType::I64) => (i128::from(i64::MIN), i128::from(i64::MAX)),
        kind => {
            return Err(format!(
                "nan_value is for whole-number points, not {} (a float's NaN is unknown already)",
                kind.name()
            ))
        }
    };
    if (range.0..=range.1).contains(&nan) {
        return Ok(());
    }
    Err(format!(
        "nan_value {nan} is never read from a {}: give {} to {}, as the registers read",
        kind.name(),
        range.0,
        range.1
    ))
}

fn number(text: &str, what: &str, default: f64) -> Result<f64, String> {
    if text.is_empty() {
        return Ok(default);
    }
    text.parse::<f64>()
        .map_err(|_| format!("{what} '{text}' is not a number"))
}

/// One line of a CSV map, its columns by the header's order.
fn csv_point(columns: &[usize], fields: &[String], line: usize) -> Result<Point, String> {
    let field = |name: &str| -> &str {
        COLUMNS
            .iter()
            .position(|c| *c == name)
            .and_then(|i| columns.iter().position(|c| *c == i))
            .and_then(|at| fields.get(at))
            .map_or("", String::as_str)
    };
    if fields.len() > columns.len() {
        return Err(format!(
            "{} fields where the header has {}",
            fields.len(),
            columns.len()
        ));
    }
    point_of(&field, line)
}

/// A point from its fields by column name (`""` where not given).
fn point_of<'a>(field: &dyn Fn(&str) -> &'a str, line: usize) -> Result<Point, String> {
    let name = field("name");
    check_name(name)?;
    let (reference_text, bit) = split_bit(field("ref")).map_err(|e| e.to_string())?;
    if reference_text.is_empty() {
        return Err(format!("{name} has no ref"));
    }
    let (table, address) = parse_reference(reference_text).map_err(|e| e.to_string())?;
    if bit.is_some() && table.is_bits() {
        return Err(format!(
            "{}: a bit reference is of a register",
            field("ref")
        ));
    }
    let kind = kind_of(field("type"), table, bit)?;
    let order = match field("order") {
        "" => ByteOrder::default(),
        text => ByteOrder::from_name(&text.to_ascii_uppercase())
            .ok_or_else(|| format!("order '{text}': give ABCD, CDAB, BADC or DCBA"))?,
    };
    let writable = match (
        field("access").to_ascii_lowercase().as_str(),
        table.is_writable(),
    ) {
        ("", writable) => writable,
        ("r", _) => false,
        ("rw", true) => true,
        ("rw", false) => {
            return Err(format!(
                "{name}: {}s are read-only; give access r",
                table.name()
            ))
        }
        (other, _) => return Err(format!("access '{other}': give r or rw")),
    };
    let slave = match field("slave") {
        "" => None,
        text => {
            Some(crate::input::number::parse_in_range(text, 0, 255, "slave").map(|id| id as u8)?)
        }
    };
    checked(Point {
        name: name.to_string(),
        table,
        address,
        bit,
        kind,
        order,
        scale: number(field("scale"), "scale", 1.0)?,
        offset: number(field("offset"), "offset", 0.0)?,
        unit: field("unit").to_string(),
        writable,
        slave,
        description: field("description").to_string(),
        line,
        shown: None,
        structure: None,
        nan_value: match field("nan_value") {
            "" => None,
            text => Some(crate::input::number::parse_int(text).map_err(|_| {
                format!("nan_value '{text}': give the whole raw number that means no value")
            })?),
        },
    })
    .map_err(|error| format!("{name}: {error}"))
}

/// Reads a CSV map: a header row naming the columns (in any order, any case), then one
/// point a line; `#` starts a comment line. `file` names the map in messages.
pub fn parse_csv(file: &str, text: &str) -> Result<RegisterMap, MapError> {
    // A spreadsheet's CSV may start with a byte order mark, and have rows of commas only.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, line)| (i + 1, line.trim()))
        .filter(|(_, line)| {
            !line.starts_with('#') && !line.chars().all(|c| c == ',' || c.is_whitespace())
        });
    let (header_line, header) = lines.next().ok_or_else(|| {
        at(
            file,
            1,
            "no header row: the first line names the columns (name,ref,type,...)",
        )
    })?;
    let mut header = csv_fields(header).map_err(|e| at(file, header_line, e))?;
    while header.last().is_some_and(String::is_empty) {
        header.pop();
    }
    let mut columns = Vec::new();
    for name in header {
        let column = COLUMNS
            .iter()
            .position(|c| c.eq_ignore_ascii_case(&name))
            .ok_or_else(|| {
                at(
                    file,
                    header_line,
                    format!(
                        "unknown column '{name}': the columns are {}",
                        COLUMNS.join(", ")
                    ),
                )
            })?;
        if columns.contains(&column) {
            return Err(at(
                file,
                header_line,
                format!("column '{name}' given twice"),
            ));
        }
        columns.push(column);
    }
    for required in ["name", "ref"] {
        let index = COLUMNS
            .iter()
            .position(|c| *c == required)
            .unwrap_or_default();
        if !columns.contains(&index) {
            return Err(at(
                file,
                header_line,
                format!("the header has no '{required}' column"),
            ));
        }
    }
    let mut map = RegisterMap::default();
    let mut faults = Faults::default();
    // Names are checked on every row that gives one, whatever else is wrong with it.
    let name_column = columns.iter().position(|c| COLUMNS[*c] == "name");
    let mut names: HashMap<String, usize> = HashMap::new();
    for (number, line) in lines {
        let fields = csv_fields(line);
        let name = fields
            .as_ref()
            .ok()
            .and_then(|fields| fields.get(name_column?))
            .filter(|name| !name.is_empty());
        if let Some(name) = name {
            match names.get(name) {
                Some(first) => faults.add(at(
                    file,
                    number,
                    format!("the name '{name}' is taken already, on line {first}"),
                )),
                None => {
                    names.insert(name.clone(), number);
                }
            }
        }
        let point = fields.and_then(|mut fields| {
            while fields.len() > columns.len() && fields.last().is_some_and(String::is_empty) {
                fields.pop();
            }
            csv_point(&columns, &fields, number)
        });
        match point {
            Ok(point) => map.points.push(point),
            Err(error) => faults.add(at(file, number, error)),
        }
    }
    check(file, map, faults)
}

/// A map given as tables of keys, each a point whose keys are the columns of a CSV map
/// (a plant's inline points): each row its line and its keys with their values.
pub fn parse_points(
    file: &str,
    rows: &[(usize, Vec<(&str, &str)>)],
) -> Result<RegisterMap, MapError> {
    let mut map = RegisterMap::default();
    let mut faults = Faults::default();
    let mut names: HashMap<&str, usize> = HashMap::new();
    for (line, keys) in rows {
        if let Some((key, _)) = keys.iter().find(|(key, _)| !COLUMNS.contains(key)) {
            faults.add(at(
                file,
                *line,
                format!("{key}: a point takes {}", COLUMNS.join(", ")),
            ));
            continue;
        }
        let field = |name: &str| -> &str {
            keys.iter()
                .find(|(key, _)| *key == name)
                .map_or("", |(_, value)| *value)
        };
        let name = field("name");
        if let Some(first) = names.get(name).filter(|_| !name.is_empty()) {
            faults.add(at(
                file,
                *line,
                format!("the name '{name}' is taken already, on line {first}"),
            ));
            continue;
        }
        names.insert(name, *line);
        match point_of(&field, *line) {
            Ok(point) => map.points.push(point),
            Err(error) => faults.add(at(file, *line, error)),
        }
    }
    check(file, map, faults)
}

/// The points of a range as `read` would show them, each named by its reference: `count`
/// values of `kind` from `address` (or `count` bits of registers from `bit`).
pub fn range_points(
    table: Table,
    address: u16,
    count: u32,
    bit: Option<u8>,
    kind: Kind,
    order: ByteOrder,
) -> Vec<Point> {
    let point = |address: u16, bit: Option<u8>, kind: Kind| Point {
        name: match bit {
            Some(bit) => bit_reference(table, address, bit),
            None => reference(table, address).into(),
        },
        table,
        address,
        bit,
        kind,
        order,
        scale: 1.0,
        offset: 0.0,
        unit: String::new(),
        writable: false,
        slave: None,
        description: String::new(),
        line: 0,
        shown: None,
        structure: None,
        nan_value: None,
    };
    (0..count)
        .map_while(|i| match bit {
            Some(first) => {
                let at = u32::from(first) + i;
                let register = u16::try_from(u32::from(address) + at / 16).ok()?;
                Some(point(register, Some((at % 16) as u8), Kind::Bool))
            }
            None => {
                let at = u32::from(address) + i * u32::from(kind.width());
                Some(point(u16::try_from(at).ok()?, None, kind))
            }
        })
        .collect()
}

/// Checks a CSV map as a whole: no two points on the same addresses (bits of one register
/// apart). `faults`: those its lines had already; all are told at once, in the order of
/// the file.
fn check(file: &str, map: RegisterMap, faults: Faults<MapError>) -> Result<RegisterMap, MapError> {
    let mut faults = faults;
    if map.points.is_empty() && faults.is_empty() {
        return Err(at(file, 1, "the map names no point"));
    }
    let mut by_place: Vec<&Point> = map.points.iter().collect();
    by_place.sort_by_key(|p| (p.slave, p.table.digit(), p.address, p.bit));
    for pair in by_place.windows(2) {
        let [a, b] = pair else { continue };
        let same_place = a.slave == b.slave && a.table == b.table;
        let overlap = same_place && b.span().0 < a.span().1;
        // A bit of a register may be a point beside the register itself (a status word
        // and its alarm bit); two points of the same bit may not.
        let bit_beside = (a.bit.is_some() || b.bit.is_some()) && a.bit != b.bit;
        if overlap && !bit_beside {
            let (first, second) = if a.line < b.line { (a, b) } else { (b, a) };
            faults.add(at(
                file,
                second.line,
                format!(
                    "{} ({}) overlaps {} ({}, line {})",
                    second.name,
                    second.reference(),
                    first.name,
                    first.reference(),
                    first.line
                ),
            ));
        }
    }
    // Told in the order of the file.
    faults.sort_by_key(|error| match error {
        MapError::At { line, .. } => *line,
        _ => 0,
    });
    faults.or(map, |errors, more| MapError::Several { errors, more })
}

#[cfg(test)]
mod tests {
    use super::*;

    const EXAMPLE: &str = "\
# pump station 3
name,ref,type,order,scale,unit,access,description
voltage,400001,f32,CDAB,,V,r,\"mains, phase L1\"
speed,400003,u16,,0.1,rpm,,
alarm,400010.03,bool,,,,,
name plate,400020,string:4,,,,r,
running,000001,,,,,,
";

    #[test]
    fn the_columns_and_their_defaults() {
        let map = parse_csv("pump.csv", EXAMPLE).unwrap();
        let names: Vec<&str> = map.points.iter().map(|p| p.name.as_str()).collect();
        assert_eq!(
            names,
            ["voltage", "speed", "alarm", "name plate", "running"]
        );
        let voltage = &map.points[0];
        assert_eq!(voltage.kind, Kind::Number(ValueType::F32));
        assert_eq!(voltage.order, ByteOrder::Cdab);
        assert!(!voltage.writable);
        assert_eq!(voltage.description, "mains, phase L1");
        assert_eq!(map.points[1].scale, 0.1);
        assert!(map.points[1].writable);
        assert_eq!(
            (map.points[2].bit, map.points[2].kind),
            (Some(3), Kind::Bool)
        );
        assert_eq!(map.points[3].kind, Kind::Text(4));
        assert_eq!(map.points[4].kind, Kind::Bool);
    }

    #[test]
    fn every_fault_names_its_file_and_line() {
        let fails = |text: &str| parse_csv("m.csv", text).unwrap_err().to_string();
        assert_eq!(
            fails("name,ref\na,400001\na,400002\n"),
            "m.csv:3: the name 'a' is taken already, on line 2"
        );
        // A name given twice is told even when its first row has a fault of its own.
        assert_eq!(
            fails("name,ref\na,499999x\na,400002\n").lines().nth(1),
            Some("m.csv:3: the name 'a' is taken already, on line 2")
        );
        assert_eq!(
            fails("name,ref,type\na,400001,f32\nb,400002\n"),
            "m.csv:3: b (400002) overlaps a (400001, line 2)"
        );
        assert!(fails("name,ref,type\na,000001,u32\n")
            .starts_with("m.csv:2: a: type u32 does not fit in a coil"));
        assert!(fails("name,ref,colour\n").starts_with("m.csv:1: unknown column 'colour'"));
        assert!(
            fails("name,ref\na,400001,x\n").starts_with("m.csv:2: 3 fields where the header has 2")
        );
        assert!(fails("name,ref\nb,499999x\n").starts_with("m.csv:2: "));
        assert!(fails("name,ref,access\nc,300001,rw\n")
            .starts_with("m.csv:2: c: input registers are read-only"));
        // Two bits of one register are two points.
        assert!(parse_csv("m.csv", "name,ref\na,400001.00\nb,400001.01\n").is_ok());
    }
}
