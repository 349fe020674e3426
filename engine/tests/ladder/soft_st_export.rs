//! PLCopen export keeps Structured Text (issue #54): an ST source written
//! as a project (`export_st`) reads back (`Document::st_text`) to the
//! same bodies and runs the same on the soft PLC; the workplace's real
//! projects with ST bodies when present (never committed).

use engine::events::InputValue;
use engine::formats::plcopen::{export_st, Document};
use engine::iec::st::ast::Item;
use engine::iec::st::{lower_source, parse_body, parse_source, print_body};
use engine::machines::new_plc;
use engine::plc::{Command, Plc};
use engine::{MachineId, SimTime};

const REAL: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/fixtures/plcopen");

/// Our own project: a program with located I/O, a retained global, a
/// constant, a TON, and a function block of its own with state, every
/// body with comments (which the export keeps).
const OWN: &str = r#"
VAR_GLOBAL RETAIN
    total : DINT := 100;
END_VAR

FUNCTION_BLOCK Stepper
    VAR_INPUT
        go : BOOL;
        top : INT := 4;
    END_VAR
    VAR_OUTPUT
        n : INT;
        full : BOOL;
    END_VAR
    (* counts the scans `go` is on, up to `top` *)
    IF go AND n < top THEN
        n := n + 1; // one a scan
    END_IF;
    full := n >= top;
END_FUNCTION_BLOCK

PROGRAM main
    VAR
        start AT %IX0.0 : BOOL;
        lamp AT %QX0.0 : BOOL;
        s0 : Stepper;
        t0 : TON;
        seen : INT;
    END_VAR
    VAR CONSTANT
        PERIOD : TIME := T#30ms;
    END_VAR
    s0(go := start, top := 4);
    t0(IN := s0.full, PT := PERIOD);
    lamp := t0.Q;
    IF s0.full THEN
        total := total + 1; (* a string with ]]> in it stays: *)
        seen := s0.n;
    END_IF;
END_PROGRAM
"#;

fn plc_of(il: &str) -> Box<dyn Plc> {
    let mut plc = new_plc(MachineId::SoftPlc);
    plc.load_text(il).unwrap_or_else(|e| panic!("{e}\n{il}"));
    plc
}

/// The `.st` source as the soft PLC runs it.
fn from_st(source: &str) -> Box<dyn Plc> {
    let parsed = parse_source(source).expect("parses");
    plc_of(&lower_source(&parsed).expect("lowers").text)
}

/// A PLCopen project as the soft PLC runs it (`pou` alone, or all).
fn from_xml(xml: &str, pou: Option<&str>) -> Box<dyn Plc> {
    let program = Document::read(xml)
        .and_then(|d| d.soft_program(pou))
        .unwrap_or_else(|e| panic!("{e:?}\n{xml}"));
    plc_of(&program.text)
}

fn get(plc: &dyn Plc, device: &str) -> i64 {
    plc.read(plc.device(device).expect(device)).as_i64()
}

fn set(plc: &mut dyn Plc, device: &str, v: i64) {
    let d = plc.device(device).expect(device);
    plc.apply(Command::SetInput(d, InputValue::Int(v)))
        .expect("input");
}

/// Each POU's name and its body printed from its parse tree.
fn bodies(source: &str) -> Vec<(String, String)> {
    let parsed = parse_source(source).unwrap_or_else(|e| panic!("{e}\n{source}"));
    parsed
        .items
        .iter()
        .filter_map(|i| match i {
            Item::Pou(p) => Some((p.name.name.clone(), print_body(&p.body))),
            _ => None,
        })
        .collect()
}

/// Runs `a` and `b` side by side, `start` on from 50 ms to 150 ms,
/// comparing `watch` at every scan.
fn same_runs(mut a: Box<dyn Plc>, mut b: Box<dyn Plc>, start: &str, watch: &[&str]) -> usize {
    let mut changed = 0;
    let mut last = Vec::new();
    for ms in (0..300).step_by(10) {
        let on = i64::from((50..150).contains(&ms));
        set(a.as_mut(), start, on);
        set(b.as_mut(), start, on);
        a.run_until(SimTime::from_millis(ms));
        b.run_until(SimTime::from_millis(ms));
        let now: Vec<i64> = watch.iter().map(|w| get(a.as_ref(), w)).collect();
        let theirs: Vec<i64> = watch.iter().map(|w| get(b.as_ref(), w)).collect();
        assert_eq!(now, theirs, "{watch:?} at {ms} ms");
        if now != last {
            changed += 1;
            last = now;
        }
    }
    changed
}

#[test]
fn an_st_project_exported_reads_back_to_the_same_bodies_and_runs_the_same() {
    let xml = export_st(OWN, "own").unwrap_or_else(|e| panic!("{e:?}"));
    let document = Document::read(&xml).unwrap_or_else(|e| panic!("{e:?}\n{xml}"));
    let back = document.st_text();
    assert_eq!(bodies(&back), bodies(OWN), "{back}");
    // The bodies as written: comments kept, as the file carries them.
    assert!(xml.contains("(* counts the scans `go` is on, up to `top` *)"));
    assert!(xml.contains("n := n + 1; // one a scan"));
    assert!(xml.contains("with ]]]]><![CDATA[> in it"), "{xml}");
    assert!(back.contains("with ]]> in it"), "{back}");
    // The interface and the globals come back as declared.
    let declared = |s: &str| print_source_of(s);
    assert_eq!(declared(&back), declared(OWN), "{back}");
    // Runs the same, scan for scan: the program counts 4 scans of
    // start, then the TON's 30 ms light the lamp; total counts on.
    let watch = ["lamp", "seen", "total", "s0.n", "s0.full"];
    let changes = same_runs(from_st(OWN), from_xml(&xml, None), "start", &watch);
    assert!(changes >= 4, "{changes} changes: the run must do something");
}

/// A source printed from its parse tree with every body left out: its
/// types, globals and interfaces.
fn print_source_of(source: &str) -> String {
    let mut parsed = parse_source(source).expect("parses");
    for item in &mut parsed.items {
        if let Item::Pou(p) = item {
            p.body.clear();
        }
    }
    engine::iec::st::print_source(&parsed)
}

#[test]
fn a_project_written_back_is_read_again_to_the_same_text() {
    let once = Document::read(&export_st(OWN, "own").expect("exports"))
        .expect("reads")
        .st_text();
    let twice = Document::read(&export_st(&once, "own").expect("exports"))
        .expect("reads")
        .st_text();
    assert_eq!(once, twice);
}

#[test]
fn a_source_that_does_not_check_is_refused_at_its_place_and_nothing_written() {
    let bad = "PROGRAM p\nVAR\n  a : INT;\nEND_VAR\n  a := b;\nEND_PROGRAM\n";
    let errors = export_st(bad, "bad").expect_err("refused");
    assert_eq!(errors.len(), 1, "{errors:?}");
    assert_eq!((errors[0].span.line, errors[0].span.column), (5, 8));
    assert!(errors[0].to_string().contains("`b` is not declared"));
    let syntax = export_st("PROGRAM p\n  a := ;\nEND_PROGRAM\n", "bad").expect_err("refused");
    assert_eq!(syntax[0].span.line, 2);
}

#[test]
fn arrays_structures_and_their_initial_values_are_written_as_plcopen_has_them() {
    let source = "TYPE\n    Pair : STRUCT\n        a : INT := 1;\n        b : BOOL;\n    END_STRUCT;\nEND_TYPE\n\
PROGRAM p\nVAR\n    xs : ARRAY [1..4] OF INT := [7, 2(3), 1()];\n    p0 : Pair := (a := 9);\n    ps : ARRAY [0..2] OF Pair := [3()];\nEND_VAR\n    xs[1] := p0.a;\nEND_PROGRAM\n";
    let xml = export_st(source, "arrays").unwrap_or_else(|e| panic!("{e:?}"));
    assert!(xml.contains(
        "<array><dimension lower=\"1\" upper=\"4\"/><baseType><INT/></baseType></array>"
    ));
    assert!(xml.contains("<value repetitionValue=\"2\"><simpleValue value=\"3\"/></value>"));
    // `1()` (one default) of an INT: PLCopen has no empty value, so 0.
    assert!(xml.contains("<value repetitionValue=\"1\"><simpleValue value=\"0\"/></value>"));
    assert!(xml.contains(
        "<structValue><value member=\"a\"><simpleValue value=\"9\"/></value></structValue>"
    ));
    assert!(xml.contains("<value repetitionValue=\"3\"><structValue/></value>"));
    let back = Document::read(&xml).expect("reads").st_text();
    assert_eq!(bodies(&back), bodies(source));
    assert!(
        back.contains("xs : ARRAY [1..4] OF INT := [7, 2(3), 1(0)];"),
        "{back}"
    );
    assert!(
        back.contains("ps : ARRAY [0..2] OF Pair := [3()];"),
        "{back}"
    );
    assert!(back.contains("a : INT := 1;"), "{back}");
}

#[test]
fn beremiz_first_steps_st_written_back_reads_and_runs_the_same() {
    let Ok(xml) = std::fs::read_to_string(format!("{REAL}/beremiz-first-steps.xml")) else {
        return;
    };
    let text = Document::read(&xml).expect("reads").st_text();
    // Its ST POUs: the function AverageVal and the block CounterST.
    let names: Vec<String> = bodies(&text).into_iter().map(|(n, _)| n).collect();
    assert_eq!(names, ["AverageVal", "CounterST"], "{text}");
    let out = export_st(&text, "first-steps").unwrap_or_else(|e| panic!("{e:?}\n{text}"));
    let back = Document::read(&out).expect("reads").st_text();
    assert_eq!(back, text);
    // Each body as Beremiz wrote it, character for character.
    for (name, _) in bodies(&text) {
        let written = |x: &str| -> String {
            let at = x.find(&format!("<pou name=\"{name}\"")).expect(&name);
            let body = &x[at..];
            let body = &body[body.find("<ST>").expect("ST body")..];
            let from = body.find("<![CDATA[").expect("CDATA") + 9;
            let to = body.find("]]>").expect("CDATA end");
            body[from..to].trim().to_string()
        };
        assert_eq!(written(&out), written(&xml), "{name}");
        assert!(parse_body(&written(&out)).is_ok());
    }
    // CounterST alone runs the same in both (its ResetCounterValue the
    // configuration's global, kept).
    let a = from_xml(&xml, Some("CounterST"));
    let b = from_xml(&out, Some("CounterST"));
    let changes = same_runs(a, b, "Reset", &["OUT"]);
    assert!(changes >= 4, "{changes}");
}

/// A project with two functions of its own, one in ST and one in IL,
/// and a program in ST calling both (issue #54).
const FUNCTIONS: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <types>
    <pous>
      <pou name="Twice" pouType="function">
        <interface>
          <returnType><INT/></returnType>
          <inputVars><variable name="x"><type><INT/></type></variable></inputVars>
        </interface>
        <body><ST><xhtml:p><![CDATA[Twice := x * 2;]]></xhtml:p></ST></body>
      </pou>
      <pou name="Plus" pouType="function">
        <interface>
          <returnType><INT/></returnType>
          <inputVars>
            <variable name="a"><type><INT/></type></variable>
            <variable name="b"><type><INT/></type></variable>
          </inputVars>
        </interface>
        <body><IL><xhtml:p><![CDATA[LD a
ADD b
ST Plus]]></xhtml:p></IL></body>
      </pou>
      <pou name="main" pouType="program">
        <interface>
          <localVars>
            <variable name="n"><type><INT/></type></variable>
            <variable name="r"><type><INT/></type></variable>
            <variable name="s"><type><INT/></type></variable>
          </localVars>
        </interface>
        <body><ST><xhtml:p><![CDATA[n := n + 1;
r := Twice(n) + Plus(n, 10);
s := Plus(b := Twice(x := r), a := 1);]]></xhtml:p></ST></body>
      </pou>
    </pous>
  </types>
  <instances><configurations/></instances>
</project>
"#;

#[test]
fn the_projects_own_functions_in_st_and_il_run_when_called_from_st() {
    let mut plc = from_xml(FUNCTIONS, None);
    for scan in 1..=5_i64 {
        plc.run_until(SimTime::from_millis(10 * scan as u64));
        let n = get(plc.as_ref(), "n");
        // Twice(n) = 2n, Plus(n, 10) = n + 10: r = 3n + 10; s = 2r + 1.
        assert_eq!(n, plc.scans() as i64);
        assert_eq!(get(plc.as_ref(), "r"), 3 * n + 10, "scan {n}");
        assert_eq!(get(plc.as_ref(), "s"), 2 * (3 * n + 10) + 1, "scan {n}");
    }
}

/// The functions above called from IL (the current result the first
/// input; a formal list) and from a drawn FBD block (its `OUT`).
fn callers() -> String {
    let programs = r#"<pou name="il" pouType="program">
        <interface><localVars>
          <variable name="k"><type><INT/></type></variable>
          <variable name="p"><type><INT/></type></variable>
          <variable name="q"><type><INT/></type></variable>
          <variable name="w"><type><INT/></type></variable>
        </localVars></interface>
        <body><IL><xhtml:p><![CDATA[LD k
ADD 1
ST k
Twice (* the current result, k, as x *)
ST p
LD 5
Plus k
ST q
again: Plus(a := p, b := q)
ST w]]></xhtml:p></IL></body>
      </pou>
      <pou name="fbd" pouType="program">
        <interface><localVars>
          <variable name="m"><type><INT/></type><initialValue><simpleValue value="21"/></initialValue></variable>
          <variable name="d"><type><INT/></type></variable>
        </localVars></interface>
        <body><FBD>
          <inVariable localId="1"><position x="0" y="0"/><connectionPointOut/><expression>m</expression></inVariable>
          <block localId="2" typeName="Twice"><position x="100" y="0"/><inputVariables><variable formalParameter="x"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable></inputVariables><inOutVariables/><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>
          <outVariable localId="3"><position x="200" y="0"/><connectionPointIn><connection refLocalId="2" formalParameter="OUT"/></connectionPointIn><expression>d</expression></outVariable>
        </FBD></body>
      </pou>
    </pous>"#;
    let at = FUNCTIONS.find("<pou name=\"main\"").expect("main");
    let end = FUNCTIONS.find("</pous>").expect("pous") + "</pous>".len();
    format!("{}{programs}{}", &FUNCTIONS[..at], &FUNCTIONS[end..])
}

#[test]
fn the_projects_own_functions_run_when_called_from_il_and_from_a_drawn_block() {
    let xml = callers();
    let mut plc = from_xml(&xml, None);
    for scan in 1..=4_i64 {
        plc.run_until(SimTime::from_millis(10 * scan as u64));
        let k = get(plc.as_ref(), "k");
        assert_eq!(k, plc.scans() as i64);
        // IEC's IL: `Twice` takes the current result (k) as x; `Plus k`
        // after `LD 5` is Plus(5, k); the formal call leaves it out.
        assert_eq!(get(plc.as_ref(), "p"), 2 * k, "scan {k}");
        assert_eq!(get(plc.as_ref(), "q"), 5 + k, "scan {k}");
        assert_eq!(get(plc.as_ref(), "w"), 2 * k + 5 + k, "scan {k}");
        assert_eq!(get(plc.as_ref(), "d"), 42, "Twice(21) drawn");
    }
    // Too many operands for the function: refused at its line.
    let bad = xml.replace("Plus k\n", "Plus k, 3\n");
    let errors = Document::read(&bad)
        .and_then(|d| d.soft_program(None))
        .expect_err("refused");
    let line = bad
        .lines()
        .position(|l| l.starts_with("Plus k, 3"))
        .expect("line")
        + 1;
    assert_eq!(errors.len(), 1, "{errors:?}");
    assert_eq!(errors[0].line, line);
    assert_eq!(
        errors[0].error.to_string(),
        "Plus: it does not take 3 inputs"
    );
}

#[test]
fn an_own_function_no_body_calls_is_left_out_so_it_cannot_refuse_the_project() {
    // `Unused` calls LEN, which the soft PLC has not: were it taken in,
    // the project would be refused for it.
    let unused = r#"<pou name="Unused" pouType="function">
        <interface><returnType><INT/></returnType></interface>
        <body><ST><xhtml:p><![CDATA[Unused := LEN('abc');]]></xhtml:p></ST></body>
      </pou>
      <pou name="main""#;
    let xml = FUNCTIONS.replacen("<pou name=\"main\"", unused, 1);
    let mut plc = from_xml(&xml, None);
    plc.run_until(SimTime::from_millis(10));
    assert_eq!(get(plc.as_ref(), "r"), 3 + 10);
    // Called, it is refused at its line, saying what it lacks.
    let called = xml.replace("n := n + 1;", "n := n + Unused();");
    let errors = Document::read(&called)
        .and_then(|d| d.soft_program(None))
        .expect_err("refused");
    assert!(errors[0].error.to_string().contains("LEN"), "{errors:?}");
}

#[test]
fn every_real_projects_st_is_written_back_to_the_same_text_or_refused_at_its_place() {
    let Some(names) = crate::common::fixture_names(REAL, ".xml") else {
        return;
    };
    let mut written = Vec::new();
    for name in &names {
        let xml = std::fs::read_to_string(format!("{REAL}/{name}")).expect("readable");
        let Ok(document) = Document::read(&xml) else {
            continue;
        };
        let text = document.st_text();
        match export_st(&text, name) {
            Ok(out) => {
                let back = Document::read(&out).expect("reads").st_text();
                assert_eq!(back, text, "{name}");
                written.push(name.clone());
            }
            // Refused (no ST POU, or bottle-refiller's pragmas): each
            // problem at a line of the text.
            Err(errors) => assert!(errors.iter().all(|e| e.span.line >= 1), "{name}"),
        }
    }
    assert!(
        written.iter().any(|n| n == "beremiz-first-steps.xml"),
        "{written:?}"
    );
}
