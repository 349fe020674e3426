//! MINASEC-U's on-delay timers: an RC delay between the coil latch and the
//! read multiplexer (seed, タイマー).

use crate::time::SimTime;

/// The delay range of `T0` (RV1 with 1 µF): 0.1 s ..= 1.1 s.
pub const T0_RANGE: (SimTime, SimTime) = (SimTime::from_millis(100), SimTime::from_millis(1100));
/// The delay range of `T1` (RV2 with 10 µF): 1 s ..= 11 s.
pub const T1_RANGE: (SimTime, SimTime) = (SimTime::from_secs(1), SimTime::from_secs(11));

/// The delay range of timer `n` (0 or 1).
pub const fn delay_range(n: usize) -> (SimTime, SimTime) {
    if n == 0 {
        T0_RANGE
    } else {
        T1_RANGE
    }
}

/// One RC on-delay timer.
///
/// The output is 1 once the coil latch has been 1 continuously for the
/// delay, and 0 at once when the coil latch drops (the diode discharges the
/// capacitor). Time is simulated time, so the timer runs while the CPU clock
/// is halted, just as the capacitor keeps charging on the board.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RcTimer {
    coil: bool,
    since: SimTime,
    delay: SimTime,
}

impl RcTimer {
    /// A timer with its coil off and the given delay.
    pub const fn new(delay: SimTime) -> Self {
        RcTimer {
            coil: false,
            since: SimTime::ZERO,
            delay,
        }
    }

    /// The coil latch.
    pub const fn coil(&self) -> bool {
        self.coil
    }

    /// The potentiometer's delay.
    pub const fn delay(&self) -> SimTime {
        self.delay
    }

    /// Turns the potentiometer; the charge so far counts toward the new delay.
    pub fn set_delay(&mut self, delay: SimTime) {
        self.delay = delay;
    }

    /// Writes the coil latch at `now`; a 0→1 change starts the delay.
    pub fn set_coil(&mut self, on: bool, now: SimTime) {
        if on && !self.coil {
            self.since = now;
        }
        self.coil = on;
    }

    /// The delayed output at `now`.
    pub fn output(&self, now: SimTime) -> bool {
        self.coil && now.saturating_sub(self.since) >= self.delay
    }

    /// How long the coil has been on at `now`, capped at the delay (the
    /// timer's current value); zero when off.
    pub fn elapsed(&self, now: SimTime) -> SimTime {
        if self.coil {
            now.saturating_sub(self.since).min(self.delay)
        } else {
            SimTime::ZERO
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn on_delay_and_immediate_off() {
        let mut t = RcTimer::new(SimTime::from_millis(100));
        t.set_coil(true, SimTime::from_millis(10));
        assert!(!t.output(SimTime::from_nanos(109_999_999)));
        assert!(t.output(SimTime::from_millis(110)));
        // Writing 1 again does not restart the delay.
        t.set_coil(true, SimTime::from_millis(105));
        assert!(t.output(SimTime::from_millis(110)));
        t.set_coil(false, SimTime::from_millis(120));
        assert!(!t.output(SimTime::from_millis(120)));
        assert_eq!(t.elapsed(SimTime::from_millis(120)), SimTime::ZERO);
    }
}
