//! An LDmicro rung as the soft PLC's rungs (docs/ldmicro.md, "Rungs").
//!
//! LDmicro runs a rung as one bit of power passed through its elements
//! left to right, a parallel group's branches each from the same power,
//! OR-ed at its end; a coil passes the power on, so outputs may stand
//! anywhere. The soft PLC's rungs end in their outputs, all on one
//! condition. So: a run of conditions ending in outputs is one rung (the
//! usual case, drawn element for element); where outputs stand before
//! more elements, or in branches of their own, the power there goes
//! into a BOOL of its own (`_ld0` …) by a rung of its own, unless it is
//! contacts only (reading contacts twice is reading them once), and the
//! rest reads that BOOL. A rung's boxes therefore run once a scan, in
//! LDmicro's order.

use super::error::LdError;
use super::file::Node;
use super::parts::Part;
use crate::error::Located;
use crate::ladder::element::Element;
use crate::ladder::grid::Pos;
use crate::ladder::net::{Net, RungLogic};

/// The rungs being made from one file.
pub(super) struct Lowering<'a> {
    /// The soft PLC's rungs so far, with the line each came from.
    pub(super) rungs: Vec<(RungLogic, usize)>,
    /// How many BOOLs were made to hold power.
    pub(super) held: usize,
    /// A comment waiting for the next rung.
    pub(super) comment: String,
    /// An element as the soft PLC has it (its instance names given).
    pub(super) element: &'a mut dyn FnMut(&super::Element) -> Result<Part, LdError>,
}

/// The BOOL LDmicro's master relay is kept in: set at the start of each
/// scan, every rung's power starts from it, `MASTER_RELAY` sets it.
pub(super) const MCR: &str = "_MCR";

/// Power at some point of a rung: from the rail (nothing yet), or a
/// network from it.
type Power = Option<Net>;

fn leaf(e: Element) -> Net {
    Net::Leaf(e, Pos::new(0, 0))
}

/// `power` then `net` in series.
fn then(power: Power, net: Net) -> Net {
    match power {
        None => net,
        Some(Net::Series(mut v)) => {
            match net {
                Net::Series(w) => v.extend(w),
                n => v.push(n),
            }
            Net::Series(v)
        }
        Some(p) => match net {
            Net::Series(mut w) => {
                w.insert(0, p);
                Net::Series(w)
            }
            n => Net::Series(vec![p, n]),
        },
    }
}

/// Whether a network only reads (contacts): reading it again is the same.
fn pure(power: &Power) -> bool {
    power.as_ref().is_none_or(|n| {
        n.leaves()
            .iter()
            .all(|(e, _)| matches!(e, Element::Contact { .. } | Element::Wire))
    })
}

/// Whether a parallel group has a branch of wires alone beside a branch
/// that does more than read contacts.
fn wired_beside_boxes(branches: &[Node]) -> bool {
    use super::Element as Ld;
    let wires = |b: &Node| {
        b.elements().iter().all(|(e, _)| {
            matches!(
                e,
                Ld::Short | Ld::Placeholder | Ld::Comment(_) | Ld::Persist(_)
            )
        })
    };
    // PERSIST passes power through (LDmicro saves its variable whatever
    // the power): a wire.
    let boxes = |b: &Node| {
        b.elements().iter().any(|(e, _)| {
            !matches!(
                e,
                Ld::Short
                    | Ld::Placeholder
                    | Ld::Comment(_)
                    | Ld::Persist(_)
                    | Ld::Contacts { .. }
                    | Ld::Open
            )
        })
    };
    branches.iter().any(wires) && branches.iter().any(boxes)
}

/// Whether every branch of a parallel group is one output (coils,
/// resets, moves and arithmetic side by side, as LDmicro draws several
/// outputs on one rung), one of them at least a coil or reset.
fn outputs_only(branches: &[Node]) -> bool {
    use super::Element as Ld;
    let output = |b: &Node| {
        matches!(
            b,
            Node::Leaf(
                Ld::Coil { .. } | Ld::Res(_) | Ld::Unary { .. } | Ld::Math { .. },
                _
            )
        )
    };
    branches.iter().all(output) && has_output(&Node::Parallel(branches.to_vec(), 0))
}

/// Whether a group holds an output anywhere: a coil, a reset.
fn has_output(node: &Node) -> bool {
    node.elements()
        .iter()
        .any(|(e, _)| matches!(e, super::Element::Coil { .. } | super::Element::Res(_)))
}

impl Lowering<'_> {
    /// A rung of `condition` driving `outputs`.
    fn emit(&mut self, condition: Power, outputs: Vec<Element>, line: usize) {
        // Outputs on the rail (LDmicro's always-on rung): output boxes
        // stand there on a wire; a coil, which the editor does not put on
        // the rail, on a closed contact of `_OPEN` (never on, so its NC
        // contact always passes).
        let boxes = outputs.iter().all(|e| matches!(e, Element::OutputBlock(_)));
        let mut condition = condition.unwrap_or_else(|| match boxes {
            true => leaf(Element::Wire),
            false => leaf(Element::nc(super::elements::OPEN)),
        });
        if outputs == [Element::coil(MCR)] {
            // LDmicro's master relay: off while this rung's power is off,
            // and back on at the next one, whatever its power (the rung
            // then starts off): `_MCR := NOT _MCR OR power`.
            condition = Net::Parallel(vec![leaf(Element::nc(MCR)), condition]);
        }
        let logic = RungLogic {
            condition,
            outputs: outputs.into_iter().map(|e| (e, Pos::new(0, 0))).collect(),
            comment: std::mem::take(&mut self.comment),
            sides: Vec::new(),
        };
        self.rungs.push((logic, line));
    }

    /// `power` as a contact on a BOOL of its own that a rung of its own
    /// sets, where reading it twice would run its boxes twice.
    fn hold(&mut self, power: Power, line: usize) -> Power {
        if pure(&power) {
            return power;
        }
        let name = format!("_ld{}", self.held);
        self.held += 1;
        self.emit(power, vec![Element::coil(&name)], line);
        Some(leaf(Element::no(&name)))
    }

    /// A series of `nodes` from `power`; `tail`: nothing after it reads
    /// its power. Returns the power at its end.
    pub(super) fn series(
        &mut self,
        nodes: &[Node],
        power: Power,
        tail: bool,
    ) -> Result<Power, Vec<Located<LdError>>> {
        let mut power = power;
        let mut pending: Vec<Element> = Vec::new();
        let mut pending_line = 0;
        for (k, node) in nodes.iter().enumerate() {
            let last = k + 1 == nodes.len();
            let line = node.line();
            let leaf_kind = match node {
                Node::Leaf(..) => Some(self.kind(node)?),
                _ => None,
            };
            let grouped_outputs = leaf_kind.is_none() && has_output(node);
            let continues = !matches!(
                leaf_kind,
                Some(Kind::Output(_) | Kind::Nothing | Kind::Comment(_))
            );
            if !pending.is_empty() && continues {
                // Outputs before more elements: the power they share is
                // read again after them.
                power = self.hold(power, pending_line);
                self.emit(power.clone(), std::mem::take(&mut pending), pending_line);
            }
            match (node, leaf_kind) {
                (_, Some(Kind::Condition(e))) => power = Some(then(power, leaf(e))),
                (_, Some(Kind::Network(net))) => power = Some(then(power, net)),
                (_, Some(Kind::Output(e))) => {
                    if pending.is_empty() {
                        pending_line = line;
                    }
                    pending.push(e);
                }
                (_, Some(Kind::Nothing)) => {}
                (_, Some(Kind::Comment(text))) => {
                    if !self.comment.is_empty() {
                        self.comment.push('\n');
                    }
                    self.comment.push_str(&text);
                }
                (Node::Series(inner, _), None) => {
                    power = self.series(inner, power, tail && last)?;
                }
                (Node::Parallel(branches, _), None) if outputs_only(branches) => {
                    // Outputs side by side: all on the power here, one rung.
                    for b in branches {
                        let out = match self.kind(b)? {
                            Kind::Output(e) => e,
                            // A MOVE or ADD beside coils: an output box.
                            Kind::Condition(Element::Block(call)) => Element::OutputBlock(call),
                            _ => continue,
                        };
                        if pending.is_empty() {
                            pending_line = b.line();
                        }
                        pending.push(out);
                    }
                }
                (Node::Parallel(branches, _), None) if wired_beside_boxes(branches) => {
                    power = self.wire_beside(branches, power, line)?;
                }
                (Node::Parallel(branches, _), None) if !grouped_outputs => {
                    let nets = self.branches(branches)?;
                    power = Some(then(power, nets));
                }
                (Node::Parallel(branches, _), None) => {
                    power = self.output_branches(branches, power, (tail && last, line))?;
                }
                (Node::Leaf(..), None) => {}
            }
        }
        let end_line = nodes.last().map_or(1, Node::line);
        self.finish(pending, (pending_line, end_line), &mut power, tail);
        Ok(power)
    }

    /// The end of a series: its waiting outputs on its power (held first
    /// when something after reads it); a rung ending in a box (a counter
    /// with no coil after it) has the box as its output, and other boxes
    /// at a rung's end still run, into a BOOL nothing reads.
    fn finish(
        &mut self,
        pending: Vec<Element>,
        (pending_line, end_line): (usize, usize),
        power: &mut Power,
        tail: bool,
    ) {
        if !pending.is_empty() {
            if !tail {
                *power = self.hold(power.take(), pending_line);
            }
            self.emit(power.clone(), pending, pending_line);
            return;
        }
        if !tail || pure(power) {
            return;
        }
        let Some(net) = power.take() else {
            return;
        };
        match split_last(net) {
            (rest, Some(Element::Block(b))) => {
                self.emit(rest, vec![Element::OutputBlock(b)], end_line)
            }
            (rest, other) => {
                let net = match other {
                    Some(e) => Some(then(rest, leaf(e))),
                    None => rest,
                };
                self.hold(net, end_line);
            }
        }
    }

    /// A wire beside boxes: power passes as it came, and each box branch
    /// still runs on it, in a rung of its own into a BOOL nothing reads.
    fn wire_beside(
        &mut self,
        branches: &[Node],
        power: Power,
        line: usize,
    ) -> Result<Power, Vec<Located<LdError>>> {
        let power = self.hold(power, line);
        for b in branches {
            let end = self.series(inner(b), power.clone(), false)?;
            self.hold(end, line);
        }
        Ok(power)
    }

    /// Branches holding outputs: each a rung (or rungs) of its own on the
    /// power before them (held); after them, when read (`tail` false),
    /// the OR of what each branch passes, held.
    fn output_branches(
        &mut self,
        branches: &[Node],
        power: Power,
        (tail, line): (bool, usize),
    ) -> Result<Power, Vec<Located<LdError>>> {
        let power = self.hold(power, line);
        let mut ends = Vec::new();
        for b in branches {
            ends.push(self.series(inner(b), power.clone(), tail)?);
        }
        if tail {
            return Ok(None);
        }
        let joined: Vec<Net> = ends.into_iter().flatten().collect();
        Ok(self.hold(Some(Net::Parallel(joined)), line))
    }

    /// The branches of a parallel group holding no outputs: one network.
    fn branches(&mut self, branches: &[Node]) -> Result<Net, Vec<Located<LdError>>> {
        let mut nets = Vec::new();
        for b in branches {
            match self.series(inner(b), None, false)? {
                Some(net) => nets.push(net),
                // A branch of wires only: the group always passes power.
                None => nets.push(leaf(Element::Wire)),
            }
        }
        if nets
            .iter()
            .any(|n| matches!(n, Net::Leaf(Element::Wire, _)))
        {
            let others: Vec<&Net> = nets
                .iter()
                .filter(|n| !matches!(n, Net::Leaf(Element::Wire, _)))
                .collect();
            if others.iter().all(|n| pure(&Some((*n).clone()))) {
                return Ok(leaf(Element::Wire));
            }
            let why = "a branch of wires alone beside boxes: power always passes, and the boxes' own power would be lost".to_string();
            let line = branches.first().map_or(1, Node::line);
            return Err(vec![Located::new(line, LdError::Drawing(why))]);
        }
        Ok(match nets.len() {
            1 => nets.remove(0),
            _ => Net::Parallel(nets),
        })
    }

    /// What one leaf is.
    fn kind(&mut self, node: &Node) -> Result<Kind, Vec<Located<LdError>>> {
        let Node::Leaf(e, line) = node else {
            return Ok(Kind::Nothing);
        };
        match (self.element)(e) {
            Ok(Part::Condition(el)) => Ok(Kind::Condition(el)),
            Ok(Part::Network(net)) => Ok(Kind::Network(net)),
            Ok(Part::Output(el)) => Ok(Kind::Output(el)),
            Ok(Part::Nothing) => Ok(Kind::Nothing),
            Ok(Part::Comment(t)) => Ok(Kind::Comment(t)),
            Err(err) => Err(vec![Located::new(*line, err)]),
        }
    }
}

/// What a leaf is, for the walk.
enum Kind {
    Condition(Element),
    Network(Net),
    Output(Element),
    Nothing,
    Comment(String),
}

/// A branch's contents: a series' nodes, or the node itself.
fn inner(b: &Node) -> &[Node] {
    match b {
        Node::Series(v, _) => v.as_slice(),
        other => std::slice::from_ref(other),
    }
}

/// A series' last leaf apart from the rest.
fn split_last(net: Net) -> (Power, Option<Element>) {
    match net {
        Net::Leaf(e, _) => (None, Some(e)),
        Net::Series(mut v) => match v.pop() {
            Some(Net::Leaf(e, _)) => {
                let rest = match v.len() {
                    0 => None,
                    1 => v.pop(),
                    _ => Some(Net::Series(v)),
                };
                (rest, Some(e))
            }
            Some(other) => {
                v.push(other);
                (Some(Net::Series(v)), None)
            }
            None => (None, None),
        },
        other => (Some(other), None),
    }
}
