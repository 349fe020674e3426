//! Labels as IL is written: on an instruction's line (`done: RET`) or
//! alone on a line of their own, labelling the next instruction (IEC
//! 61131-3's grammar allows an empty instruction after a label; Beremiz
//! and OpenPLC Editor write `QuitFb:` on its own line). A label alone
//! before another label jumps to it (`a: JMP b`), one at the end of the
//! text is a `RET` (the end of the program or block), so every label
//! stays on the line of one instruction for the loader.

use std::collections::HashMap;

use super::{IlError, Line, Operand, Operator};
use crate::iec::is_identifier;

/// The labels read so far, and the one waiting for its instruction.
#[derive(Default)]
pub(super) struct Labels {
    /// Each label (upper-case) and the line it is first on.
    first: HashMap<String, usize>,
    waiting: Option<(String, usize)>,
}

/// `name:` alone: the label.
fn lone(code: &str) -> Option<&str> {
    let label = code.strip_suffix(':')?.trim();
    is_identifier(label).then_some(label)
}

/// An instruction line with no operand: `label: OPERATOR` at `line`.
fn bare(label: String, operator: Operator, operand: Option<Operand>, line: usize) -> Line {
    Line {
        label: Some(label),
        operator,
        negated: false,
        condition: None,
        deferred: false,
        operand,
        args: Vec::new(),
        inputs: Vec::new(),
        outputs: Vec::new(),
        line,
    }
}

impl Labels {
    /// Label `label` met at line `number`: refused when used before.
    fn define(&mut self, label: &str, number: usize) -> Result<(), IlError> {
        if let Some(&first) = self.first.get(&label.to_ascii_uppercase()) {
            return Err(IlError::DuplicateLabel {
                label: label.to_string(),
                first,
            });
        }
        self.first.insert(label.to_ascii_uppercase(), number);
        Ok(())
    }

    /// Takes `code` when it is a label alone (it waits for the next
    /// instruction); `Some` with its result, `None` when it is not one.
    pub fn alone(
        &mut self,
        code: &str,
        number: usize,
        lines: &mut Vec<Line>,
    ) -> Option<Result<(), IlError>> {
        let label = lone(code)?;
        if let Err(e) = self.define(label, number) {
            return Some(Err(e));
        }
        let next = Some(Operand::Name(label.to_string()));
        if let Some((before, at)) = self.waiting.replace((label.to_string(), number)) {
            lines.push(bare(before, Operator::Jmp, next, at));
        }
        Some(Ok(()))
    }

    /// Line `l` read: its own label checked, the waiting one put on it
    /// (or, when it has its own, jumping to it).
    pub fn place(&mut self, mut l: Line, lines: &mut Vec<Line>) -> Result<(), IlError> {
        if let Some(own) = &l.label {
            self.define(own, l.line)?;
        }
        if let Some((before, at)) = self.waiting.take() {
            match &l.label {
                Some(own) => {
                    let next = Some(Operand::Name(own.clone()));
                    lines.push(bare(before, Operator::Jmp, next, at));
                }
                None => l.label = Some(before),
            }
        }
        lines.push(l);
        Ok(())
    }

    /// The end of the text: a label still waiting labels a `RET`.
    pub fn finish(self, lines: &mut Vec<Line>) {
        if let Some((label, at)) = self.waiting {
            lines.push(bare(label, Operator::Ret, None, at));
        }
    }
}
