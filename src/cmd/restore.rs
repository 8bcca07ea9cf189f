//! `mbtool restore SLAVE FILE`: a data file written back to a device, and read back.

use std::io::Write;
use std::sync::atomic::Ordering;

use anyhow::Result;

use mbtool::error::Error;
use mbtool::output::Format;
use mbtool::output::{
    self, backup::difference_text, backup::range_text, encode::write_frame, plural,
};
use mbtool::settings::{job, Settings};
use mbtool_core::codec::{Frame, Mode, Pdu};
use mbtool_core::master::backup::{file_restore_requests, restore_requests, verify, verify_files};
use mbtool_core::master::plan::parse_slave;
use mbtool_core::master::run::RunError;
use mbtool_core::master::MasterError;
use mbtool_core::slave::datafile;

pub fn run(settings: &Settings, job: &job::Restore) -> Result<u8> {
    let model = datafile::load(&job.file).map_err(Error::from)?;
    let file = job.file.display();
    let entries = datafile::entries(&model);
    for entry in entries.iter().filter(|e| !e.table.is_writable()) {
        mbtool::note!(
            "mbtool: {file}: {} skipped: {}s are read-only",
            range_text(entry.table, entry.address, entry.values.len() as u32),
            entry.table.name()
        );
    }
    let runs = model.files.runs();
    let queues = model.fifos.queues().count();
    if queues > 0 {
        mbtool::note!(
            "mbtool: {file}: {} skipped: Modbus has no function that writes a FIFO queue",
            plural(queues, "fifo line")
        );
    }
    let mut requests = restore_requests(&entries, settings.data.max_per_request);
    requests.extend(file_restore_requests(&runs));
    if requests.is_empty() {
        return Err(Error::usage(format!(
            "{file} holds no coils, holding registers or file records to write"
        ))
        .into());
    }
    if job.dry_run {
        // The frames, as encode would print them: no port is needed.
        let mode = super::shared::mode(settings);
        let slave = parse_slave(&job.slave, false, mode == Mode::Tcp).map_err(Error::from)?;
        let mut out = output::stdout();
        for (i, request) in requests.iter().enumerate() {
            let frame = Frame {
                mode,
                slave,
                transaction: (i as u16).wrapping_add(1),
                pdu: Pdu::Request(request.clone()),
            };
            let bytes = frame.encode().map_err(|e| Error::usage(e.to_string()))?;
            let function = request.function();
            write_frame(&mut out, Format::Table, mode, slave, function, &bytes)?;
        }
        out.flush()?;
        return Ok(0);
    }
    // File records (21) are resent after a lost answer only when asked, as by write-file.
    super::shared::refuse_unsafe_retries(settings, &requests)?;
    let (mut connection, slave) = super::shared::connect_to(settings, &job.slave)?;
    let stop = super::shared::stop_on_signal()?;
    connection.master.stop_on(stop.flag.clone());
    let master = &mut connection.master;
    let mut sent = 0;
    let outcome = requests
        .iter()
        .take_while(|_| !stop.flag.load(Ordering::SeqCst))
        .try_for_each(|request| {
            sent += 1;
            let answered = master.answer(slave, request).map(|_| ());
            super::shared::tell_switches(settings, master);
            super::shared::tell_after_requests(master);
            answered
        });
    if matches!(outcome, Err(RunError::Master(MasterError::Interrupted))) {
        // Stopped while a write waited for its answer: it may or may not have been done.
        mbtool::note!(
            "mbtool: restore interrupted while request {sent} of {} waited for its answer (it may or may not have been written): slave {slave} may hold part of {file}; run restore again to write it all",
            requests.len()
        );
        return Ok(stop.exit_status());
    }
    if outcome.is_ok() && sent < requests.len() {
        // Stopped between two writes: the device holds part of the file, and says so.
        mbtool::note!(
            "mbtool: restore interrupted after {} of {}: slave {slave} holds part of {file}; run restore again to write it all",
            plural(sent, "request"),
            requests.len()
        );
        return Ok(stop.exit_status());
    }
    let outcome = outcome
        .and_then(|()| verify(master, slave, &entries))
        .and_then(|mut differences| {
            differences.extend(verify_files(master, slave, &runs)?);
            Ok(differences)
        });
    if matches!(outcome, Err(RunError::Master(MasterError::Interrupted))) {
        mbtool::note!(
            "mbtool: restore interrupted while reading back: every value of {file} was written to slave {slave}, but not all were read back; run restore again to check them"
        );
        return Ok(stop.exit_status());
    }
    super::shared::tell_switches(settings, master);
    super::shared::tell_after_requests(master);
    let differences = outcome.map_err(|e| connection.explain(Error::from(e)))?;
    let written: usize = entries
        .iter()
        .filter(|e| e.table.is_writable())
        .map(|e| e.values.len())
        .sum::<usize>()
        + runs.iter().map(|run| run.values.len()).sum::<usize>();
    let mut out = output::stdout();
    for difference in &differences {
        writeln!(out, "{}", difference_text(difference))?;
    }
    out.flush()?;
    if differences.is_empty() {
        mbtool::note!(
            "mbtool: wrote {written} values to slave {slave} in {}; every one reads back as written",
            plural(requests.len(), "request")
        );
        Ok(0)
    } else {
        mbtool::note!(
            "mbtool: wrote {written} values to slave {slave} in {}; {} read back differently",
            plural(requests.len(), "request"),
            differences.len()
        );
        Ok(4)
    }
}
