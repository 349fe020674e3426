//! A drawn (LD) program of a PLCopen project calling the project's own
//! Structured Text function block (issue #55): on the soft PLC the block
//! is a ladder box of its type, declared from the project's ST as the ST
//! pane declares it, and the ladder runs it; the command line's soft PLC
//! path runs the file as written. A project block that cannot be a box
//! (IL, drawn) is still refused at the block.

use engine::events::InputValue;
use engine::formats::plcopen::{Document, ImportError};
use engine::ladder::compile::{compile, Options};
use engine::ladder::{user_blocks, Element};
use engine::machines::new_plc;
use engine::plc::{Command, Plc};
use engine::{MachineId, SimTime};

/// `Doubler` in ST (`done := go`, `y := x * 2` while go) and program
/// `main` in LD: `start` powers `d1: Doubler(x := 21)`, its `done` the
/// coil `lamp`, its `y` the variable `result`.
pub(crate) fn ld_calling_st(block_body: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201"><types><pous>
<pou name="Doubler" pouType="functionBlock"><interface>
<inputVars><variable name="go"><type><BOOL/></type></variable><variable name="x"><type><INT/></type></variable></inputVars>
<outputVars><variable name="done"><type><BOOL/></type></variable><variable name="y"><type><INT/></type></variable></outputVars>
</interface><body>{block_body}</body></pou>
<pou name="main" pouType="program"><interface><localVars>
<variable name="start" address="%IX0.0"><type><BOOL/></type></variable>
<variable name="lamp" address="%QX0.0"><type><BOOL/></type></variable>
<variable name="result"><type><INT/></type></variable>
<variable name="d1"><type><derived name="Doubler"/></type></variable>
</localVars></interface><body><LD>
<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut/></leftPowerRail>
<contact localId="2"><position x="20" y="0"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>start</variable></contact>
<inVariable localId="3"><position x="20" y="40"/><connectionPointOut/><expression>21</expression></inVariable>
<block localId="4" typeName="Doubler" instanceName="d1"><position x="60" y="0"/>
<inputVariables><variable formalParameter="go"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></variable><variable formalParameter="x"><connectionPointIn><connection refLocalId="3"/></connectionPointIn></variable></inputVariables>
<inOutVariables/><outputVariables><variable formalParameter="done"><connectionPointOut/></variable><variable formalParameter="y"><connectionPointOut/></variable></outputVariables></block>
<outVariable localId="5"><position x="120" y="40"/><connectionPointIn><connection refLocalId="4" formalParameter="y"/></connectionPointIn><expression>result</expression></outVariable>
<coil localId="6"><position x="120" y="0"/><connectionPointIn><connection refLocalId="4" formalParameter="done"/></connectionPointIn><connectionPointOut/><variable>lamp</variable></coil>
<rightPowerRail localId="7"><position x="200" y="0"/><connectionPointIn><connection refLocalId="6"/></connectionPointIn></rightPowerRail>
</LD></body></pou>
</pous></types><instances><configurations><configuration name="c"><resource name="r">
<task name="t" priority="0" interval="T#10ms"><pouInstance name="m" typeName="main"/></task>
</resource></configuration></configurations></instances></project>"#
    )
}

pub(crate) const ST_BODY: &str = r#"<ST><xhtml:p xmlns:xhtml="http://www.w3.org/1999/xhtml"><![CDATA[done := go;
IF go THEN
  y := x * 2;
END_IF;]]></xhtml:p></ST>"#;

const IL_BODY: &str = r#"<IL><xhtml:p xmlns:xhtml="http://www.w3.org/1999/xhtml"><![CDATA[LD go
ST done]]></xhtml:p></IL>"#;

fn get(plc: &dyn Plc, device: &str) -> i64 {
    plc.read(plc.device(device).expect(device)).as_i64()
}

fn switch_on(plc: &mut dyn Plc, device: &str) {
    let d = plc.device(device).expect(device);
    plc.apply(Command::SetInput(d, InputValue::Int(1)))
        .expect("on");
}

#[test]
fn a_drawn_program_calling_an_st_block_opens_with_a_box_of_its_type_and_runs() {
    user_blocks::set(Vec::new(), String::new());
    let xml = ld_calling_st(ST_BODY);
    let document = Document::read(&xml).expect("reads");
    let imported = document
        .import(Some(MachineId::SoftPlc), None, None)
        .unwrap_or_else(|e| panic!("{e:?}"));
    let boxes: Vec<_> = imported
        .ladder
        .rungs
        .iter()
        .flat_map(|r| r.elements())
        .filter_map(|(_, e)| match e {
            Element::Block(call) => Some(call.clone()),
            _ => None,
        })
        .collect();
    assert_eq!(boxes.len(), 1, "{:?}", imported.ladder);
    assert_eq!(boxes[0].kind, "DOUBLER");
    assert_eq!(boxes[0].instance, "d1");
    assert!(
        user_blocks::is_user_block("Doubler"),
        "declared by its pins"
    );
    // The page's ST pane then declares the project's ST with its IL; as
    // if drawn from the palette, the ladder compiles with the block's IL
    // and runs, the ladder's scan calling the ST block.
    let pane = engine::softplc::st::st_blocks(&document.st_text()).expect("the ST loads");
    assert!(!pane.program, "a library: the ladder runs");
    user_blocks::set(pane.blocks, pane.il);
    let text = compile(&imported.ladder, MachineId::SoftPlc, Options::default())
        .unwrap_or_else(|e| panic!("{e:?}"));
    let mut plc = new_plc(MachineId::SoftPlc);
    plc.load_text(&text)
        .unwrap_or_else(|e| panic!("{e}\n{text}"));
    plc.run_until(SimTime::from_millis(30));
    assert_eq!(
        (get(plc.as_ref(), "%QX0.0"), get(plc.as_ref(), "d1.y")),
        (0, 0)
    );
    switch_on(plc.as_mut(), "%IX0.0");
    plc.run_until(SimTime::from_millis(60));
    assert_eq!(get(plc.as_ref(), "%QX0.0"), 1, "done follows go");
    assert_eq!(get(plc.as_ref(), "d1.y"), 42);
    assert_eq!(get(plc.as_ref(), "result"), 42, "the box's y to result");
}

#[test]
fn the_command_lines_soft_plc_runs_the_same_file_as_written() {
    let xml = ld_calling_st(ST_BODY);
    let program = Document::read(&xml)
        .and_then(|d| d.soft_program(None))
        .unwrap_or_else(|e| panic!("{e:?}"));
    let mut plc = new_plc(MachineId::SoftPlc);
    plc.load_text(&program.text)
        .unwrap_or_else(|e| panic!("{e}\n{}", program.text));
    switch_on(plc.as_mut(), "%IX0.0");
    plc.run_until(SimTime::from_millis(40));
    assert_eq!(get(plc.as_ref(), "lamp"), 1);
    assert_eq!(get(plc.as_ref(), "result"), 42);
}

#[test]
fn a_project_block_that_cannot_be_a_box_is_still_refused_at_the_block() {
    user_blocks::set(Vec::new(), String::new());
    let refusal = |xml: &str| {
        let errors = Document::read(xml)
            .and_then(|d| d.import(Some(MachineId::SoftPlc), None, None))
            .expect_err("refused");
        let line = xml
            .lines()
            .position(|l| l.contains("typeName=\"Doubler\""))
            .expect("the block")
            + 1;
        assert_eq!(errors.len(), 1, "{errors:?}");
        assert_eq!(errors[0].line, line, "{errors:?}");
        errors[0].error.clone()
    };
    // In IL: no box.
    let il = refusal(&ld_calling_st(IL_BODY));
    assert_eq!(il, ImportError::ProjectBlock("Doubler".into(), "IL".into()));
    // In ST with an in-out pin: no box (a pin holds one value).
    let in_out = ld_calling_st(ST_BODY).replace(
        "</inputVars>",
        "</inputVars><inOutVars><variable name=\"k\"><type><INT/></type></variable></inOutVars>",
    );
    let st = refusal(&in_out);
    assert_eq!(st, ImportError::ProjectBlock("Doubler".into(), "ST".into()));
    assert!(!user_blocks::is_user_block("Doubler"));
}

#[test]
fn a_box_whose_st_does_not_load_opens_and_the_pane_says_why() {
    // The import reads the block's pins, not its ST: the box is drawn;
    // the ST pane shows the ST's error at its line, and until the ST
    // loads the box is an unknown kind at its cell (the page's rule).
    let broken = ST_BODY.replace("y := x * 2;", "y := x * ;");
    let document = Document::read(&ld_calling_st(&broken)).expect("reads");
    let imported = document
        .import(Some(MachineId::SoftPlc), None, None)
        .unwrap_or_else(|e| panic!("{e:?}"));
    assert_eq!(imported.ladder.rungs.len(), 1);
    let st = document.st_text();
    let errors = engine::softplc::st::st_blocks(&st).expect_err("refused");
    let line = st
        .lines()
        .position(|l| l.contains("y := x * ;"))
        .expect("the line")
        + 1;
    assert_eq!(errors[0].line, line, "{errors:?}");
    user_blocks::set(Vec::new(), String::new());
    let refused = compile(&imported.ladder, MachineId::SoftPlc, Options::default());
    let e = refused.expect_err("no block declared");
    assert!(format!("{e:?}").contains("DOUBLER"), "{e:?}");
}
