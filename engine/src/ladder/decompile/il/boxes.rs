//! The soft PLC's boxes read back from the IL its compiler writes
//! (`compile/il/blocks.rs`):
//!
//! ```text
//! comparison   LD a / GT b [/ AND p]                      in-line
//! function     [LD p / JMPCN L /] LD a / ADD b / ST out /
//!              (L: LD p | LD TRUE)                         in-line
//! either, then LD p (the rung's power again)               output box
//! ```
//!
//! `p` is the power held in a generated BOOL (`ST _pN` before it); with
//! none, the box stands on the rail.

use crate::iec::il::{Function, Line, Operand, Operator};
use crate::ladder::block::{BlockCall, COMPARISONS};
use crate::ladder::element::Element;
use crate::ladder::grid::Pos;
use crate::ladder::net::Net;

use super::{bad, StepWhy, Walk};

/// The operator's IEC name when it is a binary operator a function box
/// folds (`ADD`), or a comparison (`GT`).
fn binary(op: Operator) -> Option<&'static str> {
    Some(match op {
        Operator::Add => "ADD",
        Operator::Sub => "SUB",
        Operator::Mul => "MUL",
        Operator::Div => "DIV",
        Operator::Mod => "MOD",
        Operator::And => "AND",
        Operator::Or => "OR",
        Operator::Xor => "XOR",
        Operator::Gt => "GT",
        Operator::Ge => "GE",
        Operator::Eq => "EQ",
        Operator::Ne => "NE",
        Operator::Le => "LE",
        Operator::Lt => "LT",
        _ => return None,
    })
}

fn text(o: &Option<Operand>) -> Option<String> {
    o.as_ref().map(Operand::to_string)
}

/// Whether `line` loads the power `p` again (an output box ends so).
pub(super) fn reloads(line: Option<&Line>, p: &str) -> bool {
    loads(line, p)
}

/// Whether `line` is `LD name` (plain).
fn loads(line: Option<&Line>, name: &str) -> bool {
    line.is_some_and(|l| {
        l.operator == Operator::Ld
            && !l.negated
            && l.label.is_none()
            && text(&l.operand).as_deref() == Some(name)
    })
}

impl Walk<'_> {
    /// Whether the operand of `line` is a word (a declared non-BOOL, a
    /// word address, a literal other than TRUE / FALSE).
    fn word(&self, line: &Line) -> bool {
        match &line.operand {
            Some(Operand::Literal(d)) => d.data_type() != crate::iec::data::DataType::Bool,
            Some(Operand::Address(a)) => a.size != crate::iec::Size::Bit,
            Some(Operand::Name(n)) => self.words.contains(&n.to_ascii_uppercase()),
            Some(Operand::Text(_) | Operand::Number(_)) => true,
            None => false,
        }
    }

    /// A box starting at line `i`, if one does: the index after it.
    pub(super) fn boxed(&mut self, i: usize) -> Result<Option<usize>, super::DecompileError> {
        let lines = self.lines;
        let Some(first) = lines.get(i) else {
            return Ok(None);
        };
        let power = self.power.clone();
        // A function on the held power: LD p / JMPCN L / … / L: LD p.
        if let (Some(p), Some(jump)) = (&power, lines.get(i + 1)) {
            if loads(Some(first), p)
                && jump.operator == Operator::Jmp
                && jump.condition == Some(false)
            {
                let label = text(&jump.operand).unwrap_or_default();
                let end = (i + 2..lines.len())
                    .find(|&k| lines[k].label.as_deref() == Some(label.as_str()))
                    .ok_or_else(|| bad(i + 1, StepWhy::NoLabel))?;
                let call = self
                    .function(i + 2, end)
                    .ok_or_else(|| bad(i + 2, StepWhy::NoBoxReads))?;
                return Ok(Some(self.place(call, end + 1, Some(p.clone()))?));
            }
        }
        if first.operator != Operator::Ld || first.label.is_some() || !self.word(first) {
            return Ok(None);
        }
        // A comparison: LD a / GT b, then AND p on the held power.
        if let Some(kind) = lines.get(i + 1).and_then(|l| binary(l.operator)) {
            if COMPARISONS.contains(&kind) {
                let call = BlockCall {
                    kind: kind.into(),
                    instance: String::new(),
                    inputs: vec![
                        ("IN1".into(), text(&first.operand).unwrap_or_default()),
                        (
                            "IN2".into(),
                            text(&lines[i + 1].operand).unwrap_or_default(),
                        ),
                    ],
                    outputs: Vec::new(),
                };
                return match &power {
                    Some(p) if loads_and(lines.get(i + 2), p) => {
                        Ok(Some(self.place(call, i + 3, Some(p.clone()))?))
                    }
                    _ => Ok(Some(self.place(call, i + 2, None)?)),
                };
            }
        }
        // A function on the rail: … / LD TRUE.
        let Some(end) = (i..lines.len()).find(|&k| {
            lines[k].operator == Operator::Ld
                && lines[k].operand == Some(Operand::Literal(crate::iec::Data::Bool(true)))
        }) else {
            return Ok(None);
        };
        match self.function(i, end) {
            Some(call) => Ok(Some(self.place(call, end + 1, None)?)),
            None => Ok(None),
        }
    }

    /// Puts box `call` in the rung: an output box when the rung's power
    /// `p` is loaded again after it, else in-line (or a rung's start, on
    /// the rail). Returns the index after it.
    fn place(
        &mut self,
        call: BlockCall,
        next: usize,
        p: Option<String>,
    ) -> Result<usize, super::DecompileError> {
        if let Some(p) = &p {
            if loads(self.lines.get(next), p) {
                self.s.output(Element::OutputBlock(call), None, next)?;
                return Ok(next + 1);
            }
        }
        let leaf = Net::Leaf(Element::Block(call), Pos::new(0, 0));
        if p.is_some() {
            self.power = None;
            self.s.grow(leaf, true, next)?;
        } else {
            // A box on the rail starts a rung: the last must not lose its.
            self.no_box_lost(next)?;
            self.power = None;
            self.s.load(leaf);
        }
        Ok(next)
    }

    /// The function box lines `from..to` compute: `LD a`, its operators,
    /// then the `ST`s of its outputs.
    fn function(&self, from: usize, to: usize) -> Option<BlockCall> {
        let body = self.lines.get(from..to)?;
        let (first, rest) = body.split_first()?;
        if first.operator != Operator::Ld || first.negated {
            return None;
        }
        let stores = rest
            .iter()
            .rev()
            .take_while(|l| l.operator == Operator::St && !l.negated)
            .count();
        let (ops, outs) = rest.split_at(rest.len() - stores);
        let a = text(&first.operand)?;
        let input = |pin: &str, v: String| (pin.to_string(), v);
        let (kind, inputs) = match ops {
            [] => ("MOVE".to_string(), vec![input("IN", a)]),
            [op, ..] if binary(op.operator).is_some() => {
                let kind = binary(op.operator)?;
                if COMPARISONS.contains(&kind) || ops.iter().any(|o| o.operator != op.operator) {
                    return None;
                }
                let mut inputs = vec![input("IN1", a)];
                for (k, o) in ops.iter().enumerate() {
                    inputs.push(input(&format!("IN{}", k + 2), text(&o.operand)?));
                }
                (kind.to_string(), inputs)
            }
            [op] if op.operator == Operator::Not => ("NOT".to_string(), vec![input("IN", a)]),
            [op] => match op.operator {
                Operator::Function(f) => self.call_of(f, a, op)?,
                _ => return None,
            },
            _ => {
                // MAX / MIN of more than two: the same function each line.
                let f = match ops[0].operator {
                    Operator::Function(f @ (Function::Max | Function::Min)) => f,
                    _ => return None,
                };
                if ops.iter().any(|o| o.operator != Operator::Function(f)) {
                    return None;
                }
                let mut inputs = vec![input("IN1", a)];
                for (k, o) in ops.iter().enumerate() {
                    inputs.push(input(&format!("IN{}", k + 2), o.args.first()?.to_string()));
                }
                (f.name(), inputs)
            }
        };
        Some(BlockCall {
            kind,
            instance: String::new(),
            inputs,
            outputs: outs
                .iter()
                .map(|l| Some(("OUT".to_string(), text(&l.operand)?)))
                .collect::<Option<_>>()?,
        })
    }

    /// A standard function of the current result `a` and its line.
    fn call_of(
        &self,
        f: Function,
        a: String,
        op: &Line,
    ) -> Option<(String, Vec<(String, String)>)> {
        let arg = |k: usize| op.args.get(k).map(Operand::to_string);
        let pins: Vec<(&str, String)> = match f {
            Function::Neg | Function::Move | Function::Convert { .. } => vec![("IN", a)],
            Function::Abs | Function::Sqrt | Function::Trunc => vec![("IN", a)],
            Function::Expt => vec![("IN1", a), ("IN2", arg(0)?)],
            // MUX's inputs are as many as the line gives.
            Function::Mux => {
                let mut pins = vec![("K", a)];
                let names = ["IN0", "IN1", "IN2", "IN3", "IN4", "IN5", "IN6", "IN7"];
                for (k, name) in names.iter().enumerate().take(op.args.len()) {
                    pins.push((name, arg(k)?));
                }
                pins
            }
            Function::Shl | Function::Shr | Function::Rol | Function::Ror => {
                vec![("IN", a), ("N", arg(0)?)]
            }
            Function::Min | Function::Max => vec![("IN1", a), ("IN2", arg(0)?)],
            Function::Limit => vec![("MN", a), ("IN", arg(0)?), ("MX", arg(1)?)],
            Function::Sel => vec![("G", a), ("IN0", arg(0)?), ("IN1", arg(1)?)],
        };
        Some((
            f.name(),
            pins.into_iter().map(|(p, v)| (p.to_string(), v)).collect(),
        ))
    }
}

/// Whether `line` is `AND name`.
fn loads_and(line: Option<&Line>, name: &str) -> bool {
    line.is_some_and(|l| {
        l.operator == Operator::And
            && !l.negated
            && !l.deferred
            && text(&l.operand).as_deref() == Some(name)
    })
}

/// The box of a block `kind` called on the power (at `power_pin`) as
/// instance `block` by `line`, its power out into `q`.
pub(super) fn called(kind: &str, block: &str, line: &Line, power_pin: &str, q: &str) -> BlockCall {
    BlockCall {
        kind: kind.to_string(),
        instance: block.to_string(),
        inputs: line
            .inputs
            .iter()
            .filter(|(p, _)| !p.eq_ignore_ascii_case(power_pin))
            .map(|(p, v)| (p.clone(), v.to_string()))
            .collect(),
        outputs: line
            .outputs
            .iter()
            .filter(|(_, v)| v != q)
            .cloned()
            .collect(),
    }
}
