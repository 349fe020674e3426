//! `conveyor`: the MINASEC-U book's belt. Parts arrive at the infeed by
//! themselves when it is clear, ride the belt while the motor runs and
//! leave at its end past the outfeed eye. Starting the belt less than
//! `guard` ms after a part arrived is the book's danger: an alarm.
//!
//! Positions are in µm along the belt (0 = its start); a part's place is
//! its leading edge, so it covers `lead - part .. lead`.

use std::collections::VecDeque;

use super::alarm::AlarmKind;
use super::rng::Rng;
use super::{Direction, Kind, Misfit, ParamInfo, Plant, PlantInfo, QuantityInfo, SignalInfo};

/// Signal indexes.
const INFEED: usize = 0;
const OUTFEED: usize = 1;
const MOTOR: usize = 2;

/// Parameter indexes.
const LENGTH: usize = 0;
const SPEED: usize = 1;
const PART: usize = 2;
const INTERVAL: usize = 3;
const SPREAD: usize = 4;
const GUARD: usize = 5;
const SEED: usize = 6;

const UM_PER_MM: i64 = 1000;

static SIGNALS: [SignalInfo; 3] = [
    SignalInfo {
        name: "infeed",
        direction: Direction::In,
        kind: Kind::Bit,
        description: "a part is under the photo-eye at the belt's start",
    },
    SignalInfo {
        name: "outfeed",
        direction: Direction::In,
        kind: Kind::Bit,
        description: "a part is under the photo-eye at the belt's end",
    },
    SignalInfo {
        name: "motor",
        direction: Direction::Out,
        kind: Kind::Bit,
        description: "the belt runs",
    },
];

static QUANTITIES: [QuantityInfo; 3] = [
    QuantityInfo {
        name: "placed",
        description: "parts put on the belt",
        unit: "parts",
        range: (0, i64::MAX),
    },
    QuantityInfo {
        name: "delivered",
        description: "parts that left the belt's end",
        unit: "parts",
        range: (0, i64::MAX),
    },
    QuantityInfo {
        name: "on_belt",
        description: "parts on the belt now (at most length / part + 1)",
        unit: "parts",
        range: (0, 100_000 / 10 + 1),
    },
];

static PARAMS: [ParamInfo; 7] = [
    ParamInfo {
        key: "length",
        default: 2000,
        min: 200,
        max: 100_000,
        unit: "mm",
        description: "belt length, infeed to end",
    },
    ParamInfo {
        key: "speed",
        default: 250,
        min: 1,
        max: 10_000,
        unit: "mm/s",
        description: "belt speed while the motor runs",
    },
    ParamInfo {
        key: "part",
        default: 200,
        min: 10,
        max: 10_000,
        unit: "mm",
        description: "part length (at most half the belt)",
    },
    ParamInfo {
        key: "interval",
        default: 4000,
        min: 100,
        max: 3_600_000,
        unit: "ms",
        description: "time from one part's arrival to the next's earliest",
    },
    ParamInfo {
        key: "spread",
        default: 1000,
        min: 0,
        max: 3_600_000,
        unit: "ms",
        description: "random extra wait before each arrival, 0..spread",
    },
    ParamInfo {
        key: "guard",
        default: 1000,
        min: 0,
        max: 60_000,
        unit: "ms",
        description: "the belt must not start sooner than this after an arrival",
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

/// `conveyor`'s description.
pub static INFO: PlantInfo = PlantInfo {
    name: "conveyor",
    description: "the book's belt conveyor: parts arrive at the infeed eye, ride the belt while the motor runs and leave past the outfeed eye",
    signals: &SIGNALS,
    quantities: &QUANTITIES,
    params: &PARAMS,
};

/// The belt, its parts and its arrival schedule.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Conveyor {
    params: [i64; 7],
    /// Leading edges (µm), the one furthest along first.
    parts: VecDeque<i64>,
    placed: i64,
    delivered: i64,
    /// When the next part may arrive (ms since the start).
    next_arrival: i64,
    /// When the last part arrived.
    last_arrival: Option<i64>,
    motor_was: bool,
    rng: Rng,
}

impl Default for Conveyor {
    fn default() -> Self {
        Conveyor::new()
    }
}

impl Conveyor {
    /// A conveyor with the default parameters, empty.
    pub fn new() -> Conveyor {
        let mut c = Conveyor {
            params: PARAMS.map(|p| p.default),
            parts: VecDeque::new(),
            placed: 0,
            delivered: 0,
            next_arrival: 0,
            last_arrival: None,
            motor_was: false,
            rng: Rng::new(0),
        };
        c.reset();
        c
    }

    /// Where each part on the belt is: its leading edge in µm from the
    /// infeed (the one furthest along first), for drawing the belt.
    pub fn part_leads(&self) -> impl Iterator<Item = i64> + '_ {
        self.parts.iter().copied()
    }

    /// The belt's length and a part's length, in µm, for drawing.
    pub fn lengths_um(&self) -> (i64, i64) {
        (self.um(LENGTH), self.um(PART))
    }

    fn um(&self, param: usize) -> i64 {
        self.params[param] * UM_PER_MM
    }

    /// The infeed's place is free for a part: no part's tail within it.
    fn infeed_clear(&self) -> bool {
        let part = self.um(PART);
        self.parts.iter().all(|&lead| lead - part >= part)
    }

    fn schedule_after(&mut self, now_ms: i64) {
        self.next_arrival = self
            .rng
            .after(now_ms, self.params[INTERVAL], self.params[SPREAD]);
    }
}

impl Plant for Conveyor {
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

    fn check(&self) -> Result<(), Misfit> {
        if 2 * self.params[PART] > self.params[LENGTH] {
            return Err(Misfit::PartOverHalfBelt {
                part: self.params[PART],
                length: self.params[LENGTH],
            });
        }
        Ok(())
    }

    fn reset(&mut self) {
        self.parts.clear();
        self.placed = 0;
        self.delivered = 0;
        self.last_arrival = None;
        self.motor_was = false;
        self.rng = Rng::new(self.params[SEED] as u64);
        // The first part comes within the first spread.
        self.next_arrival = self.rng.up_to(self.params[SPREAD]);
    }

    fn step(&mut self, now_ms: i64, drive: &[i64], alarms: &mut Vec<String>) {
        let motor = drive.get(MOTOR).is_some_and(|&m| m != 0);
        if motor && !self.motor_was {
            let guard = self.params[GUARD];
            if let Some(since) = self.last_arrival.map(|t| now_ms - t) {
                if since < guard {
                    alarms.push(AlarmKind::BeltTooSoon { since, guard }.to_string());
                }
            }
        }
        self.motor_was = motor;
        if motor {
            // mm/s is µm/ms: one step moves `speed` µm.
            let moved = self.params[SPEED];
            let off_end = self.um(LENGTH) + self.um(PART);
            for lead in self.parts.iter_mut() {
                *lead += moved;
            }
            while self.parts.front().is_some_and(|&lead| lead >= off_end) {
                self.parts.pop_front();
                self.delivered += 1;
            }
        }
        if now_ms >= self.next_arrival && self.infeed_clear() {
            self.parts.push_back(self.um(PART));
            self.placed += 1;
            self.last_arrival = Some(now_ms);
            self.schedule_after(now_ms);
        }
    }

    fn sensor(&self, signal: usize) -> i64 {
        let on = match signal {
            // The infeed eye watches the place where parts land: on while
            // a part is there, so a part is never waiting unseen.
            INFEED => !self.infeed_clear(),
            // The outfeed eye sits at the very end: a part is delivered
            // as its tail passes it.
            OUTFEED => self
                .parts
                .front()
                .is_some_and(|&lead| lead >= self.um(LENGTH)),
            _ => false,
        };
        i64::from(on)
    }

    fn quantity(&self, index: usize) -> i64 {
        match index {
            0 => self.placed,
            1 => self.delivered,
            _ => self.parts.len() as i64,
        }
    }
}

#[cfg(test)]
#[path = "conveyor_tests.rs"]
mod tests;
