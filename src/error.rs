//! The library's errors, each with the exit status CLI.md gives it.

use thiserror::Error;

use crate::address::AddressError;

#[derive(Debug, Error)]
pub enum Error {
    /// A bad command line or bad input: nothing was sent.
    #[error("{0}")]
    Usage(String),
    #[error(transparent)]
    Address(#[from] AddressError),
    #[error(transparent)]
    Io(#[from] std::io::Error),
}

impl Error {
    pub fn usage(message: impl Into<String>) -> Self {
        Error::Usage(message.into())
    }

    /// The process exit status for this error (CLI.md, "Exit status").
    pub fn exit_code(&self) -> u8 {
        match self {
            Error::Usage(_) | Error::Address(_) => 2,
            Error::Io(_) => 1,
        }
    }
}

pub type Result<T, E = Error> = std::result::Result<T, E>;
