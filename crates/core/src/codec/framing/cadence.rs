//! The rhythm of a line's reads. A USB adapter hands bytes over when its latency timer runs
//! out, so while bytes flow its reads end on the timer's ticks, a whole number of periods
//! apart. A reader that takes bytes as they come (a UART, a pseudo-terminal, a capture
//! timed byte by byte) reads where the bytes end, at no period. A frame that comes whole
//! across a gap is an adapter's doing when its two reads are one period apart and the
//! line's other reads keep that period; otherwise the gap is the line's own (a device that
//! paused inside its frame).

use super::ADAPTER_GAP_MAX_US;

/// How many of the latest intervals between reads are kept.
const KEPT: usize = 16;

/// Fewer intervals than this tell no period: chance would too often line them up. More
/// would leave a capture's first frames across an adapter's ticks untold: an adapter must
/// show its period within a few reads.
const ENOUGH: usize = 3;

/// The least tolerance of a read's end around its tick, in microseconds: a USB host polls
/// every millisecond, and a busy host reads a little late.
const TOLERANCE_FLOOR_US: u64 = 500;

/// The intervals between the latest reads that brought bytes.
#[derive(Default)]
pub(super) struct ReadCadence {
    last_end: Option<u64>,
    intervals: [u64; KEPT],
    kept: usize,
    next: usize,
}

impl ReadCadence {
    /// A read that brought bytes ended at `end`. Intervals longer than an adapter's reads
    /// explain are quiet lines between exchanges: they tell nothing of a period.
    pub(super) fn record(&mut self, end: u64) {
        let Some(last) = self.last_end.replace(end) else {
            return;
        };
        let interval = end.saturating_sub(last);
        if interval > ADAPTER_GAP_MAX_US {
            return;
        }
        self.intervals[self.next] = interval;
        self.next = (self.next + 1) % KEPT;
        self.kept = (self.kept + 1).min(KEPT);
    }

    /// Whether the latest reads end on ticks `period` apart: three intervals in four, of
    /// enough of them, a whole number of periods give or take an eighth of one. An interval
    /// of reads at no period matches so by chance one time in four: all of three one time in
    /// 64, twelve of sixteen one time in 30,000.
    pub(super) fn keeps_period(&self, period: u64) -> bool {
        if self.kept < ENOUGH || period == 0 {
            return false;
        }
        let tolerance = (period / 8).max(TOLERANCE_FLOOR_US);
        let on_ticks = self.intervals[..self.kept]
            .iter()
            .filter(|interval| {
                let ticks = (**interval + period / 2) / period;
                ticks >= 1 && interval.abs_diff(ticks * period) <= tolerance
            })
            .count();
        on_ticks * 4 >= self.kept * 3
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cadence(ends: impl IntoIterator<Item = u64>) -> ReadCadence {
        let mut cadence = ReadCadence::default();
        for end in ends {
            cadence.record(end);
        }
        cadence
    }

    #[test]
    fn an_adapters_reads_keep_its_period_with_a_late_read_or_two() {
        // Ticks of 16 ms, some skipped (nothing came), two reads a millisecond late.
        let ends = [0, 16, 32, 64, 80, 113, 128, 176, 192, 209, 224].map(|ms| 5_000 + ms * 1000);
        let reads = cadence(ends);
        assert!(reads.keeps_period(16_000));
        assert!(reads.keeps_period(16_900));
        assert!(!reads.keeps_period(11_000));
    }

    #[test]
    fn reads_where_the_bytes_end_keep_no_period() {
        // A frame a read: requests and answers at the pace of a polling master.
        let ends = [
            0, 7_100, 52_000, 57_400, 101_000, 109_900, 150_000, 153_700, 199_000,
        ];
        let reads = cadence(ends.iter().flat_map(|t| [*t, *t + 4_300]));
        for period in [4_300, 5_000, 7_100, 9_000, 16_000] {
            assert!(!reads.keeps_period(period), "{period}");
        }
    }

    #[test]
    fn too_few_reads_tell_no_period() {
        let reads = cadence((0..3).map(|tick| tick * 16_000));
        assert!(!reads.keeps_period(16_000));
        let reads = cadence((0..4).map(|tick| tick * 16_000));
        assert!(reads.keeps_period(16_000));
    }

    #[test]
    fn quiet_lines_between_exchanges_are_no_interval() {
        // Exchanges a second apart, each in two reads 16 ms apart.
        let reads = cadence((0..2).flat_map(|second| [0, 16_000].map(|t| second * 1_000_000 + t)));
        assert!(!reads.keeps_period(16_000), "two intervals are too few");
        let reads = cadence((0..3).flat_map(|second| [0, 16_000].map(|t| second * 1_000_000 + t)));
        assert!(reads.keeps_period(16_000));
    }
}
