//! The front panel's controls and the command enum through which a front
//! end (the app, the CLI, a test) operates the machine.

use std::fmt;

use super::timer;
use crate::time::SimTime;

/// The FAST clock's period: f = 1/(2.2·R·C) with 15 kΩ and 1 nF is exactly
/// 33 µs (≈ 30.3 kHz); one scan is 256 periods ≈ 8.45 ms.
pub const FAST_PERIOD: SimTime = SimTime::from_micros(33);
/// The SLOW clock divides FAST by 32768 (74HC4060 + one 74HC74 stage):
/// ≈ 1.08 s a period, ≈ 0.92 Hz.
pub const SLOW_PERIOD: SimTime = SimTime::from_nanos(33_000 * 32_768);

/// The RUN-HALT-RESET switch.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Mode {
    /// The clock runs.
    Run,
    /// The clock is stopped; the CLOCK button gives one clock per press.
    Halt,
    /// Held in reset: PC, accumulator, latches and I/O images are cleared.
    Reset,
}

/// The clock's speed: the SLOW-FAST switch, or an oscillator the user chose.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ClockSpeed {
    /// ≈ 30.3 kHz.
    Fast,
    /// ≈ 0.92 Hz.
    Slow,
    /// Another period (the CLI's `clock=<Hz>`).
    Period(SimTime),
}

impl ClockSpeed {
    /// One clock period.
    pub const fn period(self) -> SimTime {
        match self {
            ClockSpeed::Fast => FAST_PERIOD,
            ClockSpeed::Slow => SLOW_PERIOD,
            ClockSpeed::Period(p) => p,
        }
    }

    /// Parses `fast`, `slow` or a frequency in Hz (`1000`, `2.5`).
    pub fn parse(text: &str) -> Result<ClockSpeed, SettingError> {
        match text.trim().to_ascii_lowercase().as_str() {
            "fast" => Ok(ClockSpeed::Fast),
            "slow" => Ok(ClockSpeed::Slow),
            hz => {
                let bad = || SettingError::BadClock(text.to_string());
                let value: f64 = hz.parse().map_err(|_| bad())?;
                if !value.is_finite() || !(MIN_HZ..=MAX_HZ).contains(&value) {
                    return Err(bad());
                }
                let period = (1e9 / value).round() as u64;
                Ok(ClockSpeed::Period(SimTime::from_nanos(period.max(2))))
            }
        }
    }
}

/// The slowest oscillator `clock=<Hz>` accepts.
pub const MIN_HZ: f64 = 0.001;
/// The fastest: a 2 ns period still gives each clock phase a nanosecond.
pub const MAX_HZ: f64 = 500e6;

/// Which on-delay timer a potentiometer sets.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TimerId {
    /// `T0`, set by RV1 (0.1 s .. 1.1 s).
    T0,
    /// `T1`, set by RV2 (1 s .. 11 s).
    T1,
}

impl TimerId {
    /// 0 for `T0`, 1 for `T1`.
    pub const fn index(self) -> usize {
        match self {
            TimerId::T0 => 0,
            TimerId::T1 => 1,
        }
    }

    /// The delays this timer's potentiometer can reach.
    pub const fn range(self) -> (SimTime, SimTime) {
        timer::delay_range(self.index())
    }
}

/// Everything a front end can do to the board, one variant per control.
///
/// Commands that carry a value are checked before anything changes, so a
/// rejected command leaves the machine as it was.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Command {
    /// Turns the 5 V supply on or off.
    Power(bool),
    /// Moves the RUN-HALT-RESET switch.
    SetMode(Mode),
    /// Moves the SLOW-FAST switch (or sets another oscillator).
    SetClock(ClockSpeed),
    /// Presses (`true`) or releases the CLOCK button.
    ClockButton(bool),
    /// Sets the input terminal `X0n` (n = 0..=7) on or off.
    SetInput(u8, bool),
    /// Sets all eight DIP switches (bit 7 = OP2 .. bit 0 = A0).
    SetDip(u8),
    /// Presses (`true`) or releases WRITE.
    WriteButton(bool),
    /// Presses (`true`) or releases CNTCLR.
    CountClearButton(bool),
    /// Turns a potentiometer to give this delay.
    SetDelay(TimerId, SimTime),
    /// Turns the counter's rotary switches (tens, ones), each 0..=9.
    SetCounterPreset(u8, u8),
}

impl std::fmt::Display for Command {
    /// Whose command it is, for a machine that has no such panel.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "MINASEC-U front panel ({self:?})")
    }
}

/// A setting or command value the board cannot take.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SettingError {
    /// A delay outside the potentiometer's range.
    DelayOutOfRange {
        /// Which timer.
        timer: TimerId,
        /// The delay asked for.
        delay: SimTime,
    },
    /// A rotary switch position above 9, or a set value above 99.
    PresetOutOfRange(u32),
    /// An input number above 7.
    NoSuchInput(u8),
    /// A clock that is not `fast`, `slow` or a frequency in range.
    BadClock(String),
}

impl fmt::Display for SettingError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SettingError::DelayOutOfRange { timer, delay } => {
                let (lo, hi) = timer.range();
                write!(
                    f,
                    "{timer:?} delay {}s is out of range: its potentiometer gives {}s..{}s",
                    delay.as_secs_f64(),
                    lo.as_secs_f64(),
                    hi.as_secs_f64()
                )
            }
            SettingError::PresetOutOfRange(v) => {
                write!(
                    f,
                    "counter set value {v} is out of range: 0..99 (two BCD digits)"
                )
            }
            SettingError::NoSuchInput(n) => write!(f, "input X{n:02} does not exist: X00..X07"),
            SettingError::BadClock(t) => write!(
                f,
                "bad clock {}: write fast, slow, or a frequency in Hz from {MIN_HZ} to {MAX_HZ}",
                crate::error::shown(t)
            ),
        }
    }
}

impl std::error::Error for SettingError {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clock_speeds() {
        assert_eq!(FAST_PERIOD.as_nanos() * 256, 8_448_000);
        assert_eq!(ClockSpeed::parse("FAST"), Ok(ClockSpeed::Fast));
        assert_eq!(ClockSpeed::parse("slow"), Ok(ClockSpeed::Slow));
        assert_eq!(
            ClockSpeed::parse("1000"),
            Ok(ClockSpeed::Period(SimTime::from_millis(1)))
        );
        for bad in ["0", "-5", "nan", "inf", "1e12", "quick", ""] {
            assert!(ClockSpeed::parse(bad).is_err(), "{bad}");
        }
    }
}
