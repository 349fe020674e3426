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
use super::grid::{Ladder, LadderError};
use super::net::{Net, RungLogic};
use crate::plc::ScanTrace;
use crate::MachineId;

/// A ladder compiled for a machine, ready to colour from its traces.
#[derive(Clone, Debug)]
pub struct LiveLadder {
    /// The non-empty rungs' logic, with their index in the ladder.
    rungs: Vec<(usize, RungLogic)>,
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
        let indices = ladder
            .rungs
            .iter()
            .enumerate()
            .filter(|(_, r)| !r.is_empty())
            .map(|(i, _)| i);
        Ok(LiveLadder {
            rungs: indices.zip(logic).collect(),
            listing,
        })
    }

    /// Every element's power in the traced scan, rung by rung (ladder
    /// index, then the elements in the order the reference evaluator
    /// reports them: the network's leaves, then the outputs). A leaf whose
    /// step did not run in the scan passes no power.
    pub fn power(&self, trace: &ScanTrace) -> Vec<(usize, Vec<ElementPower>)> {
        self.rungs
            .iter()
            .map(|(index, logic)| {
                let mut report = Vec::new();
                let walk = Walk {
                    rung: *index,
                    listing: &self.listing,
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
                (*index, report)
            })
            .collect()
    }
}

struct Walk<'a> {
    rung: usize,
    listing: &'a Listing,
    trace: &'a ScanTrace,
}

impl Walk<'_> {
    fn eval(&self, net: &Net, pin: bool, report: &mut Vec<ElementPower>) -> bool {
        match net {
            Net::Series(v) => v.iter().fold(pin, |p, n| self.eval(n, p, report)),
            Net::Parallel(v) => v.iter().fold(false, |a, n| self.eval(n, pin, report) | a),
            Net::Leaf(e, pos) => {
                let step = self
                    .listing
                    .step_of_leaf(self.rung, *pos)
                    .filter(|&s| self.trace.ran.get(s).copied().unwrap_or(false));
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
