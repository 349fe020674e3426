//! Simulated time. Nothing in the engine reads the wall clock: the caller
//! says how far to advance, and every event lands at an exact instant.

use std::fmt;
use std::ops::{Add, AddAssign, Sub};

use crate::limits::MAX_SIM_SECONDS;

/// The longest simulated time a run, a step or a setting may reach
/// ([`MAX_SIM_SECONDS`], docs/limits.md).
pub const MAX_SIM_TIME: SimTime = SimTime::from_secs(MAX_SIM_SECONDS);

/// An instant or a duration on the simulated clock, in whole nanoseconds.
///
/// Nanoseconds keep every machine's clock exact: MINASEC-U's FAST clock is
/// 33 µs a period, an IO86A scan 1 ms, an Arduino step 10 µs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct SimTime(pub u64);

impl SimTime {
    /// Time zero: power-on.
    pub const ZERO: SimTime = SimTime(0);
    /// The latest representable instant (about 584 years).
    pub const MAX: SimTime = SimTime(u64::MAX);

    /// `n` nanoseconds.
    pub const fn from_nanos(n: u64) -> Self {
        SimTime(n)
    }
    /// `n` microseconds.
    pub const fn from_micros(n: u64) -> Self {
        SimTime(n * 1_000)
    }
    /// `n` milliseconds.
    pub const fn from_millis(n: u64) -> Self {
        SimTime(n * 1_000_000)
    }
    /// `n` seconds.
    pub const fn from_secs(n: u64) -> Self {
        SimTime(n * 1_000_000_000)
    }
    /// Whole nanoseconds.
    pub const fn as_nanos(self) -> u64 {
        self.0
    }
    /// Seconds as a float, for display only.
    pub fn as_secs_f64(self) -> f64 {
        self.0 as f64 / 1e9
    }
    /// `self - other`, or zero if `other` is later.
    pub const fn saturating_sub(self, other: SimTime) -> SimTime {
        SimTime(self.0.saturating_sub(other.0))
    }
    /// `self + other`, or [`SimTime::MAX`] on overflow.
    pub const fn saturating_add(self, other: SimTime) -> SimTime {
        SimTime(self.0.saturating_add(other.0))
    }

    /// Parses `10us`, `250ms`, `1.5s`, `20s`, `100ns`, or a bare number of
    /// milliseconds (`500`, `2.5`). Fractions are exact to the nanosecond.
    /// Times past [`MAX_SIM_TIME`] are refused, so sums of
    /// parsed times cannot overflow the clock.
    pub fn parse(text: &str) -> Result<SimTime, TimeError> {
        let text = text.trim();
        let shown = crate::error::shown(text);
        if text.starts_with('-') {
            return Err(TimeError::Negative(shown));
        }
        let split = text
            .find(|c: char| !(c.is_ascii_digit() || c == '.'))
            .unwrap_or(text.len());
        let (number, unit) = text.split_at(split);
        let scale: u64 = match unit.trim() {
            "" | "ms" => 1_000_000,
            "s" => 1_000_000_000,
            "us" | "µs" => 1_000,
            "ns" => 1,
            u if u.starts_with(['e', 'E']) && !number.is_empty() => {
                return Err(TimeError::Exponent(shown))
            }
            _ => return Err(TimeError::BadUnit(shown)),
        };
        let time =
            parse_scaled(number, scale).ok_or_else(|| TimeError::BadNumber(shown.clone()))?;
        if time > MAX_SIM_TIME {
            return Err(TimeError::TooLong(shown));
        }
        Ok(time)
    }

    /// `self + other`, or `None` past [`MAX_SIM_TIME`].
    pub fn checked_add(self, other: SimTime) -> Option<SimTime> {
        self.0
            .checked_add(other.0)
            .map(SimTime)
            .filter(|&t| t <= MAX_SIM_TIME)
    }
}

/// Parses a non-negative decimal `number` and multiplies it by `scale`
/// exactly; `None` if it is malformed, has more precision than a nanosecond,
/// or overflows.
fn parse_scaled(number: &str, scale: u64) -> Option<SimTime> {
    let (whole, frac) = match number.split_once('.') {
        Some((w, f)) => (w, f),
        None => (number, ""),
    };
    if whole.is_empty() && frac.is_empty() {
        return None;
    }
    let digits_ok = |s: &str| s.bytes().all(|b| b.is_ascii_digit());
    if !digits_ok(whole) || !digits_ok(frac) {
        return None;
    }
    let whole: u64 = if whole.is_empty() {
        0
    } else {
        whole.parse().ok()?
    };
    let mut total = whole.checked_mul(scale)?;
    // Each fractional digit is worth scale / 10^k; it must come out whole.
    let mut unit = scale;
    for digit in frac.bytes() {
        let d = u64::from(digit - b'0');
        if !unit.is_multiple_of(10) {
            if d != 0 {
                return None; // finer than a nanosecond
            }
            continue;
        }
        unit /= 10;
        total = total.checked_add(d * unit)?;
    }
    Some(SimTime(total))
}

/// Why a time could not be parsed. Each holds the text as written
/// (shortened and escaped for messages).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TimeError {
    /// The number part is malformed, too precise or too large.
    BadNumber(String),
    /// The unit is not one of `ns`, `us`, `ms`, `s`.
    BadUnit(String),
    /// A minus sign: simulated time starts at 0 and runs forward.
    Negative(String),
    /// An exponent (`1e30`): times are plain decimals.
    Exponent(String),
    /// Past [`MAX_SIM_TIME`].
    TooLong(String),
}

impl fmt::Display for TimeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TimeError::BadNumber(t) => write!(
                f,
                "bad time {t}: expected a non-negative number such as 10us, 250ms, 1.5s or 20"
            ),
            TimeError::BadUnit(t) => {
                write!(f, "bad time {t}: the unit must be ns, us, ms or s")
            }
            TimeError::Negative(t) => write!(
                f,
                "bad time {t}: a time cannot be negative (simulated time starts at 0)"
            ),
            TimeError::Exponent(t) => write!(
                f,
                "bad time {t}: write a plain decimal such as 1.5s, not an exponent"
            ),
            TimeError::TooLong(t) => write!(
                f,
                "time {t} is past the simulated clock's limit of 10000000s (docs/limits.md)"
            ),
        }
    }
}

impl std::error::Error for TimeError {}

impl Add for SimTime {
    type Output = SimTime;
    fn add(self, rhs: SimTime) -> SimTime {
        SimTime(self.0 + rhs.0)
    }
}

impl AddAssign for SimTime {
    fn add_assign(&mut self, rhs: SimTime) {
        self.0 += rhs.0;
    }
}

impl Sub for SimTime {
    type Output = SimTime;
    fn sub(self, rhs: SimTime) -> SimTime {
        SimTime(self.0 - rhs.0)
    }
}

impl fmt::Display for SimTime {
    /// Milliseconds with up to six decimals, trailing zeros dropped: `8.448`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let ms = self.0 / 1_000_000;
        let rest = self.0 % 1_000_000;
        if rest == 0 {
            write!(f, "{ms}")
        } else {
            let frac = format!("{rest:06}");
            write!(f, "{ms}.{}", frac.trim_end_matches('0'))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_every_unit_exactly() {
        assert_eq!(SimTime::parse("10us"), Ok(SimTime::from_micros(10)));
        assert_eq!(SimTime::parse("250ms"), Ok(SimTime::from_millis(250)));
        assert_eq!(SimTime::parse("1.5s"), Ok(SimTime::from_millis(1500)));
        assert_eq!(SimTime::parse("20s"), Ok(SimTime::from_secs(20)));
        assert_eq!(SimTime::parse("500"), Ok(SimTime::from_millis(500)));
        assert_eq!(SimTime::parse("0.000001"), Ok(SimTime::from_nanos(1)));
        assert_eq!(SimTime::parse(".5s"), Ok(SimTime::from_millis(500)));
        assert_eq!(SimTime::parse("33ns"), Ok(SimTime::from_nanos(33)));
    }

    #[test]
    fn rejects_malformed_times() {
        for bad in [
            "",
            "s",
            "-1s",
            "1.2.3s",
            "1h",
            "1e3",
            "0.5ns",
            "99999999999999999999s",
        ] {
            assert!(SimTime::parse(bad).is_err(), "{bad:?} should be rejected");
        }
        assert!(matches!(SimTime::parse("3 m"), Err(TimeError::BadUnit(_))));
    }

    #[test]
    fn negative_exponent_and_huge_times_say_so() {
        assert!(matches!(SimTime::parse("-1"), Err(TimeError::Negative(_))));
        assert!(matches!(
            SimTime::parse("1e30"),
            Err(TimeError::Exponent(_))
        ));
        assert!(matches!(
            SimTime::parse("10000000000s"),
            Err(TimeError::TooLong(_))
        ));
        assert_eq!(SimTime::parse("10000000s"), Ok(MAX_SIM_TIME));
        let msg = SimTime::parse("-1").unwrap_err().to_string();
        assert!(msg.contains("negative"), "{msg}");
    }

    #[test]
    fn displays_as_milliseconds() {
        assert_eq!(SimTime::from_micros(8448).to_string(), "8.448");
        assert_eq!(SimTime::from_secs(2).to_string(), "2000");
        assert_eq!(SimTime::from_nanos(1).to_string(), "0.000001");
    }
}
