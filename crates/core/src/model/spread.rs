//! How long things took, in a few numbers: the quickest, the mean, the 95th percentile and
//! the slowest, for the summaries of `sniff --stats` and `gateway`.

use serde::Serialize;

/// The spread of a set of times, in microseconds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Spread {
    /// The quickest.
    pub min: u64,
    /// The mean, rounded up.
    pub mean: u64,
    /// 95 of 100 took this long or less.
    pub p95: u64,
    /// The slowest.
    pub max: u64,
}

impl Spread {
    /// The spread of `times` (sorted here), `None` when there are none.
    pub fn of(times: &mut [u64]) -> Option<Spread> {
        times.sort_unstable();
        let (min, max) = (*times.first()?, *times.last()?);
        let count = times.len() as u64;
        let mean = times.iter().sum::<u64>().div_ceil(count);
        Some(Spread {
            min,
            mean,
            p95: nearest_rank_p95(times),
            max,
        })
    }
}

/// The smallest of `sorted` that 95 % of them do not exceed (nearest rank).
pub(crate) fn nearest_rank_p95(sorted: &[u64]) -> u64 {
    let rank = (sorted.len() * 95).div_ceil(100).max(1);
    sorted.get(rank - 1).copied().unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn p95_is_the_nearest_rank() {
        let mut times: Vec<u64> = (1..=100).rev().collect();
        let spread = Spread::of(&mut times).unwrap();
        assert_eq!(
            (spread.min, spread.mean, spread.p95, spread.max),
            (1, 51, 95, 100)
        );
        assert_eq!(Spread::of(&mut [7]).map(|s| s.p95), Some(7));
        assert_eq!(Spread::of(&mut []), None);
    }
}
