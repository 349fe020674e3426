//! The typed errors of the [`super::Plc`] interface: flat enums, each
//! variant documented, `Display` written out so that the command line and
//! the page say the same thing.

use std::fmt;

use crate::error::{shown, Located};
use crate::time::{SimTime, TimeError};
use crate::{arduino, avr, io86a, minasec, MachineId};

/// Why a machine refused a program, a device, a setting or a command.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PlcError {
    /// The program text has problems, each at its 1-based line.
    Program(Vec<Located<ProgramProblem>>),
    /// A device name or value the machine does not take.
    Device(DeviceError),
    /// A setting the machine does not take.
    Setting(SettingError),
    /// A front-panel command the board refused (MINASEC-U).
    Panel(minasec::SettingError),
    /// A command for another machine's panel or terminal.
    NotThisMachine {
        /// The machine asked.
        machine: MachineId,
        /// What it lacks.
        lacks: &'static str,
    },
}

impl fmt::Display for PlcError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PlcError::Program(problems) => crate::error::write_joined(f, problems),
            PlcError::Device(e) => e.fmt(f),
            PlcError::Setting(e) => e.fmt(f),
            PlcError::Panel(e) => e.fmt(f),
            PlcError::NotThisMachine { machine, lacks } => write!(f, "{machine} has no {lacks}"),
        }
    }
}

impl std::error::Error for PlcError {}

/// A parser's located errors as [`ProgramProblem`]s, `f` naming the
/// machine (`ProgramProblem::Io86a`).
pub fn problems<E>(
    errors: Vec<Located<E>>,
    f: impl Fn(E) -> ProgramProblem,
) -> Vec<Located<ProgramProblem>> {
    errors
        .into_iter()
        .map(|e| Located::new(e.line, f(e.error)))
        .collect()
}

impl From<DeviceError> for PlcError {
    fn from(e: DeviceError) -> Self {
        PlcError::Device(e)
    }
}

impl From<SettingError> for PlcError {
    fn from(e: SettingError) -> Self {
        PlcError::Setting(e)
    }
}

/// One problem with a line of a program, in the machine's own terms.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ProgramProblem {
    /// A MINASEC-U listing line.
    Minasec(minasec::AsmError),
    /// A PLC-IO86A listing line.
    Io86a(io86a::AsmError),
    /// An Arduino PLC listing line.
    Arduino(arduino::isa::AsmError),
    /// An AVR PLC source line.
    Avr(avr::ProgramError),
}

impl fmt::Display for ProgramProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ProgramProblem::Minasec(e) => e.fmt(f),
            ProgramProblem::Io86a(e) => e.fmt(f),
            ProgramProblem::Arduino(e) => e.fmt(f),
            ProgramProblem::Avr(e) => e.fmt(f),
        }
    }
}

/// A device name, or a value for a device, that the machine does not take.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum DeviceError {
    /// A MINASEC-U address that does not parse.
    Minasec(minasec::isa::OperandError),
    /// A PLC-IO86A device that does not parse.
    Io86a(io86a::isa::OperandError),
    /// An Arduino pin that is not X000-X005 / Y000-Y005.
    ArduinoPin(String),
    /// An AVR bit that is neither a defined name nor `R4.2`.
    AvrBit(String),
    /// An AVR timer label (`NAME.v`) that names no timer word.
    AvrTimer(String),
    /// A constant (`K10.v`) where a device is needed.
    Constant(String),
    /// A device that is not an input, given an input event.
    NotAnInput {
        /// The device as written.
        device: String,
        /// What events can drive.
        drives: &'static str,
    },
    /// An output pin given an input event.
    IsAnOutput {
        /// The device as written.
        device: String,
        /// What events can drive.
        drives: &'static str,
    },
    /// A bit given a value other than 0 or 1.
    BitValue(String),
    /// A voltage for an input in digital mode (IO86A X04/X05).
    NeedsAnalogMode(String),
    /// A number for an input in analog mode (IO86A X04/X05).
    NeedsVoltage(String),
    /// An IR input given something that is not a 32-bit frame.
    IrFrame(String),
}

impl fmt::Display for DeviceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DeviceError::Minasec(e) => e.fmt(f),
            DeviceError::Io86a(e) => e.fmt(f),
            DeviceError::ArduinoPin(d) => write!(
                f,
                "unknown device {}: the Arduino PLC has X000-X005, Y000-Y005",
                shown(d)
            ),
            DeviceError::AvrBit(d) => write!(
                f,
                "unknown bit {}: name a bit defined by NAME_R and NAME_B, or write R4.2",
                shown(d)
            ),
            DeviceError::AvrTimer(d) => write!(
                f,
                "unknown timer {}: name its label after PLC_Timer_Top",
                shown(d)
            ),
            DeviceError::Constant(d) => write!(f, "{d} is a constant, not a device"),
            DeviceError::NotAnInput { device, drives } => {
                write!(f, "{device} is not an input: events drive {drives}")
            }
            DeviceError::IsAnOutput { device, drives } => {
                write!(f, "{device} is an output: events drive {drives}")
            }
            DeviceError::BitValue(d) => write!(f, "{d} is a bit: its value is 0 or 1"),
            DeviceError::NeedsAnalogMode(d) => write!(
                f,
                "{d} is a digital input: a voltage needs analog mode (--set {d}=A:n1:n2)"
            ),
            DeviceError::NeedsVoltage(d) => {
                write!(f, "{d} is in analog mode: give a voltage such as 2.5V")
            }
            DeviceError::IrFrame(d) => {
                write!(f, "{d} receives IR frames: 0 (none) or a 32-bit NEC frame")
            }
        }
    }
}

impl std::error::Error for DeviceError {}

/// A setting (`--set NAME=VALUE`, a project's settings, a panel knob) that
/// the machine does not take. Nothing changes when one is refused.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SettingError {
    /// A name the machine has no setting for.
    Unknown {
        /// The machine.
        machine: MachineId,
        /// The name as written.
        name: String,
        /// The names it takes.
        takes: &'static str,
    },
    /// A time that does not parse.
    Time(TimeError),
    /// A MINASEC-U knob, switch or clock out of range.
    Minasec(minasec::SettingError),
    /// MINASEC-U `C0=`: not a number.
    CounterPreset(String),
    /// A PLC-IO86A pin or filter setting in the terminal's words.
    Io86a(io86a::peripherals::SettingError),
    /// A period outside `0 < period <= max`.
    PeriodOutOfRange {
        /// What it is the period of.
        what: &'static str,
        /// As asked.
        period: SimTime,
        /// The longest allowed.
        max: SimTime,
    },
    /// An AVR scan period that is not whole milliseconds from 1 ms to 10 s.
    AvrScan(SimTime),
    /// A value not among a setting's choices.
    Choice {
        /// The setting (`quirk`, `chip`).
        setting: &'static str,
        /// The value as written.
        value: String,
        /// The choices.
        choices: &'static str,
    },
    /// An Arduino chip too small for the program in EEPROM.
    ChipTooSmall {
        /// The first programmed step past the chip's end.
        step: usize,
        /// The chip's steps.
        capacity: usize,
    },
}

impl fmt::Display for SettingError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SettingError::Unknown {
                machine,
                name,
                takes,
            } => write!(f, "unknown setting {}: {machine} takes {takes}", shown(name)),
            SettingError::Time(e) => e.fmt(f),
            SettingError::Minasec(e) => e.fmt(f),
            SettingError::CounterPreset(v) => {
                write!(f, "C0={v}: the counter set value is a number 0..99")
            }
            SettingError::Io86a(e) => e.fmt(f),
            SettingError::PeriodOutOfRange { what, period, max } => write!(
                f,
                "{what} {period}ms is out of range: above 0 and at most {}s",
                max.as_secs_f64()
            ),
            SettingError::AvrScan(period) => write!(
                f,
                "the AVR PLC's scan period is a whole number of milliseconds from 1ms to 10s (its programs compute timer presets as ms/Scan), not {period}ms"
            ),
            SettingError::Choice {
                setting,
                value,
                choices,
            } => write!(f, "unknown {setting} {}: {choices}", shown(value)),
            SettingError::ChipTooSmall { step, capacity } => write!(
                f,
                "step {step} is programmed but this chip holds {capacity} steps"
            ),
        }
    }
}

impl std::error::Error for SettingError {}

impl From<TimeError> for SettingError {
    fn from(e: TimeError) -> Self {
        SettingError::Time(e)
    }
}
