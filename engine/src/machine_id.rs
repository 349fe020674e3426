//! The five machines by their command-line and project-file names.

use std::fmt;

use serde::{Deserialize, Serialize};

/// One of the five simulated PLCs (../shared/spec/machines.md).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum MachineId {
    /// MINASEC-U, the logic-IC PLC.
    #[serde(rename = "minasec-u")]
    MinasecU,
    /// PLC-IO86A, the PIC-based FX-style PLC.
    #[serde(rename = "io86a")]
    Io86a,
    /// The AVR simplified PLC.
    #[serde(rename = "avr-plc")]
    AvrPlc,
    /// The Arduino PLC sketch.
    #[serde(rename = "arduino-plc")]
    ArduinoPlc,
    /// The soft PLC: a general IEC 61131-3 machine with word data.
    #[serde(rename = "soft-plc")]
    SoftPlc,
}

impl MachineId {
    /// Every machine, in the order the docs list them.
    pub const ALL: [MachineId; 5] = [
        MachineId::MinasecU,
        MachineId::Io86a,
        MachineId::AvrPlc,
        MachineId::ArduinoPlc,
        MachineId::SoftPlc,
    ];

    /// The machine's place in [`MachineId::ALL`] (for tables kept per
    /// machine in that order).
    pub fn index(self) -> usize {
        // ALL lists every machine: the position is always found.
        MachineId::ALL
            .iter()
            .position(|&m| m == self)
            .unwrap_or_default()
    }

    /// The four small PLCs of the seed documents: every machine but the
    /// soft PLC.
    pub const KITS: [MachineId; 4] = [
        MachineId::MinasecU,
        MachineId::Io86a,
        MachineId::AvrPlc,
        MachineId::ArduinoPlc,
    ];

    /// The name `--machine` and project files use.
    pub const fn name(self) -> &'static str {
        match self {
            MachineId::MinasecU => "minasec-u",
            MachineId::Io86a => "io86a",
            MachineId::AvrPlc => "avr-plc",
            MachineId::ArduinoPlc => "arduino-plc",
            MachineId::SoftPlc => "soft-plc",
        }
    }

    /// Parses a machine name.
    pub fn parse(id: &str) -> Result<MachineId, UnknownMachine> {
        MachineId::ALL
            .into_iter()
            .find(|m| m.name() == id)
            .ok_or_else(|| UnknownMachine(id.to_string()))
    }
}

/// A machine name that is none of the five (as written).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnknownMachine(pub String);

impl fmt::Display for UnknownMachine {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "unknown machine {}: minasec-u, io86a, avr-plc, arduino-plc or soft-plc",
            crate::error::shown(&self.0)
        )
    }
}

impl std::error::Error for UnknownMachine {}

impl fmt::Display for MachineId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
