//! File records (functions 20, 21) and FIFO queues (24): the words `read-file`,
//! `write-file` and `read-fifo` take, planned as requests within the specification's
//! limits.

use crate::codec::file::{
    read_answer_group_len, MAX_FILE_READ_BYTES, MAX_FILE_READ_REGISTERS, MAX_FILE_WRITE_REGISTERS,
    MAX_RECORD,
};
use crate::codec::{FileRecords, FileSpan, Request};
use crate::input::number::{parse_in_range, parse_int};
use crate::model::address::{parse_span, Access, AddressError, Table};

use super::{parse_registers, Plan, PlanError, PlanOptions, Result};

/// The most groups one Read File Record request holds: 7 bytes each in 245.
const MAX_GROUPS: usize = MAX_FILE_READ_BYTES / 7;

fn records(message: String) -> PlanError {
    PlanError::Records(message)
}

/// `FILE:RECORD`, as in `4:1`: a file 1-65535 and a record 0-9999.
fn parse_place(text: &str) -> Result<(u16, u16)> {
    let bad = || {
        records(format!(
            "'{text}' is no FILE:RECORD: give a file 1-65535 and a record 0-9999, as in 4:1"
        ))
    };
    let (file, record) = text.trim().split_once(':').ok_or_else(bad)?;
    let file = parse_int(file).map_err(|_| bad())?;
    let record = parse_int(record).map_err(|_| bad())?;
    if file == 0 {
        return Err(records(format!(
            "{text}: file 0 does not exist: files are numbered 1-65535"
        )));
    }
    let file = u16::try_from(file).map_err(|_| bad())?;
    if record < 0 {
        return Err(records(format!(
            "{text}: record {record} is no record: records are 0-{MAX_RECORD}"
        )));
    }
    if record > i128::from(MAX_RECORD) {
        return Err(records(format!(
            "{text}: record {record} is past {MAX_RECORD}, the last record of a file"
        )));
    }
    Ok((file, record as u16))
}

/// Checks that `count` records from `record` stay within the file.
fn check_last(text: &str, record: u16, count: usize) -> Result<()> {
    let last = usize::from(record) + count.max(1) - 1;
    if last > usize::from(MAX_RECORD) {
        return Err(records(format!(
            "{text} with {count} records runs to record {last}, past {MAX_RECORD}, the last of a file"
        )));
    }
    Ok(())
}

/// `read-file SLAVE FILE:RECORD COUNT [FILE:RECORD COUNT]...`: the groups, each cut
/// where one answer cannot hold it, put into as few requests as the limits allow.
pub(super) fn read_file_plan(slave: u8, words: &[String], options: PlanOptions) -> Result<Plan> {
    if words.is_empty() || words.len() % 2 != 0 {
        return Err(records(
            "give FILE:RECORD COUNT pairs, as in read-file 17 4:1 2 3:9 2".into(),
        ));
    }
    let width = options.value_type.width();
    let mut spans = Vec::new();
    for pair in words.chunks_exact(2) {
        let (file, record) = parse_place(&pair[0])?;
        let count =
            parse_in_range(&pair[1], 1, 10000, "COUNT").map_err(PlanError::Count)? as usize * width;
        check_last(&pair[0], record, count)?;
        spans.push(FileSpan {
            file,
            record,
            count: count as u16,
        });
    }
    if options
        .max_per_request
        .is_some_and(|max| usize::from(max) < width)
    {
        return Err(PlanError::MaxPerRequest(width as u16));
    }
    let requests = file_read_requests(&spans, width as u16, options.max_per_request);
    Ok(Plan {
        slave,
        requests,
        reads: None,
        bits: None,
    })
}

/// The requests that read `spans` of records: each cut where one answer cannot hold it
/// (or at `max` records), never inside a value of `unit` records, the groups put into as
/// few requests as the limits (and `max` records a request) allow, in order.
pub fn file_read_requests(spans: &[FileSpan], unit: u16, max: Option<u16>) -> Vec<Request> {
    let unit = unit.max(1);
    let limit = max.map_or(MAX_FILE_READ_REGISTERS, |max| {
        max.min(MAX_FILE_READ_REGISTERS)
    });
    // Whole values, and at least one.
    let most = (limit / unit * unit).max(unit);
    let groups = spans.iter().flat_map(|span| {
        (0..span.count)
            .step_by(usize::from(most))
            .map(move |at| FileSpan {
                file: span.file,
                record: span.record + at,
                count: most.min(span.count - at),
            })
    });
    let mut requests = Vec::new();
    let mut request: Vec<FileSpan> = Vec::new();
    let (mut answer, mut records) = (0, 0);
    for group in groups {
        let len = read_answer_group_len(group.count);
        let full = answer + len > MAX_FILE_READ_BYTES
            || request.len() == MAX_GROUPS
            || max.is_some_and(|max| records + group.count > max);
        if !request.is_empty() && full {
            requests.push(Request::ReadFileRecord {
                groups: std::mem::take(&mut request),
            });
            (answer, records) = (0, 0);
        }
        request.push(group);
        answer += len;
        records += group.count;
    }
    if !request.is_empty() {
        requests.push(Request::ReadFileRecord { groups: request });
    }
    requests
}

/// `FILE:RECORD` or `FILE:FIRST-LAST`, as `dump` takes records of a file: `4:0-99`.
pub fn parse_file_span(text: &str) -> Result<FileSpan> {
    let (place, last) = match text.split_once('-') {
        Some((place, last)) => (place, Some(last)),
        None => (text, None),
    };
    let (file, record) = parse_place(place)?;
    let count = match last {
        None => 1,
        Some(last) => {
            let last = parse_int(last)
                .ok()
                .filter(|last| (i128::from(record)..=i128::from(MAX_RECORD)).contains(last))
                .ok_or_else(|| {
                    records(format!(
                        "{text}: the last record is one of {record}-{MAX_RECORD}, as in 4:0-99"
                    ))
                })?;
            last as u16 - record + 1
        }
    };
    Ok(FileSpan {
        file,
        record,
        count,
    })
}

/// `write-file SLAVE FILE:RECORD VALUE...`: the values typed by `--type`, in requests of
/// at most as many records as one holds.
pub(super) fn write_file_plan(
    slave: u8,
    place: &str,
    values: &[String],
    options: PlanOptions,
) -> Result<Plan> {
    let (file, record) = parse_place(place)?;
    if values.is_empty() {
        return Err(PlanError::NoValues);
    }
    let registers = parse_registers(values, options)?;
    // An empty text is no value.
    if registers.is_empty() {
        return Err(PlanError::NoValues);
    }
    check_last(place, record, registers.len())?;
    // A request never cuts a value in two.
    let width = options.value_type.width();
    let most = usize::from(MAX_FILE_WRITE_REGISTERS) / width * width;
    let requests = registers
        .chunks(most)
        .enumerate()
        .map(|(i, chunk)| Request::WriteFileRecord {
            groups: vec![FileRecords {
                file,
                record: record + (i * most) as u16,
                values: chunk.to_vec(),
            }],
        })
        .collect();
    Ok(Plan {
        slave,
        requests,
        reads: None,
        bits: None,
    })
}

/// `read-fifo SLAVE REF`: the FIFO queue whose pointer is holding register REF.
pub(super) fn read_fifo_plan(slave: u8, reference: &str, options: PlanOptions) -> Result<Plan> {
    let span = parse_span(
        reference,
        Table::HoldingRegisters,
        Access::Read,
        options.numbering,
    )
    .map_err(|error| match error {
        AddressError::WrongTable { .. } => records(format!(
            "{reference}: a FIFO queue's pointer is a holding register, as in 401247"
        )),
        error => error.into(),
    })?;
    if span.count.is_some() {
        return Err(records(format!(
            "{reference}: a FIFO queue's pointer is one register, not a range"
        )));
    }
    Ok(Plan {
        slave,
        requests: vec![Request::ReadFifoQueue {
            address: span.address,
        }],
        reads: None,
        bits: None,
    })
}

#[cfg(test)]
mod tests {
    use super::super::tests::words;
    use super::*;

    #[test]
    fn groups_are_cut_and_packed_within_one_answer() {
        let options = PlanOptions::default();
        let plan = read_file_plan(17, &words("4:1 2 3:9 2"), options).unwrap();
        assert_eq!(plan.requests.len(), 1);
        // 300 records: 121 + 121 + 58, each group's answer within 245 bytes.
        let plan = read_file_plan(17, &words("7:0 300"), options).unwrap();
        let groups: Vec<Vec<u16>> = plan
            .requests
            .iter()
            .map(|r| match r {
                Request::ReadFileRecord { groups } => groups.iter().map(|g| g.count).collect(),
                _ => vec![],
            })
            .collect();
        assert_eq!(groups, [vec![121], vec![121], vec![58]]);
        for request in &plan.requests {
            let mut bytes = Vec::new();
            request.encode(&mut bytes).unwrap();
        }
        // Forty groups of one record: 35 fit one request (7 bytes each in 245).
        let many: Vec<String> = (0..40)
            .flat_map(|i| [format!("1:{i}"), "1".into()])
            .collect();
        let plan = read_file_plan(17, &many, options).unwrap();
        assert_eq!(plan.requests.len(), 2);
    }

    #[test]
    fn a_value_is_never_cut_between_requests_and_max_caps_each() {
        let f32s = PlanOptions {
            value_type: crate::model::values::ValueType::F32,
            ..PlanOptions::default()
        };
        let counts = |plan: Plan| -> Vec<Vec<u16>> {
            plan.requests
                .iter()
                .map(|r| match r {
                    Request::ReadFileRecord { groups } => groups.iter().map(|g| g.count).collect(),
                    _ => vec![],
                })
                .collect()
        };
        // 61 floats are 122 records: 120 and 2, not 121 and 1.
        let plan = read_file_plan(17, &words("5:0 61"), f32s).unwrap();
        assert_eq!(counts(plan), [vec![120], vec![2]]);
        // At most 10 records a request, groups given apart included.
        let ten = PlanOptions {
            max_per_request: Some(10),
            ..PlanOptions::default()
        };
        let plan = read_file_plan(17, &words("4:0 10 4:10 10 4:20 5 4:30 5"), ten).unwrap();
        assert_eq!(counts(plan), [vec![10], vec![10], vec![5, 5]]);
    }

    #[test]
    fn the_specification_s_limits_are_refused_in_words() {
        let options = PlanOptions::default();
        for (text, message) in [
            (
                "0:1 2",
                "0:1: file 0 does not exist: files are numbered 1-65535",
            ),
            (
                "4:10000 1",
                "4:10000: record 10000 is past 9999, the last record of a file",
            ),
            (
                "4:9999 2",
                "4:9999 with 2 records runs to record 10000, past 9999, the last of a file",
            ),
            (
                "4:1",
                "give FILE:RECORD COUNT pairs, as in read-file 17 4:1 2 3:9 2",
            ),
            (
                "4-1 2",
                "'4-1' is no FILE:RECORD: give a file 1-65535 and a record 0-9999, as in 4:1",
            ),
        ] {
            let error = read_file_plan(17, &words(text), options).unwrap_err();
            assert_eq!(error.to_string(), message);
        }
    }

    #[test]
    fn a_long_write_is_cut_between_values() {
        let options = PlanOptions {
            value_type: crate::model::values::ValueType::F32,
            ..PlanOptions::default()
        };
        let values: Vec<String> = (0..100).map(|i| i.to_string()).collect();
        let plan = write_file_plan(17, "2:0", &values, options).unwrap();
        let sizes: Vec<(u16, usize)> = plan
            .requests
            .iter()
            .map(|r| match r {
                Request::WriteFileRecord { groups } => (groups[0].record, groups[0].values.len()),
                _ => (0, 0),
            })
            .collect();
        assert_eq!(sizes, [(0, 122), (122, 78)]);
    }
}
