//! Outputs moved to the editor's output column, as a ladder tool draws
//! them: a ladder read from text or a file has its outputs right after
//! its conditions; the editor shows them at the right rail.

use crate::ladder::element::Element;
use crate::ladder::grid::{Ladder, Link, Rung};

/// `ladder` with each rung's outputs moved right to `column`, the wire
/// before them drawn out. A rung whose outputs do not stand in one
/// column, with nothing right of them, is left as it is (as is one whose
/// outputs stand on the rail, which is an error to report, not to hide).
/// The logic is unchanged: the point left of the outputs moves right
/// with every link on it, and each row that reached it reaches it still.
pub fn align_outputs(ladder: &Ladder, column: usize) -> Ladder {
    Ladder {
        rungs: ladder
            .rungs
            .iter()
            .map(|r| align_rung(r, column).unwrap_or_else(|| r.clone()))
            .collect(),
        device_comments: ladder.device_comments.clone(),
        variables: ladder.variables.clone(),
    }
}

fn align_rung(rung: &Rung, column: usize) -> Option<Rung> {
    let mut columns = rung
        .elements()
        .filter(|(_, e)| e.is_output())
        .map(|(p, _)| p.col);
    let oc = columns.next()?;
    if oc == 0 || oc >= column || columns.any(|c| c != oc) || rung.width() > oc + 1 {
        return None;
    }
    let shift = column - oc;
    let on_link = |row: usize| {
        rung.links
            .iter()
            .any(|l| l.col == oc && (l.row == row || l.row + 1 == row))
    };
    let mut out = rung.clone();
    for (r, row) in out.cells.iter_mut().enumerate() {
        let reaches = row.get(oc - 1).is_some_and(Option::is_some);
        let used = row.get(oc).is_some_and(Option::is_some) || on_link(r);
        if row.len() <= oc && !(reaches && used) {
            continue;
        }
        if row.len() < oc {
            row.resize(oc, None);
        }
        let fill = if reaches && used {
            Some(Element::Wire)
        } else {
            None
        };
        for _ in 0..shift {
            row.insert(oc, fill.clone());
        }
    }
    for l in &mut out.links {
        if l.col >= oc {
            *l = Link {
                row: l.row,
                col: l.col + shift,
            };
        }
    }
    Some(out)
}
