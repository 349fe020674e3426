//! Recording and time travel (issue #16). While a machine runs, every
//! scan's device image is kept (the bytes that changed since the scan
//! before, and a whole image with a copy of the whole machine every
//! [`KEYFRAME_EVERY`] scans), with every command and step that drove it.
//! The oldest keyframe's scans are dropped first once the recording
//! passes its memory budget.
//!
//! The machines are exact and deterministic, so any recorded scan is
//! brought back by copying the keyframe at or before it and replaying
//! the log from there ([`Recording::machine_at`]): the copy is that
//! scan's machine in full (timers, edge memories, the clock, the trace),
//! not only its device image, and can run on from it.
//!
//! Scans are addressed by their place in the recording ([`Mark`]),
//! counted from 0 at the start and never reused, so a mark stays valid
//! (or becomes plainly "dropped") as old scans are dropped.

pub mod condition;
mod recorded;
mod run;
mod store;
mod travel;

pub use condition::{Condition, ConditionError};
pub use recorded::Recorded;
pub use run::{run_scans, run_whole_scans};
pub use travel::TimeTravel;

use std::collections::VecDeque;

use crate::plc::{tick_end, Command, Device, Plc, PlcError};
use crate::time::SimTime;
use crate::time::MAX_SIM_TIME;
use store::Chunk;

/// A recorded scan's place: 0 is the state when recording started, then
/// one per completed scan.
pub type Mark = u64;

/// A whole machine copy and image every this many scans: replaying to
/// any scan runs at most this many scans again.
pub const KEYFRAME_EVERY: u64 = 256;

/// The memory a recording keeps by default (64 MB).
pub const DEFAULT_BUDGET: usize = 64 << 20;

/// What drove the machine between scans, in order, each with the time
/// at which it came (the machine had run everything due by then).
#[derive(Clone, Debug, PartialEq, Eq)]
enum Op {
    /// The command was applied.
    Apply(SimTime, Command),
    /// `step_scan`, `step_instruction`, `step_clock` ran.
    StepScan(SimTime),
    StepInstruction(SimTime),
    StepClock(SimTime),
    /// The serial terminal was opened, or a line typed at it.
    SerialOpen(SimTime),
    Serial(SimTime, String),
}

impl Op {
    /// Its memory, estimated.
    fn bytes(&self) -> usize {
        let text = match self {
            Op::Serial(_, line) => line.len(),
            _ => 0,
        };
        std::mem::size_of::<Op>() + text
    }

    fn time(&self) -> SimTime {
        match self {
            Op::Apply(t, _)
            | Op::StepScan(t)
            | Op::StepInstruction(t)
            | Op::StepClock(t)
            | Op::SerialOpen(t)
            | Op::Serial(t, _) => *t,
        }
    }
}

/// Why [`Recording::run`] stopped before its time.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Break {
    /// The scan at whose end the condition held.
    pub mark: Mark,
}

/// A machine's recorded scans. `M` is the machine (any [`Plc`] that can
/// be copied); the recording owns copies of it, never the live one.
#[derive(Clone, Debug)]
pub struct Recording<M> {
    chunks: VecDeque<Chunk<M>>,
    /// The log, from the front keyframe's first op on.
    ops: VecDeque<Op>,
    /// The absolute index of `ops[0]`.
    ops_first: u64,
    budget: usize,
    bytes: usize,
    /// The estimated size of one machine copy.
    machine_bytes: usize,
    /// The machine's scan count when last seen.
    scans_seen: u64,
}

impl<M: Plc + Clone> Recording<M> {
    /// Starts recording `machine` as it is now (mark 0), keeping at most
    /// about `budget` bytes.
    pub fn new(machine: &M, budget: usize) -> Recording<M> {
        // Its own size and about as much again on the heap (program,
        // buffers): an estimate, cheap enough to make per recording.
        let machine_bytes = 2 * std::mem::size_of::<M>();
        let first = Chunk::new(0, machine.clone(), 0);
        let mut r = Recording {
            bytes: first.bytes(machine_bytes),
            chunks: VecDeque::from([first]),
            ops: VecDeque::new(),
            ops_first: 0,
            budget,
            machine_bytes,
            scans_seen: machine.scans(),
        };
        r.trim();
        r
    }

    /// The first mark still kept.
    pub fn first(&self) -> Mark {
        self.chunks.front().map_or(0, |c| c.first)
    }

    /// The last mark recorded.
    pub fn last(&self) -> Mark {
        self.chunks.back().map_or(0, Chunk::last)
    }

    /// Memory in use, estimated (images, changes, machine copies, log).
    pub fn bytes(&self) -> usize {
        self.bytes
    }

    /// The simulated time at the end of the scan at `mark` (made, as
    /// images are, when first asked for).
    pub fn time_at(&mut self, mark: Mark) -> Option<SimTime> {
        let c = self.chunk_index(mark)?;
        self.fill(c);
        let chunk = &self.chunks[c];
        chunk.time((mark - chunk.first) as usize)
    }

    /// The device image at `mark`, into `image`; false if not kept.
    /// Images are made when first asked for, by replaying the keyframe's
    /// scans (recording itself copies nothing per scan), then kept.
    pub fn image_at(&mut self, mark: Mark, image: &mut Vec<u8>) -> bool {
        let Some(c) = self.chunk_index(mark) else {
            return false;
        };
        self.fill(c);
        let chunk = &self.chunks[c];
        chunk.image_at((mark - chunk.first) as usize, image)
    }

    /// `device`'s value at every kept mark in `from..=to`, read through
    /// `machine` (the device's owner) from each scan's image; `None` where
    /// the image does not hold it.
    pub fn values(
        &mut self,
        machine: &M,
        device: Device,
        from: Mark,
        to: Mark,
    ) -> Vec<Option<crate::plc::Value>> {
        let (from, to, chunks) = self.filled_between(from, to);
        let mut out = Vec::new();
        let mut image = Vec::new();
        for c in chunks {
            let first = self.chunks[c].first;
            self.chunks[c].each_image(&mut image, |i, img| {
                let mark = first + i as u64;
                if (from..=to).contains(&mark) {
                    out.push(machine.read_image(img, device));
                }
            });
        }
        out
    }

    /// The last mark at or before `at` where `device` took the value it
    /// has at `at` (the scan it last changed), if that is kept.
    pub fn last_change(&mut self, machine: &M, device: Device, at: Mark) -> Option<Mark> {
        let first = self.first();
        let values = self.values(machine, device, first, at);
        let now = values.last()?;
        let i = values.iter().rposition(|v| v != now)?;
        Some(first + i as u64 + 1)
    }

    /// `from..=to` within the kept marks, and the chunks holding any of
    /// it, their images and times made.
    fn filled_between(&mut self, from: Mark, to: Mark) -> (Mark, Mark, Vec<usize>) {
        let from = from.max(self.first());
        let to = to.min(self.last());
        let chunks: Vec<usize> = (0..self.chunks.len())
            .filter(|&c| self.chunks[c].last() >= from && self.chunks[c].first <= to)
            .collect();
        for &c in &chunks {
            self.fill(c);
        }
        (from, to, chunks)
    }

    /// Makes chunk `c`'s images, if not all held, by replaying it with
    /// tracing off (the images do not need it, and some machines run
    /// faster without).
    fn fill(&mut self, c: usize) {
        let chunk = &self.chunks[c];
        if chunk.filled() {
            return;
        }
        let mut shots: Vec<(Vec<u8>, SimTime)> = Vec::with_capacity(chunk.len());
        let last = chunk.last();
        let replayed = self.replay_with(last, false, |m| {
            let mut image = Vec::new();
            m.image_into(&mut image);
            shots.push((image, m.now()));
        });
        if replayed.is_none() {
            return;
        }
        let (new, old) = self.chunks[c].fill(shots.iter().map(|(i, t)| (i.as_slice(), *t)));
        self.bytes = self.bytes.saturating_sub(old) + new;
    }

    /// The end time of each kept scan in `from..=to`.
    pub fn times(&mut self, from: Mark, to: Mark) -> Vec<SimTime> {
        let (from, to, chunks) = self.filled_between(from, to);
        let mut out = Vec::new();
        for c in chunks {
            let chunk = &self.chunks[c];
            let (first, last) = (chunk.first, chunk.last());
            let skip = from.saturating_sub(first) as usize;
            let take = (to.min(last) + 1 - first.max(from)) as usize;
            out.extend(chunk.times().iter().skip(skip).take(take));
        }
        out
    }

    fn chunk_index(&self, mark: Mark) -> Option<usize> {
        if mark < self.first() || mark > self.last() {
            return None;
        }
        let c = self.chunks.partition_point(|c| c.first <= mark);
        c.checked_sub(1)
    }

    // ----- driving the machine ------------------------------------------

    /// Advances `machine` by `dt` (as [`Plc::tick`] does) one scan at a
    /// time, recording each; stops at the end of the first scan where
    /// `stop` holds.
    pub fn tick(
        &mut self,
        machine: &mut M,
        dt: SimTime,
        stop: Option<&mut Condition>,
    ) -> Option<Break> {
        self.run(machine, tick_end(machine.now(), dt), stop)
    }

    /// Runs `machine` to `t` one scan at a time, recording each; stops at
    /// the end of the first scan where `stop` holds.
    pub fn run(
        &mut self,
        machine: &mut M,
        t: SimTime,
        mut stop: Option<&mut Condition>,
    ) -> Option<Break> {
        if stop.is_none() {
            self.run_to_keyframes(machine, t);
            return None;
        }
        let mut hit = None;
        run_scans(machine, t, |m| {
            self.scanned(m);
            let holds = stop.as_mut().is_some_and(|c| c.holds(m));
            if holds {
                hit = Some(Break { mark: self.last() });
            }
            !holds
        });
        hit
    }

    /// With no condition to check after every scan: runs in one go to
    /// just before each keyframe's scan (where the machine can tell when
    /// that is), then scan by scan to it, so that the copy is taken at
    /// that scan's end.
    fn run_to_keyframes(&mut self, machine: &mut M, t: SimTime) {
        loop {
            let held = self.chunks.back().map_or(0, |c| c.len() as u64);
            let to_keyframe = KEYFRAME_EVERY.saturating_sub(held).max(1);
            let before = machine.scans();
            // The scan before the keyframe's, or (next to it, or where the
            // machine cannot tell) the next one.
            let stride = match to_keyframe {
                1 => None,
                n => machine.nth_scan_end(n - 1),
            };
            let end = match stride.or_else(|| machine.next_scan_end()) {
                Some(end) if end <= t => end,
                _ => {
                    machine.run_until(t);
                    self.scanned(machine);
                    return;
                }
            };
            machine.run_until(end);
            if machine.scans() == before && machine.now() >= t {
                return;
            }
            self.scanned(machine);
        }
    }

    /// Applies `command` to `machine` and logs it; on error nothing
    /// changes and nothing is logged.
    pub fn apply(&mut self, machine: &mut M, command: Command) -> Result<(), PlcError> {
        machine.apply(command.clone())?;
        self.log(Op::Apply(machine.now(), command));
        self.scanned(machine);
        Ok(())
    }

    /// `step_scan`, logged and recorded.
    pub fn step_scan(&mut self, machine: &mut M) {
        self.log(Op::StepScan(machine.now()));
        machine.step_scan();
        self.scanned(machine);
    }

    /// `step_instruction`, logged and recorded.
    pub fn step_instruction(&mut self, machine: &mut M) -> Option<usize> {
        self.log(Op::StepInstruction(machine.now()));
        let step = machine.step_instruction();
        self.scanned(machine);
        step
    }

    /// `step_clock`, logged and recorded.
    pub fn step_clock(&mut self, machine: &mut M) -> bool {
        self.log(Op::StepClock(machine.now()));
        let ran = machine.step_clock();
        self.scanned(machine);
        ran
    }

    /// Opens the serial terminal, logged and recorded.
    pub fn serial_open(&mut self, machine: &mut M) -> Result<String, PlcError> {
        self.log(Op::SerialOpen(machine.now()));
        let shown = machine.serial_open();
        self.scanned(machine);
        shown
    }

    /// Types `line` at the serial terminal, logged and recorded (a line
    /// can run the program, stop it or rewrite it).
    pub fn serial(&mut self, machine: &mut M, line: &str) -> Result<String, PlcError> {
        self.log(Op::Serial(machine.now(), line.to_string()));
        let reply = machine.serial(line);
        self.scanned(machine);
        reply
    }

    fn log(&mut self, op: Op) {
        self.bytes += op.bytes();
        self.ops.push_back(op);
    }

    /// Counts a scan if `machine` completed one since the last look, and
    /// every [`KEYFRAME_EVERY`] scans keeps a copy of the machine. Nothing
    /// else is copied per scan: images and times are made by replay when
    /// first asked for, which keeps recording cheap (README: figures).
    fn scanned(&mut self, machine: &M) {
        let scans = machine.scans();
        if scans == self.scans_seen {
            return;
        }
        // Scans run in one go count together; the last of them ends now.
        // A count that went back (power cycled) is one change, as replay
        // sees it.
        let more = scans.checked_sub(self.scans_seen).unwrap_or(1);
        self.scans_seen = scans;
        if more > 1 {
            if let Some(chunk) = self.chunks.back_mut() {
                chunk.push_many(more - 1);
            }
        }
        match self.chunks.back_mut() {
            Some(chunk) if (chunk.len() as u64) < KEYFRAME_EVERY => chunk.push(),
            _ => {
                let ops_at = self.ops_first + self.ops.len() as u64;
                let chunk = Chunk::new(self.last() + 1, machine.clone(), ops_at);
                self.bytes += chunk.bytes(self.machine_bytes);
                self.chunks.push_back(chunk);
                self.trim();
            }
        }
    }

    /// Drops the oldest keyframes' scans while over budget (always
    /// keeping the newest).
    fn trim(&mut self) {
        while self.bytes > self.budget && self.chunks.len() > 1 {
            let Some(old) = self.chunks.pop_front() else {
                break;
            };
            self.bytes = self.bytes.saturating_sub(old.bytes(self.machine_bytes));
            let keep_from = self.chunks.front().map_or(self.ops_first, |c| c.ops_at);
            while self.ops_first < keep_from {
                let Some(op) = self.ops.pop_front() else {
                    break;
                };
                self.ops_first += 1;
                self.bytes = self.bytes.saturating_sub(op.bytes());
            }
        }
    }

    // ----- time travel ----------------------------------------------------

    /// The whole machine as it was at the end of the scan at `mark`: the
    /// keyframe before it, replayed. `None` if `mark` is not kept.
    pub fn machine_at(&self, mark: Mark) -> Option<M> {
        self.replay_with(mark, true, |_| {}).map(|(m, _)| m)
    }

    /// Replays from the keyframe before `mark` to `mark`, calling
    /// `at_scan` with the keyframe and after every scan; with `trace`
    /// false, tracing is off in the replay. Returns the machine and the
    /// absolute index of the first op it did not apply.
    fn replay_with(
        &self,
        mark: Mark,
        trace: bool,
        mut at_scan: impl FnMut(&M),
    ) -> Option<(M, u64)> {
        let c = self.chunk_index(mark)?;
        let chunk = &self.chunks[c];
        let mut m = chunk.machine.clone();
        if !trace {
            m.set_tracing(false);
        }
        at_scan(&m);
        let mut count = Counter {
            seen: m.scans(),
            reached: chunk.first,
            target: mark,
        };
        let mut more = |m: &M| {
            let counted = count.more(m);
            if counted.0 {
                at_scan(m);
            }
            counted.1
        };
        let mut next = chunk.ops_at;
        let from = (chunk.ops_at - self.ops_first) as usize;
        for op in self.ops.iter().skip(from) {
            if !more(&m) {
                break;
            }
            // An op that came at the time the machine already is (mid-step)
            // came before anything else ran.
            let t = op.time();
            if m.now() < t && !run_scans(&mut m, t, &mut more) {
                break;
            }
            match op {
                // It applied when it was logged, so it applies again.
                Op::Apply(_, command) => {
                    let _ = m.apply(command.clone());
                }
                Op::StepScan(_) => m.step_scan(),
                Op::StepInstruction(_) => {
                    m.step_instruction();
                }
                Op::StepClock(_) => {
                    m.step_clock();
                }
                Op::SerialOpen(_) => {
                    let _ = m.serial_open();
                }
                Op::Serial(_, line) => {
                    let _ = m.serial(line);
                }
            }
            next += 1;
        }
        if more(&m) {
            // The scans were recorded, so they come before any limit.
            run_scans(&mut m, MAX_SIM_TIME, &mut more);
        }
        (count.reached == mark).then_some((m, next))
    }

    /// Drops every scan after `mark` and the log after it: the machine
    /// resumes from there ("Resume from here"). Returns the machine at
    /// `mark`, which the caller runs on; `None` if `mark` is not kept.
    pub fn resume_from(&mut self, mark: Mark) -> Option<M> {
        let (machine, next_op) = self.replay_with(mark, true, |_| {})?;
        let c = self.chunk_index(mark)?;
        while self.chunks.len() > c + 1 {
            if let Some(old) = self.chunks.pop_back() {
                self.bytes = self.bytes.saturating_sub(old.bytes(self.machine_bytes));
            }
        }
        if let Some(chunk) = self.chunks.back_mut() {
            let keep = (mark - chunk.first) as usize + 1;
            self.bytes = self.bytes.saturating_sub(chunk.truncate(keep));
        }
        // The log up to the replayed state: what the replay applied.
        let keep = next_op.saturating_sub(self.ops_first) as usize;
        let dropped: usize = self.ops.iter().skip(keep).map(Op::bytes).sum();
        self.ops.truncate(keep);
        self.bytes = self.bytes.saturating_sub(dropped);
        self.scans_seen = machine.scans();
        Some(machine)
    }
}

/// Counts scans as a replay runs, up to the mark it brings back.
struct Counter {
    seen: u64,
    reached: Mark,
    target: Mark,
}

impl Counter {
    /// Counts a scan if `m` completed one: (whether it did, whether to go
    /// on).
    fn more<M: Plc>(&mut self, m: &M) -> (bool, bool) {
        let counted = m.scans() != self.seen && !self.done();
        if counted {
            self.seen = m.scans();
            self.reached += 1;
        }
        (counted, !self.done())
    }

    fn done(&self) -> bool {
        self.reached >= self.target
    }
}
