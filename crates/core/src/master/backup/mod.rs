//! A device's tables saved and put back. `dump` reads ranges in as few requests as the
//! limits allow and splits a request that is refused with exception 02 (halves, down to
//! single addresses), so that every address that exists is read and only the holes are
//! left out. `restore` writes the coils and holding registers of data file entries with the
//! fewest requests, then reads them back and tells what differs. Records of files go the
//! same way where asked (`files`).

mod files;

pub use files::{dump_files, file_restore_requests, verify_files, FileDump};

use std::sync::atomic::{AtomicBool, Ordering};

use super::run::RunError;
use super::{Master, MasterError};
use crate::codec::{limits, ExceptionCode, Request, Response};
use crate::model::address::Table;
use crate::model::values::ReadData;
use crate::slave::datafile::Entry;

/// A range to dump: `count` addresses of `table` from `address`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Range {
    /// The table.
    pub table: Table,
    /// The first address, 0-based.
    pub address: u16,
    /// How many addresses, at least 1.
    pub count: u32,
}

/// What a dump read.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Dump {
    /// The runs of addresses that exist, with their values, in the order read.
    pub entries: Vec<Entry>,
    /// The runs of addresses the device refused with exception 02.
    pub holes: Vec<Range>,
    /// Addresses the device has but could not give (exception 03 or 04 for them alone),
    /// left out, with the exception.
    pub unreadable: Vec<(Range, ExceptionCode)>,
    /// How many requests it took.
    pub requests: u64,
    /// It was stopped before every range was read: what it holds is a part.
    pub interrupted: bool,
}

/// The most one read request carries of `table`, or `max` when lower.
fn read_limit(table: Table, max: Option<u16>) -> u32 {
    let limit = if table.is_bits() {
        limits::MAX_READ_BITS
    } else {
        limits::MAX_READ_REGISTERS
    };
    u32::from(max.map_or(limit, |max| max.clamp(1, limit)))
}

/// Reads `quantity` addresses of `table` from `address` in one request.
fn read_one(
    master: &mut Master,
    slave: u8,
    table: Table,
    address: u16,
    quantity: u16,
) -> Result<ReadData, RunError> {
    let request = super::plan::read_request(table, address, quantity);
    Ok(match master.answer(slave, &request)? {
        Some(
            Response::ReadHoldingRegisters { values } | Response::ReadInputRegisters { values },
        ) => ReadData::Registers(values),
        Some(response) => ReadData::Bits(response.bits(usize::from(quantity)).unwrap_or_default()),
        None => ReadData::Registers(Vec::new()),
    })
}

/// Appends `values` read at `address` to the entries, joining the last entry when they
/// follow on from it.
fn append(entries: &mut Vec<Entry>, table: Table, address: u16, values: ReadData) {
    if let Some(last) = entries.last_mut() {
        let end = u32::from(last.address) + last.values.len() as u32;
        if last.table == table && end == u32::from(address) {
            match (&mut last.values, values) {
                (ReadData::Bits(have), ReadData::Bits(more)) => return have.extend(more),
                (ReadData::Registers(have), ReadData::Registers(more)) => return have.extend(more),
                (_, values) => {
                    entries.push(Entry {
                        table,
                        address,
                        values,
                    });
                    return;
                }
            }
        }
    }
    entries.push(Entry {
        table,
        address,
        values,
    });
}

fn add_hole(holes: &mut Vec<Range>, table: Table, address: u16, count: u32) {
    if let Some(last) = holes.last_mut() {
        if last.table == table && u32::from(last.address) + last.count == u32::from(address) {
            last.count += count;
            return;
        }
    }
    holes.push(Range {
        table,
        address,
        count,
    });
}

/// Reads `count` addresses from `address`, split in halves where the device answers 02.
fn read_splitting(
    master: &mut Master,
    (slave, table): (u8, Table),
    (address, count): (u16, u16),
    dump: &mut Dump,
    stop: &AtomicBool,
) -> Result<(), RunError> {
    // Halving a run down to its holes can take many requests: a signal ends it too.
    if stop.load(Ordering::SeqCst) {
        dump.interrupted = true;
        return Ok(());
    }
    dump.requests += 1;
    match read_one(master, slave, table, address, count) {
        Ok(values) => append(&mut dump.entries, table, address, values),
        Err(RunError::Exception { code, .. })
            if count == 1
                && matches!(
                    code,
                    ExceptionCode::ILLEGAL_DATA_VALUE | ExceptionCode::SERVER_DEVICE_FAILURE
                ) =>
        {
            let range = Range {
                table,
                address,
                count: 1,
            };
            dump.unreadable.push((range, code));
        }
        // One address's refusal is that address's alone: the run is read in halves.
        Err(RunError::Exception {
            code:
                ExceptionCode::ILLEGAL_DATA_ADDRESS
                | ExceptionCode::ILLEGAL_DATA_VALUE
                | ExceptionCode::SERVER_DEVICE_FAILURE,
            ..
        }) => {
            if count == 1 {
                add_hole(&mut dump.holes, table, address, 1);
            } else {
                let first = count / 2;
                let place = (slave, table);
                read_splitting(master, place, (address, first), dump, stop)?;
                read_splitting(master, place, (address + first, count - first), dump, stop)?;
            }
        }
        // A signal came while the request waited for its answer: it counts as not made.
        Err(RunError::Master(MasterError::Interrupted)) => {
            dump.requests -= 1;
            dump.interrupted = true;
        }
        Err(error) => return Err(error),
    }
    Ok(())
}

/// The ranges with those of one table that overlap or meet joined, each address once,
/// in the order their tables first come.
fn merged(ranges: &[Range]) -> Vec<Range> {
    let mut tables: Vec<Table> = Vec::new();
    for range in ranges {
        if !tables.contains(&range.table) {
            tables.push(range.table);
        }
    }
    let mut out: Vec<Range> = Vec::new();
    for table in tables {
        let mut of_table: Vec<Range> = ranges
            .iter()
            .filter(|r| r.table == table)
            .copied()
            .collect();
        of_table.sort_by_key(|r| r.address);
        for range in of_table {
            let end = u32::from(range.address) + range.count;
            match out.last_mut() {
                Some(last)
                    if last.table == table
                        && u32::from(range.address) <= u32::from(last.address) + last.count =>
                {
                    last.count = last.count.max(end - u32::from(last.address));
                }
                _ => out.push(range),
            }
        }
    }
    out
}

/// Reads every range, overlapping ones once, in requests of at most the protocol's limit
/// (or `max`). `stop`, once set (by a signal handler, say), ends it between requests with
/// the part read so far, marked `interrupted`.
pub fn dump(
    master: &mut Master,
    slave: u8,
    ranges: &[Range],
    max: Option<u16>,
    stop: &AtomicBool,
) -> Result<Dump, RunError> {
    let mut dump = Dump::default();
    for range in &merged(ranges) {
        let limit = read_limit(range.table, max);
        let end = u32::from(range.address) + range.count;
        let mut at = u32::from(range.address);
        while at < end {
            let quantity = (end - at).min(limit);
            // Both fit: addresses end at 65536 and a quantity at the protocol's limit.
            let run = (at as u16, quantity as u16);
            read_splitting(master, (slave, range.table), run, &mut dump, stop)?;
            if dump.interrupted {
                return Ok(dump);
            }
            at += quantity;
        }
    }
    Ok(dump)
}

/// The requests that write the coils and holding registers of `entries`: one value with
/// 05 or 06, more with 15 or 16 in requests as full as the protocol (or `max`) allows.
/// Entries of the read-only tables are left out.
pub fn restore_requests(entries: &[Entry], max: Option<u16>) -> Vec<Request> {
    let bit_limit = usize::from(max.map_or(limits::MAX_WRITE_BITS, |m| {
        m.clamp(1, limits::MAX_WRITE_BITS)
    }));
    let register_limit = usize::from(max.map_or(limits::MAX_WRITE_REGISTERS, |m| {
        m.clamp(1, limits::MAX_WRITE_REGISTERS)
    }));
    let mut requests = Vec::new();
    for entry in entries {
        match (&entry.values, entry.table) {
            (ReadData::Bits(bits), Table::Coils) => {
                for (i, chunk) in bits.chunks(bit_limit).enumerate() {
                    let address = entry.address + (i * bit_limit) as u16;
                    requests.push(match chunk {
                        [value] => Request::WriteSingleCoil {
                            address,
                            value: *value,
                        },
                        values => Request::WriteMultipleCoils {
                            address,
                            values: values.to_vec(),
                        },
                    });
                }
            }
            (ReadData::Registers(registers), Table::HoldingRegisters) => {
                for (i, chunk) in registers.chunks(register_limit).enumerate() {
                    let address = entry.address + (i * register_limit) as u16;
                    requests.push(match chunk {
                        [value] => Request::WriteSingleRegister {
                            address,
                            value: *value,
                        },
                        values => Request::WriteMultipleRegisters {
                            address,
                            values: values.to_vec(),
                        },
                    });
                }
            }
            _ => {}
        }
    }
    requests
}

/// Where a value of a backup is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Place {
    /// An address of a table, 0-based.
    Address(Table, u16),
    /// A record of a file.
    Record {
        /// The file.
        file: u16,
        /// The record.
        record: u16,
    },
}

/// A value read back that is not the one written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Difference {
    /// Where it is.
    pub place: Place,
    /// The value written (a coil as 1 or 0).
    pub wanted: u16,
    /// The value read back; `None` where the device refused to read it (exception 02).
    pub found: Option<u16>,
}

/// Reads the coils and holding registers of `entries` back and lists what differs.
pub fn verify(
    master: &mut Master,
    slave: u8,
    entries: &[Entry],
) -> Result<Vec<Difference>, RunError> {
    let mut differences = Vec::new();
    for entry in entries.iter().filter(|e| e.table.is_writable()) {
        let range = Range {
            table: entry.table,
            address: entry.address,
            count: entry.values.len() as u32,
        };
        let read = dump(master, slave, &[range], None, &AtomicBool::new(false))?;
        // A stop asked while a read-back waited: what was not read is no difference.
        if read.interrupted {
            return Err(RunError::Master(MasterError::Interrupted));
        }
        let wanted = as_numbers(&entry.values);
        let mut found = vec![None; wanted.len()];
        for got in &read.entries {
            let offset = usize::from(got.address - entry.address);
            for (i, value) in as_numbers(&got.values).into_iter().enumerate() {
                if let Some(slot) = found.get_mut(offset + i) {
                    *slot = Some(value);
                }
            }
        }
        for (i, (wanted, found)) in wanted.iter().zip(found).enumerate() {
            if found != Some(*wanted) {
                differences.push(Difference {
                    place: Place::Address(entry.table, entry.address + i as u16),
                    wanted: *wanted,
                    found,
                });
            }
        }
    }
    Ok(differences)
}

fn as_numbers(values: &ReadData) -> Vec<u16> {
    match values {
        ReadData::Bits(bits) => bits.iter().map(|b| u16::from(*b)).collect(),
        ReadData::Registers(registers) => registers.clone(),
    }
}
