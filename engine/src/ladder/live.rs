//! The live ladder's power flow: each element's power in the last scan,
//! as the machine itself computed it (issue #14). The compiler's source
//! map names the step that reads each contact's device (or computes each
//! in-line box), the machine's trace gives what that step read and left,
//! and the rung's network is walked with those values: a contact passes
//! the power into it while the bit its step read makes it conduct, a box
//! gives out its step's result. Nothing is evaluated from device values
//! read afterwards, so a pulse of one scan shows in that scan's colours.

use super::compile::{compile_listing, Listing, Options};
use super::element::{ContactKind, Element};
use super::eval::ElementPower;
use super::grid::Pos;
use super::grid::{Ladder, LadderError};
use super::net::{Net, RungLogic};
use super::why::{self, Explanation};
use crate::plc::trace::{SEEN_READ_OFF, SEEN_READ_ON, SEEN_RESULT_OFF, SEEN_RESULT_ON};
use crate::plc::{ScanTrace, TraceHistory};
use crate::MachineId;

/// A ladder compiled for a machine, ready to colour from its traces.
#[derive(Clone, Debug)]
pub struct LiveLadder {
    /// The non-empty rungs' logic, with their index in the ladder and
    /// each leaf's step (in the network's leaf order), looked up once.
    rungs: Vec<(usize, RungLogic, Vec<Option<usize>>)>,
    /// The compiled program and its source map.
    pub listing: Listing,
}

impl LiveLadder {
    /// Compiles `ladder` for `machine`; its listing is what to load.
    pub fn new(
        ladder: &Ladder,
        machine: MachineId,
        options: Options,
    ) -> Result<LiveLadder, Vec<LadderError>> {
        let listing = compile_listing(ladder, machine, options)?;
        let logic = ladder.logic(machine)?;
        let rungs = ladder
            .logic_indices()
            .into_iter()
            .zip(logic)
            .map(|(i, l)| {
                let steps = l
                    .leaves()
                    .into_iter()
                    .map(|(_, pos)| listing.step_of_leaf(i, pos))
                    .collect();
                (i, l, steps)
            })
            .collect();
        Ok(LiveLadder { rungs, listing })
    }

    /// Every element's power in the traced scan, rung by rung (ladder
    /// index, then the elements in the order the reference evaluator
    /// reports them: the network's leaves, then the outputs). A leaf whose
    /// step did not run in the scan passes no power.
    pub fn power(&self, trace: &ScanTrace) -> Vec<(usize, Vec<ElementPower>)> {
        self.rungs
            .iter()
            .map(|(index, logic, steps)| (*index, rung_power(logic, steps, trace)))
            .collect()
    }

    /// Why the power at `target` in rung `rung` (ladder index) is what it
    /// was in the traced scan ([`why::explain`]); `None` for an empty
    /// rung or a cell that is neither a contact nor an output.
    pub fn explain(&self, trace: &ScanTrace, rung: usize, target: Pos) -> Option<Explanation> {
        let (_, logic, steps) = self.rungs.iter().find(|(i, _, _)| *i == rung)?;
        // A box input's network (its cell or one of its leaves) is
        // explained as the rung of its own it runs as.
        let mut offset = logic.condition.leaves().len();
        for side in &logic.sides {
            let leaves = side.net.leaves();
            let here = side.pos == target || leaves.iter().any(|(_, p)| *p == target);
            if here {
                let own = side.as_rung();
                let steps = steps.get(offset..offset + leaves.len())?;
                return explain_logic(&own, steps, trace, target);
            }
            offset += leaves.len();
        }
        explain_logic(logic, steps, trace, target)
    }

    /// The ladder index and logic of every non-empty rung.
    pub fn rungs(&self) -> impl Iterator<Item = (usize, &RungLogic)> {
        self.rungs.iter().map(|(i, l, _)| (*i, l))
    }
}

/// Why the power at `target` of `logic` (its leaves' steps `steps`) is
/// what it was in the traced scan.
fn explain_logic(
    logic: &RungLogic,
    steps: &[Option<usize>],
    trace: &ScanTrace,
    target: Pos,
) -> Option<Explanation> {
    let report = rung_power(logic, steps, trace);
    let conducts: Vec<bool> = logic
        .condition
        .leaves()
        .iter()
        .enumerate()
        .map(|(i, (e, _))| {
            let read = steps
                .get(i)
                .copied()
                .flatten()
                .filter(|&s| trace.ran.get(s).copied().unwrap_or(false))
                .is_some_and(|s| trace.read[s]);
            let p = report[i];
            why::leaf_conducts(e, read, p.power_in, p.power_out)
        })
        .collect();
    why::explain(logic, target, &conducts)
}

/// One rung's elements' power in the traced scan: its leaves in
/// [`Net::leaves`] order, then its outputs.
fn rung_power(logic: &RungLogic, steps: &[Option<usize>], trace: &ScanTrace) -> Vec<ElementPower> {
    let mut report = Vec::new();
    let mut walk = Walk {
        steps,
        next: 0,
        trace,
    };
    let power = walk.eval(&logic.condition, true, &mut report);
    for (_, pos) in &logic.outputs {
        report.push(ElementPower {
            pos: *pos,
            power_in: power,
            power_out: power,
        });
    }
    // A box input's network, then the input's cell with its power.
    for side in &logic.sides {
        let power = walk.eval(&side.net, true, &mut report);
        report.push(ElementPower {
            pos: side.pos,
            power_in: power,
            power_out: power,
        });
    }
    report
}

/// An element whose power may have changed in some scan since the last
/// look: marked for a frame so a one-scan pulse is never lost.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Pulse {
    /// Its cell.
    pub pos: Pos,
    /// How often its step's read bit rose (a contact), since the last look.
    pub rises: u32,
}

impl LiveLadder {
    /// The elements whose power was on in some scan and off in another
    /// since the history was taken, rung by rung. It never misses one
    /// that changed (it may name one whose inputs changed in ways that
    /// cancel out).
    pub fn pulses(&self, history: &TraceHistory) -> Vec<(usize, Vec<Pulse>)> {
        self.rungs
            .iter()
            .map(|(index, logic, steps)| {
                let mut found = Vec::new();
                let mut span = Span {
                    steps,
                    next: 0,
                    history,
                };
                let (on, off) = span.eval(&logic.condition, (true, false), &mut found);
                if on && off {
                    for (_, pos) in &logic.outputs {
                        found.push(Pulse {
                            pos: *pos,
                            rises: 0,
                        });
                    }
                }
                (*index, found)
            })
            .collect()
    }
}

/// Which values each point took over many scans: (could be on, could be
/// off), from the values each step's bits took.
struct Span<'a> {
    /// Each leaf's step, in leaf order, and the next leaf's place.
    steps: &'a [Option<usize>],
    next: usize,
    history: &'a TraceHistory,
}

impl Span<'_> {
    fn eval(&mut self, net: &Net, pin: (bool, bool), found: &mut Vec<Pulse>) -> (bool, bool) {
        match net {
            Net::Series(v) => v.iter().fold(pin, |p, n| self.eval(n, p, found)),
            Net::Parallel(v) => {
                let all: Vec<(bool, bool)> = v.iter().map(|n| self.eval(n, pin, found)).collect();
                (all.iter().any(|x| x.0), all.iter().all(|x| x.1))
            }
            Net::Leaf(e, pos) => {
                let step = self.steps.get(self.next).copied().flatten();
                self.next += 1;
                let seen = step
                    .and_then(|s| self.history.seen.get(s).copied())
                    .unwrap_or(0);
                let rises = step
                    .and_then(|s| self.history.rises.get(s).copied())
                    .unwrap_or(0);
                let out = if seen == 0 {
                    (false, true)
                } else if let Element::Contact { kind, .. } = e {
                    let (on, off) = (seen & SEEN_READ_ON != 0, seen & SEEN_READ_OFF != 0);
                    let (conducts, blocks) = match kind {
                        ContactKind::Nc => (off, on),
                        _ => (on, off),
                    };
                    (pin.0 && conducts, pin.1 || blocks)
                } else {
                    (seen & SEEN_RESULT_ON != 0, seen & SEEN_RESULT_OFF != 0)
                };
                if out.0 && out.1 {
                    found.push(Pulse { pos: *pos, rises });
                }
                out
            }
        }
    }
}

struct Walk<'a> {
    /// Each leaf's step, in leaf order, and the next leaf's place.
    steps: &'a [Option<usize>],
    next: usize,
    trace: &'a ScanTrace,
}

impl Walk<'_> {
    fn eval(&mut self, net: &Net, pin: bool, report: &mut Vec<ElementPower>) -> bool {
        match net {
            Net::Series(v) => v.iter().fold(pin, |p, n| self.eval(n, p, report)),
            Net::Parallel(v) => v.iter().fold(false, |a, n| self.eval(n, pin, report) | a),
            Net::Leaf(e, pos) => {
                let step = self
                    .steps
                    .get(self.next)
                    .copied()
                    .flatten()
                    .filter(|&s| self.trace.ran.get(s).copied().unwrap_or(false));
                self.next += 1;
                let out = match (e, step) {
                    (_, None) => false,
                    (Element::Contact { kind, .. }, Some(s)) => {
                        let read = self.trace.read[s];
                        // An edge contact's step reads the relay its edge
                        // was computed into: that relay is the contact.
                        let conducts = match kind {
                            ContactKind::Nc => !read,
                            _ => read,
                        };
                        pin && conducts
                    }
                    (_, Some(s)) => self.trace.result[s],
                };
                report.push(ElementPower {
                    pos: *pos,
                    power_in: pin,
                    power_out: out,
                });
                out
            }
        }
    }
}
