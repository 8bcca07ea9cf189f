//! The library's errors, each with the exit status docs/reading-and-writing.md gives it.

use thiserror::Error;

use mbtool_core::codec::ExceptionCode;
use mbtool_core::master::plan::PlanError;
use mbtool_core::master::run::RunError;
use mbtool_core::master::MasterError;
use mbtool_core::model::address::AddressError;
use mbtool_core::model::map::MapError;
use mbtool_core::slave::datafile::DataFileError;
use mbtool_core::sniff::replay::{ReplayError, TimingFault};
use mbtool_core::sniff::timing::TimingError;
use mbtool_core::transport::endpoint::EndpointError;
use mbtool_core::transport::tls::TlsError;

#[derive(Debug, Error)]
pub enum Error {
    /// A bad command line or bad input: nothing was sent.
    #[error("{0}")]
    Usage(String),
    /// Bad input with several faults (the lines of a map or data file), each told on a
    /// line of its own: nothing was sent.
    #[error("{}", .0.join("\n"))]
    Faults(Vec<String>),
    #[error(transparent)]
    Address(#[from] AddressError),
    #[error(transparent)]
    Plan(#[from] PlanError),
    #[error(transparent)]
    Endpoint(#[from] EndpointError),
    #[error(transparent)]
    Io(#[from] std::io::Error),
    #[error(transparent)]
    Master(#[from] MasterError),
    /// No answer, with what was tried and what usually causes it.
    #[error("{error} {tried}: {advice}")]
    NoAnswer {
        error: MasterError,
        tried: String,
        advice: &'static str,
    },
    #[error("slave {slave} answered exception {code} to function {function} ({})", mbtool_core::codec::function::name(*function))]
    Exception {
        slave: u8,
        function: u8,
        code: ExceptionCode,
    },
    /// A request that changes the device got no answer: it may have been carried out.
    #[error(
        "{error}; the request was sent {} and may have been carried out all the same: read back before writing again",
        mbtool_core::master::run::times(*.sent)
    )]
    Unconfirmed { error: Box<Error>, sent: u32 },
    /// Exception 01 over Modbus/TCP Security, which may be the server's role check.
    #[error(
        "{0}: over Modbus/TCP Security this may be the server refusing what this certificate's role may do \
         (mbtool serve and gateway with --role do so, and their log names the rule)"
    )]
    MaybeRole(Box<Error>),
}

/// A map that cannot be read is an I/O failure; one with faults in it is bad input.
impl From<MapError> for Error {
    fn from(error: MapError) -> Self {
        match error {
            MapError::Unreadable { .. } => Error::Io(std::io::Error::other(error.to_string())),
            MapError::At { .. } => Error::usage(error.to_string()),
            MapError::Several { .. } => Error::faults(&error),
        }
    }
}

/// A data file that cannot be read is an I/O failure; one with faults in it is bad input.
impl From<TlsError> for Error {
    fn from(error: TlsError) -> Self {
        match error {
            // The command line lacks an option: it is told as usage.
            TlsError::Missing(_) => Error::usage(error.to_string()),
            // A file that cannot be used, a handshake that failed: the connection fails.
            _ => Error::Io(error.into()),
        }
    }
}

impl From<DataFileError> for Error {
    fn from(error: DataFileError) -> Self {
        match error {
            DataFileError::Read { .. } => Error::Io(std::io::Error::other(error.to_string())),
            DataFileError::Line { .. } => Error::usage(error.to_string()),
            DataFileError::Lines { .. } => Error::faults(&error),
        }
    }
}

/// A request that got no usable answer: the master's error, or the slave's exception.
impl From<RunError> for Error {
    fn from(error: RunError) -> Self {
        match error {
            RunError::Master(error) => Error::Master(error),
            RunError::Unconfirmed { error, sent } => Error::Unconfirmed {
                error: Box::new(Error::Master(error)),
                sent,
            },
            RunError::Exception {
                slave,
                function,
                code,
            } => Error::Exception {
                slave,
                function,
                code,
            },
        }
    }
}

impl Error {
    pub fn usage(message: impl Into<String>) -> Self {
        Error::Usage(message.into())
    }

    /// The faults an error tells one a line.
    fn faults(error: &dyn std::fmt::Display) -> Self {
        Error::Faults(error.to_string().lines().map(String::from).collect())
    }

    /// A timeout told with what was tried (`on /dev/ttyUSB0 (rtu, 19200 baud, ...)`) and
    /// what usually causes it; other errors as they are.
    pub fn tried(self, tried: String, advice: &'static str) -> Self {
        match self {
            Error::Master(error @ MasterError::Timeout { .. }) => Error::NoAnswer {
                error,
                tried,
                advice,
            },
            Error::Unconfirmed { error, sent } => Error::Unconfirmed {
                error: Box::new(error.tried(tried, advice)),
                sent,
            },
            other => other,
        }
    }

    /// The process exit status for this error ("Exit status" in docs/reading-and-writing.md).
    pub fn exit_code(&self) -> u8 {
        match self {
            Error::Usage(_)
            | Error::Faults(_)
            | Error::Address(_)
            | Error::Plan(_)
            | Error::Endpoint(_) => 2,
            Error::Io(_) => 1,
            Error::NoAnswer { .. } => 3,
            Error::Master(error) => master_exit_code(error),
            Error::Exception { code, .. } => exception_exit_code(*code),
            Error::MaybeRole(error) | Error::Unconfirmed { error, .. } => error.exit_code(),
        }
    }
}

/// The exit status for a request's failure, as [`Error::exit_code`] gives it.
pub fn run_exit_code(error: &RunError) -> u8 {
    match error {
        RunError::Master(error) | RunError::Unconfirmed { error, .. } => master_exit_code(error),
        RunError::Exception { code, .. } => exception_exit_code(*code),
    }
}

fn master_exit_code(error: &MasterError) -> u8 {
    match error {
        MasterError::Timeout { .. } | MasterError::OutOfStep { .. } => 3,
        MasterError::BadFrame { .. } => 4,
        MasterError::Encode(_) => 2,
        MasterError::Io(_) => 1,
        MasterError::Interrupted => 130,
    }
}

/// 10 + N; a code past 245 (none is defined) saturates at 255.
fn exception_exit_code(code: ExceptionCode) -> u8 {
    10u8.saturating_add(code.0)
}

pub type Result<T, E = Error> = std::result::Result<T, E>;

/// A replay's failure, told as what to do.
pub fn replay_failed(error: ReplayError) -> anyhow::Error {
    let move_away = "move it away to replay without timing";
    match error {
        ReplayError::Capture(error) | ReplayError::Output(error) => error.into(),
        ReplayError::ShorterThanTiming => Error::usage(
            "the capture is shorter than its .timing file says: move the .timing file away to replay without timing",
        )
        .into(),
        ReplayError::Timing { path, fault } => {
            let path = path.display();
            match fault {
                TimingFault::Read(TimingError::Io(error)) => {
                    anyhow::Error::new(error).context(format!("cannot read {path}"))
                }
                TimingFault::NotAFile => {
                    Error::usage(format!("{path} is not a file, so no .timing file: {move_away}"))
                        .into()
                }
                TimingFault::Read(TimingError::NotText) => {
                    Error::usage(format!("{path} is not text, so no .timing file: {move_away}"))
                        .into()
                }
                TimingFault::Read(TimingError::Line { line, message }) => Error::usage(format!(
                    "{path}:{line}: {message}; move the file away to replay without timing"
                ))
                .into(),
            }
        }
    }
}
