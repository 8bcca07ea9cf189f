//! Modbus/UDP clients of a gateway: each source address a client, each datagram one
//! MBAP request, its answer a datagram back. A request the network repeats (a client
//! asking again after a lost answer, a datagram duplicated on the way) is carried out
//! once: while it waits or is on the line the repeat is dropped, and once answered the
//! repeat gets the same answer again.

use std::collections::{HashMap, VecDeque};
use std::io;
use std::net::{SocketAddr, UdpSocket};
use std::sync::atomic::Ordering;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use crate::codec::{Envelope, Mode};
use crate::listener::clients::lock;
use crate::transport::udp::next_datagram;

use super::{Answers, Gateway, Job};

/// How many source addresses are kept as clients: past it, the one first heard is
/// forgotten (its waiting requests with it), so that datagrams from ever new
/// addresses cannot fill the memory.
const MOST_CLIENTS: usize = 1024;

/// How long a request is remembered to tell a repeat of it: longer than any client's
/// retries of one request take.
const REPEATS_WITHIN: Duration = Duration::from_secs(30);

/// At most this many requests are remembered, the oldest forgotten first.
const MOST_REMEMBERED: usize = 4096;

/// The requests of UDP clients lately taken, by source and transaction id, each with its
/// bytes and, once sent, its answer.
#[derive(Default)]
pub(super) struct Recent {
    requests: HashMap<(SocketAddr, u16), Taken>,
    order: VecDeque<(SocketAddr, u16)>,
}

/// A request taken from a UDP client: its bytes, when, and its answer once sent.
struct Taken {
    request: Vec<u8>,
    answer: Option<Vec<u8>>,
    at: Instant,
}

impl Recent {
    /// What to do with `frame` from `from`: `None` to take it as a new request; `Some`
    /// with the answer to send again, or nothing to send while it is under way.
    fn repeat(&mut self, from: SocketAddr, frame: &[u8]) -> Option<Option<Vec<u8>>> {
        let key = (from, u16::from_be_bytes([frame[0], frame[1]]));
        match self.requests.get(&key) {
            Some(taken) if taken.request == frame && taken.at.elapsed() < REPEATS_WITHIN => {
                Some(taken.answer.clone())
            }
            _ => {
                if self.order.len() == MOST_REMEMBERED {
                    if let Some(oldest) = self.order.pop_front() {
                        self.requests.remove(&oldest);
                    }
                }
                self.order.retain(|k| *k != key);
                self.order.push_back(key);
                let taken = Taken {
                    request: frame.to_vec(),
                    answer: None,
                    at: Instant::now(),
                };
                self.requests.insert(key, taken);
                None
            }
        }
    }

    /// The answer sent to `to` for its request of the answer's transaction id.
    pub(super) fn answered(&mut self, to: SocketAddr, answer: &[u8]) {
        if let [high, low, ..] = answer {
            let key = (to, u16::from_be_bytes([*high, *low]));
            if let Some(taken) = self.requests.get_mut(&key) {
                taken.answer = Some(answer.to_vec());
            }
        }
    }
}

impl Gateway {
    /// Takes the datagrams that come to `socket`, for ever: each that is a Modbus/UDP
    /// request waits its turn in the queue, fair to every source address; one that is not
    /// is passed over and counted.
    pub fn accept_udp(self: &Arc<Self>, socket: UdpSocket) -> io::Result<()> {
        let socket = Arc::new(socket);
        let recent = Arc::new(Mutex::new(Recent::default()));
        let mut clients: HashMap<SocketAddr, (usize, Arc<str>)> = HashMap::new();
        let mut heard: VecDeque<SocketAddr> = VecDeque::new();
        let mut datagram = [0u8; 2048];
        loop {
            let (len, from) = next_datagram(&socket, &mut datagram)?;
            let frame = &datagram[..len];
            if Envelope::open(Mode::Tcp, frame).is_err() {
                lock(&self.summary).summary.bad_datagrams += 1;
                continue;
            }
            match lock(&recent).repeat(from, frame) {
                Some(Some(answer)) => {
                    let _ = socket.send_to(&answer, from);
                    continue;
                }
                Some(None) => continue,
                None => {}
            }
            let (id, peer) = match clients.get(&from) {
                Some(client) => client.clone(),
                None => {
                    if heard.len() == MOST_CLIENTS {
                        if let Some((id, _)) =
                            heard.pop_front().and_then(|old| clients.remove(&old))
                        {
                            lock(&self.writers).remove(&id);
                            self.queue.forget(id);
                        }
                    }
                    let id = self.next_client.fetch_add(1, Ordering::Relaxed);
                    let peer: Arc<str> = Arc::from(format!("udp:{from}").as_str());
                    lock(&self.writers).insert(
                        id,
                        Answers::Datagram {
                            socket: Arc::clone(&socket),
                            to: from,
                            recent: Arc::clone(&recent),
                        },
                    );
                    clients.insert(from, (id, Arc::clone(&peer)));
                    heard.push_back(from);
                    (id, peer)
                }
            };
            self.queue.push(
                id,
                Job {
                    client: peer,
                    role: None,
                    rights: None,
                    frame: frame.to_vec(),
                    arrived: Instant::now(),
                },
            );
        }
    }
}
