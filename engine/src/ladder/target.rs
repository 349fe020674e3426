//! What each machine offers a ladder: its elements and devices. The
//! editor's palette and the validator both read this one table.

use super::element::{CoilKind, ContactKind, Element};
use crate::avr::parse_register_bit;
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
        },
        MachineId::Io86a => Capabilities {
            contacts: ALL_CONTACTS,
            coils: ALL_COILS,
            inline_boxes: false,
            pulse_outputs: true,
            timer_counter_coils: true,
            data_boxes: true,
            devices: "X00-X07, Y00-Y05, M00-M63, S00-S07, T00-T31, C00-C07, D00-D07, K",
        },
        MachineId::AvrPlc => Capabilities {
            contacts: ALL_CONTACTS,
            coils: ALL_COILS,
            inline_boxes: true,
            pulse_outputs: false,
            timer_counter_coils: false,
            data_boxes: false,
            devices: "R0.0-R31.7",
        },
        MachineId::ArduinoPlc => Capabilities {
            contacts: &[ContactKind::No, ContactKind::Nc],
            coils: ALL_COILS,
            inline_boxes: false,
            pulse_outputs: false,
            timer_counter_coils: false,
            data_boxes: false,
            devices: "X000-X005, Y000-Y005",
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

/// Checks that `machine` has `element` and its devices; returns the
/// element with device names in the machine's canonical spelling.
pub fn check_element(machine: MachineId, element: &Element) -> Result<Element, String> {
    let caps = capabilities(machine);
    let name = machine.name();
    let dev = |d: &str, role: Role| canonical(machine, d, role);
    Ok(match element {
        Element::Wire => Element::Wire,
        Element::Contact { kind, device } => {
            if !caps.contacts.contains(kind) {
                return Err(format!("{name} has no {element}: it has no edge contacts"));
            }
            Element::Contact {
                kind: *kind,
                device: dev(device, Role::Read)?,
            }
        }
        Element::Not | Element::Edge { .. } | Element::Timer { .. } => {
            if !caps.inline_boxes {
                let why = if machine == MachineId::ArduinoPlc {
                    " (the Arduino sketch has no timers)"
                } else {
                    ""
                };
                return Err(format!("{name} has no in-line {element} box{why}"));
            }
            if let Element::Timer { preset_ms, .. } = element {
                if *preset_ms == 0 {
                    return Err("a timer needs a set time above 0 ms".to_string());
                }
            }
            element.clone()
        }
        Element::Coil { kind, device } => {
            let device = dev(device, Role::Write)?;
            if machine == MachineId::MinasecU {
                minasec_coil(*kind, &device)?;
            }
            if machine == MachineId::Io86a {
                io86a_coil(*kind, &device)?;
            }
            Element::Coil {
                kind: *kind,
                device,
            }
        }
        Element::Pulse { falling, device } => {
            if !caps.pulse_outputs {
                return Err(format!("{name} has no PLS/PLF output"));
            }
            Element::Pulse {
                falling: *falling,
                device: dev(device, Role::Write)?,
            }
        }
        Element::TimerCoil { device, preset } | Element::CounterCoil { device, preset } => {
            if !caps.timer_counter_coils {
                let hint = match machine {
                    MachineId::MinasecU => ": drive T0/T1 or C0 with a coil; their delay and set value are panel settings",
                    MachineId::AvrPlc => ": use an in-line TON/TOF/TP box",
                    _ => " (the Arduino sketch has no timers or counters)",
                };
                return Err(format!("{name} has no {element}{hint}"));
            }
            if i32::from(*preset) > crate::io86a::isa::K_MAX {
                return Err(format!("set value K{preset} is above K32767"));
            }
            let timer = matches!(element, Element::TimerCoil { .. });
            let d = dev(device, if timer { Role::Timer } else { Role::Counter })?;
            if timer {
                Element::TimerCoil {
                    device: d,
                    preset: *preset,
                }
            } else {
                Element::CounterCoil {
                    device: d,
                    preset: *preset,
                }
            }
        }
        Element::Mov { .. } | Element::Cmp { .. } | Element::Inc { .. } | Element::Dec { .. } => {
            if !caps.data_boxes {
                return Err(format!(
                    "{name} has no {element} box: it has no data registers"
                ));
            }
            match element {
                Element::Mov { src, dst } => Element::Mov {
                    src: dev(src, Role::WordSource)?,
                    dst: dev(dst, Role::WordTarget)?,
                },
                Element::Cmp { a, b } => Element::Cmp {
                    a: dev(a, Role::WordSource)?,
                    b: dev(b, Role::WordSource)?,
                },
                Element::Inc { dst } => Element::Inc {
                    dst: dev(dst, Role::WordTarget)?,
                },
                Element::Dec { dst } => Element::Dec {
                    dst: dev(dst, Role::WordTarget)?,
                },
                _ => element.clone(),
            }
        }
    })
}

fn canonical(machine: MachineId, device: &str, role: Role) -> Result<String, String> {
    let device = device.trim();
    match machine {
        MachineId::MinasecU => {
            let a = Address::parse(device).map_err(|e| e.to_string())?;
            if role == Role::Write && matches!(a.device(), MinasecDevice::Input(_)) {
                return Err(format!("{a} is an input: a coil cannot drive it"));
            }
            Ok(a.to_string())
        }
        MachineId::Io86a => io86a_canonical(device, role),
        MachineId::AvrPlc => parse_register_bit(device)
            .map(|b| b.to_string())
            .ok_or_else(|| {
                format!(
                    "unknown device {}: avr-plc ladders name bits R0.0-R31.7",
                    crate::error::shown(device)
                )
            }),
        MachineId::ArduinoPlc => {
            let n = arduino::isa::parse_io(device).ok_or_else(|| {
                format!(
                    "unknown device {}: arduino-plc has X000-X005 and Y000-Y005",
                    crate::error::shown(device)
                )
            })?;
            if role == Role::Write && n < 8 {
                return Err(format!(
                    "{} is an input: a coil cannot drive it",
                    arduino::isa::io_name(n)
                ));
            }
            Ok(arduino::isa::io_name(n))
        }
    }
}

fn io86a_canonical(device: &str, role: Role) -> Result<String, String> {
    match role {
        Role::WordSource | Role::WordTarget => {
            let w = parse_word(device).map_err(|e| e.to_string())?;
            if role == Role::WordTarget && !matches!(w, Word::D(_)) {
                return Err(format!(
                    "{device}: only a data register D00-D07 can take a value"
                ));
            }
            Ok(match w {
                Word::K(k) => format!("K{k}"),
                Word::D(n) => format!("D{n:02}"),
                Word::T(n) => format!("T{n:02}"),
                Word::C(n) => format!("C{n:02}"),
            })
        }
        _ => {
            let b = io86a_bit(device).map_err(|e| e.to_string())?;
            let ok = matches!(
                (role, b),
                (Role::Read, _)
                    | (Role::Write, Bit::Y(_) | Bit::M(_) | Bit::S(_) | Bit::C(_))
                    | (Role::Timer, Bit::T(_))
                    | (Role::Counter, Bit::C(_))
            );
            if !ok {
                let want = match role {
                    Role::Timer => "a timer T00-T31",
                    Role::Counter => "a counter C00-C07",
                    _ => "a Y, M or S device (C only with set/reset)",
                };
                return Err(format!("{b} cannot be driven here: use {want}"));
            }
            Ok(b.to_string())
        }
    }
}

/// An IO86A counter is driven by a counter coil with its set value
/// (`OUT C07 K10`); a plain or inverted coil would compile to `OUT C07`
/// with no `K`, which the machine refuses.
fn io86a_coil(kind: CoilKind, device: &str) -> Result<(), String> {
    if matches!(kind, CoilKind::Normal | CoilKind::Inverted) && device.starts_with('C') {
        return Err(format!(
            "a plain coil cannot drive counter {device}: use a counter coil with its set value (OUT {device} K10), or a set/reset coil"
        ));
    }
    Ok(())
}

/// MINASEC-U's T0 / T1 / C0 / C0R are wired, not latched: a set or reset
/// coil on them has no meaning, except reset on C0, which is `ST C0R`.
fn minasec_coil(kind: CoilKind, device: &str) -> Result<(), String> {
    let special = matches!(device, "T0" | "T1" | "C0" | "C0R");
    match kind {
        CoilKind::Set | CoilKind::Reset if special && !(kind == CoilKind::Reset && device == "C0") => Err(format!(
            "a {} coil on {device} has no meaning on MINASEC-U: drive it with a normal coil (a reset coil on C0 clears the count)",
            if kind == CoilKind::Set { "set" } else { "reset" }
        )),
        _ => Ok(()),
    }
}
