//! A PLC-IO86A listing read back as a ladder, with the block-stack walk
//! the Arduino sketch shares (`ladder::decompile::stack`).

use super::{Bit, Instruction as I, Program, Word};
use crate::ladder::decompile::stack::Stack;
use crate::ladder::decompile::{contact, drawn, DecompileError, StepError, StepWhy};
use crate::ladder::element::{CoilKind, Element};
use crate::ladder::grid::Ladder;

fn word(w: Word) -> String {
    match w {
        Word::K(k) => format!("K{k}"),
        Word::D(n) => format!("D{n:02}"),
        Word::T(n) => format!("T{n:02}"),
        Word::C(n) => format!("C{n:02}"),
    }
}

/// The program as a ladder.
pub fn decompile(p: &Program) -> Result<Ladder, DecompileError> {
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
                let Word::K(k) = w else {
                    return Err(DecompileError::Step(StepError {
                        step,
                        why: StepWhy::RegisterValue,
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
                    why: StepWhy::SecondDevice,
                }))
            }
            I::End => break,
        }
    }
    s.flush();
    drawn(&s.rungs)
}
