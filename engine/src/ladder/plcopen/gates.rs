//! Boolean blocks lowered to ladder (issue #18): AND, OR and XOR of
//! powers, and the SR / RS flip-flops, rewired into the body's graph of
//! points before its rungs are read off, so they come out as the series,
//! parallel and self-holding rungs a ladder draws.
//!
//! - OR: its inputs' points are joined (parallel branches meeting), when
//!   nothing else takes power from them (else the join would feed power
//!   back into that other element);
//! - AND: each input's network after the first is moved to start where the
//!   one before it ends (series), when it is its own (only the AND takes
//!   power from it);
//! - XOR of two single contacts: two branches, A and not B, not A and B;
//! - SR / RS on a relay the map gives the instance (`SR0,M10`), with R a
//!   single contact: one self-holding rung, `S or (Q and not R)` (set
//!   wins) or `(S or Q) and not R` (reset wins).
//!
//! What does not fit these shapes is refused at the block's line with the
//! reason, never approximated.

use std::collections::HashMap;

use super::import::Body;
use crate::error::Located;
use crate::ladder::element::{CoilKind, ContactKind, Element};
use crate::ladder::grid::Pos;
use crate::ladder::net::Net;
use crate::limits::MAX_GATE_WORK;

/// A boolean block waiting to be lowered.
#[derive(Clone, Debug)]
pub(super) struct Gate {
    pub kind: GateKind,
    /// The points its inputs take power from, in pin order.
    pub inputs: Vec<usize>,
    /// Its output's point.
    pub out: usize,
    /// Its place and line.
    pub pos: Pos,
    pub line: usize,
    /// `AND block`, `SR block SR0`: for messages.
    pub what: String,
}

/// Which block.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) enum GateKind {
    And,
    Or,
    Xor,
    /// A flip-flop on a relay; set wins (SR) or reset wins (RS).
    Flip {
        relay: String,
        set_wins: bool,
    },
    /// A TOF (or, `pulse`, a TP) from an on-delay timer coil and a relay
    /// that holds its output.
    Delay {
        coil: Element,
        timer: String,
        relay: String,
        pulse: bool,
    },
}

impl Body {
    /// Lowers every gate, or says why one cannot be.
    pub(super) fn lower_gates(&mut self) -> Result<(), Vec<Located<super::ImportError>>> {
        let gates = std::mem::take(&mut self.gates);
        let mut errors = Vec::new();
        for g in gates {
            if self.gate_work > MAX_GATE_WORK {
                let why = format!(
                    "the file's blocks take more than {MAX_GATE_WORK} steps to lower (docs/limits.md)"
                );
                errors.push(Located::new(g.line, super::ImportError::Gate(g.what, why)));
                break;
            }
            if let Err(why) = self.lower(&g) {
                let what = g.what.clone();
                errors.push(Located::new(g.line, super::ImportError::Gate(what, why)));
            }
        }
        if errors.is_empty() {
            Ok(())
        } else {
            Err(errors)
        }
    }

    /// How many elements take power from each point (joined points).
    fn takers(&mut self) -> HashMap<usize, usize> {
        self.gate_work += self.consumed.len();
        let mut count = HashMap::new();
        for p in self.consumed.clone() {
            *count.entry(self.find(p)).or_insert(0) += 1;
        }
        count
    }

    fn lower(&mut self, g: &Gate) -> Result<(), String> {
        match &g.kind {
            GateKind::Or => {
                let takers = self.takers();
                for &p in &g.inputs {
                    let p = self.find(p);
                    if takers.get(&p).copied().unwrap_or(0) > 1 {
                        return Err(
                            "an input also feeds another element: draw the branches in parallel"
                                .into(),
                        );
                    }
                }
                for &p in &g.inputs {
                    self.union(p, g.out);
                }
                Ok(())
            }
            GateKind::And => {
                let mut end = g.inputs.first().copied().ok_or("no inputs")?;
                for &p in &g.inputs[1..] {
                    self.reroot(p, end)?;
                    end = p;
                }
                self.union(end, g.out);
                Ok(())
            }
            GateKind::Xor => {
                let [a, b] = g.inputs[..] else {
                    return Err("XOR of more than two inputs: draw the branches".into());
                };
                let (ca, _, la) = self.single_contact(a)?;
                let (cb, _, lb) = self.single_contact(b)?;
                let out = g.out;
                let mid = [self.fresh(), self.fresh()];
                let at = |k: usize| Pos::new(g.pos.row, g.pos.col.wrapping_add(k));
                let (ka, kb) = (invert(&ca)?, invert(&cb)?);
                self.edges
                    .push((super::import::RAIL, mid[0], Net::Leaf(ca, at(1)), la));
                self.edges.push((mid[0], out, Net::Leaf(kb, at(2)), lb));
                self.edges
                    .push((super::import::RAIL, mid[1], Net::Leaf(ka, at(3)), la));
                self.edges.push((mid[1], out, Net::Leaf(cb, at(4)), lb));
                Ok(())
            }
            GateKind::Delay {
                coil,
                timer,
                relay,
                pulse,
            } => self.lower_delay(g, coil, timer, relay, *pulse),
            GateKind::Flip { relay, set_wins } => {
                let [s, r] = g.inputs[..] else {
                    return Err("a flip-flop has S and R".into());
                };
                let (cr, _, lr) = self.single_contact(r)?;
                let not_r = invert(&cr)?;
                let at = |k: usize| Pos::new(g.pos.row, g.pos.col.wrapping_add(k));
                let held = Element::no(relay);
                if *set_wins {
                    // Q := S or (Q and not R): a branch beside S.
                    let mid = self.fresh();
                    self.edges
                        .push((super::import::RAIL, mid, Net::Leaf(held, at(1)), g.line));
                    self.edges.push((mid, s, Net::Leaf(not_r, at(2)), lr));
                    self.union(s, g.out);
                } else {
                    // Q := (S or Q) and not R: the hold beside S, then not R.
                    self.edges
                        .push((super::import::RAIL, s, Net::Leaf(held, at(1)), g.line));
                    self.edges.push((s, g.out, Net::Leaf(not_r, at(2)), lr));
                }
                self.consumed.push(g.out);
                let coil = Element::Coil {
                    kind: CoilKind::Normal,
                    device: relay.clone(),
                };
                self.outputs.push((g.out, coil, at(3), g.line));
                Ok(())
            }
        }
    }

    /// TOF: `R := IN or (R and not T)`, T's coil on `R and not IN`, Q is
    /// R. TP: `R := IN rising or (R and not T)`, T's coil on R, Q is R.
    /// IN must be one contact from the rail (it is used twice).
    fn lower_delay(
        &mut self,
        g: &Gate,
        coil: &Element,
        timer: &str,
        relay: &str,
        pulse: bool,
    ) -> Result<(), String> {
        let rail = super::import::RAIL;
        let input = g.inputs.first().copied().ok_or("no IN")?;
        let (c_in, at_in, line) = self.single_contact(input)?;
        let at = |k: usize| Pos::new(g.pos.row, g.pos.col.wrapping_add(k));
        let set = if pulse { rising(&c_in)? } else { c_in.clone() };
        let (hold, running) = (self.fresh(), self.fresh());
        // The relay: set by IN (its rise), held until the timer is done.
        self.edges.push((rail, input, Net::Leaf(set, at_in), line));
        self.edges
            .push((rail, hold, Net::Leaf(Element::no(relay), at(1)), g.line));
        self.edges
            .push((hold, input, Net::Leaf(Element::nc(timer), at(2)), g.line));
        self.consumed.extend([rail, rail, hold, input]);
        let held = Element::Coil {
            kind: CoilKind::Normal,
            device: relay.to_string(),
        };
        self.outputs.push((input, held, at(3), g.line));
        // The timer: runs while the relay holds (and, TOF, IN is off).
        self.edges
            .push((rail, running, Net::Leaf(Element::no(relay), at(4)), g.line));
        let timing = if pulse {
            running
        } else {
            let off = self.fresh();
            self.edges
                .push((running, off, Net::Leaf(invert(&c_in)?, at(5)), line));
            self.consumed.push(running);
            off
        };
        self.consumed.extend([rail, timing]);
        self.outputs.push((timing, coil.clone(), at(6), g.line));
        // Q: the relay.
        self.edges
            .push((rail, g.out, Net::Leaf(Element::no(relay), at(7)), g.line));
        self.consumed.push(rail);
        Ok(())
    }

    /// A new point.
    fn fresh(&mut self) -> usize {
        let p = self.parent.len();
        self.parent.push(p);
        p
    }

    /// The one contact from the rail that feeds `p` and nothing else,
    /// taken out of the graph (its element, place and line).
    fn single_contact(&mut self, p: usize) -> Result<(Element, Pos, usize), String> {
        let p = self.find(p);
        let rail = self.find(super::import::RAIL);
        let takers = self.takers();
        self.gate_work += self.edges.len();
        let feeding: Vec<usize> = (0..self.edges.len())
            .filter(|&i| {
                let b = self.edges[i].1;
                self.find(b) == p
            })
            .collect();
        let only = match feeding[..] {
            [i] if takers.get(&p).copied().unwrap_or(0) == 1 => i,
            _ => return Err("this input must be one contact from the rail".into()),
        };
        let (a, _, net, line) = self.edges[only].clone();
        match net {
            Net::Leaf(e @ Element::Contact { .. }, at) if self.find(a) == rail => {
                self.edges.remove(only);
                Ok((e, at, line))
            }
            _ => Err("this input must be one contact from the rail".into()),
        }
    }

    /// Moves the network feeding `p` (which only `p`'s taker uses) to
    /// start at `from` instead of the rail: in series after it.
    fn reroot(&mut self, p: usize, from: usize) -> Result<(), String> {
        let rail = self.find(super::import::RAIL);
        let target = self.find(p);
        // The edges on the way back from `p` to the rail.
        let mut part = Vec::new();
        let mut todo = vec![target];
        let mut seen = vec![target];
        while let Some(q) = todo.pop() {
            self.gate_work += self.edges.len();
            for i in 0..self.edges.len() {
                let (a, b) = (self.edges[i].0, self.edges[i].1);
                if self.find(b) != q {
                    continue;
                }
                part.push(i);
                let a = self.find(a);
                if a != rail && !seen.contains(&a) {
                    seen.push(a);
                    todo.push(a);
                }
            }
        }
        // Its own: nothing outside it takes power from its points.
        let takers = self.takers();
        for &q in &seen {
            let inside = part
                .iter()
                .filter(|&&i| {
                    let a = self.edges[i].0;
                    self.find(a) == q
                })
                .count();
            let expected = if q == target { 1 } else { inside };
            if takers.get(&q).copied().unwrap_or(0) != expected {
                return Err(
                    "an input's network also feeds another element: draw it in series".into(),
                );
            }
        }
        for i in part {
            let a = self.edges[i].0;
            if self.find(a) == rail {
                self.edges[i].0 = from;
                // `from` now feeds it too: a later OR must see that.
                self.consumed.push(from);
            }
        }
        Ok(())
    }
}

/// The contact that conducts in the scan `c` starts conducting.
fn rising(c: &Element) -> Result<Element, String> {
    rekind(c, "IN is already an edge contact", |kind| match kind {
        ContactKind::No => Some(ContactKind::Rising),
        // NC conducts from when the device falls.
        ContactKind::Nc => Some(ContactKind::Falling),
        _ => None,
    })
}

/// The contact that conducts when `c` does not.
fn invert(c: &Element) -> Result<Element, String> {
    rekind(c, "an edge contact cannot be inverted", |kind| match kind {
        ContactKind::No => Some(ContactKind::Nc),
        ContactKind::Nc => Some(ContactKind::No),
        _ => None,
    })
}

/// Contact `c` on the same device with the kind `to` gives (`None`: the
/// reason `edge` says).
fn rekind(
    c: &Element,
    edge: &str,
    to: impl Fn(ContactKind) -> Option<ContactKind>,
) -> Result<Element, String> {
    match c {
        Element::Contact { kind, device } => Ok(Element::Contact {
            kind: to(*kind).ok_or(edge)?,
            device: device.clone(),
        }),
        _ => Err("not a contact".into()),
    }
}
