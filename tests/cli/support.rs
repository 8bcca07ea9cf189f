//! What the tests share: one hermetic `mbtool` command, pseudo-terminals, peers, the
//! network, and the worked frames of the Modbus manuals.

use std::io::{Read, Write};
use std::time::{Duration, Instant};

use assert_cmd::Command;
use mbtool_core::codec::framing::{Event, Framer};
use mbtool_core::codec::{Direction, Frame, Mode, Request};
use serialport::{SerialPort, TTYPort};

/// The worked frames of the Modbus manuals (every CRC checked): the `encode` arguments of
/// each request, the request on the wire, and the answer.
pub const WORKED: &[(&str, &str, &str)] = &[
    (
        "read-coils 17 000020 37",
        "11 01 00 13 00 25 0E 84",
        "11 01 05 CD 6B B2 0E 1B 45 E6",
    ),
    (
        "read-inputs 17 100197-100218",
        "11 02 00 C4 00 16 BA A9",
        "11 02 03 AC DB 35 20 18",
    ),
    (
        "read-holding 17 400108 3",
        "11 03 00 6B 00 03 76 87",
        "11 03 06 02 2B 00 00 00 64 C8 BA",
    ),
    (
        "read-input-registers 17 300009",
        "11 04 00 08 00 01 B2 98",
        "11 04 02 00 0A F8 F4",
    ),
    (
        "write-coil 17 000173 on",
        "11 05 00 AC FF 00 4E 8B",
        "11 05 00 AC FF 00 4E 8B",
    ),
    (
        "write-register 17 400002 0x0003",
        "11 06 00 01 00 03 9A 9B",
        "11 06 00 01 00 03 9A 9B",
    ),
    (
        "write-registers 17 400002-400003 0x000A 0x0102",
        "11 10 00 01 00 02 04 00 0A 01 02 C6 F0",
        "11 10 00 01 00 02 12 98",
    ),
];

/// The worked frames as bytes, requests and answers in turn: [4] and [5] are the read of
/// 400108-400110 from slave 17 and its answer (555, 0, 100).
pub static WORKED_FRAMES: std::sync::LazyLock<Vec<Vec<u8>>> = std::sync::LazyLock::new(|| {
    WORKED
        .iter()
        .flat_map(|(_, request, answer)| [request, answer])
        .map(|spaced| hex::decode(spaced.replace(' ', "")).expect("the worked frames are hex"))
        .collect()
});

/// The environment variables that would give mbtool connection settings.
const SETTINGS_FROM_ENVIRONMENT: [&str; 25] = [
    "MBTOOL_PORT",
    "MBTOOL_MODE",
    "MBTOOL_BAUD",
    "MBTOOL_PARITY",
    "MBTOOL_DATA_BITS",
    "MBTOOL_STOP_BITS",
    "MBTOOL_TIMEOUT",
    "MBTOOL_RETRIES",
    "MBTOOL_RS485",
    "MBTOOL_RS485_DELAY_BEFORE",
    "MBTOOL_RS485_DELAY_AFTER",
    "MBTOOL_RTS_LEVEL",
    "MBTOOL_RTS_TOGGLE",
    "MBTOOL_SECONDARY_PORT",
    "MBTOOL_SECONDARY_BAUD",
    "MBTOOL_SECONDARY_PARITY",
    "MBTOOL_SECONDARY_DATA_BITS",
    "MBTOOL_SECONDARY_STOP_BITS",
    "MBTOOL_SECONDARY_MODE",
    "MBTOOL_SWITCH_ON",
    "MBTOOL_SWITCH_WHEN",
    "MBTOOL_CERT",
    "MBTOOL_KEY",
    "MBTOOL_CA",
    "MBTOOL_TLS_SERVER_NAME",
];

/// mbtool with no connection settings from the environment.
pub fn mbtool() -> Command {
    Command::from_std(mbtool_process())
}

/// The same as a plain process, for what `assert_cmd` does not set (a file as stdout).
pub fn mbtool_process() -> std::process::Command {
    let mut cmd = std::process::Command::new(assert_cmd::cargo::cargo_bin("mbtool"));
    for var in SETTINGS_FROM_ENVIRONMENT {
        cmd.env_remove(var);
    }
    cmd.env("NO_COLOR", "1");
    cmd
}

/// Checks that mbtool refuses the command line `args` as bad usage (exit status 2), in one
/// line on stderr that starts with `message`.
pub fn assert_refused(args: &[&str], message: &str) {
    let output = mbtool().args(args).output().expect("mbtool runs");
    assert_eq!(output.status.code(), Some(2), "{args:?}");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.starts_with(message), "{args:?}: {stderr}");
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
}

/// Whether an outside peer is here. On a developer's machine a missing peer skips the test
/// with a reason; with `CI` set it fails, because CI must run every test.
pub fn peer_available(name: &str, found: bool) -> bool {
    if found {
        return true;
    }
    assert!(
        std::env::var_os("CI").is_none(),
        "{name} is missing and CI is set: tests/run.sh installs it"
    );
    eprintln!("skipping: {name} is not installed (tests/run.sh installs it)");
    false
}

pub fn command_exists(name: &str) -> bool {
    std::process::Command::new("sh")
        .args(["-c", &format!("command -v {name}")])
        .output()
        .is_ok_and(|o| o.status.success())
}

/// A pseudo-terminal pair: mbtool opens `path`; the test reads and writes `master`.
pub struct Pty {
    pub master: TTYPort,
    // Held open so that the master side never sees a hang-up between mbtool runs.
    _slave: TTYPort,
    pub path: String,
}

impl Pty {
    pub fn new() -> Pty {
        let (master, slave) = TTYPort::pair().expect("a pseudo-terminal pair");
        let path = slave.name().expect("the slave side has a name");
        Pty {
            master,
            _slave: slave,
            path,
        }
    }
}

/// Reads one whole frame of `mode` travelling in `direction` from `port`, or `None` when
/// nothing came within `wait`. Frames end as on a line at 19200 baud: at 1.75 ms of
/// silence, where their bytes alone do not tell.
pub fn read_frame(
    port: &mut TTYPort,
    mode: Mode,
    direction: Direction,
    wait: Duration,
) -> Option<(Frame, Vec<u8>)> {
    let mut framer = Framer::new(mode, 573.0, 1750);
    let started = Instant::now();
    let deadline = started + wait;
    let mut chunk = [0u8; 512];
    let mut events = Vec::new();
    while Instant::now() < deadline {
        port.set_timeout(Duration::from_millis(5)).ok()?;
        let read = port.read(&mut chunk);
        let now = started.elapsed().as_micros() as u64;
        match read {
            Ok(n) => framer.push_at(&chunk[..n], now, &mut events),
            // A read that times out gives nothing: the line is quiet.
            Err(_) => {
                framer.idle(now, &mut events);
            }
        }
        for event in events.drain(..) {
            if let Event::Frame(found) = event {
                if let Ok(frame) = Frame::decode(mode, &found.bytes, direction) {
                    return Some((frame, found.bytes.to_vec()));
                }
            }
        }
    }
    None
}

pub fn write_all(port: &mut TTYPort, bytes: &[u8]) {
    port.write_all(bytes).expect("write to the pty");
    port.flush().expect("flush the pty");
}

/// An RTU frame with its CRC.
pub fn rtu(body: &[u8]) -> Vec<u8> {
    let mut frame = body.to_vec();
    frame.extend_from_slice(&mbtool_core::codec::checksum::crc16(body).to_le_bytes());
    frame
}

/// A random request to one of `ids`, the slaves `slave` stands in for, and its answer, as
/// RTU frames.
pub fn random_exchange(
    rng: &mut fastrand::Rng,
    slave: &mut mbtool_core::slave::Slave,
    ids: &[u8],
) -> [Vec<u8>; 2] {
    let id = ids[rng.usize(..ids.len())];
    let request = random_request(rng);
    let answer = slave.handle(id, &request).expect("the slave answers");
    [mbtool_core::codec::Pdu::Request(request), answer].map(|pdu| {
        Frame {
            mode: Mode::Rtu,
            slave: id,
            transaction: 0,
            pdu,
        }
        .encode()
        .expect("generated frames keep the limits")
    })
}

/// A request of the common functions, as a master polling a plant sends them.
pub fn random_request(rng: &mut fastrand::Rng) -> Request {
    let address = rng.u16(..1000);
    match rng.u8(..7) {
        0 => Request::ReadCoils {
            address,
            quantity: rng.u16(1..=64),
        },
        1 => Request::ReadDiscreteInputs {
            address,
            quantity: rng.u16(1..=64),
        },
        2 => Request::ReadHoldingRegisters {
            address,
            quantity: rng.u16(1..=20),
        },
        3 => Request::ReadInputRegisters {
            address,
            quantity: rng.u16(1..=20),
        },
        4 => Request::WriteSingleRegister {
            address,
            value: rng.u16(..),
        },
        5 => Request::WriteSingleCoil {
            address,
            value: rng.bool(),
        },
        _ => Request::WriteMultipleRegisters {
            address,
            values: (0..rng.usize(1..8)).map(|_| rng.u16(..)).collect(),
        },
    }
}

/// Bytes as spaced upper-case hex, as mbtool shows them; written apart from mbtool's own,
/// so that a test does not take mbtool's word for what it should print.
pub fn spaced_hex(bytes: &[u8]) -> String {
    bytes
        .iter()
        .map(|b| format!("{b:02X}"))
        .collect::<Vec<_>>()
        .join(" ")
}

/// A free TCP port on 127.0.0.1.
pub fn free_port() -> u16 {
    std::net::TcpListener::bind("127.0.0.1:0")
        .and_then(|l| l.local_addr())
        .map(|a| a.port())
        .expect("a free port on 127.0.0.1")
}

/// Waits until something listens on 127.0.0.1:`port`.
pub fn wait_for_listener(port: u16, within: Duration) -> bool {
    let deadline = Instant::now() + within;
    while Instant::now() < deadline {
        if std::net::TcpStream::connect(("127.0.0.1", port)).is_ok() {
            return true;
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    false
}

/// Runs mbtool with the connection options `port` and `args`; (exit status, stdout + stderr).
pub fn run_against(port: &[String], args: &str) -> (i32, String) {
    let output = mbtool()
        .args(port)
        .args(["--timeout", "2s"])
        .args(args.split_whitespace())
        .output()
        .expect("mbtool runs");
    (
        output.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&output.stdout).into_owned()
            + &String::from_utf8_lossy(&output.stderr),
    )
}

/// The values mbtool prints with `-o values`.
pub fn values_of(port: &[String], args: &str) -> Vec<String> {
    let (code, out) = run_against(port, &format!("{args} -o values"));
    assert_eq!(code, 0, "{args}: {out}");
    out.lines().map(str::to_string).collect()
}

/// Every write command, each read back with every read command, counts at the protocol
/// limits: for any slave 17 whose tables are writable from address 0 to 4000.
pub fn writes_read_back(port: &[String]) {
    assert_eq!(run_against(port, "write-coil 17 000173 on").0, 0);
    assert_eq!(values_of(port, "read-coils 17 000173"), ["1"]);
    assert_eq!(run_against(port, "write-register 17 400002 3").0, 0);
    assert_eq!(values_of(port, "read-holding 17 400002"), ["3"]);
    assert_eq!(
        run_against(port, "write-registers 17 400002 0x000A 0x0102").0,
        0
    );
    assert_eq!(values_of(port, "read 17 400002-400003"), ["10", "258"]);
    assert_eq!(run_against(port, "write-coils 17 000100 10110").0, 0);
    assert_eq!(
        values_of(port, "read-coils 17 000100 5"),
        ["1", "0", "1", "1", "0"]
    );
    assert_eq!(
        run_against(port, "write 17 400010 -2.5 --type f32 --order CDAB").0,
        0
    );
    assert_eq!(
        values_of(port, "read-holding 17 400010 --type f32 --order CDAB"),
        ["-2.5"]
    );
    assert_eq!(run_against(port, "write 17 400020 7 8 --function 6").0, 0);
    assert_eq!(values_of(port, "read-holding 17 400020 2"), ["7", "8"]);
    let many: Vec<String> = (0..123).map(|i| (i * 7).to_string()).collect();
    assert_eq!(
        run_against(
            port,
            &format!("write-registers 17 401001 {}", many.join(" "))
        )
        .0,
        0
    );
    assert_eq!(values_of(port, "read-holding 17 401001 123"), many);
    assert_eq!(values_of(port, "read-holding 17 400001 300").len(), 300);
    let bits: String = (0..1968)
        .map(|i| if i % 3 == 0 { '1' } else { '0' })
        .collect();
    assert_eq!(
        run_against(port, &format!("write-coils 17 1001 {bits}")).0,
        0
    );
    assert_eq!(values_of(port, "read-coils 17 1001 1968").concat(), bits);
    assert_eq!(values_of(port, "read-coils 17 1 2000").len(), 2000);
    assert_eq!(values_of(port, "read-inputs 17 1 2000").len(), 2000);
    assert_eq!(values_of(port, "read-input-registers 17 1 125").len(), 125);
}

/// Starts `mbtool serve` with `args`; it is stopped when the guard drops.
pub fn serve(args: &[&str]) -> Stopped {
    let child = std::process::Command::new(assert_cmd::cargo::cargo_bin("mbtool"))
        .arg("serve")
        .args(args)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .expect("mbtool serve starts");
    Stopped(child)
}

/// A child process that is stopped when the test ends, however it ends.
pub struct Stopped(pub std::process::Child);

impl Drop for Stopped {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

/// A socat pty pair: `a` and `b` are linked; socat is stopped on drop.
pub struct PtyPair {
    _socat: Stopped,
    pub a: std::path::PathBuf,
    pub b: std::path::PathBuf,
    _dir: tempfile::TempDir,
}

impl PtyPair {
    /// `None` (skipped, with a reason) where socat is missing outside CI.
    pub fn new() -> Option<PtyPair> {
        if !peer_available("socat", command_exists("socat")) {
            return None;
        }
        let dir = tempfile::tempdir().expect("a temporary folder");
        let (a, b) = (dir.path().join("a"), dir.path().join("b"));
        let socat = std::process::Command::new("socat")
            .arg(format!("pty,raw,echo=0,link={}", a.display()))
            .arg(format!("pty,raw,echo=0,link={}", b.display()))
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .expect("socat starts");
        let socat = Stopped(socat);
        let deadline = Instant::now() + Duration::from_secs(5);
        while !(a.exists() && b.exists()) && Instant::now() < deadline {
            std::thread::sleep(Duration::from_millis(20));
        }
        Some(PtyPair {
            _socat: socat,
            a,
            b,
            _dir: dir,
        })
    }
}

/// Whether python3 can import `module`.
pub fn python_has(module: &str) -> bool {
    std::process::Command::new("python3")
        .args(["-c", &format!("import {module}")])
        .output()
        .is_ok_and(|o| o.status.success())
}

/// `mbtool serve` on 127.0.0.1; the connection options for a master.
pub fn serve_tcp(extra: &[&str]) -> (Stopped, Vec<String>, u16) {
    let port = free_port();
    let address = format!("tcp://127.0.0.1:{port}");
    let mut args = vec!["--port", address.as_str()];
    args.extend_from_slice(extra);
    let server = serve(&args);
    assert!(
        wait_for_listener(port, Duration::from_secs(10)),
        "serve did not listen"
    );
    (server, vec!["--port".into(), address], port)
}

/// `mbtool serve` on one end of a pty pair; the connection options for the other end.
pub fn serve_pty(pair: &PtyPair, extra: &[&str]) -> (Stopped, Vec<String>) {
    let a = pair.a.display().to_string();
    let mut args = vec!["--port", a.as_str()];
    args.extend_from_slice(extra);
    let server = serve(&args);
    let master = vec!["--port".into(), pair.b.display().to_string()];
    let mode: Vec<String> = extra
        .windows(2)
        .find(|w| w[0] == "--mode")
        .map(|w| vec!["--mode".into(), w[1].to_string()])
        .unwrap_or_default();
    let master = [master, mode].concat();
    let deadline = Instant::now() + Duration::from_secs(10);
    while run_against(&master, "read-holding 17 400108 --timeout 200ms").0 != 0 {
        assert!(Instant::now() < deadline, "serve never answered on the pty");
    }
    (server, master)
}

/// mbtool running in a real terminal: a tmux session of its own, read with capture-pane,
/// killed when dropped.
pub struct Terminal {
    socket: tempfile::TempDir,
}

impl Terminal {
    /// Runs `mbtool ARGS` (a shell word list) in a `width` x `height` terminal; `None`
    /// (skipped, with a reason) where tmux is missing outside CI. The pane stays open
    /// after mbtool ends, and `done()` tells that it has.
    pub fn run(args: &str, width: u16, height: u16) -> Option<Terminal> {
        Terminal::start(args, width, height, "NO_COLOR=1")
    }

    /// As [`Terminal::run`], with colours, as a terminal shows them by default.
    pub fn run_in_colour(args: &str, width: u16, height: u16) -> Option<Terminal> {
        Terminal::start(args, width, height, "")
    }

    fn start(args: &str, width: u16, height: u16, env: &str) -> Option<Terminal> {
        if !peer_available("tmux", command_exists("tmux")) {
            return None;
        }
        let terminal = Terminal {
            socket: tempfile::tempdir().expect("a temporary folder"),
        };
        // The shell catches SIGINT (its child gets the default action), so that after a
        // Ctrl-C that ends mbtool it still records mbtool's exit status.
        let script = format!(
            "trap : INT; {env} {} {args}; echo $? > {}; touch {}; sleep 600",
            assert_cmd::cargo::cargo_bin("mbtool").display(),
            terminal.socket.path().join("status").display(),
            terminal.done_marker().display()
        );
        terminal.tmux(&[
            "new-session",
            "-d",
            "-x",
            &width.to_string(),
            "-y",
            &height.to_string(),
            "sh",
            "-c",
            &script,
        ]);
        Some(terminal)
    }

    fn done_marker(&self) -> std::path::PathBuf {
        self.socket.path().join("done")
    }

    fn tmux(&self, args: &[&str]) -> std::process::Output {
        std::process::Command::new("tmux")
            .arg("-S")
            .arg(self.socket.path().join("tmux"))
            .args(args)
            .output()
            .expect("tmux runs")
    }

    /// Whether mbtool has ended.
    pub fn done(&self) -> bool {
        self.done_marker().exists()
    }

    /// mbtool's exit status, once it has ended.
    pub fn status(&self) -> Option<i32> {
        std::fs::read_to_string(self.socket.path().join("status"))
            .ok()
            .and_then(|text| text.trim().parse().ok())
    }

    /// Types `keys` (tmux key names: `q`, `Escape`, `C-c`).
    pub fn keys(&self, keys: &[&str]) {
        let mut args = vec!["send-keys"];
        args.extend_from_slice(keys);
        self.tmux(&args);
    }

    /// The lines on the screen now.
    pub fn screen(&self) -> Vec<String> {
        let pane = self.tmux(&["capture-pane", "-p", "-J"]);
        String::from_utf8_lossy(&pane.stdout)
            .lines()
            .map(str::to_string)
            .collect()
    }

    /// The lines on the screen now, their colours as escape sequences.
    pub fn screen_in_colour(&self) -> Vec<String> {
        let pane = self.tmux(&["capture-pane", "-p", "-J", "-e"]);
        String::from_utf8_lossy(&pane.stdout)
            .lines()
            .map(str::to_string)
            .collect()
    }

    /// The screen once `seen` holds for it, or the last screen after `within`.
    pub fn wait_for(&self, within: Duration, seen: impl Fn(&[String]) -> bool) -> Vec<String> {
        let deadline = Instant::now() + within;
        loop {
            let screen = self.screen();
            if seen(&screen) || Instant::now() > deadline {
                return screen;
            }
            std::thread::sleep(Duration::from_millis(50));
        }
    }
}

impl Drop for Terminal {
    fn drop(&mut self) {
        self.tmux(&["kill-server"]);
    }
}

/// What a scripted TCP device does with one request.
pub enum Act {
    /// Answers with this PDU.
    Answer(Vec<u8>),
    /// Says nothing, and waits for the next request.
    Silent,
    /// Closes the connection.
    Close,
    /// Answers with this PDU, then closes the connection, as a device does that closes
    /// connections idle for longer than its poll.
    AnswerThenClose(Vec<u8>),
}

/// A Modbus TCP device on 127.0.0.1 played by `act`, which is given each request's unit id
/// and PDU: framed by the MBAP header here, so that a test spells out only what the device
/// says. It serves one connection after another until the test ends; returns its port.
pub fn scripted_tcp_device(act: impl Fn(u8, &[u8]) -> Act + Send + 'static) -> u16 {
    let listener = std::net::TcpListener::bind("127.0.0.1:0").expect("a free port");
    let port = listener.local_addr().expect("a bound port").port();
    std::thread::spawn(move || {
        for stream in listener.incoming() {
            let Ok(mut stream) = stream else { return };
            let _ = stream.set_read_timeout(Some(Duration::from_secs(10)));
            let mut header = [0u8; 7];
            while stream.read_exact(&mut header).is_ok() {
                let len = usize::from(u16::from_be_bytes([header[4], header[5]]));
                let mut pdu = vec![0u8; len.saturating_sub(1)];
                if stream.read_exact(&mut pdu).is_err() {
                    break;
                }
                let (answer, close) = match act(header[6], &pdu) {
                    Act::Answer(answer) => (answer, false),
                    Act::AnswerThenClose(answer) => (answer, true),
                    Act::Silent => continue,
                    Act::Close => break,
                };
                let mut frame = header[..4].to_vec();
                frame.extend_from_slice(&((answer.len() + 1) as u16).to_be_bytes());
                frame.push(header[6]);
                frame.extend_from_slice(&answer);
                if stream.write_all(&frame).is_err() || close {
                    break;
                }
            }
        }
    });
    port
}

/// pymodbus as a Modbus TCP slave 17 (tests/peers/pymodbus_slave.py with `extra`), and
/// the connection options for it; `None` (skipped, with a reason) where pymodbus is
/// missing outside CI.
pub fn pymodbus_tcp(extra: &[String]) -> Option<(Stopped, Vec<String>)> {
    if !peer_available("pymodbus (Python)", python_has("pymodbus")) {
        return None;
    }
    let tcp = free_port();
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/peers/pymodbus_slave.py");
    let slave = Stopped(
        std::process::Command::new("python3")
            .args([script, "--framer", "socket", "--tcp", &tcp.to_string()])
            .args(extra)
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .expect("python3 starts"),
    );
    assert!(
        wait_for_listener(tcp, Duration::from_secs(15)),
        "pymodbus did not listen"
    );
    Some((
        slave,
        vec!["--port".to_string(), format!("127.0.0.1:{tcp}")],
    ))
}
