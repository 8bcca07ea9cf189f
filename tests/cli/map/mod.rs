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
    let mut lines = rows.lines();
    assert_eq!(lines.next(), Some("time,first,second,elsewhere,last,error"));
    let polls: Vec<Vec<&str>> = lines.map(|row| row.splitn(6, ',').collect()).collect();
    assert_eq!(polls.len(), 2, "{rows}");
    for poll in polls {
        // A cell a point: the ones read have their values, the failed ones none, and the
        // error column names the first that failed.
        assert_eq!(poll[1..5], ["", "5", "", "7"], "{rows}");
        assert!(poll[5].starts_with("first: "), "{rows}");
    }
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

mod files;
