//! `mbtool gateway`: Modbus TCP clients bridged to one line (a serial port, a transparent
//! serial server, or another Modbus TCP server). Requests wait their turn in a queue fair
//! to every client (`queue`), one transaction at a time goes out on the line as the
//! careful master sends it (`line`), and every transaction is reported as data.

mod line;
mod queue;
mod udp;

use std::collections::{BTreeMap, HashMap, VecDeque};
use std::io::{self, Write};
use std::net::{Shutdown, TcpListener};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use thiserror::Error;

use crate::codec::{Mode, Pdu, Request};
use crate::listener::clients::{accept_clients, lock, Accepted, ErrorSink, WRITE_DEADLINE};
use crate::listener::receive_frames;
use crate::listener::roles::Role;
use crate::listener::Security;
use crate::model::spread::Spread;
use crate::transport::tcp::Tcp;
use crate::transport::tls::TlsWriter;
use crate::transport::Transport;

pub use line::{Connect, Line};
use queue::{ClientId, FairQueue};

/// Unit ids mapped to the slave ids they reach on the line (`--unit-map 1=17,2=18`).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct UnitMap(BTreeMap<u8, u8>);

/// Why a unit map does not read.
#[derive(Debug, Error, PartialEq, Eq)]
#[error("{0}")]
pub struct UnitMapError(String);

impl UnitMap {
    /// Reads `UNIT=SLAVE[,UNIT=SLAVE...]`, each unit id once.
    pub fn parse(text: &str) -> Result<UnitMap, UnitMapError> {
        let mut map = BTreeMap::new();
        for pair in text.split(',').map(str::trim) {
            let (unit, slave) = pair.split_once('=').ok_or_else(|| {
                UnitMapError(format!("'{pair}' is not UNIT=SLAVE (as in 1=17,2=18)"))
            })?;
            let number = |text: &str, what: &str| {
                crate::input::number::parse_int(text.trim())
                    .ok()
                    .and_then(|n| u8::try_from(n).ok())
                    .ok_or_else(|| UnitMapError(format!("'{pair}': the {what} is 0-255")))
            };
            let (unit, slave) = (number(unit, "unit id")?, number(slave, "slave id")?);
            if !(1..=247).contains(&slave) {
                return Err(UnitMapError(format!(
                    "'{pair}': a slave on a line is 1-247 (0 would broadcast, 248-255 are reserved)"
                )));
            }
            if map.insert(unit, slave).is_some() {
                return Err(UnitMapError(format!("unit {unit} is mapped twice")));
            }
        }
        Ok(UnitMap(map))
    }

    /// The slave id that `unit` reaches.
    pub fn slave_for(&self, unit: u8) -> u8 {
        self.0.get(&unit).copied().unwrap_or(unit)
    }
}

/// How the gateway answers what the line does not.
#[derive(Clone, Debug, Default)]
pub struct GatewayOptions {
    /// Unit ids mapped to slave ids.
    pub unit_map: UnitMap,
    /// A broadcast's client gets an echo of its request, as some SCADAs wait for one.
    pub broadcast_reply: bool,
}

/// How a listener's clients connect: plain Modbus TCP, or inside TLS with their roles
/// checked.
#[derive(Clone, Debug)]
pub enum Listening {
    /// Modbus TCP; where the secure listeners check roles, every client of this one has
    /// the role given, having no certificate to claim one.
    Plain(Option<Arc<Role>>),
    /// Modbus/TCP Security.
    Secure(Arc<Security>),
}

/// What became of one transaction.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// The slave answered with data.
    Answer,
    /// The slave answered with an exception, or the request did not read (told without
    /// touching the line).
    Exception,
    /// The client's role may not make the request (why): it got exception 01, the line
    /// untouched.
    Refused(String),
    /// No answer after every try: the client got exception 0B.
    Timeout,
    /// Only bad answers (a CRC error, a cut frame, another slave) after every try: the
    /// client got exception 0B. What was wrong with the last.
    BadFrame(String),
    /// The line could not be used: the client got exception 0A. Why.
    LineDown(String),
    /// Sent to every slave; nothing comes back.
    Broadcast,
}

impl Outcome {
    /// Its name in the monitor's rows.
    pub fn name(&self) -> &'static str {
        match self {
            Outcome::Answer => "answer",
            Outcome::Exception => "exception",
            Outcome::Refused(_) => "refused",
            Outcome::Timeout => "timeout",
            Outcome::BadFrame(_) => "bad-frame",
            Outcome::LineDown(_) => "line-down",
            Outcome::Broadcast => "broadcast",
        }
    }
}

/// One transaction, as it completed.
#[derive(Clone, Debug)]
pub struct Transaction {
    /// The client that asked.
    pub client: Arc<str>,
    /// Its role, when it came over TLS with one.
    pub role: Option<Arc<str>>,
    /// The unit id it asked.
    pub unit: u8,
    /// The slave id asked on the line.
    pub slave: u8,
    /// The client's transaction id.
    pub transaction: u16,
    /// The request (its bytes as an opaque request when they do not read).
    pub request: Request,
    /// What the client was sent back: the slave's answer, or the gateway's exception.
    pub answer: Option<Pdu>,
    /// How long the request waited for its turn.
    pub queued: Duration,
    /// From its turn to its answer: the line's time, retries included.
    pub response_time: Duration,
    /// How many times it was sent on the line (0: it never was).
    pub tries: u32,
    /// What became of it.
    pub outcome: Outcome,
    /// Whether the client was still there to take the answer.
    pub delivered: bool,
}

/// What the gateway tells as it works, from its threads.
pub enum Event<'a> {
    /// A transaction completed.
    Transaction(&'a Transaction),
    /// The line could not be used: why; it is tried again with a growing pause.
    LineDown(&'a str),
    /// The line is open again after being down.
    LineUp,
    /// A client was closed: why (a client that simply left is not told).
    ClientClosed(&'a io::Error),
}

/// Told of every event, from any thread.
pub type Report = Arc<dyn Fn(Event) + Send + Sync>;

/// The count of a client's or a unit's transactions.
#[derive(Clone, Debug, Default)]
pub struct Tally {
    /// Requests taken.
    pub requests: u64,
    /// Answers with data.
    pub answers: u64,
    /// Exceptions, from the slave or for a request that did not read.
    pub exceptions: u64,
    /// Requests no answer came to.
    pub timeouts: u64,
    /// Requests that got only bad answers.
    pub bad_frames: u64,
    /// Requests answered 0A while the line was down.
    pub line_down: u64,
    times: Times,
}

/// Response times in bounded memory: exact count, sum, quickest and slowest, and a fair
/// sample of at most [`TIMES_KEPT`] for the 95th percentile, however long the gateway runs.
#[derive(Clone, Debug, Default)]
struct Times {
    count: u64,
    sum: u64,
    min: u64,
    max: u64,
    sample: Vec<u64>,
}

/// The most response times a tally keeps for its percentile.
const TIMES_KEPT: usize = 2_000;

/// How many clients that left keep a row of their own in the summary; those that left
/// before them are counted together, so that a gateway running for months holds and
/// prints a bounded summary however many clients came and went.
pub const RECENT_CLIENTS: usize = 32;

impl Times {
    /// `other`'s times added: exact counts and bounds, and a sample drawn from both in
    /// proportion to how many times each stands for.
    fn absorb(&mut self, other: &Times) {
        if other.count == 0 {
            return;
        }
        self.min = if self.count == 0 {
            other.min
        } else {
            self.min.min(other.min)
        };
        self.max = self.max.max(other.max);
        let (mine, theirs) = (self.count, other.count);
        self.count += other.count;
        self.sum = self.sum.saturating_add(other.sum);
        let kept = TIMES_KEPT.min(self.sample.len() + other.sample.len());
        let mut sample = Vec::with_capacity(kept);
        for _ in 0..kept {
            let take_mine = fastrand::u64(..mine + theirs) < mine;
            let from = if (take_mine && !self.sample.is_empty()) || other.sample.is_empty() {
                &self.sample
            } else {
                &other.sample
            };
            sample.push(from[fastrand::usize(..from.len())]);
        }
        self.sample = sample;
    }

    fn add(&mut self, us: u64) {
        self.min = if self.count == 0 {
            us
        } else {
            self.min.min(us)
        };
        self.max = self.max.max(us);
        self.count += 1;
        self.sum = self.sum.saturating_add(us);
        if self.sample.len() < TIMES_KEPT {
            self.sample.push(us);
        } else {
            // Reservoir sampling: every time so far is equally likely to be kept.
            let slot = fastrand::u64(..self.count) as usize;
            if let Some(kept) = self.sample.get_mut(slot) {
                *kept = us;
            }
        }
    }
}

impl Tally {
    /// `other`'s counts added to these.
    fn absorb(&mut self, other: &Tally) {
        self.requests += other.requests;
        self.answers += other.answers;
        self.exceptions += other.exceptions;
        self.timeouts += other.timeouts;
        self.bad_frames += other.bad_frames;
        self.line_down += other.line_down;
        self.times.absorb(&other.times);
    }

    fn add(&mut self, transaction: &Transaction) {
        self.requests += 1;
        match transaction.outcome {
            Outcome::Answer => self.answers += 1,
            Outcome::Exception | Outcome::Refused(_) => self.exceptions += 1,
            Outcome::Timeout => self.timeouts += 1,
            Outcome::BadFrame(_) => self.bad_frames += 1,
            Outcome::LineDown(_) => self.line_down += 1,
            Outcome::Broadcast => {}
        }
        if matches!(transaction.outcome, Outcome::Answer | Outcome::Exception)
            && transaction.tries > 0
        {
            self.times.add(transaction.response_time.as_micros() as u64);
        }
    }

    /// The response times of the answers, when any came from the line.
    pub fn times(&self) -> Option<Spread> {
        let mut sample = self.times.sample.clone();
        let p95 = Spread::of(&mut sample)?.p95;
        Some(Spread {
            min: self.times.min,
            mean: self.times.sum.div_ceil(self.times.count.max(1)),
            p95,
            max: self.times.max,
        })
    }
}

/// What the gateway did, per client and per unit.
#[derive(Clone, Debug, Default)]
pub struct Summary {
    /// By client address: the connected clients, and the [`RECENT_CLIENTS`] that left
    /// last.
    pub clients: BTreeMap<String, Tally>,
    /// The clients that left before those: how many, and their transactions together.
    pub earlier: Option<(u64, Tally)>,
    /// By unit id.
    pub units: BTreeMap<u8, Tally>,
    /// Clients closed for sending what is not Modbus TCP.
    pub bad_clients: u64,
    /// Datagrams passed over for being no Modbus/UDP request.
    pub bad_datagrams: u64,
    /// TLS clients refused: a failed or unfinished handshake, a role not allowed.
    pub refused: u64,
}

/// The summary, and the order in which clients with a row left.
#[derive(Default)]
struct Records {
    summary: Summary,
    departed: VecDeque<String>,
}

impl Records {
    /// A transaction counted against its client (whether it is still connected) and its
    /// unit.
    fn add(&mut self, transaction: &Transaction, connected: bool) {
        let client = transaction.client.as_ref();
        let summary = &mut self.summary;
        match summary.clients.get_mut(client) {
            Some(tally) => tally.add(transaction),
            None if connected => summary
                .clients
                .entry(client.to_string())
                .or_default()
                .add(transaction),
            // Finished after its client left and its row was folded: counted there.
            None => summary
                .earlier
                .get_or_insert_with(|| (1, Tally::default()))
                .1
                .add(transaction),
        }
        summary
            .units
            .entry(transaction.unit)
            .or_default()
            .add(transaction);
    }

    /// A client left: its row stays among the recent ones, and the oldest of those is
    /// folded into the earlier clients' row.
    fn departed(&mut self, client: &str) {
        if !self.summary.clients.contains_key(client) || self.departed.iter().any(|c| c == client) {
            return;
        }
        self.departed.push_back(client.to_string());
        while self.departed.len() > RECENT_CLIENTS {
            let Some(oldest) = self.departed.pop_front() else {
                break;
            };
            if let Some(tally) = self.summary.clients.remove(&oldest) {
                let earlier = self
                    .summary
                    .earlier
                    .get_or_insert_with(|| (0, Tally::default()));
                earlier.0 += 1;
                earlier.1.absorb(&tally);
            }
        }
    }
}

/// A request waiting for the line.
struct Job {
    client: Arc<str>,
    role: Option<Arc<str>>,
    /// What the client may do, where its TLS role is checked.
    rights: Option<Arc<Role>>,
    /// The whole MBAP frame.
    frame: Vec<u8>,
    arrived: Instant,
}

/// Where a client's answers are written, by a thread of its own.
enum Writing {
    Plain(Arc<std::net::TcpStream>),
    Secure(TlsWriter),
}

impl Writing {
    fn write_all(&mut self, answer: &[u8]) -> io::Result<()> {
        match self {
            Writing::Plain(stream) => (&**stream).write_all(answer),
            Writing::Secure(writer) => writer.write_all(answer),
        }
    }

    /// Closes the connection, which ends the reading side's wait too.
    fn shutdown(&self) {
        let _ = match self {
            Writing::Plain(stream) => stream.shutdown(Shutdown::Both),
            Writing::Secure(writer) => writer.shutdown(),
        };
    }
}

/// Where a client's answers go.
enum Answers {
    /// A TCP client's writing thread.
    Stream(mpsc::Sender<Vec<u8>>),
    /// A UDP client: a datagram to where its requests came from, remembered for a
    /// repeat of the request.
    Datagram {
        socket: Arc<std::net::UdpSocket>,
        to: std::net::SocketAddr,
        recent: Arc<Mutex<udp::Recent>>,
    },
}

impl Answers {
    /// Hands `answer` on; whether it went.
    fn send(&self, answer: Vec<u8>) -> bool {
        match self {
            Answers::Stream(writer) => writer.send(answer).is_ok(),
            Answers::Datagram { socket, to, recent } => {
                lock(recent).answered(*to, &answer);
                socket.send_to(&answer, to).is_ok()
            }
        }
    }
}

/// Clients bridged to one line.
pub struct Gateway {
    options: GatewayOptions,
    queue: FairQueue<Job>,
    /// Where each connected client's answers go.
    writers: Mutex<HashMap<ClientId, Answers>>,
    summary: Mutex<Records>,
    report: Report,
    /// The id of the next client, whichever listener it comes to.
    next_client: AtomicUsize,
}

impl Gateway {
    /// A gateway answering as `options` say, telling `report` what it does.
    pub fn new(options: GatewayOptions, report: Report) -> Arc<Gateway> {
        Arc::new(Gateway {
            options,
            queue: FairQueue::new(),
            writers: Mutex::new(HashMap::new()),
            summary: Mutex::new(Records::default()),
            report,
            next_client: AtomicUsize::new(0),
        })
    }

    /// What was done so far.
    pub fn summary(&self) -> Summary {
        lock(&self.summary).summary.clone()
    }

    /// Takes the clients of `listener`, each on its own threads, for ever; several
    /// listeners may feed one gateway.
    pub fn accept(
        self: &Arc<Self>,
        listener: TcpListener,
        listening: Listening,
        on_error: ErrorSink,
    ) -> io::Result<()> {
        let gateway = Arc::clone(self);
        let handshakes = match &listening {
            Listening::Secure(security) => Some(security.handshakes()),
            Listening::Plain(_) => None,
        };
        accept_clients(
            listener,
            handshakes,
            on_error,
            Arc::new(move |client: Accepted| gateway.serve_client(client, &listening)),
        )
    }

    /// Reads a client's requests into the queue until it leaves; its answers are written
    /// by a thread of its own, so that a client slow to read holds up no one.
    fn serve_client(&self, client: Accepted, listening: &Listening) -> io::Result<()> {
        let id = self.next_client.fetch_add(1, Ordering::Relaxed);
        let (mut transport, mut writing, role, rights): (Box<dyn Transport>, Writing, _, _) =
            match listening {
                Listening::Plain(role) => (
                    Box::new(Tcp::from_shared(Arc::clone(&client.stream), false)?),
                    Writing::Plain(client.stream),
                    role.as_ref().map(|role| role.name.clone()),
                    role.clone(),
                ),
                Listening::Secure(security) => {
                    let admitted = security
                        .admit(client.stream, &client.peer)
                        .inspect_err(|_| lock(&self.summary).summary.refused += 1)?;
                    let writing = Writing::Secure(admitted.stream.writer());
                    let rights = admitted.rights.map(Arc::new);
                    (Box::new(admitted.stream), writing, admitted.role, rights)
                }
            };
        let (answers, to_write) = mpsc::channel::<Vec<u8>>();
        let (report, peer) = (Arc::clone(&self.report), client.peer.clone());
        std::thread::Builder::new().spawn(move || {
            for answer in to_write {
                if let Err(error) = writing.write_all(&answer) {
                    // Not read for the write deadline, or gone: the reading side ends too.
                    writing.shutdown();
                    if matches!(
                        error.kind(),
                        io::ErrorKind::WouldBlock | io::ErrorKind::TimedOut
                    ) {
                        let stalled = io::Error::other(format!(
                            "{peer} did not read its answers for {} s: connection closed",
                            WRITE_DEADLINE.as_secs()
                        ));
                        report(Event::ClientClosed(&stalled));
                    }
                    break;
                }
            }
        })?;
        lock(&self.writers).insert(id, Answers::Stream(answers));
        let peer: Arc<str> = Arc::from(client.peer.as_str());
        let role: Option<Arc<str>> = role.map(Arc::from);
        let received = receive_frames(
            transport.as_mut(),
            Mode::Tcp,
            &client.link,
            &client.peer,
            |found| {
                self.queue.push(
                    id,
                    Job {
                        client: Arc::clone(&peer),
                        role: role.clone(),
                        rights: rights.clone(),
                        frame: found.bytes.to_vec(),
                        arrived: Instant::now(),
                    },
                );
                None
            },
        );
        // A client that closed its sending side (as `nc -N` does) still gets the answers
        // to what it asked. One that went away has its waiting requests dropped; one on
        // the line is finished and its answer thrown away, so that the line stays in step.
        if matches!(&received, Err(e) if e.kind() == io::ErrorKind::ConnectionAborted) {
            self.queue.wait_until_served(id);
        }
        lock(&self.writers).remove(&id);
        self.queue.forget(id);
        let mut records = lock(&self.summary);
        records.departed(&peer);
        if let Err(error) = &received {
            if error.kind() == io::ErrorKind::InvalidData {
                records.summary.bad_clients += 1;
            }
        }
        drop(records);
        received
    }

    /// Carries out the queued requests on `line`, one at a time, for ever.
    pub fn run(&self, line: &mut Line) {
        loop {
            let (client, job) = self.queue.pop();
            let transaction = line.carry(&job, &self.options, &self.report);
            // The records are held from the look at the client's writer to the count, so
            // that a client leaving meanwhile finds its row there to set aside.
            let mut records = lock(&self.summary);
            let (delivered, connected) = {
                let writers = lock(&self.writers);
                let writer = writers.get(&client);
                let delivered = match (&transaction.answer, writer) {
                    (Some(answer), Some(writer)) => {
                        let bytes = line::mbap(transaction.unit, transaction.transaction, answer);
                        writer.send(bytes)
                    }
                    (None, writer) => writer.is_some(),
                    (Some(_), None) => false,
                };
                (delivered, writer.is_some())
            };
            let transaction = Transaction {
                delivered,
                ..transaction
            };
            records.add(&transaction, connected);
            drop(records);
            self.queue.finished();
            (self.report)(Event::Transaction(&transaction));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_unit_map_reads_pairs_and_refuses_the_rest() {
        let map = UnitMap::parse("1=17, 2=0x12").unwrap();
        assert_eq!(
            (map.slave_for(1), map.slave_for(2), map.slave_for(3)),
            (17, 18, 3)
        );
        for bad in ["1", "1=300", "x=1", "1=2,1=3", "", "5=0", "1=248"] {
            assert!(UnitMap::parse(bad).is_err(), "{bad}");
        }
    }

    fn transaction(client: &str) -> Transaction {
        Transaction {
            client: Arc::from(client),
            role: None,
            unit: 1,
            slave: 1,
            transaction: 0,
            request: Request::ReadHoldingRegisters {
                address: 0,
                quantity: 1,
            },
            answer: None,
            queued: Duration::ZERO,
            response_time: Duration::from_micros(500),
            tries: 1,
            outcome: Outcome::Answer,
            delivered: true,
        }
    }

    #[test]
    fn clients_that_left_long_ago_are_one_row_and_nothing_is_lost() {
        let mut records = Records::default();
        for n in 0..10_000 {
            let client = format!("127.0.0.1:{}", 1024 + n);
            records.add(&transaction(&client), true);
            records.add(&transaction(&client), true);
            records.departed(&client);
        }
        // One that finishes after its client's row was folded counts there too.
        records.add(&transaction("127.0.0.1:1024"), false);
        let summary = &records.summary;
        assert_eq!(summary.clients.len(), RECENT_CLIENTS);
        let (count, earlier) = summary.earlier.as_ref().unwrap();
        assert_eq!(*count, 10_000 - RECENT_CLIENTS as u64);
        let total: u64 =
            summary.clients.values().map(|t| t.requests).sum::<u64>() + earlier.requests;
        assert_eq!(total, 20_001);
        assert_eq!(summary.units[&1].requests, 20_001);
        assert_eq!(earlier.times.count, earlier.answers);
        assert!(earlier.times.sample.len() <= TIMES_KEPT);
        assert_eq!(earlier.times().unwrap().p95, 500);
    }

    #[test]
    fn times_keep_exact_bounds_and_a_bounded_sample() {
        let mut times = Times::default();
        for us in (1..=50_000).rev() {
            times.add(us);
        }
        assert_eq!((times.min, times.max, times.count), (1, 50_000, 50_000));
        assert_eq!(times.sample.len(), TIMES_KEPT);
    }
}
