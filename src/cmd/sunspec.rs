//! `mbtool sunspec SLAVE`: a SunSpec device's models read and shown, and written as a map.

use std::io::Write;

use anyhow::{anyhow, Result};

use mbtool::note;
use mbtool::output::sunspec::write_device;
use mbtool::output::{self, colour_wanted, plural};
use mbtool::settings::{job, Settings};
use mbtool_core::codec::function;
use mbtool_core::master::run::RunError;
use mbtool_core::model::address::{reference, Table};
use mbtool_core::model::map_writer::to_csv;
use mbtool_core::sunspec::walk::{read_device, SunSpecDevice};
use mbtool_core::sunspec::SunSpecError;

pub fn run(settings: &Settings, job: &job::Sunspec) -> Result<u8> {
    if let Some(path) = &job.map_out {
        // Found out before the device is read.
        super::shared::can_write(path).map_err(|e| {
            std::io::Error::new(e.kind(), format!("cannot write {}: {e}", path.display()))
        })?;
    }
    let (mut connection, slave) = super::shared::connect_to(settings, &job.slave)?;
    let read = read_device(&mut connection.master, slave, job.base);
    super::shared::tell_foreign(connection.master.foreign());
    let device = match read {
        Ok(device) => device,
        Err(SunSpecError::Run(error)) => return Err(connection.explain(error.into()).into()),
        Err(not_found @ SunSpecError::NotFound { .. }) => {
            return Err(anyhow!(
                "slave {slave}: {not_found}; give --base ADDRESS where the device's manual puts its SunSpec map"
            ))
        }
    };
    let mut out = output::stdout();
    write_device(
        &mut out,
        settings.output.format,
        slave,
        &device,
        colour_wanted(),
    )?;
    out.flush()?;
    note!(
        "SunS at {}: {}, read in {}",
        reference(Table::HoldingRegisters, device.base),
        plural(device.models.len(), "model"),
        plural(device.requests, "request")
    );
    let status = told_status(slave, &device);
    if let Some(path) = &job.map_out {
        let (text, points) = map_text(settings, slave, &device);
        super::shared::write_whole(path, text.as_bytes()).map_err(|e| {
            std::io::Error::new(e.kind(), format!("cannot write {}: {e}", path.display()))
        })?;
        note!("{} written to {}", plural(points, "point"), path.display());
    }
    Ok(status)
}

/// Every model read in part, and a chain cut short, told on stderr; the exit status they
/// make: the first refusal's exception, else 1 where points or models were lost, else 0.
fn told_status(slave: u8, device: &SunSpecDevice) -> u8 {
    let refusal = |code| {
        mbtool::error::run_exit_code(&RunError::Exception {
            slave,
            function: function::READ_HOLDING_REGISTERS,
            code,
        })
    };
    let mut status = 0;
    for model in device.models.iter().filter(|model| model.published) {
        let Some(problem) = &model.problem else {
            continue;
        };
        note!(
            "mbtool: model {} at {}: {problem}; the points it leaves out have no value",
            model.id,
            reference(Table::HoldingRegisters, model.address)
        );
        if status == 0 {
            status = model.refused.map_or(1, refusal);
        }
    }
    if let Some(cut) = &device.cut {
        note!("mbtool: {}", cut.reason);
        if status == 0 && cut.models_lost {
            status = cut.refused.map_or(1, refusal);
        }
    }
    status
}

/// The map of the points that have a value, and how many they are.
fn map_text(settings: &Settings, slave: u8, device: &SunSpecDevice) -> (String, usize) {
    let points: Vec<_> = device
        .models
        .iter()
        .flat_map(|model| &model.points)
        .filter(|point| point.value.is_ok())
        .filter_map(|point| point.map_point())
        .collect();
    let comment = [
        format!(
            "SunSpec map of slave {slave} on {}, read by mbtool sunspec; scale factors as read then",
            settings.connection.port.as_deref().unwrap_or("?")
        ),
        format!(
            "models: {}",
            device
                .models
                .iter()
                .map(|model| format!("{} {}", model.id, model.name))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    ];
    (to_csv(&comment, &points), points.len())
}
