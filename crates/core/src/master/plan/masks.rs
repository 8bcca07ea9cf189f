//! Requests that do two things in one transaction: a mask write (22) changes some bits of
//! a register and keeps the others, a read/write (23) writes registers and reads others.

use crate::codec::{limits, Request};
use crate::input::number::parse_in_range;
use crate::model::address::{parse_span, split_bit, Access, Numbering, Span, Table};

use super::{bit_write_plan, check_end, parse_registers, Plan, PlanError, PlanOptions, Result};

/// One holding register, or a run without a range.
fn register(text: &str, access: Access, numbering: Numbering) -> Result<Span> {
    let span = parse_span(text, Table::HoldingRegisters, access, numbering)?;
    if span.count.is_some() {
        return Err(PlanError::Records(format!(
            "{text}: give one register here, not a range"
        )));
    }
    Ok(span)
}

fn mask(text: &str, which: &str) -> Result<u16> {
    parse_in_range(text, 0, 0xFFFF, which)
        .map(|mask| mask as u16)
        .map_err(PlanError::Value)
}

/// `mask-write SLAVE REF AND OR`, or a bit of a register: `REF.BIT=VALUE` or
/// `REF.BIT VALUE`.
pub(super) fn mask_write_plan(
    slave: u8,
    reference: &str,
    masks: &[String],
    options: PlanOptions,
) -> Result<Plan> {
    let (reference, assigned) = match reference.split_once('=') {
        Some((reference, value)) => (reference, Some(value.to_string())),
        None => (reference, None),
    };
    let (address, bit) = split_bit(reference)?;
    match (bit, assigned) {
        (Some(bit), Some(value)) if masks.is_empty() => {
            let span = register(address, Access::WriteOne, options.numbering)?;
            bit_write_plan(slave, (address, span), bit, &[value])
        }
        (Some(bit), None) => {
            let span = register(address, Access::WriteOne, options.numbering)?;
            bit_write_plan(slave, (address, span), bit, masks)
        }
        (None, None) => {
            let [and, or] = masks else {
                return Err(PlanError::Records(
                    "give the AND and OR masks (mask-write 17 400005 0x00F2 0x0025), or a bit: \
                     mask-write 17 400108.05=1"
                        .into(),
                ));
            };
            let span = register(address, Access::WriteOne, options.numbering)?;
            Ok(Plan {
                slave,
                requests: vec![Request::MaskWriteRegister {
                    address: span.address,
                    and_mask: mask(and, "AND")?,
                    or_mask: mask(or, "OR")?,
                }],
                reads: None,
                bits: None,
            })
        }
        _ => Err(PlanError::BitWrite),
    }
}

/// `read-write SLAVE READREF COUNT WRITEREF VALUE...`: one request, never split, since
/// its write and read are one transaction.
pub(super) fn read_write_plan(
    slave: u8,
    (read, count): (&str, &str),
    write: &str,
    values: &[String],
    options: PlanOptions,
) -> Result<Plan> {
    let width = options.value_type.width();
    let read_span = register(read, Access::Read, options.numbering)?;
    let most = usize::from(limits::MAX_RW_READ_REGISTERS) / width;
    let count = parse_in_range(count, 1, most as i128, "COUNT").map_err(|error| {
        PlanError::Count(format!(
            "{error}: function 23 reads at most {} registers in its one transaction",
            limits::MAX_RW_READ_REGISTERS
        ))
    })? as usize
        * width;
    check_end(read, read_span.address, count as u32)?;
    let write_span = register(write, Access::WriteMany, options.numbering)?;
    if values.is_empty() {
        return Err(PlanError::NoValues);
    }
    let registers = parse_registers(values, options)?;
    if registers.is_empty() {
        return Err(PlanError::NoValues);
    }
    if registers.len() > usize::from(limits::MAX_RW_WRITE_REGISTERS) {
        return Err(PlanError::Records(format!(
            "the values take {} registers, and function 23 writes at most {} in its one transaction",
            registers.len(),
            limits::MAX_RW_WRITE_REGISTERS
        )));
    }
    check_end(write, write_span.address, registers.len() as u32)?;
    Ok(Plan {
        slave,
        requests: vec![Request::ReadWriteMultipleRegisters {
            read_address: read_span.address,
            read_quantity: count as u16,
            write_address: write_span.address,
            values: registers,
        }],
        reads: Some((Table::HoldingRegisters, read_span.address)),
        bits: None,
    })
}

#[cfg(test)]
mod tests {
    use super::super::tests::words;
    use super::*;

    #[test]
    fn a_bit_is_one_mask_write_in_either_form() {
        let options = PlanOptions::default();
        let expected = vec![Request::MaskWriteRegister {
            address: 107,
            and_mask: !(1 << 5),
            or_mask: 1 << 5,
        }];
        let plan = mask_write_plan(17, "400108.05=1", &[], options).unwrap();
        assert_eq!(plan.requests, expected);
        let plan = mask_write_plan(17, "400108.05", &words("on"), options).unwrap();
        assert_eq!(plan.requests, expected);
        // The specification's example: register 5, AND 00F2, OR 0025.
        let plan = mask_write_plan(17, "400005", &words("0x00F2 0x0025"), options).unwrap();
        assert_eq!(
            plan.requests,
            [Request::MaskWriteRegister {
                address: 4,
                and_mask: 0xF2,
                or_mask: 0x25
            }]
        );
        assert!(mask_write_plan(17, "400005", &words("0x1FFFF 0"), options).is_err());
        assert!(mask_write_plan(17, "400005", &words("1"), options).is_err());
        assert!(mask_write_plan(17, "300005.01=1", &[], options).is_err());
    }

    #[test]
    fn read_write_is_one_request_or_refused() {
        let options = PlanOptions::default();
        let plan = read_write_plan(
            17,
            ("400004", "6"),
            "400015",
            &words("255 255 255"),
            options,
        )
        .unwrap();
        assert_eq!(plan.requests.len(), 1);
        let mut bytes = Vec::new();
        plan.requests[0].encode(&mut bytes).unwrap();
        // The specification's example request.
        assert_eq!(
            crate::codec::hex::spaced_hex(&bytes),
            "17 00 03 00 06 00 0E 00 03 06 00 FF 00 FF 00 FF"
        );
        assert!(read_write_plan(17, ("400001", "126"), "400001", &words("1"), options).is_err());
        let many: Vec<String> = (0..122).map(|i| i.to_string()).collect();
        assert!(read_write_plan(17, ("400001", "1"), "400001", &many, options).is_err());
    }
}
