use std::collections::HashMap;

use super::*;
use crate::model::address::Table;
use crate::model::map::Kind;
use crate::model::values::{ByteOrder, ValueType};

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

/// Files and secrets in memory, by name.
#[derive(Default)]
struct Files {
    files: HashMap<String, String>,
    secrets: HashMap<String, String>,
}

impl Sources for Files {
    fn include(&mut self, _: &str, tag: &str, spec: &str) -> Result<Vec<(String, String)>, String> {
        let mut found: Vec<(String, String)> = match tag {
            "!include" => self
                .files
                .get(spec)
                .map(|t| vec![(spec.to_string(), t.clone())])
                .unwrap_or_default(),
            _ => self
                .files
                .iter()
                .filter(|(name, _)| name.starts_with(&format!("{spec}/")))
                .map(|(n, t)| (n.clone(), t.clone()))
                .collect(),
        };
        found.sort();
        if found.is_empty() {
            return Err("no such file".into());
        }
        Ok(found)
    }

    fn secret(&mut self, _: &str, name: &str) -> Result<String, String> {
        self.secrets
            .get(name)
            .cloned()
            .ok_or_else(|| "secrets.yaml beside ha.yaml does not have it".into())
    }
}

fn read(text: &str) -> Result<RegisterMap, MapError> {
    parse("ha.yaml", text, &mut NoSources)
}

fn names(map: &RegisterMap) -> Vec<&str> {
    map.points.iter().map(|p| p.name.as_str()).collect()
}

#[test]
fn entries_become_points() {
    let map = read(CONFIGURATION).unwrap();
    assert_eq!(names(&map), ["voltage", "temperature", "running", "pump"]);
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
    // The host is a secret no file here has: the place is unknown, and why is said.
    assert_eq!(map.connection, None);
    assert!(map
        .unknown_place
        .as_deref()
        .unwrap()
        .starts_with("host is !secret pump_host, and "));
}

#[test]
fn a_secret_is_found_where_home_assistant_finds_it() {
    let mut files = Files::default();
    files.secrets.insert("pump_host".into(), "10.0.0.5".into());
    let map = parse("ha.yaml", CONFIGURATION, &mut files).unwrap();
    assert_eq!(map.connection.unwrap().port, "tcp://10.0.0.5:502");
    // A secret in a key mbtool does not read is passed over.
    let text = CONFIGURATION.replace("    port: 502\n", "    port: 502\n    timeout: !secret t\n");
    assert!(read(&text).is_ok());
    // One it needs for a point is a fault naming the key and the secret.
    let text = CONFIGURATION.replace("address: 5", "address: !secret pump_coil");
    assert_eq!(
        read(&text).unwrap_err().to_string(),
        "ha.yaml:23: pump: address is !secret pump_coil, and the text has no secrets.yaml beside it"
    );
}

#[test]
fn every_form_a_file_takes() {
    let hubs = "- name: a\n  type: tcp\n  host: 127.0.0.1\n  port: 502\n  sensors:\n    - name: x\n      address: 1\n";
    assert_eq!(names(&read(hubs).unwrap()), ["x"]);
    let one_hub = "name: a\ntype: serial\nport: /dev/ttyUSB0\nbaudrate: 9600\nparity: E\nsensors:\n  - name: x\n    address: 1\n";
    let map = read(one_hub).unwrap();
    let place = map.connection.unwrap();
    assert_eq!(
        (place.port.as_str(), place.baud, place.parity),
        ("/dev/ttyUSB0", Some(9600), Some('E'))
    );
    // A parity Home Assistant refuses is refused, not read as the default.
    let odd = one_hub.replace("parity: E", "parity: Q");
    let map = read(&odd).unwrap();
    let why = map.unknown_place.unwrap_or_default();
    assert!(why.contains("parity 'Q': give E, O or N"), "{why}");
    assert!(map.connection.is_none());
    for (key, bad) in [
        ("baudrate: 9600", "bytesize: 9"),
        ("baudrate: 9600", "stopbits: 3"),
    ] {
        let odd = one_hub.replace(key, &format!("{key}\n{bad}"));
        let why = read(&odd).unwrap().unknown_place.unwrap_or_default();
        assert!(
            why.contains(&format!("{}: give", bad.replace(": ", " "))),
            "{why}"
        );
    }
    let sensors = "- name: x\n  address: 1\n- name: flag\n  address: 2\n  input_type: coil\n- name: relay\n  address: 3\n  write_type: coil\n";
    let map = read(sensors).unwrap();
    assert_eq!(names(&map), ["x", "flag", "relay"]);
    assert_eq!(map.points[1].table, Table::Coils);
    assert!(map.points[2].writable);
    // The modbus key beside the rest of a configuration, a hub as a mapping, anchors and
    // merge keys.
    let whole = "homeassistant:\n  name: Home\nx-base: &base\n  data_type: uint16\n  scale: 10\nmodbus:\n  name: only\n  type: tcp\n  host: h\n  port: 5020\n  sensors:\n    - name: a\n      <<: *base\n      address: 7\n";
    let map = read(whole).unwrap();
    assert_eq!(map.points[0].kind, Kind::Number(ValueType::U16));
    assert_eq!(map.points[0].scale, 10.0);
    assert_eq!(map.connection.unwrap().port, "tcp://h:5020");
}

#[test]
fn includes_are_read_from_the_files_they_name() {
    let mut files = Files::default();
    files.files.insert(
        "hubs.yaml".into(),
        "- name: a\n  type: tcp\n  host: h\n  port: 502\n  sensors: !include meter.yaml\n".into(),
    );
    files.files.insert(
        "meter.yaml".into(),
        "- name: voltage\n  address: 0\n\n- name: current\n  address: [1]\n".into(),
    );
    files
        .files
        .insert("dir/a.yaml".into(), "name: first\naddress: 10\n".into());
    files
        .files
        .insert("dir/b.yaml".into(), "name: second\naddress: 11\n".into());
    let error = parse(
        "configuration.yaml",
        "modbus: !include hubs.yaml\n",
        &mut files,
    )
    .unwrap_err();
    // The fault is told in the file that has it.
    assert!(error.to_string().starts_with("meter.yaml:5: "), "{error}");
    files.files.insert(
        "meter.yaml".into(),
        "- name: voltage\n  address: 0\n- name: current\n  address: 1\n".into(),
    );
    let map = parse(
        "configuration.yaml",
        "modbus: !include hubs.yaml\n",
        &mut files,
    )
    .unwrap();
    assert_eq!(names(&map), ["voltage", "current"]);
    let text = "modbus:\n  - name: a\n    type: tcp\n    host: h\n    port: 502\n    binary_sensors: !include_dir_list dir\n";
    let map = parse("configuration.yaml", text, &mut files).unwrap();
    assert_eq!(names(&map), ["first", "second"]);
    assert!(
        parse("c.yaml", "modbus: !include nowhere.yaml\n", &mut files)
            .unwrap_err()
            .to_string()
            .starts_with("c.yaml:1: !include nowhere.yaml: no such file")
    );
}

#[test]
fn names_are_per_platform_and_a_duplicate_is_left_out() {
    let text = "
- name: h
  type: tcp
  host: h
  port: 502
  sensors:
    - name: pump
      address: 1
    - name: pump
      address: 9
  switches:
    - name: pump
      address: 1
";
    let map = read(text).unwrap();
    assert_eq!(names(&map), ["sensor.pump", "switch.pump"]);
    assert_eq!(map.points[0].address, 1);
    assert_eq!(
        map.warnings,
        ["ha.yaml:9: sensor pump is a duplicate of ha.yaml:7; Home Assistant loads the first, so this one is left out"]
    );
}

#[test]
fn counts_expand_as_home_assistant_expands_them() {
    let text = "
- name: h
  type: tcp
  host: h
  port: 502
  sensors:
    - name: phase
      address: 10
      data_type: float32
      virtual_count: 2
  binary_sensors:
    - name: door
      address: 4
      input_type: discrete_input
      slave_count: 1
";
    let map = read(text).unwrap();
    assert_eq!(
        names(&map),
        ["phase", "phase 1", "phase 2", "door", "door 1"]
    );
    let addresses: Vec<u16> = map.points.iter().map(|p| p.address).collect();
    assert_eq!(addresses, [10, 12, 14, 4, 5]);
}

#[test]
fn value_keys_are_kept_as_home_assistant_applies_them() {
    let text = "
- name: s
  address: 1
  max_value: 50
  nan_value: 0x7FFF
  precision: 1
- name: packed
  address: 2
  data_type: custom
  count: 2
  structure: '>2h'
";
    let map = read(text).unwrap();
    let shown = map.points[0].shown.clone().unwrap();
    assert_eq!(
        (shown.max, shown.nan, shown.precision),
        (Some(50.0), Some(0x7FFF), 1)
    );
    assert_eq!(map.points[1].kind, Kind::Packed(2));
    let bad = text.replace("'>2h'", "'>3h'");
    assert_eq!(
        read(&bad).unwrap_err().to_string(),
        "ha.yaml:7: packed: Size of structure is 6 bytes but `count: 2` is 4 bytes"
    );
}

#[test]
fn a_bad_entry_names_its_line() {
    let text = CONFIGURATION.replace("swap: word", "swap: sideways");
    assert_eq!(
        read(&text).unwrap_err().to_string(),
        "ha.yaml:8: voltage: swap 'sideways': give none, byte, word or word_byte"
    );
    assert!(read("- [1, 2").is_err());
    let without_address =
        "modbus:\n  - name: h\n    sensors:\n      - name: aa\n        slave: 17\n";
    assert!(read(without_address).is_err());
    assert!(read("name: h\ntype: tcp\n")
        .unwrap_err()
        .to_string()
        .starts_with("ha.yaml:1: the map names no point"));
}

#[test]
fn the_modbus_of_packages_is_read_as_home_assistant_merges_it() {
    let mut files = Files::default();
    files.files.insert("packages/vent.yaml".into(), "modbus:\n  - name: vent\n    type: tcp\n    host: h\n    port: 502\n    sensors:\n      - {name: fan, address: 3}\n".into());
    let text = "homeassistant:\n  packages: !include_dir_named packages\n";
    let map = parse("configuration.yaml", text, &mut files).unwrap();
    assert_eq!(names(&map), ["fan"]);
    let inline = "homeassistant:\n  name: Home\n  packages:\n    pump:\n      modbus:\n        - name: pump\n          type: tcp\n          host: p\n          port: 502\n          sensors:\n            - {name: flow, address: 1}\nmodbus:\n  - name: main\n    type: tcp\n    host: m\n    port: 502\n    sensors:\n      - {name: level, address: 2}\n";
    let map = read(inline).unwrap();
    assert_eq!(names(&map), ["flow", "level"]);
}

#[test]
fn an_environment_variable_is_read_or_its_default_taken() {
    let text = |port: &str| {
        format!("name: a\ntype: tcp\nhost: h\nport: {port}\nsensors:\n  - name: x\n    address: !env_var MBTOOL_TEST_UNSET_ADDRESS 7\n")
    };
    let map = read(&text("502")).unwrap();
    assert_eq!(map.points[0].address, 7);
    let unknown = read(&text("!env_var MBTOOL_TEST_UNSET_PORT")).unwrap();
    assert_eq!(
        unknown.unknown_place.as_deref(),
        Some("port is !env_var MBTOOL_TEST_UNSET_PORT, which is not set")
    );
}

#[test]
fn switches_and_covers_are_named_by_their_states() {
    use crate::model::shown::States;
    let text = "
- name: h
  type: tcp
  host: h
  port: 502
  switches:
    - name: heat
      address: 4
      command_on: 5
      verify:
        state_on: [5, 6]
  covers:
    - name: shutter
      address: 8
      status_register: 9
      state_open: 10
";
    let map = read(text).unwrap();
    let states = |i: usize| map.points[i].shown.clone().unwrap().states.unwrap();
    assert_eq!(
        states(0),
        States::OnOff {
            on: vec![5, 6],
            off: vec![0]
        }
    );
    assert_eq!(
        states(1),
        States::Cover {
            values: [10, 0, 2, 3]
        }
    );
    assert_eq!(map.points[1].address, 9);
}
