//! The TLS handshakes under way, bounded: clients that connect and never finish theirs
//! (one byte of a ClientHello, then nothing) must not hold every thread and descriptor
//! while honest clients wait. Past a limit in all, or from one address, the handshake that
//! has made the least progress gives way, the oldest first: one that sent a few bytes and
//! stopped short of a ClientHello, then one not heard yet (its thread may not have read),
//! then one under way. Once half the places in all or of its address are taken, a
//! handshake has less time.

use std::net::{IpAddr, Shutdown, TcpStream};
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use crate::transport::lock;

/// The most handshakes under way at once.
pub const MAX_PENDING: usize = 32;
/// The most handshakes under way from one address.
pub const MAX_PENDING_PER_ADDRESS: usize = 16;
/// How long a client has for its handshake.
pub const HANDSHAKE_TIMEOUT: Duration = Duration::from_secs(10);
/// How long, once half the places are taken: an honest handshake takes milliseconds.
pub const HANDSHAKE_UNDER_PRESSURE: Duration = Duration::from_secs(2);
/// A handshake that has sent nothing for this long has stalled: a client sends its
/// ClientHello as soon as it has connected.
const UNHEARD_STALLED: Duration = Duration::from_millis(200);

/// The fewest bytes a ClientHello takes: its record and handshake headers, version,
/// random, and the shortest lists. A client that has sent as many is under way.
const LEAST_HELLO: usize = 50;

/// The handshakes under way.
#[derive(Debug, Default)]
pub struct Handshakes {
    pending: Mutex<Vec<Pending>>,
    next: AtomicU64,
}

#[derive(Debug)]
struct Pending {
    id: u64,
    address: Option<IpAddr>,
    started: Instant,
    state: Arc<Progress>,
    socket: Arc<TcpStream>,
}

/// How far one handshake has come, as the server's thread and the room-making see it.
#[derive(Debug, Default)]
pub struct Progress {
    /// The bytes the client has sent.
    pub heard: AtomicUsize,
    /// It was closed to make room for another.
    pub evicted: AtomicBool,
}

impl Progress {
    /// Which handshakes give way first: a few bytes and then nothing (0), nothing heard
    /// yet (1), under way (2).
    fn standing(&self) -> u8 {
        match self.heard.load(Ordering::Relaxed) {
            0 => 1,
            n if n < LEAST_HELLO => 0,
            _ => 2,
        }
    }
}

/// A handshake's place among those under way; it gives the place up when dropped.
pub struct Ticket<'a> {
    handshakes: &'a Handshakes,
    id: u64,
    /// By when it must be done.
    pub deadline: Instant,
    /// How far it has come.
    pub progress: Arc<Progress>,
}

impl Drop for Ticket<'_> {
    fn drop(&mut self) {
        lock(&self.handshakes.pending).retain(|pending| pending.id != self.id);
    }
}

impl Handshakes {
    /// A place for the handshake on `socket`, made by closing the handshake that has come
    /// the least far when the places in all, or those of its address, are taken.
    pub fn begin(&self, socket: &Arc<TcpStream>) -> Ticket<'_> {
        let address = socket.peer_addr().ok().map(|a| a.ip());
        let mut pending = lock(&self.pending);
        let from_here = pending.iter().filter(|p| p.address == address).count();
        if from_here >= MAX_PENDING_PER_ADDRESS {
            evict(&mut pending, |p| p.address == address);
        }
        if pending.len() >= MAX_PENDING {
            evict(&mut pending, |_| true);
        }
        let from_here = pending.iter().filter(|p| p.address == address).count();
        let under_pressure =
            pending.len() >= MAX_PENDING / 2 || from_here >= MAX_PENDING_PER_ADDRESS / 2;
        let id = self.next.fetch_add(1, Ordering::Relaxed);
        let progress = Arc::new(Progress::default());
        pending.push(Pending {
            id,
            address,
            started: Instant::now(),
            state: Arc::clone(&progress),
            socket: Arc::clone(socket),
        });
        let time = match under_pressure {
            true => HANDSHAKE_UNDER_PRESSURE,
            false => HANDSHAKE_TIMEOUT,
        };
        Ticket {
            handshakes: self,
            id,
            deadline: Instant::now() + time,
            progress,
        }
    }

    /// Closes the handshake that has come the least far, if it has stalled (a few bytes
    /// and then nothing, or nothing for [`UNHEARD_STALLED`]): room for another client when
    /// the descriptors have run out. Whether one was closed.
    pub fn make_room(&self) -> bool {
        let mut pending = lock(&self.pending);
        let stalled = |p: &Pending| match p.state.standing() {
            0 => true,
            1 => p.started.elapsed() >= UNHEARD_STALLED,
            _ => false,
        };
        let any = pending.iter().any(stalled);
        if any {
            evict(&mut pending, stalled);
        }
        any
    }

    /// How many handshakes are under way.
    pub fn pending(&self) -> usize {
        lock(&self.pending).len()
    }
}

/// Closes the handshake among those `chosen` that has come the least far, the oldest
/// first.
fn evict(pending: &mut Vec<Pending>, chosen: impl Fn(&Pending) -> bool) {
    let victim = (0..pending.len())
        .filter(|&i| chosen(&pending[i]))
        .min_by_key(|&i| {
            let p = &pending[i];
            (p.state.standing(), p.started)
        });
    if let Some(index) = victim {
        let victim = pending.swap_remove(index);
        victim.state.evicted.store(true, Ordering::Relaxed);
        let _ = victim.socket.shutdown(Shutdown::Both);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::net::TcpListener;

    fn connection(listener: &TcpListener) -> Arc<TcpStream> {
        let _client = TcpStream::connect(listener.local_addr().unwrap()).unwrap();
        let (accepted, _) = listener.accept().unwrap();
        // The client end may close: only the server's socket is looked at.
        Arc::new(accepted)
    }

    #[test]
    fn the_handshake_furthest_along_is_the_last_to_give_way() {
        let listener = TcpListener::bind("127.0.0.1:0").unwrap();
        let handshakes = Handshakes::default();
        let honest = handshakes.begin(&connection(&listener));
        honest.progress.heard.store(300, Ordering::Relaxed);
        // One just accepted, its thread yet to read: it outlasts those that sent a byte.
        let unheard = handshakes.begin(&connection(&listener));
        let mut flood = Vec::new();
        for _ in 0..MAX_PENDING * 4 {
            let ticket = handshakes.begin(&connection(&listener));
            ticket.progress.heard.store(1, Ordering::Relaxed);
            flood.push(ticket);
            assert!(handshakes.pending() <= MAX_PENDING_PER_ADDRESS);
        }
        // Every one from the same address: the stalled ones made way for each other.
        assert!(!honest.progress.evicted.load(Ordering::Relaxed));
        assert!(!unheard.progress.evicted.load(Ordering::Relaxed));
        let evicted = flood
            .iter()
            .filter(|t| t.progress.evicted.load(Ordering::Relaxed))
            .count();
        assert_eq!(evicted, MAX_PENDING * 4 - (MAX_PENDING_PER_ADDRESS - 2));
        // Under pressure the time is short.
        let last = flood.last().unwrap();
        assert!(last.deadline <= Instant::now() + HANDSHAKE_UNDER_PRESSURE);
        // Room when the descriptors run out is made from the stalled ones alone.
        while handshakes.make_room() {}
        assert!(!unheard.progress.evicted.load(Ordering::Relaxed));
        assert!(!honest.progress.evicted.load(Ordering::Relaxed));
        drop(flood);
        drop(unheard);
        assert_eq!(handshakes.pending(), 1);
        drop(honest);
        assert_eq!(handshakes.pending(), 0);
        let calm = handshakes.begin(&connection(&listener));
        assert!(calm.deadline > Instant::now() + HANDSHAKE_UNDER_PRESSURE);
    }
}
