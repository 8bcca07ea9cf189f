//! A read repeated on a schedule, for hours: every interval a result, a read's failure
//! among them, and a connection that drops (a device rebooting, a USB adapter unplugged)
//! opened again, waiting longer each time up to 5 s, so that reads resume by themselves.
//! The schedule keeps to the interval from the start instead of drifting by each read's
//! time, and skips ahead rather than bursting after a long stall.

use std::time::{Duration, Instant};

use super::failover::{PathName, Switch};
use super::run::{PollStats, RunError};
use super::{Master, MasterError};

/// The longest wait between two attempts to connect again.
pub const MAX_BACKOFF: Duration = Duration::from_secs(5);

/// The first wait before connecting again.
const FIRST_BACKOFF: Duration = Duration::from_millis(100);

/// One poll's outcome.
#[derive(Debug)]
pub enum Tick<T> {
    /// The read's result.
    Read(T),
    /// The read failed: no answer, a bad frame, an exception, or the connection dropping.
    Failed(RunError),
    /// No connection: why an attempt to connect failed, or that the next is awaited.
    Disconnected(String),
    /// The master changed to its other path (before the outcome of the read that made it
    /// change, which was asked again there).
    Switched(Switch),
}

/// How long to poll.
#[derive(Clone, Copy, Debug)]
pub struct PollOptions {
    /// From the start of one read to the start of the next (0: back to back).
    pub interval: Duration,
    /// Stop after this many polls.
    pub count: Option<u64>,
}

/// When the next attempt to connect may be made, how long to wait after it, and why the
/// last one failed.
pub(crate) struct Backoff {
    pub(crate) next_attempt: Instant,
    wait: Duration,
    pub(crate) last_error: String,
}

impl Backoff {
    pub(crate) fn new() -> Self {
        Self {
            next_attempt: Instant::now(),
            wait: FIRST_BACKOFF,
            last_error: String::new(),
        }
    }

    pub(crate) fn failed(&mut self, error: String) {
        self.next_attempt = Instant::now() + self.wait;
        self.wait = (self.wait * 2).min(MAX_BACKOFF);
        self.last_error = error;
    }
}

/// Polls until `count` polls or until `wait` says stop. `connect` opens the master,
/// given the path last in use when it has two (so that a connection opened again
/// starts where the poll was, and a change is told only when it is one);
/// `read` makes one read; `tick` is told each poll's outcome; `wait` sleeps up to the time
/// given and returns true when polling should stop (Ctrl-C).
pub fn poll<T, E: std::fmt::Display>(
    mut connect: impl FnMut(Option<PathName>) -> Result<Master, E>,
    mut read: impl FnMut(&mut Master) -> Result<T, RunError>,
    options: PollOptions,
    mut wait: impl FnMut(Duration) -> bool,
    mut tick: impl FnMut(Tick<T>) -> std::io::Result<()>,
) -> std::io::Result<PollStats> {
    let mut master: Option<Master> = None;
    let mut stats = PollStats::default();
    let mut backoff = Backoff::new();
    let start = Instant::now();
    let mut polls = 0u64;
    let mut last_path = None;
    loop {
        if master.is_none() && Instant::now() >= backoff.next_attempt {
            match connect(last_path) {
                Ok(opened) => {
                    master = Some(opened);
                    backoff = Backoff::new();
                }
                Err(error) => {
                    backoff.failed(error.to_string());
                    stats.disconnected += 1;
                    tick(Tick::Disconnected(error.to_string()))?;
                }
            }
        } else if master.is_none() {
            stats.disconnected += 1;
            let left = backoff
                .next_attempt
                .saturating_duration_since(Instant::now());
            tick(Tick::Disconnected(format!(
                "not connected ({}); trying again in {} ms",
                backoff.last_error,
                left.as_millis().max(1)
            )))?;
        }
        if let Some(current) = master.as_mut() {
            let began = Instant::now();
            let outcome = read(current);
            for switch in current.take_switches() {
                stats.switches += 1;
                if let Some(left) = switch.left {
                    stats.record_left(left);
                }
                tick(Tick::Switched(switch))?;
            }
            last_path = current.path();
            stats.record(outcome.as_ref().map(|_| ()), began.elapsed());
            match outcome {
                Ok(result) => tick(Tick::Read(result))?,
                Err(error) => {
                    // A transport that failed is opened again from the next poll on.
                    if matches!(error, RunError::Master(MasterError::Io(_))) {
                        master = None;
                        backoff = Backoff::new();
                    }
                    tick(Tick::Failed(error))?;
                }
            }
        }
        polls += 1;
        if options.count.is_some_and(|count| polls >= count) {
            return Ok(stats);
        }
        // The next poll at start + n x interval; after a stall, the next one still ahead.
        let interval = options.interval;
        let next = if interval.is_zero() {
            // Back to back, but not while there is no connection to read from.
            match master {
                Some(_) => Instant::now(),
                None => backoff.next_attempt,
            }
        } else {
            let elapsed = start.elapsed().as_nanos() / interval.as_nanos();
            start + interval * u32::try_from(elapsed + 1).unwrap_or(u32::MAX)
        };
        if wait(next.saturating_duration_since(Instant::now())) {
            return Ok(stats);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn back_to_back_polls_wait_for_the_next_attempt_to_connect() {
        let mut waits = Vec::new();
        let mut ticks = 0;
        let stats = poll(
            |_| Err::<Master, _>("refused"),
            |_: &mut Master| Ok(()),
            PollOptions {
                interval: Duration::ZERO,
                count: Some(4),
            },
            |time| {
                waits.push(time);
                false
            },
            |tick| {
                assert!(matches!(tick, Tick::Disconnected(_)));
                ticks += 1;
                Ok(())
            },
        )
        .unwrap();
        assert_eq!((ticks, stats.disconnected), (4, 4));
        // Without a connection, even --poll 0 waits for the back-off instead of spinning.
        assert!(waits.iter().all(|w| *w > Duration::ZERO), "{waits:?}");
    }
}
