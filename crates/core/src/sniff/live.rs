//! Packets captured live from a network interface, through libpcap: a BPF filter keeps the
//! Modbus ports, and each packet comes out as a capture file's would.

use thiserror::Error;

use super::capture::Packet;

/// Why an interface cannot be captured from.
#[derive(Clone, Debug, Error, PartialEq, Eq)]
pub enum LiveError {
    /// Capturing needs privileges the process lacks.
    #[error("capturing on {0} needs privileges: run as root, or once: sudo setcap cap_net_raw,cap_net_admin=eip \"$(command -v mbtool)\"")]
    Permission(String),
    /// No interface has the name.
    #[error("there is no interface {name}: the interfaces here are {here}")]
    NoInterface {
        /// The name given.
        name: String,
        /// The interfaces that exist.
        here: String,
    },
    /// Anything else libpcap says.
    #[error("cannot capture on {interface}: {message}")]
    Pcap {
        /// The interface.
        interface: String,
        /// libpcap's words.
        message: String,
    },
}

/// A live capture.
pub struct LiveCapture {
    capture: pcap::Capture<pcap::Active>,
    link: u32,
    count: u64,
}

impl LiveCapture {
    /// Opens `interface`, keeping the TCP traffic of `ports`. Reads do not block (libpcap's
    /// own timeout is not kept in immediate mode): [`LiveCapture::next`] waits itself.
    pub fn open(interface: &str, ports: &[u16]) -> Result<Self, LiveError> {
        let failed = |error: pcap::Error| classify(interface, &error.to_string());
        let mut capture = pcap::Capture::from_device(interface)
            .map_err(failed)?
            .immediate_mode(true)
            .snaplen(65535)
            .open()
            .and_then(pcap::Capture::setnonblock)
            .map_err(failed)?;
        let filter = ports
            .iter()
            .map(|port| format!("tcp port {port}"))
            .collect::<Vec<_>>()
            .join(" or ");
        capture.filter(&filter, true).map_err(failed)?;
        let link = u32::try_from(capture.get_datalink().0).unwrap_or(u32::MAX);
        Ok(Self {
            capture,
            link,
            count: 0,
        })
    }

    /// The link type of the interface's packets.
    pub fn link(&self) -> u32 {
        self.link
    }

    /// The next packet, handed to `each`; `Ok(false)` when none came within `wait`.
    pub fn next(
        &mut self,
        wait: std::time::Duration,
        each: impl FnOnce(Packet),
    ) -> Result<bool, LiveError> {
        let until = std::time::Instant::now() + wait;
        loop {
            match self.capture.next_packet() {
                Ok(packet) => {
                    self.count += 1;
                    let ts = packet.header.ts;
                    let seconds = u64::try_from(ts.tv_sec).unwrap_or(0);
                    let micros = u64::try_from(ts.tv_usec).unwrap_or(0);
                    each(Packet {
                        number: self.count,
                        time_us: seconds * 1_000_000 + micros,
                        link: self.link,
                        data: packet.data,
                        original_len: packet.header.len,
                    });
                    return Ok(true);
                }
                Err(pcap::Error::TimeoutExpired) if std::time::Instant::now() < until => {
                    std::thread::sleep(std::time::Duration::from_millis(2));
                }
                Err(pcap::Error::TimeoutExpired) => return Ok(false),
                Err(error) => {
                    return Err(LiveError::Pcap {
                        interface: String::new(),
                        message: error.to_string(),
                    })
                }
            }
        }
    }
}

/// What libpcap's message means for the user.
fn classify(interface: &str, message: &str) -> LiveError {
    let lower = message.to_lowercase();
    if lower.contains("permission") || lower.contains("not permitted") {
        return LiveError::Permission(interface.to_string());
    }
    if lower.contains("no such device") {
        let here = pcap::Device::list()
            .map(|devices| {
                devices
                    .iter()
                    .map(|d| d.name.clone())
                    .filter(|n| n != "any" && !n.contains("nflog") && !n.contains("nfqueue"))
                    .collect::<Vec<_>>()
                    .join(", ")
            })
            .unwrap_or_default();
        return LiveError::NoInterface {
            name: interface.to_string(),
            here,
        };
    }
    LiveError::Pcap {
        interface: interface.to_string(),
        message: message.to_string(),
    }
}
