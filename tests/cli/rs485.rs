//! RS-485 direction control on a pseudo-terminal. A pty has neither the kernel's RS-485
//! mode nor an RTS line, so `tests/shim/rs485.c`, loaded with LD_PRELOAD, answers those
//! ioctls as a UART driver would and records each of them, with the bytes written and
//! read and when. Without the shim the pty refuses both, as a port without them does.

use std::path::{Path, PathBuf};
use std::process::Stdio;
use std::time::{Duration, Instant};

use serialport::SerialPort;

use crate::support::*;

/// The kernel's flags of `struct serial_rs485`.
const SER_RS485_ENABLED: u32 = 1;
const SER_RS485_RTS_ON_SEND: u32 = 2;
const SER_RS485_RTS_AFTER_SEND: u32 = 4;

/// The shim built for this test in `dir`, or `None` (skipped, with a reason) where there
/// is no C compiler outside CI.
fn shim(dir: &Path) -> Option<PathBuf> {
    if !peer_available(
        "cc (a C compiler, for the RS-485 shim)",
        command_exists("cc"),
    ) {
        return None;
    }
    let source = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/shim/rs485.c");
    let library = dir.join("rs485-shim.so");
    let built = std::process::Command::new("cc")
        .args(["-shared", "-fPIC", "-O1", "-Wall", "-Werror", "-o"])
        .arg(&library)
        .arg(&source)
        .arg("-ldl")
        .output()
        .expect("cc runs");
    assert!(
        built.status.success(),
        "the shim does not build: {}",
        String::from_utf8_lossy(&built.stderr)
    );
    Some(library)
}

/// One line of the shim's log.
#[derive(Clone, Debug, PartialEq)]
enum Seen {
    Rs485 { flags: u32, before: u32, after: u32 },
    Rts(bool),
    Write(usize),
    Drain,
    Read(usize),
}

/// The shim's log: what happened, and when (nanoseconds, monotonic).
fn log_of(path: &Path) -> Vec<(u64, Seen)> {
    let text = std::fs::read_to_string(path).unwrap_or_default();
    text.lines()
        .map(|line| {
            let words: Vec<&str> = line.split_whitespace().collect();
            let number = |i: usize| words[i].parse::<u64>().expect("a number in the log");
            let seen = match words[1] {
                "rs485" => Seen::Rs485 {
                    flags: number(2) as u32,
                    before: number(3) as u32,
                    after: number(4) as u32,
                },
                "rts" => Seen::Rts(words[2] == "1"),
                "write" => Seen::Write(number(2) as usize),
                "drain" => Seen::Drain,
                "read" => Seen::Read(number(2) as usize),
                other => panic!("an unknown line in the shim's log: {other}"),
            };
            (number(0), seen)
        })
        .collect()
}

/// mbtool with the shim loaded, recording to `log`.
fn mbtool_with_shim(library: &Path, log: &Path) -> std::process::Command {
    let mut command = mbtool_process();
    command
        .env("LD_PRELOAD", library)
        .env("RS485_SHIM_LOG", log);
    command
}

/// Checks that RTS was at the sending level from at least `before` ahead of every byte
/// written until at least `after` past the drain that followed it, and at the listening
/// level whenever bytes were read. Returns how many frames were sent.
fn check_toggled(log: &[(u64, Seen)], sending: bool, before: Duration, after: Duration) -> usize {
    let mut rts = false;
    let mut raised_at = 0;
    let mut drained_at = None;
    let mut frames = 0;
    let mut writing = false;
    for (at, seen) in log {
        match seen {
            Seen::Rts(level) => {
                if *level == sending {
                    raised_at = *at;
                } else if writing {
                    let drained = drained_at.expect("RTS went back only after the drain");
                    assert!(
                        at - drained >= after.as_nanos() as u64,
                        "RTS went back {} µs after the drain, not {after:?}",
                        (at - drained) / 1000
                    );
                    writing = false;
                }
                rts = *level;
            }
            Seen::Write(_) => {
                assert_eq!(rts, sending, "a byte was written while listening: {log:?}");
                if !writing {
                    assert!(
                        at - raised_at >= before.as_nanos() as u64,
                        "the first byte went {} µs after RTS, not {before:?}",
                        (at - raised_at) / 1000
                    );
                    frames += 1;
                }
                writing = true;
                drained_at = None;
            }
            Seen::Drain => drained_at = Some(*at),
            Seen::Read(_) => {
                assert_ne!(rts, sending, "the answer was read while sending: {log:?}");
            }
            Seen::Rs485 { .. } => panic!("--rts-toggle set the kernel's RS-485 mode: {log:?}"),
        }
    }
    assert_ne!(rts, sending, "RTS was left at the sending level");
    frames
}

#[test]
fn rts_toggle_frames_every_request_and_listens_for_the_answer() {
    let Some(pair) = PtyPair::new() else { return };
    let dir = tempfile::tempdir().unwrap();
    let Some(library) = shim(dir.path()) else {
        return;
    };
    let (_server, port) = serve_pty(&pair, &[]);
    for (level, sending) in [("high", true), ("low", false)] {
        let log = dir.path().join(format!("master-{level}.log"));
        let output = mbtool_with_shim(&library, &log)
            .args(&port)
            .args(["read-holding", "17", "400108", "3", "-o", "values"])
            .args(["--poll", "20ms", "--count", "4", "--timeout", "2s"])
            .args(["--rts-toggle", "--rts-level", level])
            .args(["--rs485-delay-before", "3", "--rs485-delay-after", "5"])
            .output()
            .unwrap();
        let stdout = String::from_utf8_lossy(&output.stdout);
        assert!(
            output.status.success(),
            "{}",
            String::from_utf8_lossy(&output.stderr)
        );
        assert_eq!(
            stdout.lines().count(),
            12,
            "four reads of three values: {stdout}"
        );
        let log = log_of(&log);
        let frames = check_toggled(
            &log,
            sending,
            Duration::from_millis(3),
            Duration::from_millis(5),
        );
        assert_eq!(frames, 4, "one frame a request: {log:?}");
        assert!(log.iter().any(|(_, s)| matches!(s, Seen::Read(_))));
    }
}

#[test]
fn serve_toggles_rts_around_each_answer() {
    let Some(pair) = PtyPair::new() else { return };
    let dir = tempfile::tempdir().unwrap();
    let Some(library) = shim(dir.path()) else {
        return;
    };
    let log = dir.path().join("serve.log");
    let server = mbtool_with_shim(&library, &log)
        .args(["serve", "--port"])
        .arg(&pair.a)
        .env("MBTOOL_RTS_TOGGLE", "1")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let server = Stopped(server);
    let port = vec!["--port".to_string(), pair.b.display().to_string()];
    let deadline = Instant::now() + Duration::from_secs(10);
    while run_against(&port, "read-holding 17 400108 --timeout 200ms").0 != 0 {
        assert!(Instant::now() < deadline, "serve never answered on the pty");
    }
    assert_eq!(values_of(&port, "read-holding 17 400108 2"), ["555", "0"]);
    drop(server);
    let log = log_of(&log);
    let answers = check_toggled(&log, true, Duration::ZERO, Duration::ZERO);
    assert!(answers >= 2, "the answers went out with RTS: {log:?}");
}

#[test]
fn rs485_sets_the_kernel_mode_before_the_first_byte_and_puts_it_back() {
    let Some(pair) = PtyPair::new() else { return };
    let dir = tempfile::tempdir().unwrap();
    let Some(library) = shim(dir.path()) else {
        return;
    };
    let (_server, port) = serve_pty(&pair, &[]);
    // The options typed, the environment, and the flags and delays the kernel is given.
    type Case<'a> = (&'a [&'a str], &'a [(&'a str, &'a str)], u32, u32, u32);
    let cases: [Case; 3] = [
        (&["--rs485"], &[], SER_RS485_RTS_ON_SEND, 0, 0),
        (
            &[
                "--rs485",
                "--rs485-delay-before",
                "2",
                "--rs485-delay-after",
                "7",
            ],
            &[("MBTOOL_RTS_LEVEL", "low")],
            SER_RS485_RTS_AFTER_SEND,
            2,
            7,
        ),
        // From the environment, as a script sets the line once.
        (
            &[],
            &[("MBTOOL_RS485", "1"), ("MBTOOL_RS485_DELAY_AFTER", "1")],
            SER_RS485_RTS_ON_SEND,
            0,
            1,
        ),
    ];
    for (i, (args, env, level, before, after)) in cases.into_iter().enumerate() {
        let log = dir.path().join(format!("kernel-{i}.log"));
        let output = mbtool_with_shim(&library, &log)
            .args(&port)
            .args([
                "read-holding",
                "17",
                "400108",
                "-o",
                "values",
                "--timeout",
                "2s",
            ])
            .args(args)
            .envs(env.iter().copied())
            .output()
            .unwrap();
        assert_eq!(
            String::from_utf8_lossy(&output.stdout).trim(),
            "555",
            "{}",
            String::from_utf8_lossy(&output.stderr)
        );
        let log = log_of(&log);
        let first_write = log
            .iter()
            .position(|(_, s)| matches!(s, Seen::Write(_)))
            .expect("the request was written");
        let set: Vec<&Seen> = log.iter().map(|(_, s)| s).take(first_write).collect();
        assert_eq!(
            set,
            [&Seen::Rs485 {
                flags: SER_RS485_ENABLED | level,
                before,
                after,
            }],
            "case {i}: the mode, and nothing else, before the first byte"
        );
        assert_eq!(
            log.last().map(|(_, s)| s),
            Some(&Seen::Rs485 {
                flags: 0,
                before: 0,
                after: 0
            }),
            "case {i}: the port's mode put back as it was"
        );
        assert!(
            !log.iter().any(|(_, s)| matches!(s, Seen::Rts(_))),
            "case {i}: the kernel moves RTS, not mbtool: {log:?}"
        );
    }
}

#[test]
fn a_port_without_rs485_says_so_and_sends_nothing() {
    let mut pty = Pty::new();
    let cases = [
        (
            vec!["read-holding", "17", "400108", "--rs485"],
            format!("mbtool: {} does not support RS-485 mode: try --rts-toggle", pty.path),
        ),
        (
            vec!["write-register", "17", "400108", "5", "--rts-toggle"],
            format!(
                "mbtool: {} cannot drive RTS: try --rs485, or an adapter that switches its transceiver itself",
                pty.path
            ),
        ),
        (
            vec!["serve", "--rs485"],
            format!("mbtool: {} does not support RS-485 mode: try --rts-toggle", pty.path),
        ),
        (
            vec!["gateway", "--listen", "tcp://127.0.0.1:0", "--rs485"],
            format!("mbtool: {} does not support RS-485 mode: try --rts-toggle", pty.path),
        ),
    ];
    for (args, message) in cases {
        let started = Instant::now();
        let output = mbtool()
            .args(&args)
            .args(["--port", &pty.path])
            .timeout(Duration::from_secs(10))
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(1), "{args:?}");
        assert_eq!(String::from_utf8_lossy(&output.stderr), message + "\n");
        assert!(
            started.elapsed() < Duration::from_secs(2),
            "{args:?} waited"
        );
        pty.master.set_timeout(Duration::from_millis(100)).unwrap();
        let mut heard = [0u8; 64];
        let got = std::io::Read::read(&mut pty.master, &mut heard).unwrap_or(0);
        assert_eq!(got, 0, "{args:?} sent {:02x?}", &heard[..got]);
    }
}

#[test]
fn direction_options_are_checked_before_anything_is_opened() {
    let cases: [(&[&str], &str); 4] = [
        (
            &["--port", "tcp://127.0.0.1:1", "--rs485"],
            "mbtool: --rs485 and --rts-toggle drive the RTS line of a serial port: tcp://127.0.0.1:1 has none (a gateway switches its own transceiver)",
        ),
        (
            &["--port", "/dev/null", "--rs485", "--rts-toggle"],
            "mbtool: --rs485 and --rts-toggle: give one (--rs485 for the kernel's RS-485 mode, --rts-toggle where the driver has none)",
        ),
        (
            &["--port", "/dev/null", "--rts-level", "low"],
            "mbtool: --rts-level times the RS-485 direction: give --rs485 or --rts-toggle with it",
        ),
        (
            &["--port", "/dev/null", "--rs485", "--rs485-delay-after", "101"],
            "mbtool: invalid value '101' for '--rs485-delay-after <MS>': give a whole number from 0 to 100",
        ),
    ];
    for (args, message) in cases {
        assert_refused(&[&["read-holding", "17", "400108"], args].concat(), message);
    }
    // From the environment, the option is for the serial commands of the same shell: a
    // TCP device is read as if it were not set.
    let (_server, port, _) = serve_tcp(&[]);
    let output = mbtool()
        .args(&port)
        .args(["read-holding", "17", "400108", "-o", "values"])
        .env("MBTOOL_RS485", "1")
        .output()
        .unwrap();
    assert_eq!(String::from_utf8_lossy(&output.stdout).trim(), "555");
}
