//! Records of files in a backup: dumped with function 20 where asked, written back with
//! 21, and read back.

use super::{Difference, Place};
use crate::codec::file::MAX_FILE_WRITE_REGISTERS;
use crate::codec::{ExceptionCode, FileRecords, FileSpan, Request};
use crate::master::plan::{file_read_requests, Plan};
use crate::master::run::RunError;
use crate::master::Master;

/// What a dump of file records read.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct FileDump {
    /// The runs of records read, with their values.
    pub records: Vec<FileRecords>,
    /// The runs asked that the device refused with exception 02, left out whole.
    pub holes: Vec<FileSpan>,
    /// How many requests it took.
    pub requests: u64,
}

/// The records of `span`: `None` where the device refused them (exception 02).
fn read_span(
    master: &mut Master,
    slave: u8,
    span: FileSpan,
    requests: &mut u64,
) -> Result<Option<Vec<FileRecords>>, RunError> {
    let plan = Plan {
        slave,
        requests: file_read_requests(&[span]),
        reads: None,
        bits: None,
    };
    *requests += plan.requests.len() as u64;
    match master.read_files(&plan) {
        Ok(records) => Ok(Some(records)),
        Err(RunError::Exception { code, .. }) if code == ExceptionCode::ILLEGAL_DATA_ADDRESS => {
            Ok(None)
        }
        Err(error) => Err(error),
    }
}

/// Reads the records of `spans`, a run the device refuses left out whole.
pub fn dump_files(
    master: &mut Master,
    slave: u8,
    spans: &[FileSpan],
) -> Result<FileDump, RunError> {
    let mut dump = FileDump::default();
    for span in spans {
        match read_span(master, slave, *span, &mut dump.requests)? {
            Some(records) => dump.records.extend(records),
            None => dump.holes.push(*span),
        }
    }
    Ok(dump)
}

/// The requests that write `runs` of records back: a request a run, or as many as one
/// request's limit needs.
pub fn file_restore_requests(runs: &[FileRecords]) -> Vec<Request> {
    let most = usize::from(MAX_FILE_WRITE_REGISTERS);
    runs.iter()
        .flat_map(|run| {
            run.values
                .chunks(most)
                .enumerate()
                .map(move |(i, chunk)| Request::WriteFileRecord {
                    groups: vec![FileRecords {
                        file: run.file,
                        record: run.record + (i * most) as u16,
                        values: chunk.to_vec(),
                    }],
                })
        })
        .collect()
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
