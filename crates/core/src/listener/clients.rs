//! TCP clients accepted, each on its own thread so that none can hold up another. When
//! all places are taken, the client silent the longest gives way; a busy client is never
//! closed, and running out of file descriptors is told, not fatal.

use std::io;
use std::net::{Shutdown, TcpListener, TcpStream};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant, SystemTime, UNIX_EPOCH};

use super::handshakes::Handshakes;
use super::Link;
pub(crate) use crate::transport::lock;

/// A TCP client that sends nothing for this long is dropped.
pub const CLIENT_IDLE: Duration = Duration::from_secs(60);
/// Past this many clients, a new one takes the place of the one silent the longest, if
/// that one is idle; a busy client is never closed, so a busy server serves any number.
pub const MAX_CLIENTS: usize = 64;
/// The listen queue asked for (the kernel holds it to net.core.somaxconn): std's 128 fills
/// under a flood of connections that reconnect when closed, and a client whose SYN finds
/// it full waits a second for its retransmission.
const LISTEN_QUEUE: i32 = 4096;
/// How often running out of file descriptors is told while it lasts.
const RETELL_AFTER: Duration = Duration::from_secs(10);
/// A client silent this long is idle: it may make room for a new one.
pub const IDLE_FOR_ROOM: Duration = Duration::from_secs(10);
/// A client that has not taken its answers within this time is dropped: it holds a
/// thread and the answers that wait for it.
pub const WRITE_DEADLINE: Duration = Duration::from_secs(5);
/// Refusals (a TLS handshake failed, a role not allowed) are told in full a few at once
/// ([`REFUSALS_AT_ONCE`]), then one in this time, those in between counted: a flood of
/// clients is a line a second, not one each.
pub const REFUSALS_TOLD_EVERY: Duration = Duration::from_secs(1);
/// How many refusals are told in full before they are held to one in
/// [`REFUSALS_TOLD_EVERY`]: a few misconfigured clients are each named.
pub const REFUSALS_AT_ONCE: u32 = 5;

/// Told of what goes wrong with a client or the listener, from any thread.
pub type ErrorSink = Arc<dyn Fn(io::Error) + Send + Sync>;

/// A client just accepted, handed to the code that serves it on its own thread.
pub struct Accepted {
    /// Its socket, with the write deadline set: the one descriptor of the connection,
    /// shared with the registry that may close it to make room.
    pub stream: Arc<TcpStream>,
    /// Its address, as logs show it.
    pub peer: String,
    /// How many clients were accepted before it.
    pub number: usize,
    /// Its link: idle after [`CLIENT_IDLE`], its activity seen by the room-making.
    pub link: Link,
}

/// Serves a client until it leaves; an error ends the connection and is told.
pub type Serve = Arc<dyn Fn(Accepted) -> io::Result<()> + Send + Sync>;

/// A connected TCP client, as the accepting thread sees it.
struct Client {
    number: usize,
    /// The client's socket, to close it when it must give way.
    handle: Arc<TcpStream>,
    activity: Arc<AtomicU64>,
}

/// Accepts clients on `listener` for ever, each served by `serve` on its own thread. Over
/// TLS, `handshakes` are those under way: when the descriptors run out, a stalled one
/// gives its descriptor to the next client waiting.
pub fn accept_clients(
    listener: TcpListener,
    handshakes: Option<Arc<Handshakes>>,
    on_error: ErrorSink,
    serve: Serve,
) -> io::Result<()> {
    socket2::SockRef::from(&listener).listen(LISTEN_QUEUE)?;
    let clients: Arc<Mutex<Vec<Client>>> = Arc::new(Mutex::new(Vec::new()));
    let refusals = Refusals::start(Arc::clone(&on_error))?;
    // When running out of file descriptors was last told: not at every refused accept.
    let mut told_out_of_descriptors: Option<Instant> = None;
    let mut tell_out_of_descriptors = |connected: usize| {
        if told_out_of_descriptors.is_none_or(|at| at.elapsed() >= RETELL_AFTER) {
            told_out_of_descriptors = Some(Instant::now());
            on_error(out_of_descriptors_error(connected));
        }
    };
    for (number, stream) in listener.incoming().enumerate() {
        let stream = match stream {
            Ok(stream) => stream,
            Err(error) if is_out_of_descriptors(&error) => {
                let mut clients = lock(&clients);
                if close_idlest(&mut clients, &on_error, "no file descriptor was left") {
                    continue;
                }
                let connected = clients.len();
                drop(clients);
                if handshakes.as_ref().is_some_and(|h| h.make_room()) {
                    // Its descriptor comes back as its thread ends, in a moment.
                    std::thread::sleep(Duration::from_millis(1));
                    continue;
                }
                tell_out_of_descriptors(connected);
                // The waiting client stays in the listen queue; try again soon.
                std::thread::sleep(Duration::from_millis(20));
                continue;
            }
            Err(error) => {
                on_error(error);
                continue;
            }
        };
        let peer = stream
            .peer_addr()
            .map_or_else(|_| "?".to_string(), |a| a.to_string());
        let activity = Arc::new(AtomicU64::new(now_ms()));
        let stream = Arc::new(stream);
        make_room_and_add(
            &clients,
            Client {
                number,
                handle: Arc::clone(&stream),
                activity: Arc::clone(&activity),
            },
            &on_error,
        );
        let (clients_left, on_error_there, serve, refusals) = (
            Arc::clone(&clients),
            Arc::clone(&on_error),
            Arc::clone(&serve),
            Arc::clone(&refusals),
        );
        let spawned = std::thread::Builder::new().spawn(move || {
            let (clients, on_error) = (clients_left, on_error_there);
            let link = Link::Tcp {
                idle: CLIENT_IDLE,
                activity,
            };
            // A client that does not read its answers is dropped, not waited for.
            let served = stream
                .set_write_timeout(Some(WRITE_DEADLINE))
                .and_then(|()| {
                    serve(Accepted {
                        stream,
                        peer: peer.clone(),
                        number,
                        link,
                    })
                });
            match served.map_err(|error| worth_telling(error, &peer)) {
                Err(Some(refusal)) if refusal.kind() == io::ErrorKind::PermissionDenied => {
                    refusals.tell(refusal);
                }
                Err(Some(error)) => on_error(error),
                _ => {}
            }
            lock(&clients).retain(|c| c.number != number);
        });
        if let Err(error) = spawned {
            // No thread for it: the client is closed rather than left unanswered.
            let mut clients = lock(&clients);
            if let Some(index) = clients.iter().position(|c| c.number == number) {
                let client = clients.swap_remove(index);
                let _ = client.handle.shutdown(Shutdown::Both);
            }
            on_error(io::Error::other(format!(
                "no thread for another client ({} connected): {error}",
                clients.len()
            )));
        }
    }
    Ok(())
}

/// Refusals told in full while they are few (a bucket of [`REFUSALS_AT_ONCE`], one more
/// every [`REFUSALS_TOLD_EVERY`]); past that, while they keep coming, one line every
/// [`REFUSALS_TOLD_EVERY`] with their number and the last of them.
struct Refusals {
    on_error: ErrorSink,
    state: Mutex<Told>,
}

struct Told {
    /// How many may be told in full now.
    allowed: u32,
    /// When one was last added.
    refilled: Instant,
    /// Held back since the count was last told, and the last of them.
    held: u64,
    last_held: Option<io::Error>,
    /// When the count was last told: while refusals keep coming, the count is all.
    counted: Option<Instant>,
}

impl Refusals {
    /// With a thread that tells the count of those held back.
    fn start(on_error: ErrorSink) -> io::Result<Arc<Refusals>> {
        let refusals = Arc::new(Refusals {
            on_error,
            state: Mutex::new(Told {
                allowed: REFUSALS_AT_ONCE,
                refilled: Instant::now(),
                held: 0,
                last_held: None,
                counted: None,
            }),
        });
        let weak = Arc::downgrade(&refusals);
        std::thread::Builder::new().spawn(move || loop {
            std::thread::sleep(REFUSALS_TOLD_EVERY);
            let Some(refusals) = weak.upgrade() else {
                break;
            };
            refusals.tell_held();
        })?;
        Ok(refusals)
    }

    fn tell(&self, refusal: io::Error) {
        let mut state = lock(&self.state);
        let flood = state
            .counted
            .is_some_and(|at| at.elapsed() < 2 * REFUSALS_TOLD_EVERY);
        if !flood && state.refilled.elapsed() >= REFUSALS_TOLD_EVERY {
            state.refilled = Instant::now();
            state.allowed = (state.allowed + 1).min(REFUSALS_AT_ONCE);
        }
        if flood || state.allowed == 0 {
            state.held += 1;
            state.last_held = Some(refusal);
            return;
        }
        state.allowed -= 1;
        drop(state);
        (self.on_error)(refusal);
    }

    fn tell_held(&self) {
        let mut state = lock(&self.state);
        let held = std::mem::take(&mut state.held);
        let Some(last) = state.last_held.take() else {
            return;
        };
        state.counted = Some(Instant::now());
        drop(state);
        (self.on_error)(io::Error::other(format!(
            "{held} more clients refused in the last {} s, the last: {last}",
            REFUSALS_TOLD_EVERY.as_secs()
        )));
    }
}

/// What ended a client's connection, as it is told: nothing for a client that simply left.
fn worth_telling(error: io::Error, peer: &str) -> Option<io::Error> {
    match error.kind() {
        io::ErrorKind::ConnectionAborted
        | io::ErrorKind::ConnectionReset
        | io::ErrorKind::NotConnected
        | io::ErrorKind::BrokenPipe => None,
        io::ErrorKind::WouldBlock | io::ErrorKind::TimedOut if error.get_ref().is_none() => {
            Some(io::Error::other(format!(
                "{peer} did not read its answers for {} s: connection closed",
                WRITE_DEADLINE.as_secs()
            )))
        }
        _ => Some(error),
    }
}

/// Adds a client; past [`MAX_CLIENTS`], the one silent the longest is closed first if it
/// is idle.
fn make_room_and_add(clients: &Mutex<Vec<Client>>, client: Client, on_error: &ErrorSink) {
    let mut clients = lock(clients);
    if clients.len() >= MAX_CLIENTS {
        let why = format!("{} clients were connected", clients.len());
        close_idlest(&mut clients, on_error, &why);
    }
    clients.push(client);
}

/// Closes the client silent the longest, if it has been silent for [`IDLE_FOR_ROOM`]; says
/// so with `why`, and whether one was closed.
fn close_idlest(clients: &mut Vec<Client>, on_error: &ErrorSink, why: &str) -> bool {
    let now = now_ms();
    let idle_ms = IDLE_FOR_ROOM.as_millis() as u64;
    let idlest = (0..clients.len())
        .min_by_key(|&i| clients[i].activity.load(Ordering::Relaxed))
        .filter(|&i| now.saturating_sub(clients[i].activity.load(Ordering::Relaxed)) >= idle_ms);
    let Some(index) = idlest else {
        return false;
    };
    let idlest = clients.swap_remove(index);
    let _ = idlest.handle.shutdown(Shutdown::Both);
    let silent = now.saturating_sub(idlest.activity.load(Ordering::Relaxed)) / 1000;
    on_error(io::Error::other(format!(
        "{why}: {}, silent for {silent} s, was closed to make room",
        idlest
            .handle
            .peer_addr()
            .map_or_else(|_| "?".to_string(), |a| a.to_string())
    )));
    true
}

/// What the server says when the file descriptors run out with `connected` clients.
fn out_of_descriptors_error(connected: usize) -> io::Error {
    io::Error::other(format!(
        "no file descriptor left for another client ({connected} connected): \
         new clients wait until one leaves; 'ulimit -n' raises the limit"
    ))
}

/// Whether accepting failed because the process or the system has no file descriptor left.
fn is_out_of_descriptors(error: &io::Error) -> bool {
    // EMFILE and ENFILE on Linux and the BSDs alike.
    matches!(error.raw_os_error(), Some(23 | 24))
}

/// Milliseconds since 1970, for telling which client has been silent the longest.
pub(crate) fn now_ms() -> u64 {
    SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_millis() as u64)
}
