//! The edits, and how each becomes a [`Change`] before anything changes.

use std::fmt;

use super::change::{Change, Step};
use super::clip::{Clip, ClipError};
use super::{Cursor, Editor, MAX_COLUMNS, MAX_ROWS};
use crate::ladder::element::Element;
use crate::ladder::grid::{Ladder, Link, Pos, Rung};

/// One edit, as the keys and the palette ask for it (docs/editor.md).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Edit {
    /// F5 / F6 / F8 and the palette: a contact or in-line box at the
    /// cell (the cursor then moves one right); an output goes to the
    /// output column of the cell's row, with wire filled into the empty
    /// cells between (F7).
    Place {
        /// The cell.
        at: Cursor,
        /// What to put there.
        element: Element,
    },
    /// Shift+F5 / Shift+F6: a contact at row ≥ 1 in parallel with the
    /// cell above (links at the left edge of its column, unless that is
    /// the rail, and at the left edge of the next).
    PlaceBranch {
        /// The cell.
        at: Cursor,
        /// The contact.
        element: Element,
    },
    /// F9: a horizontal wire in the cell.
    Wire {
        /// The cell.
        at: Cursor,
    },
    /// Shift+F9: the vertical link at the cell's left edge, down to the
    /// next row, on or off.
    ToggleLink {
        /// The cell.
        at: Cursor,
    },
    /// Ctrl+F9: removes the horizontal wire in the cell.
    DeleteWire {
        /// The cell.
        at: Cursor,
    },
    /// Ctrl+F10: removes the vertical link at the cell's left edge.
    DeleteLink {
        /// The cell.
        at: Cursor,
    },
    /// Delete: empties the cell.
    Clear {
        /// The cell.
        at: Cursor,
    },
    /// Empties a block of cells of one rung (corners in any order).
    ClearBlock {
        /// One corner.
        from: Cursor,
        /// The opposite corner (same rung).
        to: Cursor,
    },
    /// Insert / Shift+Insert: an empty rung at `index`.
    InsertRung {
        /// Where it goes (0..=rungs).
        index: usize,
    },
    /// Ctrl+Delete, or whole rungs selected: removes rungs
    /// `first..=last`.
    DeleteRungs {
        /// The first.
        first: usize,
        /// The last.
        last: usize,
    },
    /// Alt+Up / Alt+Down: swaps a rung with the one above or below.
    MoveRung {
        /// The rung.
        index: usize,
        /// Up (else down).
        up: bool,
    },
    /// The comment above a rung.
    RungComment {
        /// The rung.
        index: usize,
        /// The text (empty: none).
        text: String,
    },
    /// A device's comment (empty: none).
    DeviceComment {
        /// The device, in the machine's spelling.
        device: String,
        /// The text.
        text: String,
    },
    /// Ctrl+V: a clip of cells at the cell (its top-left there), or a
    /// clip of rungs before the cell's rung.
    Paste {
        /// Where.
        at: Cursor,
        /// What.
        clip: Clip,
    },
    /// Batch replace: every use of the device or range `from` becomes
    /// `to` (`X00`→`X03`, `M00-M07`→`M20-M27`), see [`super::replace_plan`].
    ReplaceDevices {
        /// What to replace.
        from: String,
        /// With what.
        to: String,
    },
    /// The variables pane's edits of the soft PLC's declarations: declare
    /// or change one, remove one, rename one in every cell that uses it;
    /// refused where a use would no longer fit.
    Variable(super::variables::VariableEdit),
    /// An empty ladder (the old one comes back with undo).
    NewLadder,
    /// Another whole ladder: text loaded as a ladder, an example, a
    /// ladder brought from another machine (the old one comes back with
    /// undo).
    Replace {
        /// The new ladder.
        ladder: Ladder,
    },
}

/// Why an edit was refused; nothing changed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum EditError {
    /// A rung that does not exist (nor is the one after the last).
    NoSuchRung(usize),
    /// A cell beyond [`MAX_ROWS`] × [`MAX_COLUMNS`].
    OutsideGrid(Cursor),
    /// An OR branch asked for on a rung's top row.
    BranchOnTopRow,
    /// An OR branch of something other than a contact.
    BranchNotContact,
    /// A wire or link to delete where there is none, a cell already
    /// empty, a rung that cannot move further: the edit would change
    /// nothing.
    NothingToDo,
    /// A block that spans rungs.
    BlockAcrossRungs,
    /// A clip that does not paste.
    Clip(ClipError),
    /// A replace that does not apply (the reason).
    Replace(super::devices::ReplaceError),
    /// A variables pane's edit that does not apply (the reason).
    Variable(super::variables::VariableEditError),
}

impl fmt::Display for EditError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            EditError::NoSuchRung(r) => write!(f, "there is no rung {}", r + 1),
            EditError::OutsideGrid(c) => write!(
                f,
                "row {}, column {} is outside the grid: a rung has at most {MAX_ROWS} rows and {MAX_COLUMNS} columns",
                c.row + 1,
                c.col + 1
            ),
            EditError::BranchOnTopRow => {
                f.write_str("an OR branch goes below another row: move the cursor down first")
            }
            EditError::BranchNotContact => f.write_str("only a contact can be an OR branch"),
            EditError::NothingToDo => f.write_str("nothing to change here"),
            EditError::BlockAcrossRungs => {
                f.write_str("a block of cells lies within one rung: select whole rungs instead")
            }
            EditError::Clip(e) => e.fmt(f),
            EditError::Replace(why) => why.fmt(f),
            EditError::Variable(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for EditError {}

/// A change being planned: the steps so far, on a scratch copy of the
/// rungs it touches.
pub(super) struct Plan<'a> {
    /// The ladder before the edit.
    pub(super) ladder: &'a Ladder,
    /// The steps so far.
    pub(super) steps: Vec<Step>,
    /// Rungs appended so far (a cell one past the last rung creates it).
    appended: Vec<Rung>,
}

impl<'a> Plan<'a> {
    fn new(ladder: &'a Ladder) -> Plan<'a> {
        Plan {
            ladder,
            steps: Vec::new(),
            appended: Vec::new(),
        }
    }

    /// The rung at `index` as the plan has it, to change; `index` may be
    /// one past the last rung, which creates it.
    pub(super) fn rung(&mut self, index: usize) -> Result<Rung, EditError> {
        let len = self.ladder.rungs.len();
        match index.cmp(&len) {
            std::cmp::Ordering::Less => Ok(self.ladder.rungs[index].clone()),
            std::cmp::Ordering::Equal => {
                self.steps.push(Step::Insert {
                    index,
                    rung: Rung::default(),
                });
                self.appended.push(Rung::default());
                Ok(Rung::default())
            }
            std::cmp::Ordering::Greater => Err(EditError::NoSuchRung(index)),
        }
    }

    /// Records rung `index` becoming `after` (if it changed).
    pub(super) fn set(&mut self, index: usize, after: Rung) -> Result<(), EditError> {
        let before = self.ladder.rungs.get(index).cloned().unwrap_or_default();
        if before == after && self.appended.is_empty() {
            return Err(EditError::NothingToDo);
        }
        self.steps.push(Step::Rung {
            index,
            before,
            after,
        });
        Ok(())
    }

    fn done(self, before: Cursor, after: Cursor) -> Result<Change, EditError> {
        if self.steps.is_empty() {
            return Err(EditError::NothingToDo);
        }
        Ok(Change {
            steps: self.steps,
            cursor_before: before,
            cursor_after: after,
        })
    }
}

fn inside(at: Cursor) -> Result<Pos, EditError> {
    if at.row >= MAX_ROWS || at.col >= MAX_COLUMNS {
        return Err(EditError::OutsideGrid(at));
    }
    Ok(at.pos())
}

/// The change `edit` would make to the editor's ladder; nothing changes
/// here.
pub(super) fn plan(editor: &Editor, edit: Edit) -> Result<Change, EditError> {
    let ladder = editor.ladder();
    let cursor = editor.cursor();
    let out_col = editor.output_column();
    let mut plan = Plan::new(ladder);
    let after = match edit {
        Edit::Place { at, element } => place(&mut plan, at, element, out_col)?,
        Edit::PlaceBranch { at, element } => {
            let pos = inside(at)?;
            if at.row == 0 {
                return Err(EditError::BranchOnTopRow);
            }
            if !matches!(element, Element::Contact { .. }) {
                return Err(EditError::BranchNotContact);
            }
            let mut rung = plan.rung(at.rung)?;
            rung.set(pos, Some(element));
            let mut add = |col: usize| {
                let link = Link {
                    row: at.row - 1,
                    col,
                };
                if !rung.links.contains(&link) {
                    rung.links.push(link);
                }
            };
            if at.col > 0 {
                add(at.col);
            }
            add(at.col + 1);
            crate::sort::all(&mut rung.links);
            plan.set(at.rung, rung)?;
            Cursor {
                col: at.col + 1,
                ..at
            }
        }
        Edit::Wire { at } => {
            let pos = inside(at)?;
            let mut rung = plan.rung(at.rung)?;
            rung.set(pos, Some(Element::Wire));
            plan.set(at.rung, rung)?;
            Cursor {
                col: at.col + 1,
                ..at
            }
        }
        Edit::ToggleLink { at } | Edit::DeleteLink { at } => {
            let delete_only = matches!(edit, Edit::DeleteLink { .. });
            inside(Cursor {
                row: at.row + 1,
                ..at
            })?;
            let mut rung = plan.rung(at.rung)?;
            let link = Link {
                row: at.row,
                col: at.col,
            };
            if let Some(i) = rung.links.iter().position(|l| *l == link) {
                rung.links.remove(i);
            } else if delete_only {
                return Err(EditError::NothingToDo);
            } else {
                rung.links.push(link);
                crate::sort::all(&mut rung.links);
            }
            plan.set(at.rung, rung)?;
            at
        }
        Edit::DeleteWire { at } => {
            let pos = inside(at)?;
            let mut rung = plan.rung(at.rung)?;
            if rung.get(pos) != Some(&Element::Wire) {
                return Err(EditError::NothingToDo);
            }
            rung.set(pos, None);
            rung.remove_stubs_around(pos);
            plan.set(at.rung, rung)?;
            at
        }
        Edit::Clear { at } => {
            let pos = inside(at)?;
            let mut rung = plan.rung(at.rung)?;
            if rung.get(pos).is_none() {
                return Err(EditError::NothingToDo);
            }
            rung.set(pos, None);
            rung.remove_stubs_around(pos);
            plan.set(at.rung, rung)?;
            at
        }
        Edit::ClearBlock { from, to } => {
            if from.rung != to.rung {
                return Err(EditError::BlockAcrossRungs);
            }
            let mut rung = plan.rung(from.rung)?;
            for row in from.row.min(to.row)..=from.row.max(to.row) {
                for col in from.col.min(to.col)..=from.col.max(to.col) {
                    if rung.get(Pos::new(row, col)).is_some() {
                        rung.set(Pos::new(row, col), None);
                        rung.remove_stubs_around(Pos::new(row, col));
                    }
                }
            }
            plan.set(from.rung, rung)?;
            Cursor::new(from.rung, from.row.min(to.row), from.col.min(to.col))
        }
        Edit::InsertRung { index } => {
            if index > ladder.rungs.len() {
                return Err(EditError::NoSuchRung(index));
            }
            plan.steps.push(Step::Insert {
                index,
                rung: Rung::default(),
            });
            Cursor::new(index, 0, 0)
        }
        Edit::DeleteRungs { first, last } => {
            let (first, last) = (first.min(last), first.max(last));
            if last >= ladder.rungs.len() {
                return Err(EditError::NoSuchRung(last));
            }
            // From the last down, so each index is right when applied.
            for index in (first..=last).rev() {
                plan.steps.push(Step::Remove {
                    index,
                    rung: ladder.rungs[index].clone(),
                });
            }
            Cursor::new(first, 0, 0)
        }
        Edit::MoveRung { index, up } => {
            let other = if up {
                index.checked_sub(1)
            } else {
                index.checked_add(1)
            };
            let Some(other) = other.filter(|&o| o < ladder.rungs.len()) else {
                return Err(EditError::NothingToDo);
            };
            if index >= ladder.rungs.len() {
                return Err(EditError::NoSuchRung(index));
            }
            let (a, b) = (ladder.rungs[index].clone(), ladder.rungs[other].clone());
            plan.set(index, b)?;
            plan.steps.push(Step::Rung {
                index: other,
                before: ladder.rungs[other].clone(),
                after: a,
            });
            Cursor {
                rung: other,
                ..cursor
            }
        }
        Edit::RungComment { index, text } => {
            let mut rung = plan.rung(index)?;
            rung.comment = text;
            plan.set(index, rung)?;
            Cursor::new(index, 0, 0)
        }
        Edit::DeviceComment { device, text } => {
            let before = ladder.device_comments.get(&device).cloned();
            let after = (!text.is_empty()).then_some(text);
            if before == after {
                return Err(EditError::NothingToDo);
            }
            plan.steps.push(Step::DeviceComment {
                device,
                before,
                after,
            });
            cursor
        }
        Edit::Paste { at, clip } => clip.paste(&mut plan, at)?,
        Edit::ReplaceDevices { from, to } => {
            let uses = super::replace_plan(ladder, &from, &to).map_err(EditError::Replace)?;
            if uses.is_empty() {
                return Err(EditError::NothingToDo);
            }
            let mut rungs: Vec<usize> = uses.iter().map(|u| u.0).collect();
            rungs.dedup();
            for index in rungs {
                let mut rung = ladder.rungs[index].clone();
                for (_, pos, _, new) in uses.iter().filter(|u| u.0 == index) {
                    if let Some(Some(e)) =
                        rung.cells.get_mut(pos.row).and_then(|r| r.get_mut(pos.col))
                    {
                        *e = new.clone();
                    }
                }
                plan.set(index, rung)?;
            }
            cursor
        }
        Edit::Variable(change) => {
            let new = super::variables::planned(ladder, change).map_err(EditError::Variable)?;
            replace_all(&mut plan, ladder, new)?
        }
        Edit::NewLadder => replace_all(&mut plan, ladder, Ladder::default())?,
        Edit::Replace { ladder: new } => replace_all(&mut plan, ladder, new)?,
    };
    plan.done(cursor, after)
}

/// A place edit: contacts and boxes at the cell, outputs in the output
/// column with wire filled in.
fn place(
    plan: &mut Plan,
    at: Cursor,
    element: Element,
    out_col: usize,
) -> Result<Cursor, EditError> {
    let pos = inside(at)?;
    let mut rung = plan.rung(at.rung)?;
    if !element.is_output() {
        rung.set(pos, Some(element));
        plan.set(at.rung, rung)?;
        return Ok(Cursor {
            col: at.col + 1,
            ..at
        });
    }
    let out = inside(Cursor { col: out_col, ..at })?;
    for col in at.col.min(out_col)..out_col {
        if rung.get(Pos::new(at.row, col)).is_none() {
            rung.set(Pos::new(at.row, col), Some(Element::Wire));
        }
    }
    rung.set(out, Some(element));
    plan.set(at.rung, rung)?;
    // After an output on the top row the next rung starts (created when
    // there is none); on a lower row, the next row.
    if at.row > 0 {
        return Ok(Cursor::new(at.rung, at.row + 1, 0));
    }
    let next = at.rung + 1;
    if next >= plan.ladder.rungs.len() + plan.appended.len() {
        plan.steps.push(Step::Insert {
            index: next,
            rung: Rung::default(),
        });
    }
    Ok(Cursor::new(next, 0, 0))
}

/// Plans replacing the whole ladder; the cursor goes to the first cell.
fn replace_all(plan: &mut Plan<'_>, ladder: &Ladder, new: Ladder) -> Result<Cursor, EditError> {
    if *ladder == new {
        return Err(EditError::NothingToDo);
    }
    plan.steps.push(Step::Ladder {
        before: Box::new(ladder.clone()),
        after: Box::new(new),
    });
    Ok(Cursor::default())
}
