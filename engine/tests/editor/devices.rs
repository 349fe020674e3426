//! Devices: names, completion, cross-reference, find, the clip between
//! machines.

use std::collections::BTreeMap;

use engine::ladder::edit::{
    complete, device_names, find, xref, Clip, ClipError, Cursor, Edit, Editor, Found, Use, UseRole,
};
use engine::ladder::{Element, Pos};
use engine::MachineId;

use crate::no;

#[test]
fn every_machine_lists_its_devices() {
    let count = |m| device_names(m).len();
    assert_eq!(count(MachineId::MinasecU), 8 + 8 + 8 + 4 + 4);
    assert_eq!(count(MachineId::Io86a), 8 + 6 + 64 + 8 + 32 + 8 + 8);
    assert_eq!(count(MachineId::AvrPlc), 256);
    assert_eq!(count(MachineId::ArduinoPlc), 12);
    assert_eq!(device_names(MachineId::AvrPlc)[10], "R1.2");
}

#[test]
fn completion_offers_names_with_their_comments() {
    let comments = BTreeMap::from([("X01".to_string(), "stop".to_string())]);
    let offered = complete(MachineId::MinasecU, "x0", &comments);
    assert_eq!(offered.len(), 8);
    assert_eq!(offered[1], ("X01".to_string(), Some("stop".to_string())));
    let by_comment = complete(MachineId::MinasecU, "sto", &comments);
    assert_eq!(by_comment, [("X01".to_string(), Some("stop".to_string()))]);
}

fn drawn() -> Editor {
    let mut e = Editor::default();
    for edit in [
        Edit::Place {
            at: Cursor::new(0, 0, 0),
            element: no("X00"),
        },
        Edit::Place {
            at: Cursor::new(0, 0, 1),
            element: Element::coil("Y00"),
        },
        Edit::Place {
            at: Cursor::new(1, 0, 0),
            element: no("Y00"),
        },
        Edit::Place {
            at: Cursor::new(1, 0, 1),
            element: Element::coil("Y01"),
        },
        Edit::RungComment {
            index: 1,
            text: "Lamp follows".into(),
        },
        Edit::DeviceComment {
            device: "Y00".into(),
            text: "motor".into(),
        },
    ] {
        e.apply(edit).expect("edit");
    }
    e
}

#[test]
fn cross_reference_and_find() {
    let e = drawn();
    assert_eq!(
        xref(e.ladder(), "y00"),
        [
            Use {
                rung: 0,
                pos: Pos::new(0, 9),
                role: UseRole::Coil
            },
            Use {
                rung: 1,
                pos: Pos::new(0, 0),
                role: UseRole::Contact
            },
        ]
    );
    assert_eq!(find(e.ladder(), "MOTOR").len(), 2, "by device comment");
    assert_eq!(find(e.ladder(), "lamp"), [Found { rung: 1, pos: None }]);
    assert!(find(e.ladder(), "  ").is_empty());
}

#[test]
fn a_clip_travels_as_text_and_refuses_what_the_target_lacks() {
    let e = drawn();
    let clip = Clip::rungs(e.ladder(), 0, 1).expect("rungs");
    let text = clip.to_text();
    assert!(text.starts_with("hashigo-clip 1\n"));
    assert_eq!(Clip::from_text(&text), Ok(clip.clone()));
    assert!(matches!(
        Clip::from_text("{\"kind\":\"rungs\"}"),
        Err(ClipError::NotAClip(_))
    ));
    assert!(matches!(
        Clip::from_text("hashigo-clip 1\n[1,2]"),
        Err(ClipError::NotAClip(_))
    ));
    // MINASEC-U's X00 is the IO86A's too; the Arduino names pins X000.
    assert!(clip.for_machine(MachineId::Io86a).is_ok());
    let errors = clip
        .for_machine(MachineId::ArduinoPlc)
        .expect_err("other names");
    assert_eq!(errors.len(), 4);
    assert!(
        errors[0]
            .to_string()
            .starts_with("copied rung 1, row 1, column 1: unknown device"),
        "{}",
        errors[0]
    );
    // A paste that does not fit changes nothing.
    let cells = Clip::cells(e.ladder(), Cursor::new(0, 0, 0), Cursor::new(0, 0, 9)).expect("cells");
    let mut e = e;
    let before = e.ladder().clone();
    assert!(e
        .apply(Edit::Paste {
            at: Cursor::new(0, 0, 60),
            clip: cells
        })
        .is_err());
    assert_eq!(e.ladder(), &before);
}

#[test]
fn the_soft_plc_entry_offers_declared_variables_first() {
    use engine::ladder::edit::complete_declared;
    use engine::ladder::Variable;
    let mut level = Variable::new("level", "INT");
    level.comment = "tank level".into();
    let vars = [Variable::new("lamp", "BOOL"), level];
    let all = complete_declared(MachineId::SoftPlc, "", &Default::default(), &vars);
    assert_eq!(all[0], ("lamp".to_string(), Some("BOOL".to_string())));
    assert_eq!(all[1].0, "level");
    assert_eq!(all[2].0, "%IX0.0", "then the board's I/O");
    assert_eq!(all.len(), 18);
    let tank = complete_declared(MachineId::SoftPlc, "tank", &Default::default(), &vars);
    assert_eq!(
        tank,
        [("level".to_string(), Some("tank level".to_string()))]
    );
    let q = complete_declared(MachineId::SoftPlc, "%q", &Default::default(), &vars);
    assert_eq!(q.len(), 8);
}
