//! How `ports` shows the serial ports: a table for people, one JSON line or CSV row per
//! port, or the device names alone for a script's loop.

use std::io::{self, Write};

use serde_json::json;

use super::{csv_field, new_table, Format};
use mbtool_core::transport::ports::{Holder, PortInfo};

const COLUMNS: [&str; 9] = [
    "device",
    "by_id",
    "vid",
    "pid",
    "manufacturer",
    "product",
    "serial",
    "driver",
    "busy",
];

/// A USB id as lsusb and the kernel write it: four hex digits.
fn usb_id(id: Option<u16>) -> Option<String> {
    id.map(|id| format!("{id:04x}"))
}

/// `minicom (1234)`, or the pid alone when its name cannot be read.
fn holder_text(holder: &Holder) -> String {
    match &holder.command {
        Some(command) => format!("{command} ({})", holder.pid),
        None => format!("pid {}", holder.pid),
    }
}

/// The port's fields in the order of [`COLUMNS`], absent ones as `None`.
fn fields(port: &PortInfo) -> [Option<String>; 9] {
    let busy = (!port.busy.is_empty()).then(|| {
        let holders: Vec<String> = port.busy.iter().map(holder_text).collect();
        holders.join(", ")
    });
    [
        Some(port.device.clone()),
        port.by_id.clone(),
        usb_id(port.vid),
        usb_id(port.pid),
        port.manufacturer.clone(),
        port.product.clone(),
        port.serial.clone(),
        port.driver.clone(),
        busy,
    ]
}

pub fn write_ports(
    out: &mut dyn Write,
    format: Format,
    ports: &[PortInfo],
    colour: bool,
) -> io::Result<()> {
    match format {
        Format::Values => {
            for port in ports {
                writeln!(out, "{}", port.device)?;
            }
        }
        Format::Json => {
            for port in ports {
                let [device, by_id, vid, pid, manufacturer, product, serial, driver, _] =
                    fields(port);
                let busy: Vec<_> = port
                    .busy
                    .iter()
                    .map(|holder| json!({"pid": holder.pid, "command": holder.command}))
                    .collect();
                let line = json!({
                    "device": device, "by_id": by_id, "vid": vid, "pid": pid,
                    "manufacturer": manufacturer, "product": product, "serial": serial,
                    "driver": driver, "busy": busy,
                });
                writeln!(out, "{line}")?;
            }
        }
        Format::Csv => {
            writeln!(out, "{}", COLUMNS.join(","))?;
            for port in ports {
                let row: Vec<String> = fields(port)
                    .iter()
                    .map(|field| csv_field(field.as_deref().unwrap_or("")))
                    .collect();
                writeln!(out, "{}", row.join(","))?;
            }
        }
        Format::Table => {
            let mut table = new_table(colour);
            table.set_header(COLUMNS.map(|name| name.replace('_', "-")));
            for port in ports {
                table.add_row(fields(port).map(|field| field.unwrap_or_else(|| "-".into())));
            }
            writeln!(out, "{table}")?;
        }
    }
    Ok(())
}
