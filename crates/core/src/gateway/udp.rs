//! Modbus/UDP clients of a gateway: each source address a client, each datagram one
//! MBAP request, its answer a datagram back.

use std::collections::{HashMap, VecDeque};
use std::io;
use std::net::{SocketAddr, UdpSocket};
use std::sync::atomic::Ordering;
use std::sync::Arc;
use std::time::Instant;

use crate::codec::{Envelope, Mode};
use crate::listener::clients::lock;
use crate::transport::udp::next_datagram;

use super::{Answers, Gateway, Job};

/// How many source addresses are kept as clients: past it, the one first heard is
/// forgotten (its waiting requests with it), so that datagrams from ever new
/// addresses cannot fill the memory.
const MOST_CLIENTS: usize = 1024;

impl Gateway {
    /// Takes the datagrams that come to `socket`, for ever: each that is a Modbus/UDP
    /// request waits its turn in the queue, fair to every source address; one that is not
    /// is passed over and counted.
    pub fn accept_udp(self: &Arc<Self>, socket: UdpSocket) -> io::Result<()> {
        let socket = Arc::new(socket);
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
