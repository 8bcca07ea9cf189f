//! Map files refused or written to, and where a Home Assistant hub says its device is

use super::*;

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
