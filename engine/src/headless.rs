//! Headless runs: a machine, an input timeline and watched devices in; the
//! CSV of `hashigo run` out (../shared/spec/cli.md).

use std::io::Write;

use crate::error::Located;
use crate::events::{InputEvent, InputValue};
use crate::limits::MAX_CSV_VALUES;
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
    /// `--every` so small that the run would print more than this many
    /// values (rows × watched devices).
    TooManyValues(u64),
    /// The output could not be written (the message of the I/O error).
    Output(String),
}

/// [`run`] into a string.
pub fn run_csv<S: Simulation>(
    sim: &mut S,
    events: &[InputEvent],
    schedule: Schedule,
    watch: &[String],
) -> Result<String, Vec<RunError>> {
    let mut out = Vec::new();
    run(sim, events, schedule, watch, &mut out)?;
    String::from_utf8(out).map_err(|e| vec![RunError::Output(e.to_string())])
}

/// Simulates from the machine's current (power-on) state to `schedule.until`
/// and writes the CSV to `out` row by row (nothing is buffered, so the
/// output's size is bounded only by [`MAX_CSV_VALUES`]). Every watch name
/// and every event is checked before anything runs, so a bad input yields
/// errors and no output at all.
pub fn run<S: Simulation, W: Write>(
    sim: &mut S,
    events: &[InputEvent],
    schedule: Schedule,
    watch: &[String],
    out: &mut W,
) -> Result<(), Vec<RunError>> {
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
    } else if schedule.every > SimTime::ZERO {
        let rows = schedule.until.as_nanos() / schedule.every.as_nanos() + 2;
        let values = rows.saturating_mul(watch.len().max(1) as u64);
        if values > MAX_CSV_VALUES {
            errors.push(RunError::TooManyValues(MAX_CSV_VALUES));
        }
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    let failed = |e: std::io::Error| vec![RunError::Output(e.to_string())];

    let mut header = String::from("time_ms");
    for name in watch {
        header.push(',');
        header.push_str(name);
    }
    writeln!(out, "{header}").map_err(failed)?;

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
        write!(out, "{row_time}").map_err(failed)?;
        for &w in &watches {
            write!(out, ",{}", sim.value(w)).map_err(failed)?;
        }
        writeln!(out).map_err(failed)?;
        if row_time >= schedule.until {
            break;
        }
        row_time = row_time.saturating_add(schedule.every).min(schedule.until);
    }
    Ok(())
}
