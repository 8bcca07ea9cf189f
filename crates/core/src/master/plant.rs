//! The devices on one port of a plant, kept read: each at its own rate, in turn, on the one
//! connection the port has (a serial line, an RTU server, a TCP device). A device that
//! keeps failing is asked less often, so that its timeouts take less of the line from the
//! others; a connection that drops is opened again with the poll's back-off; a poll that
//! reads nothing is told as such, never as the last values again.

use std::time::{Duration, Instant};

use super::map::{read_points, MapRead, Refused};
use super::poll::Backoff;
use super::run::RunError;
use super::{Master, MasterError};
use crate::codec::Request;
use crate::model::map::Point;

/// After this many failed polls in a row a device rests between its polls.
const FAILURES_BEFORE_REST: u32 = 3;

/// The longest rest of a failing device, unless its own rate is slower.
const LONGEST_REST: Duration = Duration::from_secs(60);

/// A device on the port, and its schedule.
#[derive(Clone, Debug)]
pub struct Scheduled {
    /// Its slave address or unit id.
    pub slave: u8,
    /// Its points, read as `read --map` groups them.
    pub points: Vec<Point>,
    /// How often it is read.
    pub every: Duration,
}

/// What a poll of one device gave.
#[derive(Debug)]
pub enum Outcome {
    /// Its points, each with a value or why it has none.
    Read(MapRead),
    /// Nothing read: no answer, a bad frame, the connection dropping.
    Failed(RunError),
    /// No connection to ask on, and why.
    Down(String),
}

/// One poll of one device.
#[derive(Debug)]
pub struct Polled {
    /// The device, as its index among those given.
    pub device: usize,
    /// What the poll gave.
    pub outcome: Outcome,
    /// How long it took.
    pub took: Duration,
}

/// What a port's worker is told when it wakes.
#[derive(Debug)]
pub enum Wake {
    /// Polling ends.
    Stop,
    /// The time given has passed: the next poll is due.
    Due,
    /// A write to send before the next poll.
    Write {
        /// The device's index among those polled.
        device: usize,
        /// The write.
        request: Request,
    },
}

/// What the worker of one port needs from its caller.
pub trait Port {
    /// Why the port could not be opened.
    type Refusal: std::fmt::Display;
    /// Opens the port's master.
    fn connect(&mut self) -> Result<Master, Self::Refusal>;
    /// Waits up to `time`, or until there is something else to do.
    fn wait(&mut self, time: Duration) -> Wake;
    /// Each poll, as it is done.
    fn polled(&mut self, polled: Polled);
    /// Each write asked by [`Wake::Write`], done or not.
    fn wrote(&mut self, device: usize, request: &Request, outcome: Result<(), String>);
}

/// Polls `devices` on `port` until it says stop, at most `max` registers or coils a
/// request where given; writes it hands over are sent between polls.
pub fn keep_read<P: Port>(port: &mut P, devices: &[Scheduled], max: Option<u16>) {
    if devices.is_empty() {
        return;
    }
    let points: Vec<Vec<&Point>> = devices.iter().map(|d| d.points.iter().collect()).collect();
    let start = Instant::now();
    let mut due = vec![start; devices.len()];
    let mut failures = vec![0u32; devices.len()];
    let mut master: Option<Master> = None;
    let mut backoff = Backoff::new();
    loop {
        let (device, when) = due
            .iter()
            .enumerate()
            .min_by_key(|(_, when)| **when)
            .map(|(device, when)| (device, *when))
            .unwrap_or((0, start));
        match port.wait(when.saturating_duration_since(Instant::now())) {
            Wake::Stop => return,
            Wake::Due => {}
            Wake::Write { device, request } => {
                let outcome = match devices.get(device) {
                    None => Err(format!("no device {device} on this port")),
                    Some(asked) => {
                        open(port, &mut master, &mut backoff);
                        match master.as_mut().map(|m| m.answer(asked.slave, &request)) {
                            None => Err(format!("not connected: {}", backoff.last_error)),
                            Some(Ok(_)) => Ok(()),
                            Some(Err(error)) => {
                                dropped_on(&error, &mut master, &mut backoff);
                                Err(error.to_string())
                            }
                        }
                    }
                };
                port.wrote(device, &request, outcome);
                continue;
            }
        }
        let began = Instant::now();
        open(port, &mut master, &mut backoff);
        let outcome = match master.as_mut() {
            None => Outcome::Down(backoff.last_error.clone()),
            Some(current) => {
                let asked = &devices[device];
                match read_points(
                    current,
                    &points[device],
                    asked.slave,
                    max,
                    Refused::ErrorAndAway,
                ) {
                    Ok(read) => Outcome::Read(read),
                    // Polling ends (see `Master::stop_on`): a poll cut short is no poll.
                    Err(RunError::Master(MasterError::Interrupted)) => return,
                    Err(error) => {
                        dropped_on(&error, &mut master, &mut backoff);
                        Outcome::Failed(error)
                    }
                }
            }
        };
        // A device that gave any value, or said it lacks a point, is there.
        let answered = match &outcome {
            Outcome::Read(read) => {
                !read.values.is_empty() || !read.missing.is_empty() || read.failed.is_empty()
            }
            Outcome::Failed(_) | Outcome::Down(_) => false,
        };
        failures[device] = if answered { 0 } else { failures[device] + 1 };
        port.polled(Polled {
            device,
            outcome,
            took: began.elapsed(),
        });
        due[device] = next_due(
            due[device],
            devices[device].every,
            failures[device],
            Instant::now(),
        );
    }
}

/// A transport that failed is opened again before the next request.
fn dropped_on(error: &RunError, master: &mut Option<Master>, backoff: &mut Backoff) {
    if matches!(error, RunError::Master(MasterError::Io(_))) {
        *master = None;
        *backoff = Backoff::new();
    }
}

/// Opens the port's master where it is closed and its back-off allows.
fn open<P: Port>(port: &mut P, master: &mut Option<Master>, backoff: &mut Backoff) {
    if master.is_none() && Instant::now() >= backoff.next_attempt {
        match port.connect() {
            Ok(opened) => {
                *master = Some(opened);
                *backoff = Backoff::new();
            }
            Err(error) => backoff.failed(error.to_string()),
        }
    }
}

/// When a device polled at `due` is next polled: its next slot after `now` on its own
/// rate (a slot missed while the line was busy is skipped, not made up in a burst), or,
/// after failures in a row, a rest that doubles with each.
fn next_due(due: Instant, every: Duration, failures: u32, now: Instant) -> Instant {
    if failures >= FAILURES_BEFORE_REST {
        let doublings = (failures - FAILURES_BEFORE_REST + 1).min(16);
        let rest = every
            .saturating_mul(1 << doublings)
            .min(LONGEST_REST.max(every));
        return now + rest;
    }
    let mut next = due + every;
    if next <= now {
        let behind = now.duration_since(next).as_nanos() / every.as_nanos().max(1);
        next += every.saturating_mul(u32::try_from(behind + 1).unwrap_or(u32::MAX));
    }
    next
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_device_keeps_its_rate_and_skips_the_slots_it_missed() {
        let start = Instant::now();
        let every = Duration::from_millis(100);
        // On time: the next slot.
        assert_eq!(
            next_due(start, every, 0, start + Duration::from_millis(10)),
            start + every
        );
        // 350 ms late: the slot after now, at 400 ms.
        let next = next_due(start, every, 0, start + Duration::from_millis(350));
        assert_eq!(next, start + Duration::from_millis(400));
    }

    #[test]
    fn a_failing_device_rests_longer_with_each_failure_up_to_a_minute() {
        let now = Instant::now();
        let every = Duration::from_secs(1);
        assert_eq!(next_due(now, every, 2, now), now + every);
        assert_eq!(next_due(now, every, 3, now), now + Duration::from_secs(2));
        assert_eq!(next_due(now, every, 4, now), now + Duration::from_secs(4));
        assert_eq!(next_due(now, every, 40, now), now + Duration::from_secs(60));
        // A device read every 5 min rests no less than its own rate.
        let slow = Duration::from_secs(300);
        assert_eq!(next_due(now, slow, 40, now), now + slow);
    }

    #[test]
    fn a_port_that_never_opens_reports_every_device_down_and_ends_when_told() {
        let devices = vec![
            Scheduled {
                slave: 1,
                points: Vec::new(),
                every: Duration::from_millis(10),
            };
            2
        ];
        struct Refusing {
            waits: u32,
            polled: Vec<Polled>,
        }
        impl Port for Refusing {
            type Refusal = &'static str;
            fn connect(&mut self) -> Result<Master, &'static str> {
                Err("refused")
            }
            fn wait(&mut self, _: Duration) -> Wake {
                self.waits += 1;
                match self.waits > 6 {
                    true => Wake::Stop,
                    false => Wake::Due,
                }
            }
            fn polled(&mut self, polled: Polled) {
                self.polled.push(polled);
            }
            fn wrote(&mut self, _: usize, _: &Request, _: Result<(), String>) {}
        }
        let mut port = Refusing {
            waits: 0,
            polled: Vec::new(),
        };
        keep_read(&mut port, &devices, None);
        let polled = port.polled;
        assert_eq!(polled.len(), 6);
        assert!(polled
            .iter()
            .all(|p| matches!(&p.outcome, Outcome::Down(why) if why == "refused")));
        assert!(polled.iter().any(|p| p.device == 0) && polled.iter().any(|p| p.device == 1));
    }
}
