//! What each machine offers a ladder: its capabilities, the roles its
//! devices play, and the checks of a drawn element against them. The
//! machine's own rules come from its ladder target
//! ([`super::machine_target::LadderTarget`], implemented in its folder and
//! handed out by the registry as a machine id's `target()`), so this layer
//! names no machine. The editor's palette, the validator and the
//! compilers all ask the target.

use std::fmt;

use serde::{Deserialize, Serialize};

use super::element::{CoilKind, ContactKind, Element};
pub use super::lack::{Drivable, LackReason, Latch};
use crate::error::shown;
use crate::MachineId;

/// Which elements a machine's compiler accepts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Capabilities {
    /// Contact kinds.
    pub contacts: &'static [ContactKind],
    /// Coil kinds.
    pub coils: &'static [CoilKind],
    /// NOT, R_TRIG/F_TRIG and TON/TOF/TP as in-line boxes.
    pub inline_boxes: bool,
    /// PLS / PLF outputs.
    pub pulse_outputs: bool,
    /// `OUT T K` / `OUT C K` outputs.
    pub timer_counter_coils: bool,
    /// MOV / CMP / INC / DEC.
    pub data_boxes: bool,
    /// Functions and blocks on words as boxes, their inputs wired as
    /// networks, and variables named in the ladder (an IEC machine).
    pub word_boxes: bool,
    /// The device names, for the palette and error messages.
    pub devices: &'static str,
    /// The devices a first rung uses (the guided first rung, issue #47):
    /// a start input, a stop input and an output, as the machine's
    /// documents name its first switches and lamp.
    pub starter: [&'static str; 3],
}

/// Every contact kind (most machines have them all).
pub const ALL_CONTACTS: &[ContactKind] = &[
    ContactKind::No,
    ContactKind::Nc,
    ContactKind::Rising,
    ContactKind::Falling,
];
/// Every coil kind.
pub const ALL_COILS: &[CoilKind] = &[
    CoilKind::Normal,
    CoilKind::Inverted,
    CoilKind::Set,
    CoilKind::Reset,
];

/// How an element uses a device: which of a machine's devices it may name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// A contact reads it.
    Read,
    /// A coil or pulse output drives it.
    Write,
    /// A timer coil drives it.
    Timer,
    /// A counter coil drives it.
    Counter,
    /// A data box reads it as a word (a constant included).
    WordSource,
    /// A data box writes it as a word.
    WordTarget,
}

/// The capability table of `machine`.
pub fn capabilities(machine: MachineId) -> Capabilities {
    machine.target().capabilities()
}

/// Why a machine cannot take an element as drawn: what the editor shows
/// on the cell and the compiler reports at it.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum ElementError {
    /// The machine has no such element (`what` names it, `why` adds a
    /// reason or a hint, possibly empty).
    Lacks {
        /// The machine.
        machine: MachineId,
        /// The element, as [`Element`]'s `Display` names it.
        what: String,
        /// The rest of the sentence: a reason or what to use instead.
        why: LackReason,
    },
    /// An in-line timer with a set time of 0 ms.
    ZeroTimer,
    /// A timer or counter set value above K32767.
    PresetTooLarge(u16),
    /// A MINASEC-U device name that does not parse.
    Minasec(crate::operand::MinasecOperandError),
    /// A PLC-IO86A device name that does not parse.
    Io86a(crate::operand::Io86aOperandError),
    /// A device name the machine does not have.
    UnknownDevice {
        /// The machine.
        machine: MachineId,
        /// The name as written.
        device: String,
    },
    /// A coil on an input.
    InputAsCoil(String),
    /// A word target that is not a data register.
    NotADataRegister(String),
    /// A device this element cannot drive (`want` says what it can).
    CannotDrive {
        /// The device.
        device: String,
        /// What the element drives.
        want: Drivable,
    },
    /// A set or reset coil on MINASEC-U's wired T0 / T1 / C0 / C0R.
    MinasecLatch {
        /// `set` or `reset`.
        kind: Latch,
        /// The device.
        device: String,
    },
    /// A plain or inverted coil on an IO86A counter (it needs its set value).
    Io86aCounterCoil(String),
    /// A soft PLC box that is not one.
    Block(crate::ladder::block::BoxError),
}

impl fmt::Display for ElementError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ElementError::Lacks { machine, what, why } => write!(f, "{machine} has no {what}{why}"),
            ElementError::ZeroTimer => f.write_str("a timer needs a set time above 0 ms"),
            ElementError::PresetTooLarge(k) => write!(f, "set value K{k} is above K32767"),
            ElementError::Minasec(e) => e.fmt(f),
            ElementError::Io86a(e) => e.fmt(f),
            ElementError::UnknownDevice { machine, device } => {
                let has = machine.target().devices_help();
                write!(f, "unknown device {}: {has}", shown(device))
            }
            ElementError::InputAsCoil(d) => write!(f, "{d} is an input: a coil cannot drive it"),
            ElementError::NotADataRegister(d) => {
                write!(f, "{d}: only a data register D00-D07 can take a value")
            }
            ElementError::CannotDrive { device, want } => {
                write!(f, "{device} cannot be driven here: use {want}")
            }
            ElementError::MinasecLatch { kind, device } => write!(
                f,
                "a {kind} coil on {device} has no meaning on MINASEC-U: drive it with a normal coil (a reset coil on C0 clears the count)"
            ),
            ElementError::Block(why) => why.fmt(f),
            ElementError::Io86aCounterCoil(d) => write!(
                f,
                "a plain coil cannot drive counter {d}: use a counter coil with its set value (OUT {d} K10), or a set/reset coil"
            ),
        }
    }
}

impl std::error::Error for ElementError {}

/// Checks that `machine` has `element` and its devices; returns the
/// element with device names in the machine's canonical spelling.
pub fn check_element(machine: MachineId, element: &Element) -> Result<Element, ElementError> {
    match element {
        Element::Wire => Ok(Element::Wire),
        Element::Contact { kind, device } => {
            if !capabilities(machine).contacts.contains(kind) {
                return Err(lacks(machine, element, LackReason::NoEdgeContacts));
            }
            Ok(Element::Contact {
                kind: *kind,
                device: machine.target().canonical(device, Role::Read)?,
            })
        }
        Element::Not | Element::Edge { .. } | Element::Timer { .. } => {
            check_inline_box(machine, element)
        }
        Element::Coil { kind, device } => check_coil(machine, *kind, device),
        Element::Pulse { falling, device } => {
            if !capabilities(machine).pulse_outputs {
                return Err(lacks(machine, element, LackReason::Plain));
            }
            Ok(Element::Pulse {
                falling: *falling,
                device: machine.target().canonical(device, Role::Write)?,
            })
        }
        Element::TimerCoil { .. } | Element::CounterCoil { .. } => {
            check_timer_counter_coil(machine, element)
        }
        Element::Mov { .. } | Element::Cmp { .. } | Element::Inc { .. } | Element::Dec { .. } => {
            check_data_box(machine, element)
        }
        Element::BoxInput { pin } => {
            if !capabilities(machine).word_boxes {
                return Err(ElementError::Lacks {
                    machine,
                    what: format!("box input {pin}"),
                    why: LackReason::BoxInputsAreSoft,
                });
            }
            if !crate::iec::is_identifier(pin) {
                return Err(ElementError::Block(
                    crate::ladder::block::BoxError::NoSuchInput(
                        "the box".into(),
                        pin.clone(),
                        "R, LD, R1, S1, CD …".into(),
                    ),
                ));
            }
            Ok(element.clone())
        }
        Element::Block(b) | Element::OutputBlock(b) => {
            if !capabilities(machine).word_boxes {
                return Err(ElementError::Lacks {
                    machine,
                    what: format!("{} box", b.kind()),
                    why: LackReason::WordBoxesAreSoft,
                });
            }
            b.check().map_err(ElementError::Block)?;
            Ok(element.clone())
        }
    }
}

/// Checks that `machine` has a device named `device` in any role (a bit,
/// a timer, a counter or a data word); returns its canonical spelling.
/// The error is the one for a bit, the commonest use.
pub fn check_device(machine: MachineId, device: &str) -> Result<String, ElementError> {
    let target = machine.target();
    target.canonical(device, Role::Read).or_else(|first| {
        if target.capabilities().data_boxes {
            target
                .canonical(device, Role::WordSource)
                .map_err(|_| first)
        } else {
            Err(first)
        }
    })
}

fn lacks(machine: MachineId, element: &Element, why: LackReason) -> ElementError {
    let what = match element {
        Element::Not | Element::Edge { .. } | Element::Timer { .. } => {
            format!("in-line {element} box")
        }
        Element::Pulse { .. } => "PLS/PLF output".to_string(),
        Element::Mov { .. } | Element::Cmp { .. } | Element::Inc { .. } | Element::Dec { .. } => {
            format!("{element} box")
        }
        other => other.to_string(),
    };
    ElementError::Lacks { machine, what, why }
}

fn check_inline_box(machine: MachineId, element: &Element) -> Result<Element, ElementError> {
    if !capabilities(machine).inline_boxes {
        let why = machine.target().lacks_inline_boxes();
        return Err(lacks(machine, element, why));
    }
    if let Element::Timer { preset_ms: 0, .. } = element {
        return Err(ElementError::ZeroTimer);
    }
    Ok(element.clone())
}

fn check_coil(machine: MachineId, kind: CoilKind, device: &str) -> Result<Element, ElementError> {
    let target = machine.target();
    let device = target.canonical(device, Role::Write)?;
    target.check_coil(kind, &device)?;
    Ok(Element::Coil { kind, device })
}

fn check_timer_counter_coil(
    machine: MachineId,
    element: &Element,
) -> Result<Element, ElementError> {
    let target = machine.target();
    if !target.capabilities().timer_counter_coils {
        let hint = target.lacks_timer_counter_coils();
        return Err(lacks(machine, element, hint));
    }
    match element {
        Element::TimerCoil { device, preset } | Element::CounterCoil { device, preset } => {
            if *preset > target.max_preset() {
                return Err(ElementError::PresetTooLarge(*preset));
            }
            let preset = *preset;
            Ok(if matches!(element, Element::TimerCoil { .. }) {
                let device = target.canonical(device, Role::Timer)?;
                Element::TimerCoil { device, preset }
            } else {
                let device = target.canonical(device, Role::Counter)?;
                Element::CounterCoil { device, preset }
            })
        }
        other => Ok(other.clone()),
    }
}

fn check_data_box(machine: MachineId, element: &Element) -> Result<Element, ElementError> {
    if !capabilities(machine).data_boxes {
        return Err(lacks(machine, element, LackReason::NoDataRegisters));
    }
    let word = |d: &str, role| machine.target().canonical(d, role);
    Ok(match element {
        Element::Mov { src, dst } => Element::Mov {
            src: word(src, Role::WordSource)?,
            dst: word(dst, Role::WordTarget)?,
        },
        Element::Cmp { a, b } => Element::Cmp {
            a: word(a, Role::WordSource)?,
            b: word(b, Role::WordSource)?,
        },
        Element::Inc { dst } => Element::Inc {
            dst: word(dst, Role::WordTarget)?,
        },
        Element::Dec { dst } => Element::Dec {
            dst: word(dst, Role::WordTarget)?,
        },
        other => other.clone(),
    })
}
