//! What a ladder cell can hold: contacts, in-line boxes and outputs.

use std::fmt;

use serde::{Deserialize, Serialize};

/// How a contact reads its device.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum ContactKind {
    /// Normally open: passes power while the device is on.
    No,
    /// Normally closed: passes power while the device is off.
    Nc,
    /// Passes power for one scan after the device turns on.
    Rising,
    /// Passes power for one scan after the device turns off.
    Falling,
}

/// How a coil drives its device.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum CoilKind {
    /// The device follows the power.
    Normal,
    /// The device follows the inverted power.
    Inverted,
    /// Power turns the device on; it stays on.
    Set,
    /// Power turns the device off; it stays off.
    Reset,
}

/// The IEC timer kinds, as in-line boxes (power in = IN, power out = Q).
pub use crate::scan_timer::TimerKind;

/// One element of a ladder: what a non-empty cell holds.
///
/// Contacts and the in-line boxes (`Not`, `Edge`, `Timer`) pass power from
/// left to right; the others are outputs and stand at the rung's right end.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "lowercase")]
pub enum Element {
    /// A horizontal wire.
    Wire,
    /// A contact on a bit device.
    Contact {
        /// NO, NC, rising or falling.
        kind: ContactKind,
        /// The device, by the machine's own name (`X00`, `R4.2`).
        device: String,
    },
    /// Inverts the power flow.
    Not,
    /// Passes one scan of power when the power flow rises (or falls):
    /// R_TRIG / F_TRIG, the AVR PLC's `Pulse_A` / `Pulse_B`.
    Edge {
        /// Falling instead of rising.
        falling: bool,
    },
    /// An in-line timer (the AVR PLC's TON / TOF / TP).
    Timer {
        /// TON, TOF or TP.
        kind: TimerKind,
        /// Its name (a label for its RAM word).
        name: String,
        /// The set time in milliseconds.
        preset_ms: u32,
    },
    /// A coil.
    Coil {
        /// Normal, inverted, set or reset.
        kind: CoilKind,
        /// The device driven.
        device: String,
    },
    /// PLS / PLF: the device is on for one scan after the power rises / falls.
    Pulse {
        /// PLF instead of PLS.
        falling: bool,
        /// The device driven.
        device: String,
    },
    /// A timer coil with its set value (`OUT T00 K19`).
    TimerCoil {
        /// The timer.
        device: String,
        /// The set value in the timer's units.
        preset: u16,
    },
    /// A counter coil with its set value (`OUT C00 K10`).
    CounterCoil {
        /// The counter.
        device: String,
        /// The set value.
        preset: u16,
    },
    /// `MOV src dst` while powered.
    Mov {
        /// A constant (`K10`) or word device.
        src: String,
        /// A data register.
        dst: String,
    },
    /// `CMP a b` while powered.
    Cmp {
        /// The first operand.
        a: String,
        /// The second operand.
        b: String,
    },
    /// `INC dst` while powered.
    Inc {
        /// A data register.
        dst: String,
    },
    /// `DEC dst` while powered.
    Dec {
        /// A data register.
        dst: String,
    },
    /// A soft PLC function or function block in the rung's condition:
    /// power in, power on ([`BlockCall`]).
    Block(BlockCall),
    /// Below a soft PLC block, in its column: its Boolean input `pin`
    /// (`R`, `LD`, `R1`), fed by the network to the cell's left on its own
    /// rows (`ladder::net::Side`).
    #[serde(rename = "box_input")]
    BoxInput {
        /// The input.
        pin: String,
    },
    /// A soft PLC function or function block at the rung's right end: it
    /// runs on the rung's power, its power out goes nowhere.
    #[serde(rename = "output_block")]
    OutputBlock(BlockCall),
}

pub use super::block::BlockCall;

impl Element {
    /// A normally open contact.
    pub fn no(device: &str) -> Element {
        Element::Contact {
            kind: ContactKind::No,
            device: device.to_string(),
        }
    }

    /// A normally closed contact.
    pub fn nc(device: &str) -> Element {
        Element::Contact {
            kind: ContactKind::Nc,
            device: device.to_string(),
        }
    }

    /// A normal coil.
    pub fn coil(device: &str) -> Element {
        Element::Coil {
            kind: CoilKind::Normal,
            device: device.to_string(),
        }
    }

    /// Whether the element ends a rung (coils and output boxes).
    pub fn is_output(&self) -> bool {
        !matches!(
            self,
            Element::Wire
                | Element::Contact { .. }
                | Element::Not
                | Element::Edge { .. }
                | Element::Timer { .. }
                | Element::Block(_)
                | Element::BoxInput { .. }
        )
    }

    /// The box a soft PLC block element calls.
    pub fn block(&self) -> Option<&BlockCall> {
        match self {
            Element::Block(b) | Element::OutputBlock(b) => Some(b),
            _ => None,
        }
    }

    /// The bit devices the element reads as a contact.
    pub fn read_device(&self) -> Option<&str> {
        match self {
            Element::Contact { device, .. } => Some(device),
            _ => None,
        }
    }

    /// Calls `f` on every device or operand the element names (a
    /// contact's, a coil's, a data box's, a soft PLC box's inputs and
    /// results; not a box's instance): what a device replace or a rename
    /// rewrites.
    pub fn names_mut(&mut self, mut f: impl FnMut(&mut String)) {
        match self {
            Element::Contact { device, .. }
            | Element::Coil { device, .. }
            | Element::Pulse { device, .. }
            | Element::TimerCoil { device, .. }
            | Element::CounterCoil { device, .. } => f(device),
            Element::Mov { src: a, dst: b } | Element::Cmp { a, b } => {
                f(a);
                f(b);
            }
            Element::Inc { dst } | Element::Dec { dst } => f(dst),
            Element::Block(b) | Element::OutputBlock(b) => {
                b.inputs
                    .iter_mut()
                    .chain(b.outputs.iter_mut())
                    .for_each(|(_, o)| f(o));
            }
            Element::Wire
            | Element::Not
            | Element::Edge { .. }
            | Element::Timer { .. }
            | Element::BoxInput { .. } => {}
        }
    }

    /// The bit device an output drives, if it drives one.
    pub fn written_device(&self) -> Option<&str> {
        match self {
            Element::Coil { device, .. }
            | Element::Pulse { device, .. }
            | Element::TimerCoil { device, .. }
            | Element::CounterCoil { device, .. } => Some(device),
            _ => None,
        }
    }
}

impl fmt::Display for Element {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Element::Wire => f.write_str("wire"),
            Element::Contact { kind, device } => {
                let k = match kind {
                    ContactKind::No => "contact",
                    ContactKind::Nc => "NC contact",
                    ContactKind::Rising => "rising contact",
                    ContactKind::Falling => "falling contact",
                };
                write!(f, "{k} {device}")
            }
            Element::Not => f.write_str("NOT"),
            Element::Edge { falling: false } => f.write_str("R_TRIG"),
            Element::Edge { falling: true } => f.write_str("F_TRIG"),
            Element::Timer { kind, name, .. } => write!(f, "{} {name}", kind.name()),
            Element::Coil { kind, device } => {
                let k = match kind {
                    CoilKind::Normal => "coil",
                    CoilKind::Inverted => "inverted coil",
                    CoilKind::Set => "set coil",
                    CoilKind::Reset => "reset coil",
                };
                write!(f, "{k} {device}")
            }
            Element::Pulse { falling, device } => {
                write!(f, "{} {device}", if *falling { "PLF" } else { "PLS" })
            }
            Element::TimerCoil { device, preset } => write!(f, "timer {device} K{preset}"),
            Element::CounterCoil { device, preset } => write!(f, "counter {device} K{preset}"),
            Element::Mov { src, dst } => write!(f, "MOV {src} {dst}"),
            Element::Cmp { a, b } => write!(f, "CMP {a} {b}"),
            Element::Inc { dst } => write!(f, "INC {dst}"),
            Element::Dec { dst } => write!(f, "DEC {dst}"),
            Element::Block(b) | Element::OutputBlock(b) => write!(f, "{b}"),
            Element::BoxInput { pin } => write!(f, "box input {pin}"),
        }
    }
}
