//! Ladder tests (docs/tests.md): cases stored with the project, each an
//! input timeline and expectations, run on a fresh machine through the
//! [`Plc`] interface. The page, `hashigo test` and share links carry the
//! same cases.

mod expect;
mod observed;
mod schedule;

use std::fmt;

use serde::{Deserialize, Serialize};

pub use expect::{Compare, ExpectError, Expectation, Want};
pub use observed::{EdgeSeen, Observed};

use crate::error::Located;
use crate::events::{parse_events, EventError};
use crate::plc::{Command, Device, Plc, PlcError, Value};
use crate::time::SimTime;
use schedule::Schedule;

/// How finely windows (`stays`, `rises`) are sampled, besides every
/// event time and the windows' ends: every millisecond of simulated time.
pub const SAMPLE: SimTime = SimTime::from_millis(1);

pub use crate::limits::MAX_TEST_WORK;

/// One test case.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct TestCase {
    /// Its name.
    pub name: String,
    /// The input timeline: the events CSV `hashigo run --input` takes.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub events: String,
    /// Expectations, one a line ([`Expectation`]).
    #[serde(default)]
    pub expect: Vec<String>,
    /// The author's hint, shown to a student whose answer fails this
    /// case (an exercise's words instead of the expectation's).
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub hint: String,
}

/// How a case came out.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// Every expectation held.
    Pass,
    /// The first expectation (in the case's order) that did not hold.
    Fail {
        /// Its index.
        index: usize,
        /// It, as written back.
        expectation: String,
        /// What was seen instead.
        observed: String,
        /// The same, typed (the page says it in its own language).
        seen: Observed,
    },
}

/// Why a case could not run.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CaseError {
    /// A bad line of the timeline.
    Events(Vec<Located<EventError>>),
    /// An event the machine does not take (its line).
    Event(Located<PlcError>),
    /// A bad expectation (its index, 0-based).
    Expect(usize, ExpectError),
    /// An expectation's device the machine lacks (its index).
    Device(usize, PlcError),
    /// More than [`MAX_TEST_WORK`] samples to take (with the cases
    /// before it, when a project's cases run together).
    TooLong,
}

impl fmt::Display for CaseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CaseError::Events(errors) => crate::error::write_joined(
                f,
                errors
                    .iter()
                    .map(|e| format!("events line {}: {}", e.line, e.error)),
            ),
            CaseError::Event(e) => write!(f, "events line {}: {}", e.line, e.error),
            CaseError::Expect(i, e) => write!(f, "expectation {}: {e}", i + 1),
            CaseError::Device(i, e) => write!(f, "expectation {}: {e}", i + 1),
            CaseError::TooLong => write!(
                f,
                "the tests would take more than {MAX_TEST_WORK} samples (instants and expectations looked at; docs/limits.md): shorten their windows"
            ),
        }
    }
}

impl std::error::Error for CaseError {}

/// What one expectation has seen so far.
struct Watch {
    expectation: Expectation,
    device: Device,
    /// The first instant it failed at, and what was seen.
    failed: Option<Observed>,
    /// Edges: the value at the span's first and latest samples, whether
    /// it ever changed, when it first moved the other way, and whether the
    /// edge was seen.
    first: Option<Value>,
    last: Option<Value>,
    changed: bool,
    opposite: Option<SimTime>,
    seen: bool,
}

impl Watch {
    fn new(expectation: Expectation, device: Device) -> Watch {
        Watch {
            expectation,
            device,
            failed: None,
            first: None,
            last: None,
            changed: false,
            opposite: None,
            seen: false,
        }
    }

    /// Looks at the device's `value` at `t`, an instant of its span. No
    /// allocation unless it fails: a long window takes millions of looks.
    fn sample(&mut self, t: SimTime, value: Value) {
        if self.failed.is_some() {
            return;
        }
        let device = self.expectation.device();
        let want = match &self.expectation {
            Expectation::At { value: want, .. } | Expectation::Stays { value: want, .. } => {
                Some(want)
            }
            Expectation::Edge { .. } => None,
        };
        if let Some(wrong) = want.and_then(|w| w.kind_of(device, &value)) {
            self.failed = Some(wrong);
            return;
        }
        let holds = match &self.expectation {
            Expectation::At {
                op, value: want, ..
            } => op.holds_want(&value, want),
            Expectation::Stays { value: want, .. } => Compare::Eq.holds_want(&value, want),
            Expectation::Edge { falling, .. } => {
                if let Some(before) = &self.last {
                    let (was, on) = (before.is_on(), value.is_on());
                    let wanted = if *falling { was && !on } else { !was && on };
                    let other = if *falling { !was && on } else { was && !on };
                    self.seen |= wanted;
                    if other && self.opposite.is_none() {
                        self.opposite = Some(t);
                    }
                    self.changed |= *before != value;
                }
                self.first.get_or_insert_with(|| value.clone());
                self.last = Some(value.clone());
                true
            }
        };
        if !holds {
            self.failed = Some(Observed::Was {
                device: self.expectation.device().to_string(),
                value: value.watched(),
                at: t,
            });
        }
    }

    fn verdict(&self) -> Option<Observed> {
        if let Some(f) = &self.failed {
            return Some(f.clone());
        }
        let Expectation::Edge { falling, .. } = &self.expectation else {
            return None;
        };
        if self.seen {
            return None;
        }
        let (first, last) = (
            self.first.clone().unwrap_or(Value::Int(0)),
            self.last.clone().unwrap_or(Value::Int(0)),
        );
        // Say what was seen: a device that did the opposite is not one
        // that stayed put.
        let seen = if self.changed {
            EdgeSeen::Went {
                first: first.to_string(),
                last: last.to_string(),
                opposite: self.opposite,
            }
        } else {
            EdgeSeen::Stayed(first.to_string())
        };
        Some(Observed::NoEdge {
            device: self.expectation.device().to_string(),
            falling: *falling,
            seen,
        })
    }
}

/// A case read and checked, ready to run on any machine.
pub struct Prepared {
    events: Vec<crate::events::InputEvent>,
    /// Each distinct expectation once, with the index of its first line.
    expectations: Vec<(usize, Expectation)>,
    work: u64,
}

impl Prepared {
    /// Reads `case`'s timeline and expectations (no machine needed).
    pub fn new(case: &TestCase) -> Result<Prepared, CaseError> {
        let events = parse_events(&case.events).map_err(CaseError::Events)?;
        let mut expectations: Vec<(usize, Expectation)> = Vec::new();
        let mut seen = std::collections::HashSet::new();
        for (i, line) in case.expect.iter().enumerate() {
            let expectation = Expectation::parse(line).map_err(|e| CaseError::Expect(i, e))?;
            // The same line twice holds or fails together: looked at once.
            if seen.insert(expectation.clone()) {
                expectations.push((i, expectation));
            }
        }
        let work = schedule(&events, &expectations).work();
        Ok(Prepared {
            events,
            expectations,
            work,
        })
    }

    /// How many samples the case takes at most ([`MAX_TEST_WORK`]).
    pub fn work(&self) -> u64 {
        self.work
    }
}

fn schedule(
    events: &[crate::events::InputEvent],
    expectations: &[(usize, Expectation)],
) -> Schedule {
    Schedule::new(
        events.iter().map(|e| e.time),
        expectations.iter().map(|(_, e)| e.span()).collect(),
    )
}

/// Reads every case (each may be bad on its own) and counts the work of
/// all of them together before any runs: past [`MAX_TEST_WORK`] the whole
/// set is refused with [`CaseError::TooLong`].
pub fn prepare_all(cases: &[TestCase]) -> Result<Vec<Result<Prepared, CaseError>>, CaseError> {
    let prepared: Vec<_> = cases.iter().map(Prepared::new).collect();
    let total = prepared
        .iter()
        .flatten()
        .fold(0u64, |sum, p| sum.saturating_add(p.work));
    if total > MAX_TEST_WORK {
        return Err(CaseError::TooLong);
    }
    Ok(prepared)
}

/// Runs `case` on `plc` (a fresh machine with the program loaded and its
/// settings applied) from time zero.
pub fn run_case(plc: &mut dyn Plc, case: &TestCase) -> Result<Outcome, CaseError> {
    let prepared = Prepared::new(case)?;
    if prepared.work > MAX_TEST_WORK {
        return Err(CaseError::TooLong);
    }
    run_prepared(plc, &prepared)
}

/// Runs a case read by [`Prepared::new`] on `plc` (a fresh machine with
/// the program loaded and its settings applied) from time zero.
pub fn run_prepared(plc: &mut dyn Plc, case: &Prepared) -> Result<Outcome, CaseError> {
    let mut inputs = Vec::with_capacity(case.events.len());
    for e in &case.events {
        let device = plc
            .device(&e.device)
            .and_then(|d| plc.check_input(d, e.value).map(|()| d))
            .map_err(|err| CaseError::Event(Located::new(e.line, err)))?;
        inputs.push(device);
    }
    let mut watches = Vec::with_capacity(case.expectations.len());
    for (i, expectation) in &case.expectations {
        let device = plc
            .device(expectation.device())
            .map_err(|e| CaseError::Device(*i, e))?;
        watches.push(Watch::new(expectation.clone(), device));
    }
    let mut schedule = schedule(&case.events, &case.expectations);
    let mut pending = case.events.iter().zip(inputs).peekable();
    let mut due = Vec::new();
    while let Some(t) = schedule.next(&mut due) {
        while let Some((event, device)) = pending.next_if(|(e, _)| e.time <= t) {
            plc.run_before(event.time);
            // Checked above: the machine takes it.
            let _ = plc.apply(Command::SetInput(device, event.value));
        }
        plc.run_until(t);
        for &i in &due {
            let w = &mut watches[i];
            let value = plc.read(w.device);
            w.sample(t, value);
        }
    }
    Ok(watches
        .iter()
        .zip(&case.expectations)
        .find_map(|(w, (index, _))| {
            w.verdict().map(|seen| Outcome::Fail {
                index: *index,
                expectation: w.expectation.to_string(),
                observed: seen.to_string(),
                seen,
            })
        })
        .unwrap_or(Outcome::Pass))
}
