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

pub use condition::{Condition, ConditionError};
pub use recorded::Recorded;
pub use run::run_scans;

use std::collections::VecDeque;

use crate::limits::MAX_SIM_TIME;
use crate::plc::{Command, Device, Plc, PlcError, MAX_TICK};
use crate::time::SimTime;
use store::Chunk;

/// A recorded scan's place: 0 is the state when recording started, then
/// one per completed scan.
pub type Mark = u64;

/// A whole machine copy and image every this many scans: replaying to
/// any scan runs at most this many scans again.
pub const KEYFRAME_EVERY: u64 = 64;

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
    /// The last scan's image, and a buffer for the next.
    image: Vec<u8>,
    scratch: Vec<u8>,
    /// The machine's scan count when last seen.
    scans_seen: u64,
}

impl<M: Plc + Clone> Recording<M> {
    /// Starts recording `machine` as it is now (mark 0), keeping at most
    /// about `budget` bytes.
    pub fn new(machine: &M, budget: usize) -> Recording<M> {
        let machine_bytes = std::mem::size_of::<M>() + machine.listing().len();
        let mut image = Vec::new();
        machine.image_into(&mut image);
        let first = Chunk::new(0, machine.clone(), 0, &image, machine.now());
        let mut r = Recording {
            bytes: first.bytes(machine_bytes),
            chunks: VecDeque::from([first]),
            ops: VecDeque::new(),
            ops_first: 0,
            budget,
            machine_bytes,
            image,
            scratch: Vec::new(),
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
        self.chunks.back().map_or(0, |c| c.first + c.len() as u64 - 1)
    }

    /// Memory in use, estimated (images, changes, machine copies, log).
    pub fn bytes(&self) -> usize {
        self.bytes
    }

    /// The simulated time at the end of the scan at `mark`.
    pub fn time_at(&self, mark: Mark) -> Option<SimTime> {
        let (chunk, i) = self.locate(mark)?;
        Some(chunk.times[i])
    }

    /// The device image at `mark`, into `image`; false if not kept.
    pub fn image_at(&self, mark: Mark, image: &mut Vec<u8>) -> bool {
        match self.locate(mark) {
            Some((chunk, i)) => {
                chunk.image_at(i, image);
                true
            }
            None => false,
        }
    }

    /// `device`'s value at every kept mark in `from..=to`, read through
    /// `machine` (the device's owner) from each scan's image; `None` where
    /// the image does not hold it.
    pub fn values(&self, machine: &M, device: Device, from: Mark, to: Mark) -> Vec<Option<i64>> {
        let from = from.max(self.first());
        let to = to.min(self.last());
        let mut out = Vec::new();
        let mut image = Vec::new();
        for chunk in &self.chunks {
            let end = chunk.first + chunk.len() as u64 - 1;
            if end < from || chunk.first > to {
                continue;
            }
            chunk.each_image(&mut image, |i, img| {
                let mark = chunk.first + i as u64;
                if (from..=to).contains(&mark) {
                    out.push(machine.read_image(img, device));
                }
            });
        }
        out
    }

    /// The last mark at or before `at` where `device` took the value it
    /// has at `at` (the scan it last changed), if that is kept.
    pub fn last_change(&self, machine: &M, device: Device, at: Mark) -> Option<Mark> {
        let first = self.first();
        let values = self.values(machine, device, first, at);
        let now = *values.last()?;
        let i = values.iter().rposition(|v| *v != now)?;
        Some(first + i as u64 + 1)
    }

    /// The mark whose scan ended last at or before `t`.
    pub fn mark_at_time(&self, t: SimTime) -> Option<Mark> {
        let mut found = None;
        for chunk in &self.chunks {
            if chunk.times.first().is_some_and(|&c| c > t) {
                break;
            }
            let i = chunk.times.partition_point(|&c| c <= t);
            if i > 0 {
                found = Some(chunk.first + i as u64 - 1);
            }
        }
        found
    }

    fn locate(&self, mark: Mark) -> Option<(&Chunk<M>, usize)> {
        let c = self.chunk_index(mark)?;
        let chunk = &self.chunks[c];
        Some((chunk, (mark - chunk.first) as usize))
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
        let t = machine
            .now()
            .saturating_add(dt.min(MAX_TICK))
            .min(MAX_SIM_TIME);
        self.run(machine, t, stop)
    }

    /// Runs `machine` to `t` one scan at a time, recording each; stops at
    /// the end of the first scan where `stop` holds.
    pub fn run(
        &mut self,
        machine: &mut M,
        t: SimTime,
        mut stop: Option<&mut Condition>,
    ) -> Option<Break> {
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

    /// Records a scan if `machine` completed one since the last look.
    fn scanned(&mut self, machine: &M) {
        let scans = machine.scans();
        if scans == self.scans_seen {
            return;
        }
        self.scans_seen = scans;
        machine.image_into(&mut self.scratch);
        let now = machine.now();
        let ops_at = self.ops_first + self.ops.len() as u64;
        let last = self.last();
        let full = self
            .chunks
            .back()
            .is_none_or(|c| c.len() as u64 >= KEYFRAME_EVERY);
        if full {
            let chunk = Chunk::new(last + 1, machine.clone(), ops_at, &self.scratch, now);
            self.bytes += chunk.bytes(self.machine_bytes);
            self.chunks.push_back(chunk);
        } else if let Some(chunk) = self.chunks.back_mut() {
            self.bytes += chunk.push(&self.image, &self.scratch, now);
        }
        std::mem::swap(&mut self.image, &mut self.scratch);
        self.trim();
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
        self.replay(mark).map(|(m, _)| m)
    }

    /// The machine at `mark` and the absolute index of the first op the
    /// replay did not apply.
    fn replay(&self, mark: Mark) -> Option<(M, u64)> {
        let c = self.chunk_index(mark)?;
        let chunk = &self.chunks[c];
        let mut m = chunk.machine.clone();
        let mut count = Counter {
            seen: m.scans(),
            reached: chunk.first,
            target: mark,
        };
        let mut next = chunk.ops_at;
        let from = (chunk.ops_at - self.ops_first) as usize;
        for op in self.ops.iter().skip(from) {
            if count.done() {
                break;
            }
            // An op that came at the time the machine already is (mid-step)
            // came before anything else ran.
            let t = op.time();
            if m.now() < t && !run_scans(&mut m, t, |m| count.more(m)) {
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
            count.more(&m);
            next += 1;
        }
        if !count.done() {
            let end = self.time_at(mark)?;
            run_scans(&mut m, end, |m| count.more(m));
        }
        (count.reached == mark).then_some((m, next))
    }

    /// Drops every scan after `mark` and the log after it: the machine
    /// resumes from there ("Resume from here"). Returns the machine at
    /// `mark`, which the caller runs on; `None` if `mark` is not kept.
    pub fn resume_from(&mut self, mark: Mark) -> Option<M> {
        let (machine, next_op) = self.replay(mark)?;
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
        let mut image = std::mem::take(&mut self.image);
        self.image_at(mark, &mut image);
        self.image = image;
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
    /// Counts a scan if `m` completed one; whether to go on.
    fn more<M: Plc>(&mut self, m: &M) -> bool {
        if m.scans() != self.seen {
            self.seen = m.scans();
            self.reached += 1;
        }
        !self.done()
    }

    fn done(&self) -> bool {
        self.reached >= self.target
    }
}
