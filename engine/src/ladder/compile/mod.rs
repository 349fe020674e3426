//! Ladder → each machine's mnemonic text (the `.il` / `.asm` that
//! `hashigo run` accepts back).
//!
//! Each machine's ladder target (`target.rs` in its folder) picks one of
//! these compilers:
//!
//! - [`accumulator`]: MINASEC-U and the AVR PLC (one accumulator; partial
//!   results go to temporary relays);
//! - [`compile_listing`]: the same, with each rung's steps (for the editor);
//! - [`stack`]: PLC-IO86A and the Arduino sketch (block stacks, ORB / ANB);
//! - `il`: the soft PLC (IEC Instruction List, deferred `AND(` … `)`).

pub mod accumulator;
pub(crate) mod il;
mod listing;
pub mod stack;

pub use listing::{compile_listing, LeafSource, Listing, RungStart};

use std::collections::BTreeSet;

use super::element::{ContactKind, Element};
use super::grid::{Ladder, LadderError, Pos};
use super::net::{Net, RungLogic};
use crate::MachineId;

/// A compiled program with where its rungs and leaves are (what a
/// machine's ladder target's `compile` gives).
pub struct Mapped {
    /// The program text.
    pub text: String,
    /// Each rung's first step.
    pub starts: Vec<usize>,
    /// (rung among those given, leaf's cell, 0-based text line of the op
    /// reading or computing it), in emission order.
    pub sources: Vec<(usize, Pos, usize)>,
}

/// Settings a compiler needs beyond the ladder.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Options {
    /// The AVR PLC's scan period in ms (timer presets count scans; the
    /// compiled source writes them as `ms/Scan` so `--set scan=` applies).
    pub avr_scan_ms: u32,
}

impl Default for Options {
    fn default() -> Options {
        Options { avr_scan_ms: 10 }
    }
}

/// Compiles a whole ladder for `machine`: checks it against the machine's
/// capability table, then emits the program text. All problems found are
/// returned, each at its rung and cell.
pub fn compile(
    ladder: &Ladder,
    machine: MachineId,
    options: Options,
) -> Result<String, Vec<LadderError>> {
    let logic = ladder.logic(machine)?;
    let mapped = machine
        .compiler()
        .compile(&logic, &ladder.variables, options)?;
    Ok(mapped.text)
}

/// Compiles checked rung logic (from [`Ladder::logic`]).
pub fn compile_logic(
    rungs: &[RungLogic],
    machine: MachineId,
    options: Options,
) -> Result<String, Vec<LadderError>> {
    let mapped = machine.compiler().compile(rungs, &[], options)?;
    Ok(mapped.text)
}

/// Free bit devices for temporaries, taken in order, never one the
/// ladder itself uses.
#[derive(Clone, Debug)]
pub(crate) struct Temps {
    /// Never handed out yet, in reverse order (pop() gives the next).
    fresh: Vec<String>,
    /// Handed out and returned: reused first.
    returned: Vec<String>,
    what: &'static str,
}

impl Temps {
    /// A pool of `candidates` minus every device `rungs` mention.
    pub(crate) fn new(candidates: Vec<String>, rungs: &[RungLogic], what: &'static str) -> Temps {
        let used = used_devices(rungs);
        let mut fresh: Vec<String> = candidates
            .into_iter()
            .filter(|c| !used.contains(c))
            .collect();
        fresh.reverse();
        Temps {
            fresh,
            returned: Vec::new(),
            what,
        }
    }

    fn exhausted(&self) -> String {
        format!(
            "the rung needs more temporary relays than are free ({}): split it or free some",
            self.what
        )
    }

    /// Takes a temporary for the rung; the error explains what ran out.
    pub(crate) fn take(&mut self) -> Result<String, String> {
        self.returned
            .pop()
            .or_else(|| self.fresh.pop())
            .ok_or_else(|| self.exhausted())
    }

    /// Takes a relay for good (an edge's memory of the last scan): one no
    /// other rung has used as a temporary.
    pub(crate) fn take_for_good(&mut self) -> Result<String, String> {
        if self.fresh.is_empty() {
            return Err(self.exhausted());
        }
        Ok(self.fresh.remove(0))
    }

    /// Returns a temporary for reuse.
    pub(crate) fn give(&mut self, t: String) {
        self.returned.push(t);
    }
}

/// Every bit device a ladder reads or writes.
pub(crate) fn used_devices(rungs: &[RungLogic]) -> BTreeSet<String> {
    let mut used = BTreeSet::new();
    for r in rungs {
        for (e, _) in r.leaves() {
            if let Some(d) = e.read_device() {
                used.insert(d.to_string());
            }
        }
        for s in &r.sides {
            used.insert(s.variable.clone());
        }
        for (e, _) in &r.outputs {
            if let Some(d) = e.written_device() {
                used.insert(d.to_string());
            }
        }
    }
    used
}

/// The logical negation of a network of NO / NC contacts (De Morgan).
pub fn negate(net: &Net) -> Net {
    match net {
        Net::Leaf(Element::Contact { kind, device }, p) => {
            let kind = match kind {
                ContactKind::No => ContactKind::Nc,
                _ => ContactKind::No,
            };
            Net::Leaf(
                Element::Contact {
                    kind,
                    device: device.clone(),
                },
                *p,
            )
        }
        Net::Leaf(..) => net.clone(),
        Net::Series(v) => Net::Parallel(v.iter().map(negate).collect()),
        Net::Parallel(v) => Net::Series(v.iter().map(negate).collect()),
    }
}

/// Whether a network holds only contacts (no in-line boxes).
pub(crate) fn is_pure(net: &Net) -> bool {
    net.leaves()
        .iter()
        .all(|(e, _)| matches!(e, Element::Contact { .. }))
}

/// A contact leaf's device and whether it reads inverted (NC).
pub(crate) fn contact(net: &Net) -> Option<(&str, bool)> {
    match net {
        Net::Leaf(Element::Contact { kind, device }, _) => match kind {
            ContactKind::No => Some((device, false)),
            ContactKind::Nc => Some((device, true)),
            _ => None,
        },
        _ => None,
    }
}

/// The items of a network as a series (one item when it is not one).
pub(crate) fn series_items(net: &Net) -> Vec<Net> {
    match net {
        Net::Series(v) => v.clone(),
        other => vec![other.clone()],
    }
}

/// Size of a network in leaves (to pick which block goes first).
pub(crate) fn size(net: &Net) -> usize {
    net.leaves().len()
}

/// Replaces every rising / falling contact with a NO contact on the
/// device `edge(kind, device)` returns (code computing the edge there).
pub(crate) fn replace_edges(
    net: &Net,
    edge: &mut impl FnMut(ContactKind, &str) -> Result<String, String>,
) -> Result<Net, String> {
    Ok(match net {
        Net::Leaf(Element::Contact { kind, device }, p)
            if matches!(kind, ContactKind::Rising | ContactKind::Falling) =>
        {
            Net::Leaf(Element::no(&edge(*kind, device)?), *p)
        }
        Net::Leaf(..) => net.clone(),
        Net::Series(v) => Net::Series(
            v.iter()
                .map(|n| replace_edges(n, edge))
                .collect::<Result<_, _>>()?,
        ),
        Net::Parallel(v) => Net::Parallel(
            v.iter()
                .map(|n| replace_edges(n, edge))
                .collect::<Result<_, _>>()?,
        ),
    })
}
