//! Ladder tests (docs/tests.md): cases stored with the project, each an
//! input timeline and expectations, run on a fresh machine through the
//! [`Plc`] interface. The page, `hashigo test` and share links carry the
//! same cases.

mod expect;

use std::fmt;

use serde::{Deserialize, Serialize};

pub use expect::{Compare, ExpectError, Expectation};

use crate::error::Located;
use crate::events::{parse_events, EventError};
use crate::plc::{Command, Device, Plc, PlcError};
use crate::time::SimTime;

/// How finely windows (`stays`, `rises`) are sampled, besides every
/// event time and the windows' ends: every millisecond of simulated time.
pub const SAMPLE: SimTime = SimTime::from_millis(1);

/// The most instants one case may sample.
pub const MAX_SAMPLES: usize = 10_000_000;

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
    /// More than [`MAX_SAMPLES`] instants to look at.
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
                "the case looks at more than {MAX_SAMPLES} instants: shorten its windows"
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
    failed: Option<String>,
    /// Edges: the value at the window's previous sample, and whether the
    /// edge was seen.
    last: Option<i64>,
    seen: bool,
}

impl Watch {
    fn sample(&mut self, t: SimTime, value: i64) {
        if self.failed.is_some() {
            return;
        }
        let name = self.expectation.device().to_string();
        match &self.expectation {
            Expectation::At {
                op,
                value: want,
                time,
                ..
            } => {
                if t == *time && !op.holds(value, *want) {
                    self.failed = Some(format!("{name} was {value} at {t}ms"));
                }
            }
            Expectation::Stays {
                value: want,
                from,
                to,
                ..
            } => {
                if (*from..=*to).contains(&t) && value != *want {
                    self.failed = Some(format!("{name} was {value} at {t}ms"));
                }
            }
            Expectation::Edge {
                falling, from, to, ..
            } => {
                if (*from..=*to).contains(&t) {
                    let on = value != 0;
                    if let Some(before) = self.last {
                        let was = before != 0;
                        if (!*falling && !was && on) || (*falling && was && !on) {
                            self.seen = true;
                        }
                    }
                    self.last = Some(value);
                }
            }
        }
    }

    fn verdict(&self) -> Option<String> {
        if let Some(f) = &self.failed {
            return Some(f.clone());
        }
        match &self.expectation {
            Expectation::Edge { falling, .. } if !self.seen => Some(format!(
                "{} did not {} (it stayed {})",
                self.expectation.device(),
                if *falling { "fall" } else { "rise" },
                self.last.unwrap_or(0)
            )),
            _ => None,
        }
    }
}

/// Runs `case` on `plc` (a fresh machine with the program loaded and its
/// settings applied) from time zero.
pub fn run_case(plc: &mut dyn Plc, case: &TestCase) -> Result<Outcome, CaseError> {
    let events = parse_events(&case.events).map_err(CaseError::Events)?;
    let mut inputs = Vec::with_capacity(events.len());
    for e in &events {
        let device = plc
            .device(&e.device)
            .and_then(|d| plc.check_input(d, e.value).map(|()| d))
            .map_err(|err| CaseError::Event(Located::new(e.line, err)))?;
        inputs.push(device);
    }
    let mut watches = Vec::new();
    for (i, line) in case.expect.iter().enumerate() {
        let expectation = Expectation::parse(line).map_err(|e| CaseError::Expect(i, e))?;
        let device = plc
            .device(expectation.device())
            .map_err(|e| CaseError::Device(i, e))?;
        watches.push(Watch {
            expectation,
            device,
            failed: None,
            last: None,
            seen: false,
        });
    }
    let instants = Instants::new(&events, &watches);
    // Counted before anything runs: a case past the limit runs nothing.
    if instants.clone().nth(MAX_SAMPLES).is_some() {
        return Err(CaseError::TooLong);
    }
    let mut pending = events.iter().zip(inputs).peekable();
    for t in instants {
        while let Some((event, device)) = pending.next_if(|(e, _)| e.time <= t) {
            plc.run_before(event.time);
            // Checked above: the machine takes it.
            let _ = plc.apply(Command::SetInput(device, event.value));
        }
        plc.run_until(t);
        for w in &mut watches {
            let value = plc.read(w.device);
            w.sample(t, value);
        }
    }
    Ok(watches
        .iter()
        .enumerate()
        .find_map(|(index, w)| {
            w.verdict().map(|observed| Outcome::Fail {
                index,
                expectation: w.expectation.to_string(),
                observed,
            })
        })
        .unwrap_or(Outcome::Pass))
}

/// Every instant to look at, in order, each once: the events' times, the
/// expectations' times and windows' ends, and each window sampled every
/// [`SAMPLE`] from its start. Yielded one at a time, so a long window
/// costs no memory.
#[derive(Clone)]
struct Instants {
    /// The single instants, sorted, each once.
    points: Vec<SimTime>,
    /// The next point not yet passed.
    next_point: usize,
    /// Windows `(from, to)` with `from < to`.
    windows: Vec<(SimTime, SimTime)>,
    /// The last instant yielded.
    last: Option<SimTime>,
}

impl Instants {
    fn new(events: &[crate::events::InputEvent], watches: &[Watch]) -> Instants {
        let mut points: Vec<SimTime> = events.iter().map(|e| e.time).collect();
        let mut windows = Vec::new();
        for w in watches {
            let (from, to) = w.expectation.span();
            points.extend([from, to]);
            if from < to {
                windows.push((from, to));
            }
        }
        points.sort_unstable();
        points.dedup();
        Instants {
            points,
            next_point: 0,
            windows,
            last: None,
        }
    }
}

impl Iterator for Instants {
    type Item = SimTime;

    fn next(&mut self) -> Option<SimTime> {
        let after = |t: SimTime| self.last.is_none_or(|last| t > last);
        while self.points.get(self.next_point).is_some_and(|&p| !after(p)) {
            self.next_point += 1;
        }
        let mut next = self.points.get(self.next_point).copied();
        if let Some(last) = self.last {
            // The next sample of each window the last instant lies in (a
            // window's start is a point, so none starts between samples).
            for &(from, to) in &self.windows {
                if (from..to).contains(&last) {
                    let steps = (last - from).as_nanos() / SAMPLE.as_nanos() + 1;
                    let sample =
                        from.saturating_add(SimTime::from_nanos(steps * SAMPLE.as_nanos()));
                    if sample < to && next.is_none_or(|n| sample < n) {
                        next = Some(sample);
                    }
                }
            }
        }
        self.last = next;
        next
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeSet;

    fn watch(line: &str) -> Watch {
        Watch {
            expectation: Expectation::parse(line).expect("expectation"),
            device: Device(0),
            failed: None,
            last: None,
            seen: false,
        }
    }

    /// The instants as a set, built the obvious way.
    fn naive(events: &[crate::events::InputEvent], watches: &[Watch]) -> Vec<SimTime> {
        let mut out: BTreeSet<SimTime> = events.iter().map(|e| e.time).collect();
        for w in watches {
            let (from, to) = w.expectation.span();
            out.extend([from, to]);
            let mut t = from;
            while t < to {
                out.insert(t);
                t = t.saturating_add(SAMPLE);
            }
        }
        out.into_iter().collect()
    }

    #[test]
    fn instants_are_every_point_and_every_sample_once_in_order() {
        let events = parse_events("0.5ms,X00,1\n3ms,X00,0\n7.25ms,X01,1\n").expect("events");
        let watches = [
            watch("Y00 = 1 at 2.5ms"),
            watch("Y00 stays 1 from 0.3ms to 4.1ms"),
            watch("Y01 rises within 2ms..9ms"),
            watch("Y02 falls within 8.7ms..8.7ms"),
        ];
        let walked: Vec<SimTime> = Instants::new(&events, &watches).collect();
        assert_eq!(walked, naive(&events, &watches));
        assert!(walked.windows(2).all(|w| w[0] < w[1]));
    }

    #[test]
    fn a_case_past_the_sample_limit_is_refused_before_it_runs() {
        let watches = [watch("Y00 stays 0 from 0s to 10001s")];
        let walked = Instants::new(&[], &watches);
        assert!(walked.clone().nth(MAX_SAMPLES).is_some());
        let watches = [watch("Y00 stays 0 from 0s to 9999s")];
        assert!(Instants::new(&[], &watches).nth(MAX_SAMPLES).is_none());
    }
}
