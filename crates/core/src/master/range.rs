//! A range read around its holes, as `--poll` of a range needs: a device that has 400003,
//! 400004 and 400006 but not 400005 refuses `400003 4` whole with exception 02, and the
//! user still wants to see the three it has.

use super::map::{read_points, Refused};
use super::plan::Plan;
use super::run::{ReadResult, RunError};
use super::Master;
use crate::codec::ExceptionCode;
use crate::model::address::Table;
use crate::model::map::{range_points, Kind, Point};
use crate::model::values::ReadData;
use crate::model::values::{ByteOrder, ValueType};

/// What a range read around its holes gave.
#[derive(Clone, Debug, PartialEq)]
pub struct RangeRead {
    /// The runs of consecutive addresses the device has, in address order.
    pub parts: Vec<ReadResult>,
    /// The first address of each item (a value of the type read, or a bit) the device
    /// refused alone with exception 02, in address order.
    pub missing: Vec<u16>,
}

impl From<ReadResult> for RangeRead {
    fn from(result: ReadResult) -> Self {
        Self {
            parts: vec![result],
            missing: Vec::new(),
        }
    }
}

/// How the registers of a range read are values, so that a hole is never found inside
/// one.
#[derive(Clone, Copy, Debug)]
pub struct Items {
    /// The type each value is read as: a wide one takes several registers.
    pub value_type: ValueType,
    /// The order of its bytes and words.
    pub order: ByteOrder,
    /// At most this many items per request, below the protocol's limit.
    pub max_per_request: Option<u16>,
}

/// Reads `plan` as [`Master::read`] does; where the device refuses the range with
/// exception 02, reads it again around its holes, down to single values, as `watch` and
/// `dump` do. A range of which nothing exists, a single value, bits of a register and text
/// (one value across all its registers) keep the device's exception.
pub fn read_range(
    master: &mut Master,
    plan: &Plan,
    (table, address): (Table, u16),
    items: Items,
) -> Result<RangeRead, RunError> {
    let refused = match master.read(plan, table, address) {
        Ok(result) => return Ok(result.into()),
        Err(error @ RunError::Exception { code, .. })
            if code == ExceptionCode::ILLEGAL_DATA_ADDRESS
                && plan.bits.is_none()
                && items.value_type != ValueType::Ascii =>
        {
            error
        }
        Err(error) => return Err(error),
    };
    let kind = if table.is_bits() {
        Kind::Bool
    } else {
        Kind::Number(items.value_type)
    };
    let width = u32::from(kind.width());
    let quantity: u32 = plan
        .requests
        .iter()
        .map(|request| u32::from(request.read_quantity()))
        .sum();
    if quantity <= width {
        return Err(refused);
    }
    let points = range_points(table, address, quantity / width, None, kind, items.order);
    let asked: Vec<&Point> = points.iter().collect();
    // The whole range was refused already: its halves are read, not it again.
    let middle = asked.len() / 2;
    let (mut values, mut missing) = (Vec::new(), Vec::new());
    for (offset, half) in [(0, &asked[..middle]), (middle, &asked[middle..])] {
        let read = read_points(
            master,
            half,
            plan.slave,
            items.max_per_request,
            Refused::Around,
        )?;
        // A range is one read: a part of it that failed otherwise than by a hole fails it.
        if let Some(failure) = read.failed.into_iter().next() {
            return Err(failure.error);
        }
        values.extend(read.values.into_iter().map(|mut value| {
            value.point += offset;
            value
        }));
        missing.extend(read.missing.into_iter().map(|index| index + offset));
    }
    if values.is_empty() {
        return Err(refused);
    }
    let mut parts: Vec<ReadResult> = Vec::new();
    for value in &values {
        let point = &points[value.point];
        let next = parts
            .last()
            .map(|part| u32::from(part.address) + part.data.len() as u32);
        let part = match parts.last_mut() {
            Some(part) if next == Some(u32::from(point.address)) => part,
            _ => {
                parts.push(ReadResult {
                    slave: plan.slave,
                    function: table.read_function(),
                    table,
                    address: point.address,
                    data: match table.is_bits() {
                        true => ReadData::Bits(Vec::new()),
                        false => ReadData::Registers(Vec::new()),
                    },
                    first_bit: None,
                });
                let last = parts.len() - 1;
                &mut parts[last]
            }
        };
        match &mut part.data {
            ReadData::Registers(registers) => registers.extend(&value.raw),
            ReadData::Bits(bits) => bits.extend(value.raw.iter().map(|state| *state != 0)),
        }
    }
    let mut missing: Vec<u16> = missing.iter().map(|i| points[*i].address).collect();
    missing.sort_unstable();
    Ok(RangeRead { parts, missing })
}
