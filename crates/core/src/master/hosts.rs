//! Finding Modbus TCP devices on a network, politely: a bounded number of hosts at once,
//! one connection to a host at a time, a pause between two requests to one host, and each
//! connection closed (FIN) as soon as its host is asked. Port 802 is asked over TLS
//! (Modbus/TCP Security) where this end's certificates are given. Per host and port: whether it
//! takes a connection, whether Modbus answers, which unit ids answer, and their
//! identification (43/14) and server id (17).

use std::collections::HashSet;
use std::io::Read;
use std::net::{IpAddr, Shutdown, SocketAddr, TcpStream, ToSocketAddrs};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Condvar, Mutex};
use std::time::Duration;

use super::device::{identification, server_id, Asked, Identification, ServerId};
use super::{Master, MasterError, MasterOptions, Reply, Traffic};
use crate::codec::{ExceptionCode, Mode, Request, Response};
use crate::input::hosts::Host;
use crate::transport::tcp::Tcp;
use crate::transport::tls::{ClientTls, Tls, MODBUS_TLS_PORT};
use crate::transport::Transport;

/// How a sweep asks.
#[derive(Clone, Debug)]
pub struct SweepOptions {
    /// The TCP ports asked on each host.
    pub ports: Vec<u16>,
    /// The unit ids asked on each, in order.
    pub ids: Vec<u8>,
    /// How many hosts are asked at once.
    pub parallel: usize,
    /// How long a connection, and an answer, is waited for.
    pub timeout: Duration,
    /// The pause between two requests to one host.
    pub pause: Duration,
    /// What each unit id is asked first.
    pub probe: Request,
    /// Whether every id is asked even where the first ones got no answer at all.
    pub ask_silent: bool,
    /// This end's certificates: port 802 is then asked over TLS (Modbus/TCP Security).
    pub tls: Option<ClientTls>,
    /// Told of every frame sent and received, with the host and port it went to.
    pub trace: Option<SweepTracer>,
}

/// Told of a frame: the host and port, which way, the bytes.
pub type FrameSeen = dyn Fn(&str, Traffic, &[u8]) + Send + Sync;

/// What a sweep tells of each frame, shared by the threads that ask hosts.
#[derive(Clone)]
pub struct SweepTracer(pub Arc<FrameSeen>);

impl std::fmt::Debug for SweepTracer {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("SweepTracer")
    }
}

/// How a host's port took the connection.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reach {
    /// It took it.
    Open,
    /// Nothing listens there: refused.
    Refused,
    /// No answer within the timeout (a host that is not there, or a firewall).
    Silent,
    /// The name has no address.
    Unknown,
}

/// What a connection that took no Modbus answer did instead.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Instead {
    /// It sent bytes that are no Modbus answer (another protocol on the port).
    Garbage,
    /// It closed or reset the connection.
    Closed,
    /// It speaks TLS: Modbus/TCP Security on a port other than 802, or without this
    /// end's certificates.
    Tls,
}

/// How a unit id answered.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Unit {
    /// The unit id.
    pub id: u8,
    /// Its exception to the probe, if it gave one.
    pub exception: Option<ExceptionCode>,
    /// Its identification, where it gave one.
    pub identification: Option<Identification>,
    /// Its server id, where it gave one.
    pub server_id: Option<ServerId>,
}

/// What one host's port said.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HostReport {
    /// The host as given.
    pub host: String,
    /// Its address and the port asked; `None` for a name without an address.
    pub address: Option<SocketAddr>,
    /// The port asked.
    pub port: u16,
    /// How it took the connection.
    pub reach: Reach,
    /// Whether a Modbus TCP frame came back at all (a gateway's 0A/0B included).
    pub modbus: bool,
    /// The unit ids that answer (a gateway's 0A and 0B are no answer of a device).
    pub units: Vec<Unit>,
    /// A stop ended its asking before every id was asked: what it holds is what was
    /// found until then.
    pub interrupted: bool,
    /// Where Modbus did not answer: what the connection did instead, if anything.
    pub instead: Option<Instead>,
    /// Silent to 0, 1 and 255, it was not asked the other ids (`ask_silent` asks them).
    pub given_up: bool,
    /// It took the connection and the TLS handshake failed: why.
    pub tls_failed: Option<String>,
}

impl HostReport {
    /// Whether anything Modbus was found there.
    pub fn found(&self) -> bool {
        self.modbus
    }
}

/// A master on `transport`, asking with `options`' timeout, never more than once; a stop
/// ends the request it waits on.
fn master_on(
    transport: Box<dyn Transport>,
    options: &SweepOptions,
    stop: &Arc<AtomicBool>,
    place: SocketAddr,
) -> Master {
    let mut master = Master::new(
        transport,
        MasterOptions {
            mode: Mode::Tcp,
            timeout: options.timeout,
            retries: 0,
            retry_non_idempotent: false,
            frame_gap: Duration::ZERO,
            character: Duration::ZERO,
            silence: Duration::ZERO,
            turnaround: Duration::ZERO,
        },
    );
    master.stop_on(Arc::clone(stop));
    if let Some(SweepTracer(trace)) = &options.trace {
        let trace = Arc::clone(trace);
        let place = place.to_string();
        master.trace(Box::new(move |traffic, bytes| {
            trace(&place, traffic, bytes);
        }));
    }
    master
}

/// The addresses a connection is open to: one host named twice (an address and its name)
/// still gets one connection at a time.
#[derive(Default)]
struct Busy {
    addresses: Mutex<HashSet<IpAddr>>,
    freed: Condvar,
}

impl Busy {
    /// Waits until no connection is open to `address`, then takes it until the guard
    /// drops.
    fn hold(&self, address: IpAddr) -> Held<'_> {
        let mut busy = self.addresses.lock().unwrap_or_else(|p| p.into_inner());
        while busy.contains(&address) {
            busy = self.freed.wait(busy).unwrap_or_else(|p| p.into_inner());
        }
        busy.insert(address);
        Held {
            busy: self,
            address,
        }
    }
}

struct Held<'a> {
    busy: &'a Busy,
    address: IpAddr,
}

impl Drop for Held<'_> {
    fn drop(&mut self) {
        let mut busy = self
            .busy
            .addresses
            .lock()
            .unwrap_or_else(|p| p.into_inner());
        busy.remove(&self.address);
        self.busy.freed.notify_all();
    }
}

/// Whether a gateway's exception says that no device stands behind the unit id.
fn nobody_there(code: ExceptionCode) -> bool {
    matches!(
        code,
        ExceptionCode::GATEWAY_PATH_UNAVAILABLE | ExceptionCode::GATEWAY_TARGET_FAILED
    )
}

/// The longest a sweep waits for a device to close its side once the sweep has closed its
/// own.
const CLOSE_WAIT: Duration = Duration::from_secs(1);

/// A connection that gives no answer at all to this many unit ids (the usual 0, 1 and
/// 255) is taken as silent, and asked no more: a listener that never answers would
/// otherwise cost a timeout for each of the hundreds of ids a sweep may ask.
const SILENT_AFTER: usize = 3;

/// Asks the unit ids of one open connection; what was learnt, even when it broke off.
/// Whether it ended of itself: every id asked, or the connection found silent.
fn ask_units(
    master: &mut Master,
    options: &SweepOptions,
    report: &mut HostReport,
    stop: &AtomicBool,
) -> bool {
    let pause = || std::thread::sleep(options.pause);
    let mut heard = false;
    for (i, &id) in options.ids.iter().enumerate() {
        if stop.load(Ordering::SeqCst) {
            return false;
        }
        if i == SILENT_AFTER && !heard && !options.ask_silent {
            report.given_up = true;
            return true;
        }
        if i > 0 {
            pause();
        }
        // A probe of function 17 is the server id already.
        let mut given_id = None;
        let asked = master.transact(id, &options.probe);
        heard |= !matches!(asked, Err(MasterError::Timeout { .. }));
        match &asked {
            Err(MasterError::BadFrame { .. }) => report.instead = Some(Instead::Garbage),
            Err(MasterError::Io(error)) => {
                report.instead = Some(match error.kind() {
                    // The transport tells a TLS server's first bytes so.
                    std::io::ErrorKind::InvalidData => Instead::Tls,
                    _ => Instead::Closed,
                });
            }
            _ => {}
        }
        let exception = match asked {
            Ok(Reply::Response(Response::ReportServerId { data })) => {
                given_id = Some(ServerId::parse(&data));
                None
            }
            Ok(Reply::Response(_)) => None,
            Ok(Reply::Exception(exception)) if nobody_there(exception.code) => {
                report.modbus = true;
                continue;
            }
            Ok(Reply::Exception(exception)) => Some(exception.code),
            Ok(Reply::Broadcast) => continue,
            // A frame that is no Modbus is still an answer of a kind; nothing of a unit.
            Err(MasterError::BadFrame { .. } | MasterError::Timeout { .. }) => continue,
            Err(_) => return false,
        };
        report.modbus = true;
        pause();
        let identification = match identification(master, id) {
            Ok(Asked::Answered(found)) => Some(found),
            Ok(_) | Err(MasterError::BadFrame { .. } | MasterError::Timeout { .. }) => None,
            Err(_) => return false,
        };
        let server_id = match given_id {
            Some(given) => Some(given),
            None => {
                pause();
                match server_id(master, id) {
                    Ok(Asked::Answered(found)) => Some(found),
                    Ok(_) | Err(MasterError::BadFrame { .. } | MasterError::Timeout { .. }) => None,
                    Err(_) => return false,
                }
            }
        };
        report.units.push(Unit {
            id,
            exception,
            identification,
            server_id,
        });
    }
    true
}

/// Asks one host's port: connects, asks its units, closes.
fn ask_host(
    host: &Host,
    port: u16,
    options: &SweepOptions,
    stop: &Arc<AtomicBool>,
    busy: &Busy,
) -> HostReport {
    let mut report = HostReport {
        host: host.to_string(),
        address: None,
        port,
        reach: Reach::Unknown,
        modbus: false,
        units: Vec::new(),
        interrupted: false,
        instead: None,
        given_up: false,
        tls_failed: None,
    };
    let address = match host {
        Host::Address(address) => Some(SocketAddr::new(*address, port)),
        Host::Name(name) => (name.as_str(), port)
            .to_socket_addrs()
            .ok()
            .and_then(|mut addresses| addresses.next()),
    };
    let Some(address) = address else {
        return report;
    };
    report.address = Some(address);
    let _held = busy.hold(address.ip());
    let reached = |error: std::io::Error| match error.kind() {
        std::io::ErrorKind::ConnectionRefused => Reach::Refused,
        std::io::ErrorKind::TimedOut | std::io::ErrorKind::WouldBlock => Reach::Silent,
        // Taken, and then the TLS handshake failed: open, no Modbus heard.
        _ => Reach::Open,
    };
    if let (MODBUS_TLS_PORT, Some(tls)) = (port, &options.tls) {
        match Tls::connect(&address.ip().to_string(), port, options.timeout, tls) {
            Ok(stream) => {
                report.reach = Reach::Open;
                let mut master = master_on(Box::new(stream), options, stop, address);
                let completed = ask_units(&mut master, options, &mut report, stop);
                report.interrupted = !completed && stop.load(Ordering::SeqCst);
            }
            // Refused by the system: nothing listens. A handshake that failed is told
            // with its reason, by a host that took the connection.
            Err(error) if error.raw_os_error().is_some() => report.reach = reached(error),
            Err(error) if error.kind() == std::io::ErrorKind::TimedOut => {
                report.reach = reached(error);
            }
            Err(error) => {
                report.reach = Reach::Open;
                report.tls_failed = Some(error.to_string());
            }
        }
        return report;
    }
    let stream = match TcpStream::connect_timeout(&address, options.timeout) {
        Ok(stream) => stream,
        Err(error) => {
            report.reach = match reached(error) {
                Reach::Open => Reach::Silent,
                reach => reach,
            };
            return report;
        }
    };
    report.reach = Reach::Open;
    let closer = stream.try_clone();
    if let Ok(transport) = Tcp::from_stream(stream, false) {
        let mut master = master_on(Box::new(transport), options, stop, address);
        let completed = ask_units(&mut master, options, &mut report, stop);
        report.interrupted = !completed && stop.load(Ordering::SeqCst);
    }
    // Closed at once, with a FIN, and the device's own close awaited (a moment at most):
    // no connection is left for it to hold when the next one to it opens.
    if let Ok(mut closer) = closer {
        let _ = closer.shutdown(Shutdown::Write);
        let _ = closer.set_read_timeout(Some(options.timeout.min(CLOSE_WAIT)));
        let mut left = [0u8; 512];
        while matches!(closer.read(&mut left), Ok(n) if n > 0) {}
    }
    report
}

/// Asks every host on every port, `options.parallel` hosts at once (each host's ports one
/// after another), handing each report to `found` as it is done. `stop`, once set, ends
/// it: no new host is begun, and one being asked is left after its current request.
pub fn sweep(
    hosts: &[Host],
    options: &SweepOptions,
    stop: &Arc<AtomicBool>,
    found: impl Fn(HostReport) + Send,
) {
    let next = AtomicUsize::new(0);
    let busy = Busy::default();
    let found = Mutex::new(found);
    std::thread::scope(|scope| {
        for _ in 0..options.parallel.clamp(1, hosts.len().max(1)) {
            scope.spawn(|| loop {
                if stop.load(Ordering::SeqCst) {
                    return;
                }
                let Some(host) = hosts.get(next.fetch_add(1, Ordering::SeqCst)) else {
                    return;
                };
                for (i, &port) in options.ports.iter().enumerate() {
                    if i > 0 {
                        std::thread::sleep(options.pause);
                    }
                    let report = ask_host(host, port, options, stop, &busy);
                    let found = found.lock().unwrap_or_else(|p| p.into_inner());
                    found(report);
                }
            });
        }
    });
}
