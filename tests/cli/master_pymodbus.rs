//! mbtool's master against pymodbus as a slave: RTU and ASCII over a socat pty pair, and
//! TCP on 127.0.0.1. pymodbus is a happy-path peer (it answers for slave ids it does not
//! have and answers broadcasts), so only the writes and reads of a healthy bus are checked.

use std::process::{Command as Process, Stdio};
use std::time::{Duration, Instant};

use crate::support::{
    free_port, peer_available, python_has, run_against, wait_for_listener, writes_read_back,
    PtyPair, Stopped,
};

const SCRIPT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/peers/pymodbus_slave.py");

fn pymodbus() -> bool {
    peer_available("pymodbus (Python)", python_has("pymodbus"))
}

fn start(args: &[&str]) -> Stopped {
    Stopped(
        Process::new("python3")
            .arg(SCRIPT)
            .args(args)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .expect("python3 starts"),
    )
}

/// Waits until the slave answers a read, or panics after 15 s.
fn wait_until_answering(port: &[String]) {
    let deadline = Instant::now() + Duration::from_secs(15);
    while Instant::now() < deadline {
        if run_against(port, "read-holding 17 400001 --timeout 300ms").0 == 0 {
            return;
        }
        std::thread::sleep(Duration::from_millis(100));
    }
    panic!("pymodbus never answered on {port:?}");
}

fn serial(framer: &str, mode: &str) {
    if !pymodbus() {
        return;
    }
    let Some(pair) = PtyPair::new() else { return };
    let _slave = start(&[
        "--framer",
        framer,
        "--serial",
        &pair.a.display().to_string(),
    ]);
    let port = vec![
        "--port".to_string(),
        pair.b.display().to_string(),
        "--mode".to_string(),
        mode.to_string(),
    ];
    wait_until_answering(&port);
    writes_read_back(&port);
}

#[test]
fn against_pymodbus_in_rtu_on_a_pty() {
    serial("rtu", "rtu");
}

#[test]
fn against_pymodbus_in_ascii_on_a_pty() {
    serial("ascii", "ascii");
}

#[test]
fn against_pymodbus_on_tcp() {
    if !pymodbus() {
        return;
    }
    let tcp = free_port();
    let _slave = start(&["--framer", "socket", "--tcp", &tcp.to_string()]);
    assert!(
        wait_for_listener(tcp, Duration::from_secs(15)),
        "pymodbus did not listen"
    );
    let port = vec!["--port".to_string(), format!("tcp://127.0.0.1:{tcp}")];
    wait_until_answering(&port);
    writes_read_back(&port);
}
