//! Random edit sequences: undone to the start they give the empty
//! project back, redone they give the same project again.

use engine::ladder::edit::{Clip, Cursor, Edit, Editor};
use engine::ladder::{CoilKind, ContactKind, Element, Ladder};
use proptest::prelude::*;

fn element() -> impl Strategy<Value = Element> {
    let device = prop::sample::select(vec!["X00", "X01", "Y00", "M10", "T0", "C0"]);
    prop_oneof![
        (device.clone(), any::<bool>()).prop_map(|(d, nc)| Element::Contact {
            kind: if nc { ContactKind::Nc } else { ContactKind::No },
            device: d.into(),
        }),
        device.prop_map(|d| Element::Coil {
            kind: CoilKind::Normal,
            device: d.into()
        }),
        Just(Element::Not),
    ]
}

fn cursor() -> impl Strategy<Value = Cursor> {
    (0usize..4, 0usize..4, 0usize..11).prop_map(|(r, row, col)| Cursor::new(r, row, col))
}

fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        4 => (cursor(), element()).prop_map(|(at, element)| Edit::Place { at, element }),
        2 => (cursor(), element()).prop_map(|(at, element)| Edit::PlaceBranch { at, element }),
        1 => cursor().prop_map(|at| Edit::Wire { at }),
        1 => cursor().prop_map(|at| Edit::ToggleLink { at }),
        1 => cursor().prop_map(|at| Edit::Clear { at }),
        1 => (cursor(), cursor()).prop_map(|(from, to)| Edit::ClearBlock { from, to: Cursor { rung: from.rung, ..to } }),
        1 => (0usize..4).prop_map(|index| Edit::InsertRung { index }),
        1 => (0usize..4, 0usize..4).prop_map(|(first, last)| Edit::DeleteRungs { first, last }),
        1 => (0usize..4, any::<bool>()).prop_map(|(index, up)| Edit::MoveRung { index, up }),
        1 => (0usize..4, "[a-z ]{0,8}").prop_map(|(index, text)| Edit::RungComment { index, text }),
        1 => ("X0[0-3]", "[a-z]{0,5}").prop_map(|(device, text)| Edit::DeviceComment { device, text }),
        1 => Just(Edit::ReplaceDevices { from: "X00-X01".into(), to: "X02-X03".into() }),
        1 => Just(Edit::NewLadder),
        1 => (0usize..4, cursor()).prop_map(|(first, at)| Edit::Paste {
            at,
            clip: Clip::Rungs { rungs: vec![Default::default(); first % 2 + 1] },
        }),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 1000, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn random_edits_undo_to_the_start_and_redo_to_the_end(
        edits in prop::collection::vec(edit(), 1..40),
        moves in prop::collection::vec(cursor(), 1..40),
    ) {
        let mut e = Editor::default();
        let mut applied = 0;
        // The ladder and the cursor after the last edit that applied (a
        // cursor move alone is no edit).
        let mut end = (Ladder::default(), Cursor::default());
        for (edit, to) in edits.into_iter().zip(moves.into_iter().cycle()) {
            e.move_to(to);
            if e.apply(edit).is_ok() {
                applied += 1;
                end = (e.ladder().clone(), e.cursor());
            }
        }
        for _ in 0..applied {
            prop_assert!(e.undo());
        }
        prop_assert!(!e.undo());
        prop_assert_eq!(e.ladder(), &Ladder::default());
        for _ in 0..applied {
            prop_assert!(e.redo());
        }
        prop_assert!(!e.redo());
        prop_assert_eq!(e.ladder(), &end.0);
        if applied > 0 {
            prop_assert_eq!(e.cursor(), end.1, "redo leaves the cursor where the last edit did");
        }
        // And a clip of everything round-trips through its text.
        if !e.ladder().rungs.is_empty() {
            let clip = Clip::rungs(e.ladder(), 0, e.ladder().rungs.len() - 1).expect("rungs");
            prop_assert_eq!(Clip::from_text(&clip.to_text()), Ok(clip));
        }
    }
}
