//! A Home Assistant `modbus:` configuration read as a register map, as it is: each entry
//! of `sensors`, `binary_sensors`, `switches` and `climates` is a point.

use serde::Deserialize;
use serde_saphyr::Spanned;

use super::address::Table;
use super::faults::Faults;
use super::map::{
    at, check, check_name, checked, Kind, MapConnection, MapError, Point, RegisterMap,
};
use super::values::{ByteOrder, ValueType};

/// The configuration with its `modbus:` key.
#[derive(Deserialize)]
struct Configuration {
    modbus: Vec<Hub>,
}

#[derive(Default, Deserialize)]
struct Hub {
    name: Option<String>,
    #[serde(rename = "type")]
    kind: Option<String>,
    host: Option<String>,
    port: Option<HubPort>,
    baudrate: Option<u32>,
    parity: Option<String>,
    bytesize: Option<u8>,
    stopbits: Option<u8>,
    method: Option<String>,
    #[serde(default)]
    sensors: Vec<Entry>,
    #[serde(default)]
    binary_sensors: Vec<Entry>,
    #[serde(default)]
    switches: Vec<Entry>,
    #[serde(default)]
    climates: Vec<Entry>,
}

/// A hub's `port`: a TCP port number, or a serial device.
#[derive(Deserialize)]
#[serde(untagged)]
enum HubPort {
    Number(u16),
    Device(String),
}

impl Hub {
    /// Where the hub's device is, as `--port` and the line options would say it: `None`
    /// for a hub that names no place (`!secret` values are left for the command line).
    fn connection(&self) -> Option<MapConnection> {
        let hub = self.name.clone().unwrap_or_default();
        let port = match (self.kind.as_deref(), &self.host, &self.port) {
            (Some("tcp"), Some(host), Some(HubPort::Number(port))) => {
                format!("tcp://{host}:{port}")
            }
            (Some("rtuovertcp"), Some(host), Some(HubPort::Number(port))) => {
                format!("rtu+tcp://{host}:{port}")
            }
            (Some("serial"), _, Some(HubPort::Device(device))) => device.clone(),
            _ => return None,
        };
        Some(MapConnection {
            hub,
            port,
            mode: self.method.clone(),
            baud: self.baudrate,
            parity: self.parity.as_deref().and_then(|p| p.chars().next()),
            data_bits: self.bytesize,
            stop_bits: self.stopbits,
        })
    }
}

/// The keys of an entry that make a point; the others (`scan_interval`, `device_class`,
/// ...) are Home Assistant's own.
#[derive(Deserialize)]
struct Entry {
    name: Spanned<String>,
    address: u32,
    input_type: Option<String>,
    write_type: Option<String>,
    data_type: Option<String>,
    swap: Option<String>,
    count: Option<u16>,
    scale: Option<f64>,
    offset: Option<f64>,
    unit_of_measurement: Option<String>,
    slave: Option<u8>,
    device_address: Option<u8>,
}

/// Which list an entry came from.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Platform {
    Sensor,
    BinarySensor,
    Switch,
    Climate,
}

fn table_of(platform: Platform, entry: &Entry) -> Result<Table, String> {
    let (key, given) = match platform {
        Platform::Switch => ("write_type", entry.write_type.as_deref()),
        _ => ("input_type", entry.input_type.as_deref()),
    };
    let default = match platform {
        Platform::BinarySensor => "coil",
        _ => "holding",
    };
    let table = match given.unwrap_or(default) {
        "holding" | "holdings" => Table::HoldingRegisters,
        "input" => Table::InputRegisters,
        "coil" | "coils" => Table::Coils,
        "discrete_input" => Table::DiscreteInputs,
        other => {
            return Err(format!(
                "{key} '{other}': give holding, input, coil or discrete_input"
            ))
        }
    };
    if platform == Platform::Switch && !table.is_writable() {
        return Err(format!(
            "{key} '{}': a switch writes, and {}s are read-only; give holding or coil",
            given.unwrap_or(default),
            table.name()
        ));
    }
    Ok(table)
}

/// The point's kind from `data_type`, and `count` checked against it: a count that is not
/// the registers the type takes would read something else than the type says.
fn kind_of(entry: &Entry, table: Table) -> Result<Kind, String> {
    let kind = match (entry.data_type.as_deref(), table.is_bits()) {
        (None, true) => Kind::Bool,
        (None, false) => Kind::Number(ValueType::I16),
        (Some(data_type), _) => number_kind(data_type, entry.count)?,
    };
    match (entry.count, kind) {
        (Some(count), Kind::Bool | Kind::Number(_)) if count != kind.width() => Err(format!(
            "count {count}: {} takes {} {}; leave count out",
            entry.data_type.as_deref().unwrap_or("a bit"),
            kind.width(),
            if table.is_bits() { "bit" } else { "registers" }
        )),
        _ => Ok(kind),
    }
}

fn number_kind(data_type: &str, count: Option<u16>) -> Result<Kind, String> {
    let value_type = match data_type {
        "int16" | "int" => ValueType::I16,
        "uint16" | "uint" => ValueType::U16,
        "int32" => ValueType::I32,
        "uint32" => ValueType::U32,
        "int64" => ValueType::I64,
        "uint64" => ValueType::U64,
        "float32" | "float" => ValueType::F32,
        "float64" => ValueType::F64,
        "string" => {
            return match count {
                Some(count @ 1..=125) => Ok(Kind::Text(count)),
                _ => Err("data_type string needs count: the registers it takes, 1 to 125".into()),
            }
        }
        other => {
            return Err(format!(
                "data_type '{other}': give int16, uint16, int32, uint32, int64, uint64, float32, float64 or string"
            ))
        }
    };
    Ok(Kind::Number(value_type))
}

fn order_of(entry: &Entry) -> Result<ByteOrder, String> {
    Ok(match entry.swap.as_deref().unwrap_or("none") {
        "none" => ByteOrder::Abcd,
        "byte" => ByteOrder::Badc,
        "word" => ByteOrder::Cdab,
        "word_byte" => ByteOrder::Dcba,
        other => {
            return Err(format!(
                "swap '{other}': give none, byte, word or word_byte"
            ))
        }
    })
}

fn point(platform: Platform, entry: Entry, line: usize) -> Result<Point, String> {
    let table = table_of(platform, &entry)?;
    let kind = kind_of(&entry, table)?;
    let address = u16::try_from(entry.address)
        .map_err(|_| format!("address {} is past the last, 65535", entry.address))?;
    let slave = match (entry.slave, entry.device_address) {
        (Some(slave), Some(other)) if slave != other => {
            return Err(format!(
                "slave {slave} and device_address {other} disagree; give one"
            ))
        }
        (slave, other) => slave.or(other),
    };
    checked(Point {
        table,
        address,
        bit: None,
        kind,
        order: order_of(&entry)?,
        scale: entry.scale.unwrap_or(1.0),
        offset: entry.offset.unwrap_or(0.0),
        unit: entry.unit_of_measurement.unwrap_or_default(),
        writable: platform == Platform::Switch && table.is_writable(),
        slave,
        description: String::new(),
        line,
        name: entry.name.value,
    })
}

/// Reads a Home Assistant `modbus:` configuration; `file` names it in messages. The file
/// may hold the configuration with its `modbus:` key, the list of hubs an `!include`
/// names, or one hub; which it is is told by its first line, so that a mistake in it is
/// reported rather than read as an empty hub.
pub fn parse(file: &str, text: &str) -> Result<RegisterMap, MapError> {
    let first = text
        .lines()
        .map(str::trim_end)
        .find(|line| !line.trim().is_empty() && !line.trim_start().starts_with('#'))
        .unwrap_or_default();
    let unreadable = |e: serde_saphyr::Error| {
        let error = match e.without_snippet() {
            // The YAML reader's guard against files that expand without end (aliases of
            // aliases); a real configuration is far below it.
            serde_saphyr::Error::Budget { .. } => {
                "larger than a YAML map may be (about 40,000 points): give a CSV map".to_string()
            }
            e => format!(
                "not a Home Assistant modbus configuration: {}",
                e.to_string().lines().next().unwrap_or_default()
            ),
        };
        at(file, 1, error)
    };
    let hubs: Vec<Hub> = if text.lines().any(|line| line.starts_with("modbus:")) {
        serde_saphyr::from_str::<Configuration>(text)
            .map_err(unreadable)?
            .modbus
    } else if first.starts_with('-') {
        serde_saphyr::from_str(text).map_err(unreadable)?
    } else {
        vec![serde_saphyr::from_str(text).map_err(unreadable)?]
    };
    let mut map = RegisterMap::default();
    let mut faults = Faults::default();
    // The device is where the hub says; a place kept in Home Assistant's secrets
    // (`host: !secret pump_host`) is not in the file.
    let secret = text.lines().any(|line| {
        let line = line.trim_start();
        (line.starts_with("host:") || line.starts_with("port:")) && line.contains("!secret")
    });
    // Several hubs that say different places are several devices, and a point does not
    // say which it is on: none is taken, and --port says which is meant.
    let mut places: Vec<MapConnection> = hubs.iter().filter_map(Hub::connection).collect();
    places.dedup();
    map.connection = match places.as_slice() {
        [one] if !secret => Some(one.clone()),
        _ => None,
    };
    for hub in hubs {
        let lists = [
            (Platform::Sensor, hub.sensors),
            (Platform::BinarySensor, hub.binary_sensors),
            (Platform::Switch, hub.switches),
            (Platform::Climate, hub.climates),
        ];
        for (platform, entries) in lists {
            for entry in entries {
                let line = usize::try_from(entry.name.referenced.line()).unwrap_or(1);
                if let Err(error) = check_name(&entry.name.value) {
                    faults.add(at(file, line, error));
                    continue;
                }
                let name = entry.name.value.clone();
                match point(platform, entry, line) {
                    Ok(point) => map.points.push(point),
                    Err(error) => faults.add(at(file, line, format!("{name}: {error}"))),
                }
            }
        }
    }
    check(file, map, faults)
}

#[cfg(test)]
mod tests {
    use super::*;

    const CONFIGURATION: &str = "
modbus:
  - name: pump station
    type: tcp
    host: !secret pump_host
    port: 502
    sensors:
      - name: voltage
        address: 0
        data_type: float32
        swap: word
        unit_of_measurement: V
        slave: 17
      - name: temperature
        address: 2
        input_type: input
        scale: 0.1
        offset: -40
    binary_sensors:
      - name: running
        address: 0
    switches:
      - name: pump
        address: 5
        write_type: coil
";

    #[test]
    fn entries_become_points() {
        let map = parse("ha.yaml", CONFIGURATION).unwrap();
        let names: Vec<&str> = map.points.iter().map(|p| p.name.as_str()).collect();
        assert_eq!(names, ["voltage", "temperature", "running", "pump"]);
        let voltage = &map.points[0];
        assert_eq!(
            (voltage.table, voltage.kind, voltage.order, voltage.slave),
            (
                Table::HoldingRegisters,
                Kind::Number(ValueType::F32),
                ByteOrder::Cdab,
                Some(17)
            )
        );
        assert_eq!(voltage.line, 8);
        let temperature = &map.points[1];
        assert_eq!(
            (temperature.table, temperature.kind, temperature.scale),
            (Table::InputRegisters, Kind::Number(ValueType::I16), 0.1)
        );
        assert_eq!(
            (map.points[2].table, map.points[2].kind),
            (Table::Coils, Kind::Bool)
        );
        assert!(map.points[3].writable && !map.points[0].writable);
    }

    #[test]
    fn a_bad_entry_names_its_line() {
        let text = CONFIGURATION.replace("swap: word", "swap: sideways");
        assert_eq!(
            parse("ha.yaml", &text).unwrap_err().to_string(),
            "ha.yaml:8: voltage: swap 'sideways': give none, byte, word or word_byte"
        );
        assert!(parse("ha.yaml", "- [1, 2").is_err());
        // An entry without its address, or a hub that names no point, is no map.
        let without_address =
            "modbus:\n  - name: h\n    sensors:\n      - name: aa\n        slave: 17\n";
        assert!(parse("ha.yaml", without_address).is_err());
        assert_eq!(
            parse("ha.yaml", "name: h\ntype: tcp\n")
                .unwrap_err()
                .to_string(),
            "ha.yaml:1: the map names no point"
        );
    }
}
