//! Ladder diagrams: the model the editor draws, its logic, the reference
//! evaluator, and the compilers to each machine and back (docs/ladder.md);
//! the files that hold a ladder are `crate::formats`.
//!
//! - [`element`], [`grid`]: cells, rungs, links, device comments;
//! - [`block`]: the soft PLC's functions and blocks as boxes in a rung;
//! - [`net`]: a rung's series-parallel logic read off the grid, and back;
//! - [`target`]: what each machine offers (palette and validation);
//! - [`eval`]: power flow by the book, per element;
//! - [`compile`], [`decompile`]: to and from each machine's mnemonic text;
//! - [`live`]: each element's power in the last scan, from the machine's trace.

pub mod block;
pub mod compile;
pub mod decompile;
pub mod edit;
pub mod element;
pub mod eval;
pub mod grid;
mod lack;
pub mod live;
pub mod machine_target;
pub mod net;
pub mod problem;
pub mod target;
pub mod user_blocks;
pub mod variables;
pub mod why;

pub use block::BlockCall;
pub use element::{CoilKind, ContactKind, Element, TimerKind};
pub use grid::{Ladder, LadderError, LadderErrorKind, Link, Pos, Rung};
pub use net::{analyse, layout, try_layout, Net, NetError, RungLogic};
pub use variables::Variable;

use crate::MachineId;

impl Ladder {
    /// Every rung's logic, checked against `machine`'s capability table
    /// with device names in the machine's spelling. Empty rungs are
    /// skipped; every problem found is returned, each at its rung and cell.
    pub fn logic(&self, machine: MachineId) -> Result<Vec<RungLogic>, Vec<LadderError>> {
        let mut errors = Vec::new();
        let mut out = Vec::new();
        for (i, rung) in self.rungs.iter().enumerate() {
            match analyse(rung, i) {
                Ok(Some(mut logic)) => match check_logic(&mut logic, machine, i) {
                    Ok(()) => out.push(logic),
                    Err(e) => errors.extend(e),
                },
                Ok(None) => {}
                Err(e) => errors.extend(e),
            }
        }
        if errors.is_empty() {
            Ok(out)
        } else {
            Err(errors)
        }
    }

    /// The ladder index of each rung [`Ladder::logic`] returns (the
    /// non-empty ones), in order.
    pub fn logic_indices(&self) -> Vec<usize> {
        (0..self.rungs.len())
            .filter(|&i| !self.rungs[i].is_empty())
            .collect()
    }

    /// A ladder of one rung per logic, drawn by [`layout`].
    pub fn from_logic(rungs: &[RungLogic]) -> Ladder {
        Ladder {
            rungs: rungs.iter().map(layout).collect(),
            ..Ladder::default()
        }
    }
}

fn check_logic(
    logic: &mut RungLogic,
    machine: MachineId,
    index: usize,
) -> Result<(), Vec<LadderError>> {
    let mut errors = Vec::new();
    let mut fix = |e: &mut Element, pos: Pos| match target::check_element(machine, e) {
        Ok(canonical) => *e = canonical,
        Err(m) => errors.push(LadderError::refused(index, pos, m)),
    };
    visit_leaves(&mut logic.condition, &mut fix);
    for side in &mut logic.sides {
        visit_leaves(&mut side.net, &mut fix);
    }
    for (e, p) in &mut logic.outputs {
        fix(e, *p);
    }
    if errors.is_empty() {
        Ok(())
    } else {
        Err(errors)
    }
}

fn visit_leaves(net: &mut Net, f: &mut impl FnMut(&mut Element, Pos)) {
    match net {
        Net::Leaf(e, p) => f(e, *p),
        Net::Series(v) | Net::Parallel(v) => v.iter_mut().for_each(|n| visit_leaves(n, f)),
    }
}
