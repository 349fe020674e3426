//! From the lowered graph to rungs: each group of coils fed from one point
//! becomes a rung whose condition is the series-parallel network between
//! the left rail and that point; helpers' rungs run before their readers,
//! comments go to the rung below them.

mod order;
mod placing;

use std::collections::{BTreeMap, HashMap, HashSet};

use super::error::{Errors, ImportError};
use super::lower::body::{Body, ElementEdge, RAIL};
use super::main_line::{off_main_line, Link};
use super::parts::*;
use crate::error::Located;
use crate::formats::plcopen::warning::ImportWarning;
use crate::ladder::element::{CoilKind, ContactKind, Element, TimerKind};
use crate::ladder::grid::Pos;
use crate::ladder::net::{reduce_all, Edge, Net, NetError, RungLogic};
use crate::ladder::target::{capabilities, check_element};
use crate::MachineId;

/// What [`Body::lower_leaf`] needs to know of the whole body.
struct LeafEnv {
    machine: Option<MachineId>,
    /// IO86A: timers and counters are coils with contacts.
    timer_coils: bool,
    /// The points something takes power from.
    consumed: HashSet<usize>,
    /// The box edges off their rung's main line.
    off_main: HashSet<usize>,
}

impl Body {
    /// The rungs, each with the XML line of its first output.
    pub(super) fn rungs(
        &mut self,
        machine: Option<MachineId>,
        warnings: &mut Vec<Located<ImportWarning>>,
    ) -> Result<Vec<(RungLogic, usize)>, Errors> {
        warnings.append(&mut self.warnings);
        self.machine = machine;
        self.lower_gates()?;
        if let Some(m) = machine {
            self.fold_boxes_into_contacts(m);
        }
        let (mut edges, mut lines) = self.graph(machine)?;
        // An element whose output was joined to the rail (a wire joined
        // with an always-on output: OR TRUE), or a contact between one
        // point, changes no power: dropped (said as leading to no coil),
        // as the loop it makes would not reduce.
        let rail = self.find(RAIL);
        edges.retain(|e| {
            let shorted = e.from == e.to && matches!(e.net, Net::Leaf(Element::Contact { .. }, _));
            e.to != rail && !shorted
        });
        if let Some(m) = machine {
            self.check_machine(m, &edges, &lines)?;
        }
        let mut errors = Vec::new();
        let (mut groups, buses) =
            self.output_groups(machine, (&mut edges, &mut lines), &mut errors);
        // Every group's network at once, each from the part of the graph
        // that leads to it (linear in the sum of their sizes).
        let conditions = reduce_all(&edges, self.parent.len(), rail, &buses);
        let mut rungs = Vec::new();
        for (bus, condition) in buses.iter().zip(conditions) {
            let outs = groups.remove(bus).unwrap_or_default();
            let first_line = outs.first().map_or(1, |o| o.2);
            match condition {
                Ok(condition) => {
                    let logic = RungLogic {
                        condition,
                        outputs: outs.into_iter().map(|(e, p, _)| (e, p)).collect(),
                        comment: String::new(),
                        sides: Vec::new(),
                    };
                    rungs.push((top(&logic), logic, first_line));
                }
                Err(NetError::NoPath) => {
                    let what = outs.first().map(|o| o.0.to_string()).unwrap_or_default();
                    errors.push(Located::new(first_line, ImportError::NoPath(what)))
                }
                Err(e @ (NetError::NotSeriesParallel(p) | NetError::TooDeep(p))) => {
                    let line = lines.get(&p).copied().unwrap_or(first_line);
                    errors.push(Located::new(line, ImportError::Net(e)))
                }
            }
        }
        if !errors.is_empty() {
            return Err(errors);
        }
        // Logic that reaches no coil has no effect in the tool that drew
        // it either (the right rail is no output): said, not kept.
        warnings.extend(unused(&edges, &rungs, &lines));
        crate::sort::by_key(&mut rungs, |(top, _, _)| *top);
        self.attach_comments(&mut rungs);
        self.helpers_first(&mut rungs);
        Ok(rungs.into_iter().map(|(_, r, line)| (r, line)).collect())
    }

    /// The outputs grouped by the point feeding them (each group is one
    /// rung), and those points in order. A group on the rail is fed
    /// through IO86A's always-on M57; on another machine it is an error.
    #[allow(clippy::type_complexity)] // the groups and their points, named at the call
    fn output_groups(
        &mut self,
        machine: Option<MachineId>,
        (edges, lines): (&mut Vec<Edge>, &mut HashMap<Pos, usize>),
        errors: &mut Errors,
    ) -> (BTreeMap<usize, Vec<(Element, Pos, usize)>>, Vec<usize>) {
        let rail = self.find(RAIL);
        let mut groups: BTreeMap<usize, Vec<(Element, Pos, usize)>> = BTreeMap::new();
        for out in std::mem::take(&mut self.outputs) {
            let bus = self.find(out.from);
            groups
                .entry(bus)
                .or_default()
                .push((out.element, out.pos, out.line));
        }
        if self.soft() {
            self.boxes_on_rail(&mut groups, (edges, lines));
        }
        let mut buses = Vec::new();
        let mut moved = Vec::new();
        for (bus, outs) in &mut groups {
            crate::sort::by_key(outs, |(_, p, _)| *p);
            let on = machine.and_then(|m| m.target().always_on());
            if let (true, Some(on)) = (*bus == rail, on) {
                // Always on: IO86A's M57 (ON) carries the rail to it.
                let q = self.fresh();
                let (_, p, line) = &outs[0];
                let at = Pos::new(p.row, p.col.wrapping_sub(1));
                lines.insert(at, *line);
                edges.push(Edge {
                    from: rail,
                    to: q,
                    net: Net::Leaf(Element::no(on), at),
                });
                moved.push((*bus, q));
                buses.push(q);
            } else if *bus == rail {
                let on_rail = ImportError::OnRail(outs[0].0.to_string());
                errors.push(Located::new(outs[0].2, on_rail));
            } else {
                buses.push(*bus);
            }
        }
        for (from, to) in moved {
            if let Some(outs) = groups.remove(&from) {
                groups.insert(to, outs);
            }
        }
        (groups, buses)
    }

    /// The elements as edges between their (joined) points, and each
    /// leaf's line. A TON or CTU whose output drives nothing becomes the
    /// machine's timer or counter coil (`OUT T00 K19`).
    #[allow(clippy::type_complexity)] // a pair of plain collections, named at the call
    fn graph(
        &mut self,
        machine: Option<MachineId>,
    ) -> Result<(Vec<Edge>, HashMap<Pos, usize>), Errors> {
        // IO86A's timers and counters are coils (`OUT T00 K19`) with
        // contacts: an in-line TON or CTU is split ([`Body::split_box`]).
        let timer_coils = machine.is_some_and(|m| m.target().capabilities().timer_counter_coils);
        let consumed: HashSet<usize> = self
            .consumed
            .clone()
            .into_iter()
            .map(|p| self.find(p))
            .collect();
        let off_main = self.boxes_off_main_line(machine);
        let mut edges = Vec::new();
        let mut lines: HashMap<Pos, usize> = HashMap::new();
        let env = LeafEnv {
            machine,
            timer_coils,
            consumed,
            off_main,
        };
        let body_edges = std::mem::take(&mut self.edges);
        for (
            index,
            ElementEdge {
                from: a,
                to: b,
                net,
                line,
            },
        ) in body_edges.into_iter().enumerate()
        {
            let (a, b) = (self.find(a), self.find(b));
            if let Net::Leaf(e, pos) = &net {
                lines.insert(*pos, line);
                let leaf = (e.clone(), *pos, line, index);
                if self.lower_leaf((a, b), leaf, &net, &env, (&mut edges, &mut lines))? {
                    continue;
                }
            }
            edges.push(Edge {
                from: a,
                to: b,
                net,
            });
        }
        Ok((edges, lines))
    }

    /// Lowers one leaf edge `a → b` the machine cannot take as it is (a
    /// TON or CTU as its coil and contact, a box through a spare relay):
    /// whether it did (else the edge goes in as it is).
    fn lower_leaf(
        &mut self,
        (a, b): (usize, usize),
        (e, pos, line, index): (Element, Pos, usize, usize),
        net: &Net,
        env: &LeafEnv,
        (edges, lines): (&mut Vec<Edge>, &mut HashMap<Pos, usize>),
    ) -> Result<bool, Errors> {
        let (e, pos) = (&e, &pos);
        let terminal = !env.consumed.contains(&b);
        match (e, terminal) {
            (
                Element::Timer {
                    kind: TimerKind::Ton,
                    name,
                    preset_ms,
                },
                true,
            ) => {
                let coil = timer_coil(name, *preset_ms).map_err(|m| vec![Located::new(line, m)])?;
                self.output(a, coil, *pos, line);
                return Ok(true);
            }
            (
                Element::Timer {
                    kind: TimerKind::Ton,
                    name,
                    preset_ms,
                },
                false,
            ) if env.timer_coils => {
                let coil = timer_coil(name, *preset_ms).map_err(|m| vec![Located::new(line, m)])?;
                let contact = Element::no(name);
                self.split_box(
                    (a, b),
                    coil,
                    contact,
                    *pos,
                    line,
                    (&mut *edges, &mut *lines),
                );
                return Ok(true);
            }
            // A soft PLC box whose power goes on to nothing: an output box.
            (Element::CounterCoil { .. } | Element::Block(_), true) => {
                self.output(a, super::boxes::as_output(e), *pos, line);
                return Ok(true);
            }
            (Element::CounterCoil { device, .. }, false) if env.timer_coils => {
                // Q is the counter's count-reached bit.
                let contact = Element::no(device);
                self.split_box(
                    (a, b),
                    e.clone(),
                    contact,
                    *pos,
                    line,
                    (&mut *edges, &mut *lines),
                );
                return Ok(true);
            }
            (Element::CounterCoil { device, .. }, false) => {
                let wired = ImportError::CounterQWired(device.clone());
                return Err(vec![Located::new(line, wired)]);
            }
            (Element::Timer { .. } | Element::Block(_), _) if env.off_main.contains(&index) => {
                self.timer_through_relay((a, b), (e, *pos, line), net, (edges, lines))?;
                return Ok(true);
            }
            (Element::Not | Element::Edge { .. }, _)
                if env.machine.is_some_and(|m| check_element(m, e).is_err())
                    || env.off_main.contains(&index) =>
            {
                self.box_through_relay((a, b), (e, *pos, line), (edges, lines))?;
                return Ok(true);
            }
            _ => {}
        }
        Ok(false)
    }

    /// A timer off its rung's main line, where the machine takes timers
    /// in-line only: it gets a rung of its own into a spare relay, whose
    /// contact gives Q where Q went.
    fn timer_through_relay(
        &mut self,
        (a, b): (usize, usize),
        (e, pos, line): (&Element, Pos, usize),
        net: &Net,
        (edges, lines): (&mut Vec<Edge>, &mut HashMap<Pos, usize>),
    ) -> Result<(), Errors> {
        // Off the rung's main line, where the machine
        // takes timers in-line only: the timer gets a rung
        // of its own into a spare relay, whose contact
        // gives Q where Q went.
        let what = format!("{e} box's output");
        let relay = self
            .spare_relay(&what, line)
            .map_err(|why| vec![Located::new(line, ImportError::Lower(e.to_string(), why))])?;
        let q = self.fresh();
        let at_coil = Pos::new(pos.row, pos.col.wrapping_add(1));
        edges.push(Edge {
            from: a,
            to: q,
            net: net.clone(),
        });
        let held = coil(CoilKind::Normal, relay.clone());
        let split = (&mut *edges, &mut *lines);
        self.split_box((q, b), held, Element::no(&relay), at_coil, line, split);
        Ok(())
    }

    /// A NOT or edge box the machine has no in-line form for here (none
    /// at all, or not off the rung's main line): a relay holds the box's
    /// input, and its NC (NOT) or edge contact gives the box's output.
    fn box_through_relay(
        &mut self,
        (a, b): (usize, usize),
        (e, pos, line): (&Element, Pos, usize),
        (edges, lines): (&mut Vec<Edge>, &mut HashMap<Pos, usize>),
    ) -> Result<(), Errors> {
        // No in-line box on this machine, or not here (off
        // the rung's main line): a relay holds the box's
        // input, and its NC (NOT) or edge contact gives the
        // box's output.
        let what = match e {
            Element::Not => "NOT block".to_string(),
            Element::Edge { falling: true } => "F_TRIG block".to_string(),
            _ => "R_TRIG block".to_string(),
        };
        let at = Pos::new(pos.row, pos.col.wrapping_sub(1));
        let device = self
            .hold_in_relay(a, &format!("{what}'s input"), line, at)
            .map_err(|why| vec![Located::new(line, ImportError::Lower(what, why))])?;
        let kind = match e {
            Element::Not => ContactKind::Nc,
            Element::Edge { falling: true } => ContactKind::Falling,
            _ => ContactKind::Rising,
        };
        lines.insert(pos, line);
        let rail = self.find(RAIL);
        edges.push(Edge {
            from: rail,
            to: b,
            net: Net::Leaf(Element::Contact { kind, device }, pos),
        });
        Ok(())
    }

    /// The edges (by index) holding a NOT, edge or timer box that
    /// `machine` takes in-line but that would not stand on its rung's main
    /// line ([`super::main_line`]).
    fn boxes_off_main_line(&mut self, machine: Option<MachineId>) -> HashSet<usize> {
        if self.soft() {
            // The soft PLC takes boxes anywhere; one feeding several
            // rungs gets a rung of its own.
            return self.shared_boxes().into_iter().collect();
        }
        if !machine.is_some_and(|m| capabilities(m).inline_boxes) {
            return HashSet::new();
        }
        let rail = self.find(RAIL);
        let mut links: Vec<Link> = Vec::with_capacity(self.edges.len());
        for i in 0..self.edges.len() {
            let (a, b) = (self.edges[i].from, self.edges[i].to);
            let relayable = matches!(
                self.edges[i].net,
                Net::Leaf(
                    Element::Not | Element::Edge { .. } | Element::Timer { .. },
                    _
                )
            );
            let (from, to) = (self.find(a), self.find(b));
            links.push(Link {
                from,
                to,
                relayable,
            });
        }
        let points = self.parent.len();
        off_main_line(&mut links, rail, points, self.spares.len())
    }

    /// An in-line timer or counter box from point `a` to `b` as IO86A
    /// has it: its `coil` where the box was fed, and its `contact`, from
    /// the rail, where its Q went (Q is on only while the coil's
    /// condition has held long enough), at a place of its own. Also an
    /// AVR timer off its rung's main line: `a` is then the timer's own
    /// output, the coil and contact a spare relay's.
    fn split_box(
        &mut self,
        (a, b): (usize, usize),
        coil: Element,
        contact: Element,
        pos: Pos,
        line: usize,
        (edges, lines): (&mut Vec<Edge>, &mut HashMap<Pos, usize>),
    ) {
        if let Some(d) = coil.written_device() {
            self.ordered.push(d.to_string());
        }
        self.output(a, coil, pos, line);
        let at = Pos::new(pos.row, pos.col.wrapping_add(SPLIT_PLACES));
        lines.insert(at, line);
        let rail = self.find(RAIL);
        edges.push(Edge {
            from: rail,
            to: b,
            net: Net::Leaf(contact, at),
        });
    }

    /// Every element and device checked against `machine`, at its line.
    fn check_machine(
        &self,
        machine: MachineId,
        edges: &[Edge],
        lines: &HashMap<Pos, usize>,
    ) -> Result<(), Errors> {
        let leaves = edges.iter().filter_map(|e| match &e.net {
            Net::Leaf(e, p) => Some((e, lines.get(p).copied().unwrap_or(1))),
            _ => None,
        });
        let outs = self.outputs.iter().map(|o| (&o.element, o.line));
        let errors: Errors = leaves
            .chain(outs)
            .filter_map(|(e, line)| {
                check_element(machine, e)
                    .err()
                    .map(|e| Located::new(line, ImportError::Element(e)))
            })
            .collect();
        if errors.is_empty() {
            Ok(())
        } else {
            Err(errors)
        }
    }
}

/// The elements no rung uses: they lead to no coil (a warning each).
fn unused(
    edges: &[Edge],
    rungs: &[(Pos, RungLogic, usize)],
    lines: &HashMap<Pos, usize>,
) -> Vec<Located<ImportWarning>> {
    let used: HashSet<Pos> = rungs
        .iter()
        .flat_map(|(_, r, _)| r.condition.leaves().into_iter().map(|(_, p)| p))
        .collect();
    edges
        .iter()
        .filter_map(|e| match &e.net {
            Net::Leaf(leaf, p) if !used.contains(p) => Some(Located::new(
                lines.get(p).copied().unwrap_or(1),
                ImportWarning::LeadsNowhere(leaf.to_string()),
            )),
            _ => None,
        })
        .collect()
}

fn top(r: &RungLogic) -> Pos {
    r.outputs
        .iter()
        .map(|(_, p)| *p)
        .chain([r.condition.top_left()])
        .min()
        .unwrap_or(Pos::new(0, 0))
}
