//! The block-stack walk shared by IO86A and the Arduino sketch: `LD`
//! opens a block, `ORB` / `ANB` join the top two, outputs close the rung.

use super::{add_output, close_rung, contact, Part, StepError, StepWhy};
use crate::ladder::element::Element;
use crate::ladder::net::{Net, RungLogic};

/// The block-stack walk shared by IO86A, the Arduino sketch and the soft
/// PLC's IL (each machine's decompiler drives it step by step).
#[derive(Default)]
pub(crate) struct Stack {
    pub(crate) rungs: Vec<RungLogic>,
    pub(crate) blocks: Vec<Part>,
    pub(crate) cur: Option<Part>,
    outputs: Vec<Element>,
    anchor: Option<String>,
}

impl Stack {
    /// Whether the open rung has a soft PLC box and no output yet: closed
    /// now, the box would be lost (a ladder draws no rung without one).
    pub(crate) fn boxes_without_output(&self) -> bool {
        self.outputs.is_empty()
            && self.cur.iter().chain(&self.blocks).any(|p| {
                p.net
                    .leaves()
                    .iter()
                    .any(|(e, _)| matches!(e, Element::Block(_)))
            })
    }

    pub(crate) fn flush(&mut self) {
        close_rung(&mut self.rungs, self.cur.take(), &mut self.outputs);
        self.blocks.clear();
        self.anchor = None;
    }

    pub(crate) fn load(&mut self, n: Net) {
        if !self.outputs.is_empty() {
            self.flush();
        } else if let Some(c) = self.cur.take() {
            self.blocks.push(c);
        }
        self.cur = Some(Part::of(n));
    }

    pub(crate) fn grow(&mut self, n: Net, and: bool, step: usize) -> Result<(), StepError> {
        if !self.outputs.is_empty() {
            let Some(d) = self.anchor.clone() else {
                return Err(StepError {
                    step,
                    why: StepWhy::AfterOutputs,
                });
            };
            self.flush();
            self.cur = Some(Part::of(contact(d, false)));
        }
        let cur = self.cur.take().ok_or(StepError {
            step,
            why: StepWhy::NoLoad,
        })?;
        self.cur = Some(cur.join(Part::of(n), and, step)?);
        Ok(())
    }

    pub(crate) fn join(&mut self, and: bool, step: usize) -> Result<(), StepError> {
        let (Some(a), Some(b)) = (self.blocks.pop(), self.cur.take()) else {
            return Err(StepError {
                step,
                why: StepWhy::TwoBlocks,
            });
        };
        self.cur = Some(a.join(b, and, step)?);
        Ok(())
    }

    pub(crate) fn output(
        &mut self,
        e: Element,
        holds: Option<String>,
        step: usize,
    ) -> Result<(), StepError> {
        let open = self.cur.is_some();
        add_output(open, &mut self.outputs, &mut self.anchor, e, holds, step)
    }
}
