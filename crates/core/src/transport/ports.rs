//! The serial ports of this machine and what each one is: on Linux read from sysfs (the
//! USB device above each tty, its driver), `/dev/serial/by-id` and `/proc` (who has it
//! open), all under a root that is `/` except for a copy of those trees; elsewhere what
//! the serialport crate reports.

use std::path::Path;

/// One serial port.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct PortInfo {
    /// The name to open: `/dev/ttyUSB0`, `COM3`.
    pub device: String,
    /// Its stable name under `/dev/serial/by-id`, which survives replugging.
    pub by_id: Option<String>,
    /// The USB vendor id of the adapter (0403 is FTDI).
    pub vid: Option<u16>,
    /// The USB product id of the adapter.
    pub pid: Option<u16>,
    /// The maker's name, as the adapter tells it.
    pub manufacturer: Option<String>,
    /// The adapter's product name, as it tells it.
    pub product: Option<String>,
    /// The adapter's serial number, which tells two adapters of one model apart.
    pub serial: Option<String>,
    /// The kernel driver that runs it (`ftdi_sio`, `ch341-uart`, `cdc_acm`, `serial`).
    pub driver: Option<String>,
    /// The processes that have it open, as far as the system lets this user see.
    pub busy: Vec<Holder>,
}

/// A process that has a port open.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Holder {
    /// Its process id.
    pub pid: u32,
    /// Its command name, when it can be read.
    pub command: Option<String>,
}

/// The serial ports under `root` (`/` for this machine), sorted by device name with
/// numbers in order (`ttyS2` before `ttyS10`). A tree that cannot be read has no ports.
#[cfg(target_os = "linux")]
pub fn list(root: &Path) -> Vec<PortInfo> {
    let mut ports = described(root);
    let by_id = stable_names(root);
    let holders = holders(root);
    for port in &mut ports {
        let name = port.device.trim_start_matches("/dev/");
        port.by_id = by_id
            .iter()
            .find(|(_, target)| target == name)
            .map(|(link, _)| format!("/dev/serial/by-id/{link}"));
        port.busy = holders
            .iter()
            .filter(|(_, device)| *device == port.device)
            .map(|(holder, _)| holder.clone())
            .collect();
    }
    ports
}

/// Every file that every process whose descriptors this user may read has open, and that
/// `keep` takes (by the target of its descriptor: `/dev/ttyUSB0`, `socket:[1234]`), each
/// once per process; this process's own left out.
#[cfg(target_os = "linux")]
fn open_files(root: &Path, keep: impl Fn(&str) -> bool) -> Vec<(Holder, String)> {
    let mut found = Vec::new();
    let own = std::process::id();
    let processes = std::fs::read_dir(root.join("proc"))
        .into_iter()
        .flatten()
        .flatten();
    for process in processes {
        let Some(pid) = process
            .file_name()
            .to_str()
            .and_then(|n| n.parse::<u32>().ok())
        else {
            continue;
        };
        if pid == own {
            continue;
        }
        let Ok(fds) = std::fs::read_dir(process.path().join("fd")) else {
            continue;
        };
        let mut files: Vec<String> = fds
            .flatten()
            .filter_map(|fd| std::fs::read_link(fd.path()).ok())
            .filter_map(|target| target.to_str().map(str::to_string))
            .filter(|target| keep(target))
            .collect();
        files.sort();
        files.dedup();
        let command = read_text(&process.path().join("comm"));
        for file in files {
            found.push((
                Holder {
                    pid,
                    command: command.clone(),
                },
                file,
            ));
        }
    }
    found
}

/// The processes listening on TCP port `port` (any address), as far as this user may see:
/// the sockets of `/proc/net/tcp` and `tcp6` in state LISTEN, and who holds them.
#[cfg(target_os = "linux")]
pub fn listeners_of(root: &Path, port: u16) -> Vec<Holder> {
    let mut sockets = Vec::new();
    for table in ["proc/net/tcp", "proc/net/tcp6"] {
        let text = std::fs::read_to_string(root.join(table)).unwrap_or_default();
        for line in text.lines().skip(1) {
            let fields: Vec<&str> = line.split_whitespace().collect();
            let (Some(local), Some(state), Some(inode)) =
                (fields.get(1), fields.get(3), fields.get(9))
            else {
                continue;
            };
            let listening = *state == "0A";
            let on_port = local
                .rsplit_once(':')
                .and_then(|(_, hex)| u16::from_str_radix(hex, 16).ok())
                == Some(port);
            if listening && on_port {
                sockets.push(format!("socket:[{inode}]"));
            }
        }
    }
    if sockets.is_empty() {
        return Vec::new();
    }
    let mut holders: Vec<Holder> = open_files(root, |target| sockets.iter().any(|s| s == target))
        .into_iter()
        .map(|(holder, _)| holder)
        .collect();
    holders.dedup();
    holders
}

/// Who listens on a port, where the system does not tell.
#[cfg(not(target_os = "linux"))]
pub fn listeners_of(_root: &Path, _port: u16) -> Vec<Holder> {
    Vec::new()
}

/// The processes that have the serial port at `path` open (a link such as
/// `/dev/serial/by-id/...` followed to its device), as far as this user may see.
#[cfg(target_os = "linux")]
pub fn holders_of(root: &Path, path: &str) -> Vec<Holder> {
    let device = std::fs::canonicalize(path)
        .ok()
        .and_then(|device| device.to_str().map(str::to_string))
        .unwrap_or_else(|| path.to_string());
    holders(root)
        .into_iter()
        .filter(|(_, held)| *held == device)
        .map(|(holder, _)| holder)
        .collect()
}

/// The processes that have a port open, where the system does not tell.
#[cfg(not(target_os = "linux"))]
pub fn holders_of(_root: &Path, _path: &str) -> Vec<Holder> {
    Vec::new()
}

/// The device names of the serial ports under `root`, as [`list`] orders them, without
/// the look through every process that finds who holds them.
#[cfg(target_os = "linux")]
pub fn devices(root: &Path) -> Vec<String> {
    described(root)
        .into_iter()
        .map(|port| port.device)
        .collect()
}

/// Every serial port sysfs describes under `root`, sorted.
#[cfg(target_os = "linux")]
fn described(root: &Path) -> Vec<PortInfo> {
    let Ok(entries) = std::fs::read_dir(root.join("sys/class/tty")) else {
        return Vec::new();
    };
    let mut ports: Vec<PortInfo> = entries
        .flatten()
        .filter_map(|entry| describe(&entry.path(), &entry.file_name().to_string_lossy()))
        .collect();
    ports.sort_by(|a, b| natural_key(&a.device).cmp(&natural_key(&b.device)));
    ports
}

/// What sysfs says of the tty `name` at `class` (`/sys/class/tty/NAME`), or `None` for a
/// tty that is no serial port: a virtual terminal or pty (no device behind it), or a
/// UART slot that the 8250 driver reserves with no UART in it (its type 0, unknown).
#[cfg(target_os = "linux")]
fn describe(class: &Path, name: &str) -> Option<PortInfo> {
    let device = std::fs::canonicalize(class.join("device")).ok()?;
    if read_text(&class.join("type")).as_deref() == Some("0") {
        return None;
    }
    // Since Linux 6.5 a UART's tty hangs under two devices of the serial core (the
    // `serial-base` bus, drivers `port` and `ctrl`); the driver that runs it is above.
    let driver = device
        .ancestors()
        .take(4)
        .find(|folder| link_name(&folder.join("subsystem")).as_deref() != Some("serial-base"))
        .and_then(|folder| link_name(&folder.join("driver")));
    let mut port = PortInfo {
        device: format!("/dev/{name}"),
        driver,
        ..PortInfo::default()
    };
    // The USB device is the first folder above the tty's that has a vendor id: the
    // interface (`1-1:1.0`) for most drivers, one more up for the usb-serial ones.
    if let Some(usb) = device
        .ancestors()
        .take(5)
        .find(|folder| folder.join("idVendor").exists())
    {
        port.vid = read_hex(&usb.join("idVendor"));
        port.pid = read_hex(&usb.join("idProduct"));
        port.manufacturer = read_text(&usb.join("manufacturer"));
        port.product = read_text(&usb.join("product"));
        port.serial = read_text(&usb.join("serial"));
    }
    Some(port)
}

/// The links of `/dev/serial/by-id`, each with the tty it names (`ttyUSB0`).
#[cfg(target_os = "linux")]
fn stable_names(root: &Path) -> Vec<(String, String)> {
    let Ok(entries) = std::fs::read_dir(root.join("dev/serial/by-id")) else {
        return Vec::new();
    };
    let mut names: Vec<(String, String)> = entries
        .flatten()
        .filter_map(|entry| {
            let tty = link_name(&entry.path())?;
            Some((entry.file_name().to_string_lossy().into_owned(), tty))
        })
        .collect();
    names.sort();
    names
}

/// Every open file under `/dev/` of every process whose descriptors this user may read
/// (all of them for root, its own otherwise), and the processes that hold a UUCP lock
/// file (`/var/lock/LCK..ttyUSB0`, as minicom and many older tools leave).
#[cfg(target_os = "linux")]
fn holders(root: &Path) -> Vec<(Holder, String)> {
    let mut found = open_files(root, |target| {
        target.starts_with("/dev/tty") || target.starts_with("/dev/pts/")
    });
    for folder in ["var/lock", "run/lock"] {
        let locks = std::fs::read_dir(root.join(folder))
            .into_iter()
            .flatten()
            .flatten();
        for lock in locks {
            let name = lock.file_name().to_string_lossy().into_owned();
            let Some(tty) = name.strip_prefix("LCK..") else {
                continue;
            };
            let Some(pid) = read_text(&lock.path()).and_then(|text| text.parse::<u32>().ok())
            else {
                continue;
            };
            let device = format!("/dev/{tty}");
            // A lock left by a process that is gone holds nothing.
            let alive = root.join(format!("proc/{pid}")).is_dir();
            let known = found
                .iter()
                .any(|(holder, held)| holder.pid == pid && *held == device);
            if alive && !known {
                let command = read_text(&root.join(format!("proc/{pid}/comm")));
                found.push((Holder { pid, command }, device));
            }
        }
    }
    found
}

/// The last part of where the link at `path` points: a driver's or a bus's name.
#[cfg(target_os = "linux")]
fn link_name(path: &Path) -> Option<String> {
    let target = std::fs::read_link(path).ok()?;
    Some(target.file_name()?.to_string_lossy().into_owned())
}

/// A sysfs attribute's text, trimmed, control characters as spaces; `None` when it is
/// absent, empty or no regular file. Read up to a page, which is all sysfs gives: a copied
/// tree with a huge file or a FIFO in it costs no more than that.
#[cfg(target_os = "linux")]
fn read_text(path: &Path) -> Option<String> {
    use std::io::Read;
    if !std::fs::metadata(path).ok()?.is_file() {
        return None;
    }
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .ok()?
        .take(4096)
        .read_to_end(&mut bytes)
        .ok()?;
    let text: String = String::from_utf8_lossy(&bytes)
        .trim()
        .chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .collect();
    (!text.is_empty()).then_some(text)
}

#[cfg(target_os = "linux")]
fn read_hex(path: &Path) -> Option<u16> {
    u16::from_str_radix(&read_text(path)?, 16).ok()
}

/// The device names of the serial ports, as [`list`] orders them.
#[cfg(not(target_os = "linux"))]
pub fn devices(root: &Path) -> Vec<String> {
    list(root).into_iter().map(|port| port.device).collect()
}

/// What serialport reports, where there is no sysfs to read.
#[cfg(not(target_os = "linux"))]
pub fn list(_root: &Path) -> Vec<PortInfo> {
    let mut ports: Vec<PortInfo> = serialport::available_ports()
        .unwrap_or_default()
        .into_iter()
        .map(|port| {
            let mut info = PortInfo {
                device: port.port_name,
                ..PortInfo::default()
            };
            if let serialport::SerialPortType::UsbPort(usb) = port.port_type {
                info.vid = Some(usb.vid);
                info.pid = Some(usb.pid);
                info.manufacturer = usb.manufacturer;
                info.product = usb.product;
                info.serial = usb.serial_number;
            }
            info
        })
        .collect();
    ports.sort_by(|a, b| natural_key(&a.device).cmp(&natural_key(&b.device)));
    ports
}

/// `ttyUSB10` as (`ttyUSB`, 10), so that it sorts after `ttyUSB9`.
fn natural_key(device: &str) -> (&str, u64, &str) {
    let stem = device.trim_end_matches(|c: char| c.is_ascii_digit());
    let number = device[stem.len()..].parse().unwrap_or(0);
    (stem, number, device)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_sort_as_numbers() {
        let mut names = [
            "/dev/ttyUSB10",
            "/dev/ttyS1",
            "/dev/ttyUSB9",
            "/dev/ttyACM0",
        ];
        names.sort_by(|a, b| natural_key(a).cmp(&natural_key(b)));
        assert_eq!(
            names,
            [
                "/dev/ttyACM0",
                "/dev/ttyS1",
                "/dev/ttyUSB9",
                "/dev/ttyUSB10"
            ]
        );
    }
}
