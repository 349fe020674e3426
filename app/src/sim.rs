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
    /// As much simulated time as the time each frame leaves allows.
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
/// How long before the next frame is due `Speed::Max` stops simulating,
/// so that the next frame's own work starts on time (`Display::deadline`).
const MAX_SPEED_MARGIN_MS: f64 = 1.5;
/// The display's interval taken until frames have shown it: 60 Hz.
const FIRST_INTERVAL_MS: f64 = 1000.0 / 60.0;
/// `Speed::Max` advances in slices of this much simulated time, checking
/// the clock between slices.
const MAX_SPEED_SLICE: SimTime = SimTime::from_millis(20);
/// ... and of this much with a plant coupled: the rig steps the plant and
/// keeps its past at each of its milliseconds, so 20 ms of it cost more
/// than the time a frame leaves, and the first slice always runs (issue
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
    /// The plant coupled to the machine (issue #52): when there is one,
    /// it advances the machine step by step with itself.
    rig: RigSlot,
    /// Where a running scan stops by itself (issue #55: a Structured
    /// Text breakpoint): while set, frames run the machine instruction by
    /// instruction and ask it after each.
    stop: Option<StopAt<M>>,
    /// A frame stopped at `stop` since the last [`Simulator::take_stopped`].
    stopped: bool,
    /// The wall time of the last frame at `Speed::Max`, which its run
    /// after the frame simulates at least: Max is never slower than x1.
    max_floor: SimTime,
}

/// Asked of the machine after each instruction: `None` while no scan is
/// under way, else whether the scan stops before its next instruction.
pub type StopAt<M> = Box<dyn Fn(&M) -> Option<bool>>;

/// The most instructions one frame steps through while a stop is set: a
/// long scan goes on in the next frame rather than freezing the page.
const MAX_STEPS_PER_FRAME: usize = 200_000;

/// The display's pace as the frames show it, for `Speed::Max` to simulate
/// in the time each frame leaves: after the page is drawn and until just
/// before the next frame is due ([`Simulator::after_frame`]). A share of
/// the frame itself (before the drawing) was tried first: whatever the
/// share, a frame's own work varies, so a share that fitted most frames
/// made the others late (issue #52: the 200-rung ladder with a plant,
/// docs/performance.md "As fast as possible in the time a frame leaves").
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Display {
    /// The shortest time seen between frames: the display's interval.
    interval_ms: f64,
}

impl Default for Display {
    fn default() -> Display {
        Display {
            interval_ms: f64::INFINITY,
        }
    }
}

impl Display {
    /// Learns from a frame that came `wall_ms` after the last.
    pub fn learn(&mut self, wall_ms: f64) {
        // No display runs faster than 165 Hz: a shorter gap is jitter (two
        // frames at once after a hidden tab shows again), not the display.
        if wall_ms.is_finite() && wall_ms >= 6.0 {
            self.interval_ms = self.interval_ms.min(wall_ms);
        }
    }

    /// When `Speed::Max`'s simulation stops after the frame that began at
    /// `frame_ms` (wall clock, ms): shortly before the next one is due.
    pub fn deadline(&self, frame_ms: f64) -> f64 {
        let interval = if self.interval_ms.is_finite() {
            self.interval_ms
        } else {
            FIRST_INTERVAL_MS
        };
        frame_ms + interval - MAX_SPEED_MARGIN_MS
    }
}

impl<M: Plc + Clone> Simulator<M> {
    /// A simulator around `machine`.
    pub fn new(machine: M) -> Simulator<M> {
        Simulator {
            machine: Recorded::new(machine),
            rig: None,
            stop: None,
            stopped: false,
            max_floor: SimTime::ZERO,
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

    /// Whether time runs at `pace`: not paused, no past scan on show
    /// (it holds time still), and the machine not stopped (HALT, STOP,
    /// disabled: nothing runs, nothing counts).
    fn runs(&self, pace: Pace) -> bool {
        !pace.paused && self.machine.shown().is_none() && self.machine.running()
    }

    /// Advances for one animation frame that came `wall_ms` after the
    /// last, at `pace`: the frame's wall time times the speed.
    /// `Speed::Max` runs after the frame instead ([`Simulator::after_frame`]),
    /// at least this frame's wall time.
    pub fn frame(&mut self, pace: Pace, wall_ms: f64) {
        self.max_floor = SimTime::ZERO;
        if !self.runs(pace) || !wall_ms.is_finite() || wall_ms <= 0.0 {
            return;
        }
        let wall_ms = wall_ms.min(CATCH_UP_CAP_MS);
        let Speed::Times(factor) = pace.speed else {
            self.max_floor = SimTime::from_nanos((wall_ms * 1e6) as u64);
            return;
        };
        let dt = SimTime::from_nanos((wall_ms * 1e6 * f64::from(factor)) as u64);
        if self.stop.is_some() && self.rig.is_none() {
            self.step_through(dt);
        } else {
            self.tick(dt);
        }
    }

    /// `Speed::Max`'s simulation for a frame, run once the frame is drawn:
    /// slices of simulated time until one more would end past
    /// `deadline_ms` (wall clock, [`Display::deadline`]), read with
    /// `now_ms`. The first slice always runs, so time moves on however
    /// late the frame was, and covers at least the frame's wall time.
    pub fn after_frame(&mut self, pace: Pace, deadline_ms: f64, mut now_ms: impl FnMut() -> f64) {
        if pace.speed != Speed::Max || !self.runs(pace) {
            return;
        }
        if self.stop.is_some() && self.rig.is_none() {
            self.step_through(MAX_SPEED_SLICE);
            return;
        }
        let slice = match self.rig {
            Some(_) => MAX_SPEED_SLICE_PLANT,
            None => MAX_SPEED_SLICE,
        };
        // The first slice runs at least the frame's wall time (Max is
        // never slower than x1) and to the end of the scan under way (each
        // frame shows a scan of its own), however little time the frame
        // left.
        let now = self.machine.now();
        let mut dt = slice.max(std::mem::take(&mut self.max_floor));
        if let Some(end) = self.machine.next_scan_end().filter(|end| *end > now) {
            dt = dt.max(end - now);
        }
        // A slice is started only when one as long as the last would end
        // by the deadline, whatever a slice costs on this machine.
        let mut last_end = now_ms();
        loop {
            self.tick(dt);
            dt = slice;
            let end = now_ms();
            let next_end = end + (end - last_end);
            last_end = end;
            if next_end > deadline_ms || self.machine.has_break() {
                break;
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
        s.frame(Pace { speed, paused }, wall_ms);
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
        s.frame(pace, 16.0);
        assert_eq!(s.machine().now(), SimTime::ZERO, "stopped");
        s.machine_mut().apply(Command::Run(true)).expect("runs");
        s.frame(pace, 16.0);
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

    const MAX: Pace = Pace {
        speed: Speed::Max,
        paused: false,
    };

    /// Simulated time `Speed::Max` runs after a frame with `ms_left` to
    /// its deadline, when each slice takes `slice_ms` of wall time.
    fn max_speed_frame(slice_ms: f64, ms_left: f64) -> SimTime {
        let mut s = sim();
        let mut clock = 0.0;
        s.after_frame(MAX, ms_left, move || {
            let t = clock;
            clock += slice_ms;
            t
        });
        s.machine().now()
    }

    #[test]
    fn max_speed_starts_no_slice_that_would_end_past_the_deadline() {
        // Slices of 4 ms: two end by 8 ms; a third would end at 12 ms.
        assert_eq!(max_speed_frame(4.0, 10.0), SimTime::from_millis(2 * 20));
        // Slices of 1 ms: ten fit 10 ms exactly.
        assert_eq!(max_speed_frame(1.0, 10.0), SimTime::from_millis(10 * 20));
        // A slice longer than the time left, or a deadline already past,
        // still runs once: time moves on.
        assert_eq!(max_speed_frame(25.0, 10.0), SimTime::from_millis(20));
        assert_eq!(max_speed_frame(1.0, -5.0), SimTime::from_millis(20));
    }

    #[test]
    fn max_speed_is_never_slower_than_real_time() {
        let mut s = sim();
        s.frame(MAX, 75.0);
        s.after_frame(MAX, -1.0, || 0.0);
        assert!(
            s.machine().now() >= SimTime::from_millis(75),
            "{:?}",
            s.machine().now()
        );
        // Once per frame: a second run after it keeps to a slice.
        let before = s.machine().now();
        s.after_frame(MAX, -1.0, || 0.0);
        assert!(s.machine().now() - before < SimTime::from_millis(75));
    }

    #[test]
    fn max_speed_runs_after_the_frame_and_other_speeds_in_it() {
        let mut s = sim();
        s.frame(MAX, 16.0);
        assert_eq!(s.machine().now(), SimTime::ZERO, "not in the frame");
        let ten = Pace {
            speed: Speed::Times(10),
            paused: false,
        };
        s.after_frame(ten, 1e9, || 0.0);
        assert_eq!(s.machine().now(), SimTime::ZERO, "x10 runs in the frame");
        s.after_frame(
            Pace {
                paused: true,
                ..MAX
            },
            1e9,
            || 0.0,
        );
        assert_eq!(s.machine().now(), SimTime::ZERO, "paused");
    }

    #[test]
    fn max_speed_stops_short_of_the_next_frame_the_display_shows() {
        let mut d = Display::default();
        let first = d.deadline(1000.0);
        assert!((first - (1000.0 + 1000.0 / 60.0 - MAX_SPEED_MARGIN_MS)).abs() < 1e-9);
        // Late frames and jitter do not change the display's interval.
        for gap in [16.7, 33.4, 100.0, 3.0, 0.5, 16.7, f64::NAN, -1.0] {
            d.learn(gap);
        }
        assert!((d.deadline(0.0) - (16.7 - MAX_SPEED_MARGIN_MS)).abs() < 1e-9);
        // A 120 Hz display: its own interval.
        let mut fast = Display::default();
        for _ in 0..10 {
            fast.learn(8.3);
        }
        assert!((fast.deadline(0.0) - (8.3 - MAX_SPEED_MARGIN_MS)).abs() < 1e-9);
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
        s.frame(pace, 16.0);
        assert!(s.take_stopped());
        assert!(!s.take_stopped(), "said once");
        assert_eq!(line_now(&s), Some(4));
        assert_eq!(
            (read(&s, "a"), read(&s, "b")),
            (Value::Int(1), Value::Int(0))
        );
        // The next frame runs on past the line it stood before, to the
        // same line in the next scan.
        s.frame(pace, 16.0);
        assert!(s.take_stopped());
        assert_eq!(
            (read(&s, "a"), read(&s, "b")),
            (Value::Int(2), Value::Int(1))
        );
        // No stop: whole scans again, none left under way.
        s.set_stop(None);
        s.frame(pace, 100.0);
        assert!(!s.take_stopped());
        assert_eq!(line_now(&s), None);
        assert_eq!(read(&s, "b"), read(&s, "a"));
    }
}
