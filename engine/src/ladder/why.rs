//! "Why is this coil off (or on)?" (issue #16): the elements that decide
//! the power at a coil, or at a contact's right side, in one scan.
//!
//! A rung is a series-parallel network, so the question has an exact
//! answer in terms of which elements would have to change:
//! - when one element changing alone would flip the answer, every such
//!   element is named, and each alone suffices ([`Explanation::together`]
//!   false): the contacts of a powered series chain, the one open contact
//!   in each of several branches;
//! - otherwise the smallest set that must change together is named (the
//!   two open contacts of one series chain), and no smaller set would do.
//!
//! Each element is judged by whether it passes power when it gets it: a
//! contact by the bit its step read, a box (timer, compare) by what it
//! gave out; a box that got no power is not blamed (the cause is before
//! it).

use std::collections::HashMap;

use super::edit::{xref, UseRole};
use super::element::{ContactKind, Element};
use super::grid::{Ladder, Pos};
use super::net::{Net, RungLogic};

/// Why the power at one element is what it is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Explanation {
    /// The element asked about.
    pub target: Pos,
    /// Whether power reaches it (a coil) or leaves it (a contact).
    pub powered: bool,
    /// The elements that decide it, left to right, top to bottom.
    pub causes: Vec<Pos>,
    /// Whether the causes must all change together to flip the answer
    /// (else any one of them alone flips it).
    pub together: bool,
}

/// Explains the power at `target` in `logic`: at a coil's input, or at a
/// leaf's right side. `conducts[i]` says whether leaf `i` (in
/// [`Net::leaves`] order) passes power when it gets it. `None` if
/// `target` is neither an output nor a leaf of the rung.
pub fn explain(logic: &RungLogic, target: Pos, conducts: &[bool]) -> Option<Explanation> {
    let leaves: HashMap<Pos, usize> = logic
        .condition
        .leaves()
        .iter()
        .enumerate()
        .map(|(i, (_, p))| (*p, i))
        .collect();
    let path = if logic.outputs.iter().any(|(_, p)| *p == target) {
        vec![&logic.condition]
    } else {
        let mut path = Vec::new();
        if !path_to(&logic.condition, target, &mut path) {
            return None;
        }
        path
    };
    let state = |pos: Pos| leaves.get(&pos).is_some_and(|&i| conducts[i]);
    let powered = path.iter().all(|n| eval(n, &state, None));
    // Every leaf that alone flips the answer.
    let mut single: Vec<Pos> = path
        .iter()
        .flat_map(|n| n.leaves())
        .map(|(_, p)| p)
        .filter(|&p| path.iter().all(|n| eval(n, &state, Some(p))) != powered)
        .collect();
    if !single.is_empty() {
        crate::sort::all(&mut single);
        return Some(Explanation {
            target,
            powered,
            causes: single,
            together: false,
        });
    }
    // The smallest set that flips it: to power a series every part
    // must conduct, a parallel any one branch; to cut, the reverse.
    let mut causes = Vec::new();
    for n in &path {
        let (_, set) = if powered {
            off_cost(n, &state)
        } else {
            on_cost(n, &state)
        };
        if powered {
            // Cutting one part of the path is enough: the cheapest.
            if causes.is_empty() || set.len() < causes.len() {
                causes = set;
            }
        } else {
            causes.extend(set);
        }
    }
    crate::sort::all(&mut causes);
    Some(Explanation {
        target,
        powered,
        causes,
        together: true,
    })
}

/// Collects the networks that must all conduct for power to leave
/// `target`: the series parts before it on the way down, then itself.
fn path_to<'a>(net: &'a Net, target: Pos, path: &mut Vec<&'a Net>) -> bool {
    match net {
        Net::Leaf(_, p) => {
            if *p == target {
                path.push(net);
            }
            *p == target
        }
        Net::Series(v) => {
            for (i, child) in v.iter().enumerate() {
                let mark = path.len();
                if path_to(child, target, path) {
                    // The parts before it in this series come first.
                    let before: Vec<&Net> = v[..i].iter().collect();
                    path.splice(mark..mark, before);
                    return true;
                }
            }
            false
        }
        Net::Parallel(v) => v.iter().any(|child| path_to(child, target, path)),
    }
}

/// Whether `net` conducts, with the leaf at `flip` (if any) changed.
fn eval(net: &Net, state: &impl Fn(Pos) -> bool, flip: Option<Pos>) -> bool {
    match net {
        Net::Leaf(_, p) => state(*p) != (flip == Some(*p)),
        Net::Series(v) => v.iter().all(|n| eval(n, state, flip)),
        Net::Parallel(v) => v.iter().any(|n| eval(n, state, flip)),
    }
}

/// The fewest leaves to change so that `net` conducts, and which.
fn on_cost(net: &Net, state: &impl Fn(Pos) -> bool) -> (usize, Vec<Pos>) {
    match net {
        Net::Leaf(_, p) if state(*p) => (0, Vec::new()),
        Net::Leaf(_, p) => (1, vec![*p]),
        Net::Series(v) => all_of(v.iter().map(|n| on_cost(n, state))),
        Net::Parallel(v) => cheapest(v.iter().map(|n| on_cost(n, state))),
    }
}

/// The fewest leaves to change so that `net` no longer conducts.
fn off_cost(net: &Net, state: &impl Fn(Pos) -> bool) -> (usize, Vec<Pos>) {
    match net {
        Net::Leaf(_, p) if state(*p) => (1, vec![*p]),
        Net::Leaf(_, _) => (0, Vec::new()),
        Net::Series(v) => cheapest(v.iter().map(|n| off_cost(n, state))),
        Net::Parallel(v) => all_of(v.iter().map(|n| off_cost(n, state))),
    }
}

/// Every option's changes together.
fn all_of(options: impl Iterator<Item = (usize, Vec<Pos>)>) -> (usize, Vec<Pos>) {
    options.fold((0, Vec::new()), |(n, mut set), (m, more)| {
        set.extend(more);
        (n + m, set)
    })
}

/// The option with the fewest changes.
fn cheapest(options: impl Iterator<Item = (usize, Vec<Pos>)>) -> (usize, Vec<Pos>) {
    options.min_by_key(|(n, _)| *n).unwrap_or((0, Vec::new()))
}

/// Whether a leaf passes power when it gets it: a contact by the bit its
/// step read (`read`), a box by its output (`power_out`) when it had
/// power in, and not blamed when it had none.
pub fn leaf_conducts(element: &Element, read: bool, power_in: bool, power_out: bool) -> bool {
    match element {
        Element::Contact { kind, .. } => match kind {
            ContactKind::Nc => !read,
            _ => read,
        },
        _ => !power_in || power_out,
    }
}

/// One element an explanation names, with what the user follows next.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Cause {
    /// Its cell.
    pub pos: Pos,
    /// The element.
    pub element: Element,
    /// The device it reads, if any.
    pub device: Option<String>,
    /// The rungs (ladder indices) whose outputs write that device: where
    /// to look next. Empty for an input or a device nothing drives.
    pub drivers: Vec<usize>,
}

/// The elements `why` names in rung `rung` of `ladder`, each with the
/// rungs that drive its device.
pub fn causes(ladder: &Ladder, rung: usize, why: &Explanation) -> Vec<Cause> {
    let Some(r) = ladder.rungs.get(rung) else {
        return Vec::new();
    };
    why.causes
        .iter()
        .filter_map(|&pos| {
            let element = r.get(pos)?.clone();
            let device = match &element {
                Element::Contact { device, .. } => Some(device.clone()),
                _ => None,
            };
            let drivers = device
                .as_deref()
                .map_or_else(Vec::new, |d| drivers(ladder, d));
            Some(Cause {
                pos,
                element,
                device,
                drivers,
            })
        })
        .collect()
}

/// The rungs whose outputs (coils, pulses, timer and counter coils)
/// write `device`, top to bottom, each once.
pub fn drivers(ladder: &Ladder, device: &str) -> Vec<usize> {
    let mut rungs: Vec<usize> = xref(ladder, device)
        .into_iter()
        .filter(|u| u.role == UseRole::Coil)
        .map(|u| u.rung)
        .collect();
    rungs.dedup();
    rungs
}

/// The output that decides `device`'s state at the end of a scan: the
/// last one in the ladder that writes it (rung, cell).
pub fn deciding_output(ladder: &Ladder, device: &str) -> Option<(usize, Pos)> {
    xref(ladder, device)
        .into_iter()
        .filter(|u| u.role == UseRole::Coil)
        .map(|u| (u.rung, u.pos))
        .next_back()
}

/// A box that writes `device` through one of its outputs (`CV => parts`),
/// or the box of the instance whose output `device` names (`c0.CV`):
/// the last one in the ladder (rung, cell, the output pin). What `why`
/// names when no coil or output box writes it.
pub fn box_output(ladder: &Ladder, device: &str) -> Option<(usize, Pos, String)> {
    let device = device.trim();
    let member = device.split_once('.');
    let mut found = None;
    for (i, rung) in ladder.rungs.iter().enumerate() {
        for (pos, e) in rung.elements() {
            let Some(b) = e.block() else {
                continue;
            };
            let through = b
                .outputs
                .iter()
                .find(|(_, v)| v.trim().eq_ignore_ascii_case(device))
                .map(|(pin, _)| pin.clone());
            let own = member
                .filter(|(inst, _)| {
                    !b.instance.is_empty() && b.instance.trim().eq_ignore_ascii_case(inst)
                })
                .and_then(|(_, pin)| {
                    let kind = b.kind();
                    crate::ladder::user_blocks::outputs(&kind)
                        .into_iter()
                        .find(|(p, _)| p.eq_ignore_ascii_case(pin))
                        .map(|(p, _)| p.to_string())
                });
            if let Some(pin) = through.or(own) {
                found = Some((i, pos, pin));
            }
        }
    }
    found
}
