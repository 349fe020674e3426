//! `sorter`: tall and short parts ride a belt past a height sensor to a
//! pusher. A tall part belongs in the pusher's bin, a short one in the bin
//! at the belt's end. A part fully in front of the pusher's face is held
//! by it as it extends and drops into its bin at the end of the stroke;
//! the pusher out of its home position while a part is only partly in
//! front of its face hits that part: an alarm, and the part is knocked
//! off (wrong).
//!
//! Positions are in µm along the belt (0 = its start); a part's place is
//! its leading edge, so it covers `lead - part .. lead`.

use std::collections::VecDeque;

use super::alarm::AlarmKind;
use super::rng::Rng;
use super::{Direction, Kind, Misfit, ParamInfo, Plant, PlantInfo, QuantityInfo, SignalInfo};

/// Signal indexes.
const PART: usize = 0;
const TALL: usize = 1;
const PUSHER_OUT: usize = 2;
const PUSHER_IN: usize = 3;
const BELT: usize = 4;
const PUSH: usize = 5;

/// Parameter indexes.
const LENGTH: usize = 0;
const SPEED: usize = 1;
const SIZE: usize = 2;
const HEIGHT_AT: usize = 3;
const PUSHER_AT: usize = 4;
const FACE: usize = 5;
const STROKE: usize = 6;
const INTERVAL: usize = 7;
const SPREAD: usize = 8;
const TALL_PCT: usize = 9;
const SEED: usize = 10;

const UM_PER_MM: i64 = 1000;

const fn bit(name: &'static str, direction: Direction, description: &'static str) -> SignalInfo {
    SignalInfo {
        name,
        direction,
        kind: Kind::Bit,
        description,
    }
}

const fn param(
    key: &'static str,
    default: i64,
    (min, max): (i64, i64),
    unit: &'static str,
    description: &'static str,
) -> ParamInfo {
    ParamInfo {
        key,
        default,
        min,
        max,
        unit,
        description,
    }
}

static SIGNALS: [SignalInfo; 6] = [
    bit(
        "part",
        Direction::In,
        "a part is fully in front of the pusher's face",
    ),
    bit("tall", Direction::In, "the height sensor sees a tall part"),
    bit(
        "pusher_out",
        Direction::In,
        "the pusher is fully out (end switch)",
    ),
    bit(
        "pusher_in",
        Direction::In,
        "the pusher is fully in, at home (end switch)",
    ),
    bit("belt", Direction::Out, "the belt runs"),
    bit(
        "push",
        Direction::Out,
        "the pusher's valve: out while on, back in while off",
    ),
];

static QUANTITIES: [QuantityInfo; 3] = [
    QuantityInfo {
        name: "right",
        description: "parts in the right bin (tall pushed off, short at the belt's end)",
        unit: "parts",
        range: (0, i64::MAX),
    },
    QuantityInfo {
        name: "wrong",
        description: "parts in the wrong bin, or knocked off by the pusher",
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

static PARAMS: [ParamInfo; 11] = [
    param(
        "length",
        1000,
        (100, 100_000),
        "mm",
        "belt length, start to end",
    ),
    param(
        "speed",
        100,
        (1, 10_000),
        "mm/s",
        "belt speed while it runs",
    ),
    param(
        "part",
        50,
        (10, 10_000),
        "mm",
        "part length (at most the face)",
    ),
    param(
        "height_at",
        400,
        (0, 100_000),
        "mm",
        "where the height sensor looks",
    ),
    param(
        "pusher_at",
        500,
        (0, 100_000),
        "mm",
        "where the pusher's face begins",
    ),
    param(
        "face",
        80,
        (10, 10_000),
        "mm",
        "the pusher's face, along the belt",
    ),
    param(
        "stroke",
        500,
        (1, 10_000),
        "ms",
        "the pusher's time from in to out (and back)",
    ),
    param(
        "interval",
        3000,
        (100, 3_600_000),
        "ms",
        "time from one part's arrival to the next's earliest",
    ),
    param(
        "spread",
        2000,
        (0, 3_600_000),
        "ms",
        "random extra wait before each arrival, 0..spread",
    ),
    param("tall", 50, (0, 100), "%", "the share of tall parts"),
    param(
        "seed",
        1,
        (0, u32::MAX as i64),
        "",
        "seed of the arrivals and their heights",
    ),
];

/// `sorter`'s description.
pub static INFO: PlantInfo = PlantInfo {
    name: "sorter",
    description: "a sorter: tall and short parts on a belt, a height sensor, a part sensor at a pusher with end switches, a bin for pushed parts and one at the belt's end",
    signals: &SIGNALS,
    quantities: &QUANTITIES,
    params: &PARAMS,
};

/// One part on the belt.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Part {
    /// Its leading edge (µm).
    lead: i64,
    tall: bool,
    /// Held by the pusher's face (it no longer rides the belt).
    held: bool,
}

/// The belt, its parts, the pusher and the arrival schedule.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Sorter {
    params: [i64; 11],
    /// The parts, the one furthest along first.
    parts: VecDeque<Part>,
    /// The pusher's place: 0 in ..= `stroke` out (ms of travel).
    pusher: i64,
    right: i64,
    wrong: i64,
    next_arrival: i64,
    rng: Rng,
}

impl Default for Sorter {
    fn default() -> Self {
        Sorter::new()
    }
}

impl Sorter {
    /// A sorter with the default parameters, empty, the pusher in.
    pub fn new() -> Sorter {
        let mut s = Sorter {
            params: PARAMS.map(|p| p.default),
            parts: VecDeque::new(),
            pusher: 0,
            right: 0,
            wrong: 0,
            next_arrival: 0,
            rng: Rng::new(0),
        };
        s.reset();
        s
    }

    fn um(&self, param: usize) -> i64 {
        self.params[param] * UM_PER_MM
    }

    /// Where `p` lies against the face: (overlaps it, fully in front).
    fn at_face(&self, p: &Part) -> (bool, bool) {
        let (from, to) = (self.um(PUSHER_AT), self.um(PUSHER_AT) + self.um(FACE));
        let tail = p.lead - self.um(SIZE);
        (p.lead > from && tail < to, tail >= from && p.lead <= to)
    }

    /// The pusher acts on the parts at its face: holds those fully in
    /// front, knocks off those partly in front, drops the held ones into
    /// its bin at the end of the stroke.
    fn push(&mut self, alarms: &mut Vec<String>) {
        let out = self.pusher >= self.params[STROKE];
        let mut kept = VecDeque::with_capacity(self.parts.len());
        for mut p in std::mem::take(&mut self.parts) {
            let (overlaps, in_front) = self.at_face(&p);
            if self.pusher == 0 || !overlaps {
                p.held = false;
                kept.push_back(p);
            } else if in_front || p.held {
                if out {
                    self.count(p.tall);
                } else {
                    p.held = true;
                    kept.push_back(p);
                }
            } else {
                alarms.push(AlarmKind::PusherHit { tall: p.tall }.to_string());
                self.wrong += 1;
            }
        }
        self.parts = kept;
    }

    fn count(&mut self, right: bool) {
        if right {
            self.right += 1;
        } else {
            self.wrong += 1;
        }
    }

    fn arrive(&mut self, now_ms: i64) {
        let size = self.um(SIZE);
        if now_ms < self.next_arrival || self.parts.iter().any(|p| p.lead - size < size) {
            return;
        }
        let tall = self.rng.up_to(99) < self.params[TALL_PCT];
        self.parts.push_back(Part {
            lead: size,
            tall,
            held: false,
        });
        self.next_arrival = self
            .rng
            .after(now_ms, self.params[INTERVAL], self.params[SPREAD]);
    }
}

impl Plant for Sorter {
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
        let p = &self.params;
        if p[SIZE] > p[FACE] {
            return Err(Misfit::PartOverFace {
                part: p[SIZE],
                face: p[FACE],
            });
        }
        if 2 * p[SIZE] > p[LENGTH] || p[PUSHER_AT] + p[FACE] > p[LENGTH] {
            return Err(Misfit::BeltTooShort {
                length: p[LENGTH],
                part: p[SIZE],
                from: p[PUSHER_AT],
                to: p[PUSHER_AT] + p[FACE],
            });
        }
        Ok(())
    }

    fn reset(&mut self) {
        self.parts.clear();
        self.pusher = 0;
        self.right = 0;
        self.wrong = 0;
        self.rng = Rng::new(self.params[SEED] as u64);
        self.next_arrival = self.rng.up_to(self.params[SPREAD]);
    }

    fn step(&mut self, now_ms: i64, drive: &[i64], alarms: &mut Vec<String>) {
        let on = |i: usize| drive.get(i).is_some_and(|&v| v != 0);
        let stroke = self.params[STROKE];
        self.pusher = if on(PUSH) {
            (self.pusher + 1).min(stroke)
        } else {
            (self.pusher - 1).clamp(0, stroke)
        };
        self.push(alarms);
        if on(BELT) {
            // mm/s is µm/ms.
            let (moved, size, end) = (self.params[SPEED], self.um(SIZE), self.um(LENGTH));
            for p in self.parts.iter_mut().filter(|p| !p.held) {
                p.lead += moved;
            }
            while let Some(i) = self.parts.iter().position(|p| p.lead - size >= end) {
                if let Some(p) = self.parts.remove(i) {
                    self.count(!p.tall);
                }
            }
        }
        self.arrive(now_ms);
    }

    fn sensor(&self, signal: usize) -> i64 {
        let on = match signal {
            PART => self.parts.iter().any(|p| self.at_face(p).1),
            TALL => {
                let at = self.um(HEIGHT_AT);
                let size = self.um(SIZE);
                (self.parts.iter()).any(|p| p.tall && p.lead > at && p.lead - size <= at)
            }
            PUSHER_OUT => self.pusher >= self.params[STROKE],
            PUSHER_IN => self.pusher == 0,
            _ => false,
        };
        i64::from(on)
    }

    fn quantity(&self, index: usize) -> i64 {
        match index {
            0 => self.right,
            1 => self.wrong,
            _ => self.parts.len() as i64,
        }
    }
}

#[cfg(test)]
#[path = "sorter_tests.rs"]
mod tests;
