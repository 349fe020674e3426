//! The ladder editor's model, with no view: a cursor on the grid, every
//! edit a command, an unbounded undo stack, and the clipboard's text form
//! (docs/editor.md). The page renders it and maps keys to [`Edit`]s; the
//! tests drive it natively.
//!
//! Every edit becomes a [`Change`]: a list of reversible steps on whole
//! rungs (replace, insert, remove), on device comments, or on the whole
//! ladder, with the cursor before and after. Undo applies the steps
//! backwards, so memory grows with what an edit touched, not with the
//! ladder's size.

mod align;
mod block_entry;
mod change;
mod clip;
mod command;
mod declare_as;
mod devices;
mod entry;
mod entry_error;
mod variables;

pub use align::align_outputs;
pub use block_entry::{box_operands, BoxOperand, OperandRole, BOX_USAGE};
pub use change::{Change, Step};
pub use clip::{Clip, ClipError, CLIP_HEADER};
pub use command::{Edit, EditError};
pub use declare_as::undeclared_in_box;
pub use devices::{
    complete, complete_declared, device_names, find, replace_plan, xref, Found, ReplaceError, Use,
    UseRole,
};
pub use entry::{parse_entry, EntryError, EntryKind};
pub use variables::{VariableEdit, VariableEditError};

use super::grid::{Ladder, Pos};

/// Columns a new rung offers: conditions in 0..=8, outputs in column 9.
pub const COLUMNS: usize = 10;
/// The most rows and columns a rung may have in the editor (a share link
/// holds the same).
pub const MAX_ROWS: usize = 64;
/// See [`MAX_ROWS`].
pub const MAX_COLUMNS: usize = 64;

/// A cell of the ladder: rung, row, column (all 0-based).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Cursor {
    /// The rung.
    pub rung: usize,
    /// The row within the rung.
    pub row: usize,
    /// The column.
    pub col: usize,
}

impl Cursor {
    /// The cell at `rung`, `row`, `col`.
    pub const fn new(rung: usize, row: usize, col: usize) -> Cursor {
        Cursor { rung, row, col }
    }

    /// The cell's place within its rung.
    pub const fn pos(self) -> Pos {
        Pos::new(self.row, self.col)
    }
}

/// A ladder being edited: the ladder, the cursor, the output column, and
/// the changes that can be undone and redone.
#[derive(Clone, Debug, Default)]
pub struct Editor {
    ladder: Ladder,
    cursor: Cursor,
    undo: Vec<Change>,
    redo: Vec<Change>,
    touched: Vec<usize>,
}

impl Editor {
    /// An editor on `ladder`, cursor at the first cell.
    pub fn new(ladder: Ladder) -> Editor {
        Editor {
            ladder,
            ..Editor::default()
        }
    }

    /// The ladder as it stands.
    pub fn ladder(&self) -> &Ladder {
        &self.ladder
    }

    /// The cursor.
    pub fn cursor(&self) -> Cursor {
        self.cursor
    }

    /// The column outputs stand in: the widest rung's last column, at
    /// least [`COLUMNS`] − 1.
    pub fn output_column(&self) -> usize {
        let widest = self
            .ladder
            .rungs
            .iter()
            .flat_map(|r| r.elements())
            .filter(|(_, e)| e.is_output())
            .map(|(p, _)| p.col)
            .max()
            .unwrap_or(0);
        widest.max(COLUMNS - 1)
    }

    /// Moves the cursor (clamped to the grid: the rungs there are, one
    /// past the last, and [`MAX_ROWS`] × [`MAX_COLUMNS`]).
    pub fn move_to(&mut self, to: Cursor) {
        self.cursor = self.clamp(to);
    }

    fn clamp(&self, c: Cursor) -> Cursor {
        Cursor {
            rung: c.rung.min(self.ladder.rungs.len()),
            row: c.row.min(MAX_ROWS - 1),
            col: c.col.min(self.output_column()),
        }
    }

    /// Applies an edit: on success it can be undone in one step, and the
    /// redo stack is dropped; on error nothing changed.
    pub fn apply(&mut self, edit: Edit) -> Result<(), EditError> {
        let change = command::plan(self, edit)?;
        change.redo(&mut self.ladder);
        self.cursor = self.clamp(change.cursor_after);
        self.touched = change.touched_rungs();
        self.undo.push(change);
        self.redo.clear();
        Ok(())
    }

    /// Undoes the last edit; false when there is none.
    pub fn undo(&mut self) -> bool {
        let Some(change) = self.undo.pop() else {
            return false;
        };
        change.undo(&mut self.ladder);
        self.cursor = change.cursor_before;
        self.touched = change.touched_rungs();
        self.redo.push(change);
        true
    }

    /// Redoes the last undone edit; false when there is none.
    pub fn redo(&mut self) -> bool {
        let Some(change) = self.redo.pop() else {
            return false;
        };
        change.redo(&mut self.ladder);
        self.cursor = self.clamp(change.cursor_after);
        self.touched = change.touched_rungs();
        self.undo.push(change);
        true
    }

    /// Whether there is an edit to undo / to redo.
    pub fn can_undo(&self) -> bool {
        !self.undo.is_empty()
    }

    /// See [`Editor::can_undo`].
    pub fn can_redo(&self) -> bool {
        !self.redo.is_empty()
    }

    /// The rungs the last applied, undone or redone change touched (by
    /// their index now), for a view that repaints only those.
    pub fn last_touched(&self) -> &[usize] {
        &self.touched
    }
}
