//! The hosts a network sweep asks, as typed: `10.0.0.0/24,10.0.1.5-20,plc1`.

use std::net::{IpAddr, Ipv4Addr};

/// The most addresses one sweep asks: a /16.
pub const MOST_HOSTS: usize = 65536;

/// A host to ask: an address, or a name resolved when it is asked.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Host {
    /// An IP address.
    Address(IpAddr),
    /// A host name.
    Name(String),
}

impl std::fmt::Display for Host {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Host::Address(address) => write!(f, "{address}"),
            Host::Name(name) => f.write_str(name),
        }
    }
}

fn ipv4(text: &str, whole: &str) -> Result<Ipv4Addr, String> {
    text.trim()
        .parse()
        .map_err(|_| format!("--hosts {whole}: '{text}' is no IPv4 address (as in 10.0.0.5)"))
}

/// Every host of `text`: comma-separated addresses (IPv4 or IPv6), IPv4 networks
/// (`10.0.0.0/24`, every address but the network's and the broadcast's from /31 up),
/// ranges of the last byte (`10.0.1.5-20`) or of whole addresses (`10.0.1.250-10.0.2.5`),
/// and names; each host once, in the order given, at most [`MOST_HOSTS`].
pub fn parse_hosts(text: &str) -> Result<Vec<Host>, String> {
    let mut hosts: Vec<Host> = Vec::new();
    let mut seen = std::collections::HashSet::new();
    let mut add = |host: Host, hosts: &mut Vec<Host>| -> Result<(), String> {
        if seen.insert(host.clone()) {
            if hosts.len() == MOST_HOSTS {
                return Err(format!(
                    "--hosts {text}: more than {MOST_HOSTS} hosts; sweep a /16 or less at a time"
                ));
            }
            hosts.push(host);
        }
        Ok(())
    };
    for part in text.split(',').map(str::trim) {
        if part.is_empty() {
            return Err(format!("--hosts {text}: an empty entry between commas"));
        }
        if let Ok(address) = part.parse::<IpAddr>() {
            add(Host::Address(address), &mut hosts)?;
        } else if let Some((network, bits)) = part.split_once('/') {
            let network = ipv4(network, part)?;
            let bits: u32 = bits
                .parse()
                .ok()
                .filter(|bits| *bits <= 32)
                .ok_or_else(|| format!("--hosts {part}: the prefix is 0-32, as in /24"))?;
            if bits < 16 {
                return Err(format!(
                    "--hosts {part}: more than {MOST_HOSTS} hosts; sweep a /16 or less at a time"
                ));
            }
            let size = 1u32 << (32 - bits);
            let first = u32::from(network) & !(size - 1);
            // The network's own address and its broadcast answer nothing of their own.
            let (start, end) = match size {
                1 | 2 => (first, first + size - 1),
                _ => (first + 1, first + size - 2),
            };
            for address in start..=end {
                add(Host::Address(Ipv4Addr::from(address).into()), &mut hosts)?;
            }
        } else if let Some((first, last)) = part.split_once('-') {
            let first = ipv4(first, part)?;
            let last = match last.trim().parse::<u8>() {
                Ok(byte) => {
                    let [a, b, c, _] = first.octets();
                    Ipv4Addr::new(a, b, c, byte)
                }
                Err(_) => ipv4(last, part)?,
            };
            let (first, last) = (u32::from(first), u32::from(last));
            if first > last {
                return Err(format!(
                    "--hosts {part}: the first address of a range comes first"
                ));
            }
            if (last - first) as usize >= MOST_HOSTS {
                return Err(format!(
                    "--hosts {part}: more than {MOST_HOSTS} hosts; sweep a /16 or less at a time"
                ));
            }
            for address in first..=last {
                add(Host::Address(Ipv4Addr::from(address).into()), &mut hosts)?;
            }
        } else if part.chars().all(|c| c.is_ascii_digit() || c == '.') {
            // Digits and dots are an address mistyped, never a name.
            return Err(format!(
                "--hosts {part}: not an address: four numbers 0-255 (10.0.0.5)"
            ));
        } else if part
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || matches!(c, '.' | '-' | '_'))
        {
            add(Host::Name(part.to_string()), &mut hosts)?;
        } else if part.rsplit_once(':').is_some_and(|(host, port)| {
            !host.contains(':') && !port.is_empty() && port.chars().all(|c| c.is_ascii_digit())
        }) {
            return Err(format!(
                "--hosts {part}: give the port with --tcp-port (--hosts 10.0.0.5 --tcp-port 502)"
            ));
        } else {
            return Err(format!(
                "--hosts {part}: give addresses (10.0.0.5), networks (10.0.0.0/24), ranges (10.0.0.5-20) or names"
            ));
        }
    }
    Ok(hosts)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mistyped_addresses_and_ports_are_told() {
        assert_eq!(
            parse_hosts("127.0.0.300"),
            Err("--hosts 127.0.0.300: not an address: four numbers 0-255 (10.0.0.5)".into())
        );
        assert_eq!(
            parse_hosts("10.0.0.5:502"),
            Err("--hosts 10.0.0.5:502: give the port with --tcp-port (--hosts 10.0.0.5 --tcp-port 502)".into())
        );
    }

    fn shown(text: &str) -> Vec<String> {
        parse_hosts(text)
            .unwrap()
            .iter()
            .map(ToString::to_string)
            .collect()
    }

    #[test]
    fn networks_ranges_lists_and_names() {
        assert_eq!(
            shown("10.0.0.0/30,10.0.1.5-7,plc1,10.0.0.1,::1"),
            ["10.0.0.1", "10.0.0.2", "10.0.1.5", "10.0.1.6", "10.0.1.7", "plc1", "::1"]
        );
        assert_eq!(
            shown("10.0.0.255-10.0.1.1"),
            ["10.0.0.255", "10.0.1.0", "10.0.1.1"]
        );
        assert_eq!(parse_hosts("10.0.0.0/16").unwrap().len(), 65534);
        assert_eq!(shown("127.0.0.9/32"), ["127.0.0.9"]);
        for bad in [
            "10.0.0.0/8",
            "10.0.0.9-3",
            "10.0.0.0/33",
            "a b",
            "10.0.0.1,,x",
            "10.0.300.1-2",
        ] {
            assert!(parse_hosts(bad).is_err(), "{bad}");
        }
    }
}
