//! Expectations, one a line (docs/tests.md):
//!
//! - `DEV OP VALUE at TIME` with OP one of `= != >= <= > <`
//!   (`Y00 = 1 at 1s`, `C0.v >= 5 at 20s`);
//! - `DEV stays VALUE from T1 to T2`;
//! - `DEV rises within T1..T2`, `DEV falls within T1..T2`.

use std::fmt;

use crate::error::shown;
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
    const ALL: [(&'static str, Compare); 6] = [
        ("!=", Compare::Ne),
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

    fn symbol(self) -> &'static str {
        Compare::ALL
            .iter()
            .find(|(_, c)| *c == self)
            .map_or("=", |(s, _)| s)
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
        value: i64,
        /// When.
        time: SimTime,
    },
    /// `DEV stays VALUE from T1 to T2`: at every sample in the window.
    Stays {
        /// The device.
        device: String,
        /// Its value throughout.
        value: i64,
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
        }
    }
}

impl std::error::Error for ExpectError {}

impl Expectation {
    /// Reads one expectation line.
    pub fn parse(line: &str) -> Result<Expectation, ExpectError> {
        let words: Vec<&str> = line.split_whitespace().collect();
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
                    value: value(v)?,
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
                Ok(Expectation::At {
                    device: device.to_string(),
                    op,
                    value: value(v)?,
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
