//! The editor's model (issue #13): every edit and its undo, the seed
//! program drawn edit by edit, random edit sequences undone and redone,
//! the clipboard's text form, devices (completion, find, cross-reference,
//! replace).

mod devices;
mod entry;
mod examples;
mod properties;

use engine::formats::Project;
use engine::ladder::compile::{compile, Options};
use engine::ladder::edit::{Clip, Cursor, Edit, EditError, Editor};
use engine::ladder::{ContactKind, Element, Ladder, Link, Pos};
use engine::MachineId;

pub fn no(d: &str) -> Element {
    Element::Contact {
        kind: ContactKind::No,
        device: d.into(),
    }
}

pub fn nc(d: &str) -> Element {
    Element::Contact {
        kind: ContactKind::Nc,
        device: d.into(),
    }
}

fn at(rung: usize, row: usize, col: usize) -> Cursor {
    Cursor::new(rung, row, col)
}

/// Applies `edit`, checks that undo restores the ladder and the cursor
/// exactly and that redo gives the edit's result again; returns the
/// editor after the edit.
fn applies(mut e: Editor, edit: Edit) -> Editor {
    let (before, cursor) = (e.ladder().clone(), e.cursor());
    e.apply(edit.clone())
        .unwrap_or_else(|err| panic!("{edit:?}: {err}"));
    let (after, moved) = (e.ladder().clone(), e.cursor());
    assert_ne!(after, before, "{edit:?} changed something");
    assert!(e.undo());
    assert_eq!(
        (e.ladder(), e.cursor()),
        (&before, cursor),
        "undo of {edit:?}"
    );
    assert!(e.redo());
    assert_eq!(
        (e.ladder(), e.cursor()),
        (&after, moved),
        "redo of {edit:?}"
    );
    e
}

fn refused(e: &mut Editor, edit: Edit, why: EditError) {
    let before = e.ladder().clone();
    assert_eq!(e.apply(edit), Err(why));
    assert_eq!(e.ladder(), &before, "a refused edit changes nothing");
}

#[test]
fn a_contact_goes_at_the_cursor_which_moves_right() {
    let e = applies(
        Editor::default(),
        Edit::Place {
            at: at(0, 0, 0),
            element: no("X00"),
        },
    );
    assert_eq!(e.ladder().rungs[0].get(Pos::new(0, 0)), Some(&no("X00")));
    assert_eq!(e.cursor(), at(0, 0, 1));
}

#[test]
fn an_output_goes_to_the_output_column_and_the_next_rung_starts() {
    let e = applies(
        Editor::default(),
        Edit::Place {
            at: at(0, 0, 0),
            element: no("X00"),
        },
    );
    let e = applies(
        e,
        Edit::Place {
            at: at(0, 0, 1),
            element: Element::coil("Y00"),
        },
    );
    let rung = &e.ladder().rungs[0];
    assert_eq!(rung.get(Pos::new(0, 9)), Some(&Element::coil("Y00")));
    assert!((1..9).all(|c| rung.get(Pos::new(0, c)) == Some(&Element::Wire)));
    assert_eq!(e.ladder().rungs.len(), 2, "an empty rung was made");
    assert!(e.ladder().rungs[1].is_empty());
    assert_eq!(e.cursor(), at(1, 0, 0));
    assert_eq!(
        e.ladder().logic(MachineId::MinasecU).map(|l| l.len()),
        Ok(1)
    );
}

#[test]
fn an_or_branch_links_around_the_cell_above() {
    let e = applies(
        Editor::default(),
        Edit::Place {
            at: at(0, 0, 0),
            element: no("X00"),
        },
    );
    let e = applies(
        e,
        Edit::PlaceBranch {
            at: at(0, 1, 0),
            element: no("Y00"),
        },
    );
    assert_eq!(
        e.ladder().rungs[0].links,
        [Link { row: 0, col: 1 }],
        "none at the rail"
    );
    let e = applies(
        e,
        Edit::Place {
            at: at(0, 0, 1),
            element: no("X01"),
        },
    );
    let e = applies(
        e,
        Edit::PlaceBranch {
            at: at(0, 1, 1),
            element: nc("X02"),
        },
    );
    assert_eq!(
        e.ladder().rungs[0].links,
        [Link { row: 0, col: 1 }, Link { row: 0, col: 2 }]
    );
    let mut e = e;
    refused(
        &mut e,
        Edit::PlaceBranch {
            at: at(0, 0, 3),
            element: no("X03"),
        },
        EditError::BranchOnTopRow,
    );
    refused(
        &mut e,
        Edit::PlaceBranch {
            at: at(0, 1, 3),
            element: Element::coil("Y01"),
        },
        EditError::BranchNotContact,
    );
}

#[test]
fn wires_links_and_clearing() {
    let e = applies(Editor::default(), Edit::Wire { at: at(0, 0, 2) });
    let e = applies(e, Edit::ToggleLink { at: at(0, 0, 3) });
    assert_eq!(e.ladder().rungs[0].links, [Link { row: 0, col: 3 }]);
    let e = applies(e, Edit::ToggleLink { at: at(0, 0, 3) });
    assert!(
        e.ladder().rungs[0].links.is_empty(),
        "a second toggle removes it"
    );
    let mut e = applies(e, Edit::DeleteWire { at: at(0, 0, 2) });
    refused(
        &mut e,
        Edit::DeleteWire { at: at(0, 0, 2) },
        EditError::NothingToDo,
    );
    refused(
        &mut e,
        Edit::DeleteLink { at: at(0, 0, 3) },
        EditError::NothingToDo,
    );
    refused(
        &mut e,
        Edit::Clear { at: at(0, 0, 0) },
        EditError::NothingToDo,
    );
    let e = applies(
        e,
        Edit::Place {
            at: at(0, 0, 0),
            element: no("X00"),
        },
    );
    let e = applies(e, Edit::Clear { at: at(0, 0, 0) });
    let e = applies(
        e,
        Edit::Place {
            at: at(0, 1, 1),
            element: no("X01"),
        },
    );
    let e = applies(
        e,
        Edit::Place {
            at: at(0, 2, 2),
            element: no("X02"),
        },
    );
    let e = applies(
        e,
        Edit::ClearBlock {
            from: at(0, 2, 2),
            to: at(0, 1, 1),
        },
    );
    assert!(e.ladder().rungs[0].elements().next().is_none());
    let mut e = e;
    refused(
        &mut e,
        Edit::ClearBlock {
            from: at(0, 0, 0),
            to: at(1, 0, 0),
        },
        EditError::BlockAcrossRungs,
    );
    refused(
        &mut e,
        Edit::Wire { at: at(0, 70, 0) },
        EditError::OutsideGrid(at(0, 70, 0)),
    );
    refused(
        &mut e,
        Edit::Wire { at: at(5, 0, 0) },
        EditError::NoSuchRung(5),
    );
}

fn three_rungs() -> Editor {
    let mut e = Editor::default();
    for (i, d) in ["X00", "X01", "X02"].iter().enumerate() {
        e.apply(Edit::Place {
            at: at(i, 0, 0),
            element: no(d),
        })
        .expect("contact");
        e.apply(Edit::Place {
            at: at(i, 0, 1),
            element: Element::coil(&format!("Y0{i}")),
        })
        .expect("coil");
    }
    e
}

#[test]
fn rungs_insert_delete_move_and_comments() {
    let e = applies(three_rungs(), Edit::InsertRung { index: 1 });
    assert!(e.ladder().rungs[1].is_empty());
    let e = applies(e, Edit::DeleteRungs { first: 1, last: 1 });
    let e = applies(e, Edit::MoveRung { index: 2, up: true });
    assert_eq!(e.ladder().rungs[1].get(Pos::new(0, 0)), Some(&no("X02")));
    assert_eq!(e.cursor().rung, 1, "the cursor goes with the rung");
    let e = applies(e, Edit::DeleteRungs { first: 0, last: 1 });
    assert_eq!(e.ladder().rungs[0].get(Pos::new(0, 0)), Some(&no("X01")));
    let e = applies(
        e,
        Edit::RungComment {
            index: 0,
            text: "Start".into(),
        },
    );
    let e = applies(
        e,
        Edit::DeviceComment {
            device: "X01".into(),
            text: "start button".into(),
        },
    );
    let mut e = applies(
        e,
        Edit::DeviceComment {
            device: "X01".into(),
            text: String::new(),
        },
    );
    assert!(e.ladder().device_comments.is_empty());
    refused(
        &mut e,
        Edit::MoveRung { index: 0, up: true },
        EditError::NothingToDo,
    );
    refused(
        &mut e,
        Edit::InsertRung { index: 9 },
        EditError::NoSuchRung(9),
    );
}

#[test]
fn paste_cells_and_rungs() {
    let e = three_rungs();
    let cells = Clip::cells(e.ladder(), at(0, 0, 0), at(0, 0, 0)).expect("one cell");
    let e = applies(
        e,
        Edit::Paste {
            at: at(1, 1, 0),
            clip: cells,
        },
    );
    assert_eq!(e.ladder().rungs[1].get(Pos::new(1, 0)), Some(&no("X00")));
    let rungs = Clip::rungs(e.ladder(), 0, 1).expect("two rungs");
    let n = e.ladder().rungs.len();
    let e = applies(
        e,
        Edit::Paste {
            at: at(0, 0, 0),
            clip: rungs,
        },
    );
    assert_eq!(e.ladder().rungs.len(), n + 2);
    assert_eq!(e.ladder().rungs[0], e.ladder().rungs[2]);
}

#[test]
fn replace_a_range_of_devices() {
    let e = applies(
        three_rungs(),
        Edit::ReplaceDevices {
            from: "X00-X02".into(),
            to: "X05-X07".into(),
        },
    );
    let contacts: Vec<_> = e
        .ladder()
        .rungs
        .iter()
        .filter_map(|r| r.get(Pos::new(0, 0)).cloned())
        .collect();
    assert_eq!(contacts, [no("X05"), no("X06"), no("X07")]);
    let mut e = e;
    let before = e.ladder().clone();
    assert!(matches!(
        e.apply(Edit::ReplaceDevices {
            from: "X00-X02".into(),
            to: "X05".into()
        }),
        Err(EditError::Replace(_))
    ));
    assert_eq!(e.ladder(), &before);
}

#[test]
fn a_new_ladder_is_one_undo_away_from_the_old() {
    let e = applies(three_rungs(), Edit::NewLadder);
    assert_eq!(e.ladder(), &Ladder::default());
    assert_eq!(e.cursor(), Cursor::default());
    assert_eq!(e.last_touched(), &[] as &[usize]);
}

#[test]
fn the_seed_program_drawn_edit_by_edit_compiles_like_the_seed_ladder() {
    let seed = Project::from_json(include_str!("../../programs/minasec-u/seed-test.json"))
        .expect("seed project");
    let mut e = Editor::default();
    let mut edit = |edit: Edit| {
        e.apply(edit.clone())
            .unwrap_or_else(|err| panic!("{edit:?}: {err}"))
    };
    let place = |rung, row, col, element| Edit::Place {
        at: at(rung, row, col),
        element,
    };
    // Rung 1: start / stop with self-hold.
    edit(place(0, 0, 0, no("X00")));
    edit(place(0, 0, 1, nc("X01")));
    edit(place(0, 0, 2, Element::coil("Y00")));
    edit(Edit::PlaceBranch {
        at: at(0, 1, 0),
        element: no("Y00"),
    });
    // Rung 2: the flicker's T0.
    edit(place(1, 0, 0, no("Y00")));
    edit(place(1, 0, 1, nc("T1")));
    edit(place(1, 0, 2, Element::coil("T0")));
    // Rung 3: T0 drives T1 and the counter.
    edit(place(2, 0, 0, no("T0")));
    edit(place(2, 1, 9, Element::coil("C0")));
    edit(place(2, 0, 1, Element::coil("T1")));
    edit(Edit::ToggleLink { at: at(2, 0, 9) });
    // Rungs 4 and 5.
    edit(place(3, 0, 0, no("C0")));
    edit(place(3, 0, 1, Element::coil("Y01")));
    edit(place(4, 0, 0, no("X02")));
    edit(place(4, 0, 1, Element::coil("C0R")));
    for (i, r) in seed.ladder.rungs.iter().enumerate() {
        edit(Edit::RungComment {
            index: i,
            text: r.comment.clone(),
        });
    }
    for (device, text) in &seed.ladder.device_comments {
        edit(Edit::DeviceComment {
            device: device.clone(),
            text: text.clone(),
        });
    }
    let ours = compile(e.ladder(), MachineId::MinasecU, Options::default()).expect("compiles");
    let theirs = compile(&seed.ladder, MachineId::MinasecU, Options::default()).expect("compiles");
    assert_eq!(ours, theirs);
}

#[test]
fn deleting_an_or_branchs_contact_takes_its_links_along() {
    // X00 and, below it, X01 in an OR branch; a second branch under X02
    // at column 1 whose links stay while it keeps its contact.
    let mut e = Editor::default();
    for (edit, what) in [
        (
            Edit::Place {
                at: at(0, 0, 0),
                element: no("X00"),
            },
            "X00",
        ),
        (
            Edit::PlaceBranch {
                at: at(0, 1, 0),
                element: no("X01"),
            },
            "X01",
        ),
        (
            Edit::Place {
                at: at(0, 0, 1),
                element: no("X02"),
            },
            "X02",
        ),
        (
            Edit::PlaceBranch {
                at: at(0, 1, 1),
                element: nc("X03"),
            },
            "X03",
        ),
    ] {
        e.apply(edit).unwrap_or_else(|err| panic!("{what}: {err}"));
    }
    let both = [Link { row: 0, col: 1 }, Link { row: 0, col: 2 }];
    assert_eq!(e.ladder().rungs[0].links, both);
    // X01 deleted: its right-hand link (col 1) still meets X03's left
    // edge, so both stay.
    let e = applies(e, Edit::Clear { at: at(0, 1, 0) });
    assert_eq!(e.ladder().rungs[0].links, both, "col 1 still joins X03");
    // X03 deleted too: nothing on the lower row, no stubs left.
    let e = applies(e, Edit::Clear { at: at(0, 1, 1) });
    assert_eq!(
        e.ladder().rungs[0].links,
        [],
        "no stub left hanging: {:?}",
        e.ladder().rungs[0]
    );
    // The same by a block cleared, in one undoable step.
    let mut e = Editor::default();
    for edit in [
        Edit::Place {
            at: at(0, 0, 0),
            element: no("X00"),
        },
        Edit::PlaceBranch {
            at: at(0, 1, 0),
            element: no("X01"),
        },
    ] {
        e.apply(edit).expect("drawn");
    }
    let e = applies(
        e,
        Edit::ClearBlock {
            from: at(0, 1, 0),
            to: at(0, 1, 0),
        },
    );
    assert_eq!(e.ladder().rungs[0].links, []);
    // A link drawn by hand with nothing yet below is the user's: a Clear
    // elsewhere leaves it.
    let mut e = Editor::default();
    for edit in [
        Edit::Place {
            at: at(0, 0, 0),
            element: no("X00"),
        },
        Edit::Place {
            at: at(0, 0, 2),
            element: no("X05"),
        },
        Edit::ToggleLink { at: at(0, 0, 1) },
    ] {
        e.apply(edit).expect("drawn");
    }
    let e = applies(e, Edit::Clear { at: at(0, 0, 2) });
    assert_eq!(e.ladder().rungs[0].links, [Link { row: 0, col: 1 }]);
}
