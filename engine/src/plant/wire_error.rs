//! Why a wiring row is refused (issue #52): typed, so that the page says
//! it in its own language from the kind and its names, as it does the
//! alarms ([`super::alarm::AlarmKind`]); `Display` is the English the
//! command line says.

use std::fmt;

use super::PlantError;
use crate::error::shown;
use crate::plc::PlcError;

/// A wiring row the plant and the machine do not take. `full` is the
/// plant's signal with its plant (`tank.level`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum WireError {
    /// A signal the plant does not have.
    Signal(PlantError),
    /// A device the machine does not have.
    NoDevice {
        /// The plant's signal.
        full: String,
        /// The device as written.
        device: String,
        /// The machine's refusal.
        error: PlcError,
    },
    /// An analog input that takes no value from an analog sensor.
    AnalogRefused {
        /// The plant's signal.
        full: String,
        /// The device.
        device: String,
        /// The machine's refusal.
        error: PlcError,
    },
    /// An analog signal on a device that is no analog input.
    NotAnalog {
        /// The plant's signal.
        full: String,
        /// The device.
        device: String,
        /// The machine's name (`MINASEC-U`).
        machine: &'static str,
        /// The machine's analog inputs (none: it has none).
        analog: Vec<String>,
    },
    /// A sensor on a device the PLC does not read.
    SensorNeedsInput {
        /// The plant's signal.
        full: String,
        /// The machine's refusal.
        error: PlcError,
    },
    /// An actuator on an input.
    ActuatorOnInput {
        /// The plant's signal.
        full: String,
        /// The device.
        device: String,
    },
    /// A signal on two rows.
    Twice {
        /// The plant's signal.
        full: String,
    },
    /// A device on two rows.
    TwoSignals {
        /// The device.
        device: String,
        /// The plant's signal of the later row.
        full: String,
    },
}

impl fmt::Display for WireError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            WireError::Signal(e) => e.fmt(f),
            WireError::NoDevice {
                full,
                device,
                error,
            } => write!(f, "{full} on {}: {error}", shown(device)),
            WireError::AnalogRefused {
                full,
                device,
                error,
            } => write!(f, "{full} on {device}: {error}"),
            WireError::NotAnalog {
                full,
                device,
                machine,
                analog,
            } => {
                write!(
                    f,
                    "{full} is an analog signal and {device} is not an analog input ("
                )?;
                if analog.is_empty() {
                    write!(f, "{machine} has no analog input)")
                } else {
                    write!(f, "{machine}'s analog inputs are {})", analog.join(", "))
                }
            }
            WireError::SensorNeedsInput { full, error } => write!(
                f,
                "{full} is a sensor the PLC reads, so it needs an input: {error}"
            ),
            WireError::ActuatorOnInput { full, device } => write!(
                f,
                "{full} is an actuator the PLC drives, and {device} is an input"
            ),
            WireError::Twice { full } => write!(f, "{full} is wired twice"),
            WireError::TwoSignals { device, full } => {
                write!(f, "{device} carries two signals ({full} and another)")
            }
        }
    }
}

impl std::error::Error for WireError {}
