//! `room-light`: the Arduino sketch's example. Daylight rises and falls
//! over a simulated day, from a table of hourly values (no floating
//! point: straight lines between the hours); a light sensor gives a bit
//! `dark` and an analog `light`; the PLC drives a lamp. The sensor faces
//! the window, so the lamp does not light it. A lamp on while it is light
//! is wasted: `lamp_on_ms`.

use super::{Direction, Kind, ParamInfo, Plant, PlantInfo, QuantityInfo, SignalInfo, ANALOG_FULL};

/// Signal indexes.
const DARK: usize = 0;
const LIGHT: usize = 1;
const LAMP: usize = 2;

/// Parameter indexes.
const DAY: usize = 0;
const START: usize = 1;
const DARK_BELOW: usize = 2;

/// Thousandths of a percent per percent.
const PER_PERCENT: i64 = ANALOG_FULL / 100;

/// Daylight at each hour of the day, 0 h to 24 h, in percent: night
/// until 5 h, full at noon, night again from 20 h.
pub const DAYLIGHT: [i64; 25] = [
    0, 0, 0, 0, 0, 5, 20, 40, 60, 75, 85, 95, 100, 95, 85, 75, 60, 40, 20, 5, 0, 0, 0, 0, 0,
];

static SIGNALS: [SignalInfo; 3] = [
    SignalInfo {
        name: "dark",
        direction: Direction::In,
        kind: Kind::Bit,
        description: "the light sensor reads less daylight than dark_below",
    },
    SignalInfo {
        name: "light",
        direction: Direction::In,
        kind: Kind::Analog,
        description: "the daylight, 0-100 % scaled to the analog input",
    },
    SignalInfo {
        name: "lamp",
        direction: Direction::Out,
        kind: Kind::Bit,
        description: "the room's lamp is on",
    },
];

static QUANTITIES: [QuantityInfo; 4] = [
    QuantityInfo {
        name: "lamp_on_ms",
        description: "time the lamp was on while it was light (wasted)",
        unit: "ms",
        range: (0, i64::MAX),
    },
    QuantityInfo {
        name: "unlit_ms",
        description: "time it was dark with the lamp off",
        unit: "ms",
        range: (0, i64::MAX),
    },
    QuantityInfo {
        name: "daylight",
        description: "the daylight now, whole percent",
        unit: "%",
        range: (0, 100),
    },
    QuantityInfo {
        name: "hour",
        description: "the simulated hour of the day, 0-23",
        unit: "h",
        range: (0, 23),
    },
];

static PARAMS: [ParamInfo; 3] = [
    ParamInfo {
        key: "day",
        default: 60_000,
        min: 2400,
        max: 86_400_000,
        unit: "ms",
        description: "the length of a simulated day",
    },
    ParamInfo {
        key: "start",
        default: 0,
        min: 0,
        max: 23,
        unit: "h",
        description: "the hour of the day at power-on",
    },
    ParamInfo {
        key: "dark_below",
        default: 30,
        min: 1,
        max: 100,
        unit: "%",
        description: "the sensor reads dark below this daylight",
    },
];

/// `room-light`'s description.
pub static INFO: PlantInfo = PlantInfo {
    name: "room-light",
    description: "the Arduino sketch's room light: daylight over a simulated day, a light sensor (a bit, and an analog value where the machine has one) and a lamp",
    signals: &SIGNALS,
    quantities: &QUANTITIES,
    params: &PARAMS,
};

/// The room, its window and its lamp.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RoomLight {
    params: [i64; 3],
    /// ms into the simulated day.
    time_of_day: i64,
    lamp_on_ms: i64,
    unlit_ms: i64,
}

impl Default for RoomLight {
    fn default() -> Self {
        RoomLight::new()
    }
}

impl RoomLight {
    /// A room with the default parameters, at its start hour.
    pub fn new() -> RoomLight {
        let mut r = RoomLight {
            params: PARAMS.map(|p| p.default),
            time_of_day: 0,
            lamp_on_ms: 0,
            unlit_ms: 0,
        };
        r.reset();
        r
    }

    /// The daylight now, 0..=[`ANALOG_FULL`]: a straight line between the
    /// table's hours.
    fn daylight(&self) -> i64 {
        let day = self.params[DAY];
        let at = self.time_of_day.rem_euclid(day) * 24;
        let hour = (at / day).clamp(0, 23) as usize;
        let into = at % day;
        let (from, to) = (DAYLIGHT[hour], DAYLIGHT[hour + 1]);
        (from * day + (to - from) * into) * PER_PERCENT / day
    }

    fn dark(&self) -> bool {
        self.daylight() < self.params[DARK_BELOW] * PER_PERCENT
    }
}

impl Plant for RoomLight {
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
        if index == START || index == DAY {
            // The clock is set to the start hour of a day of the new length.
            self.time_of_day = self.params[START] * self.params[DAY] / 24;
        }
    }

    fn reset(&mut self) {
        self.time_of_day = self.params[START] * self.params[DAY] / 24;
        self.lamp_on_ms = 0;
        self.unlit_ms = 0;
    }

    fn step(&mut self, _now_ms: i64, drive: &[i64], _alarms: &mut Vec<String>) {
        let lamp = drive.get(LAMP).is_some_and(|&v| v != 0);
        // The step's light is the one at its start, as the sensor read it.
        match (self.dark(), lamp) {
            (false, true) => self.lamp_on_ms += 1,
            (true, false) => self.unlit_ms += 1,
            _ => {}
        }
        self.time_of_day = (self.time_of_day + 1) % self.params[DAY];
    }

    fn sensor(&self, signal: usize) -> i64 {
        match signal {
            DARK => i64::from(self.dark()),
            LIGHT => self.daylight(),
            _ => 0,
        }
    }

    fn quantity(&self, index: usize) -> i64 {
        match index {
            0 => self.lamp_on_ms,
            1 => self.unlit_ms,
            2 => self.daylight() / PER_PERCENT,
            _ => (self.time_of_day * 24 / self.params[DAY]).clamp(0, 23),
        }
    }
}

#[cfg(test)]
#[path = "room_light_tests.rs"]
mod tests;
