//! The accumulator walk shared by MINASEC-U and the AVR PLC: `LD` starts
//! a condition, `AND` / `OR` grow it, each store is an output of the rung.

use super::{add_output, close_rung, contact, drawn, DecompileError, Part, StepError};
use crate::ladder::compile::negate;
use crate::ladder::element::{CoilKind, ContactKind, Element, TimerKind};
use crate::ladder::grid::{Ladder, Pos};
use crate::ladder::net::{Net, RungLogic};
use crate::limits::MAX_NESTING;
use crate::{avr, minasec};

/// The accumulator walk shared by MINASEC-U and the AVR PLC.
#[derive(Default)]
struct Acc {
    rungs: Vec<RungLogic>,
    a: Option<Part>,
    outputs: Vec<Element>,
    /// An output holding the accumulator's value: (device, inverted).
    anchor: Option<(String, bool)>,
}

impl Acc {
    fn flush(&mut self) {
        close_rung(&mut self.rungs, self.a.take(), &mut self.outputs);
    }

    fn load(&mut self, n: Net) {
        self.flush();
        self.anchor = None;
        self.a = Some(Part::of(n));
    }

    /// The running result, restarting from the anchor after outputs.
    fn current(&mut self, step: usize) -> Result<Part, StepError> {
        if !self.outputs.is_empty() {
            let Some((d, inv)) = self.anchor.clone() else {
                return Err(StepError {
                    step,
                    message: "the result is used again after outputs none of which holds it: store it in a relay first".into(),
                });
            };
            self.flush();
            self.a = Some(Part::of(contact(d, inv)));
        }
        self.a.take().ok_or(StepError {
            step,
            message: "no LD before this step".into(),
        })
    }

    fn and(&mut self, n: Net, step: usize) -> Result<(), StepError> {
        let a = self.current(step)?;
        self.a = Some(a.join(Part::of(n), true, step)?);
        Ok(())
    }

    fn or(&mut self, n: Net, step: usize) -> Result<(), StepError> {
        let a = self.current(step)?;
        self.a = Some(a.join(Part::of(n), false, step)?);
        Ok(())
    }

    fn output(
        &mut self,
        e: Element,
        holds: Option<(String, bool)>,
        step: usize,
    ) -> Result<(), StepError> {
        let open = self.a.is_some();
        add_output(open, &mut self.outputs, &mut self.anchor, e, holds, step)
    }
}

pub(super) fn minasec_ladder(p: &minasec::Program) -> Result<Ladder, DecompileError> {
    use minasec::isa::Device;
    use minasec::Opcode;
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

pub(super) fn avr_ladder(p: &avr::Program, scan_ms: u32) -> Result<Ladder, DecompileError> {
    use avr::Instruction as I;
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
                    avr::TimerKind::Ton => TimerKind::Ton,
                    avr::TimerKind::Tof => TimerKind::Tof,
                    avr::TimerKind::Tp => TimerKind::Tp,
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
    drawn(&acc.rungs)
}

/// Folds a temporary stored by one rung and read once by a later one back
/// into the reader, when nothing in between changes what it was made of.
fn fold_temporaries(mut rungs: Vec<RungLogic>, temps: &[&str]) -> Vec<RungLogic> {
    let reads = |r: &RungLogic, d: &str| {
        r.condition
            .leaves()
            .iter()
            .filter(|(e, _)| e.read_device() == Some(d))
            .count()
    };
    let writes =
        |r: &RungLogic, d: &str| r.outputs.iter().any(|(e, _)| e.written_device() == Some(d));
    let mut i = 0;
    while i < rungs.len() {
        let foldable = match rungs[i].outputs.as_slice() {
            [(
                Element::Coil {
                    kind: CoilKind::Normal,
                    device,
                },
                _,
            )] if temps.contains(&device.as_str()) => Some(device.clone()),
            _ => None,
        };
        if let Some(t) = foldable {
            let total: usize = rungs.iter().map(|r| reads(r, &t)).sum();
            let written: usize = rungs.iter().filter(|r| writes(r, &t)).count();
            let reader = (i + 1..rungs.len()).find(|&j| reads(&rungs[j], &t) > 0);
            if let (1, 1, Some(j)) = (total, written, reader) {
                let inputs: Vec<String> = rungs[i]
                    .condition
                    .leaves()
                    .iter()
                    .filter_map(|(e, _)| e.read_device().map(String::from))
                    .collect();
                let untouched = (i + 1..j).all(|k| inputs.iter().all(|d| !writes(&rungs[k], d)))
                    && inputs.iter().all(|d| d != &t);
                if untouched {
                    let cond = rungs[i].condition.clone();
                    let folded = substitute(&rungs[j].condition, &t, &cond).normalised();
                    // Folding stacks one rung's logic into another; a fold
                    // that would nest too deep is not made.
                    if folded.depth() > MAX_NESTING {
                        i += 1;
                        continue;
                    }
                    rungs[j].condition = folded;
                    rungs.remove(i);
                    continue;
                }
            }
        }
        i += 1;
    }
    rungs
}

fn substitute(net: &Net, device: &str, with: &Net) -> Net {
    match net {
        Net::Leaf(Element::Contact { kind, device: d }, _) if d == device => match kind {
            ContactKind::Nc => negate(with),
            _ => with.clone(),
        },
        Net::Leaf(..) => net.clone(),
        Net::Series(v) => Net::Series(v.iter().map(|n| substitute(n, device, with)).collect()),
        Net::Parallel(v) => Net::Parallel(v.iter().map(|n| substitute(n, device, with)).collect()),
    }
}
