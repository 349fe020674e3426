//! A PLCopen project's Structured Text on the soft PLC (issue #55): its
//! ST POUs come back as one `.st` text for the ST pane, beside the
//! ladder its drawn programs make (an empty one when none is drawn).

use super::*;

const OWN: &str = include_str!("../../engine/tests/ladder/fixtures/soft-st.xml");

fn import_on(machine: MachineId, text: &str, pou: Option<&str>) -> ImportReply {
    match handle(Request::Import {
        file: "p.xml".into(),
        text: text.into(),
        machine,
        rows: None,
        pou: pou.map(str::to_string),
    }) {
        Reply::Import(reply) => reply,
        other => panic!("{other:?}"),
    }
}

/// `OWN` without its LD program: every POU in ST.
fn st_only() -> String {
    let start = OWN.find("<pou name=\"inline\"").expect("the LD program");
    let end = start + OWN[start..].find("</pou>").expect("its end") + "</pou>".len();
    let text = format!("{}{}", &OWN[..start], &OWN[end..]);
    text.replace("<pouInstance name=\"inlineInst\" typeName=\"inline\"/>", "")
}

/// `OWN` with its LD program a plain contact and coil (the ladder does
/// not draw CODESYS's EXECUTE block): a project mixing LD and ST.
fn mixed() -> String {
    let start = OWN.find("<block localId=\"3\"").expect("the EXECUTE block");
    let end = start + OWN[start..].find("</block>").expect("its end") + "</block>".len();
    format!("{}{}", &OWN[..start], &OWN[end..]).replace(
        "<connection refLocalId=\"3\"/></connectionPointIn><connectionPointOut/><variable>seen",
        "<connection refLocalId=\"2\"/></connectionPointIn><connectionPointOut/><variable>seen",
    )
}

#[test]
fn a_project_all_in_st_opens_with_its_text_and_an_empty_ladder() {
    let reply = import_on(MachineId::SoftPlc, &st_only(), None);
    assert!(reply.errors.is_empty(), "{:?}", reply.errors);
    let ladder = reply.ladder.expect("a ladder, empty");
    assert!(ladder.rungs.is_empty(), "{ladder:?}");
    let st = reply.st.expect("the ST text");
    assert!(st.contains("FUNCTION_BLOCK Counter"), "{st}");
    assert!(st.contains("PROGRAM main"), "{st}");
    // It is the project's ST as a `.st` text: it runs as one.
    let run = engine::softplc::st::st_run(&st).expect("runs");
    let line = st
        .lines()
        .position(|l| l.contains("count := c0.OUT;"))
        .expect("a line")
        + 1;
    assert!(run.lines.contains(&Some(line)), "{:?}", run.lines);
}

#[test]
fn a_project_mixing_ld_and_st_opens_its_ladder_and_its_st_apart() {
    let reply = import_on(MachineId::SoftPlc, &mixed(), None);
    assert!(reply.errors.is_empty(), "{:?}", reply.errors);
    let ladder = reply.ladder.expect("the LD program drawn");
    assert_eq!(ladder.rungs.len(), 1, "{ladder:?}");
    let st = reply.st.expect("the ST POUs beside it");
    assert!(
        st.contains("PROGRAM main") && !st.contains("PROGRAM inline"),
        "{st}"
    );
    // One POU picked: that POU alone, no ST text.
    let one = import_on(MachineId::SoftPlc, &mixed(), Some("inline"));
    assert!(one.ladder.is_some(), "{:?}", one.errors);
    assert_eq!(one.st, None);
}

#[test]
fn a_project_without_st_has_no_st_text() {
    let timer = include_str!("../../engine/tests/ladder/fixtures/openplc-timer.xml");
    let reply = import_on(MachineId::SoftPlc, timer, None);
    assert!(reply.ladder.is_some(), "{:?}", reply.errors);
    assert_eq!(reply.st, None);
}

#[test]
fn an_st_project_on_another_machine_is_refused_and_names_the_soft_plc() {
    let reply = import_on(MachineId::MinasecU, &st_only(), None);
    assert!(reply.ladder.is_none());
    assert!(!reply.errors.is_empty());
    assert_eq!(reply.st, None);
    assert_eq!(
        reply.runs_on,
        Some(MachineId::SoftPlc),
        "{:?}",
        reply.errors
    );
}

#[test]
fn a_project_whose_st_does_not_load_still_opens_with_its_text() {
    // The pane shows the ST's own errors at their lines, as typed.
    let broken = st_only().replace("Cnt := Cnt + 1;", "Cnt := Cnt + ;");
    let reply = import_on(MachineId::SoftPlc, &broken, None);
    assert!(reply.errors.is_empty(), "{:?}", reply.errors);
    let st = reply.st.expect("the text, errors and all");
    assert!(st.contains("Cnt := Cnt + ;"));
    assert!(engine::softplc::st::st_run(&st).is_err());
}
