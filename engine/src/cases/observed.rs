//! What a failed expectation saw, as a kind with its arguments (issue
//! #49): `hashigo test` says it in English ([`fmt::Display`]), the page's
//! Tests pane in its own language from the kind. Values are kept as the
//! watch shows them (`1`, `'abc'`): data, not words.

use std::fmt;

use crate::time::SimTime;

/// What was seen instead of what an expectation asked.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Observed {
    /// The device held `value` at `at`.
    Was {
        /// The device as written.
        device: String,
        /// Its value as watched.
        value: String,
        /// When.
        at: SimTime,
    },
    /// A text asked of a device that holds a number (the number).
    NumberNotText {
        /// The device.
        device: String,
        /// Its value.
        value: String,
    },
    /// A number asked of a device that holds a text (the text, quoted).
    TextNotNumber {
        /// The device.
        device: String,
        /// Its value.
        value: String,
    },
    /// An edge that did not come.
    NoEdge {
        /// The device.
        device: String,
        /// A fall was asked (else a rise).
        falling: bool,
        /// What it did instead.
        seen: EdgeSeen,
    },
}

/// What a device did in a window where an edge was asked.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum EdgeSeen {
    /// It kept its first value.
    Stayed(String),
    /// It went from one value to another, moving the other way first at
    /// the time given, when it did.
    Went {
        /// Its first value.
        first: String,
        /// Its last value.
        last: String,
        /// When it moved the opposite way.
        opposite: Option<SimTime>,
    },
}

impl fmt::Display for Observed {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Observed::Was { device, value, at } => write!(f, "{device} was {value} at {at}ms"),
            Observed::NumberNotText { device, value } => write!(
                f,
                "{device} is a number ({value}), not a text: compare it with a number"
            ),
            Observed::TextNotNumber { device, value } => write!(
                f,
                "{device} is a text ({value}): compare it with a text in quotes ('…')"
            ),
            Observed::NoEdge {
                device,
                falling,
                seen,
            } => {
                let verb = if *falling { "fall" } else { "rise" };
                write!(f, "{device} did not {verb} (")?;
                match seen {
                    EdgeSeen::Stayed(v) => write!(f, "it stayed {v}")?,
                    EdgeSeen::Went {
                        first,
                        last,
                        opposite: Some(t),
                    } => write!(
                        f,
                        "it went from {first} to {last}, {} at {t}ms",
                        if *falling { "rising" } else { "falling" }
                    )?,
                    EdgeSeen::Went { first, last, .. } => {
                        write!(f, "it went from {first} to {last}")?
                    }
                }
                f.write_str(")")
            }
        }
    }
}
