//! `mbtool ports` against a machine made by the test (sysfs as Linux 6 lays it out, with
//! a USB FTDI adapter, a CH340, an on-board UART, a UART slot with nothing in it and
//! virtual terminals) and against the real machine.

use std::os::unix::fs::symlink;
use std::path::Path;

use serde_json::{json, Value};

use crate::support::*;

fn write(root: &Path, path: &str, text: &str) {
    let path = root.join(path);
    std::fs::create_dir_all(path.parent().unwrap()).unwrap();
    std::fs::write(path, text).unwrap();
}

fn link(root: &Path, path: &str, target: &str) {
    let path = root.join(path);
    std::fs::create_dir_all(path.parent().unwrap()).unwrap();
    symlink(target, path).unwrap();
}

/// The tty `name` of the device folder `device` (under sys/devices), and its class link.
fn tty(root: &Path, name: &str, device: &str) {
    let class = format!("{device}/tty/{name}");
    write(root, &format!("{class}/dev"), "188:0\n");
    link(
        root,
        &format!("{class}/device"),
        &format!("../../../{}", last(device)),
    );
    let from_sys = &class["sys/".len()..];
    link(
        root,
        &format!("sys/class/tty/{name}"),
        &format!("../../{from_sys}"),
    );
}

fn last(path: &str) -> &str {
    path.rsplit('/').next().unwrap()
}

/// The link `driver` of `folder` to the driver `name` of `bus`.
fn driver(root: &Path, folder: &str, bus: &str, name: &str) {
    let ups = "../".repeat(folder.split('/').count() - 1);
    write(root, &format!("sys/bus/{bus}/drivers/{name}/uevent"), "");
    link(
        root,
        &format!("{folder}/driver"),
        &format!("{ups}bus/{bus}/drivers/{name}"),
    );
    link(
        root,
        &format!("{folder}/subsystem"),
        &format!("{ups}bus/{bus}"),
    );
}

fn usb_device(root: &Path, folder: &str, ids: (&str, &str), strings: &[(&str, &str)]) {
    write(root, &format!("{folder}/idVendor"), &format!("{}\n", ids.0));
    write(
        root,
        &format!("{folder}/idProduct"),
        &format!("{}\n", ids.1),
    );
    for (name, text) in strings {
        write(root, &format!("{folder}/{name}"), &format!("{text}\n"));
    }
}

fn fake_machine(root: &Path) {
    // An FTDI FT232R: the usb-serial port ttyUSB0 under interface 1-1:1.0.
    let usb = "sys/devices/pci0000:00/0000:00:14.0/usb1";
    usb_device(
        root,
        &format!("{usb}/1-1"),
        ("0403", "6001"),
        &[
            ("manufacturer", "FTDI"),
            ("product", "FT232R USB UART"),
            ("serial", "A50285BI"),
        ],
    );
    let ftdi = format!("{usb}/1-1/1-1:1.0/ttyUSB0");
    tty(root, "ttyUSB0", &ftdi);
    driver(root, &ftdi, "usb-serial", "ftdi_sio");
    // A CH340, which has no serial number.
    usb_device(
        root,
        &format!("{usb}/1-2"),
        ("1a86", "7523"),
        &[("product", "USB Serial")],
    );
    let ch340 = format!("{usb}/1-2/1-2:1.0/ttyUSB1");
    tty(root, "ttyUSB1", &ch340);
    driver(root, &ch340, "usb-serial", "ch341-uart");
    // The on-board 16550A (type 4), its tty under the serial core's port and controller.
    let pnp = "sys/devices/pnp0/00:05";
    driver(root, pnp, "pnp", "serial");
    let port = format!("{pnp}/00:05:0/00:05:0.0");
    driver(root, &format!("{pnp}/00:05:0"), "serial-base", "ctrl");
    driver(root, &port, "serial-base", "port");
    tty(root, "ttyS0", &port);
    write(root, &format!("{port}/tty/ttyS0/type"), "4\n");
    // A slot the 8250 driver keeps with no UART in it (type 0, unknown): not a port.
    let slot = "sys/devices/platform/serial8250/serial8250:0/serial8250:0.1";
    driver(root, slot, "serial-base", "port");
    tty(root, "ttyS1", slot);
    write(root, &format!("{slot}/tty/ttyS1/type"), "0\n");
    // Virtual terminals have no device behind them.
    for name in ["tty0", "ptmx", "console"] {
        write(
            root,
            &format!("sys/devices/virtual/tty/{name}/dev"),
            "4:0\n",
        );
        link(
            root,
            &format!("sys/class/tty/{name}"),
            &format!("../../devices/virtual/tty/{name}"),
        );
    }
    link(
        root,
        "dev/serial/by-id/usb-FTDI_FT232R_USB_UART_A50285BI-if00-port0",
        "../../ttyUSB0",
    );
    link(
        root,
        "dev/serial/by-id/usb-1a86_USB_Serial-if00-port0",
        "../../ttyUSB1",
    );
    // minicom has the CH340 open; cu left a lock file on the on-board port.
    write(root, "proc/4242/comm", "minicom\n");
    link(root, "proc/4242/fd/0", "/dev/pts/3");
    link(root, "proc/4242/fd/3", "/dev/ttyUSB1");
    write(root, "proc/4343/comm", "cu\n");
    write(root, "var/lock/LCK..ttyS0", "      4343\n");
    // A lock left by a process that is gone, and a FIFO where the CH340's serial number
    // would be (a copied tree can hold anything): neither is read as data.
    write(root, "run/lock/LCK..ttyUSB0", "99999\n");
    let fifo = root.join(format!("{usb}/1-2/serial"));
    let made = std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap();
    assert!(made.success());
}

#[test]
fn ports_lists_each_adapter_with_its_ids_driver_and_holder() {
    let dir = tempfile::tempdir().unwrap();
    fake_machine(dir.path());
    let output = mbtool()
        .args(["ports", "--json", "--root"])
        .arg(dir.path())
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(0));
    let rows: Vec<Value> = String::from_utf8(output.stdout)
        .unwrap()
        .lines()
        .map(|line| serde_json::from_str(line).unwrap())
        .collect();
    assert_eq!(
        rows,
        [
            json!({"device": "/dev/ttyS0", "by_id": null, "vid": null, "pid": null,
                "manufacturer": null, "product": null, "serial": null, "driver": "serial",
                "busy": [{"pid": 4343, "command": "cu"}]}),
            json!({"device": "/dev/ttyUSB0",
                "by_id": "/dev/serial/by-id/usb-FTDI_FT232R_USB_UART_A50285BI-if00-port0",
                "vid": "0403", "pid": "6001", "manufacturer": "FTDI",
                "product": "FT232R USB UART", "serial": "A50285BI", "driver": "ftdi_sio",
                "busy": []}),
            json!({"device": "/dev/ttyUSB1",
                "by_id": "/dev/serial/by-id/usb-1a86_USB_Serial-if00-port0",
                "vid": "1a86", "pid": "7523", "manufacturer": null, "product": "USB Serial",
                "serial": null, "driver": "ch341-uart",
                "busy": [{"pid": 4242, "command": "minicom"}]}),
        ]
    );
    // The table a person reads, and the bare names for a script's loop.
    let table = mbtool()
        .args(["ports", "--root"])
        .arg(dir.path())
        .output()
        .unwrap();
    let table = String::from_utf8(table.stdout).unwrap();
    let usb0 = table.lines().find(|l| l.contains("/dev/ttyUSB0")).unwrap();
    for cell in ["0403", "6001", "FTDI", "A50285BI", "ftdi_sio"] {
        assert!(usb0.contains(cell), "{cell} missing from {usb0}");
    }
    assert!(table.contains("minicom (4242)"), "{table}");
    let values = mbtool()
        .args(["ports", "-o", "values", "--root"])
        .arg(dir.path())
        .output()
        .unwrap();
    assert_eq!(
        String::from_utf8(values.stdout).unwrap(),
        "/dev/ttyS0\n/dev/ttyUSB0\n/dev/ttyUSB1\n"
    );
}

#[test]
fn ports_of_an_empty_machine_is_an_empty_table() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("sys")).unwrap();
    for format in ["csv", "json", "values"] {
        let output = mbtool()
            .args(["ports", "-o", format, "--root"])
            .arg(dir.path())
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(0));
        let expected = if format == "csv" {
            "device,by_id,vid,pid,manufacturer,product,serial,driver,busy\n"
        } else {
            ""
        };
        assert_eq!(String::from_utf8(output.stdout).unwrap(), expected);
    }
}

#[test]
fn ports_of_a_root_that_is_no_copy_is_refused() {
    let output = mbtool()
        .args(["ports", "--root", "/nonexistent"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&output.stderr),
        "mbtool: --root /nonexistent: no sys folder there; give the folder that holds the copied sys, dev and proc\n"
    );
}

#[test]
fn ports_of_this_machine_names_devices_that_are_there() {
    let output = mbtool().args(["ports", "-o", "values"]).output().unwrap();
    assert_eq!(output.status.code(), Some(0), "{output:?}");
    for device in String::from_utf8(output.stdout).unwrap().lines() {
        assert!(
            Path::new(device).exists() || !cfg!(target_os = "linux"),
            "{device} is not there"
        );
    }
    let table = mbtool().arg("ports").output().unwrap();
    assert_eq!(table.status.code(), Some(0));
    assert!(String::from_utf8(table.stdout).unwrap().contains("device"));
}

#[test]
fn a_port_this_test_holds_open_is_busy_with_its_pid() {
    let output = mbtool().args(["ports", "--json"]).output().unwrap();
    let devices: Vec<String> = String::from_utf8(output.stdout)
        .unwrap()
        .lines()
        .map(|line| {
            serde_json::from_str::<Value>(line).unwrap()["device"]
                .as_str()
                .unwrap()
                .to_string()
        })
        .collect();
    let opened = devices.iter().find_map(|device| {
        use std::os::unix::fs::OpenOptionsExt;
        std::fs::OpenOptions::new()
            .read(true)
            .custom_flags(0o4000) // O_NONBLOCK: no wait for carrier
            .open(device)
            .ok()
            .map(|file| (device.clone(), file))
    });
    let Some((device, _held)) = opened else {
        eprintln!("skipping: no serial port here that this user can open");
        return;
    };
    let output = mbtool().args(["ports", "--json"]).output().unwrap();
    let row: Value = String::from_utf8(output.stdout)
        .unwrap()
        .lines()
        .map(|line| serde_json::from_str::<Value>(line).unwrap())
        .find(|row| row["device"] == device.as_str())
        .unwrap();
    assert!(
        row["busy"]
            .as_array()
            .unwrap()
            .iter()
            .any(|holder| holder["pid"] == std::process::id()),
        "{row}"
    );
}

/// A port another process holds is refused with that process named, so that it can be
/// closed: here `mbtool serve`, on one end of a pseudo-terminal pair.
#[test]
fn a_busy_port_names_the_process_that_holds_it() {
    let Some(pair) = crate::support::PtyPair::new() else {
        return;
    };
    let (server, _) = crate::support::serve_pty(&pair, &[]);
    let held = pair.a.display().to_string();
    let output = mbtool()
        .args(["--port", &held, "read-holding", "17", "400108"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains(&format!("mbtool (pid {})", server.0.id()))
            && stderr.ends_with("close it there first\n"),
        "{stderr}"
    );
    assert_eq!(stderr.lines().count(), 1);
}
