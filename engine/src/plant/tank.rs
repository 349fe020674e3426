//! `tank`: a tank with an inflow valve (`fill`), an outflow valve
//! (`drain`), a steady demand drawn by the process, low and high level
//! switches and an analog level. Filling a full tank overflows: an alarm.
//!
//! The level is kept in thousandths of a percent (0..=[`ANALOG_FULL`]).

use super::alarm::AlarmKind;
use super::{
    Direction, Kind, Misfit, ParamInfo, Plant, PlantInfo, QuantityInfo, SignalInfo, ANALOG_FULL,
};

/// Signal indexes.
const LOW: usize = 0;
const HIGH: usize = 1;
const LEVEL: usize = 2;
const FILL: usize = 3;
const DRAIN: usize = 4;

/// Parameter indexes.
const FILL_RATE: usize = 0;
const DRAIN_RATE: usize = 1;
const DEMAND: usize = 2;
const LOW_AT: usize = 3;
const HIGH_AT: usize = 4;
const START: usize = 5;

/// Thousandths of a percent per percent.
const PER_PERCENT: i64 = ANALOG_FULL / 100;

static SIGNALS: [SignalInfo; 5] = [
    SignalInfo {
        name: "low",
        direction: Direction::In,
        kind: Kind::Bit,
        description: "the level is at or above the low switch",
    },
    SignalInfo {
        name: "high",
        direction: Direction::In,
        kind: Kind::Bit,
        description: "the level is at or above the high switch",
    },
    SignalInfo {
        name: "level",
        direction: Direction::In,
        kind: Kind::Analog,
        description: "the level, 0-100 % scaled to the analog input",
    },
    SignalInfo {
        name: "fill",
        direction: Direction::Out,
        kind: Kind::Bit,
        description: "the inflow valve is open",
    },
    SignalInfo {
        name: "drain",
        direction: Direction::Out,
        kind: Kind::Bit,
        description: "the outflow valve is open",
    },
];

static QUANTITIES: [QuantityInfo; 2] = [
    QuantityInfo {
        name: "level",
        description: "the level, whole percent",
        unit: "%",
        range: (0, 100),
    },
    QuantityInfo {
        name: "overflow_ms",
        description: "time the tank ran over, in all",
        unit: "ms",
        range: (0, i64::MAX),
    },
];

static PARAMS: [ParamInfo; 6] = [
    ParamInfo {
        key: "fill_rate",
        default: 8,
        min: 0,
        max: 100,
        unit: "%/s",
        description: "inflow with the fill valve open",
    },
    ParamInfo {
        key: "drain_rate",
        default: 6,
        min: 0,
        max: 100,
        unit: "%/s",
        description: "outflow with the drain valve open",
    },
    ParamInfo {
        key: "demand",
        default: 2,
        min: 0,
        max: 100,
        unit: "%/s",
        description: "outflow the process draws all the time",
    },
    ParamInfo {
        key: "low_at",
        default: 20,
        min: 0,
        max: 100,
        unit: "%",
        description: "where the low switch sits",
    },
    ParamInfo {
        key: "high_at",
        default: 80,
        min: 0,
        max: 100,
        unit: "%",
        description: "where the high switch sits",
    },
    ParamInfo {
        key: "start",
        default: 50,
        min: 0,
        max: 100,
        unit: "%",
        description: "the level at power-on",
    },
];

/// `tank`'s description.
pub static INFO: PlantInfo = PlantInfo {
    name: "tank",
    description: "a tank with fill and drain valves, a steady demand, low and high level switches and an analog level",
    signals: &SIGNALS,
    quantities: &QUANTITIES,
    params: &PARAMS,
};

/// The tank and its level.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Tank {
    params: [i64; 6],
    level: i64,
    overflowing: bool,
    overflow_ms: i64,
}

impl Default for Tank {
    fn default() -> Self {
        Tank::new()
    }
}

impl Tank {
    /// A tank with the default parameters, at its start level.
    pub fn new() -> Tank {
        let mut t = Tank {
            params: PARAMS.map(|p| p.default),
            level: 0,
            overflowing: false,
            overflow_ms: 0,
        };
        t.reset();
        t
    }
}

impl Plant for Tank {
    fn info(&self) -> &'static PlantInfo {
        &INFO
    }

    fn params(&self) -> &[i64] {
        &self.params
    }

    fn set_param(&mut self, index: usize, value: i64) {
        if let Some(p) = self.params.get_mut(index) {
            *p = value;
        }
        if index == START {
            self.level = value * PER_PERCENT;
        }
    }

    fn check(&self) -> Result<(), Misfit> {
        if self.params[LOW_AT] > self.params[HIGH_AT] {
            return Err(Misfit::LowAboveHigh {
                low: self.params[LOW_AT],
                high: self.params[HIGH_AT],
            });
        }
        Ok(())
    }

    fn reset(&mut self) {
        self.level = self.params[START] * PER_PERCENT;
        self.overflowing = false;
        self.overflow_ms = 0;
    }

    fn step(&mut self, _now_ms: i64, drive: &[i64], alarms: &mut Vec<String>) {
        let on = |i: usize| drive.get(i).is_some_and(|&v| v != 0);
        // %/s is thousandths of a percent per ms.
        let inflow = if on(FILL) { self.params[FILL_RATE] } else { 0 };
        let mut outflow = self.params[DEMAND];
        if on(DRAIN) {
            outflow += self.params[DRAIN_RATE];
        }
        let wanted = self.level + inflow - outflow;
        let over = wanted > ANALOG_FULL && inflow > 0;
        if over && !self.overflowing {
            alarms.push(AlarmKind::Overflow.to_string());
        }
        self.overflowing = over;
        if over {
            self.overflow_ms += 1;
        }
        self.level = wanted.clamp(0, ANALOG_FULL);
    }

    fn sensor(&self, signal: usize) -> i64 {
        match signal {
            LOW => i64::from(self.level >= self.params[LOW_AT] * PER_PERCENT),
            HIGH => i64::from(self.level >= self.params[HIGH_AT] * PER_PERCENT),
            LEVEL => self.level,
            _ => 0,
        }
    }

    fn quantity(&self, index: usize) -> i64 {
        match index {
            0 => self.level / PER_PERCENT,
            _ => self.overflow_ms,
        }
    }
}

#[cfg(test)]
#[path = "tank_tests.rs"]
mod tests;
