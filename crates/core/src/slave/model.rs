//! The four tables of one slave id, its files of records and FIFO queues, and which of
//! their addresses exist.

use std::collections::BTreeMap;

use crate::codec::file::{MAX_FIFO_COUNT, MAX_RECORD};
use crate::codec::{ExceptionCode, FileRecords};
use crate::model::address::Table;

/// One table: its values, which addresses exist, and which may not be written.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TableData<T> {
    values: Vec<T>,
    /// Ranges `[start, end)` that exist; `None`: every address does.
    exists: Option<Vec<(u32, u32)>>,
    read_only: Vec<(u32, u32)>,
}

impl<T: Copy + Default> Default for TableData<T> {
    fn default() -> Self {
        Self {
            values: vec![T::default(); 65536],
            exists: None,
            read_only: Vec::new(),
        }
    }
}

fn covers(ranges: &[(u32, u32)], start: u32, end: u32) -> bool {
    // A run of addresses is covered when each address lies in some range.
    let mut at = start;
    while at < end {
        match ranges.iter().find(|(s, e)| *s <= at && at < *e) {
            Some((_, e)) => at = *e,
            None => return false,
        }
    }
    true
}

fn touches(ranges: &[(u32, u32)], start: u32, end: u32) -> bool {
    ranges.iter().any(|(s, e)| *s < end && start < *e)
}

impl<T: Copy + Default> TableData<T> {
    /// Whether `quantity` addresses from `address` may be read (or written).
    pub fn check(&self, address: u16, quantity: u16, write: bool) -> Result<(), ExceptionCode> {
        let (start, end) = (u32::from(address), u32::from(address) + u32::from(quantity));
        if end > 65536 {
            return Err(ExceptionCode::ILLEGAL_DATA_ADDRESS);
        }
        if let Some(exists) = &self.exists {
            if !covers(exists, start, end) {
                return Err(ExceptionCode::ILLEGAL_DATA_ADDRESS);
            }
        }
        if write && touches(&self.read_only, start, end) {
            return Err(ExceptionCode::ILLEGAL_DATA_ADDRESS);
        }
        Ok(())
    }

    /// The values of `quantity` addresses from `address`, or the exception a slave answers.
    pub fn read(&self, address: u16, quantity: u16) -> Result<Vec<T>, ExceptionCode> {
        self.check(address, quantity, false)?;
        let start = usize::from(address);
        Ok(self.values[start..start + usize::from(quantity)].to_vec())
    }

    /// Writes `values` from `address`, or gives the exception a slave answers.
    pub fn write(&mut self, address: u16, values: &[T]) -> Result<(), ExceptionCode> {
        let quantity =
            u16::try_from(values.len()).map_err(|_| ExceptionCode::ILLEGAL_DATA_VALUE)?;
        self.check(address, quantity, true)?;
        let start = usize::from(address);
        self.values[start..start + values.len()].copy_from_slice(values);
        Ok(())
    }

    /// Sets values without the write checks: initial data.
    pub fn preset(&mut self, address: u16, values: &[T]) {
        let start = usize::from(address);
        let end = (start + values.len()).min(65536);
        self.values[start..end].copy_from_slice(&values[..end - start]);
    }

    /// Declares that `[start, end)` exists; once any range is declared, only declared
    /// ranges exist.
    pub fn declare(&mut self, start: u32, end: u32) {
        self.exists.get_or_insert_with(Vec::new).push((start, end));
    }

    /// Makes `[start, end)` read-only: a write that touches it is refused.
    pub fn protect(&mut self, start: u32, end: u32) {
        self.read_only.push((start, end));
    }

    /// The declared ranges, merged where they meet or overlap, in address order, each with
    /// its values; none when every address exists.
    pub fn runs(&self) -> Vec<(u16, Vec<T>)> {
        let mut ranges: Vec<(u32, u32)> = self
            .exists
            .iter()
            .flatten()
            .copied()
            .filter(|(start, end)| start < end)
            .collect();
        ranges.sort_unstable();
        let mut merged: Vec<(u32, u32)> = Vec::new();
        for (start, end) in ranges {
            match merged.last_mut() {
                Some(last) if start <= last.1 => last.1 = last.1.max(end),
                _ => merged.push((start, end)),
            }
        }
        merged
            .into_iter()
            .filter_map(|(start, end)| {
                let values = self.values.get(start as usize..end as usize)?;
                Some((u16::try_from(start).ok()?, values.to_vec()))
            })
            .collect()
    }
}

/// The files of records of one slave id (functions 20, 21): records 0-9999 of files
/// 1-65535, a register each.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct FileData {
    records: BTreeMap<(u16, u16), u16>,
    /// Only the records given exist (a data file's); otherwise every record of every file
    /// does, 0 until written.
    only_given: bool,
}

impl FileData {
    /// Files in which only the records preset exist.
    pub fn only_given() -> Self {
        Self {
            records: BTreeMap::new(),
            only_given: true,
        }
    }

    fn check(&self, file: u16, record: u16, count: usize) -> Result<(), ExceptionCode> {
        let end = usize::from(record) + count;
        if file == 0 || count == 0 || end > usize::from(MAX_RECORD) + 1 {
            return Err(ExceptionCode::ILLEGAL_DATA_ADDRESS);
        }
        if self.only_given
            && self
                .records
                .range((file, record)..(file, end as u16))
                .count()
                != count
        {
            return Err(ExceptionCode::ILLEGAL_DATA_ADDRESS);
        }
        Ok(())
    }

    /// `count` records of `file` from `record`, or the exception a slave answers.
    pub fn read(&self, file: u16, record: u16, count: u16) -> Result<Vec<u16>, ExceptionCode> {
        self.check(file, record, usize::from(count))?;
        Ok((record..record + count)
            .map(|at| self.records.get(&(file, at)).copied().unwrap_or(0))
            .collect())
    }

    /// Checks that `values` may be written from `record` of `file`.
    pub fn check_write(&self, file: u16, record: u16, values: &[u16]) -> Result<(), ExceptionCode> {
        self.check(file, record, values.len())
    }

    /// Writes `values` from `record` of `file`, or gives the exception a slave answers.
    pub fn write(&mut self, file: u16, record: u16, values: &[u16]) -> Result<(), ExceptionCode> {
        self.check(file, record, values.len())?;
        self.preset(file, record, values);
        Ok(())
    }

    /// Sets records without the checks: initial data.
    pub fn preset(&mut self, file: u16, record: u16, values: &[u16]) {
        for (at, value) in (record..=MAX_RECORD).zip(values) {
            self.records.insert((file, at), *value);
        }
    }

    /// Whether a record holds a value: one given, or written.
    pub fn holds(&self, file: u16, record: u16) -> bool {
        self.records.contains_key(&(file, record))
    }

    /// The records that hold values, a run of consecutive records a group.
    pub fn runs(&self) -> Vec<FileRecords> {
        let mut runs: Vec<FileRecords> = Vec::new();
        for (&(file, record), &value) in &self.records {
            match runs.last_mut() {
                Some(run)
                    if run.file == file
                        && usize::from(run.record) + run.values.len() == usize::from(record) =>
                {
                    run.values.push(value);
                }
                _ => runs.push(FileRecords {
                    file,
                    record,
                    values: vec![value],
                }),
            }
        }
        runs
    }
}

/// The FIFO queues of one slave id (function 24), by the address of their pointer.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct FifoData {
    queues: BTreeMap<u16, Vec<u16>>,
}

impl FifoData {
    /// The queue at `address`: exception 02 where there is none, 03 where it holds more
    /// than one answer carries (31 registers), as the specification says.
    pub fn read(&self, address: u16) -> Result<Vec<u16>, ExceptionCode> {
        let queue = self
            .queues
            .get(&address)
            .ok_or(ExceptionCode::ILLEGAL_DATA_ADDRESS)?;
        if queue.len() > usize::from(MAX_FIFO_COUNT) {
            return Err(ExceptionCode::ILLEGAL_DATA_VALUE);
        }
        Ok(queue.clone())
    }

    /// Puts a queue at `address`, oldest value first.
    pub fn set(&mut self, address: u16, values: Vec<u16>) {
        self.queues.insert(address, values);
    }

    /// Whether a queue stands at `address`.
    pub fn has(&self, address: u16) -> bool {
        self.queues.contains_key(&address)
    }

    /// Every queue, by address.
    pub fn queues(&self) -> impl Iterator<Item = (u16, &[u16])> {
        self.queues
            .iter()
            .map(|(address, values)| (*address, values.as_slice()))
    }
}

/// The four tables of one slave id, its files of records and its FIFO queues.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct DataModel {
    /// Coils (0xxxxx).
    pub coils: TableData<bool>,
    /// Discrete inputs (1xxxxx).
    pub discrete_inputs: TableData<bool>,
    /// Input registers (3xxxxx).
    pub input_registers: TableData<u16>,
    /// Holding registers (4xxxxx).
    pub holding_registers: TableData<u16>,
    /// Files of records (functions 20, 21).
    pub files: FileData,
    /// FIFO queues (function 24).
    pub fifos: FifoData,
}

impl DataModel {
    /// The example values of the source manuals: coils 20-56 = CD 6B B2 0E 1B, inputs
    /// 10197-10218 = AC DB 35, input register 30009 = 10, holding 40108-40110 = 555, 0, 100;
    /// and those of the Modbus application protocol specification's examples: records 1-2
    /// of file 4 = 0DFE 0020, records 9-10 of file 3 = 33CD 0040, and the FIFO queue at
    /// 04DE (401247) = 01B8 1284.
    pub fn manual_examples() -> Self {
        let mut model = DataModel::default();
        let coils = crate::codec::bits::unpack(&[0xCD, 0x6B, 0xB2, 0x0E, 0x1B], 37);
        model.coils.preset(19, &coils);
        let inputs = crate::codec::bits::unpack(&[0xAC, 0xDB, 0x35], 22);
        model.discrete_inputs.preset(196, &inputs);
        model.input_registers.preset(8, &[10]);
        model.holding_registers.preset(107, &[555, 0, 100]);
        model.files.preset(4, 1, &[0x0DFE, 0x0020]);
        model.files.preset(3, 9, &[0x33CD, 0x0040]);
        model.fifos.set(0x04DE, vec![0x01B8, 0x1284]);
        model
    }

    /// Declares or protects a range in the table it belongs to.
    pub fn declare(&mut self, table: Table, start: u32, end: u32) {
        match table {
            Table::Coils => self.coils.declare(start, end),
            Table::DiscreteInputs => self.discrete_inputs.declare(start, end),
            Table::InputRegisters => self.input_registers.declare(start, end),
            Table::HoldingRegisters => self.holding_registers.declare(start, end),
        }
    }
}
