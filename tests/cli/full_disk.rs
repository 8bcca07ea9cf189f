//! A disk that is full (`/dev/full`, where every write fails with ENOSPC): whatever mbtool
//! was writing, standard output or a file it was given, the one line on stderr names it,
//! and the exit status says it failed.

use std::fs::File;
use std::process::Stdio;

use crate::support::mbtool_process;

const FULL: &str = "/dev/full";

/// Runs mbtool with `args`, standard output to `/dev/full` when `stdout_full`, and returns
/// its exit status and stderr.
fn run(args: &[&str], stdout_full: bool) -> (i32, String) {
    let stdout = if stdout_full {
        Stdio::from(File::options().write(true).open(FULL).unwrap())
    } else {
        Stdio::null()
    };
    let output = mbtool_process()
        .args(args)
        .stdout(stdout)
        .stderr(Stdio::piped())
        .output()
        .unwrap();
    (
        output.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&output.stderr).into_owned(),
    )
}

#[test]
fn a_full_disk_is_named_whatever_was_being_written() {
    if !std::path::Path::new(FULL).exists() {
        eprintln!("skipped: no {FULL} on this system");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let capture = dir.path().join("line.bin");
    std::fs::write(&capture, [0x01, 0x03, 0x00, 0x00, 0x00, 0x0A, 0xC5, 0xCD]).unwrap();
    let capture = capture.display().to_string();
    let stdout = "cannot write standard output: No space left on device";
    let file = format!("cannot write {FULL}: No space left on device");
    for (args, stdout_full, says) in [
        (
            vec![
                "--port",
                "sim",
                "read-holding",
                "17",
                "400001",
                "3",
                "-o",
                "csv",
            ],
            true,
            stdout,
        ),
        (
            vec!["--port", "sim", "read", "17", "000001", "8", "--json"],
            true,
            stdout,
        ),
        (
            vec!["--port", "sim", "dump", "17", "400001-400100"],
            true,
            stdout,
        ),
        (
            vec!["--port", "sim", "scan", "--ids", "16-18"],
            true,
            stdout,
        ),
        (vec!["decode", "01030000000AC5CD"], true, stdout),
        (vec!["--help"], true, stdout),
        (vec!["--version"], true, stdout),
        (vec!["sniff", "--help"], true, stdout),
        (vec!["sniff", "--input", &capture, "--json"], true, stdout),
        (
            vec![
                "--port",
                "sim",
                "--poll",
                "50ms",
                "--count",
                "2",
                "read-holding",
                "17",
                "400001",
                "--log",
                FULL,
            ],
            false,
            &file,
        ),
        (
            vec!["--port", "sim", "dump", "17", "400001-400010", "-o", FULL],
            false,
            &file,
        ),
        (
            vec!["sniff", "--input", &capture, "--save", FULL],
            false,
            &file,
        ),
        (
            vec!["sniff", "--input", &capture, "--pcap", FULL],
            false,
            &file,
        ),
    ] {
        let (code, stderr) = run(&args, stdout_full);
        assert_eq!(code, 1, "{args:?}: {stderr}");
        let last = stderr.lines().last().unwrap_or_default();
        assert!(
            last.starts_with("mbtool: ") && last.contains(says),
            "{args:?}: {stderr}"
        );
    }
}
