//! The grid model: wiring checks located at their cells, capability
//! tables, the reference evaluator's per-element power, the project file.

use engine::formats::Project;
use engine::ladder::compile::{compile, Options};
use engine::ladder::eval::Reference;
use engine::ladder::target::capabilities;
use engine::ladder::{
    analyse, CoilKind, ContactKind, Element, Ladder, LadderError, Link, Pos, Rung, TimerKind,
};
use engine::MachineId;

/// A rung from rows of cell codes: `X00` NO contact, `/X00` NC, `-` wire,
/// `.` empty, `(Y00)` coil, `[NOT]` in-line NOT.
fn rung(rows: &[&str], links: &[(usize, usize)]) -> Rung {
    let mut r = Rung::default();
    for (i, row) in rows.iter().enumerate() {
        for (j, code) in row.split_whitespace().enumerate() {
            let e = match code {
                "." => None,
                "-" => Some(Element::Wire),
                "[NOT]" => Some(Element::Not),
                c if c.starts_with('(') => Some(Element::coil(c.trim_matches(['(', ')']))),
                c if c.starts_with('/') => Some(Element::nc(&c[1..])),
                c => Some(Element::no(c)),
            };
            r.set(Pos::new(i, j), e);
        }
    }
    r.links = links.iter().map(|&(row, col)| Link { row, col }).collect();
    r
}

fn errors(r: &Rung) -> Vec<String> {
    analyse(r, 2)
        .expect_err("a wiring error")
        .iter()
        .map(LadderError::to_string)
        .collect()
}

#[test]
fn wiring_errors_name_rung_and_cell() {
    // An output that is not in the last column.
    assert_eq!(
        errors(&rung(&["X00 (Y00) .", "X01 - (Y01)"], &[])),
        [
            "rung 3, row 1, column 2: outputs must line up in the rung's last column: move this one right",
        ]
    );
    // A contact after the coil column.
    assert!(errors(&rung(&["X00 (Y00)", ". . X01"], &[]))[0]
        .contains("row 2, column 3: nothing may follow an output"));
    // A contact bridged by a link on both sides.
    assert_eq!(
        errors(&rung(&["X00 X01 (Y00)", "X02 - ."], &[(0, 1), (0, 2)])),
        ["rung 3, row 1, column 2: short circuit: a wire joins both sides of this element"]
    );
    // A contact that leads nowhere, and a wire that leads nowhere.
    let e = errors(&rung(&["X00 (Y00)", "X01 ."], &[]));
    assert_eq!(e, ["rung 3, row 2, column 1: dangling: this element is not on a path from the left rail to the outputs"]);
    let e = errors(&rung(&["X00 X01 (Y00)", ". - ."], &[]));
    assert_eq!(
        e,
        ["rung 3, row 2, column 2: dangling wire: it does not join the left rail to the outputs"]
    );
    // Two outputs on different conditions.
    let e = errors(&rung(&["X00 (Y00)", "X01 (Y01)"], &[]));
    assert!(
        e[0].starts_with("rung 3, row 2, column 2: this output is not joined"),
        "{e:?}"
    );
    // No output; an output straight on the rail.
    assert_eq!(
        errors(&rung(&["X00 X01"], &[])),
        ["rung 3: the rung has no output: end it with a coil or an output box"]
    );
    assert!(errors(&rung(&["(Y00)"], &[]))[0].contains("wired straight to the left rail"));
    // A link below the last row.
    assert!(errors(&rung(&["X00 (Y00)"], &[(0, 1)]))[0].contains("vertical link reaches past"));
}

#[test]
fn a_bridge_is_not_series_parallel() {
    // X00 then X01 on top, X02 then X03 below, X04 joining their middle
    // points: the Wheatstone bridge, which no series-parallel form holds.
    let r = rung(
        &["X00 - X01 (Y00)", ". X04 . .", "X02 - X03 ."],
        &[(0, 1), (1, 2), (0, 3), (1, 3)],
    );
    let e = analyse(&r, 0).expect_err("not drawable as blocks");
    assert_eq!(e.len(), 1, "{e:?}");
    assert!(e[0].message.contains("not series-parallel"), "{e:?}");
}

#[test]
fn machines_refuse_what_they_lack_by_name() {
    let boxed = |e: Element| {
        let mut r = rung(&["X000 - (Y000)"], &[]);
        r.set(Pos::new(0, 1), Some(e));
        Ladder {
            rungs: vec![r],
            ..Ladder::default()
        }
    };
    let timer = Element::Timer {
        kind: TimerKind::Ton,
        name: "t".into(),
        preset_ms: 100,
    };
    let e = boxed(timer.clone())
        .logic(MachineId::ArduinoPlc)
        .expect_err("no timers");
    assert_eq!(e[0].to_string(), "rung 1, row 1, column 2: arduino-plc has no in-line TON t box (the Arduino sketch has no timers)");
    let mut io = boxed(timer);
    io.rungs[0].set(Pos::new(0, 0), Some(Element::no("X00")));
    io.rungs[0].set(Pos::new(0, 2), Some(Element::coil("Y00")));
    assert!(io.logic(MachineId::Io86a).expect_err("no in-line timer")[0]
        .message
        .contains("io86a has no in-line TON"));
    // Coils on inputs; unknown devices.
    let l = Ladder {
        rungs: vec![rung(&["X00 (X01)"], &[])],
        ..Ladder::default()
    };
    assert_eq!(
        l.logic(MachineId::MinasecU).expect_err("input")[0].message,
        "X01 is an input: a coil cannot drive it"
    );
    let l = Ladder {
        rungs: vec![rung(&["X08 (Y00)"], &[])],
        ..Ladder::default()
    };
    assert!(l.logic(MachineId::MinasecU).expect_err("X08")[0]
        .message
        .starts_with("unknown device \"X08\""));
    // The palette's table says the same.
    assert!(!capabilities(MachineId::ArduinoPlc).inline_boxes);
    assert!(!capabilities(MachineId::ArduinoPlc)
        .contacts
        .contains(&ContactKind::Rising));
    assert!(capabilities(MachineId::Io86a).timer_counter_coils);
    assert!(capabilities(MachineId::AvrPlc).inline_boxes);
}

#[test]
fn avr_in_line_boxes_stay_on_the_main_line() {
    let mut r = rung(&["R0.0 - (R1.0)", "R0.1 [NOT] ."], &[(0, 2)]);
    r.set(Pos::new(0, 1), Some(Element::Wire));
    let l = Ladder {
        rungs: vec![r],
        ..Ladder::default()
    };
    let e = compile(&l, MachineId::AvrPlc, Options::default()).expect_err("NOT in a branch");
    assert_eq!(e[0].to_string(), "rung 1, row 2, column 2: an in-line box (NOT, edge, timer) must stand on the rung's main line, not in a parallel branch");
}

#[test]
fn minasec_runs_out_of_steps_and_temporaries_with_a_clear_error() {
    let many = Ladder {
        rungs: vec![rung(&["X00 X01 (Y00)"], &[]); 90],
        ..Ladder::default()
    };
    let e = compile(&many, MachineId::MinasecU, Options::default()).expect_err("270 steps");
    assert_eq!(
        e[0].to_string(),
        "rung 86: the program needs 258 steps by this rung: MINASEC-U has 256"
    );
    // The ladder itself uses every M relay but M10: one temporary only.
    let mut l = Ladder {
        rungs: Vec::new(),
        ..Ladder::default()
    };
    let relays = [
        "M00", "M01", "M02", "M03", "M04", "M05", "M06", "M07", "M11", "M12", "M13",
    ];
    for m in relays {
        l.rungs.push(rung(&[&format!("X07 ({m})")], &[]));
    }
    // Series of two parallel groups: the second needs a temporary.
    l.rungs
        .push(rung(&["X00 X02 (Y00)", "X01 X03 ."], &[(0, 1), (0, 2)]));
    l.rungs.push(rung(
        &["X00 X02 X04 (Y01)", "X01 X03 X05 ."],
        &[(0, 1), (0, 2), (0, 3)],
    ));
    let e = compile(&l, MachineId::MinasecU, Options::default()).expect_err("one temporary");
    assert!(
        e[0].to_string().starts_with("rung 13, row 1, column 1: the rung needs more temporary relays than are free (M10-M13, then unused M00-M07)"),
        "{e:?}"
    );
}

#[test]
fn the_reference_reports_power_per_element() {
    let r = rung(&["X00 /X01 (Y00)", "Y00 . ."], &[(0, 1)]);
    let logic = analyse(&r, 0).expect("draws").expect("not empty");
    let mut reference = Reference::new(vec![logic], 10).expect("runs");
    reference.set("X00", true);
    let power = reference.scan();
    let at = |row, col| {
        power[0]
            .iter()
            .find(|p| p.pos == Pos::new(row, col))
            .map(|p| (p.power_in, p.power_out))
    };
    assert_eq!(at(0, 0), Some((true, true)), "X00 on");
    assert_eq!(at(1, 0), Some((true, false)), "Y00 still off");
    assert_eq!(at(0, 1), Some((true, true)), "X01 off: NC passes");
    assert_eq!(at(0, 2), Some((true, true)), "the coil gets power");
    assert!(reference.get("Y00"));
    // Self-hold: X00 released, Y00 keeps itself on; X01 breaks it.
    reference.set("X00", false);
    reference.scan();
    assert!(reference.get("Y00"));
    reference.set("X01", true);
    let power = reference.scan();
    assert!(!reference.get("Y00"));
    assert_eq!(
        power[0]
            .iter()
            .find(|p| p.pos == Pos::new(0, 1))
            .map(|p| p.power_out),
        Some(false)
    );
}

#[test]
fn projects_round_trip_through_json() {
    let mut l = Ladder {
        rungs: vec![rung(&["X00 (Y00)"], &[])],
        ..Ladder::default()
    };
    l.rungs[0].comment = "motor".into();
    l.device_comments.insert("X00".into(), "start".into());
    l.rungs.push(Rung::default());
    l.rungs[1].set(
        Pos::new(0, 0),
        Some(Element::Coil {
            kind: CoilKind::Set,
            device: "M00".into(),
        }),
    );
    let mut p = Project::new(MachineId::MinasecU, l);
    p.settings.insert("T0".into(), "0.5s".into());
    assert_eq!(Project::from_json(&p.to_json()), Ok(p));
}

#[test]
fn minasec_counter_reset_coil_is_st_c0r() {
    let mut r = rung(&["X02 (C0)"], &[]);
    r.set(
        Pos::new(0, 1),
        Some(Element::Coil {
            kind: CoilKind::Reset,
            device: "C0".into(),
        }),
    );
    let l = Ladder {
        rungs: vec![r],
        ..Ladder::default()
    };
    let text = compile(&l, MachineId::MinasecU, Options::default()).expect("compiles");
    assert!(text.contains("000 LD   X02\n001 ST   C0R\n"), "{text}");
    let mut r = rung(&["X02 (T0)"], &[]);
    r.set(
        Pos::new(0, 1),
        Some(Element::Coil {
            kind: CoilKind::Set,
            device: "T0".into(),
        }),
    );
    let l = Ladder {
        rungs: vec![r],
        ..Ladder::default()
    };
    let e = l.logic(MachineId::MinasecU).expect_err("set on a timer");
    assert!(
        e[0].message.starts_with("a set coil on T0 has no meaning"),
        "{e:?}"
    );
}
