//! The typed parts of [`super::target::ElementError`] (issue #49): why a
//! machine lacks an element, what a device can be driven by, a latch's
//! kind. Kinds, not sentences, so the page can say them in its own
//! language; `Display` gives the command line's English.

use std::fmt;

use serde::{Deserialize, Serialize};

/// Why a machine lacks an element: the rest of the sentence
/// `{machine} has no {element}…`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum LackReason {
    /// Nothing more to say.
    Plain,
    /// The machine has no edge contacts.
    NoEdgeContacts,
    /// A block's inputs wired as networks are the soft PLC's.
    BoxInputsAreSoft,
    /// Functions and blocks on words are the soft PLC's.
    WordBoxesAreSoft,
    /// The Arduino sketch has no timers.
    ArduinoNoTimers,
    /// MINASEC-U's timers and counter are wired, set on its panel.
    MinasecPanelTimers,
    /// A timer is written as an in-line TON/TOF/TP box here.
    UseInlineTimer,
    /// The Arduino sketch has no timers or counters.
    ArduinoNoTimersOrCounters,
    /// The machine has no data registers.
    NoDataRegisters,
}

impl fmt::Display for LackReason {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            LackReason::Plain => "",
            LackReason::NoEdgeContacts => ": it has no edge contacts",
            LackReason::BoxInputsAreSoft => {
                ": a block's inputs wired as networks are the soft PLC's"
            }
            LackReason::WordBoxesAreSoft => ": functions and blocks on words are the soft PLC's",
            LackReason::ArduinoNoTimers => " (the Arduino sketch has no timers)",
            LackReason::MinasecPanelTimers => {
                ": drive T0/T1 or C0 with a coil; their delay and set value are panel settings"
            }
            LackReason::UseInlineTimer => ": use an in-line TON/TOF/TP box",
            LackReason::ArduinoNoTimersOrCounters => {
                " (the Arduino sketch has no timers or counters)"
            }
            LackReason::NoDataRegisters => ": it has no data registers",
        })
    }
}

/// What may drive a device an element cannot (IO86A's roles).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Drivable {
    /// A timer T00-T31.
    Timer,
    /// A counter C00-C07.
    Counter,
    /// A Y, M or S device (C only with set/reset).
    Output,
}

impl fmt::Display for Drivable {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Drivable::Timer => "a timer T00-T31",
            Drivable::Counter => "a counter C00-C07",
            Drivable::Output => "a Y, M or S device (C only with set/reset)",
        })
    }
}

/// A set or a reset coil.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Latch {
    Set,
    Reset,
}

impl fmt::Display for Latch {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Latch::Set => "set",
            Latch::Reset => "reset",
        })
    }
}
