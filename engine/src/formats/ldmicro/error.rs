//! What can be wrong with an `.ld` file, each reported at its line
//! (`error: FILE:LINE: …`).

use std::fmt;

/// Why a line of an `.ld` file is refused.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum LdError {
    /// The file does not start with `LDmicro` (what it starts with).
    NotLdmicro(String),
    /// No `PROGRAM` line.
    NoProgram,
    /// A line between rungs that is not `RUNG` (the line).
    NotARung(String),
    /// A keyword LDmicro has no element for.
    UnknownElement(String),
    /// An element with arguments of the wrong number or form (the element,
    /// the forms it takes).
    Arguments {
        element: String,
        takes: &'static str,
    },
    /// A number that is none (the element, the text).
    BadNumber { element: String, text: String },
    /// A table whose entries are not as many as it says (the element,
    /// how many it says, how many there are).
    TableCount {
        element: String,
        says: usize,
        has: usize,
    },
    /// The file ends inside a rung, a series or a parallel group.
    Unclosed(&'static str),
    /// `PARALLEL` directly inside `PARALLEL` (LDmicro puts a `SERIES`
    /// between).
    ParallelInParallel,
    /// A group with nothing in it.
    Empty(&'static str),
    /// Groups nested deeper than [`crate::limits::MAX_NESTING`].
    TooDeep,
    /// More rungs than [`crate::limits::MAX_RUNGS`].
    TooManyRungs,
    /// A table longer than [`crate::limits::MAX_LD_TABLE`] (the element).
    TableTooLong(String),
    /// A line of a list that does not read (the list, the line).
    BadListLine { list: &'static str, text: String },
    /// An element that drives hardware Hashigo does not simulate (its
    /// keyword).
    Hardware(String),
    /// An element the soft PLC does not run yet (its keyword).
    NotYet(String),
    /// An element LDmicro itself runs only where a chip cannot be
    /// simulated scan by scan (the element, why).
    NoScanMeaning(String, &'static str),
    /// A formatted string LDmicro's compiler refuses (why).
    Format(crate::runtime::ldmicro::format::FormatError),
    /// A STRING whose text is no C format of its one variable (why).
    Printf(crate::runtime::ldmicro::printf::PrintfError),
    /// A timer whose delay is not a whole number of cycles above zero
    /// (the timer, its delay in µs, the cycle in µs, the adjust).
    TimerPeriod {
        name: String,
        delay: String,
        cycle: u64,
        adjust: i32,
    },
    /// A rung whose groups cannot be drawn as a ladder (why).
    Drawing(String),
    /// A `CYCLE=` the soft PLC cannot scan at (what follows `CYCLE=`,
    /// why).
    Cycle { text: String, why: &'static str },
    /// A name used as two things (the name as LDmicro wrote it, what it
    /// is here, what it is where first used).
    Role {
        name: String,
        here: String,
        there: String,
    },
    /// What the soft PLC refuses in a rung made of this line's elements
    /// (its message), where nothing above said it in LDmicro's terms.
    SoftPlc(String),
}

impl fmt::Display for LdError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use crate::limits::{MAX_LD_TABLE, MAX_NESTING, MAX_RUNGS};
        match self {
            LdError::NotLdmicro(first) => write!(
                f,
                "not an LDmicro file: it starts with {} where LDmicro writes LDmicro0.1 or LDmicro0.2",
                crate::shown(first)
            ),
            LdError::NoProgram => f.write_str("no PROGRAM line: the file has no rungs"),
            LdError::NotARung(text) => {
                write!(f, "{} here: a rung starts with RUNG", crate::shown(text))
            }
            LdError::UnknownElement(k) => write!(
                f,
                "unknown element {}: LDmicro has no element of that name (docs/ldmicro.md lists them)",
                crate::shown(k)
            ),
            LdError::Arguments { element, takes } => {
                write!(f, "{element} takes {takes}")
            }
            LdError::BadNumber { element, text } => {
                write!(f, "{element}: {} is not a number", crate::shown(text))
            }
            LdError::TableCount { element, says, has } => write!(
                f,
                "{element} says {says} entries but has {has}"
            ),
            LdError::Unclosed(what) => {
                write!(f, "the file ends inside this {what}: it needs its END")
            }
            LdError::ParallelInParallel => f.write_str(
                "PARALLEL directly inside PARALLEL: LDmicro puts each branch in a SERIES",
            ),
            LdError::Empty(what) => write!(f, "an empty {what}"),
            LdError::TooDeep => write!(
                f,
                "SERIES and PARALLEL nested more than {MAX_NESTING} deep (docs/limits.md)"
            ),
            LdError::TooManyRungs => {
                write!(f, "more than {MAX_RUNGS} rungs (docs/limits.md)")
            }
            LdError::TableTooLong(e) => write!(
                f,
                "{e} has more than {MAX_LD_TABLE} entries (docs/limits.md)"
            ),
            LdError::BadListLine { list, text } => {
                write!(f, "{list}: {} does not read", crate::shown(text))
            }
            LdError::Hardware(k) => write!(
                f,
                "{k} drives hardware Hashigo does not simulate (I²C, SPI, buses, steppers, pulse trains, sleep, delay loops, jumps): the file is not opened"
            ),
            LdError::NotYet(k) => write!(
                f,
                "{k} does not run on the soft PLC yet (docs/ldmicro.md lists what does)"
            ),
            LdError::NoScanMeaning(element, why) => {
                write!(f, "{element}: {why}: the file is not opened")
            }
            LdError::Format(e) => write!(f, "FORMATTED_STRING: {e}"),
            LdError::Printf(e) => write!(f, "STRING: {e}"),
            LdError::TimerPeriod {
                name,
                delay,
                cycle,
                adjust,
            } => write!(
                f,
                "timer {name}: {delay} µs with adjust {adjust} is no count of {cycle} µs cycles above zero"
            ),
            LdError::Drawing(why) => write!(f, "this rung cannot be drawn: {why}"),
            LdError::Role { .. } | LdError::SoftPlc(_) | LdError::Cycle { .. } => self.lowered(f),
        }
    }
}

impl LdError {
    /// The errors of a whole file's names and settings, and what the soft
    /// PLC refuses.
    fn lowered(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LdError::Role { name, here, there } => write!(
                f,
                "{} is {here} here, but {there}: one name cannot be both",
                crate::shown(name)
            ),
            LdError::SoftPlc(why) => write!(f, "the soft PLC cannot run this: {why}"),
            LdError::Cycle { text, why } => {
                write!(f, "CYCLE= holds {}: {why}", crate::shown(text))
            }
            // Only the three above come here.
            other => write!(f, "{other:?}"),
        }
    }
}

impl std::error::Error for LdError {}
