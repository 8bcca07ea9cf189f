//! Where a poll's rows go beyond standard output: a server that may be down. Rows are kept
//! in a bounded buffer and sent in batches by a thread of their own, so that a sink that is
//! down never holds back the polling; what does not fit is counted and told.

pub mod influx;
pub mod metrics;
pub mod mqtt;

use std::collections::VecDeque;
use std::sync::{Arc, Condvar, Mutex};
use std::time::{Duration, Instant};

/// The rows waiting for a sink, and what became of the others.
struct Waiting<T> {
    rows: VecDeque<T>,
    /// Rows dropped, oldest first, when the buffer was full.
    dropped: u64,
    /// Set when no more rows will come: send what is left, then end.
    closing: bool,
    /// When it was closed: the last try of a sink counts from then.
    closed_at: Option<Instant>,
}

/// A bounded buffer of rows (lines, messages), shared by the poll that fills it and the
/// thread that sends its rows.
pub struct Buffer<T> {
    waiting: Arc<(Mutex<Waiting<T>>, Condvar)>,
    capacity: usize,
}

impl<T> Clone for Buffer<T> {
    fn clone(&self) -> Self {
        Self {
            waiting: Arc::clone(&self.waiting),
            capacity: self.capacity,
        }
    }
}

impl<T: Clone> Buffer<T> {
    pub fn new(capacity: usize) -> Self {
        let waiting = Waiting {
            rows: VecDeque::new(),
            dropped: 0,
            closing: false,
            closed_at: None,
        };
        Self {
            waiting: Arc::new((Mutex::new(waiting), Condvar::new())),
            capacity: capacity.max(1),
        }
    }

    /// Adds a row; when the buffer is full, the oldest row gives way and is counted.
    pub fn push(&self, row: T) {
        let (lock, ready) = &*self.waiting;
        let mut waiting = lock.lock().unwrap_or_else(|p| p.into_inner());
        if waiting.rows.len() >= self.capacity {
            waiting.rows.pop_front();
            waiting.dropped += 1;
        }
        waiting.rows.push_back(row);
        ready.notify_one();
    }

    /// No more rows: the sender sends what is left and ends.
    pub fn close(&self) {
        let (lock, ready) = &*self.waiting;
        let mut waiting = lock.lock().unwrap_or_else(|p| p.into_inner());
        waiting.closing = true;
        waiting.closed_at.get_or_insert_with(Instant::now);
        ready.notify_all();
    }

    /// Up to `most` of the oldest rows, waiting up to `within` for one to come; and whether
    /// the buffer is closing.
    fn oldest(&self, most: usize, within: Duration) -> (Vec<T>, bool) {
        let (lock, ready) = &*self.waiting;
        let mut waiting = lock.lock().unwrap_or_else(|p| p.into_inner());
        if waiting.rows.is_empty() && !waiting.closing {
            waiting = ready
                .wait_timeout(waiting, within)
                .map_or_else(|p| p.into_inner().0, |(w, _)| w);
        }
        let rows = waiting.rows.iter().take(most).cloned().collect();
        (rows, waiting.closing)
    }

    /// When the buffer was closed, if it was.
    fn closed_at(&self) -> Option<Instant> {
        let (lock, _) = &*self.waiting;
        lock.lock().unwrap_or_else(|p| p.into_inner()).closed_at
    }

    /// Waits up to `time`, or until the buffer is closing.
    fn rest(&self, time: Duration) {
        let (lock, ready) = &*self.waiting;
        let waiting = lock.lock().unwrap_or_else(|p| p.into_inner());
        if !waiting.closing {
            let _ = ready.wait_timeout_while(waiting, time, |w| !w.closing);
        }
    }

    /// The `count` oldest rows were sent.
    fn sent(&self, count: usize) {
        let (lock, _) = &*self.waiting;
        let mut waiting = lock.lock().unwrap_or_else(|p| p.into_inner());
        let count = count.min(waiting.rows.len());
        waiting.rows.drain(..count);
    }

    /// How many rows were dropped, and how many wait still.
    fn counts(&self) -> (u64, usize) {
        let (lock, _) = &*self.waiting;
        let waiting = lock.lock().unwrap_or_else(|p| p.into_inner());
        (waiting.dropped, waiting.rows.len())
    }
}

/// What a sink did, for the summary.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Delivered {
    /// Rows the server took.
    pub sent: u64,
    /// Rows dropped when the buffer was full.
    pub dropped: u64,
    /// Rows still waiting when the poll ended and the server could not take them.
    pub unsent: usize,
    /// Rows the server refused (a bad request), which are not sent again.
    pub refused: u64,
}

impl Delivered {
    /// `1200 rows written, 30 dropped while it was down (the buffer holds 1000 rows), 5 unsent`,
    /// of rows or of another `thing`.
    pub fn summary(&self, capacity: usize, thing: &str) -> String {
        let mut said = format!(
            "{} written",
            crate::output::plural(self.sent as usize, thing)
        );
        if self.dropped > 0 {
            said.push_str(&format!(
                ", {} dropped while it was down (the buffer holds {capacity} rows; --buffer sets it)",
                self.dropped
            ));
        }
        if self.refused > 0 {
            said.push_str(&format!(", {} refused by the server", self.refused));
        }
        if self.unsent > 0 {
            said.push_str(&format!(", {} unsent at the end", self.unsent));
        }
        said
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_full_buffer_drops_its_oldest_rows_and_counts_them() {
        let buffer = Buffer::new(3);
        for row in ["a", "b", "c", "d", "e"] {
            buffer.push(row.to_string());
        }
        let (rows, closing) = buffer.oldest(10, Duration::ZERO);
        assert_eq!(
            (rows, closing),
            (vec!["c".into(), "d".into(), "e".into()], false)
        );
        buffer.sent(2);
        assert_eq!(buffer.counts(), (2, 1));
        buffer.close();
        assert_eq!(
            buffer.oldest(10, Duration::ZERO),
            (vec!["e".to_string()], true)
        );
    }
}
