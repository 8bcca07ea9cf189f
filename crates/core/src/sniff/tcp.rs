//! Modbus in a TCP capture: each connection's two directions put back in order
//! (`reassembly`), framed by the codec's framer (MBAP, or RTU through a transparent gateway),
//! each answer paired with its request by transaction and unit id, and the tally kept.
//! Modbus/UDP is read the same way, each pair of addresses a connection whose every
//! datagram ends what it carries. Pure: packets in, records out.

use std::collections::BTreeMap;
use std::net::SocketAddr;

use serde::Serialize;

use super::capture::{datagram, segment, Datagram, Packet};
use super::pairing::RequestSent;
use super::reassembly::{At, Piece, Stream};
use super::session::{Counts, Filter, FrameRecord, Record, TcpPlace};
use crate::codec::answer::Mismatch;
use crate::codec::framing::{Broken, Event, Found, Framer};
use crate::codec::{Direction, Envelope, Mode, Pdu, Ways};
use crate::describe::{describe_frame, FrameReport, Kind};

/// At most this many requests of one connection wait on one transaction and unit id: a
/// client may pipeline requests that reuse an id, but one whose requests are never
/// answered holds no more than this.
const MOST_WAITING_ON_ONE_ID: usize = 16;

/// Whether a TCP payload reads as MBAP: protocol id 0, a length that the payload holds
/// (one ADU, or one followed by another header), a function code that exists.
fn looks_like_mbap(payload: &[u8]) -> bool {
    let [_, _, 0, 0, hi, lo, _, function, ..] = payload else {
        return false;
    };
    let end = 6 + usize::from(u16::from_be_bytes([*hi, *lo]));
    let adu = (8..=260).contains(&end) && !matches!(function, 0 | 0x80);
    adu && (payload.len() == end || payload.get(end + 2..end + 4) == Some(&[0, 0]))
}

/// The port Modbus TCP servers listen on, unless told otherwise.
pub const MODBUS_PORT: u16 = 502;

/// What a capture held beside its Modbus frames.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize)]
pub struct PacketCounts {
    /// Every packet read.
    pub packets: u64,
    /// Packets of TCP connections, and UDP datagrams, on a Modbus port.
    pub modbus: u64,
    /// Everything else, passed over: other ports, other protocols.
    pub other: u64,
    /// Bytes seen twice (retransmitted, duplicated), read once.
    pub repeated_bytes: u64,
    /// Bytes that never came (lost segments, packets the snap length cut).
    pub missing_bytes: u64,
    /// Jumps of sequence numbers, and acknowledgements of bytes never sent, passed over:
    /// corrupt numbers, or more lost than a sender has in flight.
    pub sequence_jumps: u64,
}

/// One direction of a connection: its bytes in order, and the frames in them.
struct Side {
    stream: Stream,
    framer: Framer,
    /// What the framer found in a piece, before it is told when: kept, so that its memory
    /// is taken once.
    events: Vec<Event>,
}

/// What the framer found, with when and in which packet it was completed: the packet of
/// the bytes that completed it (or `now` for what a gap or the end decided).
type Completed = (Event, At);

impl Side {
    /// Bytes, or their absence, given to the framer.
    fn frame(&mut self, pieces: &mut Vec<Piece>, now: At, found: &mut Vec<Completed>) {
        let mut events = std::mem::take(&mut self.events);
        for piece in pieces.drain(..) {
            let at = match piece {
                Piece::Bytes { data, at } => {
                    self.framer.push_at(&data, at.0, &mut events);
                    at
                }
                Piece::Gap(missing) => {
                    self.framer.gap(missing, &mut events);
                    now
                }
            };
            found.extend(events.drain(..).map(|event| (event, at)));
        }
        self.events = events;
    }

    fn new(mode: Mode) -> Self {
        // No timing: frames are found by their length (MBAP) or their layout and CRC
        // (RTU), never by silence.
        let framer = Framer::new(mode, 0.0, u64::MAX).resynchronising();
        Self {
            stream: Stream::default(),
            framer,
            events: Vec::new(),
        }
    }
}

/// A request waiting for its answer.
struct Pending {
    slave: u8,
    transaction: u16,
    request: RequestSent,
    /// When its last byte came.
    time: u64,
    packet: u64,
}

/// A connection, from the client's side to the server's.
struct Connection {
    to_server: Side,
    to_client: Side,
    /// By transaction id and unit id; in RTU, in the order sent.
    pending: Vec<Pending>,
    /// FINs seen: at two, both sides are done.
    fins: u8,
}

/// A connection: its client, its server, and whether it is Modbus/UDP (a TCP connection
/// and a UDP flow between the same ports are two).
type Key = (SocketAddr, SocketAddr, bool);

/// The connection of `key` among `connections`, new or going on.
fn connection(
    connections: &mut BTreeMap<Key, Connection>,
    mode: Mode,
    key: Key,
) -> &mut Connection {
    connections.entry(key).or_insert_with(|| Connection {
        to_server: Side::new(mode),
        to_client: Side::new(mode),
        pending: Vec::new(),
        fins: 0,
    })
}

/// A frame as the session has it before it is shown: read, and described only if shown;
/// or described already (broken, or its PDU does not read).
enum Seen {
    Read {
        slave: u8,
        /// As on the wire, with the 0x80 flag of an exception.
        function: u8,
        /// A request, or an answer that reads as one (the way it travelled).
        kind: Kind,
        /// The request a read's answer answers.
        answers: Option<RequestSent>,
    },
    /// Boxed: rare, and large beside a frame read.
    Described(Box<FrameReport>),
}

/// A Modbus TCP capture's session: packets in, records out.
pub struct TcpSession {
    mode: Mode,
    ports: Vec<u16>,
    filter: Filter,
    connections: BTreeMap<Key, Connection>,
    counts: Counts,
    packets: PacketCounts,
    numbered: u64,
    /// The first packet's time: frames are timed from it, as Wireshark does.
    first_time: Option<u64>,
    last_time: u64,
    pieces: Vec<Piece>,
    found: Vec<Completed>,
    /// Packets on other ports whose payload reads as MBAP, by their server's port.
    elsewhere: BTreeMap<u16, u64>,
    /// The servers of connections on other ports, as their SYNs tell (bounded).
    servers_elsewhere: std::collections::HashSet<SocketAddr>,
    /// The connections closed lately, oldest first (bounded): the last ACK of a closed
    /// connection, or a FIN sent again, opens no new one that would never close.
    closed: ClosedLately,
}

/// How many closed connections are remembered.
const CLOSED_KEPT: usize = 4096;

/// The keys of the latest connections closed, at most [`CLOSED_KEPT`].
#[derive(Default)]
struct ClosedLately {
    order: std::collections::VecDeque<Key>,
    keys: std::collections::HashSet<Key>,
}

impl ClosedLately {
    fn add(&mut self, key: Key) {
        if self.keys.insert(key) {
            self.order.push_back(key);
        }
        if self.order.len() > CLOSED_KEPT {
            if let Some(oldest) = self.order.pop_front() {
                self.keys.remove(&oldest);
            }
        }
    }

    /// A connection of `key` opens again (a new SYN, or bytes on it).
    fn reopened(&mut self, key: &Key) {
        if self.keys.remove(key) {
            self.order.retain(|closed| closed != key);
        }
    }

    fn contains(&self, key: &Key) -> bool {
        self.keys.contains(key)
    }
}

impl TcpSession {
    /// `mode`: MBAP (`Mode::Tcp`) or RTU frames (`Mode::Rtu`) in the streams; `ports`: the
    /// servers' ports.
    pub fn new(mode: Mode, ports: Vec<u16>, filter: Filter) -> Self {
        Self {
            mode,
            ports,
            filter,
            connections: BTreeMap::new(),
            counts: Counts::default(),
            packets: PacketCounts::default(),
            numbered: 0,
            first_time: None,
            last_time: 0,
            pieces: Vec::new(),
            found: Vec::new(),
            elsewhere: BTreeMap::new(),
            servers_elsewhere: std::collections::HashSet::new(),
            closed: ClosedLately::default(),
        }
    }

    /// The server ports not asked for whose packets carry MBAP headers, and how many, the
    /// most first: Modbus TCP served on ports of its own.
    pub fn modbus_elsewhere(&self) -> Vec<(u16, u64)> {
        let mut ports: Vec<(u16, u64)> = self.elsewhere.iter().map(|(p, n)| (*p, *n)).collect();
        ports.sort_by_key(|(port, count)| (std::cmp::Reverse(*count), *port));
        ports
    }

    /// The tally of frames so far.
    pub fn counts(&self) -> &Counts {
        &self.counts
    }

    /// The tally of packets so far.
    pub fn packet_counts(&self) -> PacketCounts {
        let mut counts = self.packets.clone();
        for connection in self.connections.values() {
            for side in [&connection.to_server, &connection.to_client] {
                counts.repeated_bytes += side.stream.repeated;
                counts.missing_bytes += side.stream.missing;
                counts.sequence_jumps += side.stream.jumps;
            }
        }
        counts
    }

    /// One packet of the capture.
    pub fn packet(&mut self, packet: &Packet, out: &mut Vec<Record>) {
        self.packets.packets += 1;
        let first = *self.first_time.get_or_insert(packet.time_us);
        self.last_time = packet.time_us.max(first);
        let Ok(segment) = segment(packet) else {
            match datagram(packet) {
                Some(datagram) => self.datagram(datagram, packet, out),
                None => self.packets.other += 1,
            }
            return;
        };
        let (client, server, from_client) = if self.ports.contains(&segment.destination.port()) {
            (segment.source, segment.destination, true)
        } else if self.ports.contains(&segment.source.port()) {
            (segment.destination, segment.source, false)
        } else {
            self.packets.other += 1;
            // A connection's server is the end its SYN went to; where the capture has no
            // SYN, the lower port (clients' are ephemeral).
            if segment.syn
                && segment.acknowledgement.is_none()
                && self.servers_elsewhere.len() < 4096
            {
                self.servers_elsewhere.insert(segment.destination);
            }
            if looks_like_mbap(segment.payload) {
                let server = if self.servers_elsewhere.contains(&segment.source) {
                    segment.source.port()
                } else if self.servers_elsewhere.contains(&segment.destination) {
                    segment.destination.port()
                } else {
                    segment.source.port().min(segment.destination.port())
                };
                *self.elsewhere.entry(server).or_default() += 1;
            }
            return;
        };
        self.packets.modbus += 1;
        let key = (client, server, false);
        if segment.syn && from_client {
            // A new connection on the same addresses: the old one is over.
            self.close(key, false, out);
        }
        if self.closed.contains(&key) {
            // What comes after a connection closed: its last ACK, a FIN again, carry
            // nothing; bytes or a SYN open it again.
            if segment.payload.is_empty() && !segment.syn {
                return;
            }
            self.closed.reopened(&key);
        }
        let connection = connection(&mut self.connections, self.mode, key);
        let (side, other) = match from_client {
            true => (&mut connection.to_server, &mut connection.to_client),
            false => (&mut connection.to_client, &mut connection.to_server),
        };
        let now = (packet.time_us, packet.number);
        let mut pieces = std::mem::take(&mut self.pieces);
        // What this side acknowledges and the capture never had is a gap on the other:
        // decided first, so that a request released by it comes before this answer.
        let mut acknowledged = Vec::new();
        if let Some(acknowledgement) = segment.acknowledgement {
            other.stream.acknowledged(acknowledgement, now, &mut pieces);
            other.frame(&mut pieces, now, &mut acknowledged);
        }
        let mut found = std::mem::take(&mut self.found);
        side.stream.segment(
            segment.sequence,
            segment.syn,
            (segment.payload, segment.cut),
            now,
            &mut pieces,
        );
        side.frame(&mut pieces, now, &mut found);
        if segment.fin {
            let length = u32::try_from(segment.payload.len())
                .unwrap_or(0)
                .wrapping_add(segment.cut);
            side.stream.fin(
                segment
                    .sequence
                    .wrapping_add(u32::from(segment.syn))
                    .wrapping_add(length),
            );
        }
        self.pieces = pieces;
        let place = TcpPlace {
            client,
            server,
            udp: false,
            from_client,
            packet: packet.number,
            time_us: packet.time_us,
            request_packet: None,
            response_time: None,
        };
        let other_place = TcpPlace {
            from_client: !from_client,
            ..place
        };
        self.read_events(&mut acknowledged, other_place, out);
        self.read_events(&mut found, place, out);
        self.found = found;
        if segment.rst {
            self.close(key, false, out);
        } else if segment.fin {
            let done = self.connections.get_mut(&key).is_some_and(|c| {
                c.fins += 1;
                c.fins >= 2
            });
            if done {
                self.close(key, false, out);
            }
        }
    }

    /// A UDP datagram: on a Modbus port, the next bytes of the connection of its two
    /// addresses, its end ending the MBAP frame it carries; elsewhere, passed over (and
    /// counted where it reads as MBAP).
    fn datagram(&mut self, datagram: Datagram, packet: &Packet, out: &mut Vec<Record>) {
        let (client, server, from_client) = if self.ports.contains(&datagram.destination.port()) {
            (datagram.source, datagram.destination, true)
        } else if self.ports.contains(&datagram.source.port()) {
            (datagram.destination, datagram.source, false)
        } else {
            self.packets.other += 1;
            if looks_like_mbap(datagram.payload) {
                let server = datagram.source.port().min(datagram.destination.port());
                *self.elsewhere.entry(server).or_default() += 1;
            }
            return;
        };
        self.packets.modbus += 1;
        let now = (packet.time_us, packet.number);
        let connection = connection(&mut self.connections, self.mode, (client, server, true));
        let side = match from_client {
            true => &mut connection.to_server,
            false => &mut connection.to_client,
        };
        let mut pieces = vec![Piece::Bytes {
            data: datagram.payload.to_vec(),
            at: now,
        }];
        // Modbus/UDP is a frame a datagram; RTU in datagrams is a stream a serial server
        // packed, which may cut a frame in two.
        if self.mode == Mode::Tcp {
            pieces.push(Piece::Gap(0));
        }
        let mut found = std::mem::take(&mut self.found);
        side.frame(&mut pieces, now, &mut found);
        let place = TcpPlace {
            client,
            server,
            udp: true,
            from_client,
            packet: packet.number,
            time_us: packet.time_us,
            request_packet: None,
            response_time: None,
        };
        self.read_events(&mut found, place, out);
        self.found = found;
    }

    /// The end of the capture: what every connection still holds is decided, and the
    /// requests still waiting are unanswered.
    pub fn finish(&mut self, out: &mut Vec<Record>) {
        let keys: Vec<_> = self.connections.keys().copied().collect();
        for key in keys {
            self.close(key, true, out);
        }
    }

    /// A connection is over (closed, or `capture_ended`): its streams are read to their
    /// end, and what still waits for an answer is unanswered.
    fn close(&mut self, key: Key, capture_ended: bool, out: &mut Vec<Record>) {
        for from_client in [true, false] {
            let Some(connection) = self.connections.get_mut(&key) else {
                return;
            };
            let side = match from_client {
                true => &mut connection.to_server,
                false => &mut connection.to_client,
            };
            let (mut pieces, mut found, mut ended) = (Vec::new(), Vec::new(), Vec::new());
            let now = (self.last_time, self.packets.packets);
            side.stream.finish(&mut pieces);
            side.frame(&mut pieces, now, &mut found);
            side.framer.finish(&mut ended);
            found.extend(ended.into_iter().map(|event| (event, now)));
            let place = TcpPlace {
                client: key.0,
                server: key.1,
                udp: key.2,
                from_client,
                packet: self.packets.packets,
                time_us: self.last_time,
                request_packet: None,
                response_time: None,
            };
            self.read_events(&mut found, place, out);
        }
        let Some(connection) = self.connections.remove(&key) else {
            return;
        };
        if !capture_ended {
            self.closed.add(key);
        }
        for side in [&connection.to_server, &connection.to_client] {
            self.packets.repeated_bytes += side.stream.repeated;
            self.packets.missing_bytes += side.stream.missing;
            self.packets.sequence_jumps += side.stream.jumps;
        }
        for pending in connection.pending {
            self.unanswered(pending, key, capture_ended, out);
        }
    }

    fn unanswered(
        &mut self,
        pending: Pending,
        key: Key,
        capture_ended: bool,
        out: &mut Vec<Record>,
    ) {
        self.counts.unanswered(pending.slave);
        if self.filter.shows(pending.slave, pending.request.function()) {
            let place = TcpPlace {
                client: key.0,
                server: key.1,
                udp: key.2,
                from_client: true,
                packet: pending.packet,
                time_us: pending.time,
                request_packet: None,
                response_time: None,
            };
            out.push(Record::Unanswered {
                slave: pending.slave,
                request: pending.request.request(),
                waited: Some(self.last_time.saturating_sub(pending.time)).filter(|w| *w > 0),
                capture_ended,
                tcp: Some((place, pending.transaction)),
            });
        }
    }

    fn read_events(&mut self, found: &mut Vec<Completed>, place: TcpPlace, out: &mut Vec<Record>) {
        for (event, (time, packet)) in found.drain(..) {
            match event {
                Event::Noise(noise) => {
                    self.counts.noise_bytes += noise.len;
                    if self.filter.is_empty() {
                        let at = self.at(noise.start);
                        out.push(Record::Noise {
                            kept: noise.kept,
                            len: noise.len,
                            offset: noise.offset,
                            time: Some(at),
                            at,
                        });
                    }
                }
                Event::Frame(frame) => {
                    let place = TcpPlace {
                        packet,
                        time_us: time,
                        ..place
                    };
                    self.frame(frame, time, place, out);
                }
            }
        }
    }

    /// Microseconds from the first packet.
    fn at(&self, time: Option<u64>) -> u64 {
        time.unwrap_or(self.last_time)
            .saturating_sub(self.first_time.unwrap_or(0))
    }

    /// A frame completed at `time` (microseconds since 1970) in the packet `place` names.
    /// A frame whose PDU reads is paired and counted now, and described only when shown.
    fn frame(&mut self, found: Found, time: u64, mut place: TcpPlace, out: &mut Vec<Record>) {
        let direction = match place.from_client {
            true => Direction::Request,
            false => Direction::Response,
        };
        let key = (place.client, place.server, place.udp);
        let mut mismatch = None;
        let seen = match (found.broken, Envelope::open(self.mode, &found.bytes)) {
            (None, Ok(envelope)) => {
                // Paired by its bytes; what they say is read only if it is shown.
                let reads = Pdu::reads(&envelope.pdu, direction);
                // A request that breaks its function's rules is still answered, with an
                // exception: it waits for that answer all the same. A malformed answer
                // still answers its request, which its header names.
                let paired = !envelope.pdu.is_empty()
                    && (reads || direction == Direction::Request || self.mode == Mode::Tcp);
                let request = match paired {
                    true => self.pair(
                        &envelope,
                        direction,
                        !reads,
                        key,
                        time,
                        &mut place,
                        &mut mismatch,
                        out,
                    ),
                    false => None,
                };
                let function = envelope.pdu.first().copied().unwrap_or_default();
                match reads {
                    true => {
                        let kind = Kind::travelling(direction, function);
                        // Only a read's answer takes its addresses from the request.
                        let answers = request.filter(|_| kind == Kind::Response);
                        Seen::Read {
                            slave: envelope.slave,
                            function,
                            kind,
                            answers,
                        }
                    }
                    false => {
                        self.counts.malformed += 1;
                        Seen::Described(Box::new(describe_frame(
                            &found.bytes,
                            Some(self.mode),
                            Some(direction),
                        )))
                    }
                }
            }
            (broken, _) => {
                let mut report = describe_frame(&found.bytes, Some(self.mode), Some(direction));
                report.valid = false;
                // What the header of a cut frame says still stands.
                if self.mode == Mode::Tcp {
                    let bytes = &found.bytes;
                    if let Some([hi, lo]) = bytes.get(..2) {
                        report.transaction = Some(u16::from_be_bytes([*hi, *lo]));
                    }
                    report.slave = bytes.get(6).copied().unwrap_or(report.slave);
                    report.function = bytes.get(7).copied().unwrap_or(report.function);
                }
                report.kind = Kind::travelling(direction, report.function);
                if broken == Some(Broken::Incomplete) {
                    report.error =
                        Some("incomplete: bytes of the frame are missing from the capture".into());
                }
                self.counts.crc_errors += u64::from(broken == Some(Broken::Checksum));
                Seen::Described(Box::new(report))
            }
        };
        let (slave, function, kind) = match &seen {
            Seen::Read {
                slave,
                function,
                kind,
                ..
            } => (*slave, *function, *kind),
            Seen::Described(report) => (report.slave, report.function, report.kind),
        };
        // Over TCP the direction tells a request from an answer, whatever its PDU holds:
        // every frame is counted as what its record says it is.
        self.counts.tell(slave, Some(kind));
        self.counts.mismatched += u64::from(mismatch.is_some());
        self.numbered += 1;
        if self.filter.shows(slave, function) {
            let (number, at) = (self.numbered, self.at(Some(time)));
            let mut record = match seen {
                Seen::Read { kind, answers, .. } => {
                    let ways = match kind {
                        Kind::Request => Ways::Request,
                        _ => Ways::Answer,
                    };
                    let answers = answers.map(|request| request.request());
                    FrameRecord::read(number, found, at, self.mode, ways, answers)
                }
                Seen::Described(report) => FrameRecord::new(number, found, at, *report),
            };
            record.paired = place.request_packet.is_some();
            record.mismatch = mismatch;
            record.tcp = Some(place);
            out.push(Record::Frame(record));
        }
    }

    /// A request waits for its answer; an answer is paired with its request, which it
    /// returns, and `place` learns the request's packet and the response time. A
    /// `malformed` answer (its PDU does not read) is paired by its header alone; one that
    /// does not fit the request it answers is told in `mismatch`.
    #[allow(clippy::too_many_arguments)]
    fn pair(
        &mut self,
        envelope: &Envelope,
        direction: Direction,
        malformed: bool,
        key: Key,
        time: u64,
        place: &mut TcpPlace,
        mismatch: &mut Option<Mismatch>,
        out: &mut Vec<Record>,
    ) -> Option<RequestSent> {
        let by_transaction = self.mode == Mode::Tcp;
        let connection = self.connections.get_mut(&key)?;
        let slave = envelope.slave;
        let transaction = envelope.transaction;
        match direction {
            Direction::Request => {
                // A client may send requests with one transaction id before the first is
                // answered (pipelined): they wait in order. Past a bound, the oldest of them
                // is taken as unanswered, so that a client that never gets an answer holds
                // no more than that.
                let same: Vec<usize> = (0..connection.pending.len())
                    .filter(|i| {
                        let p = &connection.pending[*i];
                        by_transaction && p.transaction == transaction && p.slave == slave
                    })
                    .collect();
                let pending = Pending {
                    slave,
                    transaction,
                    request: RequestSent::new(&envelope.pdu, !malformed),
                    time,
                    packet: place.packet,
                };
                connection.pending.push(pending);
                if same.len() >= MOST_WAITING_ON_ONE_ID {
                    let old = connection.pending.remove(same[0]);
                    self.unanswered(old, key, false, out);
                }
                None
            }
            Direction::Response => {
                // MBAP pairs by transaction and unit id, RTU by unit and function: with the
                // oldest request waiting that the answer fits (a write's echo, a read's
                // count); over MBAP, one that fits none still answers the oldest of its
                // transaction, and is told as not fitting it.
                let answer = &envelope.pdu;
                let fits = |p: &Pending| p.request.fit(answer, !malformed).is_ok();
                let waiting: Vec<usize> = (0..connection.pending.len())
                    .filter(|i| {
                        let p = &connection.pending[*i];
                        match by_transaction {
                            true => p.transaction == transaction && p.slave == slave,
                            false => p.slave == slave,
                        }
                    })
                    .collect();
                let fitting = waiting
                    .iter()
                    .copied()
                    .find(|i| fits(&connection.pending[*i]));
                let index = match (fitting, by_transaction) {
                    (Some(index), _) => index,
                    (None, true) => *waiting.first()?,
                    (None, false) => return None,
                };
                if fitting.is_none() && !malformed {
                    *mismatch = connection.pending[index].request.fit(answer, true).err();
                }
                let pending = connection.pending.remove(index);
                place.request_packet = Some(pending.packet);
                place.response_time = Some(time.saturating_sub(pending.time));
                Some(pending.request)
            }
        }
    }
}
