//! Plants: simulated machines for the ladder to control (issue #50,
//! docs/plants.md). A plant has named signals (`in`: sensors the PLC
//! reads; `out`: actuators it drives), quantities to watch and test,
//! documented parameters and alarms. It moves on the machine's simulated
//! clock in fixed steps of [`STEP`], in integer arithmetic only, so a run
//! gives the same rows natively and in wasm. [`Planted`] attaches one to a
//! machine through the one [`crate::plc::Plc`] interface; the plants name
//! no machine: a machine's terminals come from [`crate::plc::Plc::terminals`].

pub mod alarm;
pub mod any;
mod boxed;
pub mod conveyor;
mod coupling;
pub mod door;
pub mod error;
pub mod fault;
mod misfit;
mod planted;
mod rng;
pub mod room_light;
pub mod sorter;
pub mod tank;
pub mod traffic;
mod wire_error;
pub mod wiring;

pub use any::AnyPlant;
pub use coupling::Coupling;
pub use error::PlantError;
pub use fault::{Fault, FaultKind};
pub use misfit::Misfit;
pub use planted::{Planted, PlantedError};
pub use wiring::{Wire, WireEntry};

use crate::time::SimTime;

/// The plant's fixed time step: every plant moves 1 ms at a time.
pub const STEP: SimTime = SimTime::from_millis(1);

/// Full scale of an analog signal: 0..=ANALOG_FULL is 0–100 % in
/// thousandths of a percent.
pub const ANALOG_FULL: i64 = 100_000;

/// Whether the PLC reads a signal or drives it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    /// A sensor: the PLC reads it.
    In,
    /// An actuator: the PLC drives it.
    Out,
}

/// What a signal carries.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// 0 or 1.
    Bit,
    /// 0..=[`ANALOG_FULL`] (0–100 %).
    Analog,
}

/// One signal of a plant.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SignalInfo {
    /// Its name (`infeed`).
    pub name: &'static str,
    /// In or out.
    pub direction: Direction,
    /// Bit or analog.
    pub kind: Kind,
    /// What it is, in words.
    pub description: &'static str,
}

/// One quantity a plant shows for watching and tests.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct QuantityInfo {
    /// Its name (`delivered`).
    pub name: &'static str,
    /// What it is.
    pub description: &'static str,
    /// Its unit (`parts`, `%`).
    pub unit: &'static str,
    /// Its documented range (an upper bound of `i64::MAX`: unbounded).
    pub range: (i64, i64),
}

/// One parameter of a plant: a whole number within its range.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ParamInfo {
    /// Its key (`speed`).
    pub key: &'static str,
    /// Its value on a new plant.
    pub default: i64,
    /// The values it takes.
    pub min: i64,
    /// The values it takes.
    pub max: i64,
    /// Its unit; `ms` parameters also take times (`1.5s`).
    pub unit: &'static str,
    /// What it sets.
    pub description: &'static str,
}

/// What `hashigo plants` lists of a plant.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PlantInfo {
    /// Its name (`conveyor`).
    pub name: &'static str,
    /// The plant in a sentence.
    pub description: &'static str,
    /// Its signals.
    pub signals: &'static [SignalInfo],
    /// Its quantities (the framework adds `alarms`).
    pub quantities: &'static [QuantityInfo],
    /// Its parameters.
    pub params: &'static [ParamInfo],
}

impl PlantInfo {
    /// The signal called `name`, by index.
    pub fn signal(&self, name: &str) -> Option<usize> {
        self.signals.iter().position(|s| s.name == name)
    }

    /// The signal called `name` (or `PLANT.name`), by index, or the error
    /// naming the plant's signals.
    pub fn signal_named(&self, name: &str) -> Result<usize, PlantError> {
        let name = name
            .strip_prefix(self.name)
            .and_then(|n| n.strip_prefix('.'))
            .unwrap_or(name);
        self.signal(name).ok_or_else(|| PlantError::UnknownSignal {
            plant: self.name,
            name: name.to_string(),
            known: self.signal_names(),
        })
    }

    /// The signals' names, for messages.
    pub fn signal_names(&self) -> String {
        let names: Vec<_> = self.signals.iter().map(|s| s.name).collect();
        names.join(", ")
    }
}

/// The quantity every plant has: alarms raised so far.
pub const ALARMS: QuantityInfo = QuantityInfo {
    name: "alarms",
    description: "alarms raised so far (each counted once, when it begins)",
    unit: "alarms",
    range: (0, i64::MAX),
};

/// An alarm a plant raises as it begins: what a real machine did wrong.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Alarm {
    /// When it began (the end of the step that raised it).
    pub at: SimTime,
    /// What happened, in words.
    pub message: String,
}

/// A simulated machine for the PLC to control.
pub trait Plant {
    /// What it is: signals, quantities, parameters.
    fn info(&self) -> &'static PlantInfo;

    /// The parameters' values, in [`PlantInfo::params`] order.
    fn params(&self) -> &[i64];

    /// Sets parameter `index` (within its range: the caller checks).
    fn set_param(&mut self, index: usize, value: i64);

    /// A problem with the parameters together (a part longer than half
    /// the belt), if there is one.
    fn check(&self) -> Result<(), Misfit> {
        Ok(())
    }

    /// Back to its start, with its parameters as they are (the machine's
    /// power cycle; its seeded schedule starts over).
    fn reset(&mut self);

    /// Moves one [`STEP`]; `now_ms` is the plant's time at the step's end
    /// (ms since its start), `drive` the values acting on each signal (by
    /// signal index; `in` signals' entries are unused). Alarms that begin
    /// are pushed to `alarms` as messages.
    fn step(&mut self, now_ms: i64, drive: &[i64], alarms: &mut Vec<String>);

    /// An `in` signal's value now (0/1, or 0..=[`ANALOG_FULL`]).
    fn sensor(&self, signal: usize) -> i64;

    /// A quantity's value now, by index in [`PlantInfo::quantities`].
    fn quantity(&self, index: usize) -> i64;
}

/// Parses a parameter's value: a whole number, or for an `ms` parameter
/// a time (`1.5s`, `250ms`); checked against its range.
pub fn parse_param(info: &ParamInfo, text: &str) -> Result<i64, PlantError> {
    let text = text.trim();
    let value = if info.unit == "ms" {
        SimTime::parse(text)
            .ok()
            .and_then(|t| i64::try_from(t.as_nanos() / 1_000_000).ok())
    } else {
        text.parse::<i64>().ok()
    };
    let range = format!("{}..{} {}", info.min, info.max, info.unit);
    let range = range.trim_end().to_string();
    match value {
        Some(v) if (info.min..=info.max).contains(&v) => Ok(v),
        Some(value) => Err(PlantError::OutOfRange {
            key: info.key,
            value,
            range,
        }),
        None => Err(PlantError::NotANumber {
            key: info.key,
            text: text.to_string(),
            range,
        }),
    }
}
