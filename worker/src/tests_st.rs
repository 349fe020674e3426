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

/// A project whose LD program calls its own ST block `Doubler`
/// (`y := x * 2` while `go`): `start` powers the box, `done` the lamp.
fn ld_calling_st() -> String {
    let block = r#"<pou name="Doubler" pouType="functionBlock"><interface>
<inputVars><variable name="go"><type><BOOL/></type></variable><variable name="x"><type><INT/></type></variable></inputVars>
<outputVars><variable name="done"><type><BOOL/></type></variable><variable name="y"><type><INT/></type></variable></outputVars>
</interface><body><ST><xhtml:p xmlns:xhtml="http://www.w3.org/1999/xhtml"><![CDATA[done := go;
IF go THEN
  y := x * 2;
END_IF;]]></xhtml:p></ST></body></pou>"#;
    let program = r#"<pou name="main" pouType="program"><interface><localVars>
<variable name="start" address="%IX0.0"><type><BOOL/></type></variable>
<variable name="lamp" address="%QX0.0"><type><BOOL/></type></variable>
<variable name="d1"><type><derived name="Doubler"/></type></variable>
</localVars></interface><body><LD>
<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut/></leftPowerRail>
<contact localId="2"><position x="20" y="0"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>start</variable></contact>
<inVariable localId="3"><position x="20" y="40"/><connectionPointOut/><expression>21</expression></inVariable>
<block localId="4" typeName="Doubler" instanceName="d1"><position x="60" y="0"/>
<inputVariables><variable formalParameter="go"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></variable><variable formalParameter="x"><connectionPointIn><connection refLocalId="3"/></connectionPointIn></variable></inputVariables>
<inOutVariables/><outputVariables><variable formalParameter="done"><connectionPointOut/></variable><variable formalParameter="y"><connectionPointOut/></variable></outputVariables></block>
<coil localId="5"><position x="120" y="0"/><connectionPointIn><connection refLocalId="4" formalParameter="done"/></connectionPointIn><connectionPointOut/><variable>lamp</variable></coil>
<rightPowerRail localId="6"><position x="200" y="0"/><connectionPointIn><connection refLocalId="5"/></connectionPointIn></rightPowerRail>
</LD></body></pou>"#;
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201"><types><pous>{block}{program}</pous></types>
<instances><configurations><configuration name="c"><resource name="r">
<task name="t" priority="0" interval="T#10ms"><pouInstance name="m" typeName="main"/></task>
</resource></configuration></configurations></instances></project>"#
    )
}

#[test]
fn a_drawn_program_calling_the_projects_st_block_opens_with_its_box_and_the_block_in_the_pane() {
    let reply = import_on(MachineId::SoftPlc, &ld_calling_st(), None);
    assert!(reply.errors.is_empty(), "{:?}", reply.errors);
    let ladder = reply.ladder.expect("the LD program drawn");
    let kinds: Vec<String> = ladder
        .rungs
        .iter()
        .flat_map(|r| r.elements())
        .filter_map(|(_, e)| e.block().map(|b| format!("{}: {}", b.instance, b.kind)))
        .collect();
    assert_eq!(kinds, ["d1: DOUBLER"], "{ladder:?}");
    let st = reply.st.expect("the block in the pane");
    assert!(st.contains("FUNCTION_BLOCK Doubler"), "{st}");
    // The pane's text declares the box's type (a library: the ladder
    // runs, calling it).
    let blocks = engine::softplc::st::st_blocks(&st).expect("loads");
    assert!(!blocks.program);
    assert_eq!(blocks.blocks[0].name, "DOUBLER");
    // On a bit machine it is refused at the block, as before.
    let io = import_on(MachineId::Io86a, &ld_calling_st(), None);
    assert!(io.ladder.is_none());
    assert!(
        io.errors.iter().any(|e| e.contains("Doubler")),
        "{:?}",
        io.errors
    );
}

#[test]
fn a_project_with_two_st_programs_opens_with_both_in_the_pane_and_they_run() {
    // `OWN`'s ST program twice, under two names, both run by the task.
    let only = st_only();
    let start = only.find("<pou name=\"main\"").expect("the ST program");
    let end = start + only[start..].find("</pou>").expect("its end") + "</pou>".len();
    let again = only[start..end].replace("name=\"main\"", "name=\"again\"");
    let text = format!("{}{again}{}", &only[..end], &only[end..]).replace(
        "<pouInstance name=\"mainInst\" typeName=\"main\"/>",
        "<pouInstance name=\"mainInst\" typeName=\"main\"/><pouInstance name=\"i2\" typeName=\"again\"/>",
    );
    let reply = import_on(MachineId::SoftPlc, &text, None);
    assert!(reply.errors.is_empty(), "{:?}", reply.errors);
    assert!(reply.ladder.expect("an empty ladder").rungs.is_empty());
    let st = reply.st.expect("the ST text");
    assert!(
        st.contains("PROGRAM main") && st.contains("PROGRAM again"),
        "{st}"
    );
    let run = engine::softplc::st::st_run(&st).unwrap_or_else(|e| panic!("{e:?}\n{st}"));
    let line = st
        .rfind("count := c0.OUT;")
        .map(|at| st[..at].lines().count() + 1);
    let line = line.expect("the second program's line");
    assert!(run.lines.contains(&Some(line)), "{:?}", run.lines);
    assert_eq!(run.il_name(line, "count"), "again_count");
}
