//! Modbus/TCP Security: tls:// against pymodbus's TLS server and `mbtool serve`, pymodbus's
//! TLS client against `mbtool serve`, roles, and every way a connection fails told as
//! what to do. The certificates are made here, with rcgen.

use std::io::{Read, Write};

use std::net::TcpListener;

use std::path::{Path, PathBuf};

use std::process::{Command as Process, Stdio};

use std::time::{Duration, Instant};

use rcgen::{
    date_time_ymd, BasicConstraints, CertificateParams, CustomExtension, DnType, IsCa, Issuer,
    KeyPair, KeyUsagePurpose,
};

use crate::support::{
    command_exists, free_port, mbtool, mbtool_process, peer_available, python_has,
    wait_for_listener, writes_read_back, Stopped,
};

/// The role extension of MB/TCP Security.
const ROLE_OID: &[u64] = &[1, 3, 6, 1, 4, 1, 50316, 802, 1];

/// A CA, and the certificates it and a stranger CA sign, written as PEM files.
struct Pki {
    dir: tempfile::TempDir,
}

impl Pki {
    fn new() -> Pki {
        let dir = tempfile::tempdir().unwrap();
        let pki = Pki { dir };
        let (ca_params, ca_key) = pki.ca("ca", "Plant CA");
        let ca = Issuer::new(ca_params, ca_key);
        let (other_params, other_key) = pki.ca("other-ca", "Another CA");
        let other = Issuer::new(other_params, other_key);
        let always = (2020, 2090);
        let here = ["localhost", "127.0.0.1"];
        pki.leaf(&ca, "server", "localhost", &here, None, always);
        pki.leaf(&ca, "operator", "operator", &[], Some("operator"), always);
        pki.leaf(&ca, "viewer", "viewer", &[], Some("viewer"), always);
        pki.leaf(&ca, "norole", "norole", &[], None, always);
        let past = (2020, 2021);
        pki.leaf(&ca, "expired", "localhost", &here, None, past);
        pki.leaf(&ca, "expired-client", "old", &[], Some("operator"), past);
        let future = (2090, 2091);
        pki.leaf(&ca, "future", "localhost", &here, None, future);
        pki.leaf(&other, "stranger", "localhost", &here, None, always);
        pki.leaf(
            &other,
            "stranger-client",
            "x",
            &[],
            Some("operator"),
            always,
        );
        pki.leaf(&ca, "plc", "plc.example", &["plc.example"], None, always);
        // A device's certificate from before subjectAltName: its name in the CN alone.
        pki.leaf(&ca, "cn-only", "localhost", &[], None, always);
        // A role that would forge a line in a log.
        let forged = Some("op\u{1b}[31m\nfake line");
        pki.leaf(&ca, "forger", "forger", &[], forged, always);
        pki
    }

    fn path(&self, name: &str) -> String {
        self.dir.path().join(name).display().to_string()
    }

    fn ca(&self, file: &str, name: &str) -> (CertificateParams, KeyPair) {
        let mut params = CertificateParams::new(Vec::<String>::new()).unwrap();
        params.distinguished_name.push(DnType::CommonName, name);
        params.is_ca = IsCa::Ca(BasicConstraints::Unconstrained);
        params.key_usages = vec![
            KeyUsagePurpose::KeyCertSign,
            KeyUsagePurpose::DigitalSignature,
        ];
        let key = KeyPair::generate().unwrap();
        let cert = params.self_signed(&key).unwrap();
        std::fs::write(self.dir.path().join(format!("{file}.pem")), cert.pem()).unwrap();
        (params, key)
    }

    fn leaf(
        &self,
        issuer: &Issuer<'_, KeyPair>,
        file: &str,
        common_name: &str,
        names: &[&str],
        role: Option<&str>,
        // Valid from the first of January of one year to that of another.
        (not_before, not_after): (i32, i32),
    ) {
        let names: Vec<String> = names.iter().map(|n| n.to_string()).collect();
        let mut params = CertificateParams::new(names).unwrap();
        params
            .distinguished_name
            .push(DnType::CommonName, common_name);
        params.not_before = date_time_ymd(not_before, 1, 1);
        params.not_after = date_time_ymd(not_after, 1, 1);
        if let Some(role) = role {
            // A DER UTF8String.
            let mut der = vec![0x0C, role.len() as u8];
            der.extend_from_slice(role.as_bytes());
            params
                .custom_extensions
                .push(CustomExtension::from_oid_content(ROLE_OID, der));
        }
        let key = KeyPair::generate().unwrap();
        let cert = params.signed_by(&key, issuer).unwrap();
        std::fs::write(self.dir.path().join(format!("{file}.pem")), cert.pem()).unwrap();
        std::fs::write(
            self.dir.path().join(format!("{file}.key")),
            key.serialize_pem(),
        )
        .unwrap();
    }

    /// `--cert`, `--key` and `--ca` for the client `name`.
    fn client(&self, name: &str) -> Vec<String> {
        vec![
            "--cert".into(),
            self.path(&format!("{name}.pem")),
            "--key".into(),
            self.path(&format!("{name}.key")),
            "--ca".into(),
            self.path("ca.pem"),
        ]
    }
}

/// `mbtool serve` on tls://127.0.0.1 with the certificate `server` and `extra`; its log
/// goes to the file returned.
fn serve_tls(pki: &Pki, server: &str, extra: &[&str]) -> (Stopped, u16, PathBuf) {
    let port = free_port();
    let log = pki.dir.path().join(format!("serve-{port}.log"));
    let child = mbtool_process()
        .args(["--port", &format!("tls://127.0.0.1:{port}")])
        .args(["--cert", &pki.path(&format!("{server}.pem"))])
        .args(["--key", &pki.path(&format!("{server}.key"))])
        .args(["--ca", &pki.path("ca.pem")])
        .arg("serve")
        .args(extra)
        .stdout(Stdio::null())
        .stderr(std::fs::File::create(&log).unwrap())
        .spawn()
        .unwrap();
    let server = Stopped(child);
    assert!(wait_for_listener(port, Duration::from_secs(10)));
    (server, port, log)
}

/// The server's log once it holds every one of `lines`, or as it is after 5 s: the server
/// tells of a refusal after the client has its error.
fn logged_once(log: &Path, lines: &[&str]) -> String {
    let deadline = Instant::now() + Duration::from_secs(5);
    loop {
        let logged = std::fs::read_to_string(log).unwrap();
        if lines.iter().all(|line| logged.contains(line)) || Instant::now() > deadline {
            return logged;
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// mbtool with `args` as a client of 127.0.0.1:`port`; (exit status, stdout, stderr).
fn client(port_url: &str, args: &[String], command: &str) -> (i32, String, String) {
    let output = mbtool()
        .args(["--port", port_url, "--timeout", "3s"])
        .args(args)
        .args(command.split_whitespace())
        .output()
        .unwrap();
    (
        output.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&output.stdout).into_owned(),
        String::from_utf8_lossy(&output.stderr).into_owned(),
    )
}

#[test]
fn roles_decide_what_a_client_may_do() {
    let pki = Pki::new();
    let (_server, port, log) = serve_tls(
        &pki,
        "server",
        &[
            "--role",
            "operator=read,write:400001-400100",
            "--role",
            "viewer=read",
        ],
    );
    let url = format!("tls://localhost:{port}");
    let (operator, viewer) = (pki.client("operator"), pki.client("viewer"));
    let read = |who: &[String], what: &str| {
        let (code, out, err) = client(&url, who, &format!("{what} -o values"));
        assert_eq!(code, 0, "{err}");
        out.split_whitespace()
            .map(str::to_string)
            .collect::<Vec<_>>()
    };
    assert_eq!(
        read(&operator, "read-holding 17 400108 3"),
        ["555", "0", "100"]
    );
    assert_eq!(
        read(&viewer, "read-holding 17 400108 3"),
        ["555", "0", "100"]
    );
    // The viewer's write gets exception 01 and changes nothing.
    let (code, _, err) = client(&url, &viewer, "write-register 17 400010 7");
    assert_eq!(code, 11, "{err}");
    assert!(err.contains("exception 01"), "{err}");
    assert_eq!(read(&operator, "read-holding 17 400010"), ["0"]);
    // The operator's, outside its range: 01; inside, it lands.
    let (code, _, err) = client(&url, &operator, "write-register 17 400101 7");
    assert_eq!(code, 11, "{err}");
    let (code, _, err) = client(&url, &operator, "write-registers 17 400100 1 2");
    assert_eq!(code, 11, "{err}");
    assert_eq!(read(&operator, "read-holding 17 400100 2"), ["0", "0"]);
    let (code, _, err) = client(&url, &operator, "write-register 17 400010 7");
    assert_eq!(code, 0, "{err}");
    assert_eq!(read(&viewer, "read-holding 17 400010"), ["7"]);
    // Coils are outside the operator's write range too.
    let (code, _, _) = client(&url, &operator, "write-coil 17 000001 on");
    assert_eq!(code, 11);
    // A certificate without a role, and no default role: refused.
    let (code, _, err) = client(&url, &pki.client("norole"), "read-holding 17 400108");
    assert_eq!(code, 1);
    assert!(
        err.contains("closed the connection without answering"),
        "{err}"
    );
    assert_eq!(err.lines().count(), 1, "{err}");
    // The monitor lines show each client's role, and why one was refused.
    let logged = logged_once(&log, &["(CN=norole) refused"]);
    assert!(
        logged.contains("(operator) slave 17: 6 Write Single Register 400101 = 7 -> exception 01"),
        "{logged}"
    );
    assert!(
        logged.contains("(viewer) slave 17: 6 Write Single Register 400010 = 7 -> exception 01"),
        "{logged}"
    );
    assert!(
        logged.contains("(CN=norole) refused: its certificate carries no role"),
        "{logged}"
    );
}

#[test]
fn a_client_without_a_role_gets_the_default_role() {
    let pki = Pki::new();
    let (_server, port, _log) = serve_tls(
        &pki,
        "server",
        &[
            "--role",
            "viewer=read",
            "--role",
            "operator=read,write",
            "--default-role",
            "viewer",
        ],
    );
    let url = format!("tls://127.0.0.1:{port}");
    let norole = [
        pki.client("norole"),
        vec!["--tls-server-name".into(), "localhost".into()],
    ]
    .concat();
    let (code, out, err) = client(&url, &norole, "read-holding 17 400108 -o values");
    assert_eq!((code, out.trim()), (0, "555"), "{err}");
    let (code, _, _) = client(&url, &norole, "write-register 17 400001 1");
    assert_eq!(code, 11);
}

#[test]
fn verbose_tells_the_tls_session_and_an_answer_is_read_at_once() {
    let pki = Pki::new();
    let (_server, port, _log) = serve_tls(&pki, "server", &[]);
    let started = Instant::now();
    let output = mbtool()
        .args([
            "--port",
            &format!("tls://localhost:{port}"),
            "--timeout",
            "5s",
            "-v",
        ])
        .args(pki.client("operator"))
        .args(["read-holding", "17", "400108", "3", "-o", "values"])
        .output()
        .unwrap();
    assert!(
        started.elapsed() < Duration::from_secs(1),
        "{:?}",
        started.elapsed()
    );
    assert!(output.status.success(), "{output:?}");
    let err = String::from_utf8_lossy(&output.stderr);
    for told in [
        "TLS 1.3",
        "TLS13_",
        "CN=localhost",
        "valid until",
        "role sent: 'operator'",
    ] {
        assert!(err.contains(told), "{told}: {err}");
    }
    // The MBAP frames inside it, as over plain TCP.
    assert!(
        err.contains("> 00 01 00 00 00 06 11 03 00 6B 00 03"),
        "{err}"
    );
}

#[test]
fn the_certificates_come_from_the_environment_too() {
    let pki = Pki::new();
    let (_server, port, _log) = serve_tls(&pki, "server", &["--role", "viewer=read"]);
    let output = mbtool()
        .env("MBTOOL_PORT", format!("tls://localhost:{port}"))
        .env("MBTOOL_CERT", pki.path("viewer.pem"))
        .env("MBTOOL_KEY", pki.path("viewer.key"))
        .env("MBTOOL_CA", pki.path("ca.pem"))
        .args(["read-holding", "17", "400108", "-o", "values"])
        .output()
        .unwrap();
    assert_eq!(
        String::from_utf8_lossy(&output.stdout).trim(),
        "555",
        "{output:?}"
    );
    // A command that talks to no device does not take them.
    crate::support::assert_refused(
        &["decode", "--ca", "x.pem", "11 03 00 6B 00 03 76 87"],
        "mbtool: decode does not take --ca",
    );
}

/// A listener that records what a client sends before it closes: for the failures found
/// before or during the handshake, nothing of Modbus may have gone out.
fn recording_listener(answer: &'static [u8]) -> (u16, std::sync::mpsc::Receiver<Vec<u8>>) {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let port = listener.local_addr().unwrap().port();
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        for stream in listener.incoming() {
            let Ok(mut stream) = stream else { return };
            stream
                .set_read_timeout(Some(Duration::from_millis(300)))
                .unwrap();
            let mut seen = Vec::new();
            let mut chunk = [0u8; 4096];
            while let Ok(n @ 1..) = stream.read(&mut chunk) {
                seen.extend_from_slice(&chunk[..n]);
                let _ = stream.write_all(answer);
            }
            let _ = tx.send(seen);
        }
    });
    (port, rx)
}

#[test]
fn every_failure_is_one_line_saying_what_to_do() {
    let pki = Pki::new();
    let url = |port: u16| format!("tls://localhost:{port}");
    let expect = |port_url: &str, args: &[String], message: &str| {
        let (code, out, err) = client(port_url, args, "read-holding 17 400108");
        assert_eq!(code, 1, "{message}: {out}{err}");
        assert!(
            err.starts_with("mbtool: ") && err.contains(message),
            "{message}: {err}"
        );
        assert_eq!(err.lines().count(), 1, "{err}");
    };
    let operator = pki.client("operator");
    for (server, message) in [
        ("expired", "the device's certificate has expired (on "),
        ("future", "the device's certificate is not valid yet"),
        ("stranger", "is not signed by a CA of"),
        (
            "plc",
            "the device's certificate is not for 'localhost' but for plc.example",
        ),
        (
            "cn-only",
            "the device's certificate has no subjectAltName: its name 'localhost' is only in its subject CN",
        ),
    ] {
        let (_server, port, _) = serve_tls(&pki, server, &[]);
        expect(&url(port), &operator, message);
    }
    // The name the certificate holds, given: the same device answers.
    let (_server, port, _) = serve_tls(&pki, "plc", &[]);
    let named = [
        operator.clone(),
        vec!["--tls-server-name".into(), "plc.example".into()],
    ]
    .concat();
    assert_eq!(client(&url(port), &named, "read-holding 17 400108").0, 0);
    // A device that wants a client certificate, given none.
    let (_server, port, log) = serve_tls(&pki, "server", &[]);
    let ca_only = vec!["--ca".to_string(), pki.path("ca.pem")];
    expect(
        &url(port),
        &ca_only,
        "wants a client certificate: give --cert and --key",
    );
    // A client certificate the device's CA did not sign, or out of date.
    expect(
        &url(port),
        &pki.client("stranger-client"),
        "the device refused this end's certificate",
    );
    expect(
        &url(port),
        &pki.client("expired-client"),
        "expired-client.pem expired on",
    );
    // A plain Modbus TCP client on the TLS port: told to use tls://.
    expect(
        &format!("tcp://127.0.0.1:{port}"),
        &[],
        "this looks like a Modbus/TCP Security port: use tls://",
    );
    // The server tells of a refusal after the client has its error: wait for the last.
    let refusals = [
        "refused: it sent no client certificate",
        "refused: its certificate is not signed by a CA of --ca",
        "refused: it did not speak TLS",
    ];
    let logged = logged_once(&log, &refusals);
    for refusal in refusals {
        assert!(logged.contains(refusal), "{refusal}: {logged}");
    }
    // A plain Modbus TCP device on tls://: it answers an MBAP exception, which is no TLS.
    let (plain, sent) = recording_listener(&[0x00, 0x00, 0x00, 0x00, 0x00, 0x03, 0x11, 0x83, 0x01]);
    expect(
        &url(plain),
        &operator,
        "this looks like a plain Modbus TCP port: use tcp://",
    );
    let sent = sent.recv_timeout(Duration::from_secs(5)).unwrap();
    assert_eq!(
        sent.first(),
        Some(&0x16),
        "a TLS ClientHello first: {sent:02X?}"
    );
    assert!(
        !sent
            .windows(6)
            .any(|w| w == [0x00, 0x06, 0x11, 0x03, 0x00, 0x6B]),
        "no Modbus request before the handshake"
    );
    // Bad files: nothing is even connected.
    let (quiet, connections) = recording_listener(b"");
    let files = |cert: &str, key: &str| {
        vec![
            "--cert".into(),
            cert.to_string(),
            "--key".into(),
            key.to_string(),
            "--ca".into(),
            pki.path("ca.pem"),
        ]
    };
    let garbage = pki.dir.path().join("garbage.pem");
    std::fs::write(&garbage, "not a certificate\n").unwrap();
    let garbage = garbage.display().to_string();
    for (args, message) in [
        (
            files(&pki.path("viewer.pem"), &pki.path("operator.key")),
            "does not belong to the certificate",
        ),
        (
            files(&pki.path("viewer.pem"), "/nonexistent/viewer.key"),
            "cannot read /nonexistent/viewer.key",
        ),
        (
            files(&garbage, &pki.path("viewer.key")),
            "holds no certificate",
        ),
        (
            files(&pki.path("viewer.pem"), &garbage),
            "holds no private key",
        ),
    ] {
        expect(&url(quiet), &args, message);
    }
    // An option missing for tls:// is a usage error.
    for (args, message) in [
        (
            vec![
                "--cert".into(),
                pki.path("viewer.pem"),
                "--ca".into(),
                pki.path("ca.pem"),
            ],
            "--cert needs --key",
        ),
        (vec![], "tls:// needs --ca FILE"),
    ] {
        let (code, _, err) = client(&url(quiet), &args, "read-holding 17 400108");
        assert_eq!(code, 2, "{err}");
        assert!(
            err.starts_with("mbtool: ") && err.contains(message),
            "{err}"
        );
    }
    assert!(
        connections
            .recv_timeout(Duration::from_millis(300))
            .is_err(),
        "nothing connects with bad files"
    );
}

#[test]
fn serve_refuses_a_tls_setup_it_cannot_use_before_it_listens() {
    let pki = Pki::new();
    let port = free_port();
    for (args, message) in [
        (
            vec![
                "--port".to_string(),
                format!("tls://127.0.0.1:{port}"),
                "serve".into(),
            ],
            "a tls:// server needs --cert and --key",
        ),
        (
            vec![
                "--port".to_string(),
                format!("tcp://127.0.0.1:{port}"),
                "serve".into(),
                "--role".into(),
                "viewer=read".into(),
            ],
            "--role and --default-role are for clients known by their certificates",
        ),
        (
            [
                vec!["--port".to_string(), format!("tls://127.0.0.1:{port}")],
                pki.client("server"),
                vec!["serve".into(), "--role".into(), "viewer=delete".into()],
            ]
            .concat(),
            "--role viewer=delete: 'delete' is no right",
        ),
    ] {
        let output = mbtool().args(&args).output().unwrap();
        let err = String::from_utf8_lossy(&output.stderr);
        assert!(
            matches!(output.status.code(), Some(1 | 2)),
            "{args:?}: {err}"
        );
        assert!(err.contains(message), "{args:?}: {err}");
        assert!(std::net::TcpStream::connect(("127.0.0.1", port)).is_err());
    }
}

#[test]
fn pymodbus_tls_server_reads_and_writes_as_over_plain_tcp() {
    if !peer_available("pymodbus (Python)", python_has("pymodbus")) {
        return;
    }
    let pki = Pki::new();
    let port = free_port();
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/peers/pymodbus_slave.py");
    let tls = format!(
        "{},{},{}",
        pki.path("server.pem"),
        pki.path("server.key"),
        pki.path("ca.pem")
    );
    let _slave = Stopped(
        std::process::Command::new("python3")
            .args([
                script,
                "--framer",
                "tls",
                "--tcp",
                &port.to_string(),
                "--tls",
                &tls,
            ])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap(),
    );
    assert!(
        wait_for_listener(port, Duration::from_secs(15)),
        "pymodbus did not listen"
    );
    let options = [
        vec!["--port".to_string(), format!("tls://localhost:{port}")],
        pki.client("operator"),
    ]
    .concat();
    writes_read_back(&options);
}

#[test]
fn pymodbus_tls_client_reads_and_writes_serve_as_over_plain_tcp() {
    if !peer_available("pymodbus (Python)", python_has("pymodbus")) {
        return;
    }
    let pki = Pki::new();
    let script = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/peers/pymodbus_tls_client.py"
    );
    let run = |args: &[String]| {
        let output = std::process::Command::new("python3")
            .arg(script)
            .args(args)
            .output()
            .unwrap();
        assert!(output.status.success(), "{output:?}");
        String::from_utf8_lossy(&output.stdout).into_owned()
    };
    let (_tls_server, tls_port, log) = serve_tls(&pki, "server", &[]);
    let tls = format!(
        "{},{},{}",
        pki.path("operator.pem"),
        pki.path("operator.key"),
        pki.path("ca.pem")
    );
    let over_tls = run(&[tls_port.to_string(), "--tls".into(), tls]);
    let (_plain_server, _, plain_port) = crate::support::serve_tcp(&[]);
    let over_tcp = run(&[plain_port.to_string()]);
    assert_eq!(over_tls, over_tcp);
    assert!(
        over_tls.contains("\"holding\": [555, 0, 100]"),
        "{over_tls}"
    );
    assert!(
        over_tls.contains("\"written\": [4711, 1, 2, 3]"),
        "{over_tls}"
    );
    let logged = std::fs::read_to_string(log).unwrap();
    assert!(
        logged.contains("(operator) slave 17: 16 Write Multiple Registers"),
        "{logged}"
    );
}

#[test]
fn gateway_takes_tls_clients_with_their_roles() {
    let pki = Pki::new();
    let (port, plain) = (free_port(), free_port());
    let rows = pki.dir.path().join("gateway.jsonl");
    let gateway = |extra: &[&str]| {
        mbtool_process()
            .args(["--port", "sim", "-o", "json"])
            .args(pki.client("server"))
            .args(["gateway", "--listen", &format!("tls://127.0.0.1:{port}")])
            .args(["--listen", &format!("tcp://127.0.0.1:{plain}")])
            .args([
                "--role",
                "operator=read,write:400001-400010",
                "--role",
                "viewer=read",
            ])
            .args(extra)
            .stdout(std::fs::File::create(&rows).unwrap())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap()
    };
    // A plain listener beside the secure one would let anyone past the roles.
    let refused = gateway(&[]).wait_with_output().unwrap();
    let said = String::from_utf8_lossy(&refused.stderr);
    assert_eq!(refused.status.code(), Some(2), "{said}");
    assert!(said.contains("give --plain-role NAME"), "{said}");
    assert_eq!(said.lines().count(), 1, "{said}");
    let mut started = gateway(&["--plain-role", "viewer"]);
    let stderr = started.stderr.take().unwrap();
    let gateway = Stopped(started);
    assert!(wait_for_listener(port, Duration::from_secs(10)));
    let mut first = String::new();
    std::io::BufRead::read_line(&mut std::io::BufReader::new(stderr), &mut first).unwrap();
    assert!(first.contains("(no certificate: role viewer)"), "{first}");
    let url = format!("tls://localhost:{port}");
    let (viewer, operator) = (pki.client("viewer"), pki.client("operator"));
    let (code, out, err) = client(&url, &viewer, "read-holding 17 400108 3 -o values");
    assert_eq!(
        (code, out.split_whitespace().collect::<Vec<_>>()),
        (0, vec!["555", "0", "100"]),
        "{err}"
    );
    let (code, _, err) = client(&url, &viewer, "write-register 17 400001 3");
    assert_eq!(code, 11, "{err}");
    assert!(err.contains("may be the server refusing"), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert_eq!(client(&url, &operator, "write-register 17 400011 3").0, 11);
    assert_eq!(client(&url, &operator, "write-register 17 400001 3").0, 0);
    let (_, out, _) = client(&url, &viewer, "read-holding 17 400001 -o values");
    assert_eq!(out.trim(), "3");
    // Without a client certificate: refused before anything reaches the line.
    let ca_only = vec!["--ca".to_string(), pki.path("ca.pem")];
    assert_eq!(client(&url, &ca_only, "read-holding 17 400001").0, 1);
    // The plain listener's clients are viewers.
    let plain_url = format!("127.0.0.1:{plain}");
    assert_eq!(client(&plain_url, &[], "write-register 17 400001 4").0, 11);
    let (_, out, _) = client(&plain_url, &[], "read-holding 17 400001 -o values");
    assert_eq!(out.trim(), "3");
    // The gateway writes a row once its client has its answer: the last may come a moment
    // after the client ended.
    let read_rows = || -> Vec<serde_json::Value> {
        std::fs::read_to_string(&rows)
            .unwrap_or_default()
            .lines()
            .filter_map(|line| serde_json::from_str(line).ok())
            .filter(|row: &serde_json::Value| row.get("client").is_some())
            .collect()
    };
    let deadline = Instant::now() + Duration::from_secs(5);
    while read_rows().len() < 7 && Instant::now() < deadline {
        std::thread::sleep(Duration::from_millis(20));
    }
    drop(gateway);
    let rows = read_rows();
    assert_eq!(rows.len(), 7, "{rows:#?}");
    let refused: Vec<_> = rows
        .iter()
        .filter(|row| row["outcome"] == "refused")
        .collect();
    assert_eq!(refused.len(), 3, "{rows:#?}");
    for row in &refused {
        // Answered by the gateway itself: the line was not asked.
        assert_eq!(row["tries"], 0, "{row}");
        assert_eq!(row["answer"]["exception"], 1, "{row}");
    }
    assert_eq!(refused[0]["why"], "role viewer may not write 400001");
    assert_eq!(refused[1]["why"], "role operator may not write 400011");
    assert_eq!(refused[2]["role"], "viewer", "{rows:#?}");
    assert_eq!(rows[1]["role"], "viewer", "{rows:#?}");
    assert_eq!(rows[3]["role"], "operator", "{rows:#?}");
    // The client is its address alone, as for plain clients.
    assert!(
        rows[3]["client"]
            .as_str()
            .unwrap()
            .starts_with("127.0.0.1:"),
        "{rows:#?}"
    );
}

/// The closing device of tests/peers (Python's ssl, that is OpenSSL), speaking `version`
/// (`1.3`, or `1.2` alone), on a free port.
fn openssl_device(pki: &Pki, version: &str) -> (Stopped, u16) {
    let port = free_port();
    let script = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/peers/tls_closing_slave.py"
    );
    let device = Stopped(
        std::process::Command::new("python3")
            .arg(script)
            .args([
                pki.path("server.pem"),
                pki.path("server.key"),
                pki.path("ca.pem"),
            ])
            .args([port.to_string(), version.to_string()])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap(),
    );
    assert!(wait_for_listener(port, Duration::from_secs(10)));
    (device, port)
}

mod faults;
