//! Records of files in a backup: dumped with function 20 where asked, written back with
//! 21, and read back.

use super::{Difference, Place};
use crate::codec::file::{MAX_FILE_READ_REGISTERS, MAX_FILE_WRITE_BYTES, MAX_FILE_WRITE_REGISTERS};
use crate::codec::{ExceptionCode, FileRecords, FileSpan, Request};
use crate::master::plan::{file_read_requests, Plan};
use crate::master::run::RunError;
use crate::master::Master;

/// What a dump of file records read.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct FileDump {
    /// The runs of records read, with their values.
    pub records: Vec<FileRecords>,
    /// The runs of records the device refused with exception 02: it has none there.
    pub holes: Vec<FileSpan>,
    /// Records the device has but could not give (exception 03 or 04 for them alone),
    /// left out, with the exception.
    pub unreadable: Vec<(FileSpan, ExceptionCode)>,
    /// How many requests it took.
    pub requests: u64,
}

/// The records of `span`, read with one request a group, or `None` with the exception
/// the device refused them with.
fn read_span(
    master: &mut Master,
    slave: u8,
    span: FileSpan,
    requests: &mut u64,
) -> Result<Result<Vec<FileRecords>, ExceptionCode>, RunError> {
    let plan = Plan {
        slave,
        requests: file_read_requests(&[span], 1, None),
        reads: None,
        bits: None,
    };
    *requests += plan.requests.len() as u64;
    match master.read_files(&plan) {
        Ok(records) => Ok(Ok(records)),
        Err(RunError::Exception { code, .. }) => Ok(Err(code)),
        Err(error) => Err(error),
    }
}

/// Adds `span` to `spans`, joined with the last one where they meet.
fn add_span(spans: &mut Vec<FileSpan>, span: FileSpan) {
    match spans.last_mut() {
        Some(last)
            if last.file == span.file
                && u32::from(last.record) + u32::from(last.count) == u32::from(span.record) =>
        {
            last.count += span.count;
        }
        _ => spans.push(span),
    }
}

/// Reads `span`, split in halves where the device refuses it (02, 03 or 04), down to the
/// records it lacks (02) or cannot give (03, 04).
fn read_splitting(
    master: &mut Master,
    slave: u8,
    span: FileSpan,
    dump: &mut FileDump,
) -> Result<(), RunError> {
    match read_span(master, slave, span, &mut dump.requests)? {
        Ok(records) => {
            for run in records {
                match dump.records.last_mut() {
                    Some(last)
                        if last.file == run.file
                            && usize::from(last.record) + last.values.len()
                                == usize::from(run.record) =>
                    {
                        last.values.extend(run.values);
                    }
                    _ => dump.records.push(run),
                }
            }
        }
        Err(code)
            if !matches!(
                code,
                ExceptionCode::ILLEGAL_DATA_ADDRESS
                    | ExceptionCode::ILLEGAL_DATA_VALUE
                    | ExceptionCode::SERVER_DEVICE_FAILURE
            ) =>
        {
            return Err(RunError::Exception {
                slave,
                function: crate::codec::function::READ_FILE_RECORD,
                code,
            });
        }
        Err(ExceptionCode::ILLEGAL_DATA_ADDRESS) if span.count == 1 => {
            add_span(&mut dump.holes, span);
        }
        Err(code) if span.count == 1 => dump.unreadable.push((span, code)),
        Err(_) => {
            let first = span.count / 2;
            let halves = [
                FileSpan {
                    count: first,
                    ..span
                },
                FileSpan {
                    record: span.record + first,
                    count: span.count - first,
                    ..span
                },
            ];
            for half in halves {
                read_splitting(master, slave, half, dump)?;
            }
        }
    }
    Ok(())
}

/// Reads the records of `spans`, each in requests of at most `max` records (or as many
/// as an answer holds), a run the device refuses read in halves down to its holes.
pub fn dump_files(
    master: &mut Master,
    slave: u8,
    spans: &[FileSpan],
    max: Option<u16>,
) -> Result<FileDump, RunError> {
    let most = max.map_or(MAX_FILE_READ_REGISTERS, |max| {
        max.clamp(1, MAX_FILE_READ_REGISTERS)
    });
    let mut dump = FileDump::default();
    for span in spans {
        for at in (0..span.count).step_by(usize::from(most)) {
            let piece = FileSpan {
                record: span.record + at,
                count: most.min(span.count - at),
                ..*span
            };
            read_splitting(master, slave, piece, &mut dump)?;
        }
    }
    Ok(dump)
}

/// The requests that write `runs` of records back: as many groups a request as its 251
/// bytes hold, a run longer than one group holds cut in groups.
pub fn file_restore_requests(runs: &[FileRecords]) -> Vec<Request> {
    let most = usize::from(MAX_FILE_WRITE_REGISTERS);
    let groups = runs.iter().flat_map(|run| {
        run.values
            .chunks(most)
            .enumerate()
            .map(move |(i, chunk)| FileRecords {
                file: run.file,
                record: run.record + (i * most) as u16,
                values: chunk.to_vec(),
            })
    });
    let mut requests = Vec::new();
    let mut request: Vec<FileRecords> = Vec::new();
    let mut bytes = 0;
    for group in groups {
        let len = 7 + 2 * group.values.len();
        if !request.is_empty() && bytes + len > MAX_FILE_WRITE_BYTES {
            requests.push(Request::WriteFileRecord {
                groups: std::mem::take(&mut request),
            });
            bytes = 0;
        }
        bytes += len;
        request.push(group);
    }
    if !request.is_empty() {
        requests.push(Request::WriteFileRecord { groups: request });
    }
    requests
}

/// Reads `runs` back and lists the records that differ.
pub fn verify_files(
    master: &mut Master,
    slave: u8,
    runs: &[FileRecords],
) -> Result<Vec<Difference>, RunError> {
    let mut differences = Vec::new();
    let mut requests = 0;
    for run in runs {
        let span = FileSpan {
            file: run.file,
            record: run.record,
            count: run.values.len() as u16,
        };
        let found: Vec<u16> = read_span(master, slave, span, &mut requests)?
            .unwrap_or_default()
            .into_iter()
            .flat_map(|records| records.values)
            .collect();
        for (i, wanted) in run.values.iter().enumerate() {
            let found = found.get(i).copied();
            if found != Some(*wanted) {
                differences.push(Difference {
                    place: Place::Record {
                        file: run.file,
                        record: run.record + i as u16,
                    },
                    wanted: *wanted,
                    found,
                });
            }
        }
    }
    Ok(differences)
}
