//! `--stats`: what a capture says of each server and unit: requests, answers, exceptions
//! by code, requests left unanswered, and how long answers took.

use std::collections::BTreeMap;
use std::net::SocketAddr;

use serde::Serialize;

use super::session::Record;
use crate::describe::Kind;
use crate::model::spread::Spread;

/// Who answered: a server's address in a TCP capture (`None` on a serial line), and the
/// unit id or slave address.
pub type Station = (Option<SocketAddr>, u8);

/// What was seen of one station.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Tally {
    /// Valid requests.
    pub requests: u64,
    /// Valid answers, exceptions included.
    pub answers: u64,
    /// Exception answers, by exception code.
    pub exceptions: BTreeMap<u8, u64>,
    /// Requests no answer followed.
    pub unanswered: u64,
    /// The response time of every answer paired with its request, in microseconds.
    times: Vec<u64>,
    /// By function: answers timed and their total time.
    functions: BTreeMap<u8, (u64, u64)>,
}

/// How long answers took, in microseconds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Times {
    /// The quickest, mean, 95th percentile and slowest.
    #[serde(flatten)]
    pub spread: Spread,
    /// The function whose answers took longest on average.
    pub slowest_function: u8,
}

impl Tally {
    /// The response times, when any answer was paired.
    pub fn times(&self) -> Option<Times> {
        let spread = Spread::of(&mut self.times.clone())?;
        let slowest_function = self
            .functions
            .iter()
            .max_by(|(_, (n1, t1)), (_, (n2, t2))| (t1 * n2).cmp(&(t2 * n1)))
            .map_or(0, |(function, _)| *function);
        Some(Times {
            spread,
            slowest_function,
        })
    }
}

/// The tallies of every station, in address order.
#[derive(Clone, Debug, Default)]
pub struct Stats {
    /// Each station's tally.
    pub stations: BTreeMap<Station, Tally>,
}

impl Stats {
    /// Takes a record into the tallies.
    pub fn record(&mut self, record: &Record) {
        match record {
            Record::Frame(frame) if frame.report().valid => {
                let station = (frame.tcp.map(|place| place.server), frame.report().slave);
                let tally = self.stations.entry(station).or_default();
                match frame.report().kind {
                    Kind::Request => tally.requests += 1,
                    Kind::Response | Kind::Exception => {
                        tally.answers += 1;
                        if let Some(code) = frame.report().fields.exception {
                            *tally.exceptions.entry(code).or_default() += 1;
                        }
                    }
                }
                if let Some(time) = frame.tcp.and_then(|place| place.response_time) {
                    tally.times.push(time);
                    let function = tally
                        .functions
                        .entry(frame.report().function & 0x7F)
                        .or_default();
                    *function = (function.0 + 1, function.1 + time);
                }
            }
            Record::Unanswered { slave, tcp, .. } => {
                let station = (tcp.map(|(place, _)| place.server), *slave);
                self.stations.entry(station).or_default().unanswered += 1;
            }
            _ => {}
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn p95_is_the_nearest_rank() {
        let mut tally = Tally::default();
        for (time, function) in (1..=100).map(|t| (t, if t > 90 { 16 } else { 3 })) {
            tally.times.push(time);
            let entry = tally.functions.entry(function).or_default();
            *entry = (entry.0 + 1, entry.1 + time);
        }
        let times = tally.times().unwrap();
        assert_eq!(
            (times.spread.min, times.spread.p95, times.spread.max),
            (1, 95, 100)
        );
        assert_eq!(times.spread.mean, 51);
        assert_eq!(times.slowest_function, 16);
        assert_eq!(Tally::default().times(), None);
    }
}
