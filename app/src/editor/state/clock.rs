//! The machine's clock as the app bar shows it (`crate::appbar::clock`).

/// The machine's clock as the app bar shows it: simulated time, scans,
/// the last scans' duration, and whether it runs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Clock {
    /// Simulated time, in ns.
    pub nanos: u64,
    /// Scans run since power-up.
    pub scans: u64,
    /// The scans of the last frame that ran any took this long each
    /// (simulated µs, on average); `None` before it.
    pub scan_us: Option<u64>,
    /// The machine runs its program (RUN, powered).
    pub running: bool,
}

impl Clock {
    /// Simulated time in whole ms (`data-ms`).
    pub fn ms(&self) -> u64 {
        self.nanos / 1_000_000
    }

    /// The clock after a frame that left the machine at `nanos` with
    /// `scans` scans, `running` or not: a scan's duration is the frame's
    /// simulated time over the scans it ran (a reset starts afresh).
    pub fn next(self, nanos: u64, scans: u64, running: bool) -> Clock {
        let ran = scans.saturating_sub(self.scans);
        let scan_us = if scans < self.scans || nanos < self.nanos {
            None
        } else if ran > 0 && self.scans > 0 {
            Some((nanos - self.nanos) / ran / 1_000)
        } else {
            self.scan_us
        };
        Clock {
            nanos,
            scans,
            scan_us,
            running,
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
        // 16 ms, 160 scans: 100 µs each.
        let c = c.next(26_000_000, 165, true);
        assert_eq!(c.scan_us, Some(100));
        // A frame with no scan keeps the figure; stopped, time stands.
        let c = c.next(26_000_000, 165, false);
        assert_eq!((c.scan_us, c.running, c.ms()), (Some(100), false, 26));
        // A power cycle (fewer scans) starts afresh.
        assert_eq!(c.next(30_000_000, 2, true).scan_us, None);
    }
}
