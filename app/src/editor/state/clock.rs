//! The machine's clock as the app bar shows it (`crate::appbar::clock`).

/// The machine's clock as the app bar shows it: simulated time, scans,
/// the last scans' duration, and whether it runs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Clock {
    /// Simulated time, in ns.
    pub nanos: u64,
    /// Scans run since power-up.
    pub scans: u64,
    /// The scans since the last measurement took this long each
    /// (simulated µs, on average); `None` before the first.
    pub scan_us: Option<u64>,
    /// The machine runs its program (RUN, powered).
    pub running: bool,
    /// Where the scan's duration is next measured from: (ns, scans).
    since: (u64, u64),
}

/// A scan's duration is measured over at least this much simulated
/// time or [`MEASURE_SCANS`] scans: a frame alone runs a periodic task's
/// scans one or two at a time (a 10 ms task under 16.7 ms frames read
/// 16.7 ms and 8.35 ms in turn).
const MEASURE_NS: u64 = 1_000_000_000;
/// ... or at least this many scans (a fast machine's figure stays live).
const MEASURE_SCANS: u64 = 1_000;

impl Clock {
    /// Simulated time in whole ms (`data-ms`).
    pub fn ms(&self) -> u64 {
        self.nanos / 1_000_000
    }

    /// The clock after a frame that left the machine at `nanos` with
    /// `scans` scans, `running` or not: a scan's duration is the time
    /// since the last measurement over the scans run in it, once that is
    /// long enough (a reset starts afresh).
    pub fn next(self, nanos: u64, scans: u64, running: bool) -> Clock {
        let fresh = Clock {
            nanos,
            scans,
            scan_us: self.scan_us,
            running,
            since: (nanos, scans),
        };
        if scans < self.scans || nanos < self.nanos {
            return Clock {
                scan_us: None,
                ..fresh
            };
        }
        if self.scans == 0 {
            // When the first scans began is not known: measure from here.
            return fresh;
        }
        let (from_ns, from_scans) = self.since;
        let ran = scans - from_scans;
        let span = nanos - from_ns;
        if ran > 0 && (span >= MEASURE_NS || ran >= MEASURE_SCANS) {
            Clock {
                scan_us: Some(span / ran / 1_000),
                ..fresh
            }
        } else {
            Clock {
                since: self.since,
                ..fresh
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Clock;

    #[test]
    fn a_scan_lasts_the_frames_time_over_its_scans() {
        let c = Clock::default().next(10_000_000, 5, true);
        assert_eq!((c.ms(), c.scans, c.scan_us), (10, 5, None));
        // 160 ms, 1600 scans: 100 µs each.
        let c = c.next(170_000_000, 1605, true);
        assert_eq!(c.scan_us, Some(100));
        // A frame with no scan keeps the figure; stopped, time stands.
        let c = c.next(170_000_000, 1605, false);
        assert_eq!((c.scan_us, c.running, c.ms()), (Some(100), false, 170));
        // A power cycle (fewer scans) starts afresh.
        assert_eq!(c.next(180_000_000, 2, true).scan_us, None);
    }

    #[test]
    fn a_periodic_scan_reads_its_period_not_a_frames_share() {
        // A 10 ms task under 16.7 ms frames runs one scan, then two: each
        // frame alone says 16.7 ms or 8.35 ms, flickering.
        let mut c = Clock::default().next(0, 0, true);
        let (mut nanos, mut scans) = (0u64, 0u64);
        for frame in 0..200u64 {
            nanos += 16_700_000;
            scans = nanos / 10_000_000;
            c = c.next(nanos, scans, true);
            if frame > 70 {
                let us = c.scan_us.expect("measured");
                assert!((9_800..=10_200).contains(&us), "frame {frame}: {us} µs");
            }
        }
        assert!(scans > 100);
    }
}
