//! What each machine offers a ladder: its elements and devices. The
//! editor's palette and the validator both read this one table.

use std::fmt;

use serde::{Deserialize, Serialize};

use super::element::{CoilKind, ContactKind, Element};
pub use super::lack::{Drivable, LackReason, Latch};
use crate::avr::parse_register_bit;
use crate::error::shown;
use crate::io86a::{isa::parse_bit as io86a_bit, isa::parse_word, Bit, Word};
use crate::minasec::{isa::Device as MinasecDevice, Address};
use crate::{arduino, MachineId};

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
    /// The device names, for the palette and error messages.
    pub devices: &'static str,
    /// The devices a first rung uses (the guided first rung, issue #47):
    /// a start input, a stop input and an output, as the machine's
    /// documents name its first switches and lamp.
    pub starter: [&'static str; 3],
}

const ALL_CONTACTS: &[ContactKind] = &[
    ContactKind::No,
    ContactKind::Nc,
    ContactKind::Rising,
    ContactKind::Falling,
];
const ALL_COILS: &[CoilKind] = &[
    CoilKind::Normal,
    CoilKind::Inverted,
    CoilKind::Set,
    CoilKind::Reset,
];

/// The capability table of `machine`.
pub const fn capabilities(machine: MachineId) -> Capabilities {
    match machine {
        MachineId::MinasecU => Capabilities {
            contacts: ALL_CONTACTS,
            coils: ALL_COILS,
            inline_boxes: false,
            pulse_outputs: false,
            timer_counter_coils: false,
            data_boxes: false,
            devices: "X00-X07, Y00-Y07, M00-M07, M10-M13, T0, T1, C0, C0R",
            starter: ["X00", "X01", "Y00"],
        },
        MachineId::Io86a => Capabilities {
            contacts: ALL_CONTACTS,
            coils: ALL_COILS,
            inline_boxes: false,
            pulse_outputs: true,
            timer_counter_coils: true,
            data_boxes: true,
            devices: "X00-X07, Y00-Y05, M00-M63, S00-S07, T00-T31, C00-C07, D00-D07, K",
            starter: ["X00", "X01", "Y00"],
        },
        MachineId::AvrPlc => Capabilities {
            contacts: ALL_CONTACTS,
            coils: ALL_COILS,
            inline_boxes: true,
            pulse_outputs: false,
            timer_counter_coils: false,
            data_boxes: false,
            devices: "R0.0-R31.7",
            starter: ["R0.0", "R0.1", "R1.0"],
        },
        MachineId::ArduinoPlc => Capabilities {
            contacts: &[ContactKind::No, ContactKind::Nc],
            coils: ALL_COILS,
            inline_boxes: false,
            pulse_outputs: false,
            timer_counter_coils: false,
            data_boxes: false,
            devices: "X000-X005, Y000-Y005",
            starter: ["X000", "X001", "Y000"],
        },
        MachineId::SoftPlc => Capabilities {
            contacts: ALL_CONTACTS,
            coils: ALL_COILS,
            inline_boxes: true,
            pulse_outputs: true,
            timer_counter_coils: false,
            data_boxes: false,
            devices: "%IX0.0, %QX0.0, %MX0.0 or a name",
            starter: ["%IX0.0", "%IX0.1", "%QX0.0"],
        },
    }
}

/// How an element uses a device.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Role {
    Read,
    Write,
    Timer,
    Counter,
    WordSource,
    WordTarget,
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
                let has = match machine {
                    MachineId::AvrPlc => "avr-plc ladders name bits R0.0-R31.7",
                    MachineId::ArduinoPlc => "arduino-plc has X000-X005 and Y000-Y005",
                    MachineId::SoftPlc => {
                        "soft-plc ladders name bits as %IX0.0, %QX0.0, %MX0.0 or a variable name"
                    }
                    _ => capabilities(*machine).devices,
                };
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
                device: canonical(machine, device, Role::Read)?,
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
                device: canonical(machine, device, Role::Write)?,
            })
        }
        Element::TimerCoil { .. } | Element::CounterCoil { .. } => {
            check_timer_counter_coil(machine, element)
        }
        Element::Mov { .. } | Element::Cmp { .. } | Element::Inc { .. } | Element::Dec { .. } => {
            check_data_box(machine, element)
        }
        Element::BoxInput { pin } => {
            if machine != MachineId::SoftPlc {
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
            if machine != MachineId::SoftPlc {
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
    canonical(machine, device, Role::Read).or_else(|first| {
        if capabilities(machine).data_boxes {
            canonical(machine, device, Role::WordSource).map_err(|_| first)
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
        let why = if machine == MachineId::ArduinoPlc {
            LackReason::ArduinoNoTimers
        } else {
            LackReason::Plain
        };
        return Err(lacks(machine, element, why));
    }
    if let Element::Timer { preset_ms: 0, .. } = element {
        return Err(ElementError::ZeroTimer);
    }
    Ok(element.clone())
}

fn check_coil(machine: MachineId, kind: CoilKind, device: &str) -> Result<Element, ElementError> {
    let device = canonical(machine, device, Role::Write)?;
    match machine {
        MachineId::MinasecU => minasec_coil(kind, &device)?,
        MachineId::Io86a => io86a_coil(kind, &device)?,
        _ => {}
    }
    Ok(Element::Coil { kind, device })
}

fn check_timer_counter_coil(
    machine: MachineId,
    element: &Element,
) -> Result<Element, ElementError> {
    if !capabilities(machine).timer_counter_coils {
        let hint = match machine {
            MachineId::MinasecU => LackReason::MinasecPanelTimers,
            MachineId::AvrPlc | MachineId::SoftPlc => LackReason::UseInlineTimer,
            _ => LackReason::ArduinoNoTimersOrCounters,
        };
        return Err(lacks(machine, element, hint));
    }
    match element {
        Element::TimerCoil { device, preset } | Element::CounterCoil { device, preset } => {
            if i32::from(*preset) > crate::io86a::isa::K_MAX {
                return Err(ElementError::PresetTooLarge(*preset));
            }
            let preset = *preset;
            Ok(if matches!(element, Element::TimerCoil { .. }) {
                let device = canonical(machine, device, Role::Timer)?;
                Element::TimerCoil { device, preset }
            } else {
                let device = canonical(machine, device, Role::Counter)?;
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
    let word = |d: &str, role| canonical(machine, d, role);
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

fn canonical(machine: MachineId, device: &str, role: Role) -> Result<String, ElementError> {
    let device = device.trim();
    let unknown = || ElementError::UnknownDevice {
        machine,
        device: device.to_string(),
    };
    match machine {
        MachineId::MinasecU => {
            let a = Address::parse(device).map_err(ElementError::Minasec)?;
            if role == Role::Write && matches!(a.device(), MinasecDevice::Input(_)) {
                return Err(ElementError::InputAsCoil(a.to_string()));
            }
            Ok(a.to_string())
        }
        MachineId::Io86a => io86a_canonical(device, role),
        MachineId::AvrPlc => parse_register_bit(device)
            .map(|b| b.to_string())
            .ok_or_else(unknown),
        MachineId::ArduinoPlc => {
            let n = arduino::isa::parse_io(device).ok_or_else(unknown)?;
            if role == Role::Write && n < 8 {
                return Err(ElementError::InputAsCoil(arduino::isa::io_name(n)));
            }
            Ok(arduino::isa::io_name(n))
        }
        MachineId::SoftPlc => {
            let name = soft_canonical(device).ok_or_else(unknown)?;
            if role == Role::Write && name.starts_with("%I") {
                return Err(ElementError::InputAsCoil(name));
            }
            Ok(name)
        }
    }
}

/// A soft PLC bit: an address (`%IX0.0`; `%I0.0` is written `%IX0.0`)
/// or a variable's name.
fn soft_canonical(device: &str) -> Option<String> {
    use crate::iec::{Address, Size};
    if device.starts_with('%') {
        let a = Address::parse(device).ok()?;
        return (a.size == Size::Bit).then(|| a.to_string());
    }
    crate::iec::is_identifier(device).then(|| device.to_string())
}

fn io86a_canonical(device: &str, role: Role) -> Result<String, ElementError> {
    if matches!(role, Role::WordSource | Role::WordTarget) {
        let w = parse_word(device).map_err(ElementError::Io86a)?;
        if role == Role::WordTarget && !matches!(w, Word::D(_)) {
            return Err(ElementError::NotADataRegister(device.to_string()));
        }
        return Ok(match w {
            Word::K(k) => format!("K{k}"),
            Word::D(n) => format!("D{n:02}"),
            Word::T(n) => format!("T{n:02}"),
            Word::C(n) => format!("C{n:02}"),
        });
    }
    let b = io86a_bit(device).map_err(ElementError::Io86a)?;
    let ok = matches!(
        (role, b),
        (Role::Read, _)
            | (Role::Write, Bit::Y(_) | Bit::M(_) | Bit::S(_) | Bit::C(_))
            | (Role::Timer, Bit::T(_))
            | (Role::Counter, Bit::C(_))
    );
    if !ok {
        let want = match role {
            Role::Timer => Drivable::Timer,
            Role::Counter => Drivable::Counter,
            _ => Drivable::Output,
        };
        return Err(ElementError::CannotDrive {
            device: b.to_string(),
            want,
        });
    }
    Ok(b.to_string())
}

/// An IO86A counter is driven by a counter coil with its set value
/// (`OUT C07 K10`); a plain or inverted coil would compile to `OUT C07`
/// with no `K`, which the machine refuses.
fn io86a_coil(kind: CoilKind, device: &str) -> Result<(), ElementError> {
    if matches!(kind, CoilKind::Normal | CoilKind::Inverted) && device.starts_with('C') {
        return Err(ElementError::Io86aCounterCoil(device.to_string()));
    }
    Ok(())
}

/// MINASEC-U's T0 / T1 / C0 / C0R are wired, not latched: a set or reset
/// coil on them has no meaning, except reset on C0, which is `ST C0R`.
fn minasec_coil(kind: CoilKind, device: &str) -> Result<(), ElementError> {
    let special = matches!(device, "T0" | "T1" | "C0" | "C0R");
    let latch = match kind {
        CoilKind::Set => Latch::Set,
        CoilKind::Reset if device != "C0" => Latch::Reset,
        _ => return Ok(()),
    };
    if special {
        return Err(ElementError::MinasecLatch {
            kind: latch,
            device: device.to_string(),
        });
    }
    Ok(())
}
