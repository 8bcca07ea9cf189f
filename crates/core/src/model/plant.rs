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
//!     map: drive.csv
//!     every: 5s
//! ```

use std::collections::BTreeMap;
use std::fmt;
use std::time::Duration;

use serde::de::{Deserializer, MapAccess, SeqAccess, Visitor};
use serde::Deserialize;
use serde_saphyr::Spanned;

use super::faults::Faults;
use super::map::{at, MapConnection, MapError};
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
    /// The register map's file, as written (relative to the plant file's folder).
    pub map: String,
    /// How often its points are read.
    pub every: Duration,
    /// The line of the file the device starts on.
    pub line: usize,
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
            faults: Err(error),
        },
    }
}

fn read_all(file: &str, text: &str) -> Result<Parsed, MapError> {
    let top: Option<BTreeMap<String, Spanned<Scalar>>> =
        serde_saphyr::from_str(text).map_err(|e| {
            let line = e
                .location()
                .map_or(1, |l| usize::try_from(l.line()).unwrap_or(1));
            // The reader's first line, without its own `error: line L column C: `.
            let said = e.to_string();
            let first = said.lines().next().unwrap_or_default();
            let first = first.strip_prefix("error: ").unwrap_or(first);
            let first = match first.split_once(": ") {
                Some((place, rest)) if place.starts_with("line ") => rest,
                _ => first,
            };
            at(
                file,
                line,
                format!("not a plant file, which is YAML with devices: ({first})"),
            )
        })?;
    let mut faults = Faults::default();
    let top = top.unwrap_or_default();
    for (key, value) in &top {
        if key != "devices" {
            faults.add(at(
                file,
                line_of(value),
                format!("{key}: a plant file has devices: only"),
            ));
        }
    }
    let devices = match top.get("devices").map(|d| &d.value) {
        Some(Scalar::List(devices)) => devices.as_slice(),
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
    for device in devices {
        let line = line_of(device);
        let Scalar::Map(keys) = &device.value else {
            faults.add(at(
                file,
                line,
                "a device is its keys: name, port, slave, map, every",
            ));
            continue;
        };
        if let Some(Scalar::Text(name)) = keys.get("name").map(|n| &n.value) {
            if let Some((_, first)) = names.iter().find(|(known, _)| known == name) {
                faults.add(at(
                    file,
                    line,
                    format!("the name '{name}' is taken already, on line {first}"),
                ));
                continue;
            }
            names.push((name.clone(), line));
        }
        match read_device(file, line, keys) {
            Ok(device) => found.push(device),
            Err(errors) => errors.into_iter().for_each(|e| faults.add(e)),
        }
    }
    Ok(Parsed {
        devices: found,
        faults: faults.or((), |errors, more| MapError::Several { errors, more }),
    })
}

fn line_of<T>(spanned: &Spanned<T>) -> usize {
    usize::try_from(spanned.referenced.line()).unwrap_or(1)
}

/// One device's keys read, or each of their faults.
fn read_device(
    file: &str,
    line: usize,
    keys: &BTreeMap<String, Spanned<Scalar>>,
) -> Result<PlantDevice, Vec<MapError>> {
    let mut faults = Vec::new();
    let mut fault = |at_line: usize, message: String| faults.push(at(file, at_line, message));
    for (key, value) in keys {
        if !KEYS.contains(&key.as_str()) {
            fault(
                line_of(value),
                format!("{key}: a device takes {}", KEYS.join(", ")),
            );
        }
    }
    let text = |key: &str| match keys.get(key) {
        Some(Spanned {
            value: Scalar::Text(text),
            referenced,
            ..
        }) => Some((
            text.clone(),
            usize::try_from(referenced.line()).unwrap_or(line),
        )),
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
    let map = needed("map", "map: its register map (CSV or Home Assistant YAML)");
    let every = needed("every", "every: how often it is read (1s, 500ms)");
    let name = needed("name", "name: how its rows name it");
    if keys.contains_key("points") {
        fault(
            line,
            format!("{what}: points are given in a map file for now: give map: FILE"),
        );
    }
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
    let (Some((name, _)), Some((port, _)), Some(slave), Some((map, _)), Some(every), true) =
        (name, port, slave_id, map, every_time, faults.is_empty())
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
        map,
        every,
        line,
    })
}

/// A value of a plant file as YAML gives it: a scalar's text, a list, a mapping, or
/// nothing; each with where it stands.
enum Scalar {
    Text(String),
    List(Vec<Spanned<Scalar>>),
    Map(BTreeMap<String, Spanned<Scalar>>),
    Nothing,
}

impl<'de> Deserialize<'de> for Scalar {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Any;
        impl<'de> Visitor<'de> for Any {
            type Value = Scalar;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a value")
            }
            fn visit_str<E: serde::de::Error>(self, v: &str) -> Result<Scalar, E> {
                Ok(Scalar::Text(v.to_string()))
            }
            fn visit_i64<E: serde::de::Error>(self, v: i64) -> Result<Scalar, E> {
                Ok(Scalar::Text(v.to_string()))
            }
            fn visit_u64<E: serde::de::Error>(self, v: u64) -> Result<Scalar, E> {
                Ok(Scalar::Text(v.to_string()))
            }
            fn visit_f64<E: serde::de::Error>(self, v: f64) -> Result<Scalar, E> {
                Ok(Scalar::Text(v.to_string()))
            }
            fn visit_bool<E: serde::de::Error>(self, v: bool) -> Result<Scalar, E> {
                Ok(Scalar::Text(v.to_string()))
            }
            fn visit_unit<E: serde::de::Error>(self) -> Result<Scalar, E> {
                Ok(Scalar::Nothing)
            }
            fn visit_none<E: serde::de::Error>(self) -> Result<Scalar, E> {
                Ok(Scalar::Nothing)
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Scalar, A::Error> {
                let mut items = Vec::new();
                while let Some(item) = seq.next_element::<Spanned<Scalar>>()? {
                    items.push(item);
                }
                Ok(Scalar::List(items))
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Scalar, A::Error> {
                let mut keys = BTreeMap::new();
                while let Some((key, value)) = map.next_entry::<String, Spanned<Scalar>>()? {
                    keys.insert(key, value);
                }
                Ok(Scalar::Map(keys))
            }
        }
        deserializer.deserialize_any(Any)
    }
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
