//! `dump` and `restore`: a device with holes saved, cloned by `serve --data`, saved again;
//! a data file put back and read back; a slave that ignores a write caught.

use crate::support::{mbtool, scripted_tcp_device, serve_tcp, Act};

/// A device with holes: registers 400001-400010, 400020-400025 and a float at 400040,
/// coils 000001-000020 and four input registers.
const PLANT: &str = "\
400001-400010 = 7
400020-400025 = 1 2 3 4 5 6
400040 = 3.14 f32
000001-000020 = 1 0 1 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0
300001-300004 = 9
";

const RANGES: [&str; 3] = ["400001-400050", "000001-000030", "300001-300010"];

fn data_file(dir: &tempfile::TempDir, name: &str, text: &str) -> String {
    let path = dir.path().join(name);
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

/// Dumps RANGES of slave 17 at `port` into `file`; the file's text and stderr.
fn dump(port: &[String], file: &str) -> (String, String) {
    let output = mbtool()
        .args(port)
        .args(["dump", "17"])
        .args(RANGES)
        .args(["-o", file])
        .output()
        .unwrap();
    assert!(output.status.success(), "{output:?}");
    (
        std::fs::read_to_string(file).unwrap(),
        String::from_utf8_lossy(&output.stderr).into_owned(),
    )
}

/// The file without its header comment.
fn body(text: &str) -> &str {
    text.split_once('\n').map_or("", |(_, rest)| rest)
}

#[test]
fn a_dump_serves_as_the_device_holes_included() {
    let dir = tempfile::tempdir().unwrap();
    let plant = data_file(&dir, "plant.txt", PLANT);
    let (_device, port, _) = serve_tcp(&["--data", &plant]);
    let first = dir.path().join("first.txt").display().to_string();
    let (text, stderr) = dump(&port, &first);
    assert!(
        text.starts_with("# mbtool dump of slave 17 from tcp://127.0.0.1:"),
        "{text}"
    );
    assert_eq!(
        body(&text),
        "400001 = 7 7 7 7 7 7 7 7 7 7\n\
         400020 = 1 2 3 4 5 6\n\
         400040 = 16456 62915\n\
         000001 = 1 0 1 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n\
         300001 = 9 9 9 9\n"
    );
    assert!(
        stderr.contains(
            "left out: 400011-400019, 400026-400039, 400042-400050, 000021-000030, 300005-300010"
        ),
        "{stderr}"
    );
    // The dump stands in for the device: dumped again, it gives the same file.
    let (_clone, clone_port, _) = serve_tcp(&["--data", &first]);
    let second = dir.path().join("second.txt").display().to_string();
    let (again, again_stderr) = dump(&clone_port, &second);
    assert_eq!(body(&again), body(&text));
    assert!(
        again_stderr.contains("left out: 400011-400019"),
        "{again_stderr}"
    );
}

#[test]
fn restore_puts_a_dump_back_and_reads_it_back() {
    let dir = tempfile::tempdir().unwrap();
    let plant = data_file(&dir, "plant.txt", PLANT);
    let (_device, port, _) = serve_tcp(&["--data", &plant]);
    let saved = dir.path().join("saved.txt").display().to_string();
    let (text, _) = dump(&port, &saved);
    // A replacement device: the same addresses, all zero.
    let blank = data_file(
        &dir,
        "blank.txt",
        "400001-400010 = 0\n400020-400025 = 0\n400040-400041 = 0\n000001-000020 = 0\n300001-300004 = 9\n",
    );
    let (_replacement, new_port, _) = serve_tcp(&["--data", &blank]);
    let output = mbtool()
        .args(&new_port)
        .args(["restore", "17", &saved])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(0), "{stderr}");
    assert!(
        stderr.contains("300001-300004 skipped: input registers are read-only"),
        "{stderr}"
    );
    assert!(
        stderr
            .contains("wrote 38 values to slave 17 in 4 requests; every one reads back as written"),
        "{stderr}"
    );
    let restored = dir.path().join("restored.txt").display().to_string();
    let (after, _) = dump(&new_port, &restored);
    assert_eq!(body(&after), body(&text));
}

#[test]
fn restore_dry_run_prints_the_frames_and_needs_no_port() {
    let dir = tempfile::tempdir().unwrap();
    let file = data_file(&dir, "set.txt", "400002-400003 = 10 258\n000173 = on\n");
    let output = mbtool()
        .args(["restore", "17", &file, "--dry-run"])
        .output()
        .unwrap();
    assert!(output.status.success(), "{output:?}");
    // The manuals' worked frames: 06 for one value would not do here, the run is two.
    assert_eq!(
        String::from_utf8_lossy(&output.stdout),
        "11 05 00 AC FF 00 4E 8B\n11 10 00 01 00 02 04 00 0A 01 02 C6 F0\n"
    );
}

/// A TCP device with holding registers 0-99 that answers every write as done but keeps
/// none written to `ignored`.
fn forgetful_device(ignored: u16) -> Vec<String> {
    let registers = std::sync::Mutex::new([0u16; 100]);
    let tcp = scripted_tcp_device(move |_, pdu| {
        let Ok(mut registers) = registers.lock() else {
            return Act::Close;
        };
        let word = |i: usize| u16::from_be_bytes([pdu[i], pdu[i + 1]]);
        let (address, quantity) = (usize::from(word(1)), usize::from(word(3)));
        Act::Answer(match pdu[0] {
            0x03 if address + quantity <= 100 => {
                let mut answer = vec![0x03, (quantity * 2) as u8];
                for register in &registers[address..address + quantity] {
                    answer.extend_from_slice(&register.to_be_bytes());
                }
                answer
            }
            0x06 | 0x10 if address + quantity.max(1) <= 100 => {
                let values: Vec<u16> = if pdu[0] == 0x06 {
                    vec![word(3)]
                } else {
                    (0..quantity).map(|i| word(6 + 2 * i)).collect()
                };
                for (i, value) in values.into_iter().enumerate() {
                    if address + i != usize::from(ignored) {
                        registers[address + i] = value;
                    }
                }
                pdu[..5].to_vec()
            }
            function => vec![function | 0x80, 0x02],
        })
    });
    vec!["--port".to_string(), format!("127.0.0.1:{tcp}")]
}

#[test]
fn a_write_the_device_ignored_is_named_and_exits_4() {
    let dir = tempfile::tempdir().unwrap();
    let file = data_file(&dir, "set.txt", "400001-400030 = 5\n");
    let port = forgetful_device(21);
    let output = mbtool()
        .args(&port)
        .args(["restore", "17", &file])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(4), "{output:?}");
    assert_eq!(
        String::from_utf8_lossy(&output.stdout),
        "400022: wrote 5, read back 0\n"
    );
    assert!(String::from_utf8_lossy(&output.stderr).contains("1 read back differently"));
}

#[test]
fn bad_ranges_and_files_are_refused_before_anything_is_sent() {
    let dir = tempfile::tempdir().unwrap();
    let bad = data_file(&dir, "bad.txt", "400001 = 1\n400002 = lots\n");
    let output = mbtool()
        .args(["--port", "127.0.0.1:9", "restore", "17", &bad])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.starts_with(&format!("mbtool: {bad}:2: ")),
        "{stderr}"
    );
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    let output = mbtool()
        .args(["--port", "127.0.0.1:9", "dump", "17", "400001-300002"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&output.stderr),
        "mbtool: range 400001-300002 spans two tables\n"
    );
}

#[test]
fn a_dump_of_nothing_that_exists_is_the_device_saying_02() {
    let dir = tempfile::tempdir().unwrap();
    let plant = data_file(&dir, "plant.txt", PLANT);
    let (_device, port, _) = serve_tcp(&["--data", &plant]);
    let output = mbtool()
        .args(&port)
        .args(["dump", "17", "400100-400110"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(12), "{output:?}");
}

#[test]
fn overlapping_ranges_are_dumped_once_and_dash_o_takes_a_file() {
    let dir = tempfile::tempdir().unwrap();
    let plant = data_file(&dir, "plant.txt", PLANT);
    let (_device, port, _) = serve_tcp(&["--data", &plant]);
    let output = mbtool()
        .args(&port)
        .args(["dump", "17", "400001-400005", "400003-400008"])
        .output()
        .unwrap();
    assert!(output.status.success(), "{output:?}");
    assert!(String::from_utf8_lossy(&output.stdout).ends_with("\n400001 = 7 7 7 7 7 7 7 7\n"));
    let output = mbtool()
        .args(&port)
        .args(["dump", "17", "400001", "-o", "json"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&output.stderr).contains("give ./json if that is meant"));
}

#[test]
fn a_file_that_leaves_a_value_out_or_names_an_address_twice_is_refused_with_nothing_sent() {
    let dir = tempfile::tempdir().unwrap();
    let asked = std::sync::Arc::new(std::sync::atomic::AtomicUsize::new(0));
    let counter = asked.clone();
    let tcp = scripted_tcp_device(move |_, pdu| {
        counter.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
        Act::Answer(pdu[..5].to_vec())
    });
    let port = format!("127.0.0.1:{tcp}");
    for (text, line, says) in [
        (
            "400001-400003 = 1 2\n",
            1,
            "the range has 3 holding registers and the values fill 2",
        ),
        (
            "000010-000012 = 1 0 1 1\n",
            1,
            "the range has 3 coils and the values fill 4",
        ),
        (
            "400001 = 1 2\n# again\n400001 = 3\n",
            3,
            "400001 is given already on line 1",
        ),
        (
            "400010-400020 = 0\n400005 = 1 2 3 4 5 6\n",
            2,
            "400010 is given already on line 1",
        ),
    ] {
        let file = data_file(&dir, "r.txt", text);
        for dry_run in [&["--dry-run"][..], &[]] {
            let output = mbtool()
                .args(["--port", &port, "restore", "17", &file])
                .args(dry_run)
                .output()
                .unwrap();
            assert_eq!(output.status.code(), Some(2), "{text}: {output:?}");
            assert!(output.stdout.is_empty(), "{text}: {output:?}");
            let stderr = String::from_utf8_lossy(&output.stderr);
            assert!(
                stderr.starts_with(&format!("mbtool: {file}:{line}: {says}")),
                "{text}: {stderr}"
            );
            assert_eq!(stderr.lines().count(), 1, "{stderr}");
        }
        // serve reads the same file the same way: it does not start.
        let output = mbtool()
            .args(["--port", "127.0.0.1:9", "serve", "--data", &file])
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(2), "{text}: {output:?}");
        assert!(String::from_utf8_lossy(&output.stderr).contains(says));
    }
    assert_eq!(asked.load(std::sync::atomic::Ordering::SeqCst), 0);
}

/// A file dump cannot write is found out before the device is read (a dump may take
/// minutes): one line, exit 1 (an I/O failure, as a read-only filesystem is too), and the
/// port never opened.
#[test]
fn a_dump_to_a_folder_that_does_not_exist_is_refused_before_reading() {
    let output = mbtool()
        .args(["--port", "/dev/ttyNOPE0", "dump", "17", "400001-400010"])
        .args(["-o", "/nonexistent-folder/pump.txt"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(
        stderr.starts_with("mbtool: cannot write /nonexistent-folder/pump.txt"),
        "{stderr}"
    );
}

/// An address the device has but fails to give (exception 04 for it alone) is that
/// address's alone: the dump holds the others, names it, and exits 14.
#[test]
fn an_address_the_device_fails_on_is_left_out_and_named() {
    let tcp = scripted_tcp_device(|_, pdu| {
        let word = |i: usize| u16::from_be_bytes([pdu[i], pdu[i + 1]]);
        let (address, quantity) = (word(1), word(3));
        if (address..address + quantity).contains(&3) {
            return Act::Answer(vec![0x83, 0x04]);
        }
        let mut answer = vec![0x03, (quantity * 2) as u8];
        for register in address..address + quantity {
            answer.extend_from_slice(&(register + 100).to_be_bytes());
        }
        Act::Answer(answer)
    });
    let output = mbtool()
        .args([
            "--port",
            &format!("127.0.0.1:{tcp}"),
            "dump",
            "1",
            "400001-400006",
        ])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(14), "{stderr}");
    let dumped: Vec<String> = String::from_utf8_lossy(&output.stdout)
        .lines()
        .filter(|line| !line.starts_with('#'))
        .map(String::from)
        .collect();
    assert_eq!(dumped, ["400001 = 100 101 102", "400005 = 104 105"]);
    assert!(
        stderr.contains("could not give 1 address: 400004 (04 slave device failure)"),
        "{stderr}"
    );
}
