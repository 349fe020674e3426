//! Wiring: which machine device each plant signal is on. A `WIRING.csv`
//! has `SIGNAL,DEVICE` lines (`#` comments); without one, the plant's
//! default wiring for the machine, built from the terminals the machine
//! names ([`crate::plc::Plc::terminals`]). A signal left out is not
//! connected.

pub use super::wire_error::WireError;
use super::{Direction, Kind, PlantInfo};
use crate::error::{shown, Located};
use crate::events::InputValue;
use crate::plc::{AnalogScale, Device, Plc, Terminals};

/// One line of a wiring: signal name to device name.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct WireEntry {
    /// The signal, without the plant's name (`infeed`).
    pub signal: String,
    /// The machine's device (`X00`).
    pub device: String,
    /// The 1-based line it came from (0: the default wiring).
    pub line: usize,
}

/// A signal wired to a device, checked against the machine.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Wire {
    /// The device's name as wired (`X00`).
    pub name: String,
    /// The signal's index in the plant's signals.
    pub signal: usize,
    /// The device.
    pub device: Device,
    /// For an analog signal, the device's scale.
    pub scale: Option<AnalogScale>,
}

/// The most lines a wiring file may have (a plant has a handful of signals).
const MAX_LINES: usize = 1000;

/// Parses a wiring file's `SIGNAL,DEVICE` lines (names checked later).
pub fn parse(text: &str) -> Result<Vec<WireEntry>, Vec<Located<String>>> {
    let mut entries = Vec::new();
    let mut errors = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let body = raw.split('#').next().unwrap_or("").trim();
        if body.is_empty() || body.eq_ignore_ascii_case("signal,device") {
            continue;
        }
        if entries.len() >= MAX_LINES {
            errors.push(Located::new(line, format!("more than {MAX_LINES} lines")));
            break;
        }
        match body.split(',').map(str::trim).collect::<Vec<_>>()[..] {
            [signal, device] if !signal.is_empty() && !device.is_empty() => {
                entries.push(WireEntry {
                    signal: signal.to_string(),
                    device: device.to_string(),
                    line,
                })
            }
            _ => errors.push(Located::new(
                line,
                format!("expected SIGNAL,DEVICE but found {}", shown(body)),
            )),
        }
    }
    if errors.is_empty() {
        Ok(entries)
    } else {
        Err(errors)
    }
}

/// The plant's default wiring on `machine`: bit sensors on the digital
/// inputs in order, actuators on the outputs in order, analog sensors on
/// the analog inputs in order (the AVR PLC: the program's bits named as
/// the signals in capitals). A signal with no terminal left is returned
/// in the second list, unwired.
pub fn default_wiring(plant: &PlantInfo, machine: &dyn Plc) -> (Vec<WireEntry>, Vec<usize>) {
    let terminals = machine.terminals();
    let (mut inputs, mut outputs) = (terminals.inputs.iter(), terminals.outputs.iter());
    let mut analog = terminals.analog.iter().map(|(name, _)| name);
    let mut wired = Vec::new();
    let mut left = Vec::new();
    for (i, s) in plant.signals.iter().enumerate() {
        let device = if terminals.by_name {
            let upper = s.name.to_ascii_uppercase();
            machine.device(&upper).is_ok().then_some(upper)
        } else {
            match (s.direction, s.kind) {
                (Direction::In, Kind::Bit) => inputs.next().cloned(),
                (Direction::In, Kind::Analog) => analog.next().cloned(),
                (Direction::Out, _) => outputs.next().cloned(),
            }
        };
        match device {
            Some(device) => wired.push(WireEntry {
                signal: s.name.to_string(),
                device,
                line: 0,
            }),
            None => left.push(i),
        }
    }
    (wired, left)
}

/// Checks `entries` against the plant and the machine: every signal
/// known and wired once, every device the machine's and used once, a
/// sensor on an input that takes its value, an analog sensor on an
/// analog input. Errors are located at the entry's line.
pub fn check(
    plant: &PlantInfo,
    machine: &dyn Plc,
    entries: &[WireEntry],
) -> Result<Vec<Wire>, Vec<Located<WireError>>> {
    let terminals = machine.terminals();
    let mut wires: Vec<Wire> = Vec::new();
    let mut errors = Vec::new();
    for e in entries {
        let full = || format!("{}.{}", plant.name, e.signal);
        match check_one(plant, machine, &terminals, e) {
            Ok(w) if wires.iter().any(|o| o.signal == w.signal) => {
                errors.push(Located::new(e.line, WireError::Twice { full: full() }))
            }
            Ok(w) if wires.iter().any(|o| o.device == w.device) => errors.push(Located::new(
                e.line,
                WireError::TwoSignals {
                    device: e.device.clone(),
                    full: full(),
                },
            )),
            Ok(w) => wires.push(w),
            Err(error) => errors.push(Located::new(e.line, error)),
        }
    }
    if errors.is_empty() {
        Ok(wires)
    } else {
        Err(errors)
    }
}

fn check_one(
    plant: &PlantInfo,
    machine: &dyn Plc,
    terminals: &Terminals,
    e: &WireEntry,
) -> Result<Wire, WireError> {
    let signal = plant.signal_named(&e.signal).map_err(WireError::Signal)?;
    let info = &plant.signals[signal];
    let full = format!("{}.{}", plant.name, info.name);
    let device = machine
        .device(&e.device)
        .map_err(|error| WireError::NoDevice {
            full: full.clone(),
            device: e.device.clone(),
            error,
        })?;
    let mut scale = None;
    match (info.direction, info.kind) {
        (Direction::In, Kind::Analog) => {
            let Some(s) = terminals.analog_scale(&e.device) else {
                return Err(WireError::NotAnalog {
                    full,
                    device: e.device.clone(),
                    machine: machine.id().name(),
                    analog: terminals.analog.iter().map(|(n, _)| n.clone()).collect(),
                });
            };
            let zero = match s {
                AnalogScale::Millivolts(_) => InputValue::Millivolts(0),
                AnalogScale::Word(_) => InputValue::Int(0),
            };
            machine
                .check_input(device, zero)
                .map_err(|error| WireError::AnalogRefused {
                    full: full.clone(),
                    device: e.device.clone(),
                    error,
                })?;
            scale = Some(s);
        }
        (Direction::In, Kind::Bit) => machine
            .check_input(device, InputValue::Int(0))
            .map_err(|error| WireError::SensorNeedsInput { full, error })?,
        (Direction::Out, _) => {
            let inputs = terminals
                .inputs
                .iter()
                .chain(terminals.analog.iter().map(|(n, _)| n));
            if inputs
                .into_iter()
                .any(|n| machine.device(n).ok() == Some(device))
            {
                return Err(WireError::ActuatorOnInput {
                    full,
                    device: e.device.clone(),
                });
            }
        }
    }
    Ok(Wire {
        name: e.device.clone(),
        signal,
        device,
        scale,
    })
}

/// `value` (0..=ANALOG_FULL) as the device's input value.
pub fn scaled(scale: AnalogScale, value: i64) -> InputValue {
    let full = super::ANALOG_FULL;
    match scale {
        AnalogScale::Millivolts(max) => InputValue::Millivolts(value * max / full),
        AnalogScale::Word(max) => InputValue::Int(value * max / full),
    }
}
