//! The rhythm of a line's reads. A USB adapter hands bytes over when its latency timer runs
//! out, so while bytes flow its reads end on the timer's ticks: a whole number of periods
//! after one another, and after any earlier read of the same stretch of traffic, give or
//! take the host's lateness, which does not add up. A reader that takes bytes as they come
//! (a UART, a pseudo-terminal, a capture timed byte by byte) reads where the bytes end, at
//! no period: even where its intervals are alike (a polling master's), their differences
//! add up, and its reads drift off any grid. A frame that comes whole across a gap is an
//! adapter's doing when its two reads are one period apart and the line's latest reads
//! sit on that period's grid; otherwise the gap is the line's own (a device that paused
//! inside its frame).

use smallvec::SmallVec;

use super::ADAPTER_GAP_MAX_US;

/// How many of the latest reads are kept: enough for the lateness of alike intervals to
/// add up past any grid.
const KEPT: usize = 32;

/// Fewer reads placed on a grid than this tell no period: chance would too often line
/// them up. More would leave a capture's first frames across an adapter's ticks untold:
/// an adapter must show its period within a few reads.
const ENOUGH: usize = 3;

/// From this many reads placed on a grid, a few may stray from it (a busy host's late
/// read, an adapter's early delivery of a full buffer); fewer must all sit on it closely.
const SETTLED: usize = 16;

/// The least tolerance of a read's end around its tick, in microseconds: a USB host polls
/// every millisecond, and a busy host reads a little late.
const TOLERANCE_FLOOR_US: u64 = 500;

/// When the latest reads that brought bytes ended.
#[derive(Default)]
pub(super) struct ReadCadence {
    ends: [u64; KEPT],
    kept: usize,
    next: usize,
}

impl ReadCadence {
    /// A read that brought bytes ended at `end`.
    pub(super) fn record(&mut self, end: u64) {
        self.ends[self.next] = end;
        self.next = (self.next + 1) % KEPT;
        self.kept = (self.kept + 1).min(KEPT);
    }

    /// Where each kept read ended after the first read of its stretch of traffic (reads no
    /// further apart than an adapter's explain), oldest first, with the stretch it is in;
    /// the first read of each stretch is the origin, and not placed.
    fn placed(&self) -> impl Iterator<Item = (usize, u64)> + '_ {
        let oldest = (self.next + KEPT - self.kept) % KEPT;
        let ends = (0..self.kept).map(move |i| self.ends[(oldest + i) % KEPT]);
        let mut stretch = 0;
        let mut origin = None;
        let mut last = 0;
        ends.filter_map(move |end| {
            let offset = match origin {
                Some(origin) if end.saturating_sub(last) <= ADAPTER_GAP_MAX_US => {
                    Some((stretch, end.saturating_sub(origin)))
                }
                _ => {
                    stretch += 1;
                    origin = Some(end);
                    None
                }
            };
            last = end;
            offset
        })
    }

    /// Whether the latest reads sit on a grid of ticks about `period` apart (the period
    /// itself is fitted to them, as one interval tells it only to a host's lateness).
    /// Settled, three reads in four within a twelfth of a period of a tick; before that,
    /// every one of them within a thirty-second of one (half a millisecond at 16 ms). No
    /// two reads of a stretch on the same tick. Simulated, 5,000 tries each: reads whose
    /// intervals are alike but at no period (a polling master's, 20 ms give or take 5)
    /// pass one time in 70 with 4 placed, one in 170 with 16, and never with 8 or 31; an
    /// adapter whose host reads up to half a millisecond late passes about nine times in
    /// ten from the start, and one up to 2 ms late only once 16 reads are placed (three
    /// times in four, nearly always with 31).
    pub(super) fn keeps_period(&self, period: u64) -> bool {
        if period == 0 {
            return false;
        }
        // Each read's tick, counted from the read before it: a period told only to a host's
        // lateness would miscount the ticks of reads far from their stretch's origin.
        let mut previous = (0, 0, 0.0);
        let ticked: SmallVec<[(usize, u64, f64); KEPT]> = self
            .placed()
            .map(|(stretch, offset)| {
                let (last_stretch, last_offset, last_ticks) = previous;
                let (from, counted) = if stretch == last_stretch {
                    (last_offset, last_ticks)
                } else {
                    (0, 0.0)
                };
                let ticks = counted + (offset.saturating_sub(from) as f64 / period as f64).round();
                previous = (stretch, offset, ticks);
                (stretch, offset, ticks)
            })
            .collect();
        // Least squares through the origin: the period that puts the reads nearest their
        // ticks.
        let (moments, squares) = ticked
            .iter()
            .fold((0.0, 0.0), |(m, s), (_, offset, ticks)| {
                (m + *offset as f64 * ticks, s + ticks * ticks)
            });
        let placed = ticked.len();
        if placed < ENOUGH || squares == 0.0 {
            return false;
        }
        let fitted = moments / squares;
        let (share, needed) = if placed >= SETTLED {
            (12.0, (placed * 3).div_ceil(4))
        } else {
            (32.0, placed)
        };
        let tolerance = (fitted / share).max(TOLERANCE_FLOOR_US as f64);
        let mut last = (0, 0.0);
        let on_ticks = ticked
            .iter()
            .filter(|(stretch, offset, ticks)| {
                // No two reads of a stretch on one tick.
                let new_tick = *stretch != last.0 || *ticks > last.1;
                last = (*stretch, *ticks);
                *ticks >= 1.0 && new_tick && (*offset as f64 - ticks * fitted).abs() <= tolerance
            })
            .count();
        on_ticks >= needed
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
        let ticks = [
            0, 1, 2, 4, 5, 7, 8, 11, 12, 13, 14, 16, 17, 18, 20, 21, 22, 24, 25,
        ];
        let late = |tick: u64| if tick == 7 || tick == 13 { 1_000 } else { 0 };
        let ends = ticks.map(|tick| 5_000 + tick * 16_000 + late(tick));
        let reads = cadence(ends);
        assert!(reads.keeps_period(16_000));
        assert!(
            reads.keeps_period(16_900),
            "the period is fitted to the reads"
        );
        assert!(!reads.keeps_period(11_000));
        // Before the reads are many, each must sit on its tick closely.
        assert!(!cadence(ends[..10].iter().copied()).keeps_period(16_000));
        assert!(cadence(ends[..5].iter().copied()).keeps_period(16_000));
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
    fn a_few_reads_of_a_polling_line_do_not_line_up_with_a_devices_pause() {
        // A request, an answer whose last byte a device held back 20 ms, another answer,
        // read where the bytes end: intervals of 22.0, 20.6 and 41.7 ms, each near a
        // multiple of the pause's 20.6 ms, but not as closely as an adapter's ticks.
        let reads = cadence([2_634_543, 2_656_538, 2_677_111, 2_718_785]);
        assert!(!reads.keeps_period(20_573));
        // An adapter's first reads, 16 ms apart within 300 us.
        let reads = cadence([10_000, 26_120, 42_300, 74_050]);
        assert!(reads.keeps_period(16_100));
    }

    #[test]
    fn alike_intervals_at_no_period_drift_off_every_grid() {
        // A polling line whose every interval is 20 ms give or take 5 (a frame and a
        // turnaround each): each is near a multiple of a period about as long, but their
        // differences add up.
        let mut seed = 7u64;
        let mut end = 1_000_000;
        let ends: Vec<u64> = (0..KEPT)
            .map(|_| {
                seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
                end += 15_000 + (seed >> 33) % 10_000;
                end
            })
            .collect();
        let reads = cadence(ends.iter().copied());
        for period in [17_000, 19_000, 20_000, 21_000, 23_000] {
            assert!(!reads.keeps_period(period), "{period}");
        }
        // An adapter's ticks 20 ms apart, each read up to 1.5 ms late (not adding up): on
        // the grid.
        let ticks = ends
            .iter()
            .enumerate()
            .map(|(i, end)| 1_000_000 + 20_000 * (i as u64 + 1) + end % 1_500);
        assert!(cadence(ticks).keeps_period(20_500));
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
