//! `traffic`: a pedestrian crossing. Cars have red, yellow and green;
//! pedestrians have walk and don't walk, and a request button. They
//! arrive on a seeded schedule, press the button once and wait; on walk
//! (with don't walk off) every waiting pedestrian steps onto the crossing
//! and counts as crossed. Green or yellow for cars while pedestrians have
//! walk is the alarm.

use std::collections::VecDeque;

use super::alarm::AlarmKind;
use super::rng::Rng;
use super::{Direction, Kind, ParamInfo, Plant, PlantInfo, QuantityInfo, SignalInfo};

/// Signal indexes.
const BUTTON: usize = 0;
const CAR_YELLOW: usize = 2;
const CAR_GREEN: usize = 3;
const WALK: usize = 4;
const DONT_WALK: usize = 5;

/// Parameter indexes.
const INTERVAL: usize = 0;
const SPREAD: usize = 1;
const PRESS: usize = 2;
const SEED: usize = 3;

/// The most pedestrians who wait at once; more walk away (so a crossing
/// that never gives walk stays bounded).
pub const MAX_WAITING: usize = 1000;

const fn out(name: &'static str, description: &'static str) -> SignalInfo {
    SignalInfo {
        name,
        direction: Direction::Out,
        kind: Kind::Bit,
        description,
    }
}

static SIGNALS: [SignalInfo; 6] = [
    SignalInfo {
        name: "button",
        direction: Direction::In,
        kind: Kind::Bit,
        description: "a pedestrian presses the request button",
    },
    out("car_red", "the cars' red light"),
    out("car_yellow", "the cars' yellow light"),
    out("car_green", "the cars' green light"),
    out("walk", "the pedestrians' walk light"),
    out("dont_walk", "the pedestrians' don't-walk light"),
];

static QUANTITIES: [QuantityInfo; 3] = [
    QuantityInfo {
        name: "crossed",
        description: "pedestrians who stepped onto the crossing on walk",
        unit: "people",
        range: (0, i64::MAX),
    },
    QuantityInfo {
        name: "waited_max",
        description:
            "the longest wait so far, from a pedestrian's arrival to walk (waits still going count)",
        unit: "ms",
        range: (0, i64::MAX),
    },
    QuantityInfo {
        name: "waiting",
        description: "pedestrians waiting now",
        unit: "people",
        range: (0, MAX_WAITING as i64),
    },
];

static PARAMS: [ParamInfo; 4] = [
    ParamInfo {
        key: "interval",
        default: 20_000,
        min: 100,
        max: 3_600_000,
        unit: "ms",
        description: "time from one pedestrian's arrival to the next's earliest",
    },
    ParamInfo {
        key: "spread",
        default: 10_000,
        min: 0,
        max: 3_600_000,
        unit: "ms",
        description: "random extra wait before each arrival, 0..spread",
    },
    ParamInfo {
        key: "press",
        default: 300,
        min: 1,
        max: 10_000,
        unit: "ms",
        description: "how long an arriving pedestrian holds the button",
    },
    ParamInfo {
        key: "seed",
        default: 1,
        min: 0,
        max: u32::MAX as i64,
        unit: "",
        description: "seed of the arrival schedule",
    },
];

/// `traffic`'s description.
pub static INFO: PlantInfo = PlantInfo {
    name: "traffic",
    description: "a pedestrian crossing: car lights, a pedestrian light and a request button pressed by pedestrians arriving on a seeded schedule",
    signals: &SIGNALS,
    quantities: &QUANTITIES,
    params: &PARAMS,
};

/// The crossing, its waiting pedestrians and their schedule.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Traffic {
    params: [i64; 4],
    /// Arrival times of the pedestrians waiting, the first first.
    waiting: VecDeque<i64>,
    crossed: i64,
    waited_max: i64,
    next_arrival: i64,
    /// The button is held until then (ms).
    pressed_until: i64,
    conflict: bool,
    /// The time at the end of the last step.
    now: i64,
    rng: Rng,
}

impl Default for Traffic {
    fn default() -> Self {
        Traffic::new()
    }
}

impl Traffic {
    /// A crossing with the default parameters, nobody waiting.
    pub fn new() -> Traffic {
        let mut t = Traffic {
            params: PARAMS.map(|p| p.default),
            waiting: VecDeque::new(),
            crossed: 0,
            waited_max: 0,
            next_arrival: 0,
            pressed_until: 0,
            conflict: false,
            now: 0,
            rng: Rng::new(0),
        };
        t.reset();
        t
    }
}

impl Plant for Traffic {
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
        if index == SEED {
            self.reset();
        }
    }

    fn reset(&mut self) {
        self.waiting.clear();
        self.crossed = 0;
        self.waited_max = 0;
        self.pressed_until = 0;
        self.conflict = false;
        self.now = 0;
        self.rng = Rng::new(self.params[SEED] as u64);
        self.next_arrival = self.rng.up_to(self.params[SPREAD]);
    }

    fn step(&mut self, now_ms: i64, drive: &[i64], alarms: &mut Vec<String>) {
        self.now = now_ms;
        let on = |i: usize| drive.get(i).is_some_and(|&v| v != 0);
        let cars_go = on(CAR_GREEN) || on(CAR_YELLOW);
        let conflict = cars_go && on(WALK);
        if conflict && !self.conflict {
            let green = on(CAR_GREEN);
            alarms.push(AlarmKind::CarsOnWalk { green }.to_string());
        }
        self.conflict = conflict;
        if now_ms >= self.next_arrival {
            // An arriving pedestrian presses the button, even on walk
            // (people do); on walk they step straight on.
            self.pressed_until = now_ms + self.params[PRESS];
            if self.waiting.len() < MAX_WAITING {
                self.waiting.push_back(now_ms);
            }
            self.next_arrival = self
                .rng
                .after(now_ms, self.params[INTERVAL], self.params[SPREAD]);
        }
        if let Some(&first) = self.waiting.front() {
            self.waited_max = self.waited_max.max(now_ms - first);
        }
        if on(WALK) && !on(DONT_WALK) {
            self.crossed += self.waiting.len() as i64;
            self.waiting.clear();
        }
    }

    fn sensor(&self, signal: usize) -> i64 {
        match signal {
            BUTTON => i64::from(self.pressed_until > self.now),
            _ => 0,
        }
    }

    fn quantity(&self, index: usize) -> i64 {
        match index {
            0 => self.crossed,
            1 => self.waited_max,
            _ => self.waiting.len() as i64,
        }
    }
}

#[cfg(test)]
#[path = "traffic_tests.rs"]
mod tests;
