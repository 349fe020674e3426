//! The accumulator walk shared by MINASEC-U and the AVR PLC: `LD` starts
//! a condition, `AND` / `OR` grow it, each store is an output of the rung.

use super::{add_output, close_rung, contact, Part, StepError, StepWhy};
use crate::ladder::compile::negate;
use crate::ladder::element::{CoilKind, ContactKind, Element};
use crate::ladder::net::{Net, RungLogic};
use crate::limits::MAX_NESTING;

/// The accumulator walk shared by MINASEC-U and the AVR PLC (each
/// machine's decompiler, in its folder, drives it step by step).
#[derive(Default)]
pub(crate) struct Acc {
    /// The rungs read so far.
    pub(crate) rungs: Vec<RungLogic>,
    a: Option<Part>,
    outputs: Vec<Element>,
    /// An output holding the accumulator's value: (device, inverted).
    anchor: Option<(String, bool)>,
}

impl Acc {
    pub(crate) fn flush(&mut self) {
        close_rung(&mut self.rungs, self.a.take(), &mut self.outputs);
    }

    pub(crate) fn load(&mut self, n: Net) {
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
                    why: StepWhy::UsedAgain,
                });
            };
            self.flush();
            self.a = Some(Part::of(contact(d, inv)));
        }
        self.a.take().ok_or(StepError {
            step,
            why: StepWhy::NoLoad,
        })
    }

    pub(crate) fn and(&mut self, n: Net, step: usize) -> Result<(), StepError> {
        let a = self.current(step)?;
        self.a = Some(a.join(Part::of(n), true, step)?);
        Ok(())
    }

    pub(crate) fn or(&mut self, n: Net, step: usize) -> Result<(), StepError> {
        let a = self.current(step)?;
        self.a = Some(a.join(Part::of(n), false, step)?);
        Ok(())
    }

    pub(crate) fn output(
        &mut self,
        e: Element,
        holds: Option<(String, bool)>,
        step: usize,
    ) -> Result<(), StepError> {
        let open = self.a.is_some();
        add_output(open, &mut self.outputs, &mut self.anchor, e, holds, step)
    }
}

/// Folds a temporary stored by one rung and read once by a later one back
/// into the reader, when nothing in between changes what it was made of.
pub(crate) fn fold_temporaries(mut rungs: Vec<RungLogic>, temps: &[&str]) -> Vec<RungLogic> {
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
