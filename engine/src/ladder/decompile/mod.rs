//! Programs back to ladders: each machine's mnemonic text read as rungs.
//!
//! Accumulator machines (MINASEC-U, AVR PLC): `LD` starts a condition,
//! `AND` / `OR` grow it, each store is an output of the rung. When the
//! program goes on from a stored result (`ST Y00` then `ANDI T1`), the
//! next rung starts from a contact on that output, which holds the same
//! value. A temporary relay (M10-M13 on MINASEC-U) stored once and read
//! once later is folded back into the rung that reads it; other relays
//! stay visible as rungs of their own.
//!
//! Block-stack machines (IO86A, Arduino sketch): `LD` opens a block, `ORB`
//! / `ANB` join the top two, outputs close the rung.
//!
//! The walks are here; each machine's decompiler (`decompile.rs` in its
//! folder) reads its own program with them, and its ladder target hands
//! [`decompile_text`] the result. The soft PLC's IL (an IEC text) is read
//! here ([`il_ladder`]).

use std::fmt;

pub(crate) mod accumulator;
mod il;
pub(crate) mod stack;
mod step_why;

pub use step_why::StepWhy;

use super::element::{ContactKind, Element};
use super::grid::{Ladder, Pos};
use super::net::{attach_sides, try_layout, Net, RungLogic, TooLarge};
use crate::limits::MAX_NESTING;
use crate::MachineId;

/// Why a program has no ladder form, at its step (0-based, as listed).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StepError {
    /// The step.
    pub step: usize,
    /// Why it cannot be drawn.
    pub why: StepWhy,
}

impl fmt::Display for StepError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "step {}: {}", self.step, self.why)
    }
}

impl std::error::Error for StepError {}

/// Why a program could not be decompiled.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum DecompileError {
    /// A step has no ladder form.
    Step(StepError),
    /// A rung (1-based) is too large to draw (docs/limits.md).
    Drawing {
        /// The rung, 1-based.
        rung: usize,
        /// How large it would be.
        size: TooLarge,
    },
}

impl From<StepError> for DecompileError {
    fn from(e: StepError) -> Self {
        DecompileError::Step(e)
    }
}

impl fmt::Display for DecompileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DecompileError::Step(e) => e.fmt(f),
            DecompileError::Drawing { rung, size } => write!(f, "rung {rung}: {size}"),
        }
    }
}

impl std::error::Error for DecompileError {}

/// The rungs drawn on grids, each refused past the rung size limit.
pub(crate) fn drawn(rungs: &[RungLogic]) -> Result<Ladder, DecompileError> {
    let mut ladder = Ladder::default();
    // The soft PLC's box input networks, compiled as rungs of their own
    // on their carriers, drawn under their boxes again.
    let mut rungs = rungs.to_vec();
    let joined = attach_sides(&mut rungs);
    for (i, logic) in rungs.iter().enumerate() {
        if joined.contains(&i) {
            continue;
        }
        let rung =
            try_layout(logic).map_err(|size| DecompileError::Drawing { rung: i + 1, size })?;
        ladder.rungs.push(rung);
    }
    Ok(ladder)
}

/// Why a program text could not become a ladder.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TextError {
    /// The text is no program for the machine (problems at their lines).
    Program(Vec<crate::Located<crate::plc::ProgramProblem>>),
    /// The program has no ladder form.
    Decompile(DecompileError),
}

impl fmt::Display for TextError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TextError::Program(problems) => crate::error::write_joined(f, problems),
            TextError::Decompile(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for TextError {}

/// A program in `machine`'s own text (the AVR's with `Scan` = `scan_ms`)
/// as a ladder: the machine's target reads and decompiles it.
pub fn decompile_text(machine: MachineId, text: &str, scan_ms: u32) -> Result<Ladder, TextError> {
    let options = crate::ladder::compile::Options {
        avr_scan_ms: scan_ms,
    };
    machine.compiler().decompile_text(text, options)
}

/// The soft PLC's IL (its declarations and lines) as a ladder with its
/// declared variables.
pub fn il_ladder(p: &dyn crate::iec::il::IlSource) -> Result<Ladder, DecompileError> {
    let (vars, lines) = p.source();
    let mut ladder = il::il_ladder(vars, lines)?;
    ladder.variables = il::declared(vars);
    Ok(ladder)
}

pub(crate) fn contact(device: String, inverted: bool) -> Net {
    let kind = if inverted {
        ContactKind::Nc
    } else {
        ContactKind::No
    };
    Net::Leaf(Element::Contact { kind, device }, Pos::new(0, 0))
}

/// A condition being built, with how deeply it nests, so that a program
/// that nests blocks past [`MAX_NESTING`] is refused at the step that
/// would (and no deeper network is ever built).
pub(crate) struct Part {
    net: Net,
    depth: usize,
}

impl Part {
    pub(crate) fn of(net: Net) -> Part {
        let depth = net.depth();
        Part { net, depth }
    }

    /// `self` and `b` in series (`and`) or in parallel.
    pub(crate) fn join(self, b: Part, and: bool, step: usize) -> Result<Part, StepError> {
        let merges = |p: &Part| match p.net {
            Net::Series(_) => and,
            Net::Parallel(_) => !and,
            Net::Leaf(..) => false,
        };
        let level = |p: &Part| if merges(p) { p.depth } else { p.depth + 1 };
        let depth = level(&self).max(level(&b));
        if depth > MAX_NESTING {
            return Err(StepError {
                step,
                why: StepWhy::TooDeep,
            });
        }
        let net = if and {
            Net::series(self.net, b.net)
        } else {
            Net::parallel(self.net, b.net)
        };
        Ok(Part { net, depth })
    }
}

/// Ends a rung: its condition drives the outputs collected (a condition
/// with no output drives nothing and is dropped, as the machine ignores it).
pub(crate) fn close_rung(
    rungs: &mut Vec<RungLogic>,
    condition: Option<Part>,
    outputs: &mut Vec<Element>,
) {
    if let Some(Part { net: condition, .. }) = condition {
        if !outputs.is_empty() {
            rungs.push(RungLogic {
                condition,
                outputs: outputs.drain(..).map(|e| (e, Pos::new(0, 0))).collect(),
                comment: String::new(),
                sides: Vec::new(),
            });
        }
    }
    outputs.clear();
}

/// Adds an output to the open rung; the first output that holds the
/// rung's result becomes the anchor a continuation starts from.
pub(crate) fn add_output<T>(
    open: bool,
    outputs: &mut Vec<Element>,
    anchor: &mut Option<T>,
    e: Element,
    holds: Option<T>,
    step: usize,
) -> Result<(), StepError> {
    if !open {
        return Err(StepError {
            step,
            why: StepWhy::OutputFirst,
        });
    }
    if anchor.is_none() {
        *anchor = holds;
    }
    outputs.push(e);
    Ok(())
}
#[cfg(test)]
mod tests_english;
