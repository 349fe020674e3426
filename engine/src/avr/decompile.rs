//! An AVR PLC program read back as a ladder, with the accumulator walk
//! MINASEC-U shares (`ladder::decompile::accumulator`); its named bits
//! become the ladder's device comments.

use super::{Instruction as I, Program};
use crate::ladder::decompile::accumulator::Acc;
use crate::ladder::decompile::{contact, drawn, DecompileError};
use crate::ladder::element::{CoilKind, Element, TimerKind};
use crate::ladder::grid::{Ladder, Pos};
use crate::ladder::net::Net;

/// The program as a ladder, its in-line timers' presets in ms for a
/// `scan_ms` scan.
pub fn decompile(p: &Program, scan_ms: u32) -> Result<Ladder, DecompileError> {
    let mut acc = Acc::default();
    for (step, &i) in p.instructions().iter().enumerate() {
        match i {
            I::Load(b, inv) => acc.load(contact(b.to_string(), inv)),
            I::And(b, inv) => acc.and(contact(b.to_string(), inv), step)?,
            I::Or(b, inv) => acc.or(contact(b.to_string(), inv), step)?,
            I::Coil(b, inv) => {
                let kind = if inv {
                    CoilKind::Inverted
                } else {
                    CoilKind::Normal
                };
                acc.output(
                    Element::Coil {
                        kind,
                        device: b.to_string(),
                    },
                    Some((b.to_string(), inv)),
                    step,
                )?;
            }
            I::Set(b) | I::Reset(b) => {
                let kind = if matches!(i, I::Set(_)) {
                    CoilKind::Set
                } else {
                    CoilKind::Reset
                };
                acc.output(
                    Element::Coil {
                        kind,
                        device: b.to_string(),
                    },
                    None,
                    step,
                )?;
            }
            I::Timer {
                kind,
                index,
                preset,
            } => {
                let name = format!("Timer{index}");
                let kind = match kind {
                    super::TimerKind::Ton => TimerKind::Ton,
                    super::TimerKind::Tof => TimerKind::Tof,
                    super::TimerKind::Tp => TimerKind::Tp,
                };
                let leaf = Element::Timer {
                    kind,
                    name,
                    preset_ms: u32::from(preset) * scan_ms,
                };
                acc.and(Net::Leaf(leaf, Pos::new(0, 0)), step)?;
            }
            I::Not => acc.and(Net::Leaf(Element::Not, Pos::new(0, 0)), step)?,
            I::Pulse(_, falling) => {
                acc.and(Net::Leaf(Element::Edge { falling }, Pos::new(0, 0)), step)?
            }
            I::End => break,
        }
    }
    acc.flush();
    let mut ladder = drawn(&acc.rungs)?;
    for (name, bit) in p.names() {
        ladder.device_comments.insert(bit.to_string(), name.clone());
    }
    Ok(ladder)
}
