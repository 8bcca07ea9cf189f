//! An entity of a Home Assistant platform made into the points that hold its state, as
//! the modbus integration reads it: where (table, address, slave), as what (`data_type`,
//! `count`, `structure`, `swap`) and how it is shown (`scale`, `offset`, `precision`,
//! `min_value`, `max_value`, `nan_value`, `zero_suppress`), `slave_count` and
//! `virtual_count` expanded into the entities Home Assistant adds (`name 1`, `name 2`, ...).

use super::schema::{Entity, Field, Numbers};
use crate::input::number::parse_int;
use crate::model::address::Table;
use crate::model::map::{checked, Kind, Point};
use crate::model::shown::{Shown, States};
use crate::model::structure::Structure;
use crate::model::values::{ByteOrder, ValueType};

/// How a value is shown that stands for these states.
fn with_states(states: States) -> Shown {
    Shown {
        states: Some(states),
        ..Shown::default()
    }
}

/// The platforms of the modbus integration, in the order Home Assistant sets them up.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(super) enum Platform {
    Sensor,
    BinarySensor,
    Switch,
    Light,
    Fan,
    Cover,
    Climate,
}

impl Platform {
    /// Home Assistant's name for one of its entities: `sensor`, `binary_sensor`, ...
    pub(super) fn entity(self) -> &'static str {
        match self {
            Platform::Sensor => "sensor",
            Platform::BinarySensor => "binary_sensor",
            Platform::Switch => "switch",
            Platform::Light => "light",
            Platform::Fan => "fan",
            Platform::Cover => "cover",
            Platform::Climate => "climate",
        }
    }

    /// The platform an entity of a bare list is: a sensor, unless it has keys only
    /// another platform has.
    pub(super) fn guessed(entity: &Entity) -> Platform {
        let input = entity.input_type.as_ref().map(|t| t.0.as_str());
        if entity.write_type.is_some() || entity.command_on.is_some() || entity.verify.is_some() {
            Platform::Switch
        } else if entity.target_temp_register.is_some() {
            Platform::Climate
        } else if entity.status_register.is_some() || entity.state_open.is_some() {
            Platform::Cover
        } else if matches!(input, Some("coil" | "discrete_input")) {
            Platform::BinarySensor
        } else {
            Platform::Sensor
        }
    }
}

/// A field's text, a secret resolved; `key` names it in messages.
pub(super) trait Values {
    fn text(&mut self, field: &Field, key: &str) -> Result<Option<String>, String>;
}

struct Keys<'a, V: Values> {
    values: &'a mut V,
}

impl<V: Values> Keys<'_, V> {
    fn text(&mut self, field: &Field, key: &str) -> Result<Option<String>, String> {
        self.values.text(field, key)
    }

    fn whole(
        &mut self,
        field: &Field,
        key: &str,
        min: i128,
        max: i128,
    ) -> Result<Option<i128>, String> {
        let Some(text) = self.text(field, key)? else {
            return Ok(None);
        };
        let value = parse_int(&text)
            .ok()
            .or_else(|| {
                text.parse::<f64>()
                    .ok()
                    .filter(|v| v.fract() == 0.0)
                    .map(|v| v as i128)
            })
            .ok_or_else(|| format!("{key} '{text}' is not a whole number"))?;
        if value < min || value > max {
            return Err(format!("{key} {value}: give {min} to {max}"));
        }
        Ok(Some(value))
    }

    fn number(&mut self, field: &Field, key: &str) -> Result<Option<f64>, String> {
        let Some(text) = self.text(field, key)? else {
            return Ok(None);
        };
        parse_int(&text)
            .map(|v| v as f64)
            .ok()
            .or_else(|| text.trim().parse::<f64>().ok())
            .filter(|v| v.is_finite())
            .map(Some)
            .ok_or_else(|| format!("{key} '{text}' is not a number"))
    }
}

/// The points of `entity`, one for it and one for each entity its `slave_count` or
/// `virtual_count` adds; the message of an error leaves out the entity's name.
pub(super) fn points<V: Values>(
    platform: Platform,
    entity: &Entity,
    values: &mut V,
) -> Result<Vec<Point>, String> {
    let mut keys = Keys { values };
    let name = entity.name.value.clone();
    let line = usize::try_from(entity.name.referenced.line()).unwrap_or(1);
    let address = keys
        .whole(&entity.address, "address", 0, 65535)?
        .ok_or("no address: every entity needs one")? as u16;
    let slave = match (
        keys.whole(&entity.slave, "slave", 0, 255)?,
        keys.whole(&entity.device_address, "device_address", 0, 255)?,
    ) {
        (Some(_), Some(_)) => return Err("slave and device_address both given; give one".into()),
        (slave, other) => slave.or(other).map(|id| id as u8),
    };
    let mut point = Point {
        name,
        table: Table::HoldingRegisters,
        address,
        bit: None,
        kind: Kind::Bool,
        order: ByteOrder::Abcd,
        scale: 1.0,
        offset: 0.0,
        unit: keys
            .text(&entity.unit_of_measurement, "unit_of_measurement")?
            .unwrap_or_default(),
        writable: false,
        slave,
        description: String::new(),
        line,
        shown: None,
        structure: None,
        nan_value: None,
    };
    let extra = match platform {
        Platform::Sensor | Platform::Climate => {
            point.table = table(
                &mut keys,
                &entity.input_type,
                "input_type",
                "holding",
                REGISTERS,
            )?;
            valued(&mut keys, entity, &mut point)?
        }
        Platform::BinarySensor => {
            point.table = table(&mut keys, &entity.input_type, "input_type", "coil", ANY)?;
            if !point.table.is_bits() {
                // Home Assistant takes bit 0 of a register.
                point.bit = Some(0);
            }
            point.shown = Some(with_states(States::OnOff {
                on: vec![1],
                off: vec![0],
            }));
            count_of(&mut keys, entity)?
        }
        Platform::Switch | Platform::Light | Platform::Fan => {
            let written = table(
                &mut keys,
                &entity.write_type,
                "write_type",
                "holding",
                WRITTEN,
            )?;
            let (read_at, read_table) = match &entity.verify {
                Some(Some(verify)) => (
                    keys.whole(&verify.address, "verify address", 0, 65535)?
                        .map_or(address, |a| a as u16),
                    match verify.input_type {
                        Some(_) => table(
                            &mut keys,
                            &verify.input_type,
                            "verify input_type",
                            "holding",
                            ANY,
                        )?,
                        None => written,
                    },
                ),
                _ => (address, written),
            };
            point.address = read_at;
            point.table = read_table;
            point.writable = read_at == address && read_table == written;
            point.kind = state_kind(read_table);
            // A bit is on or off; a register is on for `state_on` (the command that turns
            // it on, 1 unless given) and off for `state_off`.
            let on = keys
                .whole(&entity.command_on, "command_on", 0, 65535)?
                .unwrap_or(1) as i64;
            let off = keys
                .whole(&entity.command_off, "command_off", 0, 65535)?
                .unwrap_or(0) as i64;
            let verify = entity.verify.as_ref().and_then(Option::as_ref);
            let listed = |numbers: Option<&Numbers>, command: i64| {
                numbers.map_or_else(|| vec![command], |numbers| numbers.0.clone())
            };
            point.shown = Some(Shown {
                // `on` and `off` are written as the commands.
                commands: Some([on as u16, off as u16]).filter(|_| !written.is_bits()),
                ..with_states(match read_table.is_bits() {
                    true => States::OnOff {
                        on: vec![1],
                        off: vec![0],
                    },
                    false => States::OnOff {
                        on: listed(verify.and_then(|v| v.state_on.as_ref()), on),
                        off: listed(verify.and_then(|v| v.state_off.as_ref()), off),
                    },
                })
            });
            0
        }
        Platform::Cover => {
            let moved = table(
                &mut keys,
                &entity.input_type,
                "input_type",
                "holding",
                COVER,
            )?;
            match keys.whole(&entity.status_register, "status_register", 0, 65535)? {
                Some(status) => {
                    point.address = status as u16;
                    point.table = table(
                        &mut keys,
                        &entity.status_register_type,
                        "status_register_type",
                        "holding",
                        REGISTERS,
                    )?;
                }
                None => point.table = moved,
            }
            point.kind = state_kind(point.table);
            let mut value = |field: &Field, key: &str, default: i64| -> Result<i64, String> {
                Ok(keys
                    .whole(field, key, 0, 65535)?
                    .map_or(default, |v| v as i64))
            };
            point.shown = Some(with_states(match point.table.is_bits() {
                // A coil that is set is an open cover.
                true => States::Cover {
                    values: [1, 0, -1, -1],
                },
                false => States::Cover {
                    values: [
                        value(&entity.state_open, "state_open", 1)?,
                        value(&entity.state_closed, "state_closed", 0)?,
                        value(&entity.state_opening, "state_opening", 2)?,
                        value(&entity.state_closing, "state_closing", 3)?,
                    ],
                },
            }));
            0
        }
    };
    let first = checked(point)?;
    let mut points = vec![first.clone()];
    for index in 1..=extra {
        let at = u32::from(first.address) + u32::from(index) * u32::from(first.kind.width());
        let address = u16::try_from(at)
            .map_err(|_| format!("its entity {index} would be past the last address"))?;
        points.push(checked(Point {
            name: format!("{} {index}", first.name),
            address,
            ..first.clone()
        })?);
    }
    Ok(points)
}

const REGISTERS: &[(&str, Table)] = &[
    ("holding", Table::HoldingRegisters),
    ("input", Table::InputRegisters),
];
const ANY: &[(&str, Table)] = &[
    ("coil", Table::Coils),
    ("discrete_input", Table::DiscreteInputs),
    ("holding", Table::HoldingRegisters),
    ("input", Table::InputRegisters),
];
const WRITTEN: &[(&str, Table)] = &[
    ("holding", Table::HoldingRegisters),
    ("holdings", Table::HoldingRegisters),
    ("coil", Table::Coils),
    ("coils", Table::Coils),
];
const COVER: &[(&str, Table)] = &[("coil", Table::Coils), ("holding", Table::HoldingRegisters)];

fn table<V: Values>(
    keys: &mut Keys<'_, V>,
    field: &Field,
    key: &str,
    default: &str,
    allowed: &[(&str, Table)],
) -> Result<Table, String> {
    let given = keys
        .text(field, key)?
        .unwrap_or_else(|| default.to_string());
    allowed
        .iter()
        .find(|(name, _)| *name == given)
        .map(|(_, table)| *table)
        .ok_or_else(|| {
            let names: Vec<&str> = allowed.iter().map(|(name, _)| *name).collect();
            format!("{key} '{given}': give {}", names.join(", "))
        })
}

/// A switch's or cover's state: on or off for a bit, the register's value otherwise.
fn state_kind(table: Table) -> Kind {
    if table.is_bits() {
        Kind::Bool
    } else {
        Kind::Number(ValueType::U16)
    }
}

/// The entities `slave_count` or `virtual_count` adds.
fn count_of<V: Values>(keys: &mut Keys<'_, V>, entity: &Entity) -> Result<u16, String> {
    let slaves = keys.whole(&entity.slave_count, "slave_count", 0, 2000)?;
    let virtuals = keys.whole(&entity.virtual_count, "virtual_count", 0, 2000)?;
    Ok(slaves.filter(|n| *n > 0).or(virtuals).unwrap_or(0) as u16)
}

/// A sensor's or climate's value: its type, order and the keys of how it is shown; the
/// entities its count adds.
fn valued<V: Values>(
    keys: &mut Keys<'_, V>,
    entity: &Entity,
    point: &mut Point,
) -> Result<u16, String> {
    let data_type = keys.text(&entity.data_type, "data_type")?;
    let count = keys
        .whole(&entity.count, "count", 1, 125)?
        .map(|c| c as u16);
    let structure = keys.text(&entity.structure, "structure")?;
    let swap = keys.text(&entity.swap, "swap")?;
    let extra = count_of(keys, entity)?;
    let (kind, floating) = data_kind(data_type.as_deref().unwrap_or("int16"), count)?;
    let name = data_type.as_deref().unwrap_or("int16");
    match kind {
        Kind::Packed(registers) => {
            let half = name == "float16" || (name == "float" && count == Some(1));
            let format = match (half, structure) {
                (true, None) => ">e".to_string(),
                (true, Some(_)) => {
                    return Err(format!("`structure` illegal with `data_type: {name}`"))
                }
                (false, structure) => {
                    structure.ok_or("`structure` missing, demanded with `data_type: custom`")?
                }
            };
            let parsed = Structure::parse(&format)
                .map_err(|e| format!("error in structure format --> {e}"))?;
            if parsed.size() != usize::from(registers) * 2 {
                return Err(format!(
                    "Size of structure is {} bytes but `count: {registers}` is {} bytes",
                    parsed.size(),
                    registers * 2
                ));
            }
            point.structure = Some(parsed);
        }
        _ if structure.is_some() => {
            return Err(format!("`structure` illegal with `data_type: {name}`"))
        }
        _ => {}
    }
    if extra > 0 && !matches!(kind, Kind::Number(_)) {
        return Err(format!(
            "`virtual_count / slave_count` illegal with `data_type: {name}`"
        ));
    }
    point.order = match swap.as_deref().unwrap_or("none") {
        "none" => ByteOrder::Abcd,
        "byte" if !matches!(kind, Kind::Packed(_)) => ByteOrder::Badc,
        "word" | "word_byte" if matches!(kind, Kind::Number(t) if t.width() > 1) => {
            if swap.as_deref() == Some("word") {
                ByteOrder::Cdab
            } else {
                ByteOrder::Dcba
            }
        }
        given @ ("byte" | "word" | "word_byte") => {
            return Err(format!("`swap:{given}` illegal with `data_type: {name}`"))
        }
        other => {
            return Err(format!(
                "swap '{other}': give none, byte, word or word_byte"
            ))
        }
    };
    point.kind = kind;
    point.scale = keys.number(&entity.scale, "scale")?.unwrap_or(1.0);
    point.offset = keys.number(&entity.offset, "offset")?.unwrap_or(0.0);
    let precision = keys.whole(&entity.precision, "precision", 0, 15)?;
    point.shown = Some(Shown {
        precision: precision.map_or(if floating { 2 } else { 0 }, |p| p as u8),
        min: keys.number(&entity.min_value, "min_value")?,
        max: keys.number(&entity.max_value, "max_value")?,
        nan: keys.whole(&entity.nan_value, "nan_value", -(1 << 64), 1 << 64)?,
        zero_suppress: keys.number(&entity.zero_suppress, "zero_suppress")?,
        states: None,
        commands: None,
    });
    Ok(extra)
}

/// The kind a `data_type` reads, and whether Home Assistant shows it with decimals where
/// no precision is given. The older `int`, `uint` and `float` take their width from
/// `count`, as Home Assistant read them before the sized names.
fn data_kind(data_type: &str, count: Option<u16>) -> Result<(Kind, bool), String> {
    let sized = |types: [ValueType; 3]| match count.unwrap_or(1) {
        1 => Ok(types[0]),
        2 => Ok(types[1]),
        4 => Ok(types[2]),
        other => Err(format!(
            "count {other} with data_type {data_type}: give 1, 2 or 4"
        )),
    };
    let value_type = match data_type {
        "int" => sized([ValueType::I16, ValueType::I32, ValueType::I64])?,
        "uint" => sized([ValueType::U16, ValueType::U32, ValueType::U64])?,
        "float" => match count.unwrap_or(2) {
            1 => return half(),
            _ => sized([ValueType::F32, ValueType::F32, ValueType::F64])?,
        },
        "int16" => ValueType::I16,
        "uint16" => ValueType::U16,
        "int32" => ValueType::I32,
        "uint32" => ValueType::U32,
        "int64" => ValueType::I64,
        "uint64" => ValueType::U64,
        "float32" => ValueType::F32,
        "float64" => ValueType::F64,
        "float16" => return half(),
        "string" => {
            return match count {
                Some(count) => Ok((Kind::Text(count), false)),
                None => Err("`count` missing, demanded with `data_type: string`".into()),
            }
        }
        "custom" => {
            return match count {
                Some(count) => Ok((Kind::Packed(count), true)),
                None => Err("`count` missing, demanded with `data_type: custom`".into()),
            }
        }
        other => {
            return Err(format!(
                "data_type '{other}': give int16, uint16, int32, uint32, int64, uint64, float16, float32, float64, string or custom"
            ))
        }
    };
    let kind = Kind::Number(value_type);
    if let Some(count) =
        count.filter(|c| *c != kind.width() && !matches!(data_type, "int" | "uint" | "float"))
    {
        return Err(format!(
            "count {count}: {data_type} takes {} registers; leave count out",
            kind.width()
        ));
    }
    Ok((kind, matches!(value_type, ValueType::F32 | ValueType::F64)))
}

/// A half float, read as Python's `e`.
fn half() -> Result<(Kind, bool), String> {
    Ok((Kind::Packed(1), true))
}
