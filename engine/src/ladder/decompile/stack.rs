//! The block-stack walk shared by IO86A and the Arduino sketch: `LD`
//! opens a block, `ORB` / `ANB` join the top two, outputs close the rung.

use super::{add_output, close_rung, contact, drawn, DecompileError, Part, StepError};
use crate::ladder::element::{CoilKind, Element};
use crate::ladder::grid::Ladder;
use crate::ladder::net::{Net, RungLogic};
use crate::{arduino, io86a};

/// The block-stack walk shared by IO86A and the Arduino sketch.
#[derive(Default)]
pub(super) struct Stack {
    pub(super) rungs: Vec<RungLogic>,
    pub(super) blocks: Vec<Part>,
    pub(super) cur: Option<Part>,
    outputs: Vec<Element>,
    anchor: Option<String>,
}

impl Stack {
    /// Whether the open rung has a soft PLC box and no output yet: closed
    /// now, the box would be lost (a ladder draws no rung without one).
    pub(super) fn boxes_without_output(&self) -> bool {
        self.outputs.is_empty()
            && self.cur.iter().chain(&self.blocks).any(|p| {
                p.net
                    .leaves()
                    .iter()
                    .any(|(e, _)| matches!(e, Element::Block(_)))
            })
    }

    pub(super) fn flush(&mut self) {
        close_rung(&mut self.rungs, self.cur.take(), &mut self.outputs);
        self.blocks.clear();
        self.anchor = None;
    }

    pub(super) fn load(&mut self, n: Net) {
        if !self.outputs.is_empty() {
            self.flush();
        } else if let Some(c) = self.cur.take() {
            self.blocks.push(c);
        }
        self.cur = Some(Part::of(n));
    }

    pub(super) fn grow(&mut self, n: Net, and: bool, step: usize) -> Result<(), StepError> {
        if !self.outputs.is_empty() {
            let Some(d) = self.anchor.clone() else {
                return Err(StepError {
                    step,
                    message: "the rung goes on after outputs none of which holds its result".into(),
                });
            };
            self.flush();
            self.cur = Some(Part::of(contact(d, false)));
        }
        let cur = self.cur.take().ok_or(StepError {
            step,
            message: "no LD before this step".into(),
        })?;
        self.cur = Some(cur.join(Part::of(n), and, step)?);
        Ok(())
    }

    pub(super) fn join(&mut self, and: bool, step: usize) -> Result<(), StepError> {
        let (Some(a), Some(b)) = (self.blocks.pop(), self.cur.take()) else {
            return Err(StepError {
                step,
                message: "ORB / ANB needs two blocks".into(),
            });
        };
        self.cur = Some(a.join(b, and, step)?);
        Ok(())
    }

    pub(super) fn output(
        &mut self,
        e: Element,
        holds: Option<String>,
        step: usize,
    ) -> Result<(), StepError> {
        let open = self.cur.is_some();
        add_output(open, &mut self.outputs, &mut self.anchor, e, holds, step)
    }
}

fn word(w: io86a::Word) -> String {
    match w {
        io86a::Word::K(k) => format!("K{k}"),
        io86a::Word::D(n) => format!("D{n:02}"),
        io86a::Word::T(n) => format!("T{n:02}"),
        io86a::Word::C(n) => format!("C{n:02}"),
    }
}

pub(super) fn io86a_ladder(p: &io86a::Program) -> Result<Ladder, DecompileError> {
    use io86a::{Bit, Instruction as I};
    let mut s = Stack::default();
    for (step, &i) in p.instructions().iter().enumerate() {
        let bit = |b: Bit, inv: bool| contact(b.to_string(), inv);
        let coil = |kind: CoilKind, b: Bit| Element::Coil {
            kind,
            device: b.to_string(),
        };
        match i {
            I::Ld(b) | I::Ldi(b) => s.load(bit(b, matches!(i, I::Ldi(_)))),
            I::And(b) | I::Ani(b) => s.grow(bit(b, matches!(i, I::Ani(_))), true, step)?,
            I::Or(b) | I::Ori(b) => s.grow(bit(b, matches!(i, I::Ori(_))), false, step)?,
            I::Orb => s.join(false, step)?,
            I::Anb => s.join(true, step)?,
            I::Out(b) => s.output(coil(CoilKind::Normal, b), Some(b.to_string()), step)?,
            I::Set(b) => s.output(coil(CoilKind::Set, b), None, step)?,
            I::Rst(b) => s.output(coil(CoilKind::Reset, b), None, step)?,
            I::Pls(b) | I::Plf(b) => s.output(
                Element::Pulse {
                    falling: matches!(i, I::Plf(_)),
                    device: b.to_string(),
                },
                None,
                step,
            )?,
            I::OutTimer(n, w) | I::OutCounter(n, w) => {
                let io86a::Word::K(k) = w else {
                    return Err(DecompileError::Step(StepError {
                        step,
                        message: "a set value from a data register has no ladder form here: use a K constant".into(),
                    }));
                };
                let preset = u16::try_from(k).unwrap_or(0);
                let e = if matches!(i, I::OutTimer(..)) {
                    Element::TimerCoil {
                        device: format!("T{n:02}"),
                        preset,
                    }
                } else {
                    Element::CounterCoil {
                        device: format!("C{n:02}"),
                        preset,
                    }
                };
                s.output(e, None, step)?;
            }
            I::Mov(w, d) => s.output(
                Element::Mov {
                    src: word(w),
                    dst: format!("D{d:02}"),
                },
                None,
                step,
            )?,
            I::Cmp(a, b) => s.output(
                Element::Cmp {
                    a: word(a),
                    b: word(b),
                },
                None,
                step,
            )?,
            I::Inc(d) => s.output(
                Element::Inc {
                    dst: format!("D{d:02}"),
                },
                None,
                step,
            )?,
            I::Dec(d) => s.output(
                Element::Dec {
                    dst: format!("D{d:02}"),
                },
                None,
                step,
            )?,
            I::Sets(_) | I::Rsts(_) => {
                return Err(DecompileError::Step(StepError {
                    step,
                    message: "SETS / RSTS drive a second device: they have no ladder form here"
                        .into(),
                }))
            }
            I::End => break,
        }
    }
    s.flush();
    drawn(&s.rungs)
}

pub(super) fn arduino_ladder(p: &arduino::Program) -> Result<Ladder, DecompileError> {
    use arduino::isa::{io_name, Op};
    let words = p.words();
    let mut s = Stack::default();
    for (step, &w) in words.iter().enumerate() {
        if w == arduino::isa::ERASED {
            break;
        }
        let operand = (w & 0xFF) as u8;
        let dev = || io_name(operand);
        match Op::decode(w) {
            Some(Op::Ld) | Some(Op::Ldn) => {
                s.load(contact(dev(), Op::decode(w) == Some(Op::Ldn)));
            }
            Some(op @ (Op::And | Op::Andn | Op::Or | Op::Orn)) => s.grow(
                contact(dev(), matches!(op, Op::Andn | Op::Orn)),
                matches!(op, Op::And | Op::Andn),
                step,
            )?,
            Some(Op::Andb) => s.join(true, step)?,
            Some(Op::Orb) => s.join(false, step)?,
            Some(Op::Out) => {
                s.output(Element::coil(&dev()), None, step)?;
                // The pop: this rung ends here, the block below (if any)
                // becomes the current one.
                let below = s.blocks.pop();
                let rest = std::mem::take(&mut s.blocks);
                s.flush();
                s.blocks = rest;
                s.cur = below;
            }
            Some(Op::End) => break,
            Some(Op::Jump) if operand == 0 => break,
            Some(Op::Jump) => {
                return Err(DecompileError::Step(StepError {
                    step,
                    message: format!(
                        "JUMP {operand} has no ladder form: only a final JUMP 0 (or END)"
                    ),
                }))
            }
            None => {
                return Err(DecompileError::Step(StepError {
                    step,
                    message: format!("word {w:04X} is no instruction"),
                }))
            }
        }
    }
    s.flush();
    drawn(&s.rungs)
}
