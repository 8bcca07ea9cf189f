//! Modbus/TCP Security: Modbus TCP frames inside TLS 1.2 or 1.3 (port 802), both ends
//! known by X.509 certificates, the client's role carried in an extension of its own.
//!
//! The same stream serves a master ([`Tls::connect`]) and a server ([`TlsServer::accept`]);
//! nothing of Modbus is sent before the handshake has succeeded, and every way a
//! handshake fails is told as what to do about it ([`TlsError`]).

use std::fmt;
use std::io::{self, Read, Write};
use std::net::TcpStream;
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use rustls::pki_types::{CertificateDer, ServerName};
use rustls::{ClientConfig, ClientConnection, Connection, ServerConfig, ServerConnection};
use thiserror::Error;

use super::{
    connect_first, lock, receive_timed, time_left, TimedRead, Transport, IDLE_CHECK_AFTER,
};

mod files;
mod names;
mod refusals;

pub use files::certificate_role;
pub use files::root_store;
use files::{certificates, check_validity, key_error, not_after_of, private_key, subject_of};
use refusals::{client_side, server_side};

/// The least time a master gives a device for the TLS handshake.
const HANDSHAKE_LEAST: Duration = Duration::from_secs(3);

/// The port of Modbus/TCP Security.
pub const MODBUS_TLS_PORT: u16 = 802;

/// The certificate extension that carries a client's role, a UTF8String
/// (MB/TCP Security, "Role" extension).
pub const ROLE_OID: &str = "1.3.6.1.4.1.50316.802.1";

/// The certificate files of one end, as the options name them.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct TlsFiles {
    /// This end's certificate chain (PEM), its own first.
    pub cert: Option<PathBuf>,
    /// The private key of `cert` (PEM: PKCS#8, RSA or EC).
    pub key: Option<PathBuf>,
    /// The CAs that sign the other end's certificate (PEM).
    pub ca: Option<PathBuf>,
    /// The name the server's certificate must hold, where it is not the host connected to.
    pub server_name: Option<String>,
}

/// Why a TLS connection cannot be made or used, each said as what to do.
#[derive(Debug, Error)]
pub enum TlsError {
    /// A PEM file that cannot be read.
    #[error("cannot read {path}: {why}")]
    Unreadable {
        /// The file.
        path: PathBuf,
        /// What the system said.
        why: String,
    },
    /// A file without the PEM block it should hold.
    #[error("{path} holds no {what}: {why}")]
    NoPem {
        /// The file.
        path: PathBuf,
        /// What it should hold.
        what: &'static str,
        /// What it holds instead, and what to do.
        why: String,
    },
    /// A certificate or key that does not parse.
    #[error("{path}: {why}")]
    Malformed {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        why: String,
    },
    /// The key is not the one of the certificate.
    #[error("the key {key} does not belong to the certificate {cert}: give the key made with it")]
    KeyMismatch {
        /// The certificate file.
        cert: PathBuf,
        /// The key file.
        key: PathBuf,
    },
    /// An option needed for this end is missing.
    #[error("{0}")]
    Missing(&'static str),
    /// This end's own certificate is out of its validity.
    #[error(
        "{path} {when}: the other end will refuse it; renew it (or check this computer's clock)"
    )]
    OwnCertificate {
        /// The certificate file.
        path: PathBuf,
        /// `expired on ...` or `is not valid until ...`.
        when: String,
    },
    /// The handshake cannot be set up; the text says why.
    #[error("{0}")]
    Handshake(String),
}

impl From<TlsError> for io::Error {
    fn from(error: TlsError) -> io::Error {
        let kind = match error {
            TlsError::Unreadable { .. } => io::ErrorKind::NotFound,
            TlsError::Handshake(_) => io::ErrorKind::ConnectionRefused,
            _ => io::ErrorKind::InvalidInput,
        };
        io::Error::new(kind, error.to_string())
    }
}

/// What a master's TLS connection is made with: its configuration, checked once.
#[derive(Clone)]
pub struct ClientTls {
    config: Arc<ClientConfig>,
    server_name: Option<String>,
    /// The role this end's certificate carries, for `-v`.
    role: Option<String>,
    ca: PathBuf,
    cert: Option<PathBuf>,
}

impl fmt::Debug for ClientTls {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("ClientTls")
            .field("ca", &self.ca)
            .field("cert", &self.cert)
            .field("role", &self.role)
            .finish_non_exhaustive()
    }
}

impl ClientTls {
    /// Reads and checks the files of a master: `ca` is needed, `cert` and `key` go
    /// together.
    pub fn new(files: &TlsFiles) -> Result<ClientTls, TlsError> {
        let ca = files.ca.clone().ok_or(TlsError::Missing(
            "tls:// needs --ca FILE, the CA certificates that sign the device's certificate",
        ))?;
        let roots = root_store(&ca)?;
        let verifier = names::NamingVerifier::new(roots, provider())
            .map_err(|e| TlsError::Handshake(e.to_string()))?;
        let builder = ClientConfig::builder_with_provider(provider())
            .with_protocol_versions(rustls::DEFAULT_VERSIONS)
            .map_err(|e| TlsError::Handshake(e.to_string()))?
            .dangerous()
            .with_custom_certificate_verifier(Arc::new(verifier));
        let (config, role) = match (&files.cert, &files.key) {
            (Some(cert), Some(key)) => {
                let chain = certificates(cert)?;
                check_validity(cert, &chain[0])?;
                let role = match certificate_role(&chain[0]) {
                    RoleClaim::Named(role) => Some(role),
                    _ => None,
                };
                let private = private_key(key)?;
                let config = builder
                    .with_client_auth_cert(chain, private)
                    .map_err(|e| key_error(e, cert, key))?;
                (config, role)
            }
            (Some(_), None) => {
                return Err(TlsError::Missing("--cert needs --key, its private key"))
            }
            (None, Some(_)) => {
                return Err(TlsError::Missing("--key needs --cert, its certificate"))
            }
            (None, None) => (builder.with_no_client_auth(), None),
        };
        Ok(ClientTls {
            config: Arc::new(config),
            server_name: files.server_name.clone(),
            role,
            ca,
            cert: files.cert.clone(),
        })
    }
}

/// A client configuration for an ordinary TLS server, such as an MQTT broker: its
/// certificate checked against `roots` and its host name, as the web checks them.
pub fn standard_client(roots: rustls::RootCertStore) -> Result<ClientConfig, TlsError> {
    Ok(ClientConfig::builder_with_provider(provider())
        .with_protocol_versions(rustls::DEFAULT_VERSIONS)
        .map_err(|e| TlsError::Handshake(e.to_string()))?
        .with_root_certificates(roots)
        .with_no_client_auth())
}

/// What a server's TLS connections are made with: a certificate and key, and the CAs a
/// client's certificate must be signed by (a client without one is refused).
#[derive(Clone)]
pub struct TlsServer {
    config: Arc<ServerConfig>,
    /// Why clients will refuse this server's certificate, if they will: it is out of
    /// date. A stand-in device may serve one all the same, to test its clients.
    pub out_of_date: Option<String>,
}

impl fmt::Debug for TlsServer {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("TlsServer").finish_non_exhaustive()
    }
}

/// The role a client's certificate claims.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum RoleClaim {
    /// The extension, with this role.
    Named(String),
    /// No role extension.
    Absent,
    /// An extension that is no UTF8String, or holds control characters.
    Unreadable,
}

/// A client accepted over TLS: the stream and who it is.
pub struct AcceptedTls {
    /// The connection, handshake done.
    pub stream: Tls,
    /// The role its certificate claims.
    pub role: RoleClaim,
    /// Its certificate's subject.
    pub subject: String,
}

impl TlsServer {
    /// Reads and checks the files of a server: all three are needed.
    pub fn new(files: &TlsFiles) -> Result<TlsServer, TlsError> {
        let (Some(cert), Some(key), Some(ca)) = (&files.cert, &files.key, &files.ca) else {
            return Err(TlsError::Missing(
                "a tls:// server needs --cert and --key (its own) and --ca (the CAs that sign its clients' certificates)",
            ));
        };
        let roots = Arc::new(root_store(ca)?);
        let chain = certificates(cert)?;
        let out_of_date = check_validity(cert, &chain[0]).err().map(|e| e.to_string());
        let private = private_key(key)?;
        let verifier =
            rustls::server::WebPkiClientVerifier::builder_with_provider(roots, provider())
                .build()
                .map_err(|e| TlsError::Malformed {
                    path: ca.clone(),
                    why: e.to_string(),
                })?;
        let config = ServerConfig::builder_with_provider(provider())
            .with_protocol_versions(rustls::DEFAULT_VERSIONS)
            .map_err(|e| TlsError::Handshake(e.to_string()))?
            .with_client_cert_verifier(verifier)
            .with_single_cert(chain, private)
            .map_err(|e| key_error(e, cert, key))?;
        Ok(TlsServer {
            config: Arc::new(config),
            out_of_date,
        })
    }

    /// Makes the handshake with a client that has just connected, by `deadline`; `heard`
    /// counts the bytes the client has sent meanwhile, for whoever watches its progress.
    pub fn accept(
        &self,
        stream: Arc<TcpStream>,
        deadline: Instant,
        heard: &AtomicUsize,
    ) -> io::Result<AcceptedTls> {
        // Frames are small and each waits for an answer: send at once.
        stream.set_nodelay(true)?;
        let peer = peer_of(&stream);
        let connection = ServerConnection::new(Arc::clone(&self.config))
            .map_err(|e| io::Error::other(e.to_string()))?;
        let mut tls = Tls::new(stream, connection.into(), peer);
        tls.handshake(deadline, None, heard)
            .map_err(|e| server_side(e, &tls.peer))?;
        let own = tls.peer_certificate();
        let (role, subject) = match own {
            Some(der) => (certificate_role(&der), subject_of(&der)),
            None => (RoleClaim::Absent, String::new()),
        };
        Ok(AcceptedTls {
            stream: tls,
            role,
            subject,
        })
    }
}

/// What `-v` tells of a connection: the version, cipher suite, the other end's
/// certificate and the role this end sent.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TlsSession {
    /// `TLS 1.3`.
    pub version: String,
    /// `TLS13_AES_256_GCM_SHA384`.
    pub cipher_suite: String,
    /// The other end's certificate subject (`CN=plc1`).
    pub subject: String,
    /// When it expires.
    pub not_after: String,
    /// The role this end's certificate carries, if any.
    pub role_sent: Option<String>,
}

/// A TLS connection carrying Modbus TCP frames, either end. A server that reads and
/// writes a client from two threads takes a [`TlsWriter`] of it ([`Tls::writer`]): the TLS
/// state is shared, and no thread holds it while it waits for the socket.
pub struct Tls {
    /// Shared with the connection's [`TlsWriter`]: one descriptor a connection.
    socket: Arc<TcpStream>,
    connection: Arc<Mutex<Connection>>,
    peer: String,
    /// The read timeout last set, in whole milliseconds (as [`super::tcp::Tcp`] keeps it).
    read_timeout_ms: u64,
    session: Option<TlsSession>,
    /// A master's end: how it connected, to tell a refusal that comes after the
    /// handshake (TLS 1.3 servers judge the client's certificate then).
    master: Option<Master>,
    /// Whether anything has come since the handshake.
    heard: bool,
    /// When the connection last carried a frame either way.
    last_used: Instant,
}

/// The sending side of a [`Tls`], for another thread.
pub struct TlsWriter {
    socket: Arc<TcpStream>,
    connection: Arc<Mutex<Connection>>,
}

/// What a master's connection was made with, for its messages.
struct Master {
    tls: ClientTls,
    name: String,
    host: String,
    port: u16,
    timeout: Duration,
}

impl Tls {
    fn new(socket: Arc<TcpStream>, connection: Connection, peer: String) -> Tls {
        Tls {
            socket,
            connection: Arc::new(Mutex::new(connection)),
            peer,
            read_timeout_ms: 0,
            session: None,
            master: None,
            heard: false,
            last_used: Instant::now(),
        }
    }

    /// A failure of the connection, told as what to do.
    fn explained(&self, error: io::Error) -> io::Error {
        match &self.master {
            Some(master) => client_side(error, master.port, &master.name, &master.tls),
            None => server_side(error, &self.peer),
        }
    }

    /// The other end closed the connection: before it said anything, a device that
    /// refuses a client's role or certificate does that.
    fn closed(&self) -> io::Error {
        match (&self.master, self.heard) {
            (Some(master), false) => {
                let why = match master.tls.cert {
                    None => "most likely it wants a client certificate: give --cert and --key",
                    Some(_) => "a device does this to a certificate, or a role, it does not accept",
                };
                io::Error::new(
                    io::ErrorKind::ConnectionAborted,
                    format!(
                        "{} closed the connection without answering: {why}",
                        self.peer
                    ),
                )
            }
            _ => closed(&self.peer),
        }
    }

    /// Connects to `host` and makes the handshake, both within `timeout`.
    pub fn connect(host: &str, port: u16, timeout: Duration, tls: &ClientTls) -> io::Result<Tls> {
        let name = tls.server_name.as_deref().unwrap_or(host).to_string();
        let server_name = ServerName::try_from(name.clone()).map_err(|_| {
            io::Error::new(
                io::ErrorKind::InvalidInput,
                format!("'{name}' is no host name to check a certificate against: give --tls-server-name NAME"),
            )
        })?;
        let timeout = timeout.max(Duration::from_millis(1));
        let (socket, address) = connect_first(host, port, timeout)?;
        socket.set_nodelay(true)?;
        let connection = ClientConnection::new(Arc::clone(&tls.config), server_name)
            .map_err(|e| io::Error::other(e.to_string()))?;
        let mut stream = Tls::new(Arc::new(socket), connection.into(), address.to_string());
        stream.master = Some(Master {
            tls: tls.clone(),
            name,
            host: host.to_string(),
            port,
            timeout,
        });
        // Embedded devices take hundreds of milliseconds over a handshake: it gets at
        // least HANDSHAKE_LEAST, whatever the answer timeout (a scan's is 100 ms).
        let budget = timeout.max(HANDSHAKE_LEAST);
        stream
            .handshake(Instant::now() + budget, Some(budget), &AtomicUsize::new(0))
            .map_err(|e| stream.explained(e))?;
        let (subject, not_after) = stream
            .peer_certificate()
            .map(|der| (subject_of(&der), not_after_of(&der)))
            .unwrap_or_default();
        let (version, cipher_suite) = stream.agreed();
        stream.session = Some(TlsSession {
            version,
            cipher_suite,
            subject,
            not_after,
            role_sent: tls.role.clone(),
        });
        Ok(stream)
    }

    /// What `-v` tells of this connection (a connection this end made).
    pub fn session(&self) -> Option<&TlsSession> {
        self.session.as_ref()
    }

    /// Where another thread sends on this connection.
    pub fn writer(&self) -> TlsWriter {
        TlsWriter {
            socket: Arc::clone(&self.socket),
            connection: Arc::clone(&self.connection),
        }
    }

    /// Reads and writes until the handshake is done or `deadline` passes, counting in
    /// `heard` the bytes the other end sends.
    fn handshake(
        &mut self,
        deadline: Instant,
        timeout: Option<Duration>,
        heard: &AtomicUsize,
    ) -> io::Result<()> {
        // A server's clients have a write deadline: it outlives the handshake's.
        let write_timeout = self.socket.write_timeout()?;
        let mut connection = lock(&self.connection);
        // Whether the other end has answered in TLS: a close after that is a refusal, a
        // close before it is no TLS at all.
        let mut answered = false;
        let ended = |answered: bool| {
            let (kind, what) = match answered {
                true => (io::ErrorKind::ConnectionAborted, "ended the handshake"),
                false => (io::ErrorKind::UnexpectedEof, "closed during the handshake"),
            };
            io::Error::new(kind, what)
        };
        while connection.is_handshaking() {
            let Some(left) = time_left(deadline) else {
                return Err(handshake_timeout(timeout));
            };
            self.socket.set_read_timeout(Some(left))?;
            self.socket.set_write_timeout(Some(left))?;
            let mut watched = Watched {
                socket: &self.socket,
                heard,
            };
            match connection.complete_io(&mut watched) {
                Ok((0, 0)) if connection.is_handshaking() => {
                    return Err(ended(answered || heard.load(Ordering::Relaxed) > 0))
                }
                Ok((read, _)) => answered |= read > 0,
                Err(e)
                    if matches!(
                        e.kind(),
                        io::ErrorKind::ConnectionReset | io::ErrorKind::BrokenPipe
                    ) =>
                {
                    return Err(ended(answered || heard.load(Ordering::Relaxed) > 0))
                }
                Err(e)
                    if matches!(
                        e.kind(),
                        io::ErrorKind::WouldBlock | io::ErrorKind::TimedOut
                    ) =>
                {
                    return Err(handshake_timeout(timeout))
                }
                Err(e) => {
                    // The alert that tells the other end why, if it can still be sent.
                    let _ = connection.write_tls(&mut &*self.socket);
                    return Err(e);
                }
            }
        }
        self.socket.set_write_timeout(write_timeout)?;
        self.read_timeout_ms = 0;
        Ok(())
    }

    fn peer_certificate(&self) -> Option<CertificateDer<'static>> {
        lock(&self.connection)
            .peer_certificates()
            .and_then(|chain| chain.first())
            .map(|der| der.clone().into_owned())
    }

    /// The version and the cipher suite agreed.
    fn agreed(&self) -> (String, String) {
        let connection = lock(&self.connection);
        let version = match connection.protocol_version() {
            Some(rustls::ProtocolVersion::TLSv1_3) => "TLS 1.3".into(),
            Some(rustls::ProtocolVersion::TLSv1_2) => "TLS 1.2".into(),
            Some(other) => format!("{other:?}"),
            None => "?".into(),
        };
        let suite = connection
            .negotiated_cipher_suite()
            .map_or_else(|| "?".into(), |suite| format!("{:?}", suite.suite()));
        (version, suite)
    }

    /// Reads plaintext, reading records from the socket as needed; the socket's read
    /// timeout bounds the wait, which holds no lock.
    fn read_plain(&mut self, out: &mut [u8]) -> io::Result<usize> {
        let mut records = [0u8; 4096];
        loop {
            match lock(&self.connection).reader().read(out) {
                Ok(0) => return Err(self.closed()),
                Ok(n) => {
                    self.heard = true;
                    self.last_used = Instant::now();
                    return Ok(n);
                }
                Err(e) if e.kind() == io::ErrorKind::WouldBlock => {}
                Err(e) if e.kind() == io::ErrorKind::UnexpectedEof => return Err(self.closed()),
                Err(e) => return Err(e),
            }
            let read = match (&*self.socket).read(&mut records) {
                Ok(0) => return Err(self.closed()),
                Ok(read) => read,
                Err(e) if is_gone(&e) => return Err(self.closed()),
                Err(e) => return Err(e),
            };
            let mut connection = lock(&self.connection);
            let mut arrived = &records[..read];
            while !arrived.is_empty() {
                connection.read_tls(&mut arrived)?;
                if let Err(error) = connection.process_new_packets() {
                    let _ = flush(&mut connection, &self.socket);
                    drop(connection);
                    return Err(self.explained(io::Error::new(io::ErrorKind::InvalidData, error)));
                }
            }
        }
    }
}

/// A handshake's socket, counting what the other end sends: a server tells an honest
/// handshake under way from one stalled after a byte by it.
struct Watched<'a> {
    socket: &'a TcpStream,
    heard: &'a AtomicUsize,
}

impl Read for Watched<'_> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let n = self.socket.read(buf)?;
        self.heard.fetch_add(n, Ordering::Relaxed);
        Ok(n)
    }
}

impl Write for Watched<'_> {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.socket.write(buf)
    }

    fn flush(&mut self) -> io::Result<()> {
        self.socket.flush()
    }
}

/// Sends what `connection` has queued.
fn flush(connection: &mut Connection, mut socket: &TcpStream) -> io::Result<()> {
    while connection.wants_write() {
        connection.write_tls(&mut socket)?;
    }
    Ok(())
}

/// Encrypts `frame` and sends it.
fn send(shared: &Mutex<Connection>, socket: &TcpStream, frame: &[u8]) -> io::Result<()> {
    let mut connection = lock(shared);
    connection.writer().write_all(frame)?;
    flush(&mut connection, socket)
}

impl Write for TlsWriter {
    fn write(&mut self, frame: &[u8]) -> io::Result<usize> {
        send(&self.connection, &self.socket, frame)?;
        Ok(frame.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

impl TlsWriter {
    /// Closes the connection both ways, ending the reading thread's wait too.
    pub fn shutdown(&self) -> io::Result<()> {
        self.socket.shutdown(std::net::Shutdown::Both)
    }
}

impl Transport for Tls {
    fn discard_input(&mut self) -> io::Result<()> {
        self.socket.set_nonblocking(true)?;
        let mut scratch = [0u8; 512];
        let result = loop {
            match self.read_plain(&mut scratch) {
                Ok(_) => continue,
                Err(e) if e.kind() == io::ErrorKind::WouldBlock => break Ok(()),
                Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
                Err(e) => break Err(e),
            }
        };
        self.socket.set_nonblocking(false)?;
        match (result, &self.master) {
            // Closed while idle, as devices close a connection after a minute: nothing
            // was lost, and a new connection has nothing stale. A connection closed
            // before it carried anything was refused, and is told so.
            (Err(e), Some(master)) if self.heard && is_gone(&e) => {
                let again = Tls::connect(&master.host, master.port, master.timeout, &master.tls)?;
                *self = again;
                Ok(())
            }
            (result, _) => result,
        }
    }

    fn send(&mut self, frame: &[u8]) -> io::Result<()> {
        // A connection this end made may have been closed while it was idle (its close
        // told, or not): it is made again rather than failing the request.
        if self.master.is_some() && self.last_used.elapsed() >= IDLE_CHECK_AFTER {
            self.discard_input()?;
        }
        self.last_used = Instant::now();
        send(&self.connection, &self.socket, frame).map_err(|e| match is_gone(&e) {
            true => self.closed(),
            false => e,
        })
    }

    fn receive(&mut self, buf: &mut Vec<u8>, deadline: Instant) -> io::Result<usize> {
        receive_timed(self, buf, deadline)
    }

    fn is_serial_line(&self) -> bool {
        false
    }
}

impl TimedRead for Tls {
    fn socket(&self) -> &TcpStream {
        &self.socket
    }

    fn timeout_ms(&mut self) -> &mut u64 {
        &mut self.read_timeout_ms
    }

    fn read_some(&mut self, chunk: &mut [u8]) -> io::Result<usize> {
        self.read_plain(chunk)
    }
}

impl Drop for Tls {
    fn drop(&mut self) {
        // The polite end of a TLS connection; the other end may have gone already.
        let mut connection = lock(&self.connection);
        if !connection.is_handshaking() {
            connection.send_close_notify();
            let _ = self.socket.set_nonblocking(true);
            let _ = flush(&mut connection, &self.socket);
        }
    }
}

fn provider() -> Arc<rustls::crypto::CryptoProvider> {
    Arc::new(rustls::crypto::ring::default_provider())
}

fn peer_of(stream: &TcpStream) -> String {
    stream
        .peer_addr()
        .map_or_else(|_| "the other end".into(), |peer| peer.to_string())
}

fn closed(peer: &str) -> io::Error {
    io::Error::new(
        io::ErrorKind::ConnectionAborted,
        format!("{peer} closed the connection"),
    )
}

/// Whether the other end has closed or reset the connection.
fn is_gone(error: &io::Error) -> bool {
    matches!(
        error.kind(),
        io::ErrorKind::ConnectionAborted
            | io::ErrorKind::ConnectionReset
            | io::ErrorKind::BrokenPipe
            | io::ErrorKind::UnexpectedEof
    )
}

fn handshake_timeout(timeout: Option<Duration>) -> io::Error {
    let within = timeout.map_or_else(String::new, |t| format!(" within {} ms", t.as_millis()));
    io::Error::new(
        io::ErrorKind::TimedOut,
        format!("no TLS handshake{within}: is it a Modbus/TCP Security port (802)? a slow device may need a longer --timeout"),
    )
}

/// Whether `bytes`, the first a TCP peer sent, begin a TLS record (an alert or a
/// handshake): a TLS port answering a plain Modbus TCP request. The record's version
/// (03 01 to 03 04) tells it from an MBAP header whose transaction id is 0x1503 or 0x1603,
/// whose protocol id is 00 00.
pub fn looks_like_tls(bytes: &[u8]) -> bool {
    matches!(bytes, [0x15 | 0x16, 0x03, 0x01..=0x04, ..])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tls_records_are_told_from_mbap() {
        assert!(looks_like_tls(&[0x15, 0x03, 0x03, 0x00, 0x02, 0x02, 0x46]));
        assert!(looks_like_tls(&[0x16, 0x03, 0x01, 0x00]));
        assert!(!looks_like_tls(&[0x00, 0x01, 0x00, 0x00, 0x00, 0x05]));
        assert!(!looks_like_tls(&[0x15, 0x03]));
        // Modbus TCP requests and answers whose transaction ids read as a record's type.
        assert!(!looks_like_tls(&[
            0x16, 0x03, 0x00, 0x00, 0x00, 0x06, 0x11, 0x03
        ]));
        assert!(!looks_like_tls(&[
            0x15, 0x03, 0x00, 0x00, 0x00, 0x05, 0x11, 0x03
        ]));
    }
}
