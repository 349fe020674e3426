//! The simulator as the page drives it: the machine, how fast simulated
//! time runs against the wall clock, and pausing. It lives outside the
//! reactive graph; each animation frame advances it and the panel is copied
//! out into signals.

use engine::plc::Plc;
use engine::record::Recorded;
use engine::SimTime;

use crate::rig::RigSlot;

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
/// How much of a frame `Speed::Max` may spend simulating, at most.
pub const MAX_SPEED_BUDGET_MS: f64 = 10.0;
/// ... and at least, however late frames come.
const MIN_SPEED_BUDGET_MS: f64 = 2.0;
/// What each frame on time gives back to `Speed::Max`'s share (`FrameBudget`).
const BUDGET_STEP_MS: f64 = 0.01;
/// `Speed::Max` advances in slices of this much simulated time, checking
/// the budget between slices.
const MAX_SPEED_SLICE: SimTime = SimTime::from_millis(20);
/// ... and of this much with a plant coupled: the rig steps the plant and
/// keeps its past at each of its milliseconds, so 20 ms of it cost more
/// than a frame's whole share, and the first slice always runs (issue
/// #52: the 200-rung ladder's running frame with the conveyor).
const MAX_SPEED_SLICE_PLANT: SimTime = SimTime::from_millis(2);

/// How the page paces simulated time. Page-wide state: the header sets
/// it, the frame loop hands it to whichever workspace is shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Pace {
    /// How fast simulated time runs.
    pub speed: Speed,
    /// Whether simulated time is frozen.
    pub paused: bool,
}

/// A machine the frame loop advances, reached only through the engine's
/// [`Plc`] interface. It records itself ([`Recorded`]): every command and
/// scan goes into its recording, and time travel shows a past scan
/// through the same interface.
pub struct Simulator<M> {
    machine: Recorded<M>,
    budget: FrameBudget,
    /// The plant coupled to the machine (issue #52): when there is one,
    /// it advances the machine step by step with itself.
    rig: RigSlot,
    /// Where a running scan stops by itself (issue #55: a Structured
    /// Text breakpoint): while set, frames run the machine instruction by
    /// instruction and ask it after each.
    stop: Option<StopAt<M>>,
    /// A frame stopped at `stop` since the last [`Simulator::take_stopped`].
    stopped: bool,
}

/// Asked of the machine after each instruction: `None` while no scan is
/// under way, else whether the scan stops before its next instruction.
pub type StopAt<M> = Box<dyn Fn(&M) -> Option<bool>>;

/// The most instructions one frame steps through while a stop is set: a
/// long scan goes on in the next frame rather than freezing the page.
const MAX_STEPS_PER_FRAME: usize = 200_000;

/// `Speed::Max`'s share of a frame. The rest of the frame (the live
/// ladder's changes, layout, paint) costs what the drawing and the device
/// make it cost, so a fixed share can leave too little and every frame
/// misses the display: a late frame takes a fifth off the share, and each
/// frame on time gives back [`BUDGET_STEP_MS`]. At the edge that is a miss
/// once in `share / 5 / step` frames: 0.05 ms missed one frame in 25 with
/// a 6 ms share, enough to double the 95th percentile frame (issue #52's
/// plant coupled to 200 rungs); 0.01 ms misses one in 120, and a share
/// cut by a passing hiccup is back in about 3 s.
#[derive(Clone, Copy, Debug, PartialEq)]
struct FrameBudget {
    ms: f64,
    /// The shortest time seen between frames: the display's interval.
    interval_ms: f64,
}

impl FrameBudget {
    fn new() -> FrameBudget {
        FrameBudget {
            ms: MAX_SPEED_BUDGET_MS,
            interval_ms: f64::INFINITY,
        }
    }

    /// Learns from a frame that came `wall_ms` after the last.
    fn learn(&mut self, wall_ms: f64) {
        // No display runs faster than 165 Hz: a shorter gap is jitter.
        self.interval_ms = self.interval_ms.min(wall_ms.max(6.0));
        self.ms = if wall_ms > self.interval_ms * 1.5 {
            (self.ms * 0.8).max(MIN_SPEED_BUDGET_MS)
        } else {
            (self.ms + BUDGET_STEP_MS).min(MAX_SPEED_BUDGET_MS)
        };
    }
}

impl<M: Plc + Clone> Simulator<M> {
    /// A simulator around `machine`.
    pub fn new(machine: M) -> Simulator<M> {
        Simulator {
            machine: Recorded::new(machine),
            budget: FrameBudget::new(),
            rig: None,
            stop: None,
            stopped: false,
        }
    }

    /// Sets where running scans stop by themselves (`None`: nowhere,
    /// frames run whole scans again).
    pub fn set_stop(&mut self, stop: Option<StopAt<M>>) {
        self.stop = stop;
    }

    /// Whether a frame stopped at the stop set, since the last call.
    pub fn take_stopped(&mut self) -> bool {
        std::mem::take(&mut self.stopped)
    }

    /// Runs `dt` instruction by instruction, stopping before the
    /// instruction `stop` names. The instruction it stood before runs
    /// first: a scan resumed at a breakpoint goes on past it.
    fn step_through(&mut self, dt: SimTime) {
        let Some(stop) = self.stop.as_ref() else {
            return;
        };
        let end = self.machine.now() + dt;
        for _ in 0..MAX_STEPS_PER_FRAME {
            if stop(self.machine.shown_machine()).is_none() {
                // Between scans: the next one starts only within `dt`.
                match self.machine.next_scan_end() {
                    Some(t) if t <= end => {}
                    _ => {
                        let now = self.machine.now();
                        if end > now {
                            self.machine.tick(end - now);
                        }
                        return;
                    }
                }
            }
            self.machine.step_instruction();
            if stop(self.machine.shown_machine()) == Some(true) {
                self.stopped = true;
                return;
            }
        }
    }

    /// The machine (as shown: a past scan's while travelling).
    pub fn machine(&self) -> &Recorded<M> {
        &self.machine
    }

    /// The machine, to operate it.
    pub fn machine_mut(&mut self) -> &mut Recorded<M> {
        &mut self.machine
    }

    /// The machine and the plant coupled to it, to couple or uncouple.
    pub fn machine_and_rig(&mut self) -> (&mut Recorded<M>, &mut RigSlot) {
        (&mut self.machine, &mut self.rig)
    }

    /// After the machine's power went off and on: its plant (if any)
    /// back at its start (issue #52).
    pub fn power_cycled(&mut self) {
        if let Some(rig) = self.rig.as_mut() {
            rig.power_cycle(&mut self.machine);
        }
    }

    /// Advances the machine by `dt`, with its plant if it has one.
    fn tick(&mut self, dt: SimTime) {
        match self.rig.as_mut() {
            Some(rig) => rig.advance(&mut self.machine, dt),
            None => self.machine.tick(dt),
        }
    }

    /// Advances for one animation frame that came `wall_ms` after the
    /// last, at `pace`. `now_ms` reads the wall clock (for `Speed::Max`'s
    /// budget).
    pub fn frame(&mut self, pace: Pace, wall_ms: f64, mut now_ms: impl FnMut() -> f64) {
        // A past scan on show holds time still; so does a machine that is
        // stopped (HALT, STOP, disabled): nothing runs, nothing counts.
        let travelling = self.machine.shown().is_some();
        let stopped = !self.machine.running();
        if pace.paused || travelling || stopped || !wall_ms.is_finite() || wall_ms <= 0.0 {
            return;
        }
        let wall_ms = wall_ms.min(CATCH_UP_CAP_MS);
        if self.stop.is_some() && self.rig.is_none() {
            let nanos = match pace.speed {
                Speed::Times(factor) => wall_ms * 1e6 * f64::from(factor),
                Speed::Max => MAX_SPEED_SLICE.0 as f64,
            };
            self.step_through(SimTime::from_nanos(nanos as u64));
            return;
        }
        match pace.speed {
            Speed::Times(factor) => {
                let nanos = wall_ms * 1e6 * f64::from(factor);
                self.tick(SimTime::from_nanos(nanos as u64));
            }
            Speed::Max => {
                self.budget.learn(wall_ms);
                let budget = self.budget.ms;
                // A slice is started only when one as long as the last
                // would end within the budget: the frame's simulation then
                // ends by its budget, whatever a slice costs on this
                // machine and build (the first slice always runs).
                let slice = match self.rig {
                    Some(_) => MAX_SPEED_SLICE_PLANT,
                    None => MAX_SPEED_SLICE,
                };
                let start = now_ms();
                let mut last_end = start;
                loop {
                    self.tick(slice);
                    let end = now_ms();
                    let next_end = end + (end - last_end);
                    last_end = end;
                    if next_end - start > budget || self.machine.has_break() {
                        break;
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use engine::machines::AvrPlc;

    fn sim() -> Simulator<AvrPlc> {
        Simulator::new(AvrPlc::new())
    }

    fn run(speed: Speed, paused: bool, wall_ms: f64) -> SimTime {
        let mut s = sim();
        s.frame(Pace { speed, paused }, wall_ms, || 0.0);
        s.machine().now()
    }

    #[test]
    fn a_frame_runs_its_wall_time_times_the_speed() {
        assert_eq!(run(Speed::Times(1), false, 16.0), SimTime::from_millis(16));
        assert_eq!(
            run(Speed::Times(10), false, 16.0),
            SimTime::from_millis(160)
        );
        assert_eq!(run(Speed::Times(100), false, 0.5), SimTime::from_millis(50));
    }

    #[test]
    fn a_stopped_machines_time_stands_still() {
        use engine::plc::{Command, Plc};
        let mut s = Simulator::new(engine::machines::SoftPlc::new());
        s.machine_mut()
            .load_text(include_str!("../../engine/programs/soft-plc/self-hold.il"))
            .expect("loads");
        let pace = Pace {
            speed: Speed::Times(1),
            paused: false,
        };
        s.machine_mut().apply(Command::Run(false)).expect("stops");
        s.frame(pace, 16.0, || 0.0);
        assert_eq!(s.machine().now(), SimTime::ZERO, "stopped");
        s.machine_mut().apply(Command::Run(true)).expect("runs");
        s.frame(pace, 16.0, || 0.0);
        assert_eq!(s.machine().now(), SimTime::from_millis(16), "running");
    }

    #[test]
    fn paused_or_odd_frames_run_nothing() {
        assert_eq!(run(Speed::Times(1), true, 16.0), SimTime::ZERO);
        for odd in [0.0, -5.0, f64::NAN, f64::INFINITY] {
            assert_eq!(run(Speed::Times(1), false, odd), SimTime::ZERO, "{odd}");
        }
    }

    #[test]
    fn a_late_frame_catches_up_at_most_the_cap() {
        assert_eq!(
            run(Speed::Times(1), false, 5_000.0),
            SimTime::from_millis(CATCH_UP_CAP_MS as u64)
        );
    }

    /// Simulated time one `Speed::Max` frame runs when each slice takes
    /// `slice_ms` of wall time.
    fn max_speed_frame(slice_ms: f64) -> SimTime {
        let mut s = sim();
        let mut clock = 0.0;
        let now = move || {
            clock += slice_ms;
            clock
        };
        s.frame(
            Pace {
                speed: Speed::Max,
                paused: false,
            },
            16.0,
            now,
        );
        s.machine().now()
    }

    #[test]
    fn max_speed_starts_no_slice_that_would_end_past_the_budget() {
        // Slices of 4 ms: two end by 8 ms; a third would end at 12 ms.
        assert_eq!(max_speed_frame(4.0), SimTime::from_millis(2 * 20));
        // Slices of 1 ms: ten fit the 10 ms budget exactly.
        assert_eq!(max_speed_frame(1.0), SimTime::from_millis(10 * 20));
        // A slice longer than the budget still runs once: time moves on.
        assert_eq!(max_speed_frame(25.0), SimTime::from_millis(20));
    }

    #[test]
    fn late_frames_shrink_max_speeds_share_and_frames_on_time_give_it_back() {
        let mut b = FrameBudget::new();
        for _ in 0..100 {
            b.learn(16.7);
        }
        assert_eq!(b.ms, MAX_SPEED_BUDGET_MS, "on time: the whole share");
        b.learn(33.4);
        assert!((b.ms - 8.0).abs() < 1e-9, "{}", b.ms);
        for _ in 0..100 {
            b.learn(16.7);
        }
        assert!((b.ms - 9.0).abs() < 1e-9, "slowly back: {}", b.ms);
        for _ in 0..100 {
            b.learn(100.0);
        }
        assert_eq!(b.ms, MIN_SPEED_BUDGET_MS, "never below the least");
        // A 120 Hz display: its own interval is on time.
        let mut fast = FrameBudget::new();
        for _ in 0..10 {
            fast.learn(8.3);
        }
        assert_eq!(fast.ms, MAX_SPEED_BUDGET_MS);
    }

    #[test]
    fn after_a_late_frame_max_speed_runs_fewer_slices() {
        let mut s = sim();
        let pace = Pace {
            speed: Speed::Max,
            paused: false,
        };
        let slices = |s: &mut Simulator<AvrPlc>, wall_ms: f64| {
            let before = s.machine().now();
            let mut clock = 0.0;
            s.frame(pace, wall_ms, move || {
                clock += 1.0;
                clock
            });
            (s.machine().now() - before).as_nanos() / SimTime::from_millis(20).as_nanos()
        };
        assert_eq!(slices(&mut s, 16.7), 10);
        // Late: an 8 ms share, eight slices of 1 ms.
        assert_eq!(slices(&mut s, 40.0), 8);
    }

    #[test]
    fn speeds_read_back_from_their_codes() {
        for speed in Speed::ALL {
            assert_eq!(Speed::from_code(&speed.code()), Some(speed));
        }
        assert_eq!(Speed::from_code("fast"), None);
    }

    #[test]
    fn a_stop_set_halts_a_frame_before_the_step_it_names_and_resumes_past_it() {
        use engine::machines::SoftPlc;
        use engine::plc::{Command, Plc, Value};
        let text = "PROGRAM p\nVAR a : INT; b : INT; END_VAR\na := a + 1;\nb := a;\nEND_PROGRAM\n";
        let run = engine::softplc::st::st_run(text).expect("loads");
        let mut s = Simulator::new(SoftPlc::new());
        s.machine_mut().load_text(&run.il).expect("loads");
        s.machine_mut().apply(Command::Run(true)).expect("runs");
        // Before line 4's first step (as `machines::soft::st::stop_steps`).
        let lines = run.lines.clone();
        let at_line_4: Vec<bool> = (0..lines.len())
            .map(|p| lines[p] == Some(4) && (p == 0 || lines[p - 1] != lines[p]))
            .collect();
        s.set_stop(Some(Box::new(move |m: &SoftPlc| {
            m.machine()
                .scan_position()
                .map(|p| at_line_4.get(p).copied().unwrap_or(false))
        })));
        let pace = Pace {
            speed: Speed::Times(1),
            paused: false,
        };
        // Mid-scan: the program's values now, not the last scan's image.
        let read = |s: &Simulator<SoftPlc>, name: &str| {
            let program = s.machine().shown_machine().machine().program();
            program.value(name).expect(name).to_value()
        };
        let line_now = |s: &Simulator<SoftPlc>| {
            let p = s.machine().shown_machine().machine().scan_position();
            p.and_then(|p| run.lines[p])
        };
        s.frame(pace, 16.0, || 0.0);
        assert!(s.take_stopped());
        assert!(!s.take_stopped(), "said once");
        assert_eq!(line_now(&s), Some(4));
        assert_eq!(
            (read(&s, "a"), read(&s, "b")),
            (Value::Int(1), Value::Int(0))
        );
        // The next frame runs on past the line it stood before, to the
        // same line in the next scan.
        s.frame(pace, 16.0, || 0.0);
        assert!(s.take_stopped());
        assert_eq!(
            (read(&s, "a"), read(&s, "b")),
            (Value::Int(2), Value::Int(1))
        );
        // No stop: whole scans again, none left under way.
        s.set_stop(None);
        s.frame(pace, 100.0, || 0.0);
        assert!(!s.take_stopped());
        assert_eq!(line_now(&s), None);
        assert_eq!(read(&s, "b"), read(&s, "a"));
    }
}
