//! The clipboard: a block of cells or whole rungs, as text so that it
//! travels through the system clipboard (between two tabs of the page, or
//! into an e-mail): a header line, then JSON in the project's own element
//! form.

use std::fmt;

use serde::{Deserialize, Serialize};

use super::change::Step;
use super::command::{EditError, Plan};
use super::{Cursor, MAX_COLUMNS, MAX_ROWS};
use crate::ladder::element::Element;
use crate::ladder::grid::{Ladder, Link, Pos, Rung};
use crate::ladder::target::{check_element, ElementError};
use crate::limits::MAX_INPUT_BYTES;
use crate::MachineId;

/// The first line of a clip's text.
pub const CLIP_HEADER: &str = "hashigo-clip 1";

/// What was copied.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum Clip {
    /// A block of cells, its top-left cell first, with the links inside it.
    Cells {
        /// Rows of cells.
        cells: Vec<Vec<Option<Element>>>,
        /// Links, relative to the block's top-left.
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        links: Vec<Link>,
    },
    /// Whole rungs, comments included.
    Rungs {
        /// The rungs.
        rungs: Vec<Rung>,
    },
}

/// Why a clip does not paste.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ClipError {
    /// The text is not a clip (no header, or JSON of another shape: the
    /// parser's words).
    NotAClip(String),
    /// Larger than [`MAX_INPUT_BYTES`].
    TooLarge,
    /// An element the target machine lacks, at its place in the clip
    /// (rung 0 for a block of cells).
    Element {
        /// The clip's rung.
        rung: usize,
        /// The cell in it.
        pos: Pos,
        /// Why.
        error: ElementError,
    },
    /// Pasted there, the block would reach past the grid.
    OutsideGrid,
}

impl fmt::Display for ClipError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ClipError::NotAClip(why) => write!(f, "the clipboard holds no ladder: {why}"),
            ClipError::TooLarge => write!(
                f,
                "the clipboard text is larger than the {MAX_INPUT_BYTES} bytes a ladder may have"
            ),
            ClipError::Element { rung, pos, error } => write!(
                f,
                "copied rung {}, row {}, column {}: {error}",
                rung + 1,
                pos.row + 1,
                pos.col + 1
            ),
            ClipError::OutsideGrid => write!(
                f,
                "pasted here the cells would reach past {MAX_ROWS} rows or {MAX_COLUMNS} columns"
            ),
        }
    }
}

impl std::error::Error for ClipError {}

impl Clip {
    /// The block of rung `from.rung` between two corners (in any order).
    pub fn cells(ladder: &Ladder, from: Cursor, to: Cursor) -> Result<Clip, EditError> {
        if from.rung != to.rung {
            return Err(EditError::BlockAcrossRungs);
        }
        let rung = ladder
            .rungs
            .get(from.rung)
            .ok_or(EditError::NoSuchRung(from.rung))?;
        let (r0, r1) = (from.row.min(to.row), from.row.max(to.row));
        let (c0, c1) = (from.col.min(to.col), from.col.max(to.col));
        let cells = (r0..=r1)
            .map(|r| {
                (c0..=c1)
                    .map(|c| rung.get(Pos::new(r, c)).cloned())
                    .collect()
            })
            .collect();
        // The links between the block's rows, on its columns' edges.
        let links = rung
            .links
            .iter()
            .filter(|l| (r0..r1).contains(&l.row) && (c0..=c1 + 1).contains(&l.col))
            .map(|l| Link {
                row: l.row - r0,
                col: l.col - c0,
            })
            .collect();
        Ok(Clip::Cells { cells, links })
    }

    /// Rungs `first..=last`.
    pub fn rungs(ladder: &Ladder, first: usize, last: usize) -> Result<Clip, EditError> {
        let (first, last) = (first.min(last), first.max(last));
        let rungs = ladder
            .rungs
            .get(first..=last)
            .ok_or(EditError::NoSuchRung(last))?;
        Ok(Clip::Rungs {
            rungs: rungs.to_vec(),
        })
    }

    /// The clip as clipboard text.
    pub fn to_text(&self) -> String {
        // Serialising plain data to a string cannot fail.
        let json = serde_json::to_string(self).unwrap_or_default();
        format!("{CLIP_HEADER}\n{json}\n")
    }

    /// A clip from clipboard text.
    pub fn from_text(text: &str) -> Result<Clip, ClipError> {
        if text.len() > MAX_INPUT_BYTES {
            return Err(ClipError::TooLarge);
        }
        let body = text
            .trim_start_matches('\u{feff}')
            .trim_start()
            .strip_prefix(CLIP_HEADER)
            .ok_or_else(|| {
                ClipError::NotAClip(format!("it does not start with \"{CLIP_HEADER}\""))
            })?;
        serde_json::from_str(body.trim()).map_err(|e| ClipError::NotAClip(e.to_string()))
    }

    /// The clip with every element checked against `machine` and its
    /// devices in the machine's spelling; every element it lacks is an
    /// error (so a paste from another machine changes nothing).
    pub fn for_machine(&self, machine: MachineId) -> Result<Clip, Vec<ClipError>> {
        let mut errors = Vec::new();
        let mut check = |rung: usize, row: usize, cells: &mut Vec<Option<Element>>| {
            for (col, cell) in cells.iter_mut().enumerate() {
                if let Some(e) = cell {
                    match check_element(machine, e) {
                        Ok(canonical) => *e = canonical,
                        Err(error) => errors.push(ClipError::Element {
                            rung,
                            pos: Pos::new(row, col),
                            error,
                        }),
                    }
                }
            }
        };
        let mut clip = self.clone();
        match &mut clip {
            Clip::Cells { cells, .. } => {
                for (row, cells) in cells.iter_mut().enumerate() {
                    check(0, row, cells);
                }
            }
            Clip::Rungs { rungs } => {
                for (i, rung) in rungs.iter_mut().enumerate() {
                    for (row, cells) in rung.cells.iter_mut().enumerate() {
                        check(i, row, cells);
                    }
                }
            }
        }
        if errors.is_empty() {
            Ok(clip)
        } else {
            Err(errors)
        }
    }

    /// Plans the paste at `at`; the cursor's place afterwards.
    pub(super) fn paste(&self, plan: &mut Plan, at: Cursor) -> Result<Cursor, EditError> {
        match self {
            Clip::Rungs { rungs } => {
                let index = at.rung.min(plan.ladder.rungs.len());
                for (i, rung) in rungs.iter().enumerate() {
                    plan.steps.push(Step::Insert {
                        index: index + i,
                        rung: rung.clone(),
                    });
                }
                Ok(Cursor::new(index + rungs.len(), 0, 0))
            }
            Clip::Cells { cells, links } => {
                let height = cells.len();
                let width = cells.iter().map(Vec::len).max().unwrap_or(0);
                if at.row + height > MAX_ROWS || at.col + width > MAX_COLUMNS {
                    return Err(EditError::Clip(ClipError::OutsideGrid));
                }
                let mut rung = plan.rung(at.rung)?;
                for (r, row) in cells.iter().enumerate() {
                    for (c, cell) in row.iter().enumerate() {
                        rung.set(Pos::new(at.row + r, at.col + c), cell.clone());
                    }
                }
                for l in links {
                    let link = Link {
                        row: at.row + l.row,
                        col: at.col + l.col,
                    };
                    if !rung.links.contains(&link) {
                        rung.links.push(link);
                    }
                }
                crate::sort::all(&mut rung.links);
                plan.set(at.rung, rung)?;
                Ok(Cursor::new(at.rung, at.row, at.col + width))
            }
        }
    }
}
