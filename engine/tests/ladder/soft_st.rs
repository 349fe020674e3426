//! PLCopen projects' Structured Text on the soft PLC (issue #54): ST
//! bodies of programs and function blocks, and CODESYS's EXECUTE block,
//! run through the ST lowering; problems at their line of the file. The
//! workplace's real projects when present (never committed).

use engine::events::InputValue;
use engine::formats::plcopen::Document;
use engine::machines::new_plc;
use engine::plc::{Command, Plc};
use engine::{MachineId, SimTime};

const OWN: &str = include_str!("fixtures/soft-st.xml");
const REAL: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/fixtures/plcopen");

fn real(name: &str) -> Option<String> {
    std::fs::read_to_string(format!("{REAL}/{name}")).ok()
}

fn soft(xml: &str, pou: Option<&str>) -> Box<dyn Plc> {
    let program = Document::read(xml)
        .and_then(|document| document.soft_program(pou))
        .unwrap_or_else(|e| panic!("{e:?}"));
    let mut plc = new_plc(MachineId::SoftPlc);
    plc.load_text(&program.text)
        .unwrap_or_else(|e| panic!("{e}\n{}", program.text));
    plc
}

fn set(plc: &mut dyn Plc, device: &str, v: i64) {
    let d = plc.device(device).expect(device);
    plc.apply(Command::SetInput(d, InputValue::Int(v)))
        .expect("input");
}

fn get(plc: &dyn Plc, device: &str) -> i64 {
    plc.read(plc.device(device).expect(device)).as_i64()
}

/// The refusals of `xml`: each line and message.
fn refused(xml: &str) -> Vec<(usize, String)> {
    let errors = Document::read(xml)
        .and_then(|document| document.soft_program(None))
        .expect_err("refused");
    errors
        .iter()
        .map(|e| (e.line, e.error.to_string()))
        .collect()
}

/// The 1-based line of `xml` that holds `text`.
fn line_of(xml: &str, text: &str) -> usize {
    xml.lines().position(|l| l.contains(text)).expect(text) + 1
}

#[test]
fn an_st_program_calls_an_st_block_with_state_over_scans() {
    let mut plc = soft(OWN, None);
    let mut last = 0;
    for ms in (0..200).step_by(10) {
        plc.run_until(SimTime::from_millis(ms));
        let k = plc.scans() as i64;
        if k == last {
            continue;
        }
        last = k;
        // The block counts scans; the program scales the count until
        // 10, then RETURNs before the scaling.
        let count = if k >= 10 { k } else { k * 100 };
        assert_eq!(get(plc.as_ref(), "count"), count, "scan {k}");
        assert_eq!(
            get(plc.as_ref(), "lamp"),
            i64::from(k > 3 && k < 6),
            "scan {k}"
        );
    }
    assert!(last >= 12, "{last} scans");
    set(plc.as_mut(), "reset", 1);
    plc.run_until(SimTime::from_millis(300));
    assert_eq!(get(plc.as_ref(), "count"), 0, "reset: Cnt := 0, 0 * 100");
}

#[test]
fn an_execute_block_runs_its_st_while_en_is_on() {
    let mut plc = soft(OWN, None);
    plc.run_until(SimTime::from_millis(50));
    assert_eq!(get(plc.as_ref(), "n"), 0, "EN off: jumped over");
    assert_eq!(get(plc.as_ref(), "seen"), 0, "ENO is EN");
    set(plc.as_mut(), "go", 1);
    let start = plc.scans();
    plc.run_until(SimTime::from_millis(70));
    let ran = (plc.scans() - start) as i64;
    assert_eq!(get(plc.as_ref(), "n"), ran.min(3), "{ran} scans with EN on");
    assert_eq!(get(plc.as_ref(), "seen"), 1);
    plc.run_until(SimTime::from_millis(200));
    assert_eq!(get(plc.as_ref(), "n"), 3, "IF n < 3");
}

#[test]
fn an_st_body_error_is_said_at_its_line_of_the_file() {
    let bad = OWN.replace("lamp := count > 3 AND count < 6;", "lamp := count > 3 AND;");
    let line = line_of(&bad, "lamp := count > 3 AND;");
    let errors = refused(&bad);
    assert_eq!(errors.len(), 1, "{errors:?}");
    assert_eq!(errors[0].0, line, "{errors:?}");
    assert!(errors[0].1.contains("ST, column 22"), "{errors:?}");
    // The checker's refusals too: an undeclared name, in the block.
    let bad = OWN.replace("  Cnt := 0;", "  Cnt := nowhere;");
    let errors = refused(&bad);
    assert_eq!(errors[0].0, line_of(&bad, "Cnt := nowhere"), "{errors:?}");
    assert!(errors[0].1.contains("nowhere"), "{errors:?}");
    // And an EXECUTE block's, on its line after the STCode tag.
    let bad = OWN.replace("    n := n + 1;", "    n := n + TRUE;");
    let errors = refused(&bad);
    assert_eq!(errors[0].0, line_of(&bad, "n := n + TRUE"), "{errors:?}");
}

#[test]
fn codesys_execute_blocks_run_as_written() {
    let Some(xml) = real("codesys-execute.xml") else {
        return;
    };
    let mut plc = soft(&xml, None);
    // myContact is a local: forced on as CODESYS's online "write" does.
    set(plc.as_mut(), "myContact", 1);
    let mut ms = 0;
    while plc.scans() == 0 {
        ms += 1;
        plc.run_until(SimTime::from_millis(ms));
    }
    assert_eq!(plc.scans(), 1);
    // Scan 1: myValue 0 < 10 AND myContact: myNewValue := 1; the FOR adds
    // 0 + 1 + … + 5; myValue ends 6; CASE 16 is ELSE: myCoil := myContact.
    assert_eq!(get(plc.as_ref(), "myNewValue"), 16);
    assert_eq!(get(plc.as_ref(), "myValue"), 6);
    assert_eq!(get(plc.as_ref(), "myCoil"), 1);
    // Scan 2 on: 6 < 10: myNewValue := 7, then + 15.
    plc.run_until(SimTime::from_millis(100));
    assert_eq!(get(plc.as_ref(), "myNewValue"), 22);
    // The second block is off (myContact_1): myNewValue_1 stays 0.
    assert_eq!(get(plc.as_ref(), "myNewValue_1"), 0);
}

#[test]
fn beremiz_counter_st_and_counter_il_run_alone() {
    let Some(xml) = real("beremiz-first-steps.xml") else {
        return;
    };
    for pou in ["CounterST", "CounterIL"] {
        let mut plc = soft(&xml, Some(pou));
        plc.run_until(SimTime::from_millis(500));
        let k = plc.scans() as i64;
        // Reset off: Cnt := Cnt + 1 each scan, OUT := Cnt.
        assert_eq!(get(plc.as_ref(), "OUT"), k, "{pou}");
        set(plc.as_mut(), "Reset", 1);
        plc.run_until(SimTime::from_millis(600));
        // ResetCounterValue: the configuration's constant, 17.
        assert_eq!(get(plc.as_ref(), "OUT"), 17, "{pou}");
    }
}

#[test]
fn bottle_refiller_is_refused_for_its_c_pragmas_alone_at_their_lines() {
    let Some(xml) = real("bottle-refiller.xml") else {
        return;
    };
    let errors = refused(&xml);
    assert_eq!(errors.len(), 3, "{errors:?}");
    for (line, why) in &errors {
        assert!(why.contains("pragma"), "{errors:?}");
        let text = xml.lines().nth(line - 1).unwrap_or_default();
        assert!(text.trim_start().starts_with('{'), "line {line}: {text}");
    }
}

/// A program in ST named `name`, counting `n` (of type `ty`) up by
/// `step` while `a AND b` (an expression as a block's input: a hidden
/// variable).
fn counting_program(name: &str, ty: &str, step: i64) -> String {
    format!(
        r#"<pou name="{name}" pouType="program"><interface><localVars>
<variable name="a"><type><BOOL/></type><initialValue><simpleValue value="TRUE"/></initialValue></variable>
<variable name="b"><type><BOOL/></type><initialValue><simpleValue value="TRUE"/></initialValue></variable>
<variable name="n"><type><{ty}/></type></variable>
<variable name="t"><type><derived name="TON"/></type></variable>
</localVars></interface><body><ST><xhtml:p xmlns:xhtml="http://www.w3.org/1999/xhtml"><![CDATA[t(IN := a AND b, PT := T#0ms);
IF t.Q THEN
  n := n + {ty}#{step};
END_IF;]]></xhtml:p></ST></body></pou>"#
    )
}

#[test]
fn two_st_programs_with_the_same_names_keep_their_own() {
    let xml = format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201"><types><pous>
{}
{}
</pous></types><instances><configurations><configuration name="c"><resource name="r">
<task name="t" priority="0" interval="T#10ms"><pouInstance name="i1" typeName="one"/><pouInstance name="i2" typeName="two"/></task>
</resource></configuration></configurations></instances></project>"#,
        counting_program("one", "INT", 1),
        counting_program("two", "DINT", 10)
    );
    let mut plc = soft(&xml, None);
    plc.run_until(SimTime::from_millis(50));
    let k = plc.scans() as i64;
    // The second program's `n`, a DINT, is renamed two_n; its body is
    // read with its own `n`, not the first program's INT.
    assert_eq!(get(plc.as_ref(), "n"), k);
    assert_eq!(get(plc.as_ref(), "two_n"), 10 * k);
}

#[test]
fn two_st_programs_in_the_st_pane_run_in_their_tasks_order_each_with_its_own() {
    // The file has `one` first; the task runs `two` first.
    let xml = format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201"><types><pous>
{}
{}
</pous></types><instances><configurations><configuration name="c"><resource name="r">
<task name="t" priority="0" interval="T#10ms"><pouInstance name="i2" typeName="two"/><pouInstance name="i1" typeName="one"/></task>
</resource></configuration></configurations></instances></project>"#,
        counting_program("one", "INT", 1),
        counting_program("two", "DINT", 10)
    );
    let st = Document::read(&xml).expect("reads").st_text();
    let at = |what: &str| st.find(what).expect(what);
    assert!(at("PROGRAM two") < at("PROGRAM one"), "{st}");
    // The pane's text runs both: `two` first keeps its names, `one`'s
    // are its own (`one_n`), as on the command line.
    let mut program = engine::softplc::Program::load_st(&st).unwrap_or_else(|e| panic!("{e:?}"));
    for scan in 0..5 {
        program.scan(scan * 10_000_000);
    }
    let value = |name: &str| program.value(name).map(|d| d.to_value().as_i64());
    assert_eq!((value("n"), value("one_n")), (Some(50), Some(5)), "{st}");
    let run = engine::softplc::st::st_run(&st).expect("runs");
    let one = st[..at("PROGRAM one")].lines().count() + 1;
    assert_eq!(run.il_name(one + 8, "n"), "one_n", "{st}");
}
