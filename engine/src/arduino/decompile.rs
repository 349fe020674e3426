//! An Arduino PLC sketch program read back as a ladder, with the
//! block-stack walk IO86A shares (`ladder::decompile::stack`).

use super::isa::{io_name, Op, ERASED};
use super::Program;
use crate::ladder::decompile::stack::Stack;
use crate::ladder::decompile::{contact, drawn, DecompileError, StepError, StepWhy};
use crate::ladder::element::Element;
use crate::ladder::grid::Ladder;

/// The program as a ladder (up to its END or final JUMP 0).
pub fn decompile(p: &Program) -> Result<Ladder, DecompileError> {
    let words = p.words();
    let mut s = Stack::default();
    for (step, &w) in words.iter().enumerate() {
        if w == ERASED {
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
                    why: StepWhy::Jump(operand),
                }))
            }
            None => {
                return Err(DecompileError::Step(StepError {
                    step,
                    why: StepWhy::Word(w),
                }))
            }
        }
    }
    s.flush();
    drawn(&s.rungs)
}
