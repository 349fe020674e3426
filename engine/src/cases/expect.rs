//! Expectations, one a line (docs/tests.md):
//!
//! - `DEV OP VALUE at TIME` with OP one of `= != <> >= <= > <`
//!   (`Y00 = 1 at 1s`, `C0.v >= 5 at 20s`), VALUE a whole number or a
//!   text in single quotes with IEC's `$` escapes, compared with `=` and
//!   `<>` (`msg = 'n=0002;' at 40ms`);
//! - `DEV stays VALUE from T1 to T2`;
//! - `DEV rises within T1..T2`, `DEV falls within T1..T2`.

use std::fmt;

use crate::error::shown;
use crate::iec::literal::{parse_text, text_literal};
use crate::plc::Value;
use crate::time::{SimTime, TimeError};

/// A comparison.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Compare {
    /// `=`
    Eq,
    /// `!=`
    Ne,
    /// `>=`
    Ge,
    /// `<=`
    Le,
    /// `>`
    Gt,
    /// `<`
    Lt,
}

impl Compare {
    const ALL: [(&'static str, Compare); 7] = [
        ("!=", Compare::Ne),
        ("<>", Compare::Ne),
        (">=", Compare::Ge),
        ("<=", Compare::Le),
        ("=", Compare::Eq),
        (">", Compare::Gt),
        ("<", Compare::Lt),
    ];

    /// Whether `a OP b`.
    pub fn holds(self, a: i64, b: i64) -> bool {
        match self {
            Compare::Eq => a == b,
            Compare::Ne => a != b,
            Compare::Ge => a >= b,
            Compare::Le => a <= b,
            Compare::Gt => a > b,
            Compare::Lt => a < b,
        }
    }

    /// Whether a device's `value` OP `b`, compared as numbers whatever
    /// the value's kind (a bit is 0 or 1).
    pub fn holds_value(self, value: &crate::plc::Value, b: i64) -> bool {
        match value.partial_cmp(&b) {
            Some(order) => match self {
                Compare::Eq => order.is_eq(),
                Compare::Ne => order.is_ne(),
                Compare::Ge => order.is_ge(),
                Compare::Le => order.is_le(),
                Compare::Gt => order.is_gt(),
                Compare::Lt => order.is_lt(),
            },
            // Only NaN compares with nothing: it equals nothing.
            None => self == Compare::Ne,
        }
    }

    /// Whether a device's `value` OP `want`: a number as
    /// [`Compare::holds_value`], a text equal or not (a text is never
    /// equal to a number; [`Want::kind_of`] says which was met).
    pub fn holds_want(self, value: &Value, want: &Want) -> bool {
        match want {
            Want::Number(n) => self.holds_value(value, *n),
            Want::Text(t) => {
                let same = matches!(value, Value::Text(v) if v.as_str() == t);
                same != (self == Compare::Ne)
            }
        }
    }

    fn symbol(self) -> &'static str {
        Compare::ALL
            .iter()
            .find(|(_, c)| *c == self)
            .map_or("=", |(s, _)| s)
    }
}

/// The value an expectation compares with.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Want {
    /// A whole number (a bit is 0 or 1).
    Number(i64),
    /// A text (a STRING's value), written in single quotes.
    Text(String),
}

impl Want {
    /// What an expectation writes for a device holding `value` (a
    /// recorder's expectations): a text as a quoted literal, anything
    /// else as its whole number. Printed, it reads back as the same.
    pub fn of(value: &Value) -> Want {
        match value {
            Value::Text(t) => Want::Text(t.to_string()),
            other => Want::Number(other.as_i64()),
        }
    }

    /// Why `value` is of another kind than this (a number met where a
    /// text is wanted, or a text where a number is), said for `device`.
    pub fn kind_of(&self, device: &str, value: &Value) -> Option<super::Observed> {
        use super::Observed;
        match (self, value) {
            (Want::Text(_), Value::Text(_)) => None,
            (Want::Text(_), v) => Some(Observed::NumberNotText {
                device: device.to_string(),
                value: v.to_string(),
            }),
            (Want::Number(_), Value::Text(_)) => Some(Observed::TextNotNumber {
                device: device.to_string(),
                value: value.watched(),
            }),
            (Want::Number(_), _) => None,
        }
    }
}

impl fmt::Display for Want {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Want::Number(n) => write!(f, "{n}"),
            Want::Text(t) => f.write_str(&text_literal(t)),
        }
    }
}

/// What one expectation asks.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Expectation {
    /// `DEV OP VALUE at TIME`: after the last scan at or before TIME.
    At {
        /// The device.
        device: String,
        /// How to compare.
        op: Compare,
        /// With what.
        value: Want,
        /// When.
        time: SimTime,
    },
    /// `DEV stays VALUE from T1 to T2`: at every sample in the window.
    Stays {
        /// The device.
        device: String,
        /// Its value throughout.
        value: Want,
        /// From.
        from: SimTime,
        /// To (inclusive).
        to: SimTime,
    },
    /// `DEV rises|falls within T1..T2`: it goes from 0 to non-zero (or
    /// back) between two samples in the window.
    Edge {
        /// The device.
        device: String,
        /// Falls instead of rises.
        falling: bool,
        /// From.
        from: SimTime,
        /// To (inclusive).
        to: SimTime,
    },
}

/// Why an expectation line does not read.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ExpectError {
    /// Not one of the three forms (the line, shortened).
    Form(String),
    /// A value that is not an integer.
    Value(String),
    /// An integer past what a device holds (-2^63..2^63-1).
    OutOfRange(String),
    /// A time that does not parse.
    Time(TimeError),
    /// A window that ends before it starts.
    Window,
    /// A text that does not read: no closing quote, a bad `$` escape
    /// (the text, shortened).
    Text(String),
    /// A text compared by order (the comparison): texts take `=` and
    /// `<>`.
    TextOrder(&'static str),
}

impl fmt::Display for ExpectError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ExpectError::Form(line) => write!(
                f,
                "{line} is no expectation: write \"Y00 = 1 at 2s\", \"Y00 stays 0 from 1s to 2s\" or \"Y00 rises within 0s..3s\""
            ),
            ExpectError::Value(v) => write!(f, "{v} is not a whole number"),
            ExpectError::OutOfRange(v) => write!(
                f,
                "{v} is out of range: a value is a whole number from {} to {}",
                i64::MIN,
                i64::MAX
            ),
            ExpectError::Time(e) => e.fmt(f),
            ExpectError::Window => f.write_str("the window ends before it starts"),
            ExpectError::Text(t) => write!(
                f,
                "{t} is no text: write it in single quotes, $' for a quote, $$ for a dollar"
            ),
            ExpectError::TextOrder(op) => write!(
                f,
                "a text is compared with = or <>, not {op}"
            ),
        }
    }
}

impl std::error::Error for ExpectError {}

impl Expectation {
    /// Reads one expectation line.
    pub fn parse(line: &str) -> Result<Expectation, ExpectError> {
        let words = words(line)?;
        let form = || ExpectError::Form(shown(line.trim()));
        let time = |t: &str| SimTime::parse(t).map_err(ExpectError::Time);
        let value = |v: &str| {
            v.parse::<i64>().map_err(|e| match e.kind() {
                std::num::IntErrorKind::PosOverflow | std::num::IntErrorKind::NegOverflow => {
                    ExpectError::OutOfRange(shown(v))
                }
                _ => ExpectError::Value(shown(v)),
            })
        };
        let want = |v: &str| -> Result<Want, ExpectError> {
            if v.starts_with('\'') {
                parse_text(v)
                    .map(Want::Text)
                    .map_err(|_| ExpectError::Text(shown(v)))
            } else {
                value(v).map(Want::Number)
            }
        };
        let window = |from: SimTime, to: SimTime| {
            if to < from {
                Err(ExpectError::Window)
            } else {
                Ok((from, to))
            }
        };
        match words.as_slice() {
            [device, "stays", v, "from", t1, "to", t2] => {
                let (from, to) = window(time(t1)?, time(t2)?)?;
                Ok(Expectation::Stays {
                    device: device.to_string(),
                    value: want(v)?,
                    from,
                    to,
                })
            }
            [device, verb @ ("rises" | "falls"), "within", span] => {
                let (t1, t2) = span.split_once("..").ok_or_else(form)?;
                let (from, to) = window(time(t1)?, time(t2)?)?;
                Ok(Expectation::Edge {
                    device: device.to_string(),
                    falling: *verb == "falls",
                    from,
                    to,
                })
            }
            [device, op, v, "at", t] => {
                let op = Compare::ALL
                    .iter()
                    .find(|(s, _)| s == op)
                    .map(|(_, c)| *c)
                    .ok_or_else(form)?;
                let value = want(v)?;
                if matches!(value, Want::Text(_)) && !matches!(op, Compare::Eq | Compare::Ne) {
                    return Err(ExpectError::TextOrder(op.symbol()));
                }
                Ok(Expectation::At {
                    device: device.to_string(),
                    op,
                    value,
                    time: time(t)?,
                })
            }
            _ => Err(form()),
        }
    }

    /// The device it watches.
    pub fn device(&self) -> &str {
        match self {
            Expectation::At { device, .. }
            | Expectation::Stays { device, .. }
            | Expectation::Edge { device, .. } => device,
        }
    }

    /// The instants it needs sampled from (every sample in a window is
    /// looked at by the checker).
    pub fn span(&self) -> (SimTime, SimTime) {
        match self {
            Expectation::At { time, .. } => (*time, *time),
            Expectation::Stays { from, to, .. } | Expectation::Edge { from, to, .. } => {
                (*from, *to)
            }
        }
    }
}

/// A line's words: a text in single quotes is one word, its spaces and
/// escapes (`$'` a quote) kept; a text without its closing quote is an
/// error.
fn words(line: &str) -> Result<Vec<&str>, ExpectError> {
    let mut out = Vec::new();
    let mut rest = line.trim_start();
    while !rest.is_empty() {
        let end = if rest.starts_with('\'') {
            let mut chars = rest.char_indices().skip(1);
            let mut close = None;
            while let Some((i, c)) = chars.next() {
                match c {
                    '$' => {
                        chars.next();
                    }
                    '\'' => {
                        close = Some(i + 1);
                        break;
                    }
                    _ => {}
                }
            }
            close.ok_or_else(|| ExpectError::Text(shown(rest)))?
        } else {
            rest.find(char::is_whitespace).unwrap_or(rest.len())
        };
        out.push(&rest[..end]);
        rest = rest[end..].trim_start();
    }
    Ok(out)
}

impl fmt::Display for Expectation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let ms = |t: &SimTime| format!("{t}ms");
        match self {
            Expectation::At {
                device,
                op,
                value,
                time,
            } => write!(f, "{device} {} {value} at {}", op.symbol(), ms(time)),
            Expectation::Stays {
                device,
                value,
                from,
                to,
            } => write!(f, "{device} stays {value} from {} to {}", ms(from), ms(to)),
            Expectation::Edge {
                device,
                falling,
                from,
                to,
            } => write!(
                f,
                "{device} {} within {}..{}",
                if *falling { "falls" } else { "rises" },
                ms(from),
                ms(to)
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{Expectation, Want};
    use crate::plc::Value;

    #[test]
    fn a_value_written_as_an_expectation_reads_back_as_the_same() {
        let text = Value::Text(std::sync::Arc::new("it's 5$ (*)\r\n".into()));
        for value in [text, Value::Int(-3), Value::Bit(true)] {
            let line = format!("d = {} at 1s", Want::of(&value));
            let Ok(Expectation::At { value: want, .. }) = Expectation::parse(&line) else {
                panic!("{line} does not read");
            };
            assert_eq!(want, Want::of(&value), "{line}");
        }
    }
}
