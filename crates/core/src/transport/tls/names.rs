//! The device's certificate checked as webpki checks it, and where its name does not
//! match, looked at for why: a certificate with no subjectAltName, its name only in the
//! subject's CN, which TLS clients have not read for years (RFC 6125), is told so, not as
//! "not for this name".

use std::sync::Arc;

use rustls::client::danger::{HandshakeSignatureValid, ServerCertVerified, ServerCertVerifier};
use rustls::client::WebPkiServerVerifier;
use rustls::pki_types::{CertificateDer, ServerName, UnixTime};
use rustls::{CertificateError, DigitallySignedStruct, OtherError, RootCertStore, SignatureScheme};

/// A certificate whose names are only in its subject's CN.
#[derive(Debug)]
pub(super) struct NameOnlyInCn {
    /// The CN.
    pub(super) common_name: String,
}

impl std::fmt::Display for NameOnlyInCn {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "a certificate with no subjectAltName, its name '{}' only in its CN",
            self.common_name
        )
    }
}

impl std::error::Error for NameOnlyInCn {}

/// A certificate of X.509 version 1, which has no extensions (no subjectAltName): what
/// `openssl x509 -req` makes without `-extfile`.
#[derive(Debug)]
pub(super) struct VersionOne;

impl std::fmt::Display for VersionOne {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("an X.509 version 1 certificate")
    }
}

impl std::error::Error for VersionOne {}

/// Whether a certificate is of X.509 version 1.
fn is_version_one(certificate: &[u8]) -> bool {
    x509_parser::parse_x509_certificate(certificate)
        .is_ok_and(|(_, parsed)| parsed.version() == x509_parser::x509::X509Version::V1)
}

/// webpki's verifier, with a CN-only certificate told apart.
#[derive(Debug)]
pub(super) struct NamingVerifier {
    inner: Arc<WebPkiServerVerifier>,
}

impl NamingVerifier {
    pub(super) fn new(
        roots: RootCertStore,
        provider: Arc<rustls::crypto::CryptoProvider>,
    ) -> Result<Self, rustls::client::VerifierBuilderError> {
        let inner =
            WebPkiServerVerifier::builder_with_provider(Arc::new(roots), provider).build()?;
        Ok(Self { inner })
    }
}

/// The CN of a certificate that has no subjectAltName.
fn only_common_name(certificate: &[u8]) -> Option<String> {
    let (_, parsed) = x509_parser::parse_x509_certificate(certificate).ok()?;
    if !matches!(parsed.subject_alternative_name(), Ok(None)) {
        return None;
    }
    let common_name = parsed.subject().iter_common_name().next()?;
    common_name.as_str().ok().map(str::to_string)
}

impl ServerCertVerifier for NamingVerifier {
    fn verify_server_cert(
        &self,
        end_entity: &CertificateDer<'_>,
        intermediates: &[CertificateDer<'_>],
        server_name: &ServerName<'_>,
        ocsp_response: &[u8],
        now: UnixTime,
    ) -> Result<ServerCertVerified, rustls::Error> {
        self.inner
            .verify_server_cert(end_entity, intermediates, server_name, ocsp_response, now)
            .map_err(|error| match &error {
                rustls::Error::InvalidCertificate(_) if is_version_one(end_entity) => {
                    rustls::Error::InvalidCertificate(CertificateError::Other(OtherError(
                        Arc::new(VersionOne),
                    )))
                }
                rustls::Error::InvalidCertificate(
                    CertificateError::NotValidForName
                    | CertificateError::NotValidForNameContext { .. },
                ) => match only_common_name(end_entity) {
                    Some(common_name) => rustls::Error::InvalidCertificate(
                        CertificateError::Other(OtherError(Arc::new(NameOnlyInCn { common_name }))),
                    ),
                    None => error,
                },
                _ => error,
            })
    }

    fn verify_tls12_signature(
        &self,
        message: &[u8],
        cert: &CertificateDer<'_>,
        dss: &DigitallySignedStruct,
    ) -> Result<HandshakeSignatureValid, rustls::Error> {
        self.inner.verify_tls12_signature(message, cert, dss)
    }

    fn verify_tls13_signature(
        &self,
        message: &[u8],
        cert: &CertificateDer<'_>,
        dss: &DigitallySignedStruct,
    ) -> Result<HandshakeSignatureValid, rustls::Error> {
        self.inner.verify_tls13_signature(message, cert, dss)
    }

    fn supported_verify_schemes(&self) -> Vec<SignatureScheme> {
        self.inner.supported_verify_schemes()
    }
}
