//! `sunspec`: a SunSpec device laid out by pysunspec2 (the SunSpec Alliance's library) and
//! served by `serve`, read by mbtool as pysunspec2 reads it, in fewer requests; the map it
//! writes read back to the same values; the usual bases, a device that refuses reads past
//! its map, and devices that are no SunSpec device.

use std::collections::BTreeMap;
use std::path::Path;
use std::process::Command as Process;
use std::time::{Duration, Instant};

use crate::support::{mbtool, peer_available, python_has, serve_tcp};

const DEVICE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/peers/sunspec_device.py");
const EXAMPLE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/sunspec-inverter.txt");

/// `mbtool sunspec` with `args`, of the device on `port`.
fn sunspec(port: &[String], args: &[&str]) -> std::process::Output {
    mbtool()
        .args(port)
        .arg("sunspec")
        .args(args)
        .output()
        .unwrap()
}

/// `serve` standing for slave 1 with the registers of `data` (a data file's text).
fn serve_data(data: &str) -> (tempfile::TempDir, crate::support::Stopped, Vec<String>) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("device.txt");
    std::fs::write(&path, data).unwrap();
    let (server, port, _) = serve_tcp(&["--slave", "1", "--data", &path.display().to_string()]);
    (dir, server, port)
}

/// The points with a value, by name, as `sunspec -o json` gives them; and its requests.
fn mbtool_reading(port: &[String], extra: &[&str]) -> (BTreeMap<String, serde_json::Value>, u64) {
    let output = mbtool()
        .args(port)
        .args(["sunspec", "1", "-o", "json"])
        .args(extra)
        .output()
        .unwrap();
    assert!(output.status.success(), "{output:?}");
    let device: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    let mut points = BTreeMap::new();
    for model in device["models"].as_array().unwrap() {
        for point in model["points"].as_array().unwrap() {
            if !point["value"].is_null() {
                points.insert(
                    point["name"].as_str().unwrap().into(),
                    point["value"].clone(),
                );
            }
        }
    }
    (points, device["requests"].as_u64().unwrap())
}

/// pysunspec2's reading, by its `tcp` or `file` client.
fn pysunspec2_reading(args: &[&str]) -> (BTreeMap<String, serde_json::Value>, u64) {
    let output = Process::new("python3")
        .arg(DEVICE)
        .args(args)
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let reading: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    let points = reading["points"]
        .as_object()
        .unwrap()
        .iter()
        .map(|(name, value)| (name.clone(), value.clone()))
        .collect();
    (points, reading["requests"].as_u64().unwrap())
}

/// The same names and values: numbers equal to the last digit pysunspec2 rounds to.
fn assert_same(
    mine: &BTreeMap<String, serde_json::Value>,
    theirs: &BTreeMap<String, serde_json::Value>,
    whose: &str,
) {
    let names =
        |points: &BTreeMap<String, serde_json::Value>| points.keys().cloned().collect::<Vec<_>>();
    assert_eq!(
        names(mine),
        names(theirs),
        "the points {whose} gives a value"
    );
    for (name, value) in mine {
        let other = &theirs[name];
        match (value.as_f64(), other.as_f64()) {
            (Some(a), Some(b)) => assert!(
                (a - b).abs() <= 1e-9 * b.abs().max(1.0),
                "{name}: {a} and {whose}'s {b}"
            ),
            _ => assert_eq!(value, other, "{name}"),
        }
    }
}

fn image(dir: &Path, base: u16) -> (String, String) {
    let data = dir.join(format!("device-{base}.txt"));
    let json = dir.join(format!("device-{base}.json"));
    let made = Process::new("python3")
        .args([DEVICE, "image", &base.to_string()])
        .arg(&data)
        .arg(&json)
        .output()
        .unwrap();
    assert!(
        made.status.success(),
        "{}",
        String::from_utf8_lossy(&made.stderr)
    );
    (data.display().to_string(), json.display().to_string())
}

#[test]
fn a_device_reads_as_pysunspec2_reads_it_in_fewer_requests() {
    if !peer_available("pysunspec2 (Python)", python_has("sunspec2")) {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    for base in [40000, 50000, 0] {
        let (data, json) = image(dir.path(), base);
        let (_server, port, tcp) = serve_tcp(&["--slave", "1", "--data", &data]);
        let (mine, my_requests) = mbtool_reading(&port, &[]);
        // Models 1, 103, 120, 121 and 160 (two modules), 92 points with a value.
        assert_eq!(mine.len(), 92, "{mine:?}");
        assert_eq!(mine["inverter_three_phase.PhVphA"], 230.1);
        assert_eq!(mine["mppt.module_2.DCV"], 379.9);
        assert_eq!(mine["common.Mn"], "SunSpecTest");
        assert!(
            !mine.contains_key("inverter_three_phase.AphC"),
            "not implemented"
        );
        let (over_tcp, their_requests) = pysunspec2_reading(&["tcp", &tcp.to_string(), "1"]);
        assert_same(&mine, &over_tcp, "pysunspec2's Modbus client");
        let (from_file, _) = pysunspec2_reading(&["file", &json]);
        assert_same(&mine, &from_file, "pysunspec2's file device");
        assert!(
            my_requests * 2 <= their_requests,
            "at {base}: {my_requests} requests, pysunspec2 {their_requests}"
        );
    }
}

#[test]
fn the_map_written_reads_back_the_same_values() {
    let (_server, port, _) = serve_tcp(&["--slave", "1", "--data", EXAMPLE]);
    let dir = tempfile::tempdir().unwrap();
    let map = dir.path().join("inverter.csv");
    let map_text = map.display().to_string();
    let scanned = sunspec(&port, &["1", "-o", "values", "--map-out", &map_text]);
    assert!(scanned.status.success(), "{scanned:?}");
    let told = String::from_utf8_lossy(&scanned.stderr);
    assert!(
        told.contains(&format!("92 points written to {map_text}")),
        "{told}"
    );
    let read = mbtool()
        .args(&port)
        .args(["read", "1", "--map", &map_text, "-o", "values"])
        .output()
        .unwrap();
    assert!(read.status.success(), "{read:?}");
    assert_eq!(
        String::from_utf8_lossy(&read.stdout),
        String::from_utf8_lossy(&scanned.stdout)
    );
    let text = std::fs::read_to_string(&map).unwrap();
    assert!(
        text.contains(
            "inverter_three_phase.PhVphA,440081,u16,ABCD,0.1,0,V,r,65535,Phase Voltage AN"
        ),
        "{text}"
    );
    // A write by name goes where the map says, scaled back.
    let written = mbtool()
        .args(&port)
        .args(["write", "1", "--map", &map_text, "settings.VMax=254.5"])
        .output()
        .unwrap();
    assert!(written.status.success(), "{written:?}");
    let (after, _) = mbtool_reading(&port, &[]);
    assert_eq!(after["settings.VMax"], 254.5);
    // A point the device later marks as not implemented (at night, say) is read as
    // unknown through the map, never as 6553.5 V or -32768 W.
    for (reference, mark) in [("440081", "0xFFFF"), ("440085", "0x8000")] {
        let marked = mbtool()
            .args(&port)
            .args(["write-register", "1", reference, mark])
            .output()
            .unwrap();
        assert!(marked.status.success(), "{marked:?}");
    }
    let read = mbtool()
        .args(&port)
        .args(["read", "1", "--map", &map_text, "-o", "csv"])
        .args(["inverter_three_phase.PhVphA", "inverter_three_phase.W"])
        .output()
        .unwrap();
    assert_eq!(
        String::from_utf8_lossy(&read.stdout),
        "name,ref,value,unit,raw,error\n\
         inverter_three_phase.PhVphA,440081,unknown,V,FFFF,\n\
         inverter_three_phase.W,440085,unknown,W,8000,\n"
    );
}

#[test]
fn the_table_names_scales_and_leaves_out_what_is_not_implemented() {
    let (_server, port, _) = serve_tcp(&["--slave", "1", "--data", EXAMPLE]);
    let started = Instant::now();
    let output = mbtool()
        .args(&port)
        .args(["--timeout", "5s", "sunspec", "1"])
        .output()
        .unwrap();
    // Every answer is there at once: no read waits for its timeout.
    assert!(
        started.elapsed() < Duration::from_secs(1),
        "{:?}",
        started.elapsed()
    );
    assert!(output.status.success(), "{output:?}");
    let table = String::from_utf8_lossy(&output.stdout);
    for line in [
        "model 103 inverter_three_phase (Inverter (Three Phase)) at 440071, 50 registers",
        "│ inverter_three_phase.PhVphA  ┆ 230.1 V                        ┆ 440081 │",
        "│ inverter_three_phase.St      ┆ 4 (MPPT)                       ┆ 440109 │",
        "│ inverter_three_phase.Evt1    ┆ 5 (GROUND_FAULT,AC_DISCONNECT) ┆ 440111 │",
        "11 points not implemented by the device",
        "│ mppt.module_2.IDStr ┆ PV2       ┆ 440214 │",
        "model 64999 model_64999 at 440233, 4 registers",
        "SunSpec has published no definition of it",
    ] {
        assert!(table.contains(line), "{line}\n{table}");
    }
    assert!(!table.contains("AphC"), "{table}");
    let told = String::from_utf8_lossy(&output.stderr);
    assert!(
        told.contains("SunS at 440001: 6 models, read in 7 requests"),
        "{told}"
    );
}

#[test]
fn a_device_that_refuses_reads_across_its_models_is_read_model_by_model() {
    // A device that refuses any read crossing from one model into the next (each model's
    // first register after the common model a boundary), as some inverters do.
    let text = std::fs::read_to_string(EXAMPLE).unwrap();
    let line = text.lines().find(|l| l.starts_with("440001 = ")).unwrap();
    let words: Vec<u16> = line[9..].split(' ').map(|w| w.parse().unwrap()).collect();
    let mut boundaries = Vec::new();
    let mut at = 2;
    while at < words.len() {
        at += 2 + if words[at] == 0xFFFF {
            0
        } else {
            usize::from(words[at + 1])
        };
        boundaries.push((40000 + at).to_string());
    }
    let port = crate::support::free_port();
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/peers/bounded_device.py");
    let _device = crate::support::Stopped(
        Process::new("python3")
            .args([script, EXAMPLE, &port.to_string(), &boundaries.join(",")])
            .spawn()
            .unwrap(),
    );
    crate::hosts::listening("127.0.0.1", port);
    let bounded = vec!["--port".to_string(), format!("tcp://127.0.0.1:{port}")];
    let (split, requests) = mbtool_reading(&bounded, &[]);
    let (_whole_server, whole_port, _) = serve_tcp(&["--slave", "1", "--data", EXAMPLE]);
    let (whole, _) = mbtool_reading(&whole_port, &[]);
    assert_eq!(split, whole);
    // The marker, a read ahead refused and one with the next header refused, then a
    // header and a body a model: never more than pysunspec2's 18 on this device.
    assert!(requests <= 16, "{requests} requests");
    if peer_available("pysunspec2 (Python)", python_has("sunspec2")) {
        let (theirs, their_requests) = pysunspec2_reading(&["tcp", &port.to_string(), "1"]);
        assert_same(&split, &theirs, "pysunspec2");
        assert!(
            requests < their_requests,
            "{requests} against {their_requests}"
        );
    }
}

#[test]
fn a_device_without_a_map_is_told_and_a_silent_one_times_out() {
    // serve's own example data: every register exists, none holds SunS.
    let (_server, port, _) = serve_tcp(&["--slave", "1"]);
    let output = sunspec(&port, &["1"]);
    assert_eq!(output.status.code(), Some(1), "{output:?}");
    let told = String::from_utf8_lossy(&output.stderr);
    assert!(
        told.starts_with("mbtool: slave 1: no SunSpec map: register 40000: ")
            && told.contains("register 50000: ")
            && told.contains("register 0: ")
            && told
                .trim_end()
                .ends_with("give --base ADDRESS where the device's manual puts its SunSpec map"),
        "{told}"
    );
    assert_eq!(told.lines().count(), 1, "{told}");
    // A unit serve does not stand for: 0B at every base, told as the exception it is.
    let absent = sunspec(&port, &["9"]);
    assert_eq!(absent.status.code(), Some(21), "{absent:?}");
    // A device that takes the connection and never answers.
    let listener = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    let silent_port = format!("tcp://{}", listener.local_addr().unwrap());
    let started = Instant::now();
    let silent = mbtool()
        .args(["--port", &silent_port, "--timeout", "100ms", "sunspec", "1"])
        .output()
        .unwrap();
    assert_eq!(silent.status.code(), Some(3), "{silent:?}");
    assert!(
        started.elapsed() < Duration::from_secs(3),
        "{:?}",
        started.elapsed()
    );
    // --base names the one place to look.
    let (_image, image_port, _) = serve_tcp(&["--slave", "1", "--data", EXAMPLE]);
    let there = sunspec(&image_port, &["1", "--base", "40000", "-o", "values"]);
    assert!(there.status.success(), "{there:?}");
    let elsewhere = sunspec(&image_port, &["1", "--base", "50000"]);
    // Refused there: the device's exception 02.
    assert_eq!(elsewhere.status.code(), Some(12), "{elsewhere:?}");
}

#[test]
fn a_map_that_cannot_be_written_is_told_before_the_device_is_asked() {
    let output = mbtool()
        .args([
            "--port",
            "tcp://127.0.0.1:9",
            "sunspec",
            "1",
            "--map-out",
            "/nonexistent/map.csv",
        ])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(1), "{output:?}");
    let told = String::from_utf8_lossy(&output.stderr);
    assert!(
        told.starts_with("mbtool: cannot write /nonexistent/map.csv"),
        "{told}"
    );
}

#[test]
fn registers_the_device_refuses_leave_their_points_without_a_value() {
    // Two registers of the inverter model refused (exception 04), as a device with a
    // broken sensor may: those points have none, every other has its value.
    let (_server, port, _) = serve_tcp(&[
        "--slave",
        "1",
        "--data",
        EXAMPLE,
        "--exception",
        "4@440100-440101",
    ]);
    let output = sunspec(&port, &["1", "-o", "csv"]);
    assert_eq!(output.status.code(), Some(14), "{output:?}");
    let csv = String::from_utf8_lossy(&output.stdout);
    assert!(
        csv.contains("103,inverter_three_phase.DCV,440100,,V,,0000,the device refused its registers (slave device failure)"),
        "{csv}"
    );
    assert!(
        csv.contains("103,inverter_three_phase.DCW,440102,5200,W,,1450,"),
        "{csv}"
    );
    assert!(
        csv.contains("160,mppt.module_2.DCV,440223,379.9,V,,0ED7,"),
        "{csv}"
    );
    let told = String::from_utf8_lossy(&output.stderr);
    assert!(
        told.contains("mbtool: model 103 at 440071: the device refused 2 of its registers (slave device failure); the points it leaves out have no value"),
        "{told}"
    );
}

#[test]
fn a_short_model_keeps_its_points_and_zeros_after_the_chain_end_it() {
    // The common model with 65 registers (its last, Pad, left out), then zeros where the
    // end marker belongs.
    let mut words = vec![21365, 28243, 1, 65, 16739, 28005];
    words.extend(std::iter::repeat_n(0, 63));
    words.extend([0, 0, 0, 0]);
    let text: Vec<String> = words.iter().map(u16::to_string).collect();
    let (_dir, _server, port) = serve_data(&format!("440001 = {}\n", text.join(" ")));
    let output = sunspec(&port, &["1", "-o", "values"]);
    assert!(output.status.success(), "{output:?}");
    assert_eq!(
        String::from_utf8_lossy(&output.stdout),
        "common.ID=1\ncommon.L=65\ncommon.Mn=Acme\ncommon.DA=0\n"
    );
    let told = String::from_utf8_lossy(&output.stderr);
    assert!(
        told.contains(
            "mbtool: register 40069 holds model id 0 where a model or the end marker (0xFFFF) belongs"
        ),
        "{told}"
    );
    // A pad left out loses nothing: no model is told as read in part.
    assert!(!told.contains("mbtool: model 1"), "{told}");
}

#[test]
fn a_chain_cut_by_a_refused_header_exits_with_the_refusal() {
    // The header of the nameplate model (440123-440124) left out of the device.
    let text = std::fs::read_to_string(EXAMPLE).unwrap();
    let line = text.lines().find(|l| l.starts_with("440001 = ")).unwrap();
    let words: Vec<&str> = line[9..].split(' ').collect();
    let joined = |range: std::ops::Range<usize>| words[range].join(" ");
    let data = format!(
        "440001 = {}\n440125 = {}\n",
        joined(0..122),
        joined(124..words.len())
    );
    let (_dir, _server, port) = serve_data(&data);
    let output = sunspec(&port, &["1", "-o", "values"]);
    assert_eq!(output.status.code(), Some(12), "{output:?}");
    let told = String::from_utf8_lossy(&output.stderr);
    assert!(
        told.contains("mbtool: the device refused the model header at register 40122 (illegal data address) before the end marker"),
        "{told}"
    );
    assert!(String::from_utf8_lossy(&output.stdout).contains("inverter_three_phase.PhVphA=230.1"));
}
