//! The typed errors of the [`super::Plc`] interface: flat enums, each
//! variant documented, `Display` written out so that the command line and
//! the page say the same thing.

use std::fmt;

use super::own::{Own, OwnValue};
use crate::error::{shown, Located};
use crate::time::{SimTime, TimeError};
use crate::MachineId;

/// Why a machine refused a program, a device, a setting or a command.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PlcError {
    /// The program text has problems, each at its 1-based line.
    Program(Vec<Located<ProgramProblem>>),
    /// A device name or value the machine does not take.
    Device(DeviceError),
    /// A setting the machine does not take.
    Setting(SettingError),
    /// A machine's own command (MINASEC-U's front panel, IO86A's second
    /// device) refused, in the machine's own terms.
    Own(Own),
    /// Another machine's own command (its panel, its second device).
    NotItsOwn {
        /// The machine asked.
        machine: MachineId,
        /// The command, which says whose it is.
        command: Own,
    },
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
            PlcError::Own(e) => e.fmt(f),
            PlcError::NotThisMachine { machine, lacks } => write!(f, "{machine} has no {lacks}"),
            PlcError::NotItsOwn { machine, command } => write!(f, "{machine} has no {command}"),
        }
    }
}

impl std::error::Error for PlcError {}

/// A parser's located errors, in the machine's own terms, as
/// [`ProgramProblem`]s.
pub fn problems<E: OwnValue>(errors: Vec<Located<E>>) -> Vec<Located<ProgramProblem>> {
    errors
        .into_iter()
        .map(|e| Located::new(e.line, Own::new(e.error)))
        .collect()
}

impl PlcError {
    /// A machine's own refusal of its own command.
    pub fn own<E: OwnValue>(e: E) -> PlcError {
        PlcError::Own(Own::new(e))
    }
}

impl DeviceError {
    /// A device refused in the machine's own terms.
    pub fn own<E: OwnValue>(e: E) -> DeviceError {
        DeviceError::Own(Own::new(e))
    }
}

impl SettingError {
    /// A setting refused in the machine's own terms.
    pub fn own<E: OwnValue>(e: E) -> SettingError {
        SettingError::Own(Own::new(e))
    }
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

/// One problem with a line of a program, in the machine's own terms (its
/// assembler's error type).
pub type ProgramProblem = Own;

/// What a machine's input events can drive, said in a refusal: typed, so
/// the page says it in its language (MINASEC-U's "and the CNTCLR button").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Drives {
    /// The input terminals, as a range of names (`X00-X07`).
    Terminals(&'static str),
    /// The input terminals and a button of the board (`CNTCLR`).
    TerminalsAndButton(&'static str, &'static str),
    /// Any bit (the AVR PLC's registers).
    Bits,
}

impl fmt::Display for Drives {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Drives::Terminals(range) => f.write_str(range),
            Drives::TerminalsAndButton(range, button) => {
                write!(f, "{range} and the {button} button")
            }
            Drives::Bits => f.write_str("bits"),
        }
    }
}

/// A device name, or a value for a device, that the machine does not take.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum DeviceError {
    /// A device that does not parse, in the machine's own terms
    /// (MINASEC-U's and IO86A's operand errors).
    Own(Own),
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
        drives: Drives,
    },
    /// An output pin given an input event.
    IsAnOutput {
        /// The device as written.
        device: String,
        /// What events can drive.
        drives: Drives,
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
            DeviceError::Own(e) => e.fmt(f),
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
    /// A value the machine refuses in its own terms (a MINASEC-U knob,
    /// switch or clock out of range; a PLC-IO86A pin or filter setting in
    /// the terminal's words).
    Own(Own),
    /// MINASEC-U `C0=`: not a number.
    CounterPreset(String),
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
            SettingError::Own(e) => e.fmt(f),
            SettingError::CounterPreset(v) => {
                write!(f, "C0={v}: the counter set value is a number 0..99")
            }
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
