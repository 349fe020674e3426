//! What a device holds, typed as the machine holds it: a bit, a signed or
//! unsigned word, a real, a text (the soft PLC's STRING). Every front end (the CLI's CSV, the page, ladder
//! tests, Why?) prints and compares values through this one type, so a
//! machine with word data (the soft PLC) needs no front end of its own.

use std::cmp::Ordering;
use std::fmt;
use std::sync::Arc;

/// A device's value.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// A bit: printed 0 or 1.
    Bit(bool),
    /// A signed word (INT, DINT, a timer's or counter's current value).
    Int(i64),
    /// An unsigned word (UINT, UDINT, ULINT, WORD): printed unsigned.
    Uint(u64),
    /// A real (REAL, LREAL): printed as a decimal.
    Real(f64),
    /// A text (the soft PLC's STRING): printed as it is. Shared with the
    /// machine's own value, so a read copies no characters.
    Text(Arc<String>),
}

impl Value {
    /// Whether it is on: a bit set, a number other than zero (a contact
    /// of a word conducts while it is non-zero).
    pub fn is_on(&self) -> bool {
        match self {
            Value::Bit(b) => *b,
            Value::Int(n) => *n != 0,
            Value::Uint(n) => *n != 0,
            Value::Real(x) => *x != 0.0,
            // Not a number: no contact conducts on it.
            Value::Text(_) => false,
        }
    }

    /// As a signed whole number: a bit 0 or 1, an unsigned word clamped to
    /// `i64::MAX`, a real truncated toward zero (clamped; NaN is 0).
    pub fn as_i64(&self) -> i64 {
        match self {
            Value::Bit(b) => i64::from(*b),
            Value::Int(n) => *n,
            Value::Uint(n) => i64::try_from(*n).unwrap_or(i64::MAX),
            // `as` saturates and maps NaN to 0: what a chart wants.
            Value::Real(x) => *x as i64,
            Value::Text(_) => 0,
        }
    }

    /// As a real number (a chart's axis).
    pub fn as_f64(&self) -> f64 {
        match self {
            Value::Bit(b) => f64::from(u8::from(*b)),
            Value::Int(n) => *n as f64,
            Value::Uint(n) => *n as f64,
            Value::Real(x) => *x,
            Value::Text(_) => 0.0,
        }
    }

    /// Numeric order of two values of any kinds (`None` with a NaN), or
    /// the order of two texts (`None` between a text and a number).
    pub fn compare(&self, other: &Value) -> Option<Ordering> {
        match (self, other) {
            (Value::Text(a), Value::Text(b)) => return Some(a.cmp(b)),
            (Value::Text(_), _) | (_, Value::Text(_)) => return None,
            _ => {}
        }
        match (self.whole(), other.whole()) {
            (Some(a), Some(b)) => Some(a.cmp(&b)),
            _ => self.as_f64().partial_cmp(&other.as_f64()),
        }
    }

    /// As a watch table shows it: a number as it prints, a text between
    /// single quotes (so that an empty one, or one of spaces, shows).
    pub fn watched(&self) -> String {
        match self {
            Value::Text(t) => format!("'{t}'"),
            other => other.to_string(),
        }
    }

    /// The value as an exact whole number, when it is one.
    fn whole(&self) -> Option<i128> {
        match self {
            Value::Bit(b) => Some(i128::from(*b)),
            Value::Int(n) => Some(i128::from(*n)),
            Value::Uint(n) => Some(i128::from(*n)),
            Value::Real(_) | Value::Text(_) => None,
        }
    }
}

impl PartialEq<i64> for Value {
    /// Numerically equal: `Bit(true) == 1`, `Real(2.0) == 2`.
    fn eq(&self, other: &i64) -> bool {
        self.compare(&Value::Int(*other)) == Some(Ordering::Equal)
    }
}

impl PartialOrd<i64> for Value {
    /// Numeric order (`Real(2.5) > 2`).
    fn partial_cmp(&self, other: &i64) -> Option<Ordering> {
        self.compare(&Value::Int(*other))
    }
}

impl From<bool> for Value {
    fn from(b: bool) -> Value {
        Value::Bit(b)
    }
}

impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Value::Bit(b) => write!(f, "{}", u8::from(*b)),
            Value::Int(n) => write!(f, "{n}"),
            Value::Uint(n) => write!(f, "{n}"),
            // Always with a decimal point (`2.0`): a REAL reads as one.
            Value::Real(x) if x.is_finite() && x.fract() == 0.0 => write!(f, "{x:.1}"),
            Value::Real(x) => write!(f, "{x}"),
            Value::Text(t) => f.write_str(t),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Value;
    use std::cmp::Ordering;

    #[test]
    fn values_print_and_compare_as_numbers_whatever_their_kind() {
        assert_eq!(Value::Bit(true).to_string(), "1");
        assert_eq!(Value::Int(-5).to_string(), "-5");
        assert_eq!(Value::Uint(u64::MAX).to_string(), "18446744073709551615");
        assert_eq!(Value::Real(1.5).to_string(), "1.5");
        assert_eq!(Value::Bit(true), 1);
        assert_eq!(Value::Real(2.0), 2);
        assert_ne!(Value::Uint(u64::MAX), -1);
        assert_eq!(
            Value::Uint(u64::MAX).compare(&Value::Int(i64::MAX)),
            Some(Ordering::Greater)
        );
        assert_eq!(Value::Real(f64::NAN).compare(&Value::Int(0)), None);
        assert_eq!(Value::Uint(u64::MAX).as_i64(), i64::MAX);
        assert!(!Value::Real(0.0).is_on() && Value::Int(-1).is_on());
    }

    #[test]
    fn texts_print_as_they_are_compare_as_texts_and_show_quoted() {
        let text = |t: &str| Value::Text(std::sync::Arc::new(t.to_string()));
        let hi = text("hi");
        assert_eq!(hi.to_string(), "hi");
        assert_eq!(hi.watched(), "'hi'");
        assert_eq!(text("").watched(), "''");
        assert_eq!(Value::Int(5).watched(), "5");
        assert_eq!(hi.compare(&text("ha")), Some(Ordering::Greater));
        assert_eq!(hi.compare(&Value::Int(0)), None, "a text is no number");
        assert!(!hi.is_on());
        assert_ne!(hi, 0);
    }
}
