//! Reversible changes: what an edit did, step by step, and how to take it
//! back.

use super::Cursor;
use crate::ladder::grid::{Ladder, Rung};

/// One reversible step.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Step {
    /// Rung `index` went from `before` to `after`.
    Rung {
        /// The rung.
        index: usize,
        /// As it was.
        before: Rung,
        /// As it is.
        after: Rung,
    },
    /// A rung was inserted at `index`.
    Insert {
        /// Where.
        index: usize,
        /// The rung.
        rung: Rung,
    },
    /// The rung at `index` was removed.
    Remove {
        /// Where it was.
        index: usize,
        /// The rung.
        rung: Rung,
    },
    /// A device comment changed (`None`: no comment).
    DeviceComment {
        /// The device.
        device: String,
        /// As it was.
        before: Option<String>,
        /// As it is.
        after: Option<String>,
    },
    /// The whole ladder was replaced (a new ladder, a replace over every
    /// rung).
    Ladder {
        /// As it was.
        before: Box<Ladder>,
        /// As it is.
        after: Box<Ladder>,
    },
}

/// An edit's steps, with the cursor before and after it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Change {
    /// The steps, in the order they apply.
    pub steps: Vec<Step>,
    /// Where the cursor was.
    pub cursor_before: Cursor,
    /// Where the edit leaves it.
    pub cursor_after: Cursor,
}

impl Change {
    /// Applies the steps in order.
    pub fn redo(&self, ladder: &mut Ladder) {
        for step in &self.steps {
            apply(ladder, step, true);
        }
    }

    /// Takes the steps back, last first.
    pub fn undo(&self, ladder: &mut Ladder) {
        for step in self.steps.iter().rev() {
            apply(ladder, step, false);
        }
    }

    /// The rungs the change touches (by index after it), for repainting.
    pub fn touched_rungs(&self) -> Vec<usize> {
        let mut out: Vec<usize> = self
            .steps
            .iter()
            .filter_map(|s| match s {
                Step::Rung { index, .. }
                | Step::Insert { index, .. }
                | Step::Remove { index, .. } => Some(*index),
                _ => None,
            })
            .collect();
        crate::sort::all(&mut out);
        out.dedup();
        out
    }
}

fn apply(ladder: &mut Ladder, step: &Step, forward: bool) {
    match step {
        Step::Rung {
            index,
            before,
            after,
        } => {
            if let Some(r) = ladder.rungs.get_mut(*index) {
                *r = if forward { after } else { before }.clone();
            }
        }
        Step::Insert { index, rung } | Step::Remove { index, rung } => {
            let insert = matches!(step, Step::Insert { .. }) == forward;
            if insert {
                let at = (*index).min(ladder.rungs.len());
                ladder.rungs.insert(at, rung.clone());
            } else if *index < ladder.rungs.len() {
                ladder.rungs.remove(*index);
            }
        }
        Step::DeviceComment {
            device,
            before,
            after,
        } => {
            let value = if forward { after } else { before };
            match value {
                Some(text) => {
                    ladder.device_comments.insert(device.clone(), text.clone());
                }
                None => {
                    ladder.device_comments.remove(device);
                }
            }
        }
        Step::Ladder { before, after } => {
            *ladder = if forward { after } else { before }.as_ref().clone();
        }
    }
}
