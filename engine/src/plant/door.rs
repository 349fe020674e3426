//! `door`: a garage door. A motor drives it up or down between a top and
//! a bottom limit switch; a photo-eye across the opening is blocked now
//! and then (a car, a child), and a remote button is pressed, both on a
//! seeded schedule. Alarms: both directions at once, driving on against a
//! limit, and closing while the eye is blocked.
//!
//! The position is kept in units of [`FULL`] (0 closed ..= [`FULL`]
//! open), fine enough that any travel time moves it evenly.

use super::alarm::AlarmKind;
use super::rng::Rng;
use super::{Direction, Kind, ParamInfo, Plant, PlantInfo, QuantityInfo, SignalInfo};

/// Signal indexes.
const TOP: usize = 0;
const BOTTOM: usize = 1;
const EYE: usize = 2;
const REMOTE: usize = 3;
const UP: usize = 4;
const DOWN: usize = 5;

/// Parameter indexes.
const TRAVEL: usize = 0;
const START: usize = 1;
const REMOTE_EVERY: usize = 2;
const REMOTE_SPREAD: usize = 3;
const PRESS: usize = 4;
const EYE_EVERY: usize = 5;
const EYE_SPREAD: usize = 6;
const BLOCKED: usize = 7;
const GRACE: usize = 8;
const SEED: usize = 9;

/// Fully open: a number every travel time of whole seconds divides, so
/// the door moves evenly (3.6e11).
pub const FULL: i64 = 360_000_000_000;

const fn bit(name: &'static str, direction: Direction, description: &'static str) -> SignalInfo {
    SignalInfo {
        name,
        direction,
        kind: Kind::Bit,
        description,
    }
}

const fn ms(key: &'static str, default: i64, min: i64, description: &'static str) -> ParamInfo {
    ParamInfo {
        key,
        default,
        min,
        max: 3_600_000,
        unit: "ms",
        description,
    }
}

static SIGNALS: [SignalInfo; 6] = [
    bit(
        "top",
        Direction::In,
        "the top limit switch: the door is fully open",
    ),
    bit(
        "bottom",
        Direction::In,
        "the bottom limit switch: the door is closed",
    ),
    bit(
        "eye",
        Direction::In,
        "the photo-eye across the opening is blocked",
    ),
    bit("remote", Direction::In, "the remote's button is pressed"),
    bit("up", Direction::Out, "the motor drives the door up (opens)"),
    bit(
        "down",
        Direction::Out,
        "the motor drives the door down (closes)",
    ),
];

static QUANTITIES: [QuantityInfo; 1] = [QuantityInfo {
    name: "position",
    description: "how far the door is open, whole percent (0 closed, 100 open)",
    unit: "%",
    range: (0, 100),
}];

static PARAMS: [ParamInfo; 10] = [
    ms("travel", 10_000, 100, "time to drive from closed to open (and back)"),
    ParamInfo {
        key: "start",
        default: 0,
        min: 0,
        max: 100,
        unit: "%",
        description: "how far the door is open at power-on",
    },
    ms("remote_every", 30_000, 100, "time from one press of the remote to the next's earliest"),
    ms("remote_spread", 10_000, 0, "random extra wait before each press, 0..remote_spread"),
    ms("press", 300, 1, "how long the remote's button is held"),
    ms("eye_every", 45_000, 100, "time from one blocking of the eye to the next's earliest"),
    ms("eye_spread", 15_000, 0, "random extra wait before each blocking, 0..eye_spread"),
    ms("blocked", 2000, 1, "how long the eye stays blocked"),
    ParamInfo {
        key: "grace",
        default: 200,
        min: 0,
        max: 10_000,
        unit: "ms",
        description: "how long the motor may go on against a limit or a blocked eye before the alarm (the PLC's reaction time)",
    },
    ParamInfo {
        key: "seed",
        default: 1,
        min: 0,
        max: u32::MAX as i64,
        unit: "",
        description: "seed of the remote's and the eye's schedules",
    },
];

/// `door`'s description.
pub static INFO: PlantInfo = PlantInfo {
    name: "door",
    description: "a garage door: a motor up and down, top and bottom limit switches, a photo-eye and a remote button, both used on a seeded schedule",
    signals: &SIGNALS,
    quantities: &QUANTITIES,
    params: &PARAMS,
};

/// Which alarms are on now (each is raised as it begins).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Alarms {
    both: bool,
    limit: bool,
    eye: bool,
}

/// The door, its remote and its photo-eye.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Door {
    params: [i64; 10],
    position: i64,
    now: i64,
    next_press: i64,
    pressed_until: i64,
    next_block: i64,
    blocked_until: i64,
    on: Alarms,
    /// How long the motor has driven against a limit, and closed on the
    /// blocked eye, without a break (ms).
    against_ms: i64,
    eye_ms: i64,
    rng: Rng,
}

impl Default for Door {
    fn default() -> Self {
        Door::new()
    }
}

impl Door {
    /// A door with the default parameters, at its start position.
    pub fn new() -> Door {
        let mut d = Door {
            params: PARAMS.map(|p| p.default),
            position: 0,
            now: 0,
            next_press: 0,
            pressed_until: 0,
            next_block: 0,
            blocked_until: 0,
            on: Alarms::default(),
            against_ms: 0,
            eye_ms: 0,
            rng: Rng::new(0),
        };
        d.reset();
        d
    }

    fn blocked(&self) -> bool {
        self.blocked_until > self.now
    }

    /// Raises the alarms that begin this step.
    fn alarms(&mut self, up: bool, down: bool, alarms: &mut Vec<String>) {
        let against = (up && !down && self.position >= FULL) || (down && !up && self.position <= 0);
        let closing_on_eye = down && !up && self.blocked();
        self.against_ms = if against { self.against_ms + 1 } else { 0 };
        self.eye_ms = if closing_on_eye { self.eye_ms + 1 } else { 0 };
        let grace = self.params[GRACE];
        let now = Alarms {
            both: up && down,
            limit: self.against_ms > grace,
            eye: self.eye_ms > grace,
        };
        if now.both && !self.on.both {
            alarms.push(AlarmKind::BothWays.to_string());
        }
        if now.limit && !self.on.limit {
            alarms.push(AlarmKind::AgainstLimit { up, grace }.to_string());
        }
        if now.eye && !self.on.eye {
            alarms.push(AlarmKind::ClosingOnEye { grace }.to_string());
        }
        self.on = now;
    }
}

impl Plant for Door {
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
        match index {
            START => self.position = value * (FULL / 100),
            SEED => self.reset(),
            _ => {}
        }
    }

    fn reset(&mut self) {
        self.position = self.params[START] * (FULL / 100);
        self.now = 0;
        self.pressed_until = 0;
        self.blocked_until = 0;
        self.on = Alarms::default();
        self.against_ms = 0;
        self.eye_ms = 0;
        self.rng = Rng::new(self.params[SEED] as u64);
        self.next_press = self.params[REMOTE_EVERY] + self.rng.up_to(self.params[REMOTE_SPREAD]);
        self.next_block = self.params[EYE_EVERY] + self.rng.up_to(self.params[EYE_SPREAD]);
    }

    fn step(&mut self, now_ms: i64, drive: &[i64], alarms: &mut Vec<String>) {
        self.now = now_ms;
        let on = |i: usize| drive.get(i).is_some_and(|&v| v != 0);
        let (up, down) = (on(UP), on(DOWN));
        if now_ms >= self.next_press {
            self.pressed_until = now_ms + self.params[PRESS];
            let (every, spread) = (self.params[REMOTE_EVERY], self.params[REMOTE_SPREAD]);
            self.next_press = self.rng.after(now_ms, every, spread);
        }
        if now_ms >= self.next_block {
            self.blocked_until = now_ms + self.params[BLOCKED];
            let (every, spread) = (self.params[EYE_EVERY], self.params[EYE_SPREAD]);
            self.next_block = self.rng.after(now_ms, every, spread);
        }
        self.alarms(up, down, alarms);
        // Up and down at once: the two contactors fight, the door stays.
        let speed = FULL / self.params[TRAVEL];
        if up && !down {
            self.position = (self.position + speed).min(FULL);
        } else if down && !up {
            self.position = (self.position - speed).max(0);
        }
    }

    fn sensor(&self, signal: usize) -> i64 {
        let on = match signal {
            TOP => self.position >= FULL,
            BOTTOM => self.position <= 0,
            EYE => self.blocked(),
            REMOTE => self.pressed_until > self.now,
            _ => false,
        };
        i64::from(on)
    }

    fn quantity(&self, _index: usize) -> i64 {
        self.position / (FULL / 100)
    }
}

#[cfg(test)]
#[path = "door_tests.rs"]
mod tests;
