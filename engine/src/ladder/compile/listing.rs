//! A compiled program together with where each rung's steps are, so the
//! editor can number rungs by their first step (as GX Works does) and
//! highlight a rung's steps in the listing.

use std::ops::Range;

use super::Options;
use crate::ladder::grid::{Ladder, LadderError};
use crate::MachineId;

/// A compiled ladder: the program text and its steps by rung.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Listing {
    /// The program in the machine's own format.
    pub text: String,
    /// For each rung that compiled to steps: its index in the ladder and
    /// its first step, in order.
    pub rungs: Vec<RungStart>,
    /// The 0-based text line of each step, in step order.
    pub step_lines: Vec<usize>,
    /// Where each leaf (contact or in-line box) is computed: the first
    /// line of the listing that reads its device or computes its output.
    pub sources: Vec<LeafSource>,
    /// Steps the rungs produced (the rest is the machine's end marker).
    rung_steps: usize,
}

/// A leaf's place in the listing: the compiler's source map, so the
/// editor can point from an element to its step and back.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LeafSource {
    /// The rung's index in the ladder.
    pub rung: usize,
    /// The leaf's cell.
    pub pos: crate::ladder::grid::Pos,
    /// The 0-based text line of the op reading its device (a contact; an
    /// edge contact's computed relay) or computing its output (a box).
    pub line: usize,
}

/// Where a rung's steps begin.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RungStart {
    /// The rung's index in the ladder (0-based).
    pub rung: usize,
    /// Its first step (0-based).
    pub first_step: usize,
}

impl Listing {
    /// The steps of ladder rung `rung` (none for an empty rung).
    pub fn steps_of(&self, rung: usize) -> Option<Range<usize>> {
        let i = self.rungs.iter().position(|r| r.rung == rung)?;
        let end = self
            .rungs
            .get(i + 1)
            .map_or(self.rung_steps, |next| next.first_step);
        Some(self.rungs[i].first_step..end)
    }

    /// The ladder rung step `step` came from (none for the end marker).
    pub fn rung_of_step(&self, step: usize) -> Option<usize> {
        if step >= self.rung_steps {
            return None;
        }
        let i = self.rungs.partition_point(|r| r.first_step <= step);
        self.rungs.get(i.checked_sub(1)?).map(|r| r.rung)
    }

    /// The step that reads (or computes) the leaf at `pos` of `rung`.
    pub fn step_of_leaf(&self, rung: usize, pos: crate::ladder::grid::Pos) -> Option<usize> {
        let s = self
            .sources
            .iter()
            .find(|s| s.rung == rung && s.pos == pos)?;
        self.step_at_line(s.line)
    }

    /// The step on 0-based text line `line`, if that line is a step.
    pub fn step_at_line(&self, line: usize) -> Option<usize> {
        self.step_lines.binary_search(&line).ok()
    }
}

/// Compiles `ladder` for `machine` like [`super::compile`], keeping where
/// each rung's steps are.
pub fn compile_listing(
    ladder: &Ladder,
    machine: MachineId,
    options: Options,
) -> Result<Listing, Vec<LadderError>> {
    let logic = ladder.logic(machine)?;
    let indices = ladder.logic_indices();
    let target = machine.compiler();
    let mapped = target.compile(&logic, &ladder.variables, options)?;
    let mut sources: Vec<LeafSource> = Vec::new();
    for &(i, pos, line) in &mapped.sources {
        let rung = indices[i];
        // The first op that reads a leaf is its place in the listing (the
        // Arduino sketch may compute a rung's condition again).
        if !sources.iter().any(|s| s.rung == rung && s.pos == pos) {
            sources.push(LeafSource { rung, pos, line });
        }
    }
    let (text, starts) = (mapped.text, mapped.starts);
    // The soft PLC's steps follow its declarations.
    let code = target.code_start(&text);
    let step_lines: Vec<usize> = text
        .lines()
        .enumerate()
        .skip(code)
        .filter(|(_, l)| target.is_step(l))
        .map(|(i, _)| i)
        .collect();
    // Most machines end their program with one end marker.
    let trailer = target.end_steps();
    Ok(Listing {
        rung_steps: step_lines.len().saturating_sub(trailer),
        sources,
        rungs: indices
            .into_iter()
            .zip(starts)
            .map(|(rung, first_step)| RungStart { rung, first_step })
            .collect(),
        step_lines,
        text,
    })
}
