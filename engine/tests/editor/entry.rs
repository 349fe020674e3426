//! The device entry (F5–F8), the whole-ladder replace, and the listing's
//! steps by rung.

use engine::formats::Project;
use engine::ladder::compile::{compile, compile_listing, Options};
use engine::ladder::edit::{parse_entry, Edit, EditError, Editor, EntryError, EntryKind};
use engine::ladder::TimerKind;
use engine::ladder::{CoilKind, ContactKind, Element, Ladder, Rung};
use engine::MachineId;

use super::{nc, no};

fn entry(machine: MachineId, kind: EntryKind, text: &str) -> Result<Element, EntryError> {
    parse_entry(machine, kind, text)
}

#[test]
fn devices_are_read_in_the_machines_spelling() {
    use EntryKind::*;
    assert_eq!(entry(MachineId::Io86a, Open, "x0"), Ok(no("X00")));
    assert_eq!(entry(MachineId::MinasecU, Closed, " X01 "), Ok(nc("X01")));
    assert_eq!(
        entry(MachineId::MinasecU, Coil, "Y00"),
        Ok(Element::coil("Y00"))
    );
    assert_eq!(entry(MachineId::AvrPlc, Open, "R0.1"), Ok(no("R0.1")));
}

#[test]
fn a_device_the_machine_lacks_is_refused_with_the_engines_message() {
    let e = entry(MachineId::MinasecU, EntryKind::Open, "X09").unwrap_err();
    assert!(matches!(e, EntryError::Element(_)), "{e:?}");
    let e = entry(MachineId::Io86a, EntryKind::Coil, "X00").unwrap_err();
    assert_eq!(
        e.to_string(),
        "X00 cannot be driven here: use a Y, M or S device (C only with set/reset)"
    );
    assert_eq!(
        entry(MachineId::Io86a, EntryKind::Open, "   "),
        Err(EntryError::Empty)
    );
}

#[test]
fn instructions_in_words() {
    let i = |m, t| entry(m, EntryKind::Instruction, t);
    assert_eq!(
        i(MachineId::Io86a, "SET Y00"),
        Ok(Element::Coil {
            kind: CoilKind::Set,
            device: "Y00".into()
        })
    );
    assert_eq!(
        i(MachineId::Io86a, "rst c0"),
        Ok(Element::Coil {
            kind: CoilKind::Reset,
            device: "C00".into()
        })
    );
    assert_eq!(
        i(MachineId::Io86a, "OUT T00 K10"),
        Ok(Element::TimerCoil {
            device: "T00".into(),
            preset: 10
        })
    );
    assert_eq!(
        i(MachineId::Io86a, "MOV K50 D00"),
        Ok(Element::Mov {
            src: "K50".into(),
            dst: "D00".into()
        })
    );
    assert_eq!(
        i(MachineId::Io86a, "LDP X03"),
        Ok(Element::Contact {
            kind: ContactKind::Rising,
            device: "X03".into()
        })
    );
    assert_eq!(
        i(MachineId::AvrPlc, "TON t1 1.5s"),
        Ok(Element::Timer {
            kind: TimerKind::Ton,
            name: "t1".into(),
            preset_ms: 1500
        })
    );
    assert_eq!(i(MachineId::AvrPlc, "NOT"), Ok(Element::Not));
}

#[test]
fn instructions_the_machine_lacks_or_misspelt_are_refused() {
    let i = |m, t| entry(m, EntryKind::Instruction, t);
    assert!(matches!(
        i(MachineId::MinasecU, "TON t 1s"),
        Err(EntryError::Element(_))
    ));
    assert!(matches!(
        i(MachineId::ArduinoPlc, "PLS Y000"),
        Err(EntryError::Element(_))
    ));
    assert_eq!(
        i(MachineId::Io86a, "JMP X"),
        Err(EntryError::UnknownWord("JMP".into()))
    );
    assert_eq!(
        i(MachineId::Io86a, "OUT T00 Kx"),
        Err(EntryError::BadNumber("Kx".into()))
    );
    assert_eq!(
        i(MachineId::Io86a, "MOV K50"),
        Err(EntryError::Usage("MOV K50 D00"))
    );
    assert!(matches!(
        i(MachineId::AvrPlc, "TON t 1e999s"),
        Err(EntryError::BadNumber(_))
    ));
}

fn seed() -> Ladder {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/programs/minasec-u/seed-test.json"
    ))
    .expect("seed project");
    Project::from_json(&text).expect("seed reads").ladder
}

#[test]
fn replace_swaps_the_whole_ladder_and_undo_brings_it_back() {
    let mut editor = Editor::new(seed());
    let other = Ladder {
        rungs: vec![Rung::default()],
        ..Ladder::default()
    };
    editor
        .apply(Edit::Replace {
            ladder: other.clone(),
        })
        .expect("replaces");
    assert_eq!(editor.ladder(), &other);
    assert_eq!(
        editor.apply(Edit::Replace { ladder: other }),
        Err(EditError::NothingToDo)
    );
    assert!(editor.undo());
    assert_eq!(editor.ladder(), &seed());
}

#[test]
fn the_listing_numbers_each_rung_by_its_first_step() {
    let mut ladder = seed();
    // An empty rung compiles to nothing and has no steps.
    ladder.rungs.insert(1, Rung::default());
    let listing =
        compile_listing(&ladder, MachineId::MinasecU, Options::default()).expect("compiles");
    assert_eq!(
        listing.text,
        compile(&ladder, MachineId::MinasecU, Options::default()).expect("compiles")
    );
    // The seed's rungs: 4, 3, 3, 2 and 2 steps.
    assert_eq!(listing.steps_of(0), Some(0..4));
    assert_eq!(listing.steps_of(1), None);
    assert_eq!(listing.steps_of(2), Some(4..7));
    assert_eq!(listing.steps_of(5), Some(12..14));
    assert_eq!(listing.rung_of_step(5), Some(2));
    assert_eq!(listing.rung_of_step(14), None);
    let lines: Vec<&str> = listing.text.lines().collect();
    assert_eq!(lines[listing.step_lines[4]], "004 LD   Y00");
    assert_eq!(listing.step_at_line(listing.step_lines[4]), Some(4));
    assert_eq!(listing.step_at_line(0), None);
}

#[test]
fn the_listing_ends_before_the_end_marker_on_the_other_machines() {
    let ladder = Ladder {
        rungs: vec![Rung {
            cells: vec![vec![Some(no("X00")), Some(Element::coil("Y00"))]],
            ..Rung::default()
        }],
        ..Ladder::default()
    };
    let listing = compile_listing(&ladder, MachineId::Io86a, Options::default()).expect("ok");
    assert_eq!(listing.steps_of(0), Some(0..2));
    assert_eq!(listing.step_lines.len(), 3, "{}", listing.text);
    assert_eq!(listing.rung_of_step(2), None);
    let avr = Ladder {
        rungs: vec![Rung {
            cells: vec![vec![Some(no("R0.0")), Some(Element::coil("R1.0"))]],
            ..Rung::default()
        }],
        ..Ladder::default()
    };
    let listing = compile_listing(&avr, MachineId::AvrPlc, Options::default()).expect("ok");
    assert_eq!(listing.steps_of(0), Some(0..2), "{}", listing.text);
}
