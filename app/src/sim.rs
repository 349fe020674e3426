//! The simulator as the page drives it: the machine, how fast simulated
//! time runs against the wall clock, and pausing. It lives outside the
//! reactive graph; each animation frame advances it and the panel is copied
//! out into signals.

use engine::io86a::LinkedPair;
use engine::minasec::{Machine, Panel};
use engine::SimTime;

/// Something simulated time can advance.
pub trait Tick {
    /// Runs `dt` of simulated time.
    fn tick(&mut self, dt: SimTime);
}

impl Tick for Machine {
    fn tick(&mut self, dt: SimTime) {
        Machine::tick(self, dt);
    }
}

impl Tick for engine::arduino::Machine {
    fn tick(&mut self, dt: SimTime) {
        let t = self.now().saturating_add(dt);
        self.run_until(t);
    }
}

impl Tick for engine::avr::Machine {
    fn tick(&mut self, dt: SimTime) {
        let t = self.now().saturating_add(dt);
        self.run_until(t);
    }
}

impl Tick for LinkedPair {
    fn tick(&mut self, dt: SimTime) {
        let t = self.a.now().saturating_add(dt);
        self.run_until(t);
    }
}

/// How fast simulated time runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Speed {
    /// Simulated time = wall time times this factor (1, 10 or 100).
    Times(u32),
    /// As much simulated time as a frame's budget allows.
    Max,
}

impl Speed {
    /// The value in the `speed` select.
    pub fn code(self) -> String {
        match self {
            Speed::Times(n) => n.to_string(),
            Speed::Max => "max".to_string(),
        }
    }

    /// The speed for a select value.
    pub fn from_code(code: &str) -> Option<Speed> {
        match code {
            "1" => Some(Speed::Times(1)),
            "10" => Some(Speed::Times(10)),
            "100" => Some(Speed::Times(100)),
            "max" => Some(Speed::Max),
            _ => None,
        }
    }

    /// Every speed the select offers.
    pub const ALL: [Speed; 4] = [
        Speed::Times(1),
        Speed::Times(10),
        Speed::Times(100),
        Speed::Max,
    ];
}

/// A frame never catches up more than this much wall time: after the tab
/// was hidden, the simulation resumes instead of racing through the gap.
pub const CATCH_UP_CAP_MS: f64 = 100.0;
/// How much of a frame `Speed::Max` may spend simulating.
pub const MAX_SPEED_BUDGET_MS: f64 = 10.0;
/// `Speed::Max` advances in slices of this much simulated time, checking
/// the budget between slices.
const MAX_SPEED_SLICE: SimTime = SimTime::from_millis(20);

/// How the page paces simulated time. Page-wide state: the header sets
/// it, the frame loop hands it to whichever workspace is shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Pace {
    /// How fast simulated time runs.
    pub speed: Speed,
    /// Whether simulated time is frozen.
    pub paused: bool,
}

/// A machine the frame loop advances.
pub struct Simulator<M = Machine> {
    machine: M,
}

impl<M: Tick> Simulator<M> {
    /// A simulator around `machine`.
    pub fn new(machine: M) -> Simulator<M> {
        Simulator { machine }
    }

    /// The machine.
    pub fn machine(&self) -> &M {
        &self.machine
    }

    /// The machine, to operate it.
    pub fn machine_mut(&mut self) -> &mut M {
        &mut self.machine
    }

    /// Advances for one animation frame that came `wall_ms` after the
    /// last, at `pace`. `now_ms` reads the wall clock (for `Speed::Max`'s
    /// budget).
    pub fn frame(&mut self, pace: Pace, wall_ms: f64, mut now_ms: impl FnMut() -> f64) {
        if pace.paused || !wall_ms.is_finite() || wall_ms <= 0.0 {
            return;
        }
        let wall_ms = wall_ms.min(CATCH_UP_CAP_MS);
        match pace.speed {
            Speed::Times(factor) => {
                let nanos = wall_ms * 1e6 * f64::from(factor);
                self.machine.tick(SimTime::from_nanos(nanos as u64));
            }
            Speed::Max => {
                let start = now_ms();
                loop {
                    self.machine.tick(MAX_SPEED_SLICE);
                    if now_ms() - start >= MAX_SPEED_BUDGET_MS {
                        break;
                    }
                }
            }
        }
    }
}

impl Simulator<Machine> {
    /// Copies the front panel into `panel`.
    pub fn panel_into(&self, panel: &mut Panel) {
        self.machine.panel_into(panel);
    }
}
