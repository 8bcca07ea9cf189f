//! A plant file: the devices `mbtool poll` keeps read, each a port, a slave, a register
//! map and a rate. Every fault of the file is told at once, each with its line, and
//! nothing is polled until the whole file is good.
//!
//! ```yaml
//! devices:
//!   - name: meter1
//!     port: tcp://10.0.0.5        # any --port form
//!     slave: 1
//!     map: meter.csv               # CSV or Home Assistant YAML, beside this file
//!     every: 1s
//!   - name: drive3
//!     port: /dev/ttyUSB0
//!     baud: 19200
//!     parity: even
//!     slave: 3
//!     every: 5s
//!     points:                      # or the points here, as a CSV map's columns
//!       - {name: speed, ref: 400108, unit: rpm}
//! ```
//!
//! The same in TOML (a file named `.toml`), a `[[devices]]` table a device.

mod tree;

use std::collections::BTreeMap;
use std::time::Duration;

use tree::{Node, Tree};

use super::faults::Faults;
use super::map::{at, MapConnection, MapError, Point};
use crate::input::duration::parse_duration;
use crate::input::number::parse_in_range;

/// One device of a plant, as its file gives it.
#[derive(Clone, Debug, PartialEq)]
pub struct PlantDevice {
    /// Its name, unique in the plant: the `device` of every row.
    pub name: String,
    /// The port and its line, as `--port` and the serial options give them.
    pub connection: MapConnection,
    /// The slave address or unit id.
    pub slave: u8,
    /// Its points: a register map's file, or the points given in the plant.
    pub points: Points,
    /// How often its points are read.
    pub every: Duration,
    /// The line of the file the device starts on.
    pub line: usize,
}

/// The port and map of a device with faults, each with its line.
#[derive(Clone, Debug, PartialEq)]
pub struct Unread {
    /// Its name, or `the device` where it has none.
    pub name: String,
    /// The line it starts on.
    pub line: usize,
    /// Its port as written, and the line.
    pub port: Option<(String, usize)>,
    /// Its map's file as written, and the line.
    pub map: Option<(String, usize)>,
}

/// Where a device's points are.
#[derive(Clone, Debug, PartialEq)]
pub enum Points {
    /// A register map's file, as written (relative to the plant file's folder).
    Map(String),
    /// Given in the plant file itself.
    Given(Vec<Point>),
}

/// The keys a device takes.
const KEYS: [&str; 11] = [
    "name",
    "port",
    "slave",
    "map",
    "every",
    "mode",
    "baud",
    "parity",
    "data_bits",
    "stop_bits",
    "points",
];

/// A plant file read: the devices it gives whole, and every fault found in it.
#[derive(Debug)]
pub struct Parsed {
    /// The devices without a fault, so that what else is wrong with them (a map, a port)
    /// can be told with the file's faults.
    pub devices: Vec<PlantDevice>,
    /// What the devices with faults give of their port and map, for the caller to check
    /// as it checks the others', so that their faults are told with the file's.
    pub unread: Vec<Unread>,
    /// Every fault of the file.
    pub faults: Result<(), MapError>,
}

/// A plant file's text, read: its devices, or every fault found in it.
pub fn parse(file: &str, text: &str) -> Result<Vec<PlantDevice>, MapError> {
    let parsed = parse_all(file, text);
    parsed.faults.map(|()| parsed.devices)
}

/// A plant file's text, read: the devices given whole, and every fault of the file.
pub fn parse_all(file: &str, text: &str) -> Parsed {
    match read_all(file, text) {
        Ok(parsed) => parsed,
        Err(error) => Parsed {
            devices: Vec::new(),
            unread: Vec::new(),
            faults: Err(error),
        },
    }
}

fn read_all(file: &str, text: &str) -> Result<Parsed, MapError> {
    let (top, form) = match is_toml(file) {
        true => (tree::toml(text), "TOML with [[devices]]"),
        false => (tree::yaml(text), "YAML with devices:"),
    };
    let top = top.map_err(|(line, said)| {
        at(
            file,
            line,
            format!("not a plant file, which is {form} ({said})"),
        )
    })?;
    let mut faults = Faults::default();
    for (key, value) in &top {
        if key != "devices" {
            faults.add(at(
                file,
                value.line,
                format!("{key}: a plant file has devices: only"),
            ));
        }
    }
    let devices = match top.get("devices").map(|d| &d.value) {
        Some(Tree::List(devices)) => devices.as_slice(),
        Some(_) => {
            faults.add(at(file, 1, "devices: give a list of devices"));
            &[]
        }
        None => {
            faults.add(at(
                file,
                1,
                "the file has no devices: list them under devices:",
            ));
            &[]
        }
    };
    let mut found: Vec<PlantDevice> = Vec::new();
    // Every name given and its line, the devices with faults included.
    let mut names: Vec<(String, usize)> = Vec::new();
    let mut unread: Vec<Unread> = Vec::new();
    for device in devices {
        let line = device.line;
        let Tree::Map(keys) = &device.value else {
            faults.add(at(
                file,
                line,
                "a device is its keys: name, port, slave, map, every",
            ));
            continue;
        };
        // A device whose name is taken has its other faults told too.
        let mut taken = false;
        if let Some(Tree::Text(name)) = keys.get("name").map(|n| &n.value) {
            if let Some((_, first)) = names.iter().find(|(known, _)| known == name) {
                faults.add(at(
                    file,
                    line,
                    format!("the name '{name}' is taken already, on line {first}"),
                ));
                taken = true;
            } else {
                names.push((name.clone(), line));
            }
        }
        match read_device(file, line, keys) {
            Ok(device) if !taken => found.push(device),
            Ok(_) => {}
            Err(errors) => errors.into_iter().for_each(|e| faults.add(e)),
        }
        // The port and map of a device with faults are for the caller to check too, so
        // that their faults are told with the others.
        if taken || !found.iter().any(|d| d.line == device.line) {
            let given = |key: &str| match keys.get(key) {
                Some(Node {
                    value: Tree::Text(text),
                    line,
                }) => Some((text.clone(), *line)),
                _ => None,
            };
            let name = given("name").map_or_else(|| "the device".into(), |(name, _)| name);
            unread.push(Unread {
                name,
                line: device.line,
                port: given("port"),
                map: given("map"),
            });
        }
    }
    Ok(Parsed {
        devices: found,
        unread,
        faults: faults.or((), |errors, more| MapError::Several { errors, more }),
    })
}

/// Whether a plant file is TOML, by its name.
pub fn is_toml(file: &str) -> bool {
    file.to_ascii_lowercase().ends_with(".toml")
}

/// One device's keys read, or each of their faults.
fn read_device(
    file: &str,
    line: usize,
    keys: &BTreeMap<String, Node>,
) -> Result<PlantDevice, Vec<MapError>> {
    let mut faults = Vec::new();
    let mut fault = |at_line: usize, message: String| faults.push(at(file, at_line, message));
    for (key, value) in keys {
        if !KEYS.contains(&key.as_str()) {
            fault(
                value.line,
                format!("{key}: a device takes {}", KEYS.join(", ")),
            );
        }
    }
    let text = |key: &str| match keys.get(key) {
        Some(Node {
            value: Tree::Text(text),
            line,
        }) => Some((text.clone(), *line)),
        _ => None,
    };
    let name = text("name").map(|(name, _)| name);
    let what = name.clone().unwrap_or_else(|| "the device".into());
    let mut needed = |key: &str, why: &str| {
        let given = text(key);
        if given.is_none() {
            fault(line, format!("{what} has no {key}: give {why}"));
        }
        given
    };
    let port = needed(
        "port",
        "port: any --port form (tcp://10.0.0.5, /dev/ttyUSB0)",
    );
    let slave = needed("slave", "slave: its slave address or unit id");
    let every = needed("every", "every: how often it is read (1s, 500ms)");
    let name = needed("name", "name: how its rows name it");
    // The points' own faults, each with its line.
    let mut points_fault = None;
    let points = match (text("map"), keys.get("points")) {
        (Some((map, _)), None) => Some(Points::Map(map)),
        (None, Some(given)) => match given_points(file, &what, given) {
            Ok(points) => Some(Points::Given(points)),
            Err(error) => {
                points_fault = Some(error);
                None
            }
        },
        (Some(_), Some(_)) => {
            fault(line, format!("{what} has both map: and points:: give one"));
            None
        }
        (None, None) => {
            fault(
                line,
                format!("{what} has no map: give map: FILE (CSV or Home Assistant YAML), or its points:"),
            );
            None
        }
    };
    let mut number = |key: &str, low: i128, high: i128| -> Option<u32> {
        let (value, at_line) = text(key)?;
        match parse_in_range(&value, low, high, key) {
            Ok(n) => u32::try_from(n).ok(),
            Err(e) => {
                fault(at_line, format!("{what}: {e}"));
                None
            }
        }
    };
    let slave_id = slave.as_ref().and_then(|_| number("slave", 0, 255));
    let baud = number("baud", 50, 4_000_000);
    let data_bits = number("data_bits", 7, 8);
    let stop_bits = number("stop_bits", 1, 2);
    let every_time = every.and_then(|(value, at_line)| match parse_duration(&value) {
        Ok(time) if time.is_zero() => {
            fault(
                at_line,
                format!("{what}: every 0 would never rest: give 100ms or more"),
            );
            None
        }
        Ok(time) => Some(time),
        Err(e) => {
            fault(at_line, format!("{what}: every: {e}"));
            None
        }
    });
    let parity =
        text("parity").and_then(
            |(value, at_line)| match value.to_ascii_lowercase().as_str() {
                "even" | "e" => Some('E'),
                "odd" | "o" => Some('O'),
                "none" | "n" => Some('N'),
                _ => {
                    fault(
                        at_line,
                        format!("{what}: parity {value}: give none, even or odd"),
                    );
                    None
                }
            },
        );
    let mode = text("mode").and_then(|(value, at_line)| match value.as_str() {
        "rtu" | "ascii" => Some(value),
        _ => {
            fault(at_line, format!("{what}: mode {value}: give rtu or ascii"));
            None
        }
    });
    faults.extend(points_fault);
    let (Some((name, _)), Some((port, _)), Some(slave), Some(points), Some(every), true) =
        (name, port, slave_id, points, every_time, faults.is_empty())
    else {
        return Err(faults);
    };
    Ok(PlantDevice {
        connection: MapConnection {
            hub: name.clone(),
            port,
            mode,
            baud,
            parity,
            data_bits: data_bits.map(|bits| bits as u8),
            stop_bits: stop_bits.map(|bits| bits as u8),
        },
        name,
        slave: slave as u8,
        points,
        every,
        line,
    })
}

/// A device's `points:`: a list of tables whose keys are the columns of a CSV map.
fn given_points(file: &str, device: &str, given: &Node) -> Result<Vec<Point>, MapError> {
    if matches!(&given.value, Tree::List(items) if items.is_empty()) {
        return Err(at(
            file,
            given.line,
            format!("{device}: points: give at least one point"),
        ));
    }
    let Tree::List(items) = &given.value else {
        return Err(at(
            file,
            given.line,
            format!("{device}: points: give a list of points, each its name, ref, type, ..."),
        ));
    };
    let mut rows = Vec::new();
    for item in items {
        let Tree::Map(keys) = &item.value else {
            return Err(at(
                file,
                item.line,
                format!("{device}: a point is its keys: name, ref, type, ..."),
            ));
        };
        let mut fields = Vec::new();
        for (key, value) in keys {
            match &value.value {
                Tree::Text(text) => fields.push((key.as_str(), text.as_str())),
                Tree::Nothing => {}
                _ => {
                    return Err(at(
                        file,
                        value.line,
                        format!("{device}: {key}: give a single value"),
                    ))
                }
            }
        }
        rows.push((item.line, fields));
    }
    super::map::parse_points(file, &rows).map(|map| map.points)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_plant_reads_its_devices() {
        let text = "devices:\n  - name: meter1\n    port: tcp://127.0.0.1:5020\n    slave: 1\n    map: meter.csv\n    every: 1s\n  - name: drive3\n    port: /dev/ttyUSB0\n    baud: 9600\n    parity: none\n    slave: 3\n    map: drive.yaml\n    every: 500ms\n";
        let devices = parse("plant.yaml", text).unwrap();
        assert_eq!(devices.len(), 2);
        assert_eq!(devices[0].name, "meter1");
        assert_eq!(devices[0].connection.port, "tcp://127.0.0.1:5020");
        assert_eq!(devices[0].every, Duration::from_secs(1));
        assert_eq!(devices[1].slave, 3);
        assert_eq!(devices[1].connection.baud, Some(9600));
        assert_eq!(devices[1].connection.parity, Some('N'));
        assert_eq!(devices[1].line, 7);
    }

    #[test]
    fn every_fault_of_a_plant_is_told_at_once_with_its_line() {
        let text = "devices:\n  - name: a\n    port: tcp://127.0.0.1:1\n    slave: 300\n    map: m.csv\n    every: fast\n  - name: b\n    slave: 1\n    map: m.csv\n    every: 1s\n    colour: red\n";
        let error = parse("p.yaml", text).unwrap_err().to_string();
        for said in [
            "p.yaml:4: a: slave",
            "p.yaml:6: a: every:",
            "p.yaml:7: b has no port",
            "p.yaml:11: colour: a device takes",
        ] {
            assert!(error.contains(said), "{said}: {error}");
        }
    }

    #[test]
    fn points_given_in_the_plant_are_read_as_a_map_and_their_faults_told_with_the_rest() {
        let text = "devices:\n  - name: meter\n    port: sim\n    slave: 17\n    every: 1s\n    points:\n      - name: speed\n        ref: 400108\n        unit: rpm\n      - {name: flow, ref: 400110, scale: 0.1}\n";
        let devices = parse("p.yaml", text).unwrap();
        let Points::Given(points) = &devices[0].points else {
            panic!("{:?}", devices[0].points);
        };
        let names: Vec<(&str, u16, f64)> = points
            .iter()
            .map(|p| (p.name.as_str(), p.address, p.scale))
            .collect();
        assert_eq!(names, [("speed", 107, 1.0), ("flow", 109, 0.1)]);
        assert_eq!((points[0].line, points[1].line), (7, 10));
        let text = "devices:\n  - name: a\n    port: sim\n    slave: 1\n    every: 1s\n    map: m.csv\n    points: []\n  - name: b\n    port: sim\n    slave: 999\n    every: 1s\n    points:\n      - name: x\n        ref: 400001\n        type: u17\n";
        let error = parse("p.yaml", text).unwrap_err().to_string();
        for said in [
            "p.yaml:2: a has both map: and points:: give one",
            "p.yaml:10: b: slave 999",
            "p.yaml:13: type 'u17': give u16",
        ] {
            assert!(error.contains(said), "{said}: {error}");
        }
    }

    #[test]
    fn a_toml_plant_tells_its_faults_with_their_lines() {
        let text = "# a plant\n[[devices]]\nname = \"a\"\nport = \"sim\"\nslave = 0x11\nmap = \"m.csv\"\nevery = \"1s\"\n\n[[devices]]\nname = \"b\"\nport = \"sim\"\nslave = 1\nmap = \"m.csv\"\nevery = 0\ncolour = \"red\"\n";
        let parsed = parse_all("p.toml", text);
        assert_eq!(parsed.devices.len(), 1);
        assert_eq!((parsed.devices[0].slave, parsed.devices[0].line), (17, 2));
        let error = parsed.faults.unwrap_err().to_string();
        for said in [
            "p.toml:14: b: every 0 would never rest",
            "p.toml:15: colour: a device takes",
        ] {
            assert!(error.contains(said), "{said}: {error}");
        }
    }

    #[test]
    fn names_that_yaml_1_1_would_read_as_booleans_are_names() {
        let text = "devices:\n  - name: no\n    port: sim\n    slave: 1\n    map: m.csv\n    every: 1s\n  - name: y\n    port: sim\n    slave: 2\n    map: m.csv\n    every: 1s\n";
        let names: Vec<String> = parse("p.yaml", text)
            .unwrap()
            .into_iter()
            .map(|d| d.name)
            .collect();
        assert_eq!(names, ["no", "y"]);
    }

    #[test]
    fn a_file_without_devices_says_how_to_give_them() {
        for text in ["", "devices:\n", "devices: 3\n", "hubs: []\n"] {
            let error = parse("p.yaml", text).unwrap_err().to_string();
            assert!(error.contains("devices"), "{text:?}: {error}");
        }
    }

    #[test]
    fn any_text_is_read_or_told_never_panicked_on() {
        for text in [
            "devices:\n  - [1, 2]\n  - 3\n",
            "devices:\n  - name: {a: 1}\n",
            ":\n",
            "- a\n- b\n",
            "devices: !x\n",
        ] {
            let _ = parse("p.yaml", text);
        }
    }
}
