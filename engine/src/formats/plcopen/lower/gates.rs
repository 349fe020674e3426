//! Blocks lowered to ladder (issue #18), rewired into the body's graph of
//! points before its rungs are read off, so they come out as the series,
//! parallel and self-holding rungs a ladder draws.
//!
//! - OR: lowered first, with the wires joined at an input (the same
//!   thing drawn as a block): its inputs' points are joined (parallel
//!   branches meeting); an input something else also takes power from,
//!   or a flip-flop's output, comes through a spare relay instead
//!   (joining it would feed the others' power back);
//! - AND: each input's network after the first is moved to start where the
//!   one before it ends (series) when only the AND takes power from it,
//!   else it comes through a spare relay's contact;
//! - XOR: two branches, A and not B, not A and B, of the inputs' contacts;
//! - SR / RS on a relay the map gives the instance (`SR0,M10`): one
//!   self-holding rung, `S or (Q and not R)` (set wins) or
//!   `(S or Q) and not R` (reset wins);
//! - TOF / TP on IO86A from its on-delay timer and a relay;
//! - CTD / CTUD on the machine's up-counter; comparisons as `CMP` and a
//!   relay.
//!
//! An input needed twice or negated is one contact from the rail when it
//! is one, else a spare relay that holds its power ([`Body::relay_for`]).
//! What does not fit is refused at the block's line with the reason,
//! never approximated.

use std::collections::HashMap;

use super::body::{Body, CompareCopy, ElementEdge, Gate, GateKind, Helper};
use crate::error::Located;
use crate::formats::plcopen::error::LowerError;
use crate::formats::plcopen::parts::{invert, rising, turned};
use crate::ladder::element::{CoilKind, Element};
use crate::ladder::grid::Pos;
use crate::ladder::net::Net;
use crate::ladder::target::capabilities;
use crate::limits::MAX_GATE_WORK;
use crate::MachineId;

impl Body {
    /// Lowers every gate, or says why one cannot be: the ORs first (OR
    /// blocks and wires joined at an input, [`Body::lower_joins`]), so
    /// each other block sees the whole network feeding its inputs.
    pub(in crate::formats::plcopen) fn lower_gates(
        &mut self,
    ) -> Result<(), Vec<Located<crate::formats::plcopen::ImportError>>> {
        let (joins, gates): (Vec<Gate>, Vec<Gate>) = std::mem::take(&mut self.gates)
            .into_iter()
            .partition(|g| g.kind == GateKind::Or);
        self.gates = gates;
        let mut errors = self.lower_joins(joins);
        let gates = std::mem::take(&mut self.gates);
        for g in self.in_flow_order(gates) {
            if self.gate_work > MAX_GATE_WORK {
                let why = LowerError::TooMuchWork;
                errors.push(Located::new(
                    g.line,
                    crate::formats::plcopen::ImportError::Lower(g.what, why),
                ));
                break;
            }
            if let Err(why) = self.lower(&g) {
                let what = g.what.clone();
                errors.push(Located::new(
                    g.line,
                    crate::formats::plcopen::ImportError::Lower(what, why),
                ));
            }
        }
        if errors.is_empty() {
            Ok(())
        } else {
            Err(errors)
        }
    }

    fn lower(&mut self, g: &Gate) -> Result<(), LowerError> {
        match &g.kind {
            // Taken out and lowered first, with the joins of wires.
            GateKind::Or => Err(LowerError::OrNotJoined),
            GateKind::And => {
                let mut end = g
                    .inputs
                    .first()
                    .copied()
                    .ok_or(LowerError::NoPin("inputs"))?;
                for (k, &p) in g.inputs.iter().enumerate().skip(1) {
                    if self.reroot(p, end) {
                        end = p;
                        continue;
                    }
                    // Its network feeds something else too (or holds a
                    // box): a relay carries its power into the series.
                    end = self.relay_branch(p, end, g, k)?;
                }
                self.union(end, g.out);
                Ok(())
            }
            GateKind::Xor => {
                let [a, b] = g.inputs[..] else {
                    return Err(LowerError::XorInputs);
                };
                let (ca, _, la, _) = self.input_contact(a, g, 1)?;
                let (cb, _, lb, _) = self.input_contact(b, g, 2)?;
                let out = g.out;
                let mid = [self.fresh(), self.fresh()];
                let at = |k: usize| Pos::new(g.pos.row, g.pos.col.wrapping_add(k));
                let (ka, kb) = (invert(&ca)?, invert(&cb)?);
                self.wire(super::body::RAIL, mid[0], Net::Leaf(ca, at(1)), la);
                self.wire(mid[0], out, Net::Leaf(kb, at(2)), lb);
                self.wire(super::body::RAIL, mid[1], Net::Leaf(ka, at(3)), la);
                self.wire(mid[1], out, Net::Leaf(cb, at(4)), lb);
                Ok(())
            }
            GateKind::Delay {
                coil,
                timer,
                relay,
                pulse,
            } => self.lower_delay(g, coil, timer, relay, *pulse),
            GateKind::Compare { a, b, flag, on } => self.lower_compare(g, a, b, flag, *on),
            GateKind::Reset(coil) => {
                let p = g.inputs.first().copied().ok_or(LowerError::NoPin("R"))?;
                let p = self.own_point(p, g, 0)?;
                self.output(p, coil.clone(), g.pos, g.line);
                Ok(())
            }
            GateKind::Count {
                counter,
                load,
                reset,
                empty,
            } => self.lower_count(g, counter, *load, *reset, *empty),
            GateKind::Flip { relay, set_wins } => {
                let [s, r] = g.inputs[..] else {
                    return Err(LowerError::FlipPins);
                };
                let s = self.own_point(s, g, 0)?;
                let (cr, _, lr, _) = self.input_contact(r, g, 1)?;
                let not_r = invert(&cr)?;
                let at = |k: usize| Pos::new(g.pos.row, g.pos.col.wrapping_add(k));
                let held = Element::no(relay);
                if *set_wins {
                    // Q := S or (Q and not R): a branch beside S.
                    let mid = self.fresh();
                    self.wire(super::body::RAIL, mid, Net::Leaf(held, at(1)), g.line);
                    self.wire(mid, s, Net::Leaf(not_r, at(2)), lr);
                    self.union(s, g.out);
                } else {
                    // Q := (S or Q) and not R: the hold beside S, then not R.
                    self.wire(super::body::RAIL, s, Net::Leaf(held, at(1)), g.line);
                    self.wire(s, g.out, Net::Leaf(not_r, at(2)), lr);
                }
                self.consumed.push(g.out);
                let coil = Element::Coil {
                    kind: CoilKind::Normal,
                    device: relay.clone(),
                };
                self.output(g.out, coil, at(3), g.line);
                Ok(())
            }
        }
    }

    /// `M57 → CMP a b`, then `flag → relay` (its rung kept right after
    /// the CMP's: [`Body::compares`]); the block's output is the relay.
    fn lower_compare(
        &mut self,
        g: &Gate,
        a: &str,
        b: &str,
        flag: &str,
        on: bool,
    ) -> Result<(), LowerError> {
        let Some(always) = self.machine.and_then(|m| m.target().always_on()) else {
            return Err(LowerError::NoCompare);
        };
        let rail = super::body::RAIL;
        let at = |k: usize| Pos::new(g.pos.row, g.pos.col.wrapping_sub(k));
        let cmp = self.fresh();
        self.wire(rail, cmp, Net::Leaf(Element::no(always), at(3)), g.line);
        let cmp_op = Element::Cmp {
            a: a.to_string(),
            b: b.to_string(),
        };
        self.output(cmp, cmp_op, at(3), g.line);
        let result = self.fresh();
        let flag = if on {
            Element::no(flag)
        } else {
            Element::nc(flag)
        };
        self.wire(rail, result, Net::Leaf(flag, at(2)), g.line);
        self.consumed.extend([rail, cmp, rail, rail]);
        let what = format!("{}'s result", g.what);
        let held = self.hold_in_relay(result, &what, g.line, at(1))?;
        self.wire(rail, g.out, Net::Leaf(Element::no(&held), g.pos), g.line);
        self.compares.push(CompareCopy {
            at: at(3),
            relay: held,
            operands: [a.to_string(), b.to_string()],
        });
        Ok(())
    }

    /// CTD: the counter counts CD's rises up to PV (what CTD counts down
    /// from PV to 0); LD clears it and sets a relay "loaded", so Q is the
    /// counter's contact or not loaded (IEC's CV starts at 0: Q is on
    /// until the first LD). CTUD with only CU (and R): QU is the counter's
    /// contact, QD `CMP C K0`'s equal flag (IO86A).
    fn lower_count(
        &mut self,
        g: &Gate,
        counter: &Element,
        load: Option<usize>,
        reset: Option<usize>,
        empty: Option<usize>,
    ) -> Result<(), LowerError> {
        let Element::CounterCoil { device, .. } = counter else {
            return Err(LowerError::NotCounter);
        };
        let rail = super::body::RAIL;
        let input = g
            .inputs
            .first()
            .copied()
            .ok_or(LowerError::NoPin("count input"))?;
        let at = |k: usize| Pos::new(g.pos.row, g.pos.col.wrapping_add(k));
        let reset_coil = |device: &str| Element::Coil {
            kind: CoilKind::Reset,
            device: device.to_string(),
        };
        let set_coil = |device: &str| Element::Coil {
            kind: CoilKind::Set,
            device: device.to_string(),
        };
        self.output(input, counter.clone(), g.pos, g.line);
        self.ordered.push(device.clone());
        let takers = self.takers();
        let read = |body: &mut Body, p: usize| takers.contains_key(&body.find(p));
        let q_read = read(self, g.out);
        if let Some(ld) = load {
            // CTD: LD clears the count; Q = done or never loaded.
            let ld = self.own_point(ld, g, 1)?;
            self.output(ld, reset_coil(device), at(1), g.line);
            if q_read {
                let what = format!("whether {} has been loaded", g.what);
                let relay = self.spare_relay(&what, g.line)?;
                self.output(ld, set_coil(&relay), at(2), g.line);
                self.wire(rail, g.out, Net::Leaf(Element::no(device), at(3)), g.line);
                self.wire(rail, g.out, Net::Leaf(Element::nc(&relay), at(4)), g.line);
                self.consumed.extend([rail, rail]);
            }
            return Ok(());
        }
        if empty.is_none() {
            // CTD never loaded: CV stays at or below 0, Q always on.
            self.union(g.out, rail);
            return Ok(());
        }
        if let Some(r) = reset {
            let r = self.own_point(r, g, 1)?;
            self.output(r, reset_coil(device), at(1), g.line);
        }
        if q_read {
            self.wire(rail, g.out, Net::Leaf(Element::no(device), at(3)), g.line);
            self.consumed.push(rail);
        }
        if let Some(e) = empty.filter(|&e| read(self, e)) {
            // QD (CV = 0): the count compared with 0 after this scan's
            // count and reset ([`Body::compares`] orders them).
            let qd = Gate {
                kind: GateKind::Compare {
                    a: device.clone(),
                    b: "K0".into(),
                    flag: "M61",
                    on: true,
                },
                inputs: Vec::new(),
                out: e,
                pos: at(5),
                line: g.line,
                what: format!("{}'s QD", g.what),
            };
            self.lower(&qd)?;
        }
        Ok(())
    }

    /// A spare relay for `what`, noted among the helpers.
    pub(in crate::formats::plcopen) fn spare_relay(
        &mut self,
        what: &str,
        line: usize,
    ) -> Result<String, LowerError> {
        let relay = self.spares.pop().ok_or(LowerError::NoRelay)?;
        self.helpers.push(Helper {
            relay: relay.clone(),
            what: what.to_string(),
            line,
        });
        Ok(relay)
    }

    /// TOF: `R := IN or (R and not T)`, T's coil on `R and not IN`, Q is
    /// R. TP: `R := IN rising or (R and not T)`, T's coil on R, Q is R.
    /// IN is used twice: its one contact from the rail, or a spare relay's
    /// ([`Body::input_contact`]).
    fn lower_delay(
        &mut self,
        g: &Gate,
        coil: &Element,
        timer: &str,
        relay: &str,
        pulse: bool,
    ) -> Result<(), LowerError> {
        let rail = super::body::RAIL;
        let input = g.inputs.first().copied().ok_or(LowerError::NoPin("IN"))?;
        let (c_in, at_in, line, input) = self.input_contact(input, g, 1)?;
        let at = |k: usize| Pos::new(g.pos.row, g.pos.col.wrapping_add(k));
        let set = if pulse { rising(&c_in)? } else { c_in.clone() };
        let (hold, running) = (self.fresh(), self.fresh());
        // The relay: set by IN (its rise), held until the timer is done.
        self.wire(rail, input, Net::Leaf(set, at_in), line);
        self.wire(rail, hold, Net::Leaf(Element::no(relay), at(1)), g.line);
        self.wire(hold, input, Net::Leaf(Element::nc(timer), at(2)), g.line);
        self.consumed.extend([rail, rail, hold, input]);
        let held = Element::Coil {
            kind: CoilKind::Normal,
            device: relay.to_string(),
        };
        self.output(input, held, at(3), g.line);
        // The timer: runs while the relay holds (and, TOF, IN is off).
        self.wire(rail, running, Net::Leaf(Element::no(relay), at(4)), g.line);
        let timing = if pulse {
            running
        } else {
            let off = self.fresh();
            self.wire(running, off, Net::Leaf(invert(&c_in)?, at(5)), line);
            self.consumed.push(running);
            off
        };
        self.consumed.extend([rail, timing]);
        self.output(timing, coil.clone(), at(6), g.line);
        // Q: the relay.
        self.wire(rail, g.out, Net::Leaf(Element::no(relay), at(7)), g.line);
        self.consumed.push(rail);
        Ok(())
    }

    /// A spare relay that holds the power at point `p` (a coil on it, its
    /// rung run before its readers: [`Body::helpers`]), and its contact.
    pub(in crate::formats::plcopen) fn relay_for(
        &mut self,
        p: usize,
        g: &Gate,
        at: Pos,
    ) -> Result<Element, LowerError> {
        let relay = self.hold_in_relay(p, &format!("{}'s input", g.what), g.line, at)?;
        Ok(Element::no(&relay))
    }

    /// A spare relay that holds the power at `p` (`what` it is, for the
    /// device comment): its name.
    pub(in crate::formats::plcopen) fn hold_in_relay(
        &mut self,
        p: usize,
        what: &str,
        line: usize,
        at: Pos,
    ) -> Result<String, LowerError> {
        let relay = self.spare_relay(what, line)?;
        self.consumed.push(p);
        let coil = Element::Coil {
            kind: CoilKind::Normal,
            device: relay.clone(),
        };
        self.output(p, coil, at, line);
        Ok(relay)
    }

    /// The contact that gives input `p`'s power and a point free for it:
    /// the one contact from the rail that feeds `p` (taken out of the
    /// graph, `p` itself), or else a relay holding `p`'s power
    /// ([`Body::relay_for`]) and a new point. Its place and line too.
    fn input_contact(
        &mut self,
        p: usize,
        g: &Gate,
        k: usize,
    ) -> Result<(Element, Pos, usize, usize), LowerError> {
        if let Some((c, at, line)) = self.single_contact(p) {
            return Ok((c, at, line, p));
        }
        let at = Pos::new(g.pos.row, g.pos.col.wrapping_sub(k + 1));
        let c = self.relay_for(p, g, at)?;
        Ok((c, at, g.line, self.fresh()))
    }

    /// Input `p` (pin `k` of `g`) as a point only the block takes power
    /// from, which it may join other branches into: `p` itself, or, when
    /// something else takes power from `p` too (joining would feed the
    /// other branches' power to it), a new point fed by the contact of a
    /// spare relay holding `p`'s power.
    fn own_point(&mut self, p: usize, g: &Gate, k: usize) -> Result<usize, LowerError> {
        let takers = self.takers();
        if takers.get(&self.find(p)).copied().unwrap_or(0) <= 1 {
            return Ok(p);
        }
        self.relay_branch(p, super::body::RAIL, g, k)
    }

    /// A spare relay holding `p`'s power (input `k` of `g`), and its
    /// contact from point `from` to a new point, which is returned.
    fn relay_branch(
        &mut self,
        p: usize,
        from: usize,
        g: &Gate,
        k: usize,
    ) -> Result<usize, LowerError> {
        let at = Pos::new(g.pos.row, g.pos.col.wrapping_sub(k + 1));
        let c = self.relay_for(p, g, at)?;
        let q = self.fresh();
        self.consumed.push(from);
        self.wire(from, q, Net::Leaf(c, at), g.line);
        Ok(q)
    }

    /// A new point.
    pub(in crate::formats::plcopen) fn fresh(&mut self) -> usize {
        let p = self.parent.len();
        self.parent.push(p);
        p
    }

    /// The one contact from the rail that feeds `p` and nothing else,
    /// taken out of the graph (its element, place and line).
    fn single_contact(&mut self, p: usize) -> Option<(Element, Pos, usize)> {
        let p = self.find(p);
        let rail = self.find(super::body::RAIL);
        let takers = self.takers();
        self.gate_work += self.edges.len();
        let feeding: Vec<usize> = (0..self.edges.len())
            .filter(|&i| {
                let b = self.edges[i].to;
                self.find(b) == p
            })
            .collect();
        let only = match feeding[..] {
            [i] if takers.get(&p).copied().unwrap_or(0) == 1 => i,
            _ => return None,
        };
        let ElementEdge {
            from: a, net, line, ..
        } = self.edges[only].clone();
        match net {
            Net::Leaf(e @ Element::Contact { .. }, at) if self.find(a) == rail => {
                self.edges.remove(only);
                Some((e, at, line))
            }
            _ => None,
        }
    }

    /// Folds each NOT, R_TRIG or F_TRIG box `machine` has no in-line form
    /// for into the one contact from the rail feeding it, when that is
    /// all that feeds it and nothing else takes its power (NOT a: the NC
    /// contact of a; R_TRIG a: a's rising contact): the same power,
    /// without the spare relay [`crate::formats::plcopen::import`]'s graph would otherwise
    /// hold the box's input in. One pass over the edges in the flow of
    /// power (a box after a folded one folds too: NOT NOT a is a's NO
    /// contact).
    pub(in crate::formats::plcopen) fn fold_boxes_into_contacts(&mut self, machine: MachineId) {
        if capabilities(machine).inline_boxes {
            return;
        }
        let rail = self.find(super::body::RAIL);
        let takers = self.takers();
        let mut from = Vec::with_capacity(self.edges.len());
        let mut feeders: HashMap<usize, Vec<usize>> = HashMap::new();
        for i in 0..self.edges.len() {
            let (a, b) = (self.edges[i].from, self.edges[i].to);
            from.push(self.find(a));
            feeders.entry(self.find(b)).or_default().push(i);
        }
        let mut gone = vec![false; self.edges.len()];
        // In the flow of power, whatever order the file wrote them in: a
        // box after a folded one folds too (NOT NOT a is a's contact).
        let rank = self.flow_ranks(Vec::new());
        let mut order: Vec<usize> = (0..self.edges.len()).collect();
        crate::sort::by_key(&mut order, |&i| {
            rank.get(&from[i]).copied().unwrap_or(usize::MAX)
        });
        for i in order {
            let e = match &self.edges[i].net {
                Net::Leaf(e @ (Element::Not | Element::Edge { .. }), _) => e.clone(),
                _ => continue,
            };
            let a = from[i];
            let only = match feeders.get(&a).map(Vec::as_slice) {
                Some(&[j]) if takers.get(&a) == Some(&1) && from[j] == rail && !gone[j] => j,
                _ => continue,
            };
            let (Net::Leaf(Element::Contact { kind, device }, at), line) =
                (&self.edges[only].net, self.edges[only].line)
            else {
                continue;
            };
            let Some(kind) = turned(&e, *kind) else {
                continue;
            };
            let device = device.clone();
            let folded = Net::Leaf(Element::Contact { kind, device }, *at);
            self.edges[i] = ElementEdge {
                from: super::body::RAIL,
                to: self.edges[i].to,
                net: folded,
                line,
            };
            from[i] = rail;
            gone[only] = true;
        }
        let mut k = 0;
        self.edges.retain(|_| {
            k += 1;
            !gone[k - 1]
        });
    }

    /// Moves the network feeding `p` to start at `from` instead of the
    /// rail (in series after it), if it can: when it is contacts only and
    /// only `p`'s taker uses it. Whether it moved.
    fn reroot(&mut self, p: usize, from: usize) -> bool {
        let rail = self.find(super::body::RAIL);
        let target = self.find(p);
        // The edges on the way back from `p` to the rail.
        let mut part = Vec::new();
        let mut todo = vec![target];
        let mut seen = vec![target];
        while let Some(q) = todo.pop() {
            self.gate_work += self.edges.len();
            for i in 0..self.edges.len() {
                let (a, b) = (self.edges[i].from, self.edges[i].to);
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
        // Contacts only: a box in it (NOT, an edge, a timer) would then
        // take the earlier inputs' power too (NOT(a and b) is not a and
        // NOT b).
        let boxed = part
            .iter()
            .any(|&i| !matches!(self.edges[i].net, Net::Leaf(Element::Contact { .. }, _)));
        if boxed {
            return false;
        }
        // Its own: nothing outside it takes power from its points.
        let takers = self.takers();
        for &q in &seen {
            let inside = part
                .iter()
                .filter(|&&i| {
                    let a = self.edges[i].from;
                    self.find(a) == q
                })
                .count();
            let expected = if q == target { 1 } else { inside };
            if takers.get(&q).copied().unwrap_or(0) != expected {
                return false;
            }
        }
        for i in part {
            let a = self.edges[i].from;
            if self.find(a) == rail {
                self.edges[i].from = from;
                // `from` now feeds it too: a later OR must see that.
                self.consumed.push(from);
            }
        }
        true
    }
}
