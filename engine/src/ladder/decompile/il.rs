//! The soft PLC's Instruction List back to a ladder: the form the ladder
//! compiler writes (`compile/il.rs`) and hand-written IL of the same
//! kind. `LD` opens a block, `AND` / `OR` grow it, `AND(` / `OR(` … `)`
//! are a block joined in series / in parallel, `ST` / `STN` / `S` / `R`
//! are coils. An R_TRIG / F_TRIG called on a device (`CAL e(CLK := x,
//! Q => q)`) makes each later contact on `q` a rising / falling contact
//! on `x`; a timer called on the power (`ST p`, `CAL t(IN := p, PT :=
//! T#500ms, Q => q)`, `LD q`) is an in-line box. Anything else (word
//! data, jumps) has no ladder form yet and is refused at its step.

use std::collections::HashMap;

use super::stack::Stack;
use super::{contact, drawn, DecompileError, Part, StepError};
use crate::ladder::element::{CoilKind, ContactKind, Element, TimerKind};
use crate::ladder::grid::{Ladder, Pos};
use crate::ladder::net::Net;
use crate::softplc::il::{Line, Operand, Operator};
use crate::softplc::vars::{Kind, Variable};

/// What a generated BOOL stands for.
enum Stands {
    /// The Q of an edge block on a device.
    Edge(ContactKind, String),
    /// The Q of an in-line box, to load next.
    Boxed(Element),
}

/// The ladder of an IL program's declarations and lines.
pub(super) fn il_ladder(vars: &[Variable], lines: &[Line]) -> Result<Ladder, DecompileError> {
    let kind_of = |name: &str| {
        vars.iter().find_map(|v| match &v.kind {
            Kind::Block(b) if v.name.eq_ignore_ascii_case(name) => Some(b.as_str()),
            _ => None,
        })
    };
    let mut s = Stack::default();
    let mut pending: Vec<bool> = Vec::new();
    let mut stands: HashMap<String, Stands> = HashMap::new();
    // `ST p` of the power into a box: held until the box's CAL.
    let mut power: Option<String> = None;
    // `LD TRUE`: the rail's power, for a NOT straight after it.
    let mut rail = false;
    for (step, line) in lines.iter().enumerate() {
        let bad = |message: String| DecompileError::Step(StepError { step, message });
        let name = match &line.operand {
            Some(Operand::Name(n)) => Some(n.clone()),
            Some(Operand::Address(a)) => Some(a.to_string()),
            _ => None,
        };
        let leaf = |name: &str, inverted: bool| -> Net {
            match stands.get(name) {
                Some(Stands::Edge(kind, device)) => Net::Leaf(
                    Element::Contact {
                        kind: *kind,
                        device: device.clone(),
                    },
                    Pos::new(0, 0),
                ),
                _ => contact(name.to_string(), inverted),
            }
        };
        if line.label.is_some() || line.condition.is_some() {
            return Err(bad(
                "labels and conditional operators have no ladder form".into()
            ));
        }
        let was_rail = std::mem::take(&mut rail);
        match (line.operator, &name, line.deferred) {
            (Operator::Ld, Some(n), false) if power.as_deref() == Some(n.as_str()) => {
                return Err(bad(
                    "a box in a parallel branch has no ladder form here".into()
                ));
            }
            (Operator::Ld, Some(n), false) => match stands.get(n) {
                Some(Stands::Boxed(e)) => {
                    let e = e.clone();
                    if power.take().is_some() {
                        s.grow(Net::Leaf(e, Pos::new(0, 0)), true, step)?;
                    } else {
                        s.load(Net::Leaf(e, Pos::new(0, 0)));
                    }
                }
                _ => {
                    // A new rung: the power held for the last one's
                    // boxes and pulses is no longer this one's.
                    power = None;
                    s.load(leaf(n, line.negated));
                }
            },
            (Operator::Ld, None, false)
                if line.operand == Some(Operand::Literal(crate::softplc::Data::Bool(true))) =>
            {
                rail = true;
            }
            (Operator::And | Operator::Or, Some(n), false) => {
                s.grow(leaf(n, line.negated), line.operator == Operator::And, step)?
            }
            (Operator::And | Operator::Or, _, true) => {
                let and = line.operator == Operator::And;
                let cur = s
                    .cur
                    .take()
                    .ok_or_else(|| bad("no LD before this step".into()))?;
                s.blocks.push(cur);
                if let Some(n) = &name {
                    s.cur = Some(Part::of(leaf(n, line.negated)));
                }
                pending.push(and);
            }
            (Operator::Close, _, _) => {
                let and = pending.pop().ok_or_else(|| bad("`)` with no `(`".into()))?;
                s.join(and, step)?;
            }
            (Operator::Not, _, _) if was_rail => s.load(Net::Leaf(Element::Not, Pos::new(0, 0))),
            (Operator::Not, _, _) => s.grow(Net::Leaf(Element::Not, Pos::new(0, 0)), true, step)?,
            (Operator::St, Some(n), false) if n.starts_with("_p") && !line.negated => {
                power = Some(n.clone());
            }
            (Operator::St | Operator::S | Operator::R, Some(n), false) => {
                let kind = match (line.operator, line.negated) {
                    (Operator::St, false) => CoilKind::Normal,
                    (Operator::St, true) => CoilKind::Inverted,
                    (Operator::S, _) => CoilKind::Set,
                    _ => CoilKind::Reset,
                };
                let holds = (kind == CoilKind::Normal).then(|| n.clone());
                let coil = Element::Coil {
                    kind,
                    device: n.clone(),
                };
                s.output(coil, holds, step)?;
            }
            (Operator::Cal, Some(block), _) => {
                let kind = kind_of(block).unwrap_or_default();
                let input = |pin: &str| {
                    line.inputs
                        .iter()
                        .find(|(p, _)| p.eq_ignore_ascii_case(pin))
                        .map(|(_, v)| v)
                };
                let q = line
                    .outputs
                    .iter()
                    .find(|(p, _)| p.eq_ignore_ascii_case("Q"))
                    .map(|(_, v)| v.clone())
                    .ok_or_else(|| bad("a call with no Q => has no ladder form".into()))?;
                let from_power = |v: Option<&Operand>| match v {
                    Some(Operand::Literal(crate::softplc::Data::Bool(true))) => true,
                    Some(Operand::Name(n)) => power.as_deref() == Some(n.as_str()),
                    _ => false,
                };
                match kind {
                    "R_TRIG" | "F_TRIG" if !from_power(input("CLK")) => {
                        let Some(Operand::Name(_) | Operand::Address(_)) = input("CLK") else {
                            return Err(bad("an edge on a literal has no ladder form".into()));
                        };
                        let device = input("CLK").map(|o| o.to_string()).unwrap_or_default();
                        let edge = if kind == "R_TRIG" {
                            ContactKind::Rising
                        } else {
                            ContactKind::Falling
                        };
                        stands.insert(q, Stands::Edge(edge, device));
                    }
                    // On the power into a name of the ladder's own: a
                    // PLS / PLF output.
                    "R_TRIG" | "F_TRIG" if !q.starts_with("_q") => {
                        let e = Element::Pulse {
                            falling: kind == "F_TRIG",
                            device: q,
                        };
                        s.output(e, None, step)?;
                    }
                    "R_TRIG" | "F_TRIG" => {
                        let e = Element::Edge {
                            falling: kind == "F_TRIG",
                        };
                        stands.insert(q, Stands::Boxed(e));
                    }
                    "TON" | "TOF" | "TP" if from_power(input("IN")) => {
                        let Some(Operand::Literal(crate::softplc::Data::Time(ns))) = input("PT")
                        else {
                            return Err(bad(
                                "a timer's PT other than a T# literal has no ladder form here"
                                    .into(),
                            ));
                        };
                        let preset_ms = u32::try_from(ns / 1_000_000).unwrap_or(u32::MAX);
                        let kind = match kind {
                            "TON" => TimerKind::Ton,
                            "TOF" => TimerKind::Tof,
                            _ => TimerKind::Tp,
                        };
                        stands.insert(
                            q,
                            Stands::Boxed(Element::Timer {
                                kind,
                                name: block.clone(),
                                preset_ms,
                            }),
                        );
                    }
                    _ => return Err(bad(format!("CAL {block} has no ladder form yet"))),
                }
            }
            _ => return Err(bad(format!("`{line}` has no ladder form yet"))),
        }
    }
    s.flush();
    drawn(&s.rungs)
}
