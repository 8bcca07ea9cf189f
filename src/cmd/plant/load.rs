//! A plant's files read: its devices with their points and how each is reached, or every
//! fault of the files at once.

use std::path::Path;
use std::time::Duration;

use mbtool::connection::{Connector, Role};
use mbtool::error::Error;
use mbtool::settings::{ConnectionSettings, Settings};
use mbtool_core::model::map::{Point, RegisterMap};
use mbtool_core::model::map_file;
use mbtool_core::model::plant::{self, PlantDevice, Points};

/// A device, ready to poll.
pub(super) struct Device {
    /// The plant file it is in.
    pub file: String,
    pub plant: PlantDevice,
    pub points: Vec<Point>,
    pub connector: Connector,
}

/// The devices of every plant file with their maps, or every fault of them at once.
pub(super) fn load(
    settings: &Settings,
    files: &[std::path::PathBuf],
) -> Result<Vec<Device>, Error> {
    let mut faults: Vec<String> = Vec::new();
    let mut devices: Vec<Device> = Vec::new();
    // The names of the devices of the files read before, faulty ones too, with their file
    // and line: a name is the plant's once.
    let mut names: Vec<(String, String, usize)> = Vec::new();
    let mut read: Vec<std::path::PathBuf> = Vec::new();
    for file in files {
        let name = file.display().to_string();
        let same = std::fs::canonicalize(file).unwrap_or_else(|_| file.clone());
        if read.contains(&same) {
            faults.push(format!("{name} is given twice: give each plant file once"));
            continue;
        }
        read.push(same);
        // This file's devices with faults, by name and line.
        let mut unread: Vec<(String, usize)> = Vec::new();
        let text = match std::fs::read_to_string(file) {
            Ok(text) => text,
            Err(e) => {
                faults.push(format!("cannot read {name}: {e}"));
                continue;
            }
        };
        let folder = file.parent().unwrap_or(Path::new("."));
        let found: Vec<(PlantDevice, Result<Vec<Point>, String>)> = if is_plant(&name, &text) {
            let parsed = plant::parse_all(&name, &text);
            if let Err(e) = parsed.faults {
                faults.extend(e.to_string().lines().map(String::from));
            }
            unread.extend(parsed.unread.iter().map(|u| (u.name.clone(), u.line)));
            for unread in &parsed.unread {
                if let Some((port, line)) = &unread.port {
                    if let Err(e) = mbtool_core::transport::Endpoint::parse(port) {
                        faults.push(format!("{name}:{line}: {}: {e}", unread.name));
                    }
                }
                if let Some((map, line)) = &unread.map {
                    if let Err(e) = map_file::load(&folder.join(map)) {
                        faults.extend(e.to_string().lines().map(|e| format!("{name}:{line}: {e}")));
                    }
                }
            }
            parsed
                .devices
                .into_iter()
                .map(|device| {
                    let points = match &device.points {
                        Points::Map(map) => map_file::load(&folder.join(map))
                            .map(|map| map.points)
                            .map_err(|e| e.to_string()),
                        Points::Given(points) => Ok(points.clone()),
                    };
                    (device, points)
                })
                .collect()
        } else {
            // A Home Assistant configuration as it stands: its hubs are the devices.
            match map_file::load(file) {
                Ok(map) if map.hubs.is_empty() => {
                    faults.push(format!(
                        "{name} is a register map, not a plant: give a file of devices: (or a Home Assistant configuration with hubs), the map as a device's map:"
                    ));
                    continue;
                }
                Ok(map) => hub_devices(&name, &map, &mut faults),
                Err(e) => {
                    faults.extend(e.to_string().lines().map(String::from));
                    continue;
                }
            }
        };
        let taken = |device: &str, line: usize| {
            let (_, file, first) = names.iter().find(|(known, _, _)| known == device)?;
            Some(format!(
                "{name}:{line}: the name '{device}' is taken already, by a device of {file}:{first}"
            ))
        };
        faults.extend(
            unread
                .iter()
                .filter_map(|(device, line)| taken(device, *line)),
        );
        let mut here: Vec<(String, String, usize)> = unread
            .iter()
            .map(|(device, line)| (device.clone(), name.clone(), *line))
            .collect();
        for (device, points) in found {
            here.push((device.name.clone(), name.clone(), device.line));
            if let Some(said) = taken(&device.name, device.line) {
                faults.push(said);
                continue;
            }
            let connection = ConnectionSettings {
                port: None,
                ..settings.connection.clone()
            }
            .with_map(Some(&device.connection));
            let connector = Connector::new(&connection, Role::Master);
            let at = format!("{name}:{}: {}", device.line, device.name);
            match (points, connector) {
                (Ok(points), Ok(connector)) => devices.push(Device {
                    file: name.clone(),
                    plant: device,
                    points,
                    connector,
                }),
                (points, connector) => {
                    if let Err(e) = points {
                        faults.push(format!("{at}: {e}"));
                    }
                    if let Err(e) = connector {
                        faults.push(format!("{at}: {e}"));
                    }
                }
            }
        }
        names.extend(here);
    }
    faults.extend(lines_disagree(&devices));
    if faults.is_empty() && devices.is_empty() {
        faults.push("the plant has no device to poll".to_string());
    }
    match faults.is_empty() {
        true => Ok(devices),
        false => Err(Error::Faults(faults)),
    }
}

/// The devices of one serial line that give it other settings than the first of them:
/// one port is one line, at one speed and framing.
fn lines_disagree(devices: &[Device]) -> Vec<String> {
    use mbtool_core::input::choice::Choice;
    use mbtool_core::transport::Endpoint;
    let mut faults = Vec::new();
    for (index, device) in devices.iter().enumerate() {
        let Endpoint::Serial(port) = &device.connector.endpoint else {
            continue;
        };
        let first = devices[..index]
            .iter()
            .find(|other| other.connector.endpoint == device.connector.endpoint);
        let Some(first) = first else { continue };
        let said = |d: &Device| {
            let line = d.connector.line();
            format!(
                "{} {} baud, parity {}, {} data bits, {} stop bits",
                d.connector.mode,
                line.baud,
                line.parity.name(),
                line.data_bits,
                line.stop_bits
            )
        };
        if (device.connector.line(), device.connector.mode)
            != (first.connector.line(), first.connector.mode)
        {
            faults.push(format!(
                "{}:{}: {}: {port} is {} for {} (line {}), and {} here: give the devices of one line the same mode, baud, parity, data_bits and stop_bits",
                device.file,
                device.plant.line,
                device.plant.name,
                said(first),
                first.plant.name,
                first.plant.line,
                said(device),
            ));
        }
    }
    faults
}

/// Whether a file is mbtool's own plant form: TOML, or YAML with a `devices:` key.
fn is_plant(file: &str, text: &str) -> bool {
    // An empty file is an empty plant, told as such.
    let empty = text.lines().all(|line| {
        let line = line.trim();
        line.is_empty() || line.starts_with('#')
    });
    empty || plant::is_toml(file) || text.lines().any(|line| line.starts_with("devices:"))
}

/// How often Home Assistant reads an entity whose `scan_interval` is not given.
const HOME_ASSISTANT_RATE: Duration = Duration::from_secs(15);

/// The devices of a Home Assistant configuration: each hub's points by slave and by rate
/// (`scan_interval`, 15 s where not given), named after the hub (`meter`, `meter/2`,
/// `meter/2/5s`); an entity Home Assistant does not poll (`scan_interval: 0`) is left out.
fn hub_devices(
    file: &str,
    map: &RegisterMap,
    faults: &mut Vec<String>,
) -> Vec<(PlantDevice, Result<Vec<Point>, String>)> {
    let mut found = Vec::new();
    for hub in &map.hubs {
        let place = match &hub.place {
            Ok(place) => place,
            Err(why) => {
                faults.push(format!("{file}: hub {}: {why}", hub.name));
                continue;
            }
        };
        let mut groups: Vec<((u8, Duration), Vec<Point>)> = Vec::new();
        for (index, every) in &hub.points {
            let every = every.unwrap_or(HOME_ASSISTANT_RATE);
            if every.is_zero() {
                continue;
            }
            let point = &map.points[*index];
            let slave = point.slave.or(map.default_slave).unwrap_or(1);
            match groups.iter_mut().find(|(key, _)| *key == (slave, every)) {
                Some((_, points)) => points.push(point.clone()),
                None => groups.push(((slave, every), vec![point.clone()])),
            }
        }
        let slaves = {
            let mut slaves: Vec<u8> = groups.iter().map(|((slave, _), _)| *slave).collect();
            slaves.sort_unstable();
            slaves.dedup();
            slaves.len()
        };
        for ((slave, every), points) in &groups {
            let rates = groups.iter().filter(|((s, _), _)| s == slave).count();
            let name = match (slaves, rates) {
                (1, 1) => hub.name.clone(),
                (_, 1) => format!("{}/{slave}", hub.name),
                _ => format!("{}/{slave}/{}s", hub.name, every.as_secs()),
            };
            let device = PlantDevice {
                name,
                connection: place.clone(),
                slave: *slave,
                points: Points::Given(points.clone()),
                every: *every,
                line: points.first().map_or(1, |point| point.line),
            };
            found.push((device, Ok(points.clone())));
        }
    }
    found
}
