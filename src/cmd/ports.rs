//! `mbtool ports`: the serial ports of this machine and what each one is.

use std::io::Write;

use anyhow::Result;

use mbtool::cli::PortsArgs;
use mbtool::output::ports::write_ports;
use mbtool::settings::Settings;
use mbtool_core::transport::ports;

pub fn run(settings: &Settings, args: &PortsArgs) -> Result<u8> {
    let found = ports::list(&args.root);
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
