//! The order and the joins of a body's blocks: blocks are lowered in the
//! flow of power whatever order the file writes them in, and the ORs
//! (OR blocks and wires joined at an input) first, by joining points.

use std::collections::{HashMap, HashSet};

use super::body::{Body, Gate, GateKind};
use crate::error::Located;
use crate::ladder::element::Element;
use crate::ladder::grid::Pos;
use crate::ladder::net::Net;

impl Gate {
    /// The points it takes power from and those it gives power to (a
    /// counter's LD or R and a CTUD's QD besides its pins and output).
    fn points(&self) -> (Vec<usize>, Vec<usize>) {
        let mut inputs = self.inputs.clone();
        let mut outputs = vec![self.out];
        if let GateKind::Count {
            load, reset, empty, ..
        } = &self.kind
        {
            inputs.extend(load.iter().chain(reset));
            outputs.extend(empty);
        }
        (inputs, outputs)
    }
}

impl Body {
    /// `gates` ordered so that each comes after every gate its inputs take
    /// power from, through any wires and contacts (as the origin tools run
    /// a block after what feeds it): lowering one rewires the network
    /// feeding its inputs, which must be built by then, whatever order the
    /// file writes them in. Gates in a loop of feedback keep file order
    /// after the rest. Linear in the body's size (Kahn's algorithm over
    /// the points).
    pub(in crate::formats::plcopen) fn in_flow_order(&mut self, gates: Vec<Gate>) -> Vec<Gate> {
        let mut arrows = Vec::new();
        for g in &gates {
            let (inputs, outputs) = g.points();
            for &o in &outputs {
                arrows.extend(inputs.iter().map(|&p| (p, o)));
            }
        }
        let rank = self.flow_ranks(arrows);
        let mut keyed: Vec<(usize, Gate)> = gates
            .into_iter()
            .map(|g| {
                // Before whatever reads any of its outputs.
                let outputs = g.points().1;
                let first = outputs
                    .iter()
                    .filter_map(|&o| rank.get(&self.find(o)).copied())
                    .min();
                (first.unwrap_or(usize::MAX), g)
            })
            .collect();
        // Stable: equal ranks (loops) keep file order.
        crate::sort::by_key(&mut keyed, |(r, _)| *r);
        keyed.into_iter().map(|(_, g)| g).collect()
    }

    /// Each point's place in the flow of power from the rail (a point
    /// comes after every point with an edge, or one of `more` arrows, into
    /// it); points on a loop have none. Kahn's algorithm: linear.
    pub(in crate::formats::plcopen) fn flow_ranks(
        &mut self,
        more: Vec<(usize, usize)>,
    ) -> HashMap<usize, usize> {
        self.gate_work += self.edges.len() + more.len();
        let mut next: HashMap<usize, Vec<usize>> = HashMap::new();
        let mut pending: HashMap<usize, usize> = HashMap::new();
        let ends: Vec<(usize, usize)> = self.edges.iter().map(|e| (e.from, e.to)).collect();
        for (a, b) in ends.into_iter().chain(more) {
            let (a, b) = (self.find(a), self.find(b));
            if a == b {
                continue;
            }
            next.entry(a).or_default().push(b);
            *pending.entry(b).or_insert(0) += 1;
            pending.entry(a).or_insert(0);
        }
        let mut ready: Vec<usize> = pending
            .iter()
            .filter(|(_, &n)| n == 0)
            .map(|(&p, _)| p)
            .collect();
        crate::sort::all(&mut ready);
        let mut rank: HashMap<usize, usize> = HashMap::with_capacity(pending.len());
        while let Some(p) = ready.pop() {
            rank.insert(p, rank.len());
            for &q in next.get(&p).map(Vec::as_slice).unwrap_or(&[]) {
                if let Some(n) = pending.get_mut(&q) {
                    *n -= 1;
                    if *n == 0 {
                        ready.push(q);
                    }
                }
            }
        }
        rank
    }

    /// ORs: OR blocks and wires joined at an input, each its inputs'
    /// wires joined. A wire whose power only joins of the same wires
    /// take is one node with them (a branch drawn once and read by
    /// several elements, as Hashigo's own export writes it): its point is
    /// joined to theirs. A wire that also feeds something else, or joins
    /// of other wires, would be fed their power back: a spare relay's
    /// contact carries it instead (one relay per wire). Linear: the
    /// takers are counted once, and each join's wires are compared by a
    /// number given to each distinct set.
    pub(in crate::formats::plcopen) fn lower_joins(
        &mut self,
        joins: Vec<Gate>,
    ) -> Vec<Located<crate::formats::plcopen::ImportError>> {
        let takers = self.takers();
        let wires = self.join_wires(&joins);
        // Each wire: how many joins take it, and whether they differ.
        let mut in_joins: HashMap<usize, (usize, usize, bool)> = HashMap::new();
        for (set, id) in &wires {
            for &p in set {
                let e = in_joins.entry(p).or_insert((0, *id, false));
                e.0 += 1;
                e.2 |= e.1 != *id;
            }
        }
        // A flip-flop's output point is where its relay's coil goes: joined,
        // the other wires' power would set it. Its wire is relayed. (The
        // other blocks give their output from a contact, or are networks
        // that end there.)
        let mut driven = HashSet::new();
        for i in 0..self.gates.len() {
            if matches!(self.gates[i].kind, GateKind::Flip { .. }) {
                let out = self.gates[i].out;
                driven.insert(self.find(out));
            }
        }
        let readers = self.join_readers(&joins, &wires, &takers);
        let node = |p: usize| {
            !driven.contains(&p)
                && in_joins
                    .get(&p)
                    .is_some_and(|&(n, _, mixed)| !mixed && readers.get(&p) == Some(&n))
        };
        let mut relayed: HashMap<usize, Element> = HashMap::new();
        let mut errors = Vec::new();
        for (g, (set, _)) in joins.iter().zip(&wires) {
            for (k, &p) in set.iter().enumerate() {
                if node(p) {
                    self.union(p, g.out);
                    continue;
                }
                let at = Pos::new(g.pos.row, g.pos.col.wrapping_sub(k + 1));
                let contact = match relayed.get(&p) {
                    Some(c) => c.clone(),
                    None => match self.relay_for(p, g, at) {
                        Ok(c) => relayed.entry(p).or_insert(c).clone(),
                        Err(why) => {
                            let what = g.what.clone();
                            errors.push(Located::new(
                                g.line,
                                crate::formats::plcopen::ImportError::Lower(what, why),
                            ));
                            continue;
                        }
                    },
                };
                let rail = super::body::RAIL;
                self.consumed.push(rail);
                self.wire(rail, g.out, Net::Leaf(contact, at), g.line);
            }
        }
        errors
    }

    /// Each join's wires (their points, in pin order, each once) and a
    /// number shared by the joins of the same set of wires.
    fn join_wires(&mut self, joins: &[Gate]) -> Vec<(Vec<usize>, usize)> {
        let mut ids: HashMap<Vec<usize>, usize> = HashMap::new();
        let mut wires = Vec::with_capacity(joins.len());
        for g in joins {
            // In pin order (where a relay's contact goes), each once.
            let mut set: Vec<usize> = Vec::with_capacity(g.inputs.len());
            for &p in &g.inputs {
                let p = self.find(p);
                if !set.contains(&p) {
                    set.push(p);
                }
            }
            let mut key = set.clone();
            crate::sort::all(&mut key);
            let next = ids.len();
            let id = *ids.entry(key).or_insert(next);
            wires.push((set, id));
        }
        wires
    }

    /// How many elements read each point, a wire that is the output of
    /// joins of the same wires counting everything that reads any of
    /// their outputs.
    fn join_readers(
        &mut self,
        joins: &[Gate],
        wires: &[(Vec<usize>, usize)],
        takers: &HashMap<usize, usize>,
    ) -> HashMap<usize, usize> {
        // Joins of the same wires become one point: a wire that is the
        // output of such a group is read by everything reading any of its
        // outputs (an OR block's output may be one wire of a later join,
        // while a coil beside it reads the same wires).
        let mut outs: HashMap<usize, HashSet<usize>> = HashMap::new();
        for (g, (_, id)) in joins.iter().zip(wires) {
            let out = self.find(g.out);
            outs.entry(*id).or_default().insert(out);
        }
        let mut readers: HashMap<usize, usize> = takers.clone();
        for group in outs.values() {
            let all: usize = group
                .iter()
                .map(|o| takers.get(o).copied().unwrap_or(0))
                .sum();
            for o in group {
                readers.insert(*o, all);
            }
        }
        readers
    }

    /// How many elements take power from each point (joined points).
    pub(in crate::formats::plcopen) fn takers(&mut self) -> HashMap<usize, usize> {
        self.gate_work += self.consumed.len();
        let mut count = HashMap::new();
        for p in self.consumed.clone() {
            *count.entry(self.find(p)).or_insert(0) += 1;
        }
        count
    }
}
