//! Rungs as the editor draws them: a grid of cells with vertical links.
//!
//! Electrically, the left edge of every row's first cell is the left power
//! rail; a non-empty cell joins the point on its left to the point on its
//! right; a [`Link`] joins two rows at a column's left edge. Outputs stand
//! in one column at the rung's right end (docs/ladder.md).

use std::collections::BTreeMap;
use std::fmt;

use serde::{Deserialize, Serialize};

use super::element::Element;
use crate::error::shown;
use crate::limits::MAX_MAP_ENTRIES;

/// A cell's place in a rung, 0-based (errors print it 1-based).
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize,
)]
pub struct Pos {
    /// The row, from the top.
    pub row: usize,
    /// The column, from the left rail.
    pub col: usize,
}

impl Pos {
    /// The cell at `row`, `col`.
    pub const fn new(row: usize, col: usize) -> Pos {
        Pos { row, col }
    }
}

/// A vertical wire joining `row` and `row + 1` at the left edge of `col`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(from = "(usize, usize)", into = "(usize, usize)")]
pub struct Link {
    /// The upper row.
    pub row: usize,
    /// The column whose left edge it runs down.
    pub col: usize,
}

impl From<(usize, usize)> for Link {
    fn from((row, col): (usize, usize)) -> Link {
        Link { row, col }
    }
}

impl From<Link> for (usize, usize) {
    fn from(l: Link) -> (usize, usize) {
        (l.row, l.col)
    }
}

/// One rung: rows of cells (`None` = empty) and the vertical links.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct Rung {
    /// The rung comment.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub comment: String,
    /// Rows of cells, top first; rows may be shorter than the widest.
    pub cells: Vec<Vec<Option<Element>>>,
    /// Vertical links.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub links: Vec<Link>,
}

impl Rung {
    /// The number of columns (the longest row).
    pub fn width(&self) -> usize {
        self.cells.iter().map(Vec::len).max().unwrap_or(0)
    }

    /// The element at `pos`, if any.
    pub fn get(&self, pos: Pos) -> Option<&Element> {
        self.cells.get(pos.row)?.get(pos.col)?.as_ref()
    }

    /// Puts `element` at `pos`, growing the grid as needed.
    pub fn set(&mut self, pos: Pos, element: Option<Element>) {
        if self.cells.len() <= pos.row {
            self.cells.resize(pos.row + 1, Vec::new());
        }
        let row = &mut self.cells[pos.row];
        if row.len() <= pos.col {
            row.resize(pos.col + 1, None);
        }
        row[pos.col] = element;
    }

    /// Removes the vertical links left hanging at the edges of the cell
    /// `pos` once it was emptied: a link whose end at a point on this
    /// row meets no element and no other link leads nowhere (an OR
    /// branch's contact deleted left its links drawn as a stub). The
    /// link's other end is looked at in turn, so a branch's links go
    /// together; links elsewhere, drawn by hand ahead of their contacts,
    /// stay.
    pub fn remove_stubs_around(&mut self, pos: Pos) {
        let mut points = vec![(pos.row, pos.col), (pos.row, pos.col + 1)];
        while let Some((row, edge)) = points.pop() {
            // The left rail is not a stub: every row meets it.
            let meets_a_cell = edge == 0
                || self.get(Pos::new(row, edge - 1)).is_some()
                || self.get(Pos::new(row, edge)).is_some();
            if meets_a_cell {
                continue;
            }
            let at_point = |l: &Link| l.col == edge && (l.row == row || l.row + 1 == row);
            let mut here = self.links.iter().filter(|l| at_point(l));
            let (Some(&only), None) = (here.next(), here.next()) else {
                continue;
            };
            self.links.retain(|l| *l != only);
            let other = if only.row == row { row + 1 } else { only.row };
            points.push((other, edge));
        }
    }

    /// Whether the rung holds nothing at all.
    pub fn is_empty(&self) -> bool {
        self.cells.iter().flatten().all(Option::is_none) && self.links.is_empty()
    }

    /// Every element with its place, row by row.
    pub fn elements(&self) -> impl Iterator<Item = (Pos, &Element)> {
        self.cells.iter().enumerate().flat_map(|(r, row)| {
            row.iter()
                .enumerate()
                .filter_map(move |(c, e)| e.as_ref().map(|e| (Pos::new(r, c), e)))
        })
    }
}

/// A whole ladder: rungs and device comments.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Ladder {
    /// The rungs, run top to bottom.
    pub rungs: Vec<Rung>,
    /// Comments on devices, by device name.
    #[serde(
        default,
        skip_serializing_if = "BTreeMap::is_empty",
        deserialize_with = "each_name_once"
    )]
    pub device_comments: BTreeMap<String, String>,
    /// The soft PLC's declared variables (issue #30); none for the
    /// other machines.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub variables: Vec<super::variables::Variable>,
}

/// What sort of problem a [`LadderError`] is, so that an editor can mark
/// cells by kind (the message says the rest).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LadderErrorKind {
    /// Wires and links that do not make a circuit: shorts, outputs not
    /// joined, an output on the rail, links off the grid.
    Wiring,
    /// An element in the wrong column (outputs last, nothing after them).
    Placement,
    /// The rung has no output.
    NoOutput,
    /// An element or wire on no path from the rail to the outputs.
    Dangling,
    /// A bridge between branches.
    NotSeriesParallel,
    /// The machine lacks the element or the device, or the device cannot
    /// be used that way.
    Device,
    /// The program does not fit the machine: steps, temporaries, timers.
    Capacity,
    /// One of the engine's documented limits (docs/limits.md).
    Limit,
}

/// A problem with a ladder, at a rung (1-based) and optionally a cell.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LadderError {
    /// The 1-based rung number.
    pub rung: usize,
    /// The cell, when the problem has one.
    pub pos: Option<Pos>,
    /// What sort of problem.
    pub kind: LadderErrorKind,
    /// What is wrong.
    pub message: String,
    /// The typed reason, when the machine refused an element (issue #49:
    /// the page says it in its own language from this; `message` is its
    /// English; boxed, as it is seldom there).
    pub cause: Option<Box<super::target::ElementError>>,
    /// The typed reason of a wiring or placement problem (issue #49, as
    /// `cause`: the page's language from the kind; boxed, as `cause`).
    pub problem: Option<Box<super::problem::RungProblem>>,
}

impl LadderError {
    /// A problem with the element at a cell of rung index `rung`
    /// (0-based): by default the machine lacks it ([`LadderErrorKind::Device`]).
    pub fn at(rung: usize, pos: Pos, message: impl Into<String>) -> LadderError {
        LadderError {
            rung: rung.saturating_add(1),
            pos: Some(pos),
            kind: LadderErrorKind::Device,
            message: message.into(),
            cause: None,
            problem: None,
        }
    }

    /// A problem with rung index `rung` (0-based) as a whole: by default
    /// it does not fit the machine ([`LadderErrorKind::Capacity`]).
    pub fn rung(rung: usize, message: impl Into<String>) -> LadderError {
        LadderError {
            rung: rung.saturating_add(1),
            pos: None,
            kind: LadderErrorKind::Capacity,
            message: message.into(),
            cause: None,
            problem: None,
        }
    }

    /// The machine's refusal of the element at `pos` of rung index
    /// `rung`: its words and its typed reason.
    pub fn refused(rung: usize, pos: Pos, cause: super::target::ElementError) -> LadderError {
        LadderError {
            cause: Some(Box::new(cause.clone())),
            ..LadderError::at(rung, pos, cause.to_string())
        }
    }

    /// A wiring or placement problem of rung index `rung` (at `pos`, when
    /// it has a cell): its English and its kind.
    pub fn wiring(
        rung: usize,
        pos: Option<Pos>,
        kind: LadderErrorKind,
        problem: super::problem::RungProblem,
    ) -> LadderError {
        let message = problem.to_string();
        let plain = match pos {
            Some(p) => LadderError::at(rung, p, message),
            None => LadderError::rung(rung, message),
        };
        LadderError {
            kind,
            problem: Some(Box::new(problem)),
            ..plain
        }
    }

    /// The same problem, of `kind`.
    pub fn kind(self, kind: LadderErrorKind) -> LadderError {
        LadderError { kind, ..self }
    }
}

impl fmt::Display for LadderError {
    /// `rung 3, row 1, column 2: message` (1-based).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.pos {
            // Widened: a position read from a file may be usize::MAX.
            Some(p) => write!(
                f,
                "rung {}, row {}, column {}: {}",
                self.rung,
                p.row as u128 + 1,
                p.col as u128 + 1,
                self.message
            ),
            None => write!(f, "rung {}: {}", self.rung, self.message),
        }
    }
}

impl std::error::Error for LadderError {}

/// Reads a table of names (settings, device comments) refusing a name
/// given twice: JSON readers disagree on which copy wins, so a project
/// that says two things must not silently mean one of them. The error
/// lands at the second copy's line.
pub(crate) fn each_name_once<'de, D>(d: D) -> Result<BTreeMap<String, String>, D::Error>
where
    D: serde::Deserializer<'de>,
{
    struct Names;
    impl<'de> serde::de::Visitor<'de> for Names {
        type Value = BTreeMap<String, String>;
        fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
            f.write_str("an object of names and texts")
        }
        fn visit_map<A: serde::de::MapAccess<'de>>(
            self,
            mut map: A,
        ) -> Result<Self::Value, A::Error> {
            let mut names = BTreeMap::new();
            // Checked as each name is read, so that the error lands at
            // the second copy's line.
            while let Some(name) = map.next_key::<String>()? {
                if names.len() == MAX_MAP_ENTRIES {
                    return Err(serde::de::Error::custom(format!(
                        "more than {MAX_MAP_ENTRIES} names in one table (docs/limits.md)"
                    )));
                }
                if names.contains_key(&name) {
                    return Err(serde::de::Error::custom(format!(
                        "{} is given twice",
                        shown(&name)
                    )));
                }
                let text = map.next_value::<String>()?;
                names.insert(name, text);
            }
            Ok(names)
        }
    }
    d.deserialize_map(Names)
}
