//! Modbus/TCP Security when things are not as they should be: devices that refuse, files to mend, idle closes, handshake floods, old clients and certificates

use super::*;

#[test]
fn an_openssl_device_that_refuses_is_told_the_same_way_every_time() {
    let pki = Pki::new();
    for version in ["1.3", "1.2"] {
        let (_device, port) = openssl_device(&pki, version);
        let url = format!("tls://localhost:{port}");
        let ca_only = vec!["--ca".to_string(), pki.path("ca.pem")];
        for _ in 0..3 {
            let (code, _, err) = client(&url, &ca_only, "read-holding 17 400001");
            assert_eq!(code, 1, "{err}");
            assert!(
                err.contains("give --cert and --key"),
                "TLS {version}: {err}"
            );
            assert!(!err.contains("tcp://"), "TLS {version}: {err}");
            let (code, _, err) = client(
                &url,
                &pki.client("stranger-client"),
                "read-holding 17 400001",
            );
            assert_eq!(code, 1, "{err}");
            assert!(
                err.contains("refused this end's certificate"),
                "TLS {version}: {err}"
            );
        }
    }
}

#[test]
fn files_that_are_not_what_they_should_be_say_how_to_mend_them() {
    let pki = Pki::new();
    let dir = pki.dir.path();
    let der = dir.join("operator.der");
    let status = std::process::Command::new("openssl")
        .args([
            "x509",
            "-in",
            &pki.path("operator.pem"),
            "-outform",
            "der",
            "-out",
        ])
        .arg(&der)
        .status();
    let pem = std::fs::read_to_string(pki.path("ca.pem")).unwrap();
    std::fs::write(dir.join("cut.pem"), &pem[..pem.len() / 2]).unwrap();
    std::fs::write(
        dir.join("encrypted.key"),
        "-----BEGIN ENCRYPTED PRIVATE KEY-----\nMIIBvTBXBgkqhkiG9w0BBQ0wSjApBgkqhkiG9w0BBQwwHAQI\n-----END ENCRYPTED PRIVATE KEY-----\n",
    )
    .unwrap();
    let with = |cert: String, key: String, ca: String| {
        vec![
            "--cert".into(),
            cert,
            "--key".into(),
            key,
            "--ca".into(),
            ca,
        ]
    };
    let mut cases = vec![
        (
            with(
                pki.path("operator.pem"),
                pki.path("encrypted.key"),
                pki.path("ca.pem"),
            ),
            "the key is encrypted: give it decrypted",
        ),
        (
            with(
                pki.path("operator.pem"),
                pki.path("operator.key"),
                pki.path("cut.pem"),
            ),
            "the file is cut short",
        ),
        (
            with(
                pki.path("operator.pem"),
                pki.path("operator.key"),
                dir.display().to_string(),
            ),
            "it is a folder",
        ),
    ];
    if status.is_ok_and(|s| s.success()) {
        cases.push((
            with(
                der.display().to_string(),
                pki.path("operator.key"),
                pki.path("ca.pem"),
            ),
            "it is DER, not PEM: convert it with 'openssl x509 -inform der",
        ));
    }
    for (args, message) in cases {
        let (code, _, err) = client("tls://127.0.0.1:9", &args, "read-holding 17 400001");
        assert_eq!(code, 1, "{err}");
        assert!(err.contains(message), "{message}: {err}");
        assert_eq!(err.lines().count(), 1, "{err}");
    }
}

#[test]
fn certificate_options_for_a_port_that_is_not_tls_are_refused() {
    let pki = Pki::new();
    crate::support::assert_refused(
        &[
            "--port",
            "sim",
            "--ca",
            &pki.path("ca.pem"),
            "read-holding",
            "17",
            "400108",
        ],
        "mbtool: --cert, --key, --ca and --tls-server-name are for tls:// ports: sim is not one",
    );
    // From the environment they are left to the tls:// commands of the same shell.
    let output = mbtool()
        .env("MBTOOL_CA", pki.path("ca.pem"))
        .args([
            "--port",
            "sim",
            "read-holding",
            "17",
            "400108",
            "-o",
            "values",
        ])
        .output()
        .unwrap();
    assert_eq!(String::from_utf8_lossy(&output.stdout).trim(), "555");
    // A scan of a TLS port on tcp:// stops at once and says so.
    let (_server, port, _) = serve_tls(&pki, "server", &[]);
    let (code, _, err) = client(&format!("tcp://127.0.0.1:{port}"), &[], "scan --ids 1-3");
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("use tls://"), "{err}");
}

#[test]
fn a_device_that_closes_idle_connections_is_connected_again() {
    let pki = Pki::new();
    let (_device, port) = openssl_device(&pki, "1.3");
    let (code, out, err) = client(
        &format!("tls://localhost:{port}"),
        &pki.client("operator"),
        "read-holding 17 400001 --poll 100ms --count 4 -o values",
    );
    // wait_for_listener's own connection took no answer: every poll is one, none fails.
    assert_eq!(code, 0, "{out}{err}");
    assert_eq!(
        out.split_whitespace().collect::<Vec<_>>(),
        ["0", "1", "2", "3"],
        "{err}"
    );
}

#[test]
fn a_role_with_control_characters_forges_no_log_line() {
    let pki = Pki::new();
    let (_server, port, log) = serve_tls(&pki, "server", &["--role", "viewer=read"]);
    let url = format!("tls://localhost:{port}");
    let (code, _, err) = client(&url, &pki.client("forger"), "read-holding 17 400108");
    assert_eq!(code, 1, "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    let refusal =
        "(CN=forger) refused: its role extension is no UTF8String of printable characters";
    let logged = logged_once(&log, &[refusal]);
    assert!(logged.contains(refusal), "{logged}");
    assert!(
        !logged.lines().any(|line| line.starts_with("fake line")),
        "{logged}"
    );
    assert!(!logged.contains('\u{1b}'), "{logged}");
    // A framing of its own is refused with the port's scheme named.
    let (code, _, err) = client(
        &url,
        &pki.client("viewer"),
        "read-holding 17 400108 --mode rtu",
    );
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("tls:// carries Modbus TCP frames"), "{err}");
}

#[test]
fn a_plain_server_with_roles_gives_every_client_the_plain_role() {
    let port = free_port();
    let log = tempfile::NamedTempFile::new().unwrap();
    let _server = Stopped(
        mbtool_process()
            .args(["--port", &format!("tcp://127.0.0.1:{port}"), "serve"])
            .args([
                "--role",
                "viewer=read:400001-400010",
                "--plain-role",
                "viewer",
            ])
            .stdout(Stdio::null())
            .stderr(log.reopen().unwrap())
            .spawn()
            .unwrap(),
    );
    assert!(wait_for_listener(port, Duration::from_secs(10)));
    let url = format!("127.0.0.1:{port}");
    let (code, out, err) = client(&url, &[], "read-holding 17 400001 2 -o values");
    assert_eq!((code, out.as_str()), (0, "0\n0\n"), "{err}");
    let (code, _, err) = client(&url, &[], "write-register 17 400001 5");
    assert_eq!(code, 11, "{err}");
    let (code, _, err) = client(&url, &[], "read-holding 17 400108");
    assert_eq!(code, 11, "{err}");
    let logged = logged_once(log.path(), &["may not read 400108"]);
    assert!(logged.contains("every client gets role viewer"), "{logged}");
    assert!(
        logged.contains("(viewer) slave 17: 6 Write Single Register 400001 = 5 -> exception 01 illegal function: role viewer may not write 400001"),
        "{logged}"
    );
    assert!(
        logged.contains("-> exception 01 illegal function: role viewer may not read 400108"),
        "{logged}"
    );
}

#[test]
fn a_flood_of_unfinished_handshakes_does_not_lock_out_a_certificate_holder() {
    if !peer_available("python3", python_has("selectors")) {
        return;
    }
    let pki = Pki::new();
    // A byte of a ClientHello from the honest client's own address, and from 200 others;
    // whole ClientHellos, each stalled after the answer, from 200 others.
    for (spread, whole) in [(false, false), (true, false), (true, true)] {
        let port = free_port();
        let log = pki.dir.path().join(format!("gateway-{port}.log"));
        // Few descriptors, as a small device or a strict service unit has.
        let command = format!(
            "ulimit -n 64 && exec {} --port sim --cert {} --key {} --ca {} gateway --listen tls://127.0.0.1:{port} --role operator=read,write --quiet",
            assert_cmd::cargo::cargo_bin("mbtool").display(),
            pki.path("server.pem"),
            pki.path("server.key"),
            pki.path("ca.pem"),
        );
        let _gateway = Stopped(
            Process::new("sh")
                .args(["-c", &command])
                .stdout(Stdio::null())
                .stderr(std::fs::File::create(&log).unwrap())
                .spawn()
                .unwrap(),
        );
        assert!(wait_for_listener(port, Duration::from_secs(10)));
        let flood = Process::new("python3")
            .arg(concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/tests/peers/slow_hello_flood.py"
            ))
            .args([port.to_string(), "200".into(), "4".into()])
            .args(spread.then_some("spread"))
            .args(whole.then_some("whole"))
            .stdout(Stdio::piped())
            .spawn()
            .unwrap();
        std::thread::sleep(Duration::from_millis(500));
        let url = format!("tls://localhost:{port}");
        let operator = pki.client("operator");
        for _ in 0..4 {
            let asked = Instant::now();
            let (code, out, err) = client(&url, &operator, "read-holding 17 400108 -o values");
            let logged = std::fs::read_to_string(&log).unwrap();
            assert_eq!(
                (code, out.trim()),
                (0, "555"),
                "spread {spread}, whole {whole}: {err}{logged}"
            );
            assert!(
                asked.elapsed() < Duration::from_secs(1),
                "spread {spread}, whole {whole}: {:?}",
                asked.elapsed()
            );
            std::thread::sleep(Duration::from_millis(300));
        }
        let flooded = flood.wait_with_output().unwrap();
        let connects: u64 = String::from_utf8_lossy(&flooded.stdout)
            .trim()
            .parse()
            .unwrap();
        assert!(
            connects > 400,
            "the flood was not one: {connects} connections"
        );
        // Refusals are told a line a second, not one each.
        let logged = std::fs::read_to_string(&log).unwrap();
        assert!(
            logged.lines().count() < 20,
            "{} lines: {logged}",
            logged.lines().count()
        );
        assert!(logged.contains("more clients refused"), "{logged}");
    }
}

/// A client that speaks TLS 1.1 is told in the server's log as what it is, not by the
/// name of the TLS extension its hello lacks.
#[test]
fn a_client_of_an_older_tls_is_told_so() {
    if !peer_available("openssl", command_exists("openssl")) {
        return;
    }
    let pki = Pki::new();
    let (_server, port, log) =
        serve_tls(&pki, "server", &["--role", "x=read", "--default-role", "x"]);
    let _ = std::process::Command::new("openssl")
        .args(["s_client", "-connect", &format!("127.0.0.1:{port}")])
        .args(["-tls1_1", "-cipher", "DEFAULT@SECLEVEL=0"])
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .unwrap();
    let said = "refused: it speaks a TLS older than 1.2";
    assert!(
        logged_once(&log, &[said]).contains(said),
        "{}",
        std::fs::read_to_string(&log).unwrap()
    );
}

/// A device whose certificate is X.509 version 1 (openssl x509 -req without -extfile),
/// which has no subjectAltName, is told so, with how to make one that serves.
#[test]
fn a_device_certificate_of_version_one_is_told_as_such() {
    if !peer_available("openssl", command_exists("openssl")) {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let path = |name: &str| dir.path().join(name).display().to_string();
    let openssl = |args: &[&str]| {
        let status = std::process::Command::new("openssl")
            .args(args)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .status()
            .unwrap();
        assert!(status.success(), "openssl {args:?}");
    };
    let ec = [
        "-newkey",
        "ec",
        "-pkeyopt",
        "ec_paramgen_curve:prime256v1",
        "-nodes",
    ];
    openssl(
        &[
            &["req", "-x509"],
            &ec[..],
            &[
                "-keyout",
                &path("ca.key"),
                "-out",
                &path("ca.pem"),
                "-subj",
                "/CN=ca",
                "-days",
                "5",
            ],
        ]
        .concat(),
    );
    openssl(
        &[
            &["req"],
            &ec[..],
            &[
                "-keyout",
                &path("d.key"),
                "-out",
                &path("d.csr"),
                "-subj",
                "/CN=localhost",
            ],
        ]
        .concat(),
    );
    openssl(&[
        "x509",
        "-req",
        "-in",
        &path("d.csr"),
        "-CA",
        &path("ca.pem"),
        "-CAkey",
        &path("ca.key"),
        "-CAcreateserial",
        "-out",
        &path("d.pem"),
        "-days",
        "5",
    ]);
    let port = free_port();
    let _device = Stopped(
        std::process::Command::new("openssl")
            .args(["s_server", "-quiet", "-accept", &port.to_string()])
            .args(["-cert", &path("d.pem"), "-key", &path("d.key")])
            .stdin(Stdio::piped())
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap(),
    );
    assert!(wait_for_listener(port, Duration::from_secs(10)));
    let (code, _, err) = client(
        &format!("tls://localhost:{port}"),
        &["--ca".to_string(), path("ca.pem")],
        "read-holding 17 400108",
    );
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains("the device's certificate is X.509 version 1")
            && err.contains("subjectAltName=DNS:localhost"),
        "{err}"
    );
}
