//! The soft PLC's Instruction List back to a ladder: the form the ladder
//! compiler writes (`compile/il.rs`) and hand-written IL of the same
//! kind. `LD` opens a block, `AND` / `OR` grow it, `AND(` / `OR(` … `)`
//! are a block joined in series / in parallel, `ST` / `STN` / `S` / `R`
//! are coils. An R_TRIG / F_TRIG called on a device (`CAL e(CLK := x,
//! Q => q)`) makes each later contact on `q` a rising / falling contact
//! on `x`; a timer called on the power (`ST p`, `CAL t(IN := p, PT :=
//! T#500ms, Q => q)`, `LD q`) is an in-line box, as is any block called
//! on the power (then a soft PLC box); functions and comparisons come
//! back as boxes (`boxes.rs`). Anything else (jumps, hand-written
//! shapes) has no ladder form and is refused at its step.

mod boxes;

use std::collections::{HashMap, HashSet};

use super::stack::Stack;
use super::{contact, drawn, DecompileError, Part, StepError, StepWhy};
use crate::iec::il::{Line, Operand, Operator};
use crate::iec::vars::Kind;
use crate::iec::vars::Variable;
use crate::ladder::element::{CoilKind, ContactKind, Element, TimerKind};
use crate::ladder::grid::{Ladder, Pos};
use crate::ladder::net::Net;

/// What a generated BOOL stands for.
enum Stands {
    /// The Q of an edge block on a device.
    Edge(ContactKind, String),
    /// The Q of an in-line box, to load next.
    Boxed(Element),
}

/// The walk over the lines: the block stack, the pending `(`, what
/// each generated BOOL stands for, the power held for a box, and whether
/// the last line loaded the rail (`LD TRUE`, for a NOT after it).
struct Walk<'a> {
    vars: &'a [Variable],
    lines: &'a [Line],
    /// The declared names (upper-case) that hold words.
    words: HashSet<String>,
    s: Stack,
    pending: Vec<bool>,
    stands: HashMap<String, Stands>,
    power: Option<String>,
    rail: bool,
}

type Step = Result<(), DecompileError>;

/// The ladder of an IL program's declarations and lines.
pub(super) fn il_ladder(vars: &[Variable], lines: &[Line]) -> Result<Ladder, DecompileError> {
    let mut words: HashSet<String> = vars
        .iter()
        .filter(|v| matches!(v.kind, Kind::Value { data_type, .. } if data_type != crate::iec::data::DataType::Bool))
        .map(|v| v.name.to_ascii_uppercase())
        .collect();
    // A block's word outputs read as operands (`GT c0.CV 3`).
    for v in vars {
        if let Kind::Block(kind) = &v.kind {
            let outputs = crate::iec::pins::outputs(kind);
            for (pin, _) in outputs
                .iter()
                .filter(|(_, t)| *t != crate::iec::data::DataType::Bool)
            {
                words.insert(format!("{}.{pin}", v.name.to_ascii_uppercase()));
            }
        }
    }
    let mut w = Walk {
        vars,
        lines,
        words,
        s: Stack::default(),
        pending: Vec::new(),
        stands: HashMap::new(),
        power: None,
        rail: false,
    };
    let mut step = 0;
    while step < lines.len() {
        step = match w.boxed(step)? {
            Some(next) => next,
            None => w.line(step, &lines[step])?,
        };
    }
    w.no_box_lost(lines.len())?;
    w.s.flush();
    drawn(&w.s.rungs)
}

fn bad(step: usize, why: StepWhy) -> DecompileError {
    DecompileError::Step(StepError { step, why })
}

impl<'a> Walk<'a> {
    /// A contact on `name`, or the edge contact its R_TRIG stands for.
    fn leaf(&self, name: &str, inverted: bool) -> Net {
        match self.stands.get(name) {
            Some(Stands::Edge(kind, device)) => Net::Leaf(
                Element::Contact {
                    kind: *kind,
                    device: device.clone(),
                },
                Pos::new(0, 0),
            ),
            _ => contact(name.to_string(), inverted),
        }
    }

    /// One line; the index of the next.
    fn line(&mut self, step: usize, line: &Line) -> Result<usize, DecompileError> {
        let name = match &line.operand {
            Some(Operand::Name(n)) => Some(n.clone()),
            Some(Operand::Address(a)) => Some(a.to_string()),
            _ => None,
        };
        if line.label.is_some() || line.condition.is_some() {
            return Err(bad(step, StepWhy::Labels));
        }
        let was_rail = std::mem::take(&mut self.rail);
        match (line.operator, &name, line.deferred) {
            (Operator::Ld, Some(n), false) => return self.load(step, n, line.negated),
            (Operator::Ld, None, false)
                if line.operand == Some(Operand::Literal(crate::iec::Data::Bool(true))) =>
            {
                self.rail = true;
            }
            (Operator::And | Operator::Or, Some(n), false) => {
                let leaf = self.leaf(n, line.negated);
                self.s.grow(leaf, line.operator == Operator::And, step)?
            }
            (Operator::And | Operator::Or, _, true) => {
                let cur = self
                    .s
                    .cur
                    .take()
                    .ok_or_else(|| bad(step, StepWhy::NoLoad))?;
                self.s.blocks.push(cur);
                if let Some(n) = &name {
                    self.s.cur = Some(Part::of(self.leaf(n, line.negated)));
                }
                self.pending.push(line.operator == Operator::And);
            }
            (Operator::Close, _, _) => {
                let and = self
                    .pending
                    .pop()
                    .ok_or_else(|| bad(step, StepWhy::NoOpen))?;
                self.s.join(and, step)?;
            }
            (Operator::Not, _, _) if was_rail => {
                self.s.load(Net::Leaf(Element::Not, Pos::new(0, 0)))
            }
            (Operator::Not, _, _) => {
                self.s
                    .grow(Net::Leaf(Element::Not, Pos::new(0, 0)), true, step)?
            }
            (Operator::St, Some(n), false) if n.starts_with("_p") && !line.negated => {
                self.power = Some(n.clone());
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
                self.s.output(coil, holds, step)?;
            }
            (Operator::Cal, Some(block), _) => self.call(step, line, block)?,
            _ => return Err(bad(step, StepWhy::Line(line.to_string()))),
        }
        Ok(step + 1)
    }

    /// The block kind instance `block` is declared as ("" if none).
    fn kind_of(&self, block: &str) -> &'a str {
        self.vars
            .iter()
            .find_map(|v| match &v.kind {
                Kind::Block(b) if v.name.eq_ignore_ascii_case(block) => Some(b.as_str()),
                _ => None,
            })
            .unwrap_or_default()
    }

    /// Refuses to close a rung whose boxes drive nothing (at `step`):
    /// the ladder would lose them, and with them what they compute.
    fn no_box_lost(&self, step: usize) -> Result<(), DecompileError> {
        if self.s.boxes_without_output() {
            return Err(bad(step, StepWhy::BoxWithoutOutput));
        }
        Ok(())
    }

    /// `LD n`: a new rung from a contact, or the output of a box (on the
    /// power held for it, or on the rail; an output box when the power
    /// is loaded again after it). The index of the next line.
    fn load(&mut self, step: usize, n: &str, negated: bool) -> Result<usize, DecompileError> {
        if self.power.as_deref() == Some(n) {
            return Err(bad(step, StepWhy::ParallelBox));
        }
        match self.stands.get(n) {
            Some(Stands::Boxed(e)) => {
                let e = e.clone();
                let power = self.power.take();
                if let (Some(p), Element::Block(call)) = (&power, &e) {
                    if boxes::reloads(self.lines.get(step + 1), p) {
                        self.s
                            .output(Element::OutputBlock(call.clone()), None, step)?;
                        self.power = power;
                        return Ok(step + 2);
                    }
                }
                let e = Net::Leaf(e, Pos::new(0, 0));
                if power.is_some() {
                    self.s.grow(e, true, step)?;
                } else {
                    self.s.load(e);
                }
            }
            _ => {
                self.no_box_lost(step)?;
                // A new rung: the power held for the last one's boxes
                // and pulses is no longer this one's.
                self.power = None;
                let leaf = self.leaf(n, negated);
                self.s.load(leaf);
            }
        }
        Ok(step + 1)
    }

    /// `CAL block(…)`: an edge contact's R_TRIG, a pulse output, an
    /// in-line edge or timer box.
    fn call(&mut self, step: usize, line: &Line, block: &str) -> Step {
        let kind = self.kind_of(block);
        let input = |pin: &str| {
            line.inputs
                .iter()
                .find(|(p, _)| p.eq_ignore_ascii_case(pin))
                .map(|(_, v)| v)
        };
        // The power out: the block's first output (Q, QU, Q1).
        let out_pin = crate::iec::pins::outputs(kind)
            .first()
            .map_or("Q", |(p, _)| *p);
        let q = line
            .outputs
            .iter()
            .find(|(p, _)| p.eq_ignore_ascii_case(out_pin))
            .map(|(_, v)| v.clone())
            .ok_or_else(|| bad(step, StepWhy::NoPowerOut))?;
        let from_power = |v: Option<&Operand>| match v {
            Some(Operand::Literal(crate::iec::Data::Bool(true))) => true,
            Some(Operand::Name(n)) => self.power.as_deref() == Some(n.as_str()),
            _ => false,
        };
        let stands = match kind {
            "R_TRIG" | "F_TRIG" if !from_power(input("CLK")) => {
                let Some(clk @ (Operand::Name(_) | Operand::Address(_))) = input("CLK") else {
                    return Err(bad(step, StepWhy::EdgeOnLiteral));
                };
                let edge = if kind == "R_TRIG" {
                    ContactKind::Rising
                } else {
                    ContactKind::Falling
                };
                Stands::Edge(edge, clk.to_string())
            }
            // On the power into a name of the ladder's own: a PLS / PLF.
            "R_TRIG" | "F_TRIG" if !q.starts_with("_q") => {
                let e = Element::Pulse {
                    falling: kind == "F_TRIG",
                    device: q,
                };
                return Ok(self.s.output(e, None, step)?);
            }
            "R_TRIG" | "F_TRIG" => Stands::Boxed(Element::Edge {
                falling: kind == "F_TRIG",
            }),
            "TON" | "TOF" | "TP" if from_power(input("IN")) && timer_shaped(line) => {
                let Some(Operand::Literal(crate::iec::Data::Time(ns))) = input("PT") else {
                    return Err(bad(step, StepWhy::TimerPreset));
                };
                let kind = match kind {
                    "TON" => TimerKind::Ton,
                    "TOF" => TimerKind::Tof,
                    _ => TimerKind::Tp,
                };
                Stands::Boxed(Element::Timer {
                    kind,
                    name: block.to_string(),
                    preset_ms: u32::try_from(ns / 1_000_000).unwrap_or(u32::MAX),
                })
            }
            kind if crate::iec::pins::is_block_type(kind) => {
                let pins = crate::iec::pins::inputs(kind);
                let power_pin = pins.first().map_or("", |(p, _)| *p);
                if !from_power(input(power_pin)) {
                    return Err(bad(step, StepWhy::Call(block.to_string())));
                }
                Stands::Boxed(Element::Block(boxes::called(
                    kind, block, line, power_pin, &q,
                )))
            }
            _ => return Err(bad(step, StepWhy::Call(block.to_string()))),
        };
        self.stands.insert(q, stands);
        Ok(())
    }
}

/// Whether a timer call is an in-line timer's (IN, PT as a T# literal,
/// Q alone) rather than a box's.
fn timer_shaped(line: &Line) -> bool {
    line.inputs.len() == 2 && line.outputs.len() == 1
}

/// The program's declarations as the ladder's variables: the words and
/// the block instances it names (a BOOL needs no declaration, and the
/// compiler's own `_` names are its to make again), with their
/// addresses, start values, retain and comments.
pub(super) fn declared(vars: &[Variable]) -> Vec<crate::ladder::Variable> {
    vars.iter()
        .filter(|v| !v.name.starts_with('_'))
        .filter_map(|v| {
            let (ty, initial) = match &v.kind {
                Kind::Value { data_type, init } => {
                    let initial = if *init == data_type.zero() {
                        String::new()
                    } else {
                        init.to_string()
                    };
                    if *data_type == crate::iec::data::DataType::Bool
                        && v.address.is_none()
                        && initial.is_empty()
                        && !v.retain
                        && v.comment.is_empty()
                    {
                        return None;
                    }
                    (data_type.name().to_string(), initial)
                }
                Kind::Block(b) => (b.clone(), String::new()),
            };
            let mut out = crate::ladder::Variable::new(&v.name, &ty);
            out.address = v.address.map(|a| a.to_string()).unwrap_or_default();
            out.initial = initial;
            out.retain = v.retain;
            out.comment = v.comment.clone();
            Some(out)
        })
        .collect()
}
