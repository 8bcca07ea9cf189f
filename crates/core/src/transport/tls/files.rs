//! The certificates and keys of a TLS end, read from PEM files written by someone else:
//! refused with what is wrong rather than half read, and a certificate's role, subject
//! and expiry read for the messages.

use std::io::Read;
use std::path::Path;

use rustls::pki_types::pem::PemObject;
use rustls::pki_types::{CertificateDer, PrivateKeyDer, UnixTime};
use rustls::RootCertStore;

use super::{RoleClaim, TlsError, ROLE_OID};

/// No PEM file of certificates or a key comes near this: a bigger one is refused unread.
const PEM_LIMIT: u64 = 1 << 20;

/// A PEM file read whole, refused unread when no PEM file could be that large.
fn read_pem(path: &Path) -> Result<Vec<u8>, TlsError> {
    let unreadable = |why: String| TlsError::Unreadable {
        path: path.to_path_buf(),
        why,
    };
    if path.is_dir() {
        return Err(unreadable("it is a folder: give the PEM file in it".into()));
    }
    let file = std::fs::File::open(path).map_err(|e| unreadable(e.to_string()))?;
    let mut bytes = Vec::new();
    file.take(PEM_LIMIT + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| unreadable(e.to_string()))?;
    if bytes.len() as u64 > PEM_LIMIT {
        return Err(unreadable(format!(
            "larger than {} KiB, which no PEM file of certificates is",
            PEM_LIMIT / 1024
        )));
    }
    Ok(bytes)
}

/// What a file holds in place of the certificate or key asked for, as what to do.
#[derive(Clone, Copy)]
enum Holds {
    Certificate,
    Key,
}

impl Holds {
    fn missing(self, path: &Path, pem: &[u8]) -> TlsError {
        let (what, markers, convert) = match self {
            Holds::Certificate => (
                "certificate",
                "'-----BEGIN CERTIFICATE-----'",
                "openssl x509 -inform der",
            ),
            Holds::Key => (
                "private key",
                "'-----BEGIN PRIVATE KEY-----' (or RSA or EC PRIVATE KEY)",
                "openssl pkey -inform der",
            ),
        };
        let text = String::from_utf8_lossy(pem);
        let shown = path.display();
        let why = if pem.first() == Some(&0x30) && !text.contains("-----BEGIN") {
            format!("it is DER, not PEM: convert it with '{convert} -in {shown} -out {shown}.pem'")
        } else if text.contains("ENCRYPTED PRIVATE KEY") || text.contains("Proc-Type: 4,ENCRYPTED")
        {
            format!("the key is encrypted: give it decrypted ('openssl pkey -in {shown} -out plain.key')")
        } else {
            format!("no PEM block {markers}")
        };
        TlsError::NoPem {
            path: path.to_path_buf(),
            what,
            why,
        }
    }

    fn damaged(self, path: &Path, error: &rustls::pki_types::pem::Error) -> TlsError {
        use rustls::pki_types::pem::Error as Pem;
        let why = match error {
            Pem::MissingSectionEnd { .. } => "a PEM block has no END line: the file is cut short",
            Pem::IllegalSectionStart { .. } => "a PEM block's BEGIN line is damaged",
            Pem::Base64Decode(_) => "the base64 inside a PEM block is damaged",
            _ => "it is no PEM file",
        };
        let what = match self {
            Holds::Certificate => "certificate",
            Holds::Key => "key",
        };
        TlsError::Malformed {
            path: path.to_path_buf(),
            why: format!("{why}: give the whole {what} file"),
        }
    }
}

pub(super) fn certificates(path: &Path) -> Result<Vec<CertificateDer<'static>>, TlsError> {
    let pem = read_pem(path)?;
    let chain = CertificateDer::pem_slice_iter(&pem)
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| Holds::Certificate.damaged(path, &e))?;
    let Some(first) = chain.first() else {
        return Err(Holds::Certificate.missing(path, &pem));
    };
    if x509_parser::parse_x509_certificate(first).is_err() {
        return Err(TlsError::Malformed {
            path: path.to_path_buf(),
            why: "its first certificate is no X.509 certificate".into(),
        });
    }
    Ok(chain)
}

pub(super) fn private_key(path: &Path) -> Result<PrivateKeyDer<'static>, TlsError> {
    let pem = read_pem(path)?;
    PrivateKeyDer::from_pem_slice(&pem).map_err(|e| match e {
        rustls::pki_types::pem::Error::NoItemsFound => Holds::Key.missing(path, &pem),
        e => Holds::Key.damaged(path, &e),
    })
}

/// The CA certificates of a PEM file, to check a server's certificate against.
pub fn root_store(path: &Path) -> Result<RootCertStore, TlsError> {
    let mut roots = RootCertStore::empty();
    for certificate in certificates(path)? {
        roots.add(certificate).map_err(|e| TlsError::Malformed {
            path: path.to_path_buf(),
            why: format!(
                "a CA certificate in it cannot be used ({}): give the CA file whole",
                super::refusals::plainly(&e)
            ),
        })?;
    }
    Ok(roots)
}

pub(super) fn key_error(error: rustls::Error, cert: &Path, key: &Path) -> TlsError {
    match error {
        rustls::Error::InconsistentKeys(_) => TlsError::KeyMismatch {
            cert: cert.to_path_buf(),
            key: key.to_path_buf(),
        },
        rustls::Error::InvalidCertificate(why) => TlsError::Malformed {
            path: cert.to_path_buf(),
            why: match format!("{why:?}") {
                version if version.contains("UnsupportedCertVersion") => {
                    "an X.509 version 1 certificate: version 3 is needed (openssl makes one with -extfile)".into()
                }
                other => format!(
                    "the certificate cannot be used: {}",
                    super::refusals::plainly(&other)
                ),
            },
        },
        other => TlsError::Malformed {
            path: key.to_path_buf(),
            why: format!("the key cannot be used ({other})"),
        },
    }
}

/// Refuses this end's own certificate before any connection when it is out of date.
pub(super) fn check_validity(path: &Path, der: &CertificateDer<'_>) -> Result<(), TlsError> {
    let Ok((_, certificate)) = x509_parser::parse_x509_certificate(der) else {
        return Ok(());
    };
    let validity = certificate.validity();
    let now = i64::try_from(UnixTime::now().as_secs()).unwrap_or(i64::MAX);
    let when = if now > validity.not_after.timestamp() {
        format!("expired on {}", validity.not_after)
    } else if now < validity.not_before.timestamp() {
        format!("is not valid until {}", validity.not_before)
    } else {
        return Ok(());
    };
    Err(TlsError::OwnCertificate {
        path: path.to_path_buf(),
        when,
    })
}

/// The role a certificate claims in the [`ROLE_OID`] extension.
pub fn certificate_role(der: &[u8]) -> RoleClaim {
    let Ok((_, certificate)) = x509_parser::parse_x509_certificate(der) else {
        return RoleClaim::Absent;
    };
    let extension = certificate
        .extensions()
        .iter()
        .find(|extension| extension.oid.to_id_string() == ROLE_OID);
    match extension {
        None => RoleClaim::Absent,
        // A role with control characters would forge lines in a server's log.
        Some(extension) => match utf8_string(extension.value) {
            Some(role) if !role.chars().any(char::is_control) => RoleClaim::Named(role.into()),
            _ => RoleClaim::Unreadable,
        },
    }
}

/// The text of a DER UTF8String that is all of `der`.
fn utf8_string(der: &[u8]) -> Option<&str> {
    let (&tag, rest) = der.split_first()?;
    let (&first, rest) = rest.split_first()?;
    let (length, body) = match first {
        n if n < 0x80 => (usize::from(n), rest),
        0x81 => (usize::from(*rest.first()?), rest.get(1..)?),
        0x82 => (
            usize::from(u16::from_be_bytes([*rest.first()?, *rest.get(1)?])),
            rest.get(2..)?,
        ),
        _ => return None,
    };
    (tag == 0x0C && body.len() == length)
        .then(|| std::str::from_utf8(body).ok())
        .flatten()
}

/// A certificate's subject as messages show it: its control characters escaped, so that
/// a certificate cannot forge lines in a log.
pub(super) fn subject_of(der: &[u8]) -> String {
    x509_parser::parse_x509_certificate(der)
        .map(|(_, certificate)| {
            certificate
                .subject()
                .to_string()
                .chars()
                .flat_map(|c| match c.is_control() {
                    true => c.escape_default().collect::<Vec<_>>(),
                    false => vec![c],
                })
                .collect()
        })
        .unwrap_or_default()
}

pub(super) fn not_after_of(der: &[u8]) -> String {
    x509_parser::parse_x509_certificate(der)
        .map(|(_, certificate)| certificate.validity().not_after.to_string())
        .unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_role_is_a_der_utf8_string() {
        assert_eq!(utf8_string(b"\x0c\x08operator"), Some("operator"));
        assert_eq!(utf8_string(b"\x0c\x09operator"), None);
        assert_eq!(utf8_string(b"\x13\x08operator"), None);
        assert_eq!(utf8_string(b""), None);
        let long = [&[0x0c, 0x81, 200][..], &[b'a'; 200]].concat();
        assert_eq!(utf8_string(&long).map(str::len), Some(200));
    }
}
