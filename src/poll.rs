//! Counting what a poll saw, for the summary at its end.

use std::time::Duration;

use crate::error::Error;
use mbtool_core::master::MasterError;
use mbtool_core::model::duration::show;

#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct PollStats {
    pub requests: u64,
    pub answers: u64,
    pub timeouts: u64,
    pub bad_frames: u64,
    pub exceptions: u64,
    pub other_errors: u64,
    fastest: Option<Duration>,
    slowest: Duration,
    total: Duration,
}

impl PollStats {
    /// Counts one read and how it ended; answered reads count toward the response times.
    pub fn record(&mut self, outcome: Result<(), &Error>, elapsed: Duration) {
        self.requests += 1;
        match outcome {
            Ok(()) => {
                self.answers += 1;
                self.fastest = Some(self.fastest.map_or(elapsed, |f| f.min(elapsed)));
                self.slowest = self.slowest.max(elapsed);
                self.total += elapsed;
            }
            Err(Error::Exception { .. }) => self.exceptions += 1,
            Err(Error::Master(MasterError::Timeout { .. })) => self.timeouts += 1,
            Err(Error::Master(MasterError::BadFrame { .. })) => self.bad_frames += 1,
            Err(_) => self.other_errors += 1,
        }
    }

    /// One line: the counts, then min / mean / max response time.
    pub fn summary(&self) -> String {
        let mut line = format!(
            "{} requests, {} answers, {} timeouts, {} bad frames, {} exceptions",
            self.requests, self.answers, self.timeouts, self.bad_frames, self.exceptions
        );
        if self.other_errors > 0 {
            line.push_str(&format!(", {} other errors", self.other_errors));
        }
        if let Some(fastest) = self.fastest {
            let mean = self.total / u32::try_from(self.answers.max(1)).unwrap_or(u32::MAX);
            line.push_str(&format!(
                "; response time min {} / mean {} / max {}",
                show(fastest),
                show(mean),
                show(self.slowest)
            ));
        }
        line
    }
}
