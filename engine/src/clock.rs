//! The periodic clock of the scan-based machines (IO86A and AVR scans,
//! Arduino steps): what time it is and when the machine acts next.

use crate::plc::SettingError;
use crate::time::SimTime;

/// Fires every `period`; the machine acts at each firing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PeriodicClock {
    now: SimTime,
    next: SimTime,
    period: SimTime,
}

impl PeriodicClock {
    /// A clock at time zero whose first firing is one period later.
    pub const fn new(period: SimTime) -> PeriodicClock {
        PeriodicClock {
            now: SimTime::ZERO,
            next: period,
            period,
        }
    }

    /// The simulated time.
    pub const fn now(&self) -> SimTime {
        self.now
    }

    /// The period.
    pub const fn period(&self) -> SimTime {
        self.period
    }

    /// When the clock fires for the `n`-th time from now (`n` ≥ 1).
    pub fn nth(&self, n: u64) -> Option<SimTime> {
        let rest = n.checked_sub(1)?.checked_mul(self.period.as_nanos())?;
        self.next().checked_add(SimTime::from_nanos(rest))
    }

    /// When the clock fires next.
    pub const fn next(&self) -> SimTime {
        self.next
    }

    /// Sets the period, which must be above zero and at most `max`; the
    /// next firing comes one new period after `from`. `what` names the
    /// period in the error (`scan period`). Nothing changes on error.
    pub fn set_period(
        &mut self,
        period: SimTime,
        from: SimTime,
        max: SimTime,
        what: &'static str,
    ) -> Result<(), SettingError> {
        if period == SimTime::ZERO || period > max {
            return Err(SettingError::PeriodOutOfRange { what, period, max });
        }
        self.period = period;
        self.next = from + period;
        Ok(())
    }

    /// Starts again: the next firing is one period from now.
    pub fn restart(&mut self) {
        self.next = self.now + self.period;
    }

    /// If the clock fires at or before `t`, moves the time to that firing
    /// and returns it.
    pub fn fire_until(&mut self, t: SimTime) -> Option<SimTime> {
        if self.next > t {
            return None;
        }
        self.now = self.next;
        self.next = self.now + self.period;
        Some(self.now)
    }

    /// Ends an advance at `t`: the time becomes `t` (it never goes back).
    pub fn settle(&mut self, t: SimTime) {
        self.now = self.now.max(t);
    }

    /// The last instant before `t`, for running everything strictly
    /// before it (time is whole nanoseconds).
    pub const fn just_before(t: SimTime) -> SimTime {
        t.saturating_sub(SimTime::from_nanos(1))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fires_every_period_and_never_goes_back() {
        let mut c = PeriodicClock::new(SimTime::from_millis(10));
        let fired: Vec<u64> = std::iter::from_fn(|| c.fire_until(SimTime::from_millis(35)))
            .map(|t| t.as_nanos() / 1_000_000)
            .collect();
        assert_eq!(fired, [10, 20, 30]);
        c.settle(SimTime::from_millis(35));
        assert_eq!(c.now(), SimTime::from_millis(35));
        c.settle(SimTime::from_millis(1));
        assert_eq!(c.now(), SimTime::from_millis(35));
        c.restart();
        assert_eq!(c.next(), SimTime::from_millis(45));
        let max = SimTime::from_secs(1);
        assert_eq!(
            c.set_period(
                SimTime::from_millis(5),
                SimTime::from_millis(30),
                max,
                "step"
            ),
            Ok(())
        );
        assert_eq!(c.next(), SimTime::from_millis(35));
        for bad in [SimTime::ZERO, SimTime::from_millis(1001)] {
            assert!(c.set_period(bad, SimTime::ZERO, max, "step").is_err());
        }
        assert_eq!(
            (c.period(), c.next()),
            (SimTime::from_millis(5), SimTime::from_millis(35)),
            "unchanged"
        );
        assert_eq!(PeriodicClock::just_before(SimTime::ZERO), SimTime::ZERO);
    }
}
