//! Properties of register maps: a CSV map and a Home Assistant YAML map that say the same
//! points are read the same, accepted or refused alike, so that no rule holds for one and
//! not the other; no text panics either reader; reading costs time in proportion to the
//! text, whatever is in it.
#![allow(clippy::unwrap_used, clippy::expect_used)] // a test stops at what it did not expect

use std::time::{Duration, Instant};

use mbtool_core::model::address::{reference, Table};
use mbtool_core::model::home_assistant::{self, NoSources};
use mbtool_core::model::map::{parse_csv, RegisterMap, LONGEST_NAME, LONGEST_UNIT};
use proptest::collection::vec;
use proptest::prelude::*;

/// One point as both formats can say it.
#[derive(Clone, Debug)]
struct Spec {
    name: String,
    table: Table,
    /// CSV's type and Home Assistant's data_type; None leaves the column out.
    kind: Option<(&'static str, &'static str)>,
    /// For a string, its registers.
    text_registers: u16,
    /// Home Assistant's `count` beside a number type: the registers it takes, or not.
    count: Option<u16>,
    address: u16,
    order: (&'static str, &'static str),
    scale: f64,
    offset: f64,
    unit: String,
    writes: bool,
    slave: Option<u8>,
}

const NUMBER_TYPES: [(&str, &str); 8] = [
    ("i16", "int16"),
    ("u16", "uint16"),
    ("i32", "int32"),
    ("u32", "uint32"),
    ("i64", "int64"),
    ("u64", "uint64"),
    ("f32", "float32"),
    ("f64", "float64"),
];

fn awkward_number() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => Just(1.0),
        2 => -100.0..100.0f64,
        1 => Just(0.0),
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
        1 => Just(f64::NEG_INFINITY),
    ]
}

fn spec() -> impl Strategy<Value = Spec> {
    let kind = prop_oneof![
        2 => proptest::sample::select(NUMBER_TYPES.to_vec()).prop_map(Some),
        1 => Just(Some(("string", "string"))),
        1 => Just(None),
    ];
    let name = prop_oneof![
        8 => "[a-z][a-z0-9_]{0,6}",
        1 => Just("a".repeat(LONGEST_NAME - 1)),
        1 => Just("b".repeat(LONGEST_NAME)),
        1 => Just(String::new()),
    ];
    let unit = prop_oneof![
        4 => "[a-zA-Z%/]{0,4}",
        1 => Just("u".repeat(LONGEST_UNIT)),
        1 => Just("w".repeat(LONGEST_UNIT + 1)),
    ];
    let table = prop_oneof![
        Just(Table::Coils),
        Just(Table::DiscreteInputs),
        Just(Table::InputRegisters),
        Just(Table::HoldingRegisters),
    ];
    let order = proptest::sample::select(vec![
        ("ABCD", "none"),
        ("CDAB", "word"),
        ("BADC", "byte"),
        ("DCBA", "word_byte"),
    ]);
    (
        (name, table, kind, 0u16..130, prop::option::of(0u16..6)),
        (prop_oneof![0u16..200, 65500u16..=65535], order),
        (awkward_number(), awkward_number(), unit, any::<bool>()),
        prop::option::of(any::<u8>()),
    )
        .prop_map(
            |(
                (name, table, kind, text_registers, count),
                (address, order),
                (scale, offset, unit, writes),
                slave,
            )| Spec {
                name,
                table,
                kind,
                text_registers,
                count,
                address,
                order,
                scale,
                offset,
                unit,
                writes,
                slave,
            },
        )
}

fn yaml_number(value: f64) -> String {
    match value {
        v if v.is_nan() => ".nan".into(),
        v if v == f64::INFINITY => ".inf".into(),
        v if v == f64::NEG_INFINITY => "-.inf".into(),
        v => format!("{v:?}"),
    }
}

fn csv_of(specs: &[Spec]) -> String {
    let mut text = String::from("name,ref,type,order,scale,offset,unit,access,slave\n");
    for (i, spec) in specs.iter().enumerate() {
        let kind = match spec.kind {
            Some(("string", _)) => format!("string:{}", spec.text_registers),
            Some((csv, _)) => csv.to_string(),
            None => String::new(),
        };
        text.push_str(&format!(
            "{}{i},{},{kind},{},{:?},{:?},{},{},{}\n",
            spec.name,
            reference(spec.table, spec.address),
            spec.order.0,
            spec.scale,
            spec.offset,
            spec.unit,
            if spec.writes { "rw" } else { "r" },
            spec.slave.map(|s| s.to_string()).unwrap_or_default(),
        ));
    }
    text
}

fn yaml_of(specs: &[Spec]) -> String {
    let mut lists: [(&str, &str, Vec<String>); 3] = [
        ("sensors", "input_type", Vec::new()),
        ("binary_sensors", "input_type", Vec::new()),
        ("switches", "write_type", Vec::new()),
    ];
    for (i, spec) in specs.iter().enumerate() {
        let list = match (spec.writes, spec.table.is_bits()) {
            (true, _) => 2,
            (false, true) => 1,
            (false, false) => 0,
        };
        let table = match spec.table {
            Table::Coils => "coil",
            Table::DiscreteInputs => "discrete_input",
            Table::InputRegisters => "input",
            Table::HoldingRegisters => "holding",
        };
        let mut entry = format!(
            "      - name: \"{}{i}\"\n        address: {}\n        {}: {table}\n        swap: {}\n        scale: {}\n        offset: {}\n        unit_of_measurement: \"{}\"\n",
            spec.name,
            spec.address,
            lists[list].1,
            spec.order.1,
            yaml_number(spec.scale),
            yaml_number(spec.offset),
            spec.unit,
        );
        match spec.kind {
            Some(("string", yaml)) => entry.push_str(&format!(
                "        data_type: {yaml}\n        count: {}\n",
                spec.text_registers
            )),
            Some((_, yaml)) => entry.push_str(&format!("        data_type: {yaml}\n")),
            None => {}
        }
        if let (Some(count), false) = (spec.count, matches!(spec.kind, Some(("string", _)))) {
            entry.push_str(&format!("        count: {count}\n"));
        }
        if let Some(slave) = spec.slave {
            entry.push_str(&format!("        slave: {slave}\n"));
        }
        lists[list].2.push(entry);
    }
    let mut text = String::from("modbus:\n  - name: hub\n    type: tcp\n");
    for (list, _, entries) in lists {
        if !entries.is_empty() {
            text.push_str(&format!("    {list}:\n{}", entries.concat()));
        }
    }
    text
}

/// What a map says, without the lines its points came from (the formats lay them out
/// differently) and in one order.
fn points_of(map: RegisterMap) -> Vec<String> {
    let mut points: Vec<String> = map
        .points
        .into_iter()
        .map(|mut point| {
            point.line = 0;
            // How Home Assistant shows a value (its precision) is no CSV column.
            point.shown = None;
            format!("{point:?}")
        })
        .collect();
    points.sort();
    points
}

/// Whether the YAML says what the CSV does: a `count` beside a number type, the one thing
/// CSV cannot say, must be the registers the type takes; a register with no type is a
/// u16 in CSV and an int16 in Home Assistant; and a binary sensor has no data_type in
/// Home Assistant, which passes one over.
fn says_the_same(spec: &Spec) -> bool {
    let registers = !spec.table.is_bits();
    let untyped_register = registers && spec.kind.is_none();
    // Nor scale, offset or swap: a bit is on or off.
    let plain_bit =
        spec.kind.is_none() && spec.scale == 1.0 && spec.offset == 0.0 && spec.order.0 == "ABCD";
    if !registers && !plain_bit {
        return false;
    }
    // Home Assistant swaps words only of a type wider than a register.
    let one_word = matches!(spec.kind, None | Some(("string" | "i16" | "u16", _)));
    if one_word && matches!(spec.order.0, "CDAB" | "DCBA") {
        return false;
    }
    // A switch on a register shows the register as it is: no type, scale or swap.
    if registers && spec.writes {
        return false;
    }
    let count_disagrees = match (spec.count, spec.kind) {
        (None, _) | (_, Some(("string", _))) => false,
        (Some(count), None) => count != 1,
        (Some(count), Some((csv, _))) => {
            let width = match csv {
                "i16" | "u16" => 1,
                "i32" | "u32" | "f32" => 2,
                _ => 4,
            };
            count != width || !registers
        }
    };
    !untyped_register && !count_disagrees
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 500, max_global_rejects: 50_000, ..ProptestConfig::default() })]

    /// Every map either format reads, the other reads as the same points; every map
    /// either refuses, the other refuses. But for overlapping points: a CSV map refuses
    /// them, and Home Assistant's entities may overlap, as Home Assistant reads them.
    #[test]
    fn csv_and_yaml_maps_obey_the_same_rules(specs in vec(spec(), 1..5)) {
        let specs: Vec<Spec> = specs.into_iter().filter(says_the_same).collect();
        prop_assume!(!specs.is_empty());
        let csv = parse_csv("m.csv", &csv_of(&specs));
        let yaml = home_assistant::parse("m.yaml", &yaml_of(&specs), &mut NoSources);
        match (csv, yaml) {
            (Ok(csv), Ok(yaml)) => prop_assert_eq!(points_of(csv), points_of(yaml)),
            (Err(_), Err(_)) => {}
            (Err(csv), Ok(_)) if csv.to_string().contains(" overlaps ") => {}
            (csv, yaml) => prop_assert!(
                false,
                "CSV {:?}\nYAML {:?}\n{}\n{}",
                csv.map(points_of),
                yaml.map(points_of),
                csv_of(&specs),
                yaml_of(&specs)
            ),
        }
    }

    /// A `count` that is not what the data type takes is refused, with the line.
    #[test]
    fn a_count_that_is_not_the_types_is_refused(
        (csv, yaml) in proptest::sample::select(NUMBER_TYPES.to_vec()),
        count in 0u16..10,
    ) {
        let width = match csv {
            "i16" | "u16" => 1,
            "i32" | "u32" | "f32" => 2,
            _ => 4,
        };
        let text = format!(
            "modbus:\n  - name: hub\n    sensors:\n      - name: p\n        address: 0\n        data_type: {yaml}\n        count: {count}\n"
        );
        let read = home_assistant::parse("m.yaml", &text, &mut NoSources);
        if count == width {
            prop_assert!(read.is_ok(), "{:?}", read);
        } else {
            let message = read.unwrap_err().to_string();
            prop_assert!(message.starts_with("m.yaml:4: p: count "), "{}", message);
        }
    }

    /// No text panics either reader.
    #[test]
    fn no_text_panics_a_map_reader(text in "(name|ref|modbus|sensors|address|count|data_type|scale|:|,|-| |\n|[a-z0-9.\"]){0,200}") {
        let _ = parse_csv("m.csv", &text);
        let _ = home_assistant::parse("m.yaml", &text, &mut NoSources);
    }
}

/// Reading a map costs time in proportion to its text: a name of megabytes, or tens of
/// thousands of points, are read (or refused) at once.
#[test]
fn a_huge_map_is_read_or_refused_in_linear_time() {
    let started = Instant::now();
    let long = "n".repeat(10_000_000);
    let refused = parse_csv("m.csv", &format!("name,ref\n{long},400001\n"));
    assert!(refused
        .unwrap_err()
        .to_string()
        .starts_with("m.csv:2: a name of 10000000 characters: give one of at most 128"));
    let refused = home_assistant::parse(
        "m.yaml",
        &format!("modbus:\n  - sensors:\n      - name: {long}\n        address: 0\n"),
        &mut NoSources,
    );
    assert!(refused
        .unwrap_err()
        .to_string()
        .starts_with("m.yaml:3: a name of 10000000 characters"));

    let points = 60_000;
    let csv: String = (0..points)
        .map(|i| {
            format!(
                "point{i},{}\n",
                reference(Table::HoldingRegisters, i as u16)
            )
        })
        .collect();
    assert_eq!(
        parse_csv("m.csv", &format!("name,ref\n{csv}"))
            .unwrap()
            .points
            .len(),
        points
    );
    // A YAML map is bounded by the YAML reader's guard against files that expand without
    // end, far above any real configuration; past it, the map is refused in one line.
    let yaml = |points: usize| -> String {
        let entries: String = (0..points)
            .map(|i| format!("      - name: point{i}\n        address: {i}\n"))
            .collect();
        format!("modbus:\n  - sensors:\n{entries}")
    };
    assert_eq!(
        home_assistant::parse("m.yaml", &yaml(20_000), &mut NoSources)
            .unwrap()
            .points
            .len(),
        20_000
    );
    assert_eq!(
        home_assistant::parse("m.yaml", &yaml(points), &mut NoSources)
            .unwrap_err()
            .to_string(),
        "m.yaml:100000: larger than a YAML map may be (about 40,000 points): give a CSV map"
    );
    // Each of these takes milliseconds; the quadratic readers took minutes.
    assert!(
        started.elapsed() < Duration::from_secs(20),
        "{:?}",
        started.elapsed()
    );
}

/// A device of a plant file, written from its parts.
fn plant_device(name: &str, port: &str, slave: u8, every_ms: u64) -> String {
    format!("  - name: {name}\n    port: {port}\n    slave: {slave}\n    map: m.csv\n    every: {every_ms}ms\n")
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// Any text given as a plant file is read or told, never panicked on; a plant written
    /// from its devices reads back as them.
    #[test]
    fn a_plant_file_reads_back_as_written_and_no_text_panics(
        noise in ".{0,200}",
        slaves in vec(0u8..=255, 1..6),
        every in 1u64..100_000,
    ) {
        let _ = mbtool_core::model::plant::parse("p.yaml", &noise);
        let _ = mbtool_core::model::plant::parse("p.yaml", &format!("devices:\n{noise}"));
        let text: String = slaves
            .iter()
            .enumerate()
            .map(|(i, slave)| plant_device(&format!("d{i}"), "tcp://127.0.0.1:502", *slave, every))
            .collect();
        let devices = mbtool_core::model::plant::parse("p.yaml", &format!("devices:\n{text}")).unwrap();
        prop_assert_eq!(devices.len(), slaves.len());
        for (i, (device, slave)) in devices.iter().zip(&slaves).enumerate() {
            prop_assert_eq!(&device.name, &format!("d{i}"));
            prop_assert_eq!(device.slave, *slave);
            prop_assert_eq!(device.every, Duration::from_millis(every));
            prop_assert_eq!(device.line, 2 + 5 * i);
        }
    }

    /// The same in TOML: any text read or told; a plant written reads back as its devices,
    /// their points given inline read as a CSV map of the same points reads.
    #[test]
    fn a_toml_plant_reads_back_as_written_and_no_text_panics(
        noise in ".{0,200}",
        slaves in vec(0u8..=255, 1..6),
        every in 1u64..100_000,
        address in 1u32..=65536,
        scale in prop_oneof![-1000i32..0, 1i32..1000],
    ) {
        use mbtool_core::model::plant::{parse, Points};
        let _ = parse("p.toml", &noise);
        let _ = parse("p.toml", &format!("[[devices]]\n{noise}"));
        let reference = format!("4{address:05}");
        let text: String = slaves
            .iter()
            .enumerate()
            .map(|(i, slave)| format!(
                "[[devices]]\nname = \"d{i}\"\nport = \"tcp://127.0.0.1:502\"\nslave = {slave}\nevery = \"{every}ms\"\npoints = [{{ name = \"p\", ref = \"{reference}\", scale = {scale} }}]\n"
            ))
            .collect();
        let devices = parse("p.toml", &text).unwrap();
        let csv = mbtool_core::model::map::parse_csv("m.csv", &format!("name,ref,scale\np,{reference},{scale}\n")).unwrap();
        prop_assert_eq!(devices.len(), slaves.len());
        for (i, (device, slave)) in devices.iter().zip(&slaves).enumerate() {
            prop_assert_eq!(&device.name, &format!("d{i}"));
            prop_assert_eq!(device.slave, *slave);
            prop_assert_eq!(device.every, Duration::from_millis(every));
            prop_assert_eq!(device.line, 1 + 6 * i);
            let Points::Given(points) = &device.points else {
                return Err(TestCaseError::fail("the points are given inline"));
            };
            let point = mbtool_core::model::map::Point { line: csv.points[0].line, ..points[0].clone() };
            prop_assert_eq!(&point, &csv.points[0]);
        }
    }
}
