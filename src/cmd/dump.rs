//! `mbtool dump SLAVE RANGE...`: a device's tables to a data file.

use std::io::Write;

use anyhow::{Context, Result};

use mbtool::error::Error;
use mbtool::output::{self, plural};
use mbtool::settings::{job, Settings};
use mbtool_core::codec::ExceptionCode;
use mbtool_core::master::backup::{self, Range};
use mbtool_core::master::plan::parse_file_span;
use mbtool_core::master::run::RunError;
use mbtool_core::model::address::{parse_reference_span, AddressError};
use mbtool_core::slave::datafile;

pub fn run(settings: &Settings, job: &job::Dump) -> Result<u8> {
    // Records of files are FILE:RECORD-RECORD; the rest are references.
    let (file_texts, table_texts): (Vec<&String>, Vec<&String>) =
        job.ranges.iter().partition(|text| text.contains(':'));
    let spans = file_texts
        .iter()
        .map(|text| parse_file_span(text))
        .collect::<Result<Vec<_>, _>>()
        .map_err(Error::from)?;
    let ranges = table_texts
        .iter()
        .map(|text| {
            parse_reference_span(text).map(|span| Range {
                table: span.table,
                address: span.address,
                count: span.count.unwrap_or(1),
            })
        })
        .collect::<Result<Vec<_>, AddressError>>()
        .map_err(Error::from)?;
    if let Some(path) = &settings.output.file {
        // Found out before the device is read, which may take minutes.
        super::shared::can_write(path).map_err(|e| {
            std::io::Error::new(e.kind(), format!("cannot write {}: {e}", path.display()))
        })?;
    }
    let (mut connection, slave) = super::shared::connect_to(settings, &job.slave)?;
    let stop = super::shared::stop_on_signal()?;
    connection.master.stop_on(stop.flag.clone());
    let started = std::time::Instant::now();
    let dump = backup::dump(
        &mut connection.master,
        slave,
        &ranges,
        settings.data.max_per_request,
        &stop.flag,
    );
    let files = match &dump {
        Ok(dump) if !dump.interrupted && !spans.is_empty() => Some(backup::dump_files(
            &mut connection.master,
            slave,
            &spans,
            settings.data.max_per_request,
        )),
        _ => None,
    };
    super::shared::tell_switches(settings, &mut connection.master);
    super::shared::tell_foreign(connection.master.foreign());
    let dump = dump.map_err(|e| connection.explain(Error::from(e)))?;
    let files = files
        .transpose()
        .map_err(|e| connection.explain(Error::from(e)))?
        .unwrap_or_default();
    if dump.interrupted {
        let values: usize = dump.entries.iter().map(|e| e.values.len()).sum();
        mbtool::note!(
            "mbtool: dump interrupted after reading {values} addresses of slave {slave} in {}; nothing was written, since a part of a device is no backup",
            plural(dump.requests as usize, "request")
        );
        return Ok(stop.exit_status());
    }
    if !dump.holes.is_empty() {
        let holes: Vec<String> = dump
            .holes
            .iter()
            .map(|hole| output::backup::range_text(hole.table, hole.address, hole.count))
            .collect();
        mbtool::note!(
            "mbtool: slave {slave} has no such addresses (exception 02), left out: {}",
            holes.join(", ")
        );
    }
    if !files.holes.is_empty() {
        let holes: Vec<String> = files
            .holes
            .iter()
            .map(output::backup::records_text)
            .collect();
        mbtool::note!(
            "mbtool: slave {slave} has no such records (exception 02), left out: {}",
            holes.join(", ")
        );
    }
    // Nothing at all exists there: that is the device's answer.
    if dump.entries.is_empty() && files.records.is_empty() {
        let function = match (dump.holes.first(), files.holes.first()) {
            (Some(hole), _) => Some(hole.table.read_function()),
            (None, Some(_)) => Some(mbtool_core::codec::function::READ_FILE_RECORD),
            (None, None) => None,
        };
        if let Some(function) = function {
            let refused = RunError::Exception {
                slave,
                function,
                code: ExceptionCode::ILLEGAL_DATA_ADDRESS,
            };
            return Err(Error::from(refused).into());
        }
    }
    let (place, _) = connection.connector.tried_on(connection.master.path());
    let text = format!(
        "# mbtool dump of slave {slave} {place}, {}\n{}{}",
        output::backup::utc_now(),
        datafile::render(&dump.entries),
        datafile::render_files(&files.records)
    );
    let addresses: usize = dump.entries.iter().map(|e| e.values.len()).sum();
    let records: usize = files.records.iter().map(|r| r.values.len()).sum();
    let values = match (addresses, records) {
        (addresses, 0) => plural(addresses, "address"),
        (0, records) => plural(records, "record"),
        (addresses, records) => format!(
            "{} and {}",
            plural(addresses, "address"),
            plural(records, "record")
        ),
    };
    let requests = dump.requests + files.requests;
    let target = match &settings.output.file {
        Some(path) => {
            super::shared::write_whole(path, text.as_bytes())
                .with_context(|| format!("cannot write {}", path.display()))?;
            path.display().to_string()
        }
        None => {
            let mut out = output::stdout();
            out.write_all(text.as_bytes())?;
            out.flush()?;
            "standard output".to_string()
        }
    };
    // Requests one after another: another master's write meanwhile falls between them.
    let not_at_once = match requests {
        0 | 1 => String::new(),
        _ => format!(
            " over {}, one after another: not a snapshot if another master wrote meanwhile",
            mbtool_core::input::duration::show(started.elapsed())
        ),
    };
    mbtool::note!(
        "mbtool: dumped {values} of slave {slave} to {target} in {}{not_at_once}",
        plural(requests as usize, "request")
    );
    // Records the device has and could not give are told the same way.
    if !files.unreadable.is_empty() {
        let told: Vec<String> = files
            .unreadable
            .iter()
            .map(|(span, code)| format!("{} ({code})", output::backup::records_text(span)))
            .collect();
        mbtool::note!(
            "mbtool: slave {slave} could not give {}: {}; they are left out of the dump",
            plural(told.len(), "record"),
            told.join(", ")
        );
    }
    // Addresses the device has and could not give are no holes: the dump lacks them, and
    // its status is the first one's exception.
    let first = match (dump.unreadable.first(), files.unreadable.first()) {
        (Some((range, code)), _) => (range.table.read_function(), *code),
        (None, Some((_, code))) => (mbtool_core::codec::function::READ_FILE_RECORD, *code),
        (None, None) => return Ok(0),
    };
    if dump.unreadable.is_empty() {
        let refused = RunError::Exception {
            slave,
            function: first.0,
            code: first.1,
        };
        return Ok(mbtool::error::run_exit_code(&refused));
    }
    let first = &first.1;
    let told: Vec<String> = dump
        .unreadable
        .iter()
        .map(|(range, code)| {
            format!(
                "{} ({code})",
                output::backup::range_text(range.table, range.address, range.count)
            )
        })
        .collect();
    mbtool::note!(
        "mbtool: slave {slave} could not give {}: {}; they are left out of the dump",
        plural(told.len(), "address"),
        told.join(", ")
    );
    let first = RunError::Exception {
        slave,
        function: dump.unreadable[0].0.table.read_function(),
        code: *first,
    };
    Ok(mbtool::error::run_exit_code(&first))
}
