//! File records (functions 20, 21) and the FIFO queue (24): their groups and limits.
//!
//! A file holds records 0-9999, one register each; a request names records by file
//! (1-65535), first record and count, each group introduced by reference type 06.

use crate::codec::error::PduError;
use crate::codec::function::*;
use crate::codec::limits;

use super::wire::{Reader, Writer};

/// The reference type every file record group starts with.
pub const FILE_REFERENCE_TYPE: u8 = 0x06;
/// The highest record number of a file.
pub const MAX_RECORD: u16 = 9999;
/// The largest byte count of a Read File Record request and answer (0xF5).
pub const MAX_FILE_READ_BYTES: usize = 0xF5;
/// The largest byte count of a Write File Record request (0xFB).
pub const MAX_FILE_WRITE_BYTES: usize = 0xFB;
/// The most registers a FIFO queue answer carries, its count aside.
pub const MAX_FIFO_COUNT: u16 = 31;

/// Records of a file to read: `count` registers from `record` of `file`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FileSpan {
    /// The file, 1-65535.
    pub file: u16,
    /// The first record, 0-9999.
    pub record: u16,
    /// How many records (registers), at least 1.
    pub count: u16,
}

/// Records of a file with their values: a write, or its echo.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FileRecords {
    /// The file, 1-65535.
    pub file: u16,
    /// The first record, 0-9999.
    pub record: u16,
    /// The values, first record first; their count is the record length.
    pub values: Vec<u16>,
}

/// The bytes a group of a Read File Record answer takes: its length byte, the reference
/// type and the registers.
pub fn read_answer_group_len(count: u16) -> usize {
    2 + 2 * usize::from(count)
}

/// The record counts a Read File Record request (that reads) asks for, group by group.
pub(crate) fn counts_asked(request: &[u8]) -> impl Iterator<Item = u16> + Clone + '_ {
    // Function, byte count; then groups of seven bytes: type, file, record, count.
    request
        .get(2..)
        .unwrap_or_default()
        .chunks_exact(7)
        .map(|group| u16::from_be_bytes([group[5], group[6]]))
}

/// The records of each group of a Read File Record answer (that reads), group by group.
pub(crate) fn counts_answered(answer: &[u8]) -> impl Iterator<Item = usize> + Clone + '_ {
    // Function, byte count; then groups of a length byte, the type and the registers.
    let mut groups = answer.get(2..).unwrap_or_default();
    std::iter::from_fn(move || {
        let (&len, rest) = groups.split_first()?;
        groups = rest.get(usize::from(len)..).unwrap_or_default();
        Some(usize::from(len).saturating_sub(1) / 2)
    })
}

/// Why a group's file and records are no place in a file: a file 0, a record past 9999.
fn check_place(file: u16, record: u16, count: usize) -> Result<(), PduError> {
    if file == 0 {
        return Err(PduError::FileReference(
            "file 0 does not exist: files are numbered 1-65535".into(),
        ));
    }
    if count == 0 {
        return Err(PduError::FileReference(
            "a file record group needs a record length of at least 1".into(),
        ));
    }
    let last = usize::from(record) + count - 1;
    if last > usize::from(MAX_RECORD) {
        return Err(PduError::FileReference(format!(
            "records {record}-{last} of file {file} run past record {MAX_RECORD}"
        )));
    }
    Ok(())
}

fn check_byte_count(function: u8, bytes: usize, min: usize, max: usize) -> Result<u8, PduError> {
    match u8::try_from(bytes) {
        Ok(count) if (min..=max).contains(&bytes) => Ok(count),
        _ => Err(PduError::BadByteCount {
            function,
            byte_count: u8::try_from(bytes).unwrap_or(u8::MAX),
        }),
    }
}

/// A Read File Record request's groups.
pub(super) fn write_read_request(w: &mut Writer, groups: &[FileSpan]) -> Result<(), PduError> {
    let bytes = 7 * groups.len();
    w.u8(check_byte_count(
        READ_FILE_RECORD,
        bytes,
        7,
        MAX_FILE_READ_BYTES,
    )?);
    check_answer_len(groups.iter().map(|g| read_answer_group_len(g.count)).sum())?;
    for group in groups {
        check_place(group.file, group.record, usize::from(group.count))?;
        w.u8(FILE_REFERENCE_TYPE)
            .u16(group.file)
            .u16(group.record)
            .u16(group.count);
    }
    Ok(())
}

/// The records asked must fit one answer: `answer` is the bytes its groups would take.
fn check_answer_len(answer: usize) -> Result<(), PduError> {
    if answer > MAX_FILE_READ_BYTES {
        return Err(PduError::BadField(
            "the records asked would not fit one answer (245 bytes)",
        ));
    }
    Ok(())
}

/// Reads a group's reference type, which must be 06.
fn reference_type(r: &mut Reader) -> Result<(), PduError> {
    match r.u8()? {
        FILE_REFERENCE_TYPE => Ok(()),
        other => Err(PduError::FileReference(format!(
            "reference type {other:02X}: a file record group starts with reference type 06"
        ))),
    }
}

pub(super) fn read_read_request(r: &mut Reader) -> Result<Vec<FileSpan>, PduError> {
    let bytes = usize::from(r.u8()?);
    check_byte_count(READ_FILE_RECORD, bytes, 7, MAX_FILE_READ_BYTES)?;
    if bytes % 7 != 0 {
        return Err(PduError::BadByteCount {
            function: READ_FILE_RECORD,
            byte_count: bytes as u8,
        });
    }
    let mut groups = Vec::new();
    let mut answer = 0usize;
    for _ in 0..bytes / 7 {
        reference_type(r)?;
        let group = FileSpan {
            file: r.u16()?,
            record: r.u16()?,
            count: r.u16()?,
        };
        check_place(group.file, group.record, usize::from(group.count))?;
        answer += read_answer_group_len(group.count);
        if r.keeps() {
            groups.push(group);
        }
    }
    check_answer_len(answer)?;
    Ok(groups)
}

/// A Read File Record answer's groups.
pub(super) fn write_read_answer(w: &mut Writer, groups: &[Vec<u16>]) -> Result<(), PduError> {
    let bytes: usize = groups.iter().map(|g| 2 + 2 * g.len()).sum();
    w.u8(check_byte_count(
        READ_FILE_RECORD,
        bytes,
        4,
        MAX_FILE_READ_BYTES,
    )?);
    for group in groups {
        if group.is_empty() {
            return Err(PduError::FileReference(
                "a file record group of an answer holds at least one register".into(),
            ));
        }
        w.u8((1 + 2 * group.len()) as u8)
            .u8(FILE_REFERENCE_TYPE)
            .registers(group);
    }
    Ok(())
}

pub(super) fn read_read_answer(r: &mut Reader) -> Result<Vec<Vec<u16>>, PduError> {
    let bytes = usize::from(r.u8()?);
    check_byte_count(READ_FILE_RECORD, bytes, 4, MAX_FILE_READ_BYTES)?;
    let body = r.take(bytes)?;
    let mut inner = Reader::new_at(READ_FILE_RECORD, body, r.keeps());
    let mut groups = Vec::new();
    while !inner.at_end() {
        let len = usize::from(inner.u8()?);
        if len < 3 || len % 2 == 0 {
            return Err(PduError::FileReference(
                "a file record group of an answer is reference type 06 and whole registers".into(),
            ));
        }
        reference_type(&mut inner)?;
        let values = inner.registers((len - 1) / 2)?;
        if inner.keeps() {
            groups.push(values);
        }
    }
    Ok(groups)
}

/// A Write File Record request's (or answer's) groups.
pub(super) fn write_write_groups(w: &mut Writer, groups: &[FileRecords]) -> Result<(), PduError> {
    let bytes: usize = groups.iter().map(|g| 7 + 2 * g.values.len()).sum();
    w.u8(check_byte_count(
        WRITE_FILE_RECORD,
        bytes,
        9,
        MAX_FILE_WRITE_BYTES,
    )?);
    for group in groups {
        check_place(group.file, group.record, group.values.len())?;
        w.u8(FILE_REFERENCE_TYPE)
            .u16(group.file)
            .u16(group.record)
            .u16(group.values.len() as u16)
            .registers(&group.values);
    }
    Ok(())
}

pub(super) fn read_write_groups(r: &mut Reader) -> Result<Vec<FileRecords>, PduError> {
    let bytes = usize::from(r.u8()?);
    check_byte_count(WRITE_FILE_RECORD, bytes, 9, MAX_FILE_WRITE_BYTES)?;
    let body = r.take(bytes)?;
    let mut inner = Reader::new_at(WRITE_FILE_RECORD, body, r.keeps());
    let mut groups = Vec::new();
    while !inner.at_end() {
        reference_type(&mut inner)?;
        let (file, record, count) = (inner.u16()?, inner.u16()?, inner.u16()?);
        check_place(file, record, usize::from(count))?;
        let values = inner.registers(usize::from(count))?;
        if inner.keeps() {
            groups.push(FileRecords {
                file,
                record,
                values,
            });
        }
    }
    Ok(groups)
}

/// A FIFO queue answer: its byte count, its count and the registers.
pub(super) fn write_fifo_answer(w: &mut Writer, values: &[u16]) -> Result<(), PduError> {
    let count = u16::try_from(values.len())
        .ok()
        .filter(|count| *count <= MAX_FIFO_COUNT)
        .ok_or(PduError::BadField(
            "a FIFO queue answer carries at most 31 registers",
        ))?;
    w.u16(2 + 2 * count).u16(count).registers(values);
    Ok(())
}

pub(super) fn read_fifo_answer(r: &mut Reader) -> Result<Vec<u16>, PduError> {
    let (bytes, count) = (r.u16()?, r.u16()?);
    if count > MAX_FIFO_COUNT {
        return Err(PduError::BadField(
            "a FIFO queue answer carries at most 31 registers",
        ));
    }
    if usize::from(bytes) != 2 + 2 * usize::from(count) {
        return Err(PduError::ByteCountMismatch {
            byte_count: u8::try_from(bytes).unwrap_or(u8::MAX),
            quantity: count,
            expected: 2 + 2 * usize::from(count),
        });
    }
    r.registers(usize::from(count))
}

/// The most registers one Read File Record answer holds in one group.
pub const MAX_FILE_READ_REGISTERS: u16 = ((MAX_FILE_READ_BYTES - 2) / 2) as u16;
/// The most registers one Write File Record request carries in one group.
pub const MAX_FILE_WRITE_REGISTERS: u16 = ((MAX_FILE_WRITE_BYTES - 7) / 2) as u16;

const _: () = assert!(MAX_FILE_WRITE_BYTES + 2 <= limits::MAX_PDU);
