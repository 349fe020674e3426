//! The key map: GX Works keys first, LDmicro letters where they do not
//! clash (docs/editor.md), and cursor moves over the drawn grid. Plain
//! Rust, tested natively; the view only forwards key events here.

use engine::ladder::edit::{Cursor, EntryKind};
use engine::ladder::Ladder;

use super::model::shown_rows;

/// A cursor move.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Move {
    Left,
    Right,
    Up,
    Down,
    /// Home: the first column.
    RowStart,
    /// End: the output column.
    RowEnd,
    /// Page Up / Page Down: ten rungs.
    PageUp,
    PageDown,
    /// Ctrl+Home / Ctrl+End: the first cell, the end of the ladder.
    Top,
    Bottom,
}

/// What a key asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    /// Move the cursor; with Shift the selection grows.
    Move(Move, bool),
    /// Open the device entry for `kind` (an OR branch when `branch`),
    /// with `prefill` typed in.
    Entry {
        kind: EntryKind,
        branch: bool,
        prefill: &'static str,
    },
    /// Enter: edit the element under the cursor.
    EditCell,
    Wire,
    ToggleLink,
    DeleteWire,
    DeleteLink,
    /// Delete: the cell, or the selected block.
    Clear,
    InsertAbove,
    InsertBelow,
    /// Ctrl+Delete: the rung, or the selected rungs.
    DeleteRungs,
    RungUp,
    RungDown,
    Undo,
    Redo,
    /// Ctrl+C / Ctrl+X / Ctrl+V: the page's clipboard events do the work;
    /// these keep the selection in step.
    Copy,
    Cut,
    Paste,
    /// Ctrl+F: the find box.
    Find,
    /// `?`: the key map on screen.
    Help,
    /// Escape: drop the selection, close what is open.
    Cancel,
    /// W: why is the cell under the cursor on or off (docs/editor.md).
    Why,
}

/// The action of a key (`KeyboardEvent.key`) with its modifiers; `None`
/// for a key the ladder leaves alone.
pub fn action(key: &str, shift: bool, ctrl: bool, alt: bool) -> Option<Action> {
    use Action::*;
    let entry = |kind, branch, prefill| Entry {
        kind,
        branch,
        prefill,
    };
    Some(match (key, shift, ctrl, alt) {
        ("ArrowLeft", s, false, false) => Move(self::Move::Left, s),
        ("ArrowRight", s, false, false) => Move(self::Move::Right, s),
        ("ArrowUp", s, false, false) => Move(self::Move::Up, s),
        ("ArrowDown", s, false, false) => Move(self::Move::Down, s),
        ("ArrowUp", false, false, true) => RungUp,
        ("ArrowDown", false, false, true) => RungDown,
        ("Home", s, false, false) => Move(self::Move::RowStart, s),
        ("End", s, false, false) => Move(self::Move::RowEnd, s),
        ("Home", s, true, false) => Move(self::Move::Top, s),
        ("End", s, true, false) => Move(self::Move::Bottom, s),
        ("PageUp", s, false, false) => Move(self::Move::PageUp, s),
        ("PageDown", s, false, false) => Move(self::Move::PageDown, s),
        ("F5", b, false, false) => entry(EntryKind::Open, b, ""),
        ("F6", b, false, false) => entry(EntryKind::Closed, b, ""),
        ("F7", false, false, false) => entry(EntryKind::Coil, false, ""),
        ("F8", false, false, false) => entry(EntryKind::Instruction, false, ""),
        ("F9", false, false, false) => Wire,
        ("F9", true, false, false) => ToggleLink,
        ("F9", false, true, false) => DeleteWire,
        ("F10", false, true, false) => DeleteLink,
        ("Delete", false, false, false) => Clear,
        ("Delete", false, true, false) => DeleteRungs,
        ("Insert", false, false, false) => InsertAbove,
        ("Insert", true, false, false) => InsertBelow,
        ("Enter", false, false, false) => EditCell,
        ("Escape", _, _, _) => Cancel,
        ("?", _, false, false) => Help,
        (k, s, true, false) => match (k.to_ascii_lowercase().as_str(), s) {
            ("z", false) => Undo,
            ("z", true) | ("y", false) => Redo,
            ("c", false) => Copy,
            ("x", false) => Cut,
            ("v", false) => Paste,
            ("f", false) => Find,
            _ => return None,
        },
        // LDmicro's letters, as a second map.
        (k, _, false, false) => match k {
            "c" => entry(EntryKind::Open, false, ""),
            "C" => entry(EntryKind::Closed, false, ""),
            "l" | "L" => entry(EntryKind::Coil, false, ""),
            "s" | "S" => entry(EntryKind::Instruction, false, "SET "),
            "r" | "R" => entry(EntryKind::Instruction, false, "RST "),
            "o" | "O" => entry(EntryKind::Instruction, false, "TON "),
            "f" | "F" => entry(EntryKind::Instruction, false, "TOF "),
            "m" | "M" => entry(EntryKind::Instruction, false, "MOV "),
            "-" => Wire,
            "|" => ToggleLink,
            "w" | "W" => Why,
            _ => return None,
        },
        _ => return None,
    })
}

/// Where `mv` takes the cursor on `ladder` (output column `out_col`):
/// up and down go through every shown row and on into the next rung;
/// the rung after the last is the end line.
pub fn moved(ladder: &Ladder, out_col: usize, at: Cursor, mv: Move) -> Cursor {
    let last = ladder.rungs.len();
    let rows = |rung: usize| ladder.rungs.get(rung).map_or(1, shown_rows);
    let mut c = at;
    match mv {
        Move::Left => c.col = c.col.saturating_sub(1),
        Move::Right => c.col = (c.col + 1).min(out_col),
        Move::RowStart => c.col = 0,
        Move::RowEnd => c.col = out_col,
        Move::Up if c.row > 0 => c.row -= 1,
        Move::Up if c.rung > 0 => {
            c.rung -= 1;
            c.row = rows(c.rung) - 1;
        }
        Move::Up => {}
        Move::Down if c.row + 1 < rows(c.rung) => c.row += 1,
        Move::Down if c.rung < last => {
            c.rung += 1;
            c.row = 0;
        }
        Move::Down => {}
        Move::PageUp => {
            c.rung = c.rung.saturating_sub(10);
            c.row = 0;
        }
        Move::PageDown => {
            c.rung = (c.rung + 10).min(last);
            c.row = 0;
        }
        Move::Top => c = Cursor::default(),
        Move::Bottom => c = Cursor::new(last, 0, 0),
    }
    c.row = c.row.min(rows(c.rung) - 1);
    c
}

#[cfg(test)]
mod tests {
    use super::*;
    use engine::ladder::{Element, Rung};

    #[test]
    fn gx_works_keys() {
        assert_eq!(
            action("F5", true, false, false),
            Some(Action::Entry {
                kind: EntryKind::Open,
                branch: true,
                prefill: ""
            })
        );
        assert_eq!(action("F9", true, false, false), Some(Action::ToggleLink));
        assert_eq!(action("F10", false, true, false), Some(Action::DeleteLink));
        assert_eq!(action("Z", true, true, false), Some(Action::Redo));
        assert_eq!(action("y", false, true, false), Some(Action::Redo));
        assert_eq!(action("ArrowUp", false, false, true), Some(Action::RungUp));
        assert_eq!(
            action("ArrowLeft", true, false, false),
            Some(Action::Move(Move::Left, true))
        );
        assert_eq!(action("Tab", false, false, false), None);
        assert_eq!(action("q", false, true, false), None);
    }

    #[test]
    fn ldmicro_letters_where_they_do_not_clash() {
        assert_eq!(
            action("s", false, false, false),
            Some(Action::Entry {
                kind: EntryKind::Instruction,
                branch: false,
                prefill: "SET "
            })
        );
        assert_eq!(action("-", false, false, false), Some(Action::Wire));
        assert_eq!(action("?", true, false, false), Some(Action::Help));
        assert_eq!(action("x", false, false, false), None);
    }

    #[test]
    fn moves_run_through_every_shown_row_and_stop_at_the_end_line() {
        let rung = Rung {
            cells: vec![
                vec![Some(Element::no("X00"))],
                vec![Some(Element::no("X01"))],
            ],
            ..Rung::default()
        };
        let ladder = Ladder {
            rungs: vec![rung.clone(), rung],
            ..Ladder::default()
        };
        let at = |r, w, c| Cursor::new(r, w, c);
        // Two rows and a free one.
        assert_eq!(moved(&ladder, 9, at(0, 1, 3), Move::Down), at(0, 2, 3));
        assert_eq!(moved(&ladder, 9, at(0, 2, 3), Move::Down), at(1, 0, 3));
        assert_eq!(moved(&ladder, 9, at(1, 0, 3), Move::Up), at(0, 2, 3));
        assert_eq!(moved(&ladder, 9, at(1, 2, 3), Move::Down), at(2, 0, 3));
        assert_eq!(moved(&ladder, 9, at(2, 0, 3), Move::Down), at(2, 0, 3));
        assert_eq!(moved(&ladder, 9, at(0, 0, 9), Move::Right), at(0, 0, 9));
        assert_eq!(moved(&ladder, 9, at(0, 0, 0), Move::Left), at(0, 0, 0));
        assert_eq!(moved(&ladder, 9, at(1, 1, 4), Move::Bottom), at(2, 0, 0));
        assert_eq!(moved(&ladder, 9, at(1, 1, 4), Move::RowEnd), at(1, 1, 9));
        assert_eq!(moved(&ladder, 9, at(2, 0, 0), Move::PageUp), at(0, 0, 0));
    }
}
