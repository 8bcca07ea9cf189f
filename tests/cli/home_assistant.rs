//! Public Home Assistant modbus configurations (`tests/corpus/home-assistant`, each with its
//! source in SOURCES.md) read by mbtool as Home Assistant's own integration reads them:
//! `tests/peers/ha_reference.py` asks Home Assistant (installed by tests/run.sh) which files
//! it loads, which entities it sets up, and the state each shows for known registers; mbtool
//! reads the same files against `serve` holding those registers, and must agree.

use std::collections::{BTreeSet, HashMap};
use std::path::{Path, PathBuf};
use std::process::Command;

use crate::support::{mbtool, peer_available, serve_tcp};

fn corpus() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/corpus/home-assistant")
}

/// The Python of the virtual environment tests/run.sh puts Home Assistant in.
fn home_assistant() -> Option<PathBuf> {
    let python = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/home-assistant/bin/python");
    let found = Command::new(&python)
        .args(["-c", "import homeassistant.components.modbus"])
        .output()
        .is_ok_and(|o| o.status.success());
    peer_available("Home Assistant", found).then_some(python)
}

/// What the reference fills every register and bit with: the same as ha_reference.py.
fn register(table: u8, address: u32) -> u16 {
    let high = 0x41 + (address * 7 + u32::from(table)) % 26;
    let low = 0x41 + (address * 11 + 3) % 26;
    ((high << 8) | low) as u16
}

fn bit(table: u8, address: u32) -> bool {
    (address * 5 + u32::from(table)) % 3 == 0
}

/// A data file where every address of the four tables holds what the reference reads.
fn data_file(dir: &Path) -> String {
    let mut text = String::new();
    for table in [4u8, 3] {
        let values: Vec<String> = (0..65536u32)
            .map(|a| register(table, a).to_string())
            .collect();
        text.push_str(&format!(
            "{table}00001-{table}65536 = {}\n",
            values.join(" ")
        ));
    }
    for table in [0u8, 1] {
        let values: Vec<&str> = (0..65536u32)
            .map(|a| if bit(table, a) { "1" } else { "0" })
            .collect();
        text.push_str(&format!(
            "{table}00001-{table}65536 = {}\n",
            values.join(" ")
        ));
    }
    let path = dir.join("device.txt");
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

/// Why Home Assistant refuses a file that mbtool reads, where the reason is a known one
/// (docs/maps.md documents them): a `count` beside a type that says its width, and the older
/// `int`, `uint`, `float` types, which Home Assistant read before its sized names and mbtool
/// still reads.
fn tolerated(error: &str) -> bool {
    error.contains("`count` illegal with") || error.contains("['data_type']")
}

#[test]
fn the_public_configurations_read_as_home_assistant_reads_them() {
    let Some(python) = home_assistant() else {
        return;
    };
    let mut files: Vec<PathBuf> = std::fs::read_dir(corpus())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "yaml") && !p.ends_with("secrets.yaml"))
        .collect();
    files.sort();
    files.push(corpus().join("29-crazybunker-includes/modbus.yaml"));
    assert!(files.len() >= 20, "{files:?}");
    let output = Command::new(&python)
        .arg(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/peers/ha_reference.py"))
        .args(&files)
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let references: Vec<serde_json::Value> = String::from_utf8_lossy(&output.stdout)
        .lines()
        .map(|line| serde_json::from_str(line).unwrap())
        .collect();
    assert_eq!(references.len(), files.len());

    let dir = tempfile::tempdir().unwrap();
    let data = data_file(dir.path());
    let mut slaves: BTreeSet<u64> = BTreeSet::from([1]);
    for reference in &references {
        for entity in reference["entities"].as_array().into_iter().flatten() {
            slaves.extend(entity["slave"].as_u64().filter(|id| *id != 0));
        }
    }
    let mut serve_args = vec!["--data".to_string(), data];
    for slave in &slaves {
        serve_args.extend(["--slave".to_string(), slave.to_string()]);
    }
    let serve_args: Vec<&str> = serve_args.iter().map(String::as_str).collect();
    let (_device, port, _) = serve_tcp(&serve_args);

    let mut loaded = 0;
    let mut compared = 0;
    for (file, reference) in files.iter().zip(&references) {
        let path = file.display().to_string();
        let output = mbtool()
            .args(&port)
            .args([
                "read",
                "1",
                "--map",
                &path,
                "-o",
                "values",
                "--timeout",
                "5s",
            ])
            .output()
            .unwrap();
        let (code, stdout, stderr) = (
            output.status.code().unwrap_or(-1),
            String::from_utf8_lossy(&output.stdout).into_owned(),
            String::from_utf8_lossy(&output.stderr).into_owned(),
        );
        if reference["loads"] != true {
            let error = reference["error"].as_str().unwrap_or_default();
            assert!(
                code == 2 || tolerated(error),
                "{path}: Home Assistant refuses it ({error}) and mbtool read it: {stderr}"
            );
            if code == 2 {
                assert!(stderr.starts_with(&format!("mbtool: {path}")), "{stderr}");
            }
            continue;
        }
        assert_eq!(code, 0, "{path}: Home Assistant loads it: {stderr}");
        loaded += 1;
        let entities = reference["entities"].as_array().unwrap();
        // A name two platforms use is told apart by its platform in mbtool.
        let mut platforms: HashMap<&str, BTreeSet<&str>> = HashMap::new();
        for entity in entities {
            platforms
                .entry(entity["name"].as_str().unwrap())
                .or_default()
                .insert(entity["platform"].as_str().unwrap());
        }
        // The names as JSON gives them (a name may hold '='), the values as `name=value`
        // lines show them.
        let json = mbtool()
            .args(&port)
            .args(["read", "1", "--map", &path, "-o", "json", "--timeout", "5s"])
            .output()
            .unwrap();
        let json: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
        let names: BTreeSet<String> = json["points"]
            .as_array()
            .unwrap()
            .iter()
            .map(|point| point["name"].as_str().unwrap().to_string())
            .collect();
        let shown = |name: &str| {
            stdout
                .lines()
                .find_map(|line| line.strip_prefix(name)?.strip_prefix('='))
        };
        let mut expected = BTreeSet::new();
        for entity in entities {
            let name = entity["name"].as_str().unwrap();
            let platform = entity["platform"].as_str().unwrap();
            let name = if platforms[name].len() > 1 {
                format!(
                    "{}.{name}",
                    platform.trim_end_matches('s').replace("switche", "switch")
                )
            } else {
                name.to_string()
            };
            if let Some(state) = entity["state"].as_str() {
                assert_eq!(shown(&name), Some(state), "{path}: {platform} {name}");
                compared += 1;
            } else if entity["table"].is_string() {
                // Home Assistant shows no value (NaN, nan_value): mbtool says unknown.
                assert_eq!(shown(&name), Some("unknown"), "{path}: {name}");
            }
            expected.insert(name);
        }
        // Every entity Home Assistant sets up is a point, and every point is an entity of
        // it, but those an older Home Assistant dropped for sharing an address, which it
        // allows since.
        let warnings = reference["warnings"].to_string();
        for name in names.difference(&expected) {
            assert!(
                warnings.contains(&format!(".{name} address ")),
                "{path}: mbtool has {name}, Home Assistant has not"
            );
        }
        let lacking: Vec<&String> = expected.difference(&names).collect();
        assert!(
            lacking.is_empty(),
            "{path}: Home Assistant has {lacking:?}, mbtool has not"
        );
    }
    assert!(
        loaded >= 20 && compared >= 500,
        "{loaded} files, {compared} values"
    );
}

/// `write --map FILE NAME=VALUE` needs no SLAVE where the map gives each point's: a Home
/// Assistant entity without one is slave 1, as Home Assistant writes it.
#[test]
fn a_write_by_map_without_a_slave_goes_to_the_maps_slave() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let map = root.join("examples/pump3.yaml");
    let data = root.join("examples/pump3.txt");
    let (_device, port, _) = serve_tcp(&["--slave", "1", "--data", data.to_str().unwrap()]);
    let write = mbtool()
        .args(&port)
        .args(["write", "--map", map.to_str().unwrap(), "pump=on"])
        .output()
        .unwrap();
    assert!(write.status.success(), "{write:?}");
    let read = mbtool()
        .args(&port)
        .args([
            "read",
            "1",
            "--map",
            map.to_str().unwrap(),
            "pump",
            "-o",
            "values",
        ])
        .output()
        .unwrap();
    assert_eq!(
        String::from_utf8_lossy(&read.stdout),
        "pump=on\n",
        "{read:?}"
    );
}
