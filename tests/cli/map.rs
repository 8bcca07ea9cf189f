//! Register maps: points read and written by name through `serve`, grouped into requests
//! as the manuals' driver groups them (counted on the wire), the same map as CSV and as
//! Home Assistant YAML, and every malformed map refused before anything is sent.

use crate::support::{mbtool, serve_pty, serve_tcp, PtyPair};

/// One point of each kind, in a device's data file and in a map of it.
const DEVICE: &str = "\
400001 = 230.5 f32
400003 = 1234
400004 = -215
400005 = 70000 u32 CDAB
400007 = 2.5 f32 CDAB
400011 = -5 i64
400015 = 0.125 f64
400020 = \"PUMP 1\" ascii
400023 = 0
400030 = 0x00F0
000001 = on
100001 = 1
300001 = 45
";

const MAP_CSV: &str = "\
# one point of each kind
name,ref,type,order,scale,offset,unit,access
voltage,400001,f32,,,,V,
count,400003,u16,,,,,
temperature,400004,i16,,0.1,,°C,
energy,400005,u32,CDAB,,,Wh,
flow,400007,f32,CDAB,,,m3/h,
balance,400011,i64,,,,,
ratio,400015,f64,,,,,
label,400020,string:4,,,,,
alarm,400030.04,bool,,,,,
pump,000001,,,,,,
door,100001,,,,,,r
inlet,300001,i16,,0.5,-10,°C,r
";

const MAP_YAML: &str = "\
modbus:
  - name: plant
    type: tcp
    host: 127.0.0.1
    port: 502
    sensors:
      - {name: voltage, address: 0, data_type: float32, unit_of_measurement: V, slave: 17}
      - {name: count, address: 2, data_type: uint16}
      - {name: temperature, address: 3, data_type: int16, scale: 0.1, unit_of_measurement: °C}
      - {name: energy, address: 4, data_type: uint32, swap: word, unit_of_measurement: Wh}
      - {name: flow, address: 6, data_type: float32, swap: word, unit_of_measurement: m3/h}
      - {name: balance, address: 10, data_type: int64}
      - {name: ratio, address: 14, data_type: float64}
      - {name: label, address: 19, data_type: string, count: 4}
      - name: inlet
        address: 0
        input_type: input
        data_type: int16
        scale: 0.5
        offset: -10
        unit_of_measurement: °C
    binary_sensors:
      - {name: door, address: 0, input_type: discrete_input}
    switches:
      - {name: pump, address: 0, write_type: coil}
";

fn files(dir: &tempfile::TempDir, entries: &[(&str, &str)]) -> Vec<String> {
    entries
        .iter()
        .map(|(name, text)| {
            let path = dir.path().join(name);
            std::fs::write(&path, text).unwrap();
            path.display().to_string()
        })
        .collect()
}

fn run(port: &[String], args: &[&str]) -> (i32, String, String) {
    let output = mbtool().args(port).args(args).output().unwrap();
    (
        output.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&output.stdout).into_owned(),
        String::from_utf8_lossy(&output.stderr).into_owned(),
    )
}

#[test]
fn every_kind_of_point_reads_the_same_from_csv_and_from_home_assistant_yaml() {
    let dir = tempfile::tempdir().unwrap();
    let paths = files(
        &dir,
        &[
            ("device.txt", DEVICE),
            ("map.csv", MAP_CSV),
            ("ha.yaml", MAP_YAML),
        ],
    );
    let (_device, port, _) = serve_tcp(&["--data", &paths[0]]);
    let (code, values, stderr) = run(&port, &["read", "17", "--map", &paths[1], "-o", "values"]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(
        values,
        "voltage=230.5\ncount=1234\ntemperature=-21.5\nenergy=70000\nflow=2.5\nbalance=-5\n\
         ratio=0.125\nlabel=PUMP 1\nalarm=1\npump=1\ndoor=1\ninlet=12.5\n"
    );
    // The same points from the Home Assistant configuration (no bit of a register there),
    // shown as Home Assistant shows them: whole-number types without decimals unless
    // `precision` says, floats with two.
    let (code, yaml_values, stderr) =
        run(&port, &["read", "17", "--map", &paths[2], "-o", "values"]);
    assert_eq!(code, 0, "{stderr}");
    let mut yaml_sorted: Vec<&str> = yaml_values.lines().collect();
    yaml_sorted.sort_unstable();
    assert_eq!(
        yaml_sorted,
        [
            "balance=-5",
            "count=1234",
            "door=on",
            "energy=70000",
            "flow=2.50",
            "inlet=12",
            "label=PUMP 1",
            "pump=on",
            "ratio=0.12",
            "temperature=-22",
            "voltage=230.50"
        ]
    );
    let (_, json, _) = run(
        &port,
        &[
            "read", "17", "--map", &paths[1], "--json", "voltage", "energy",
        ],
    );
    let json: serde_json::Value = serde_json::from_str(json.trim()).unwrap();
    assert_eq!(
        json,
        serde_json::json!({"slave": 17, "points": [
            {"name": "voltage", "ref": "400001", "value": 230.5, "unit": "V", "raw": [17254, 32768]},
            {"name": "energy", "ref": "400005", "value": 70000, "unit": "Wh", "raw": [4464, 1]},
        ]})
    );
    let (_, csv, _) = run(
        &port,
        &[
            "read",
            "17",
            "--map",
            &paths[1],
            "-o",
            "csv",
            "temperature",
            "label",
        ],
    );
    assert_eq!(
        csv,
        "name,ref,value,unit,raw,error\ntemperature,400004,-21.5,°C,FF29,\nlabel,400020,PUMP 1,,5055 4D50 2031 0000,\n"
    );
    let (_, table, _) = run(&port, &["read", "17", "--map", &paths[1], "inlet"]);
    assert!(
        table.contains("│ inlet ┆ 300001 ┆ 12.5 °C ┆ 002D │"),
        "{table}"
    );
}

#[test]
fn one_points_failure_leaves_the_others_their_values() {
    let dir = tempfile::tempdir().unwrap();
    // The device has the second register of a run of two, and no slave 5 answers.
    let paths = files(
        &dir,
        &[
            ("device.txt", "400002 = 5\n400010 = 7\n400108 = 0\n"),
            (
                "map.csv",
                "name,ref,slave\nfirst,400001,\nsecond,400002,\nelsewhere,400001,5\nlast,400010,\n",
            ),
        ],
    );
    let Some(pair) = PtyPair::new() else { return };
    let (_device, port) = serve_pty(&pair, &["--data", &paths[0]]);
    let read = |format: &str| {
        let started = std::time::Instant::now();
        let got = run(
            &port,
            &[
                "read",
                "17",
                "--map",
                &paths[1],
                "-o",
                format,
                "--timeout",
                "300ms",
            ],
        );
        (got, started.elapsed())
    };
    let ((code, json, stderr), took) = read("json");
    // The first point that failed gives the status: exception 02.
    assert_eq!(code, 12, "{stderr}");
    assert!(
        stderr.contains("mbtool: first: slave 17 answered exception 02")
            && stderr.contains("(2 of 4 points without a value)"),
        "{stderr}"
    );
    // One timeout, not one a point, and no wait on the points that answer.
    assert!(took < std::time::Duration::from_secs(3), "{took:?}");
    let json: serde_json::Value = serde_json::from_str(json.trim()).unwrap();
    let points = json["points"].as_array().unwrap();
    let by_name = |name: &str| points.iter().find(|p| p["name"] == name).unwrap().clone();
    assert_eq!(by_name("second")["value"], 5);
    assert_eq!(by_name("last")["value"], 7);
    assert!(by_name("first")["value"].is_null());
    assert!(by_name("first")["error"]
        .as_str()
        .unwrap()
        .contains("exception 02 illegal data address"));
    assert!(by_name("elsewhere")["error"]
        .as_str()
        .unwrap()
        .starts_with("no answer from slave 5"));
    let ((code, csv, _), _) = read("csv");
    assert_eq!(code, 12);
    let rows: Vec<&str> = csv.lines().collect();
    assert_eq!(rows[0], "name,ref,value,unit,raw,error");
    assert!(rows.contains(&"second,400002,5,,0005,"), "{csv}");
    assert!(
        rows.iter()
            .any(|r| r.starts_with("first,400001,,,,slave 17 answered exception 02")),
        "{csv}"
    );
    let ((_, table, _), _) = read("table");
    assert!(table.contains("│ second    ┆ 400002 ┆ 5 "), "{table}");
    // A poll logs a row for every point, each naming its point, and goes on.
    let (code, rows, _) = run(
        &port,
        &[
            "read",
            "17",
            "--map",
            &paths[1],
            "-o",
            "csv",
            "--poll",
            "100ms",
            "--count",
            "2",
            "--timeout",
            "300ms",
        ],
    );
    assert_eq!(code, 12);
    let named: Vec<&str> = rows
        .lines()
        .skip(1)
        .map(|row| row.split(',').nth(1).unwrap())
        .collect();
    assert_eq!(
        named,
        [
            "first",
            "second",
            "elsewhere",
            "last",
            "first",
            "second",
            "elsewhere",
            "last"
        ]
    );
}

/// A device silent for an address it lacks (no exception, no answer): the run of points
/// that holds it is read again in halves, and only that point has no value.
#[test]
fn a_point_the_device_is_silent_for_is_that_points_alone() {
    let device = crate::support::scripted_tcp_device(|_, pdu| {
        let [3, hi, lo, qh, ql] = pdu[..] else {
            return crate::support::Act::Silent;
        };
        let (start, count) = (u16::from_be_bytes([hi, lo]), u16::from_be_bytes([qh, ql]));
        if (start..start + count).contains(&1) {
            return crate::support::Act::Silent;
        }
        let mut answer = vec![3, (count * 2) as u8];
        for address in start..start + count {
            answer.extend((address + 100).to_be_bytes());
        }
        crate::support::Act::Answer(answer)
    });
    let dir = tempfile::tempdir().unwrap();
    let map = files(
        &dir,
        &[(
            "m.csv",
            "name,ref\na,400001\nb,400002\nc,400003\nd,400004\n",
        )],
    );
    let port = vec!["--port".to_string(), format!("127.0.0.1:{device}")];
    let (code, values, stderr) = run(
        &port,
        &[
            "read",
            "1",
            "--map",
            &map[0],
            "-o",
            "values",
            "--timeout",
            "200ms",
        ],
    );
    assert_eq!(code, 3, "{stderr}");
    assert_eq!(values, "a=100\nc=102\nd=103\n");
    assert!(
        stderr.contains("mbtool: b: no answer from slave 1"),
        "{stderr}"
    );
}

/// A Home Assistant map gives every entity its slave (1 where it gives none) and where its
/// device is: `read --map FILE [NAME...]` needs neither SLAVE nor --port. A CSV map whose
/// points give no slave asks for SLAVE.
#[test]
fn a_map_that_gives_the_slave_needs_none_typed() {
    let dir = tempfile::tempdir().unwrap();
    let (_device, _, port) = serve_tcp(&[
        "--slave",
        "1",
        "--data",
        &files(&dir, &[("d.txt", "400001 = 11\n400002 = 22\n")])[0],
    ]);
    let yaml = format!(
        "modbus:\n  - name: h\n    type: tcp\n    host: 127.0.0.1\n    port: {port}\n    sensors:\n      - {{name: a, address: 0}}\n      - {{name: b, address: 1}}\n"
    );
    let paths = files(
        &dir,
        &[("h.yaml", &yaml), ("m.csv", "name,ref\na,400001\n")],
    );
    let (code, values, stderr) = run(&[], &["read", "--map", &paths[0], "-o", "values"]);
    assert_eq!((code, values.as_str()), (0, "a=11\nb=22\n"), "{stderr}");
    let (code, values, stderr) = run(&[], &["read", "--map", &paths[0], "b", "-o", "values"]);
    assert_eq!((code, values.as_str()), (0, "b=22\n"), "{stderr}");
    let (code, _, stderr) = run(&[], &["read", "--map", &paths[1]]);
    assert_eq!(code, 2);
    assert!(stderr.contains("gives a no slave: give SLAVE"), "{stderr}");
}

/// `write --map` without SLAVE writes where the map gives the points written their slave,
/// and otherwise names the point written and how to give SLAVE to a write.
#[test]
fn a_write_by_name_needs_a_slave_only_for_the_points_it_writes() {
    let dir = tempfile::tempdir().unwrap();
    let map = "name,ref,type,slave\nspeed,400001,u16,17\nlevel,400002,u16\n";
    let path = &files(&dir, &[("m.csv", map)])[0];
    let sim = ["--port".to_string(), "sim".to_string()];
    let (code, said, stderr) = run(&sim, &["write", "--map", path, "speed=7"]);
    assert_eq!(
        (code, said.as_str()),
        (0, "wrote speed = 7 (400001)\n"),
        "{stderr}"
    );
    let (code, said, stderr) = run(&sim, &["write", "--map", path, "level=7"]);
    assert_eq!((code, said.as_str()), (2, ""));
    assert_eq!(
        stderr,
        format!("mbtool: {path} gives level no slave: give SLAVE (write SLAVE --map {path} NAME=VALUE)\n")
    );
}

/// How many requests `read --map` sends for `refs`, counted in its `-v` trace.
fn requests_for(
    port: &[String],
    dir: &tempfile::TempDir,
    refs: &[&str],
    max: Option<&str>,
) -> usize {
    let map: String = refs
        .iter()
        .enumerate()
        .map(|(i, r)| format!("p{i},{r}\n"))
        .collect();
    let path = files(dir, &[("points.csv", &format!("name,ref\n{map}"))]).remove(0);
    let mut args = vec!["read", "17", "--map", &path, "-v"];
    if let Some(max) = max {
        args.extend(["--max-per-request", max]);
    }
    let (code, _, trace) = run(port, &args);
    assert_eq!(code, 0, "{trace}");
    trace.lines().filter(|line| line.contains("] > ")).count()
}

#[test]
fn points_are_grouped_as_the_manuals_driver_groups_them() {
    let dir = tempfile::tempdir().unwrap();
    let (_device, port, _) = serve_tcp(&[]);
    let first_five = ["400001", "400002", "400003", "400004", "400005", "400120"];
    assert_eq!(requests_for(&port, &dir, &first_five, Some("120")), 1);
    assert_eq!(requests_for(&port, &dir, &first_five, Some("3")), 3);
    assert_eq!(requests_for(&port, &dir, &first_five, None), 2);
    let spread = ["400001", "400010", "400011", "400021", "400031", "400041"];
    assert_eq!(requests_for(&port, &dir, &spread, Some("10")), 5);
    assert_eq!(requests_for(&port, &dir, &spread, None), 5);
    // encode prints the frames a map read sends: here the one request of 120 registers.
    let map = files(
        &dir,
        &[(
            "five.csv",
            "name,ref
a,400001
b,400005
c,400120
",
        )],
    )
    .remove(0);
    let (code, frames, _) = run(
        &[],
        &[
            "encode",
            "read",
            "17",
            "--map",
            &map,
            "--max-per-request",
            "120",
        ],
    );
    assert_eq!((code, frames.as_str()), (0, "11 03 00 00 00 78 47 78\n"));
}

#[test]
fn a_request_across_holes_that_is_refused_is_read_again_run_by_run() {
    let dir = tempfile::tempdir().unwrap();
    let paths = files(
        &dir,
        &[
            ("device.txt", "400001 = 7\n400010-400011 = 8 9\n"),
            ("map.csv", "name,ref\na,400001\nb,400010\nc,400011\n"),
        ],
    );
    let (_device, port, _) = serve_tcp(&["--data", &paths[0]]);
    let (code, values, stderr) = run(
        &port,
        &[
            "read",
            "17",
            "--map",
            &paths[1],
            "--max-per-request",
            "20",
            "-o",
            "values",
        ],
    );
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(values, "a=7\nb=8\nc=9\n");
    assert_eq!(
        stderr,
        "mbtool: a request spanning addresses no point names was refused; its points were read again one run at a time\n"
    );
}

#[test]
fn writes_by_name_round_trip_every_writable_kind() {
    let dir = tempfile::tempdir().unwrap();
    let paths = files(&dir, &[("device.txt", DEVICE), ("map.csv", MAP_CSV)]);
    let (_device, port, _) = serve_tcp(&["--data", &paths[0]]);
    let (code, said, stderr) = run(
        &port,
        &[
            "write",
            "17",
            "--map",
            &paths[1],
            "voltage=231.25",
            "count=4321",
            "temperature=-3.5",
            "energy=123456",
            "flow=0.75",
            "balance=-9000000000",
            "ratio=1e-3",
            "label=AB C",
            "alarm=0",
            "pump=off",
        ],
    );
    assert_eq!(code, 0, "{stderr}");
    assert!(
        said.starts_with("wrote voltage = 231.25 V (400001)\n"),
        "{said}"
    );
    let (_, values, _) = run(&port, &["read", "17", "--map", &paths[1], "-o", "values"]);
    assert_eq!(
        values,
        "voltage=231.25\ncount=4321\ntemperature=-3.5\nenergy=123456\nflow=0.75\n\
         balance=-9000000000\nratio=0.001\nlabel=AB C\nalarm=0\npump=0\ndoor=1\ninlet=12.5\n"
    );
}

#[test]
fn a_bad_write_by_name_is_refused_before_anything_is_sent() {
    let dir = tempfile::tempdir().unwrap();
    let path = files(&dir, &[("map.csv", MAP_CSV)]).remove(0);
    // Nothing listens there: a command that got as far as connecting would say so.
    let port = vec!["--port".to_string(), "127.0.0.1:9".to_string()];
    for (words, says) in [
        (
            "count=70000",
            "count: 70000 is out of range for this u16 point: give 0 to 65535",
        ),
        (
            "count=-1",
            "count: -1 is out of range for this u16 point: give 0 to 65535",
        ),
        ("door=1", "door (100001) is read-only in the map"),
        ("inlet=20", "inlet (300001) is read-only in the map"),
        (
            "label=TOO LONG A NAME",
            "takes 8 registers; the point holds 4",
        ),
        (
            "voltag=1",
            "has no point named 'voltag': did you mean 'voltage'?",
        ),
        ("voltage", "'voltage': give NAME=VALUE"),
    ] {
        let (code, _, stderr) = run(&port, &["write", "17", "--map", &path, words]);
        assert_eq!(code, 2, "{words}: {stderr}");
        assert!(stderr.contains(says), "{words}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
    }
}

#[test]
fn every_malformed_map_names_its_file_and_line() {
    let dir = tempfile::tempdir().unwrap();
    let port = vec!["--port".to_string(), "127.0.0.1:9".to_string()];
    let long = format!("name,ref\n{},400001\n", "n".repeat(1_000_000));
    for (name, text, says) in [
        (
            "long.csv",
            long.as_str(),
            ":2: a name of 1000000 characters: give one of at most 128",
        ),
        (
            "dup.csv",
            "name,ref\na,400001\na,400002\n",
            ":3: the name 'a' is taken already, on line 2",
        ),
        (
            "overlap.csv",
            "name,ref,type\na,400001,u32\nb,400002\n",
            ":3: b (400002) overlaps a (400001, line 2)",
        ),
        (
            "wide.csv",
            "name,ref,type\nc,000001,f32\n",
            ":2: c: type f32 does not fit in a coil",
        ),
        (
            "column.csv",
            "name,ref,colour\n",
            ":1: unknown column 'colour'",
        ),
        (
            "line.csv",
            "name,ref\nd,4000001\n",
            ":2: '4000001' is not a Modicon reference",
        ),
        (
            "bad.yaml",
            "modbus:\n  - sensors:\n      - {name: e, address: 0, data_type: int12}\n",
            ":3: e: data_type 'int12'",
        ),
        (
            "nan.yaml",
            "modbus:\n  - sensors:\n      - {name: f, address: 0, scale: .nan}\n",
            ":3: f: scale '.nan' is not a number",
        ),
        (
            "nan.csv",
            "name,ref,offset\nf,400001,inf\n",
            ":2: f: offset inf: give a finite number",
        ),
        (
            "count.yaml",
            "modbus:\n  - sensors:\n      - name: g\n        address: 0\n        data_type: int32\n        count: 1\n",
            ":3: g: count 1: int32 takes 2 registers; leave count out",
        ),
        (
            "switch.yaml",
            "modbus:\n  - switches:\n      - {name: h, address: 0, write_type: input}\n",
            ":3: h: write_type 'input': give holding, holdings, coil, coils",
        ),
        (
            "coil.yaml",
            "modbus:\n  - binary_sensors:\n      - {name: i, address: 0, input_type: sideways}\n",
            ":3: i: input_type 'sideways': give coil, discrete_input, holding, input",
        ),
    ] {
        let path = files(&dir, &[(name, text)]).remove(0);
        let (code, _, stderr) = run(&port, &["read", "17", "--map", &path]);
        assert_eq!(code, 2, "{name}: {stderr}");
        assert!(
            stderr.starts_with(&format!("mbtool: {path}")),
            "{name}: {stderr}"
        );
        assert!(stderr.contains(says), "{name}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
    }
}

#[test]
fn every_request_across_holes_that_is_refused_is_read_again() {
    let dir = tempfile::tempdir().unwrap();
    let paths = files(
        &dir,
        &[
            (
                "device.txt",
                "400001 = 1\n400003 = 3\n400201 = 5\n400203 = 7\n",
            ),
            (
                "map.csv",
                "\u{feff}name,ref,\na,400001\n,,\nb,400003\nc,400201\nd,400203\n",
            ),
        ],
    );
    let (_device, port, _) = serve_tcp(&["--data", &paths[0]]);
    let (code, values, stderr) = run(
        &port,
        &[
            "read",
            "17",
            "--map",
            &paths[1],
            "--max-per-request",
            "10",
            "-o",
            "values",
        ],
    );
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(values, "a=1\nb=3\nc=5\nd=7\n");
}

#[test]
fn a_map_is_refused_where_it_cannot_be_what_it_says() {
    let dir = tempfile::tempdir().unwrap();
    let paths = files(
        &dir,
        &[
            ("wide.csv", "name,ref,type\nlabel,400001,string:10\n"),
            ("zero.csv", "name,ref,scale\nx,400001,0\n"),
            (
                "bits.csv",
                "name,ref,type\nstatus,400010,u16\nalarm,400010.03,bool\n",
            ),
        ],
    );
    let nowhere = vec!["--port".to_string(), "127.0.0.1:9".to_string()];
    let refused = |args: &[&str], says: &str| {
        let (code, _, stderr) = run(&nowhere, args);
        assert_eq!(code, 2, "{args:?}: {stderr}");
        assert!(stderr.contains(says), "{args:?}: {stderr}");
    };
    refused(
        &["read", "17", "--map", &paths[0], "--max-per-request", "4"],
        "--max-per-request 4 is less than label takes (10 registers)",
    );
    refused(
        &["read", "17", "--map", &paths[1]],
        ":2: x: scale 0 would show every value as the offset",
    );
    refused(
        &["write", "17", "--map", &paths[2]],
        "write --map needs NAME=VALUE",
    );
    // A read may not go to slave 0 on a serial line, by map or not.
    let (code, _, stderr) = run(
        &["--port".into(), "/dev/nonexistent-tty".into()],
        &["read", "0", "--map", &paths[2]],
    );
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("slave 0 is broadcast"), "{stderr}");
    // A status word and one of its bits are two points.
    let (code, _, stderr) = run(&["encode".into()], &["read", "17", "--map", &paths[2]]);
    assert_eq!(code, 0, "{stderr}");
}

#[test]
fn a_write_says_what_the_point_holds_of_the_value_asked() {
    let map = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/pump3.csv");
    let data = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/pump3.txt");
    let (_device, port, _) = serve_tcp(&["--data", data]);
    let (code, said, stderr) = run(&port, &["write", "17", "--map", map, "pressure_max=2.56"]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(said, "wrote pressure_max = 2.6 bar (400020) (asked 2.56)\n");
}

/// A map (and a data file) with several mistakes tells them all at once, one line each
/// with its file:line, in the order of the file, and at most twenty.
#[test]
fn every_fault_of_a_map_or_data_file_is_told_at_once() {
    let dir = tempfile::tempdir().unwrap();
    let many: String = (0..30).map(|i| format!("p{i},4000{i:02}x\n")).collect();
    let paths = files(
        &dir,
        &[
            (
                "three.csv",
                "name,ref,type,scale\na,400001,f32,\nb,400010,,0\nc,000001,u32,\na,400020,,\n",
            ),
            ("many.csv", &format!("name,ref\n{many}")),
            (
                "three.yaml",
                "modbus:\n  - sensors:\n      - {name: d, address: 0, scale: .nan}\n      - {name: e, address: 1, data_type: int32, count: 1}\n      - {name: f, address: 9, swap: sideways}\n",
            ),
            ("device.txt", "400001-400003 = 1 2\n400010 = x\n400020 = 5\nfoo\n"),
        ],
    );
    let nowhere = vec!["--port".to_string(), "127.0.0.1:9".to_string()];
    let faults = |args: &[&str]| {
        let (code, _, stderr) = run(&nowhere, args);
        assert_eq!(code, 2, "{args:?}: {stderr}");
        assert!(
            stderr.lines().all(|l| l.starts_with("mbtool: ")),
            "{stderr}"
        );
        stderr
            .lines()
            .map(|line| line.split(':').nth(2).unwrap_or_default().to_string())
            .collect::<Vec<_>>()
    };
    assert_eq!(faults(&["read", "17", "--map", &paths[0]]), ["3", "4", "5"]);
    let many = faults(&["read", "17", "--map", &paths[1]]);
    assert_eq!(many.len(), 21, "{many:?}");
    let (_, _, stderr) = run(&nowhere, &["read", "17", "--map", &paths[1]]);
    assert!(stderr.ends_with("mbtool: ... and 10 more\n"), "{stderr}");
    assert_eq!(faults(&["read", "17", "--map", &paths[2]]), ["3", "4", "5"]);
    assert_eq!(
        faults(&["restore", "17", &paths[3], "--dry-run"]),
        ["1", "2", "4"]
    );
}

/// A Home Assistant file's hub says where the device is: without --port, a read or write by
/// its map goes there (TCP host and port, or a serial device and its line); what the
/// command line gives wins.
#[test]
fn a_home_assistant_hub_says_where_the_device_is() {
    let dir = tempfile::tempdir().unwrap();
    let data = files(
        &dir,
        &[("device.txt", "400001 = 230\n400002 = 7\n400003 = 0\n")],
    )
    .remove(0);
    let (_device, _, tcp_port) = serve_tcp(&["--data", &data]);
    let yaml = format!(
        "modbus:\n  - name: pump station\n    type: tcp\n    host: 127.0.0.1\n    port: {tcp_port}\n    sensors:\n      - {{name: voltage, address: 0, slave: 17}}\n      - {{name: flow, address: 1, slave: 17}}\n    switches:\n      - {{name: valve, address: 2, write_type: holding, slave: 17}}\n"
    );
    let path = files(&dir, &[("ha.yaml", &yaml)]).remove(0);
    let (code, values, stderr) = run(&[], &["read", "17", "--map", &path, "-o", "values"]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(values, "voltage=230\nflow=7\nvalve=off\n");
    let (code, _, stderr) = run(&[], &["write", "17", "--map", &path, "valve=1"]);
    assert_eq!(code, 0, "{stderr}");
    let (_, values, _) = run(
        &[],
        &["read", "17", "--map", &path, "valve", "-o", "values"],
    );
    assert_eq!(values, "valve=on\n");
    // Off, as a word, is the switch's command_off (0 unless given).
    let (code, _, stderr) = run(&[], &["write", "17", "--map", &path, "valve=off"]);
    assert_eq!(code, 0, "{stderr}");
    let (_, values, _) = run(
        &[],
        &["read", "17", "--map", &path, "valve", "-o", "values"],
    );
    assert_eq!(values, "valve=off\n");
    // The command line wins: its port is the one asked.
    let (code, _, stderr) = run(
        &["--port".into(), "127.0.0.1:9".into()],
        &["read", "17", "--map", &path],
    );
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("127.0.0.1:9"), "{stderr}");
    // Entities carry their own slave: those are asked whatever SLAVE says, and the user is
    // told, and JSON says which slave each point came from.
    let (code, json, stderr) = run(&[], &["read", "5", "--map", &path, "voltage", "--json"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stderr.contains(
            "gives points their own slave (17): those are asked, slave 5 only for the others"
        ),
        "{stderr}"
    );
    assert!(json.contains("\"slave\":17"), "{json}");
    // Two hubs in one file are two devices: none is taken for all, --port is asked for.
    let two = format!(
        "{yaml}  - name: boiler\n    type: tcp\n    host: 127.0.0.2\n    port: {tcp_port}\n    sensors:\n      - {{name: heat, address: 5, slave: 17}}\n"
    );
    let path_two = files(&dir, &[("two.yaml", &two)]).remove(0);
    let (code, _, stderr) = run(&[], &["read", "17", "--map", &path_two]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("its hubs are several devices (pump station at tcp://127.0.0.1:")
            && stderr.ends_with("; give --port\n"),
        "{stderr}"
    );
    // A place kept in Home Assistant's secrets is found in the secrets.yaml beside the
    // file, or above it; where there is none, the message names the key, the secret and
    // where it looked, and --port is asked for.
    let secret = yaml.replace("host: 127.0.0.1", "host: !secret pump_host");
    std::fs::create_dir(dir.path().join("packages")).unwrap();
    let path = files(&dir, &[("packages/secret.yaml", &secret)]).remove(0);
    let (code, _, stderr) = run(&[], &["read", "17", "--map", &path]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains(": where the device is is not known: host is !secret pump_host, and no secrets.yaml was found in ")
            && stderr.ends_with("; give --port\n"),
        "{stderr}"
    );
    files(&dir, &[("secrets.yaml", "pump_host: 127.0.0.1\n")]);
    let (code, json, stderr) = run(&[], &["read", "5", "--map", &path, "voltage", "--json"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(json.contains("\"slave\":17"), "{json}");
}

#[test]
fn a_home_assistant_serial_hub_gives_the_device_and_its_line() {
    let Some(pair) = PtyPair::new() else { return };
    let (_server, _) = serve_pty(&pair, &["--parity", "none"]);
    let dir = tempfile::tempdir().unwrap();
    let yaml = format!(
        "modbus:\n  - name: line 1\n    type: serial\n    port: {}\n    baudrate: 9600\n    parity: N\n    bytesize: 8\n    stopbits: 2\n    method: rtu\n    sensors:\n      - {{name: setpoint, address: 107}}\n",
        pair.b.display()
    );
    let path = files(&dir, &[("ha.yaml", &yaml)]).remove(0);
    let (code, values, stderr) = run(&[], &["read", "17", "--map", &path, "-o", "values"]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(values, "setpoint=555\n");
}
