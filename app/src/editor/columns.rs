//! Each column of the ladder as wide as its content needs (issue #45):
//! a contact's column narrower than a box's, a column of wires the
//! narrowest, and every rung's columns lined up at one right rail.

use super::cell_kind::CellKind;
use super::model::{CellData, RungData};

/// The narrowest a column with an element is drawn (rem): a contact
/// with a short device name.
pub const MIN_COL_REM: f64 = 3.0;
/// A column that holds only wires or nothing, in every rung (rem): wide
/// enough to point at, narrow enough that a rung of two contacts and a
/// coil fits a phone's width at 100 %.
pub const WIRE_COL_REM: f64 = 1.4;
/// The widest a column is drawn (rem); a longer text is cut with an
/// ellipsis and shown whole in its title.
pub const MAX_COL_REM: f64 = 16.0;

/// How wide (rem) `cell` needs its column: nothing for a wire or an
/// empty cell; else its symbol (a box's text) in the symbol's face and its
/// device name in the label's, with room at the sides. Monospace faces:
/// about 0.6 em a character.
pub fn cell_width_rem(cell: &CellData) -> f64 {
    if matches!(cell.kind, CellKind::Empty | CellKind::Wire) {
        return 0.0;
    }
    let symbol = cell.symbol.chars().count() as f64 * 0.6 * 0.78 + 0.6;
    let mut device = cell.device.chars().count() as f64 * 0.6 * 0.72 + 0.8;
    let counts = cell.device.starts_with('T') || cell.device.starts_with('C');
    if cell.kind.look().shows_value && counts {
        // Its current value (up to five digits, 0.65 rem) at the top right,
        // clear of the name centred above the coil: room on both sides.
        device += 2.0 * 5.0 * 0.6 * 0.65;
    }
    let values = super::cell_kind::values_width_rem(&cell.watched);
    symbol
        .max(device)
        .max(values)
        .clamp(MIN_COL_REM, MAX_COL_REM)
}

/// Each column's width (rem) over the whole ladder, so that every rung's
/// columns and right rail line up: as wide as the widest cell the column
/// holds in any rung (a contact's column narrower than a box's, a column
/// of wires narrowest), at least `cols` columns.
pub fn column_widths(rungs: &[&RungData], cols: usize) -> Vec<f64> {
    let cols = rungs.iter().map(|r| r.cols).max().unwrap_or(0).max(cols);
    let mut widths = vec![WIRE_COL_REM; cols];
    for cell in rungs.iter().flat_map(|r| r.cells.iter()) {
        if let Some(w) = widths.get_mut(cell.col) {
            *w = w.max(cell_width_rem(cell));
        }
    }
    widths
}

/// `grid-template-columns` for a rung of `cols` columns.
pub fn grid_columns(widths: &[f64], cols: usize) -> String {
    let mut out = String::from("grid-template-columns:");
    for c in 0..cols {
        let w = widths.get(c).copied().unwrap_or(MIN_COL_REM);
        out.push_str(&format!(" {w:.2}rem"));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::editor::model::rung_data;
    use engine::ladder::{Element, Rung};
    use std::collections::BTreeMap;

    fn rung(cells: Vec<Vec<Option<Element>>>, links: Vec<engine::ladder::Link>) -> Rung {
        Rung {
            comment: String::new(),
            cells,
            links,
        }
    }

    #[test]
    fn a_contacts_column_is_narrower_than_a_boxs_and_rungs_line_up() {
        let mov = Element::Mov {
            src: "K50".into(),
            dst: "D00".into(),
        };
        let none = BTreeMap::new();
        let a = rung_data(
            &rung(
                vec![vec![
                    Some(Element::no("X00")),
                    Some(mov),
                    None,
                    Some(Element::coil("Y00")),
                ]],
                vec![],
            ),
            3,
            &[],
            &none,
        );
        let b = rung_data(
            &rung(
                vec![vec![Some(Element::nc("start_button_pressed"))]],
                vec![],
            ),
            3,
            &[],
            &none,
        );
        let widths = column_widths(&[&a, &b], 4);
        assert_eq!(widths.len(), 4);
        // X00 alone needs the least; the box its text; the long name more;
        // a column of nothing the least of all.
        assert!(widths[1] > widths[3], "{widths:?}");
        assert!(
            widths[0] > MIN_COL_REM,
            "the long name widens column 0: {widths:?}"
        );
        assert_eq!(widths[2], WIRE_COL_REM);
        assert_eq!(widths[3], MIN_COL_REM, "the coil's");
        // A timer's coil has room for its name and its value beside it
        // (MINASEC-U's `OUT T0` is a plain coil that shows it too).
        let plain = CellData {
            kind: CellKind::Coil,
            device: "T0".into(),
            symbol: "( )".into(),
            ..CellData::default()
        };
        assert!(cell_width_rem(&plain) > 4.5, "{}", cell_width_rem(&plain));
        let timer = CellData {
            kind: CellKind::CountCoil,
            device: "T0".into(),
            symbol: "(K10)".into(),
            ..CellData::default()
        };
        assert!(cell_width_rem(&timer) > 4.5, "{}", cell_width_rem(&timer));
        let only_x00 = column_widths(&[&a], 4);
        assert_eq!(only_x00[0], MIN_COL_REM);
        assert!(widths
            .iter()
            .all(|w| (WIRE_COL_REM..=MAX_COL_REM).contains(w)));
        assert_eq!(
            grid_columns(&[3.4, 6.0], 3),
            "grid-template-columns: 3.40rem 6.00rem 3.00rem"
        );
    }
}
