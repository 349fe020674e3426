//! A machine that records itself: the page's simulator wraps each
//! machine in [`Recorded`], so every command, step, terminal line and
//! scan goes through the recording without the panels knowing, and time
//! travel shows a past scan through the same [`Plc`] reads.

use super::{Break, Condition, Mark, Recording, DEFAULT_BUDGET};
use crate::clock::PeriodicClock;
use crate::events::InputValue;
use crate::plc::{
    Command, Device, Front, Plc, PlcError, ScanTrace, SettingInfo, Terminals, TraceHistory, Value,
    Warning,
};
use crate::time::SimTime;
use crate::MachineId;

/// A machine, its recording, and the past scan shown, if one is.
///
/// Reads ([`Plc::read`], `trace`, `image_into`, `front_into`, …) see the
/// shown scan's machine while travelling, the live one otherwise. Anything
/// that changes the machine while a past scan is shown first resumes from
/// that scan (the later recording is dropped): the user changed history.
/// Running to a time stops early at the end of a scan where the break
/// condition holds ([`Recorded::take_break`]).
#[derive(Clone, Debug)]
pub struct Recorded<M> {
    live: M,
    recording: Recording<M>,
    past: Option<(Mark, M)>,
    stop: Option<Condition>,
    hit: Option<Break>,
    breaks: Vec<Mark>,
    budget: usize,
}

impl<M: Plc + Clone> Recorded<M> {
    /// `machine`, recorded from now on within [`DEFAULT_BUDGET`].
    pub fn new(machine: M) -> Recorded<M> {
        Recorded::with_budget(machine, DEFAULT_BUDGET)
    }

    /// `machine`, recorded within about `budget` bytes.
    pub fn with_budget(machine: M, budget: usize) -> Recorded<M> {
        Recorded {
            recording: Recording::new(&machine, budget),
            live: machine,
            past: None,
            stop: None,
            hit: None,
            breaks: Vec::new(),
            budget,
        }
    }

    /// The recording.
    pub fn recording(&self) -> &Recording<M> {
        &self.recording
    }

    /// The recording, to read images and times from (made on demand).
    pub fn recording_mut(&mut self) -> &mut Recording<M> {
        &mut self.recording
    }

    /// The recording, and the live machine to read its images through.
    pub fn recording_and_machine(&mut self) -> (&mut Recording<M>, &M) {
        (&mut self.recording, &self.live)
    }

    /// The machine shown: the past scan's while travelling, else live.
    pub fn shown_machine(&self) -> &M {
        self.past.as_ref().map_or(&self.live, |(_, m)| m)
    }

    /// The past scan shown, or `None` when live.
    pub fn shown(&self) -> Option<Mark> {
        self.past.as_ref().map(|(m, _)| *m)
    }

    /// Shows the recorded scan `mark` (a copy of the machine replayed to
    /// it); false if it is not kept.
    pub fn show(&mut self, mark: Mark) -> bool {
        match self.recording.machine_at(mark) {
            Some(m) => {
                self.past = Some((mark, m));
                true
            }
            None => false,
        }
    }

    /// Back to the live machine.
    pub fn go_live(&mut self) {
        self.past = None;
    }

    /// Resumes from the shown past scan: it becomes the live machine and
    /// the later recording is dropped. False when live already.
    pub fn resume_here(&mut self) -> bool {
        let Some((mark, _)) = self.past.take() else {
            return false;
        };
        match self.recording.resume_from(mark) {
            Some(m) => {
                self.live = m;
                self.breaks.retain(|&b| b <= mark);
                true
            }
            None => false,
        }
    }

    /// Sets (or clears) the break condition.
    pub fn set_break(&mut self, stop: Option<Condition>) {
        self.stop = stop;
    }

    /// Whether the condition held since the last [`Recorded::take_break`].
    pub fn has_break(&self) -> bool {
        self.hit.is_some()
    }

    /// Where the condition held since the last call, then forgotten.
    pub fn take_break(&mut self) -> Option<Break> {
        self.hit.take()
    }

    /// Every scan where the break condition held, oldest first.
    pub fn breaks(&self) -> &[Mark] {
        &self.breaks
    }

    /// Mutation goes to the live machine, resuming from a shown past.
    fn live_mut(&mut self) -> &mut M {
        if self.past.is_some() {
            self.resume_here();
        }
        &mut self.live
    }

    fn run_recorded(&mut self, t: SimTime) {
        if self.past.is_some() {
            self.resume_here();
        }
        if let Some(hit) = self.recording.run(&mut self.live, t, self.stop.as_mut()) {
            self.hit = Some(hit);
            self.breaks.push(hit.mark);
        }
    }
}

impl<M: Plc + Clone> Plc for Recorded<M> {
    fn id(&self) -> MachineId {
        self.live.id()
    }

    /// A new program is a new history: the recording starts again.
    fn load_text(&mut self, text: &str) -> Result<(), PlcError> {
        self.live.load_text(text)?;
        self.past = None;
        self.breaks.clear();
        self.recording = Recording::new(&self.live, self.budget);
        if let Some(stop) = &self.stop {
            // Re-resolved against the new program's start.
            self.stop = Condition::parse(stop.text(), &self.live).ok();
        }
        Ok(())
    }

    fn listing(&self) -> String {
        self.shown_machine().listing()
    }

    fn apply(&mut self, command: Command) -> Result<(), PlcError> {
        if self.past.is_some() {
            // Refused commands change nothing, not even the travel.
            self.shown_machine().clone().apply(command.clone())?;
        }
        self.live_mut();
        self.recording.apply(&mut self.live, command)
    }

    fn device(&self, name: &str) -> Result<Device, PlcError> {
        self.live.device(name)
    }

    fn check_input(&self, device: Device, value: InputValue) -> Result<(), PlcError> {
        self.live.check_input(device, value)
    }

    fn read(&self, device: Device) -> Value {
        self.shown_machine().read(device)
    }

    fn now(&self) -> SimTime {
        self.shown_machine().now()
    }

    fn scans(&self) -> u64 {
        self.shown_machine().scans()
    }

    fn run_until(&mut self, t: SimTime) {
        self.run_recorded(t);
    }

    fn run_before(&mut self, t: SimTime) {
        self.run_recorded(PeriodicClock::just_before(t));
        if self.hit.is_none() {
            self.live.run_before(t);
        }
    }

    fn step_scan(&mut self) {
        self.live_mut();
        self.recording.step_scan(&mut self.live);
    }

    fn next_scan_end(&self) -> Option<SimTime> {
        self.live.next_scan_end()
    }

    fn step_instruction(&mut self) -> Option<usize> {
        self.live_mut();
        self.recording.step_instruction(&mut self.live)
    }

    fn step_clock(&mut self) -> bool {
        self.live_mut();
        self.recording.step_clock(&mut self.live)
    }

    fn set_tracing(&mut self, on: bool) {
        self.live.set_tracing(on);
        if let Some((_, m)) = &mut self.past {
            m.set_tracing(on);
        }
    }

    fn trace(&self) -> Option<&ScanTrace> {
        self.shown_machine().trace()
    }

    fn take_trace_history(&mut self) -> TraceHistory {
        match &mut self.past {
            Some(_) => TraceHistory::default(),
            None => self.live.take_trace_history(),
        }
    }

    fn image_into(&self, image: &mut Vec<u8>) {
        self.shown_machine().image_into(image);
    }

    fn read_image(&self, image: &[u8], device: Device) -> Option<Value> {
        self.live.read_image(image, device)
    }

    fn running(&self) -> bool {
        self.shown_machine().running()
    }

    fn front_into(&self, front: &mut Front) {
        self.shown_machine().front_into(front);
    }

    fn warnings(&self) -> Vec<Warning> {
        self.live.warnings()
    }

    fn settings(&self) -> &'static [SettingInfo] {
        self.live.settings()
    }

    fn time_for_steps(&self, steps: u64) -> Option<(SimTime, u64)> {
        self.live.time_for_steps(steps)
    }

    /// The machine's own: the page wires a plant to its recorded machine.
    fn terminals(&self) -> Terminals {
        self.live.terminals()
    }

    fn serial_open(&mut self) -> Result<String, PlcError> {
        self.live_mut();
        self.recording.serial_open(&mut self.live)
    }

    fn serial(&mut self, line: &str) -> Result<String, PlcError> {
        self.live_mut();
        self.recording.serial(&mut self.live, line)
    }

    /// As the shown machine (a past one while travelling) had sent.
    fn serial_sent(&self, seen: u64, out: &mut String) -> u64 {
        self.shown_machine().serial_sent(seen, out)
    }
}
