//! `mbtool ports`: the serial ports of this machine and what each one is.

use std::io::Write;

use anyhow::Result;

use mbtool::error::Error;
use mbtool::output::ports::write_ports;
use mbtool::settings::{job, Settings};
use mbtool_core::transport::ports;

pub fn run(settings: &Settings, job: &job::Ports) -> Result<u8> {
    // A copy that is not there would read as a machine without ports.
    if job.root != std::path::Path::new("/") && !job.root.join("sys").is_dir() {
        return Err(Error::usage(format!(
            "--root {}: no sys folder there; give the folder that holds the copied sys, dev and proc",
            job.root.display()
        ))
        .into());
    }
    let found = ports::list(&job.root);
    let mut out = mbtool::output::stdout();
    write_ports(
        &mut out,
        settings.output.format,
        &found,
        settings.output.style.colour,
    )?;
    out.flush()?;
    Ok(0)
}
