//! The TLS handshakes under way, bounded: clients that connect and never finish theirs
//! (one byte of a ClientHello, then nothing) must not hold every thread and descriptor
//! while honest clients wait. Past a limit in all, or from one address, the handshake that
//! has made the least progress gives way, the oldest first: one that sent a few bytes and
//! stopped short of a ClientHello (or nothing for a while), then one under way, and a
//! newcomer whose thread has yet to read last; among those as far along, one from an
//! address whose handshakes have had to give way lately, as a flood's have. Once half the places in all or of its
//! address are taken, a handshake has less time.

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

/// How long an address's handshakes that gave way are held against it.
const MARKS_LAST: Duration = Duration::from_secs(10);
/// The most addresses whose marks are kept.
const MARKED_ADDRESSES: usize = 256;

/// The handshakes under way.
#[derive(Debug, Default)]
pub struct Handshakes {
    state: Mutex<State>,
    next: AtomicU64,
}

#[derive(Debug, Default)]
struct State {
    pending: Vec<Pending>,
    /// By address: how many of its handshakes gave way lately, and when the last did.
    marks: Vec<(Option<IpAddr>, u32, Instant)>,
}

impl State {
    fn marks_of(&self, address: Option<IpAddr>) -> u32 {
        self.marks
            .iter()
            .find(|m| m.0 == address && m.2.elapsed() < MARKS_LAST)
            .map_or(0, |m| m.1)
    }

    fn mark(&mut self, address: Option<IpAddr>) {
        match self.marks.iter_mut().find(|m| m.0 == address) {
            Some(mark) => {
                mark.1 = if mark.2.elapsed() < MARKS_LAST {
                    mark.1 + 1
                } else {
                    1
                };
                mark.2 = Instant::now();
            }
            None => {
                if self.marks.len() >= MARKED_ADDRESSES {
                    if let Some(oldest) = (0..self.marks.len()).min_by_key(|&i| self.marks[i].2) {
                        self.marks.swap_remove(oldest);
                    }
                }
                self.marks.push((address, 1, Instant::now()));
            }
        }
    }

    /// Which handshakes give way first (the least first): stalled ones (0); newcomers
    /// whose threads have yet to read, from an address whose handshakes gave way lately
    /// (1); those under way (2); newcomers from other addresses (3), not closed for another
    /// before they could say anything. Then the address most marked, then the oldest.
    fn rank(&self, p: &Pending) -> (u8, u32, Instant) {
        let marks = self.marks_of(p.address);
        let class = match () {
            () if p.stalled() => 0,
            () if p.under_way() => 2,
            () if marks > 0 => 1,
            () => 3,
        };
        (class, u32::MAX - marks, p.started)
    }

    /// Closes the handshake among those `chosen` that ranks first to give way.
    fn evict(&mut self, chosen: impl Fn(&Pending) -> bool) {
        let victim = (0..self.pending.len())
            .filter(|&i| chosen(&self.pending[i]))
            .min_by_key(|&i| self.rank(&self.pending[i]));
        if let Some(index) = victim {
            let victim = self.pending.swap_remove(index);
            victim.state.evicted.store(true, Ordering::Relaxed);
            let _ = victim.socket.shutdown(Shutdown::Both);
            self.mark(victim.address);
        }
    }
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

impl Pending {
    /// Whether it has stalled: a few bytes and then nothing, or nothing for
    /// [`UNHEARD_STALLED`].
    fn stalled(&self) -> bool {
        match self.state.heard.load(Ordering::Relaxed) {
            0 => self.started.elapsed() >= UNHEARD_STALLED,
            n => n < LEAST_HELLO,
        }
    }

    fn under_way(&self) -> bool {
        self.state.heard.load(Ordering::Relaxed) >= LEAST_HELLO
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
        lock(&self.handshakes.state)
            .pending
            .retain(|pending| pending.id != self.id);
    }
}

impl Handshakes {
    /// A place for the handshake on `socket`, made by closing the handshake that has come
    /// the least far when the places in all, or those of its address, are taken.
    pub fn begin(&self, socket: &Arc<TcpStream>) -> Ticket<'_> {
        let address = socket.peer_addr().ok().map(|a| a.ip());
        let mut state = lock(&self.state);
        let from_here = |state: &State| {
            state
                .pending
                .iter()
                .filter(|p| p.address == address)
                .count()
        };
        if from_here(&state) >= MAX_PENDING_PER_ADDRESS {
            state.evict(|p| p.address == address);
        }
        if state.pending.len() >= MAX_PENDING {
            state.evict(|_| true);
        }
        let (from_here, pending) = (from_here(&state), &mut state.pending);
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
    /// and then nothing, or nothing for 0.2 s): room for another client when
    /// the descriptors have run out. Whether one was closed.
    pub fn make_room(&self) -> bool {
        let mut state = lock(&self.state);
        let stalled = |p: &Pending| p.stalled();
        let any = state.pending.iter().any(stalled);
        if any {
            state.evict(stalled);
        }
        any
    }

    /// How many handshakes are under way.
    pub fn pending(&self) -> usize {
        lock(&self.state).pending.len()
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

    /// A connection accepted from `from`, a loopback address.
    fn connection_from(listener: &TcpListener, from: &str) -> Arc<TcpStream> {
        let client =
            socket2::Socket::new(socket2::Domain::IPV4, socket2::Type::STREAM, None).unwrap();
        let source: std::net::SocketAddr = format!("{from}:0").parse().unwrap();
        client.bind(&source.into()).unwrap();
        client
            .connect(&listener.local_addr().unwrap().into())
            .unwrap();
        let (accepted, _) = listener.accept().unwrap();
        Arc::new(accepted)
    }

    #[test]
    fn among_those_as_far_along_an_address_whose_handshakes_gave_way_goes_first() {
        let listener = TcpListener::bind("127.0.0.1:0").unwrap();
        let handshakes = Handshakes::default();
        // A flood of whole ClientHellos, each then stalled, from 40 other addresses, and
        // an honest client in the middle of it.
        let stalled = |n: usize| {
            let from = format!("127.0.0.{}", 2 + n % 40);
            let ticket = handshakes.begin(&connection_from(&listener, &from));
            ticket.progress.heard.store(300, Ordering::Relaxed);
            ticket
        };
        let mut flood: Vec<Ticket<'_>> = (0..100).map(stalled).collect();
        let honest = handshakes.begin(&connection_from(&listener, "127.0.0.1"));
        honest.progress.heard.store(300, Ordering::Relaxed);
        flood.extend((100..400).map(stalled));
        assert!(!honest.progress.evicted.load(Ordering::Relaxed));
        assert_eq!(handshakes.pending(), MAX_PENDING);
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
