//! What version 3 links add for the soft PLC (issue #30): its boxes
//! (cells 24 and 25: kind, instance, inputs, outputs) and the ladder's
//! variables after the test cases. A link that has neither stays a
//! version 1 or 2 link, which older Hashigos open.

use super::{put_len, put_str, Reader, ShareError};
use crate::ladder::block::BlockCall;
use crate::ladder::variables::Variable;
use crate::ladder::{Element, Ladder};
use crate::limits::MAX_MAP_ENTRIES;

/// The cell tag of an in-line box; the next is an output box.
pub(super) const BLOCK: u8 = 24;

/// The cell tag of a box's input wired as a network.
pub(super) const BOX_INPUT: u8 = 26;

/// Most pins a box may list in a link.
const MAX_PINS: usize = 64;

/// Whether the ladder needs a version 3 link.
pub(super) fn needed(ladder: &Ladder) -> bool {
    !ladder.variables.is_empty()
        || ladder.rungs.iter().any(|r| {
            r.elements()
                .any(|(_, e)| e.block().is_some() || matches!(e, Element::BoxInput { .. }))
        })
}

/// A box after its tag.
pub(super) fn put_block(w: &mut Vec<u8>, b: &BlockCall) {
    put_str(w, &b.kind);
    put_str(w, &b.instance);
    for pins in [&b.inputs, &b.outputs] {
        put_len(w, pins.len());
        for (pin, operand) in pins {
            put_str(w, pin);
            put_str(w, operand);
        }
    }
}

/// The variables (after the test cases).
pub(super) fn put_variables(w: &mut Vec<u8>, vars: &[Variable]) {
    put_len(w, vars.len());
    for v in vars {
        for text in [&v.name, &v.data_type, &v.address, &v.initial, &v.comment] {
            put_str(w, text);
        }
        w.push(u8::from(v.retain));
    }
}

impl Reader<'_> {
    /// A box after its tag `tag`.
    pub(super) fn block(&mut self, tag: u8) -> Result<Element, ShareError> {
        let kind = self.string()?;
        let instance = self.string()?;
        let mut pins = [Vec::new(), Vec::new()];
        for list in &mut pins {
            let n = self.count("pins of one box", MAX_PINS)?;
            for _ in 0..n {
                list.push((self.string()?, self.string()?));
            }
        }
        let [inputs, outputs] = pins;
        let call = BlockCall {
            kind,
            instance,
            inputs,
            outputs,
        };
        Ok(if tag == BLOCK {
            Element::Block(call)
        } else {
            Element::OutputBlock(call)
        })
    }

    /// The variables.
    pub(super) fn variables(&mut self) -> Result<Vec<Variable>, ShareError> {
        let n = self.count("variables", MAX_MAP_ENTRIES)?;
        let mut vars = Vec::with_capacity(n);
        for _ in 0..n {
            let mut v = Variable::new(&self.string()?, &self.string()?);
            v.address = self.string()?;
            v.initial = self.string()?;
            v.comment = self.string()?;
            v.retain = match self.byte()? {
                0 => false,
                1 => true,
                _ => return Err(self.bad("a retain flag is neither 0 nor 1")),
            };
            vars.push(v);
        }
        Ok(vars)
    }
}
