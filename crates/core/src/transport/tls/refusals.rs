//! A failed TLS handshake, or a connection refused after it, told as what to do: by the
//! master that made it, or in the log of the server that refused it.

use std::io;

use rustls::{AlertDescription, CertificateError};

use super::names::{NameOnlyInCn, VersionOne};
use super::{ClientTls, MODBUS_TLS_PORT};

/// What a device that speaks an older TLS is told.
const NO_COMMON_VERSION: &str = "the device speaks neither TLS 1.2 nor 1.3, which Modbus/TCP Security requires and mbtool speaks: update the device's firmware";

/// The rustls error inside an I/O error, if it is one.
fn rustls_error(error: &io::Error) -> Option<&rustls::Error> {
    error.get_ref()?.downcast_ref::<rustls::Error>()
}

/// A failed handshake of a master, told as what to do.
pub(super) fn client_side(error: io::Error, port: u16, name: &str, tls: &ClientTls) -> io::Error {
    let ca = tls.ca.display();
    let message = match rustls_error(&error) {
        Some(rustls::Error::InvalidCertificate(certificate)) => match certificate {
            CertificateError::Expired | CertificateError::ExpiredContext { .. } => format!(
                "the device's certificate has expired{}: renew it on the device (or check the clocks here and there)",
                expired_since(certificate)
            ),
            CertificateError::NotValidYet | CertificateError::NotValidYetContext { .. } => {
                "the device's certificate is not valid yet: check the clocks of the device and of this computer".into()
            }
            CertificateError::UnknownIssuer | CertificateError::BadSignature => format!(
                "the device's certificate is not signed by a CA of {ca}: give the CA that signed it with --ca"
            ),
            CertificateError::NotValidForName | CertificateError::NotValidForNameContext { .. } => {
                let fix = match tls.server_name {
                    Some(_) => "give --tls-server-name one of the names it holds",
                    None => "connect by a name it holds, or give it with --tls-server-name",
                };
                format!(
                    "the device's certificate is not for '{name}'{}: {fix}",
                    presented_names(certificate)
                )
            }
            CertificateError::InvalidPurpose | CertificateError::InvalidPurposeContext { .. } => {
                "the device's certificate is not one for a server (its extended key usage lacks serverAuth): the device needs a server certificate".into()
            }
            CertificateError::Other(other) => {
                if let Some(cn) = other.0.downcast_ref::<NameOnlyInCn>() {
                    format!(
                        "the device's certificate has no subjectAltName: its name '{}' is only in its subject CN, which TLS clients no longer read (RFC 6125): issue it again with subjectAltName DNS:{name} (or IP:{name})",
                        cn.common_name
                    )
                } else if other.0.downcast_ref::<VersionOne>().is_some() {
                    format!(
                        "the device's certificate is X.509 version 1, which holds no extensions and so no subjectAltName: issue it again as version 3 with subjectAltName DNS:{name} (openssl x509 -req ... -extfile with subjectAltName=DNS:{name})"
                    )
                } else {
                    format!("the device's certificate was refused: {}", plainly(other))
                }
            }
            other => format!("the device's certificate was refused: {}", plainly(other)),
        },
        Some(rustls::Error::AlertReceived(alert)) => match alert {
            AlertDescription::CertificateRequired => {
                "the device wants a client certificate: give --cert and --key".into()
            }
            AlertDescription::HandshakeFailure if tls.cert.is_none() => {
                "the device refused the handshake, most likely for want of a client certificate: give --cert and --key".into()
            }
            AlertDescription::HandshakeFailure | AlertDescription::InsufficientSecurity => {
                "the device refused the handshake: it shares no TLS 1.2 or 1.3 cipher suite with mbtool, or does not accept this end's certificate".into()
            }
            AlertDescription::BadCertificate
            | AlertDescription::UnknownCA
            | AlertDescription::CertificateUnknown
            | AlertDescription::UnsupportedCertificate
            | AlertDescription::AccessDenied => format!(
                "the device refused this end's certificate{} ({alert:?}): it must be signed by a CA the device trusts",
                tls.cert.as_ref().map_or_else(String::new, |c| format!(" {}", c.display()))
            ),
            AlertDescription::CertificateExpired => format!(
                "the device says this end's certificate{} has expired: renew it",
                tls.cert.as_ref().map_or_else(String::new, |c| format!(" {}", c.display()))
            ),
            AlertDescription::ProtocolVersion => NO_COMMON_VERSION.into(),
            other => format!("the device ended the handshake with the alert {other:?}"),
        },
        Some(rustls::Error::PeerIncompatible(why)) => format!("{NO_COMMON_VERSION} ({why:?})"),
        Some(rustls::Error::InvalidMessage(_) | rustls::Error::InappropriateMessage { .. }) => {
            "the answer is not TLS: this looks like a plain Modbus TCP port: use tcp://".into()
        }
        Some(other) => format!("TLS handshake failed: {}", plainly(other)),
        // Closed before it said anything in TLS.
        None if error.kind() == io::ErrorKind::UnexpectedEof => {
            let hint = if port == MODBUS_TLS_PORT {
                "is TLS turned on on the device?"
            } else {
                "a plain Modbus TCP port closes on a TLS greeting: if it is one, use tcp://"
            };
            format!("the device closed the connection during the TLS handshake: {hint}")
        }
        // Closed after it had answered in TLS, without an alert to say why.
        None if error.kind() == io::ErrorKind::ConnectionAborted => match &tls.cert {
            None => "the device ended the TLS handshake without saying why: most likely it wants a client certificate: give --cert and --key".into(),
            Some(cert) => format!(
                "the device ended the TLS handshake without saying why: it may not accept the certificate {} (signed by a CA it trusts? in date?)",
                cert.display()
            ),
        },
        None => return error,
    };
    // The endpoint is named by whoever tells this.
    io::Error::new(io::ErrorKind::ConnectionRefused, message)
}

/// A failed handshake of a server, told in its log.
pub(super) fn server_side(error: io::Error, peer: &str) -> io::Error {
    let message = match rustls_error(&error) {
        Some(rustls::Error::NoCertificatesPresented) => {
            "refused: it sent no client certificate".to_string()
        }
        Some(rustls::Error::InvalidCertificate(certificate)) => match certificate {
            CertificateError::UnknownIssuer | CertificateError::BadSignature => {
                "refused: its certificate is not signed by a CA of --ca".into()
            }
            CertificateError::Expired | CertificateError::ExpiredContext { .. } => {
                "refused: its certificate has expired".into()
            }
            CertificateError::NotValidYet | CertificateError::NotValidYetContext { .. } => {
                "refused: its certificate is not valid yet".into()
            }
            CertificateError::InvalidPurpose | CertificateError::InvalidPurposeContext { .. } => {
                "refused: its certificate is not one for a client (no clientAuth)".into()
            }
            other => format!("refused: its certificate: {}", plainly(other)),
        },
        Some(rustls::Error::InvalidMessage(_) | rustls::Error::InappropriateMessage { .. }) => {
            "refused: it did not speak TLS (a plain Modbus TCP client? it should use tls://)".into()
        }
        Some(rustls::Error::AlertReceived(alert)) => format!(
            "ended the handshake with the alert {alert:?}: it may not trust this server's certificate, or speak only an older TLS"
        ),
        // A hello of TLS 1.1 or older has no signature algorithms, nor a version this
        // server speaks.
        Some(rustls::Error::PeerIncompatible(why)) => format!(
            "refused: it speaks a TLS older than 1.2 ({why:?}), and Modbus/TCP Security needs TLS 1.2 or 1.3: update the client or its TLS settings"
        ),
        Some(other) => format!("TLS handshake failed: {other}"),
        None if error.kind() == io::ErrorKind::TimedOut => {
            "refused: no TLS handshake in time".into()
        }
        None => format!("TLS handshake failed: {error}"),
    };
    io::Error::new(io::ErrorKind::PermissionDenied, format!("{peer} {message}"))
}

fn expired_since(error: &CertificateError) -> String {
    match error {
        CertificateError::ExpiredContext { not_after, .. } => {
            format!(" (on {})", asn1_date(not_after.as_secs()))
        }
        _ => String::new(),
    }
}

fn presented_names(error: &CertificateError) -> String {
    match error {
        CertificateError::NotValidForNameContext { presented, .. } if !presented.is_empty() => {
            // rustls shows them as `DnsName("plc.example")`: the name alone reads better.
            let names: Vec<&str> = presented
                .iter()
                .map(|shown| {
                    shown
                        .split_once('(')
                        .and_then(|(_, inner)| inner.strip_suffix(')'))
                        .map_or(shown.as_str(), |inner| inner.trim_matches('"'))
                })
                .collect();
            format!(" but for {}", names.join(", "))
        }
        _ => String::new(),
    }
}

/// A time as certificates show it.
fn asn1_date(unix_seconds: u64) -> String {
    i64::try_from(unix_seconds)
        .ok()
        .and_then(|seconds| x509_parser::time::ASN1Time::from_timestamp(seconds).ok())
        .map_or_else(|| unix_seconds.to_string(), |time| time.to_string())
}

/// What rustls says of an error, in words where it names its own types: a critical
/// extension it cannot check (a role extension marked critical), a damaged encoding.
pub(super) fn plainly(error: &dyn std::fmt::Debug) -> String {
    let shown = format!("{error:?}");
    if shown.contains("UnsupportedCriticalExtension") {
        "it has a critical extension that cannot be checked (a role extension must not be marked critical)".into()
    } else if shown.contains("BadEncoding") {
        "it is damaged (its encoding does not read)".into()
    } else {
        shown
    }
}
