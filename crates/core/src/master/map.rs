//! Points of a register map read and written by name. Points of one table and slave are
//! read in as few requests as possible, as the source manuals' driver does with its "max
//! read count": without a limit, runs of consecutive addresses together; with
//! `max_per_request` N, every point from the lowest unread address to N registers (or bits)
//! further on, holes included. A request that spans holes and is refused with 02 or 0B is
//! read again one run at a time.
//!
//! One point's failure is that point's alone: a run the device refuses, answers garbled,
//! or does not answer while it answers others, is read again in halves down to the point
//! it fails on, and every other request is still asked.

use std::collections::VecDeque;

use super::run::RunError;
use super::{Master, MasterError};
use crate::codec::{limits, ExceptionCode, Request, Response};
use crate::input::choice::Choice;
use crate::model::address::Table;
use crate::model::map::{Kind, Point};
use crate::model::shown::UNKNOWN;
use crate::model::values::{parse_coil, text, Value, ValueType};

/// One read request of a map read, and the points it carries.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Group {
    /// The slave asked.
    pub slave: u8,
    /// The table read.
    pub table: Table,
    /// The first address read.
    pub address: u16,
    /// How many registers or bits.
    pub quantity: u16,
    /// The points, as indices into the points grouped.
    pub points: Vec<usize>,
}

impl Group {
    /// The read request.
    pub fn request(&self) -> Request {
        super::plan::read_request(self.table, self.address, self.quantity)
    }
}

/// The read requests for `points`, each point's own slave or `slave`.
pub fn groups(points: &[&Point], slave: u8, max: Option<u16>) -> Vec<Group> {
    let mut order: Vec<usize> = (0..points.len()).collect();
    order.sort_by_key(|i| {
        let p = points[*i];
        (p.slave.unwrap_or(slave), p.table.digit(), p.address)
    });
    let mut groups: Vec<Group> = Vec::new();
    for index in order {
        let point = points[index];
        let point_slave = point.slave.unwrap_or(slave);
        let (start, end) = point.span();
        let limit = u32::from(if point.table.is_bits() {
            limits::MAX_READ_BITS
        } else {
            limits::MAX_READ_REGISTERS
        });
        let joins = groups.last().is_some_and(|group| {
            let group_start = u32::from(group.address);
            let group_end = group_start + u32::from(group.quantity);
            let same = group.slave == point_slave && group.table == point.table;
            same && match max {
                // The manuals' window: N from the group's first address, holes included.
                Some(n) => end <= group_start + u32::from(n).min(limit),
                // A run: the point follows on (or shares a register, for bits).
                None => start <= group_end && end <= group_start + limit,
            }
        });
        match groups.last_mut() {
            Some(group) if joins => {
                let group_end = u32::from(group.address) + u32::from(group.quantity);
                group.quantity = (group_end.max(end) - u32::from(group.address)) as u16;
                group.points.push(index);
            }
            _ => groups.push(Group {
                slave: point_slave,
                table: point.table,
                address: point.address,
                quantity: (end - start) as u16,
                points: vec![index],
            }),
        }
    }
    groups
}

/// What a point holds, as read.
#[derive(Clone, Debug, PartialEq)]
pub struct PointValue {
    /// The index of the point in those read.
    pub point: usize,
    /// The registers it takes (for a bit of a register, that register), or for a coil or
    /// discrete input its state as 0 or 1.
    pub raw: Vec<u16>,
    /// Its value, scaled.
    pub value: Value,
}

/// Points that could not be read, and why.
#[derive(Debug)]
pub struct PointFailure {
    /// The points, as indices into the points read.
    pub points: Vec<usize>,
    /// What the request that carried them got.
    pub error: RunError,
}

/// What a map read gave.
#[derive(Debug, Default)]
pub struct MapRead {
    /// The value of every point read, in the order of the points.
    pub values: Vec<PointValue>,
    /// The points that failed, each request's failure once.
    pub failed: Vec<PointFailure>,
    /// A request that spanned holes was refused, and its points read again run by run.
    pub fell_back: bool,
    /// The points the device says it does not have (exception 02), when read around
    /// holes: indexes into the points read.
    pub missing: Vec<usize>,
}

impl MapRead {
    /// The first point, in the order of the points, that failed, and why.
    pub fn first_failure(&self) -> Option<(usize, &RunError)> {
        self.failed
            .iter()
            .filter_map(|failure| Some((*failure.points.iter().min()?, &failure.error)))
            .min_by_key(|(index, _)| *index)
    }

    /// How many points failed.
    pub fn failed_points(&self) -> usize {
        self.failed.iter().map(|failure| failure.points.len()).sum()
    }
}

/// What a run of points the device refuses with exception 02 is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Refused {
    /// An error: a map says its points exist.
    Error,
    /// Holes to read around, as in a range asked for by address: the run is split in
    /// halves down to single points, and the points refused alone are `missing`.
    Around,
    /// As `Error`, and a device silent to the read's first request is taken as away:
    /// its other requests are not sent, their points failing with the same timeout (a
    /// plant's poll, where a device that is not there must not hold its line for long).
    ErrorAndAway,
}

/// Reads `points` in the requests [`groups`] gives; `refused` says what a run the device
/// refuses is. The points of a request without a usable answer (an exception, a timeout,
/// a bad answer), found down to the points it is about, are in `failed`; only a failure
/// that ends the conversation (the port gone, a stop asked) is an error.
pub fn read_points(
    master: &mut Master,
    points: &[&Point],
    slave: u8,
    max: Option<u16>,
    refused: Refused,
) -> Result<MapRead, RunError> {
    let mut read = MapRead::default();
    let mut values: Vec<Option<PointValue>> = vec![None; points.len()];
    let mut pending: VecDeque<Group> = groups(points, slave, max).into();
    // The slaves that answered some request: a request of theirs that got no answer may
    // have been about one of its points (a device that is silent for an address it lacks).
    let mut answered: Vec<u8> = Vec::new();
    // Requests of several points without an answer, split once it is known that their
    // slave answers others.
    let mut unanswered: Vec<(Group, RunError)> = Vec::new();
    // The slaves none of whose requests got an answer, one of which was read again in
    // halves to learn whether they answer at all: a silent device costs one more request.
    let mut tried_halves: Vec<u8> = Vec::new();
    loop {
        let Some(group) = pending.pop_front() else {
            // What got no answer from a slave that answers is read again in halves. Of a
            // slave not heard from, one request is halved, to learn whether it answers at
            // all; when it does not, its requests fail.
            let mut waiting = Vec::new();
            for (group, error) in std::mem::take(&mut unanswered) {
                if answered.contains(&group.slave) {
                    read_again_in_halves(&mut pending, &group, points, slave);
                } else if !tried_halves.contains(&group.slave) {
                    tried_halves.push(group.slave);
                    read_again_in_halves(&mut pending, &group, points, slave);
                } else {
                    waiting.push((group, error));
                }
            }
            if pending.is_empty() {
                for (group, error) in waiting {
                    read.failed.push(PointFailure {
                        points: group.points,
                        error,
                    });
                }
                break;
            }
            unanswered = waiting;
            continue;
        };
        let outcome = master.answer(group.slave, &group.request());
        if matches!(outcome, Ok(_) | Err(RunError::Exception { .. }))
            && !answered.contains(&group.slave)
        {
            answered.push(group.slave);
        }
        if let Err(RunError::Master(MasterError::Timeout { slave, timeout })) = &outcome {
            if refused == Refused::ErrorAndAway && !answered.contains(slave) {
                let mut away = group.points;
                pending.retain(|other| {
                    let same = other.slave == *slave;
                    if same {
                        away.extend(&other.points);
                    }
                    !same
                });
                unanswered.retain(|(other, _)| {
                    let same = other.slave == *slave;
                    if same {
                        away.extend(&other.points);
                    }
                    !same
                });
                away.sort_unstable();
                let error = MasterError::Timeout {
                    slave: *slave,
                    timeout: *timeout,
                };
                read.failed.push(PointFailure {
                    points: away,
                    error: RunError::Master(error),
                });
                continue;
            }
        }
        match outcome {
            Ok(response) => {
                let (registers, bits) = match response {
                    Some(
                        Response::ReadHoldingRegisters { values }
                        | Response::ReadInputRegisters { values },
                    ) => (values, Vec::new()),
                    Some(response) => (
                        Vec::new(),
                        response
                            .bits(usize::from(group.quantity))
                            .unwrap_or_default(),
                    ),
                    None => (Vec::new(), Vec::new()),
                };
                for index in &group.points {
                    let point = points[*index];
                    let offset = usize::from(point.address - group.address);
                    values[*index] = Some(point_value(*index, point, offset, &registers, &bits));
                }
            }
            // A run has no holes, so a run refused is an error, never read again.
            Err(RunError::Exception { code, .. })
                if has_holes(&group, points)
                    && matches!(
                        code,
                        ExceptionCode::ILLEGAL_DATA_ADDRESS | ExceptionCode::GATEWAY_TARGET_FAILED
                    ) =>
            {
                // Read this group's points again, one run at a time.
                read.fell_back = true;
                read_again(&mut pending, &group.points, points, slave);
            }
            // An exception about some of the points, or an answer that does not read:
            // the device is there, and the points it fails on are found by halves.
            Err(RunError::Exception { code, .. })
                if group.points.len() > 1 && refuses_some_points(code) =>
            {
                read_again_in_halves(&mut pending, &group, points, slave);
            }
            Err(RunError::Master(MasterError::BadFrame { .. })) if group.points.len() > 1 => {
                read_again_in_halves(&mut pending, &group, points, slave);
            }
            Err(
                error @ RunError::Master(
                    MasterError::Timeout { .. } | MasterError::OutOfStep { .. },
                ),
            ) if group.points.len() > 1 => {
                unanswered.push((group, error));
            }
            Err(RunError::Exception { code, .. })
                if refused == Refused::Around && code == ExceptionCode::ILLEGAL_DATA_ADDRESS =>
            {
                read.missing.extend(group.points);
            }
            Err(RunError::Master(MasterError::Io(error))) => {
                return Err(RunError::Master(MasterError::Io(error)))
            }
            Err(RunError::Master(MasterError::Interrupted)) => {
                return Err(RunError::Master(MasterError::Interrupted))
            }
            Err(error) => read.failed.push(PointFailure {
                points: group.points,
                error,
            }),
        }
    }
    read.values = values.into_iter().flatten().collect();
    Ok(read)
}

/// The points `members` (indices into `points`) read again next, a run at a time, in
/// address order, before the groups still to read.
fn read_again(pending: &mut VecDeque<Group>, members: &[usize], points: &[&Point], slave: u8) {
    let chosen: Vec<&Point> = members.iter().map(|i| points[*i]).collect();
    for mut run in groups(&chosen, slave, None).into_iter().rev() {
        for index in &mut run.points {
            *index = members[*index];
        }
        pending.push_front(run);
    }
}

/// A group's points read again in two halves, the first read first.
fn read_again_in_halves(
    pending: &mut VecDeque<Group>,
    group: &Group,
    points: &[&Point],
    slave: u8,
) {
    let (first, second) = group.points.split_at(group.points.len() / 2);
    for half in [second, first] {
        read_again(pending, half, points, slave);
    }
}

/// Whether an exception may be about some of a request's points only: an address the
/// device lacks, a value it cannot give, or a failure reading one of them. A function the
/// device lacks, or a gateway's word that the device is not there, is about all of them.
fn refuses_some_points(code: ExceptionCode) -> bool {
    matches!(
        code,
        ExceptionCode::ILLEGAL_DATA_ADDRESS
            | ExceptionCode::ILLEGAL_DATA_VALUE
            | ExceptionCode::SERVER_DEVICE_FAILURE
    )
}

/// Whether a group reads addresses no point takes.
fn has_holes(group: &Group, points: &[&Point]) -> bool {
    let mut covered = vec![false; usize::from(group.quantity)];
    for index in &group.points {
        let (start, end) = points[*index].span();
        for at in start..end {
            if let Some(slot) = covered.get_mut((at - u32::from(group.address)) as usize) {
                *slot = true;
            }
        }
    }
    covered.contains(&false)
}

fn point_value(
    index: usize,
    point: &Point,
    offset: usize,
    registers: &[u16],
    bits: &[bool],
) -> PointValue {
    let width = usize::from(point.kind.width());
    let raw = registers
        .get(offset..offset + width)
        .unwrap_or_default()
        .to_vec();
    let states = point.shown.as_ref().and_then(|shown| shown.states.as_ref());
    let value = match (point.kind, point.bit) {
        (Kind::Bool, None) => Value::Unsigned(u64::from(coil(bits, offset))),
        // A register that stands for states (a switch's, a cover's) is named by them.
        (Kind::Number(_), _) if states.is_some() => {
            Value::Unsigned(u64::from(raw.first().copied().unwrap_or_default()))
        }
        _ => register_value(point, &raw),
    };
    let value = match (states, &value) {
        (Some(states), Value::Unsigned(raw)) => states.state(*raw),
        _ => value,
    };
    PointValue {
        point: index,
        raw: match (point.kind, point.bit) {
            (Kind::Bool, None) => vec![u16::from(coil(bits, offset))],
            _ => raw,
        },
        value,
    }
}

/// The value of a point kept in registers, as a map read shows it, from its registers.
pub fn register_value(point: &Point, raw: &[u16]) -> Value {
    match point.kind {
        Kind::Number(value_type) => scaled(point, value_type.read(raw, point.order)),
        Kind::Text(_) => text(raw, point.order),
        Kind::Packed(_) => packed(point, raw),
        Kind::Bool => {
            let register = raw.first().copied().unwrap_or_default();
            Value::Unsigned(u64::from(register >> point.bit.unwrap_or(0) & 1))
        }
    }
}

fn coil(bits: &[bool], offset: usize) -> bool {
    bits.get(offset).copied().unwrap_or_default()
}

/// A raw value as the map shows it: raw x scale + offset, then as its file says it is
/// shown.
fn scaled(point: &Point, raw: Value) -> Value {
    let marked = match raw {
        Value::Unsigned(v) => Some(i128::from(v)),
        Value::Signed(v) => Some(i128::from(v)),
        _ => None,
    };
    // A raw value the map says stands for none, or a float's NaN, is no measurement.
    let nan = match raw {
        Value::Float32(v) => v.is_nan(),
        Value::Float(v) => v.is_nan(),
        _ => false,
    };
    if nan || (marked.is_some() && marked == point.nan_value) {
        return Value::Text(UNKNOWN.into());
    }
    let number = match raw {
        Value::Unsigned(v) => v as f64,
        Value::Signed(v) => v as f64,
        Value::Float32(v) => f64::from(v),
        Value::Float(v) | Value::Decimal(v, _) => v,
        Value::Text(_) => return raw,
    };
    if let Some(shown) = &point.shown {
        return shown.number(point.scale, point.offset, number);
    }
    if point.is_unscaled() {
        return raw;
    }
    Value::Float(round_to(
        number * point.scale + point.offset,
        decimals(point),
    ))
}

/// The values of a point packed as its structure says, byte order applied to the registers
/// first as Home Assistant applies `swap`.
fn packed(point: &Point, raw: &[u16]) -> Value {
    let mut bytes: Vec<u8> = raw.iter().flat_map(|r| r.to_be_bytes()).collect();
    crate::model::values::reorder(&mut bytes, point.order);
    let values = point
        .structure
        .as_ref()
        .and_then(|structure| structure.unpack(&bytes));
    // Packed values come from Home Assistant's maps, which always say how they are shown.
    match (values, &point.shown) {
        (Some(values), Some(shown)) => shown.unpacked(point.scale, point.offset, &values),
        _ => Value::Text(UNKNOWN.into()),
    }
}

/// The decimals a scaled value has: those of its scale and offset (0.1 has one), so that
/// 14500 x 0.1 shows as 1450 and not as 1450.0000000000002.
fn decimals(point: &Point) -> i32 {
    let of = |x: f64| -> i32 {
        let text = format!("{x:e}");
        let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
        let digits =
            i32::try_from(mantissa.split_once('.').map_or(0, |(_, d)| d.len())).unwrap_or(0);
        (digits - exponent.parse::<i32>().unwrap_or(0)).max(0)
    };
    of(point.scale).max(of(point.offset))
}

fn round_to(value: f64, decimals: i32) -> f64 {
    let factor = 10f64.powi(decimals.min(15));
    let rounded = (value * factor).round() / factor;
    if rounded.is_finite() {
        rounded
    } else {
        value
    }
}

/// What `request`, made by [`write_request`] for `point`, writes, as the map shows it:
/// the value asked for, rounded to what the point can hold.
pub fn written_value(point: &Point, request: &Request) -> Option<Value> {
    let (registers, bits) = match request {
        Request::WriteSingleRegister { value, .. } => (vec![*value], Vec::new()),
        Request::WriteMultipleRegisters { values, .. } => (values.clone(), Vec::new()),
        Request::WriteSingleCoil { value, .. } => (Vec::new(), vec![*value]),
        Request::MaskWriteRegister { or_mask, .. } => {
            return Some(Value::Unsigned(u64::from(*or_mask != 0)))
        }
        _ => return None,
    };
    Some(point_value(0, point, 0, &registers, &bits).value)
}

/// The request that writes `text` to `point`, scale and offset taken back out and the
/// value checked against the point's type; the point must be writable.
pub fn write_request(point: &Point, text: &str) -> Result<Request, String> {
    if !point.writable {
        return Err(format!(
            "{} ({}) is read-only in the map",
            point.name,
            point.reference()
        ));
    }
    let address = point.address;
    let named = |e: String| format!("{}: {e}", point.name);
    if let Some(value) = switch_command(point, text) {
        return Ok(Request::WriteSingleRegister { address, value });
    }
    Ok(match (point.kind, point.bit) {
        (Kind::Bool, Some(bit)) => {
            let on = parse_coil(text).map_err(named)?;
            Request::MaskWriteRegister {
                address,
                and_mask: !(1 << bit),
                or_mask: u16::from(on) << bit,
            }
        }
        (Kind::Bool, None) => Request::WriteSingleCoil {
            address,
            value: parse_coil(text).map_err(named)?,
        },
        (Kind::Number(value_type), _) => {
            let raw = unscaled(point, value_type, text).map_err(named)?;
            let registers = value_type.parse(&raw, point.order).map_err(named)?;
            let written = match value_type.read(&registers, point.order) {
                Value::Unsigned(v) => Some(i128::from(v)),
                Value::Signed(v) => Some(i128::from(v)),
                _ => None,
            };
            if written.is_some() && written == point.nan_value {
                return Err(format!(
                    "{}: {text} would be written as {raw}, the raw number the map says stands for no value (nan_value)",
                    point.name
                ));
            }
            registers_request(address, registers)
        }
        (Kind::Packed(_), _) => {
            return Err(format!(
                "{} ({}) is values packed by a structure, which are read only",
                point.name,
                point.reference()
            ))
        }
        (Kind::Text(count), _) => {
            let mut registers = ValueType::Ascii.parse(text, point.order).map_err(named)?;
            if registers.len() > usize::from(count) {
                return Err(format!(
                    "{}: '{text}' takes {} registers; the point holds {count} (two characters each)",
                    point.name,
                    registers.len()
                ));
            }
            registers.resize(usize::from(count), 0);
            registers_request(address, registers)
        }
    })
}

/// For a switch kept in a register, the command `on` or `off` (`true`, `false`) is written
/// as; a number is written as it is.
fn switch_command(point: &Point, text: &str) -> Option<u16> {
    let [on, off] = point.shown.as_ref()?.commands?;
    if text.trim().parse::<f64>().is_ok() {
        return None;
    }
    parse_coil(text)
        .ok()
        .map(|state| if state { on } else { off })
}

fn registers_request(address: u16, registers: Vec<u16>) -> Request {
    match registers.as_slice() {
        [value] => Request::WriteSingleRegister {
            address,
            value: *value,
        },
        _ => Request::WriteMultipleRegisters {
            address,
            values: registers,
        },
    }
}

/// The raw value to write for a shown value: (value - offset) / scale, a whole number
/// for a whole-number type, in the type's range as the map shows it (an unsigned point
/// takes no negative value).
fn unscaled(point: &Point, value_type: ValueType, text: &str) -> Result<String, String> {
    let floating = matches!(value_type, ValueType::F32 | ValueType::F64);
    if floating && point.is_unscaled() {
        return Ok(text.to_string());
    }
    let shown = match crate::input::number::parse_int(text) {
        Ok(whole) => whole as f64,
        Err(_) => text
            .trim()
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| format!("'{text}' is not a number"))?,
    };
    let raw = (shown - point.offset) / point.scale;
    if floating {
        return Ok(raw.to_string());
    }
    let (min, max) = value_type.strict_range();
    let whole = raw.round();
    if whole < min as f64 || whole > max as f64 {
        let ends = [
            min as f64 * point.scale + point.offset,
            max as f64 * point.scale + point.offset,
        ];
        let (low, high) = (ends[0].min(ends[1]), ends[0].max(ends[1]));
        let unit = if point.unit.is_empty() {
            String::new()
        } else {
            format!(" {}", point.unit)
        };
        return Err(format!(
            "{text}{unit} is out of range for this {} point: give {} to {}",
            value_type.name(),
            round_to(low, decimals(point)),
            round_to(high, decimals(point))
        ));
    }
    Ok(format!("{}", whole as i128))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::map::parse_csv;

    fn requests(refs: &[&str], max: Option<u16>) -> Vec<(u16, u16)> {
        let text: String = refs
            .iter()
            .enumerate()
            .map(|(i, r)| format!("p{i},{r}\n"))
            .collect();
        let map = parse_csv("m", &format!("name,ref\n{text}")).unwrap();
        let points: Vec<&Point> = map.points.iter().collect();
        groups(&points, 17, max)
            .iter()
            .map(|g| (g.address, g.quantity))
            .collect()
    }

    #[test]
    fn the_manuals_grouping() {
        let first_five = ["400001", "400002", "400003", "400004", "400005", "400120"];
        assert_eq!(requests(&first_five, Some(120)), [(0, 120)]);
        assert_eq!(requests(&first_five, Some(3)), [(0, 3), (3, 2), (119, 1)]);
        let spread = ["400001", "400010", "400011", "400021", "400031", "400041"];
        assert_eq!(
            requests(&spread, Some(10)),
            [(0, 10), (10, 1), (20, 1), (30, 1), (40, 1)]
        );
        // Without the option, runs of consecutive addresses only.
        assert_eq!(requests(&first_five, None), [(0, 5), (119, 1)]);
        assert_eq!(requests(&spread, None).len(), 5);
    }

    #[test]
    fn the_mark_of_no_value_is_neither_read_nor_written() {
        let map = parse_csv(
            "m",
            "name,ref,type,scale,nan_value\ng,400001,u16,0.1,65535\n",
        )
        .unwrap();
        assert_eq!(
            write_request(&map.points[0], "6553.5"),
            Err("g: 6553.5 would be written as 65535, the raw number the map says stands for no value (nan_value)".into())
        );
        assert!(write_request(&map.points[0], "6553.4").is_ok());
        assert_eq!(
            register_value(&map.points[0], &[0xFFFF]),
            Value::Text(UNKNOWN.into())
        );
        let refused = |line: &str| {
            parse_csv("m", &format!("name,ref,type,nan_value\n{line}\n"))
                .unwrap_err()
                .to_string()
        };
        assert!(refused("a,400001,u16,-1")
            .contains("nan_value -1 is never read from a u16: give 0 to 65535"));
        assert!(refused("a,400001,i16,0x8000")
            .contains("nan_value 32768 is never read from a i16: give -32768 to 32767"));
        assert!(refused("a,400001,f32,0").contains("nan_value is for whole-number points, not f32"));
        assert!(refused("a,400001.01,bool,1")
            .contains("nan_value is for whole-number points, not bool"));
    }

    #[test]
    fn scaled_values_are_written_raw() {
        let map = parse_csv("m", "name,ref,type,scale,offset\nt,400001,i16,0.1,-40\n").unwrap();
        assert_eq!(
            write_request(&map.points[0], "21.5"),
            Ok(Request::WriteSingleRegister {
                address: 0,
                value: 615
            })
        );
        assert_eq!(
            write_request(&map.points[0], "4000"),
            Err("t: 4000 is out of range for this i16 point: give -3316.8 to 3236.7".into())
        );
        // An unsigned point takes no negative value, whatever two's complement would allow.
        let unsigned = parse_csv("m", "name,ref,scale,unit\np,400001,0.1,bar\n").unwrap();
        assert_eq!(
            write_request(&unsigned.points[0], "-3"),
            Err("p: -3 bar is out of range for this u16 point: give 0 to 6553.5".into())
        );
    }
}
