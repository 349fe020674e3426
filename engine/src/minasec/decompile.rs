//! A MINASEC-U listing read back as a ladder, with the accumulator walk
//! the AVR PLC shares (`ladder::decompile::accumulator`); a temporary
//! relay M10-M13 stored once and read once is folded back into its reader.

use super::isa::Device;
use super::{Opcode, Program};
use crate::ladder::decompile::accumulator::{fold_temporaries, Acc};
use crate::ladder::decompile::{contact, drawn, DecompileError};
use crate::ladder::element::{CoilKind, Element};
use crate::ladder::grid::Ladder;

/// The program as a ladder.
pub fn decompile(p: &Program) -> Result<Ladder, DecompileError> {
    let mut acc = Acc::default();
    for (step, i) in p.instructions().enumerate() {
        let d = i.address.to_string();
        let plain = matches!(i.address.device(), Device::Output(_) | Device::Relay(_));
        match i.opcode {
            Opcode::Ld | Opcode::Ldi => acc.load(contact(d, i.opcode == Opcode::Ldi)),
            Opcode::And | Opcode::Andi => acc.and(contact(d, i.opcode == Opcode::Andi), step)?,
            Opcode::Or | Opcode::Ori => acc.or(contact(d, i.opcode == Opcode::Ori), step)?,
            Opcode::St | Opcode::Sti => {
                let inv = i.opcode == Opcode::Sti;
                let kind = if inv {
                    CoilKind::Inverted
                } else {
                    CoilKind::Normal
                };
                let holds = plain.then(|| (d.clone(), inv));
                acc.output(Element::Coil { kind, device: d }, holds, step)?;
            }
        }
    }
    acc.flush();
    let rungs = fold_temporaries(acc.rungs, &["M10", "M11", "M12", "M13"]);
    drawn(&rungs)
}
