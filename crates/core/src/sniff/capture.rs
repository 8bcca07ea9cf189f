//! Packet captures as tcpdump, dumpcap, tshark and Wireshark write them: pcap and pcapng
//! (told apart by their magic, whatever the file's name), read block by block in bounded
//! memory, and in each packet the TCP segment under its link, VLAN and IP headers.

use std::io::{self, Read};
use std::net::{IpAddr, SocketAddr};

use etherparse::{EtherType, LaxNetSlice, LaxSlicedPacket, TransportSlice};
use pcap_parser::pcapng::Block;
use pcap_parser::traits::PcapNGPacketBlock;
use pcap_parser::{create_reader, PcapBlockOwned, PcapError};
use thiserror::Error;

/// The link types a capture's packets may start with.
mod link {
    /// BSD loopback: a 4-byte address family in the capturing machine's byte order.
    pub(super) const NULL: u32 = 0;
    pub(super) const ETHERNET: u32 = 1;
    /// Raw IP, as some systems number it.
    pub(super) const RAW_OPENBSD: u32 = 14;
    pub(super) const RAW_BSD: u32 = 12;
    pub(super) const RAW: u32 = 101;
    /// OpenBSD loopback: the family in network byte order.
    pub(super) const LOOP: u32 = 108;
    /// Linux cooked capture v1 (`tcpdump -i any` before libpcap 1.10).
    pub(super) const LINUX_SLL: u32 = 113;
    pub(super) const IPV4: u32 = 228;
    pub(super) const IPV6: u32 = 229;
    /// Linux cooked capture v2 (`tcpdump -i any`).
    pub(super) const LINUX_SLL2: u32 = 276;
}

/// One packet of a capture.
#[derive(Clone, Copy, Debug)]
pub struct Packet<'a> {
    /// Its number in the capture, from 1, as Wireshark numbers frames.
    pub number: u64,
    /// When it was captured, in microseconds since 1970.
    pub time_us: u64,
    /// Its link type, which says what its first header is.
    pub link: u32,
    /// The bytes captured.
    pub data: &'a [u8],
    /// How long it was on the wire: longer than `data` when the snap length cut it.
    pub original_len: u32,
}

/// Why a capture cannot be read (on), after how many packets.
#[derive(Clone, Debug, Error, PartialEq, Eq)]
pub enum CaptureError {
    /// The first bytes are neither pcap's magic nor pcapng's.
    #[error("is neither a pcap nor a pcapng file")]
    NotACapture,
    /// The file is empty.
    #[error("is empty, where a pcap or pcapng file was expected")]
    Empty,
    /// The file ends inside a record.
    #[error("ends in the middle of a record, after {}: the capture was cut off", packets(*.0))]
    Truncated(u64),
    /// A record that cannot be read.
    #[error("is damaged after {}: a record cannot be read", packets(*.0))]
    Damaged(u64),
    /// A read of the file failed.
    #[error("cannot be read: {0}")]
    Io(String),
}

/// "1 packet", "2 packets".
fn packets(count: u64) -> String {
    match count {
        1 => "1 packet".to_string(),
        _ => format!("{count} packets"),
    }
}

/// The buffer records are read into, grown for a larger record up to [`MOST_RECORD`].
const BUFFER: usize = 1 << 16;

/// The largest record read: a loopback capture holds packets of 64 KiB and more (segments
/// the kernel coalesced); a length past this is a damaged file, not a packet.
const MOST_RECORD: usize = 16 << 20;

/// An interface of a pcapng section: its link type, and the units and offset of its times.
#[derive(Clone, Copy)]
struct Interface {
    link: u32,
    /// Time units per second.
    resolution: u64,
    /// Seconds added to every time.
    offset: u64,
}

/// Whether a file starts as a pcap or pcapng file does.
pub fn is_capture(start: &[u8]) -> bool {
    const MAGICS: [[u8; 4]; 5] = [
        [0xD4, 0xC3, 0xB2, 0xA1],
        [0xA1, 0xB2, 0xC3, 0xD4],
        [0x4D, 0x3C, 0xB2, 0xA1],
        [0xA1, 0xB2, 0x3C, 0x4D],
        [0x0A, 0x0D, 0x0D, 0x0A],
    ];
    MAGICS.iter().any(|magic| start.starts_with(magic))
}

/// How long the file header of the capture that `start` begins is, as far as `start` tells:
/// 24 bytes for pcap; for pcapng, its first block, whose length follows its type (at most
/// 64 kB is asked for). `None` when `start` begins no capture.
pub fn header_len(start: &[u8]) -> Option<usize> {
    if !is_capture(start) {
        return None;
    }
    const PCAP_HEADER: usize = 24;
    const PCAPNG_LENGTH_AND_ORDER: usize = 12;
    if !start.starts_with(&[0x0A, 0x0D, 0x0D, 0x0A]) {
        return Some(PCAP_HEADER);
    }
    let (Some(length), Some(order)) = (start.get(4..8), start.get(8..12)) else {
        return Some(PCAPNG_LENGTH_AND_ORDER);
    };
    let length = [length[0], length[1], length[2], length[3]];
    let length = match order {
        [0x1A, 0x2B, 0x3C, 0x4D] => u32::from_be_bytes(length),
        _ => u32::from_le_bytes(length),
    };
    Some((length as usize).clamp(PCAPNG_LENGTH_AND_ORDER, 1 << 16))
}

/// Reads the packets of a pcap or pcapng capture, in order, handing each to `each` until
/// it returns false; returns how many there were.
pub fn read_packets<R: Read + Send>(
    input: R,
    mut each: impl FnMut(Packet) -> bool,
) -> Result<u64, CaptureError> {
    let mut reader = match create_reader(BUFFER, input) {
        Ok(reader) => reader,
        Err(PcapError::Eof) => return Err(CaptureError::Empty),
        Err(PcapError::ReadError) => return Err(CaptureError::Io("read failed".into())),
        Err(_) => return Err(CaptureError::NotACapture),
    };
    let mut count = 0u64;
    // pcap: one link type and one time unit for the whole file.
    let mut legacy = (link::ETHERNET, 1_000_000u64);
    let mut interfaces: Vec<Interface> = Vec::new();
    let mut going = true;
    while going {
        match reader.next() {
            Ok((size, block)) => {
                let mut packet = |link, time_us, data: &[u8], original_len| {
                    count += 1;
                    going = each(Packet {
                        number: count,
                        time_us,
                        link,
                        data,
                        original_len,
                    });
                };
                match block {
                    PcapBlockOwned::LegacyHeader(header) => {
                        let units = match header.is_nanosecond_precision() {
                            true => 1_000_000_000,
                            false => 1_000_000,
                        };
                        legacy = (header.network.0 as u32, units);
                    }
                    PcapBlockOwned::Legacy(block) => {
                        let fraction = u64::from(block.ts_usec) * 1_000_000 / legacy.1;
                        let time = u64::from(block.ts_sec) * 1_000_000 + fraction;
                        let captured = block.data.len().min(block.caplen as usize);
                        packet(legacy.0, time, &block.data[..captured], block.origlen);
                    }
                    PcapBlockOwned::NG(Block::SectionHeader(_)) => interfaces.clear(),
                    PcapBlockOwned::NG(Block::InterfaceDescription(description)) => {
                        interfaces.push(Interface {
                            link: description.linktype.0 as u32,
                            resolution: resolution(description.if_tsresol),
                            offset: ts_offset(&description),
                        });
                    }
                    PcapBlockOwned::NG(Block::EnhancedPacket(block)) => {
                        if let Some(interface) = interfaces.get(block.if_id as usize) {
                            let units = u128::from(block.ts_high) << 32 | u128::from(block.ts_low);
                            let micros =
                                units * 1_000_000 / u128::from(interface.resolution.max(1));
                            let time = u64::try_from(micros)
                                .unwrap_or(u64::MAX)
                                .saturating_add(interface.offset.saturating_mul(1_000_000));
                            packet(interface.link, time, block.packet_data(), block.origlen);
                        }
                    }
                    PcapBlockOwned::NG(Block::SimplePacket(block)) => {
                        // No time: it is placed at the start of time, as Wireshark does.
                        if let Some(interface) = interfaces.first() {
                            packet(interface.link, 0, block.packet_data(), block.origlen);
                        }
                    }
                    PcapBlockOwned::NG(_) => {}
                }
                reader.consume(size);
            }
            Err(PcapError::Eof) => return Ok(count),
            Err(PcapError::Incomplete(_) | PcapError::BufferTooSmall) => {
                if reader.reader_exhausted() {
                    return Err(CaptureError::Truncated(count));
                }
                let before = reader.data().len();
                reader
                    .refill()
                    .map_err(|_| CaptureError::Io("read failed".into()))?;
                // Nothing more fits: a record larger than the buffer.
                if reader.data().len() == before && !reader.reader_exhausted() {
                    let size = (before * 2).max(BUFFER);
                    if size > MOST_RECORD || !reader.grow(size) {
                        return Err(CaptureError::Damaged(count));
                    }
                }
            }
            Err(PcapError::UnexpectedEof) => return Err(CaptureError::Truncated(count)),
            Err(PcapError::ReadError) => return Err(CaptureError::Io("read failed".into())),
            Err(_) => return Err(CaptureError::Damaged(count)),
        }
    }
    Ok(count)
}

/// Time units per second of a pcapng interface's `if_tsresol`: 10^n, or 2^n with the top
/// bit set (pcap-parser's own reading refuses every power of 2); microseconds when it
/// makes no sense.
fn resolution(tsresol: u8) -> u64 {
    let exponent = u32::from(tsresol & 0x7F);
    let units = match tsresol & 0x80 {
        0 => 10u64.checked_pow(exponent),
        _ => 2u64.checked_pow(exponent),
    };
    units.filter(|units| *units > 0).unwrap_or(1_000_000)
}

/// Seconds added to an interface's times (`if_tsoffset`), in the byte order of its
/// section: pcap-parser reads it little-endian whatever the file's order.
fn ts_offset(description: &pcap_parser::InterfaceDescriptionBlock) -> u64 {
    // A block type read little-endian is 1 only in a little-endian section.
    let big = description.block_type != 1;
    description
        .options
        .iter()
        .find(|option| option.code == pcap_parser::pcapng::OptionCode::IfTsoffset)
        .and_then(|option| <[u8; 8]>::try_from(option.value.get(..8)?).ok())
        .map_or(0, |bytes| {
            let seconds = match big {
                true => i64::from_be_bytes(bytes),
                false => i64::from_le_bytes(bytes),
            };
            u64::try_from(seconds).unwrap_or(0)
        })
}

/// The TCP segment of a packet.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Segment<'a> {
    /// Who sent it.
    pub source: SocketAddr,
    /// Who it went to.
    pub destination: SocketAddr,
    /// The sequence number of its first byte (of its SYN, when it has one).
    pub sequence: u32,
    /// It opens a connection.
    pub syn: bool,
    /// The sender has no more to send.
    pub fin: bool,
    /// The connection was reset.
    pub rst: bool,
    /// The next byte the sender expects from the other side, when it says.
    pub acknowledgement: Option<u32>,
    /// The payload as captured.
    pub payload: &'a [u8],
    /// Payload bytes the capture left out (a snap length shorter than the packet).
    pub cut: u32,
}

/// What a packet is when it carries no TCP segment.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NotTcp {
    /// A link type this reader does not know.
    Link(u32),
    /// Anything else: ARP, UDP, ICMP, headers cut short.
    Other,
}

/// A packet's headers read down to its transport, with its IP addresses.
fn sliced<'a>(packet: &Packet<'a>) -> Result<(LaxSlicedPacket<'a>, IpAddr, IpAddr), NotTcp> {
    let data = packet.data;
    let family = |bytes: Option<&[u8]>, big: bool| -> Option<u32> {
        let bytes: [u8; 4] = bytes?.try_into().ok()?;
        Some(match big {
            true => u32::from_be_bytes(bytes),
            false => u32::from_le_bytes(bytes),
        })
    };
    let sliced = match packet.link {
        link::ETHERNET => LaxSlicedPacket::from_ethernet(data).ok(),
        link::LINUX_SLL => ether_type(data, 14, 16),
        link::LINUX_SLL2 => ether_type(data, 0, 20),
        link::NULL | link::LOOP => {
            // The family tells IPv4 (2) from IPv6 (24, 28, 30); the IP header says it too.
            let big = packet.link == link::LOOP;
            family(data.get(..4), big)
                .filter(|f| matches!(f, 2 | 24 | 28 | 30) || !big && f.swap_bytes() == 2)
                .and_then(|_| LaxSlicedPacket::from_ip(&data[4..]).ok())
        }
        link::RAW | link::RAW_BSD | link::RAW_OPENBSD | link::IPV4 | link::IPV6 => {
            LaxSlicedPacket::from_ip(data).ok()
        }
        other => return Err(NotTcp::Link(other)),
    };
    let sliced = sliced.ok_or(NotTcp::Other)?;
    let (source, destination): (IpAddr, IpAddr) = match &sliced.net {
        Some(LaxNetSlice::Ipv4(ip)) => (
            ip.header().source_addr().into(),
            ip.header().destination_addr().into(),
        ),
        Some(LaxNetSlice::Ipv6(ip)) => (
            ip.header().source_addr().into(),
            ip.header().destination_addr().into(),
        ),
        _ => return Err(NotTcp::Other),
    };
    Ok((sliced, source, destination))
}

/// The TCP segment a packet carries, under its link, VLAN and IP headers.
pub fn segment<'a>(packet: &Packet<'a>) -> Result<Segment<'a>, NotTcp> {
    let (sliced, source, destination) = sliced(packet)?;
    let Some(TransportSlice::Tcp(tcp)) = &sliced.transport else {
        return Err(NotTcp::Other);
    };
    let cut = packet
        .original_len
        .saturating_sub(u32::try_from(packet.data.len()).unwrap_or(u32::MAX));
    Ok(Segment {
        source: SocketAddr::new(source, tcp.source_port()),
        destination: SocketAddr::new(destination, tcp.destination_port()),
        sequence: tcp.sequence_number(),
        syn: tcp.syn(),
        fin: tcp.fin(),
        rst: tcp.rst(),
        acknowledgement: tcp.ack().then(|| tcp.acknowledgment_number()),
        payload: tcp.payload(),
        cut,
    })
}

/// The UDP datagram of a packet.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Datagram<'a> {
    /// Who sent it.
    pub source: SocketAddr,
    /// Who it went to.
    pub destination: SocketAddr,
    /// The payload as captured: whole, or cut by the snap length.
    pub payload: &'a [u8],
}

/// The UDP datagram a packet carries, under its link, VLAN and IP headers; `None` for any
/// other packet.
pub fn datagram<'a>(packet: &Packet<'a>) -> Option<Datagram<'a>> {
    let (sliced, source, destination) = sliced(packet).ok()?;
    let Some(TransportSlice::Udp(udp)) = &sliced.transport else {
        return None;
    };
    Some(Datagram {
        source: SocketAddr::new(source, udp.source_port()),
        destination: SocketAddr::new(destination, udp.destination_port()),
        payload: udp.payload(),
    })
}

/// A packet whose link header names its EtherType at `at` and is `len` bytes long.
fn ether_type(data: &[u8], at: usize, len: usize) -> Option<LaxSlicedPacket<'_>> {
    let kind = u16::from_be_bytes(data.get(at..at + 2)?.try_into().ok()?);
    Some(LaxSlicedPacket::from_ether_type(
        EtherType(kind),
        data.get(len..)?,
    ))
}

/// The first bytes of the input, read until they tell whether it is a packet capture and,
/// if it is, hold its file header whole: a pipe (`tcpdump -w - | mbtool sniff --input -`)
/// may bring the header in pieces, and the capture is told, and its header read, from
/// what the first read gives. Raw bytes of a line are held back by four bytes at most.
pub fn read_head(input: &mut dyn Read) -> io::Result<Vec<u8>> {
    let mut head = Vec::new();
    let mut want = 4;
    while head.len() < want {
        let mut chunk = vec![0u8; want - head.len()];
        match input.read(&mut chunk) {
            Ok(0) => break,
            Ok(n) => head.extend_from_slice(&chunk[..n]),
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        }
        if head.len() >= want {
            want = header_len(&head).unwrap_or(head.len()).max(head.len());
        }
    }
    Ok(head)
}

/// A name that says the file is a packet capture.
pub fn named_as_capture(path: &std::path::Path) -> bool {
    let extension = path
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or_default();
    ["pcap", "pcapng", "cap", "dmp"]
        .iter()
        .any(|known| extension.eq_ignore_ascii_case(known))
}

/// What the first bytes of a file that is no packet capture say it holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Content {
    /// Nothing.
    Empty,
    /// Text: a log or a paste, no line's bytes.
    Text,
    /// Bytes, as a serial line carries them.
    Bytes,
}

/// What `start`, the first bytes of a file, holds (its first 512 bytes tell text).
pub fn content(start: &[u8]) -> Content {
    match start {
        [] => Content::Empty,
        _ if start
            .iter()
            .take(512)
            .all(|b| b.is_ascii_graphic() || b.is_ascii_whitespace()) =>
        {
            Content::Text
        }
        _ => Content::Bytes,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_packet_is_said_so() {
        assert_eq!(
            CaptureError::Truncated(1).to_string(),
            "ends in the middle of a record, after 1 packet: the capture was cut off"
        );
        assert_eq!(
            CaptureError::Damaged(2).to_string(),
            "is damaged after 2 packets: a record cannot be read"
        );
    }
}
