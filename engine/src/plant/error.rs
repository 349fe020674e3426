//! What a plant refuses: a fault, a parameter, a name.

use std::fmt;

use super::Misfit;
use crate::error::shown;
use crate::time::TimeError;

/// A fault or parameter the plant does not take.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PlantError {
    /// A signal the plant does not have.
    UnknownSignal {
        /// The plant.
        plant: &'static str,
        /// The name as written.
        name: String,
        /// Its signals, for the message.
        known: String,
    },
    /// A fault that is not `SIGNAL stuck 0|1 [from TIME]` or
    /// `SIGNAL dead [from TIME]`.
    FaultUsage,
    /// A fault's `from` time that does not parse.
    FaultTime(String, TimeError),
    /// A fault on an analog signal (`tank.level`).
    AnalogFault(String),
    /// `dead` on a sensor.
    DeadSensor(String),
    /// A parameter the plant does not have.
    UnknownParam {
        /// The plant.
        plant: &'static str,
        /// The key as written.
        key: String,
        /// Its parameters, for the message.
        known: String,
    },
    /// A parameter's value that is no whole number (or time).
    NotANumber {
        /// The parameter.
        key: &'static str,
        /// The value as written.
        text: String,
        /// Its range, in words.
        range: String,
    },
    /// A parameter's value out of its range.
    OutOfRange {
        /// The parameter.
        key: &'static str,
        /// The value.
        value: i64,
        /// Its range, in words.
        range: String,
    },
    /// Parameters that do not fit together (the plant's own check).
    Together(Misfit),
    /// A plant name that is none of the plants.
    NoPlant {
        /// The name as written.
        name: String,
        /// The plants, for the message.
        known: String,
    },
}

impl fmt::Display for PlantError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PlantError::UnknownSignal { plant, name, known } => write!(
                f,
                "{plant} has no signal {} (its signals: {known})",
                shown(name)
            ),
            PlantError::FaultUsage => {
                f.write_str("expected SIGNAL stuck 0|1 [from TIME] [hidden] or SIGNAL dead [from TIME] [hidden]")
            }
            PlantError::FaultTime(time, e) => write!(f, "from {}: {e}", shown(time)),
            PlantError::AnalogFault(s) => write!(f, "{s} is analog: only bit signals take faults"),
            PlantError::DeadSensor(s) => write!(
                f,
                "{s} is a sensor: dead is for actuators (a sensor that reads nothing is stuck 0)"
            ),
            PlantError::UnknownParam { plant, key, known } => write!(
                f,
                "{plant} has no parameter {} (its parameters: {known})",
                shown(key)
            ),
            PlantError::NotANumber { key, text, range } => write!(
                f,
                "{key} takes a whole number ({range}), not {}",
                shown(text)
            ),
            PlantError::OutOfRange { key, value, range } => {
                write!(f, "{key} = {value} is out of range ({range})")
            }
            PlantError::Together(e) => e.fmt(f),
            PlantError::NoPlant { name, known } => {
                write!(f, "no plant {} (the plants: {known})", shown(name))
            }
        }
    }
}

impl std::error::Error for PlantError {}
