//! The faults of a file told at once: collected in the order found, at most [`MOST_TOLD`]
//! kept, and how many more there are, so that a file with three mistakes takes one run.

use std::fmt::Display;

/// How many faults of one file are told at once.
pub const MOST_TOLD: usize = 20;

/// The faults found in a file so far.
#[derive(Debug)]
pub struct Faults<E> {
    errors: Vec<E>,
    more: usize,
}

impl<E> Default for Faults<E> {
    fn default() -> Self {
        Self {
            errors: Vec::new(),
            more: 0,
        }
    }
}

impl<E> Faults<E> {
    /// One more fault; past [`MOST_TOLD`] only counted.
    pub fn add(&mut self, error: E) {
        if self.errors.len() < MOST_TOLD {
            self.errors.push(error);
        } else {
            self.more += 1;
        }
    }

    /// Whether none was found.
    pub fn is_empty(&self) -> bool {
        self.errors.is_empty()
    }

    /// Puts the faults kept in the order `key` gives (their lines, say).
    pub fn sort_by_key<K: Ord>(&mut self, key: impl FnMut(&E) -> K) {
        self.errors.sort_by_key(key);
    }

    /// `value` when no fault was found, the fault when there is one, or `several` of the
    /// faults kept and how many more.
    pub fn or<T>(mut self, value: T, several: impl FnOnce(Vec<E>, usize) -> E) -> Result<T, E> {
        match self.errors.len() {
            0 => Ok(value),
            1 if self.more == 0 => Err(self.errors.remove(0)),
            _ => Err(several(self.errors, self.more)),
        }
    }
}

/// Faults one a line, then how many more there are.
pub fn told<E: Display>(errors: &[E], more: usize) -> String {
    let mut text = errors
        .iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join("\n");
    if more > 0 {
        text.push_str(&format!("\n... and {more} more"));
    }
    text
}
