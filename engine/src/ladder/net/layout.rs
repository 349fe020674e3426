//! Drawing a rung's logic back onto a grid: series left to right,
//! parallel branches below each other, outputs in the last column.

use super::{Net, RungLogic, Side};
use crate::ladder::element::Element;
use crate::ladder::grid::{Link, Pos, Rung};
use crate::limits::MAX_RUNG_CELLS;

/// [`layout`], refusing a drawing larger than [`MAX_RUNG_CELLS`] before
/// anything is drawn. The logic must nest at most
/// [`crate::limits::MAX_NESTING`] deep (every [`Net`] the engine builds does).
pub fn try_layout(logic: &RungLogic) -> Result<Rung, TooLarge> {
    let (width, height) = measure(&logic.condition);
    let below: usize = logic.sides.iter().map(|s| measure(&s.net).1).sum();
    let rows = height.max(logic.outputs.len()).saturating_add(below);
    let columns = width.saturating_add(1);
    if rows as u128 * columns as u128 > MAX_RUNG_CELLS as u128 {
        return Err(TooLarge { rows, columns });
    }
    Ok(layout(logic))
}

/// A rung whose drawing would span more than [`MAX_RUNG_CELLS`] cells.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TooLarge {
    /// Rows it would span.
    pub rows: usize,
    /// Columns it would span.
    pub columns: usize,
}

impl std::fmt::Display for TooLarge {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "drawn as a ladder this rung would span {} rows and {} columns, more than the {MAX_RUNG_CELLS} cells a rung may have (docs/limits.md)",
            self.rows, self.columns
        )
    }
}

impl std::error::Error for TooLarge {}

/// Draws a rung's logic on a grid: series left to right, parallel
/// branches below each other, outputs in the last column.
pub fn layout(logic: &RungLogic) -> Rung {
    let mut rung = Rung {
        comment: logic.comment.clone(),
        ..Rung::default()
    };
    let (width, _) = place(&logic.condition, &mut rung, 0, 0);
    for (i, (e, _)) in logic.outputs.iter().enumerate() {
        rung.set(Pos::new(i, width), Some(e.clone()));
        if i > 0 {
            rung.links.push(Link {
                row: i - 1,
                col: width,
            });
        }
    }
    for side in &logic.sides {
        draw_side(&mut rung, side);
    }
    crate::sort::all(&mut rung.links);
    rung.links.dedup();
    rung
}

/// Whether every box input network of `logic` can be drawn under its box
/// ([`draw_side`]).
pub fn sides_fit(logic: &RungLogic) -> bool {
    let mut rung = layout(&RungLogic {
        sides: Vec::new(),
        ..logic.clone()
    });
    logic.sides.iter().all(|s| draw_side(&mut rung, s))
}

/// Draws a box input's network as the editor has it: the input's cell
/// ([`Element::BoxInput`]) under its box (under the box's other inputs),
/// the network to its left on rows of its own, and the box no longer
/// given the carrier at that pin. Where those cells are taken, it goes
/// below the rung instead, where reading the grid says what is wrong
/// (never dropped); returns whether it fit under its box.
fn draw_side(rung: &mut Rung, side: &Side) -> bool {
    let reading = rung.elements().find_map(|(p, e)| {
        let pin = e
            .block()?
            .inputs
            .iter()
            .find(|(_, o)| o.trim().eq_ignore_ascii_case(&side.variable))?;
        Some((p, pin.0.clone()))
    });
    let Some((at, pin)) = reading else {
        return false;
    };
    if let Some(Some(Element::Block(b) | Element::OutputBlock(b))) =
        rung.cells.get_mut(at.row).and_then(|r| r.get_mut(at.col))
    {
        b.inputs.retain(|(p, _)| *p != pin);
    }
    let (width, height) = measure(&side.net);
    let mut row = at.row + 1;
    while matches!(
        rung.get(Pos::new(row, at.col)),
        Some(Element::BoxInput { .. })
    ) {
        row += 1;
    }
    let fits = width <= at.col && free(rung, row, height, at.col);
    if !fits {
        row = rung.cells.len();
    }
    place(&side.net, rung, row, 0);
    for c in width..at.col {
        rung.set(Pos::new(row, c), Some(Element::Wire));
    }
    rung.set(
        Pos::new(row, at.col.max(width)),
        Some(Element::BoxInput { pin }),
    );
    fits
}

/// Whether rows `row..row + height` are empty up to column `col` and
/// no link joins them to the rows above or below there.
fn free(rung: &Rung, row: usize, height: usize, col: usize) -> bool {
    let rows = row..row + height;
    let cells = rows
        .clone()
        .all(|r| (0..=col).all(|c| rung.get(Pos::new(r, c)).is_none()));
    let joined = rung
        .links
        .iter()
        .any(|l| l.col <= col + 1 && l.row + 1 >= row && l.row < row + height);
    cells && !joined
}

/// The (width, height) a network takes.
fn measure(net: &Net) -> (usize, usize) {
    match net {
        Net::Leaf(..) => (1, 1),
        Net::Series(v) => v
            .iter()
            .map(measure)
            .fold((0, 1), |(w, h), (cw, ch)| (w + cw, h.max(ch))),
        Net::Parallel(v) => v
            .iter()
            .map(measure)
            .fold((0, 0), |(w, h), (cw, ch)| (w.max(cw), h + ch)),
    }
}

fn place(net: &Net, rung: &mut Rung, row: usize, col: usize) -> (usize, usize) {
    match net {
        Net::Leaf(e, _) => {
            rung.set(Pos::new(row, col), Some(e.clone()));
            (1, 1)
        }
        Net::Series(v) => {
            let (mut x, mut h) = (col, 1);
            for n in v {
                let (w, nh) = place(n, rung, row, x);
                x += w;
                h = h.max(nh);
            }
            (x - col, h)
        }
        Net::Parallel(v) => {
            let (width, _) = measure(net);
            let mut r = row;
            let mut last_top = row;
            for n in v {
                let (w, h) = place(n, rung, r, col);
                for c in col + w..col + width {
                    rung.set(Pos::new(r, c), Some(Element::Wire));
                }
                last_top = r;
                r += h;
            }
            for k in row..last_top {
                if col > 0 {
                    rung.links.push(Link { row: k, col });
                }
                rung.links.push(Link {
                    row: k,
                    col: col + width,
                });
            }
            (width, r - row)
        }
    }
}
