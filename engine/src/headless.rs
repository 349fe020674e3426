//! Headless runs: a machine, an input timeline and watched devices in; the
//! CSV of `hashigo run` out (../shared/spec/cli.md).

use std::fmt::Write as _;

use crate::error::Located;
use crate::events::{InputEvent, InputValue};
use crate::time::SimTime;

/// What the headless runner needs from a machine.
pub trait Simulation {
    /// A watched device, resolved once before the run.
    type Watch: Copy;

    /// Applies a `--set NAME=VALUE`; nothing changes on error.
    fn setting(&mut self, name: &str, value: &str) -> Result<(), String>;
    /// Resolves a device name given to `--watch`.
    fn watch(&self, name: &str) -> Result<Self::Watch, String>;
    /// The watched value after the last completed scan.
    fn value(&self, watch: Self::Watch) -> i64;
    /// Checks that `device` can take `value` without applying it.
    fn check_input(&self, device: &str, value: InputValue) -> Result<(), String>;
    /// Applies an input event (already checked) at the current time.
    fn apply_input(&mut self, device: &str, value: InputValue);
    /// Runs every clock edge strictly before `t`; the time becomes `t`.
    fn run_before(&mut self, t: SimTime);
    /// Runs every clock edge at or before `t`; the time becomes `t`.
    fn run_until(&mut self, t: SimTime);
}

/// When to print rows: at 0, every, 2·every, … up to and including until.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Schedule {
    /// The last instant simulated.
    pub until: SimTime,
    /// The row interval (`until` when not given).
    pub every: SimTime,
}

/// Why a headless run could not start. Nothing is printed in that case.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum RunError {
    /// A `--watch` name the machine does not have.
    Watch(String),
    /// An event the machine cannot take, at its line of the events file.
    Event(Located<String>),
    /// `--every` is zero while `--until` is not.
    ZeroInterval,
    /// `--every` so small that the run would print more than this many rows.
    TooManyRows(u64),
}

/// The largest number of rows one run prints; past it `--every` is
/// certainly a mistake (and the output would not fit in memory).
const MAX_ROWS: u64 = 10_000_000;

/// Simulates from the machine's current (power-on) state to `schedule.until`
/// and returns the CSV. Every watch name and every event is checked before
/// anything runs, so a bad input yields errors and no partial output.
pub fn run<S: Simulation>(
    sim: &mut S,
    events: &[InputEvent],
    schedule: Schedule,
    watch: &[String],
) -> Result<String, Vec<RunError>> {
    let mut errors = Vec::new();
    let mut watches = Vec::new();
    for name in watch {
        match sim.watch(name) {
            Ok(w) => watches.push(w),
            Err(e) => errors.push(RunError::Watch(e)),
        }
    }
    for event in events {
        if let Err(e) = sim.check_input(&event.device, event.value) {
            errors.push(RunError::Event(Located::new(event.line, e)));
        }
    }
    if schedule.every == SimTime::ZERO && schedule.until > SimTime::ZERO {
        errors.push(RunError::ZeroInterval);
    } else if schedule.every > SimTime::ZERO
        && schedule.until.as_nanos() / schedule.every.as_nanos() > MAX_ROWS
    {
        errors.push(RunError::TooManyRows(MAX_ROWS));
    }
    if !errors.is_empty() {
        return Err(errors);
    }

    let mut out = String::from("time_ms");
    for name in watch {
        out.push(',');
        out.push_str(name);
    }
    out.push('\n');

    let mut pending = events.iter().peekable();
    let mut row_time = SimTime::ZERO;
    loop {
        // Events at or before this row's time come first, each applied
        // before any clock edge at its own instant.
        while let Some(event) = pending.next_if(|e| e.time <= row_time) {
            sim.run_before(event.time);
            sim.apply_input(&event.device, event.value);
        }
        sim.run_until(row_time);
        let _ = write!(out, "{row_time}");
        for &w in &watches {
            let _ = write!(out, ",{}", sim.value(w));
        }
        out.push('\n');
        if row_time >= schedule.until {
            break;
        }
        row_time = row_time.saturating_add(schedule.every).min(schedule.until);
    }
    Ok(out)
}
