//! Headless runs: a machine, an input timeline and watched devices in; the
//! CSV of `hashigo run` out (../shared/spec/cli.md).

use std::io::Write;

use crate::plc::{Command, Plc, PlcError};

use crate::error::Located;
use crate::events::InputEvent;
use crate::limits::MAX_CSV_VALUES;
use crate::time::SimTime;

/// When to print rows: at 0, every, 2·every, … up to and including until.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Schedule {
    /// The last instant simulated.
    pub until: SimTime,
    /// The row interval (`until` when not given).
    pub every: SimTime,
}

impl Schedule {
    /// The rows a run prints: one at 0, one every `every`, and one at
    /// `until` when it is not on that grid (one row when `every` is 0).
    pub fn rows(&self) -> u64 {
        let (until, every) = (self.until.as_nanos(), self.every.as_nanos());
        match until.checked_div(every) {
            Some(whole) => whole + 1 + u64::from(until % every != 0),
            None => 1,
        }
    }
}

/// Why a headless run could not start. Nothing is printed in that case.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum RunError {
    /// A `--watch` name the machine does not have.
    Watch(PlcError),
    /// An event the machine cannot take, at its line of the events file.
    Event(Located<PlcError>),
    /// `--every` is zero while `--until` is not.
    ZeroInterval,
    /// `--every` so small that the run would print more than this many
    /// values (rows × watched devices).
    TooManyValues(u64),
    /// The output could not be written (the message of the I/O error).
    Output(String),
}

/// [`run`] into a string.
pub fn run_csv<P: Plc + ?Sized>(
    sim: &mut P,
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
pub fn run<P: Plc + ?Sized, W: Write>(
    sim: &mut P,
    events: &[InputEvent],
    schedule: Schedule,
    watch: &[String],
    out: &mut W,
) -> Result<(), Vec<RunError>> {
    let mut errors = Vec::new();
    let mut watches = Vec::new();
    for name in watch {
        match sim.device(name) {
            Ok(w) => watches.push(w),
            Err(e) => errors.push(RunError::Watch(e)),
        }
    }
    let mut inputs = Vec::with_capacity(events.len());
    for event in events {
        let checked = sim
            .device(&event.device)
            .and_then(|d| sim.check_input(d, event.value).map(|()| d));
        match checked {
            Ok(d) => inputs.push(d),
            Err(e) => errors.push(RunError::Event(Located::new(event.line, e))),
        }
    }
    if schedule.every == SimTime::ZERO && schedule.until > SimTime::ZERO {
        errors.push(RunError::ZeroInterval);
    } else if schedule.every > SimTime::ZERO {
        let rows = schedule.rows();
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

    let mut pending = events.iter().zip(inputs).peekable();
    let mut row_time = SimTime::ZERO;
    loop {
        // Events at or before this row's time come first, each applied
        // before any clock edge at its own instant.
        while let Some((event, device)) = pending.next_if(|(e, _)| e.time <= row_time) {
            sim.run_before(event.time);
            // Checked above: the machine takes it.
            let _ = sim.apply(Command::SetInput(device, event.value));
        }
        sim.run_until(row_time);
        write!(out, "{row_time}").map_err(failed)?;
        for &w in &watches {
            write!(out, ",{}", csv_field(&sim.read(w))).map_err(failed)?;
        }
        writeln!(out).map_err(failed)?;
        if row_time >= schedule.until {
            break;
        }
        row_time = row_time.saturating_add(schedule.every).min(schedule.until);
    }
    Ok(())
}

/// A value as one CSV field: numbers as they print; a text (a soft-PLC
/// STRING) quoted as RFC 4180 quotes it when it holds a comma, a quote,
/// a line end or spaces at an end.
fn csv_field(value: &crate::plc::Value) -> std::borrow::Cow<'_, str> {
    let crate::plc::Value::Text(t) = value else {
        return value.to_string().into();
    };
    let plain = !t.contains([',', '"', '\r', '\n']) && t.trim() == t.as_str();
    if plain {
        std::borrow::Cow::Borrowed(t.as_str())
    } else {
        format!("\"{}\"", t.replace('"', "\"\"")).into()
    }
}
