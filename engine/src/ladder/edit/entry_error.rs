//! Why the device entry's text gives no element (its own module: the
//! entry and its box forms both say so).

use std::fmt;

use crate::error::shown;
use crate::ladder::target::ElementError;

/// Why the entry's text does not give an element; nothing changed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum EntryError {
    /// Nothing typed.
    Empty,
    /// Words that name no instruction (the first word, as typed).
    UnknownWord(String),
    /// The instruction needs other operands (its usage).
    Usage(&'static str),
    /// A number that does not read (as typed).
    BadNumber(String),
    /// The machine lacks the element or the device.
    Element(ElementError),
}

impl fmt::Display for EntryError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            EntryError::Empty => f.write_str("type a device or an instruction"),
            EntryError::UnknownWord(w) => write!(
                f,
                "unknown instruction {}: try LD, LDI, LDP, LDF, OUT, SET, RST, PLS, PLF, MOV, CMP, INC, DEC, NOT, R_TRIG, F_TRIG, TON, TOF, TP",
                shown(w)
            ),
            EntryError::Usage(u) => write!(f, "write it as {u}"),
            EntryError::BadNumber(n) => write!(f, "{} is not a number", shown(n)),
            EntryError::Element(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for EntryError {}
