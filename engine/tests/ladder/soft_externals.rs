//! The external variables (`externalVars`) of a PLCopen project's own
//! function blocks and functions on the soft PLC (issue #54): each call
//! copies the caller's global in and, unless the external is constant,
//! back out when the block's body ends (its RETs too), so a global a
//! block writes is the program's and the next block's at once. Our own
//! project (`fixtures/soft-externals.xml`) and Beremiz's first example
//! when the workplace's fixtures are present (never committed).

use engine::events::InputValue;
use engine::formats::plcopen::Document;
use engine::machines::new_plc;
use engine::plc::{Command, Plc};
use engine::{MachineId, SimTime};

const OWN: &str = include_str!("fixtures/soft-externals.xml");
const REAL: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/fixtures/plcopen");

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

/// Each refusal of `xml`: its line and message.
fn refused(xml: &str) -> Vec<(usize, String)> {
    let errors = Document::read(xml)
        .and_then(|document| document.soft_program(None))
        .expect_err("refused");
    errors
        .iter()
        .map(|e| (e.line, e.error.to_string()))
        .collect()
}

fn line_of(xml: &str, text: &str) -> usize {
    xml.lines().position(|l| l.contains(text)).expect(text) + 1
}

/// Runs `plc` scan by scan until it has made `n` more scans.
fn scans(plc: &mut dyn Plc, n: u64) {
    let goal = plc.scans() + n;
    let mut t = plc.now();
    while plc.scans() < goal {
        t = t.saturating_add(SimTime::from_millis(1));
        plc.run_until(t);
    }
}

#[test]
fn blocks_in_il_st_and_fbd_read_and_write_the_globals_they_name() {
    let mut plc = soft(OWN, None);
    // Scan 1 (limit 3, run TRUE): b1 (FBD) adds one to total (1), w1
    // sees 1: peak 1, alarm off; b2 (IL) adds one (2); t1 (IL) with x =
    // 2 < 3 gives seen = count = 0; scaled = Scaled(2) = 2 * 3; t2 (ST)
    // gives seen = 0.
    scans(plc.as_mut(), 1);
    let at =
        |plc: &dyn Plc, names: &[&str]| -> Vec<i64> { names.iter().map(|n| get(plc, n)).collect() };
    let names = [
        "total", "count", "peak", "alarm", "full1", "scaled", "seen1", "seen2",
    ];
    assert_eq!(at(plc.as_ref(), &names), [2, 0, 1, 0, 0, 6, 0, 0]);
    // Scan 2: b1 adds the third (3), w1: alarm, peak 3; b2 finds it
    // full and returns (RETC) — its copy-out still gives 3, not the 2
    // it gave last; t1 (x = 3) counts and RETURNs (its copy-out gives
    // count 1, seen stays 0); t2 then sees count 1.
    scans(plc.as_mut(), 1);
    assert_eq!(at(plc.as_ref(), &names), [3, 1, 3, 1, 0, 9, 0, 1]);
    // Then each scan t1 counts once more; b1 is full from scan 3 on.
    scans(plc.as_mut(), 5);
    assert_eq!(at(plc.as_ref(), &names), [3, 6, 3, 1, 1, 9, 0, 6]);
    // run off: b1 returns at once (RETCN) and copies out what it was
    // given, so the 10 the ST program adds at each scan's end stays:
    // total 3 + 10 k after k scans; w1 and Scaled see it a scan later.
    set(plc.as_mut(), "run", 0);
    scans(plc.as_mut(), 4);
    let total = get(plc.as_ref(), "total");
    assert_eq!(total, 3 + 10 * 4);
    assert_eq!(get(plc.as_ref(), "peak"), total - 10);
    assert_eq!(get(plc.as_ref(), "scaled"), 3 * (total - 10));
    assert_eq!(get(plc.as_ref(), "count"), 10);
}

#[test]
fn a_block_whose_global_the_caller_lacks_is_refused_at_the_call() {
    // Without the resource's `count`, each call of Tally (from IL and
    // from ST) is refused at its line, naming the external.
    let globals = "<variable name=\"count\"><type><DINT/></type></variable>\n            <variable name=\"peak\">";
    assert!(OWN.contains(globals));
    let xml = OWN.replace(globals, "<variable name=\"peak\">");
    let got = refused(&xml);
    let want = [
        (line_of(&xml, "CAL t1("), "second"),
        (line_of(&xml, "t2(x := 0);"), "third"),
    ];
    assert_eq!(got.len(), want.len(), "{got:?}");
    for ((line, why), (want_line, pou)) in got.iter().zip(want) {
        assert_eq!(*line, want_line, "{why}");
        let said =
            format!("Tally reaches `count` as an external variable, and {pou} has no `count`");
        assert!(why.starts_with(&said), "{why}");
    }
    // A drawn call too: main's w1 without `peak`.
    let peak = "<variable name=\"peak\"><type><INT/></type></variable>\n            <variable name=\"run\">";
    assert!(OWN.contains(peak));
    let xml = OWN.replace(peak, "<variable name=\"run\">");
    let got = refused(&xml);
    assert_eq!(got.len(), 1, "{got:?}");
    assert_eq!(
        got[0].0,
        line_of(&xml, "typeName=\"Watch\" instanceName=\"w1\"")
    );
    assert!(got[0].1.starts_with("Watch reaches `peak`"), "{got:?}");
    // An external that is a block instance (a global TON) is refused at
    // its declaration in the block.
    let count =
        "<variable name=\"count\"><type><DINT/></type></variable>\n          </externalVars>";
    assert!(OWN.contains(count));
    let xml = OWN.replace(count, "<variable name=\"count\"><type><derived name=\"TON\"/></type></variable>\n          </externalVars>");
    let got = refused(&xml);
    let line = line_of(&xml, "<derived name=\"TON\"/>");
    assert_eq!(got.len(), 1, "{got:?}");
    assert_eq!(got[0].0, line);
    assert!(
        got[0]
            .1
            .contains("a block instance as a function block's external variable"),
        "{got:?}"
    );
}

#[test]
fn a_block_run_alone_declares_its_externals_as_written() {
    // `--pou Tally` with no global of its names: count and limit are
    // declared from the externals' own types, at their zero: x = 0 >= 0,
    // so each scan counts and returns.
    let mut xml = OWN.to_string();
    while let Some(start) = xml.find("<globalVars") {
        let end = xml.find("</globalVars>").expect("globals") + "</globalVars>".len();
        xml.replace_range(start..end, "");
    }
    let mut plc = soft(&xml, Some("Tally"));
    scans(plc.as_mut(), 3);
    assert_eq!(get(plc.as_ref(), "limit"), 0);
    assert_eq!(get(plc.as_ref(), "count"), 3);
    assert_eq!(get(plc.as_ref(), "seen"), 0);
    // With the configuration's globals it is their values: limit 3.
    let mut plc = soft(OWN, Some("Tally"));
    scans(plc.as_mut(), 3);
    assert_eq!(get(plc.as_ref(), "limit"), 3);
    assert_eq!(get(plc.as_ref(), "count"), 0);
}

#[test]
fn beremiz_first_steps_counters_read_the_configuration_constant() {
    let Ok(xml) = std::fs::read_to_string(format!("{REAL}/beremiz-first-steps.xml")) else {
        return;
    };
    // As written it is refused for its SFC block alone.
    for (line, why) in refused(&xml) {
        assert!(why.contains("SFC"), "line {line}: {why}");
    }
    // With CounterSFC0 a second CounterST (changed here, in memory), the
    // program runs its five counters, each block reaching the
    // configuration's constant ResetCounterValue (17) as an external.
    let xml = xml
        .replace("typeName=\"CounterSFC\"", "typeName=\"CounterST\"")
        .replace(
            "<derived name=\"CounterSFC\"/>",
            "<derived name=\"CounterST\"/>",
        );
    let mut plc = soft(&xml, None);
    let counters = ["Cnt1", "Cnt2", "Cnt3", "Cnt4", "Cnt5"];
    // Reset off: every counter (ST, FBD, ST, IL, LD) counts every scan
    // made, the drawn ones too: their loop through the inOutVariable Cnt
    // is broken at ADD (which reads the last scan's Cnt), so Out reads
    // the Cnt written in the same scan, as Beremiz runs them.
    for _ in 0..7 {
        scans(plc.as_mut(), 1);
        let made = plc.scans() as i64;
        for c in counters {
            assert_eq!(get(plc.as_ref(), c), made, "{c} after {made} scans");
        }
    }
    // Reset on: each gives the constant in the scan it sees it, and
    // counts on from it in the scan after.
    set(plc.as_mut(), "Reset", 1);
    for _ in 0..2 {
        scans(plc.as_mut(), 1);
        for c in counters {
            assert_eq!(get(plc.as_ref(), c), 17, "{c}");
        }
    }
    set(plc.as_mut(), "Reset", 0);
    scans(plc.as_mut(), 1);
    for c in counters {
        assert_eq!(get(plc.as_ref(), c), 18, "{c}");
    }
}

/// A project whose block `Outer` (ST) calls block `Inner` (IL), both
/// reaching the resource's global `total`; `outer_external`: whether
/// Outer declares `total` as its own external (and adds to it).
fn nested(outer_external: bool) -> String {
    let p = r#"<xhtml:p xmlns:xhtml="http://www.w3.org/1999/xhtml"><![CDATA["#;
    let external =
        "<externalVars><variable name=\"total\"><type><INT/></type></variable></externalVars>";
    let (outer, add) = match outer_external {
        true => (external, "\ntotal := total + 100;"),
        false => ("", ""),
    };
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201"><types><pous>
<pou name="Inner" pouType="functionBlock"><interface>{external}</interface>
<body><IL>{p}LD total
ADD 1
ST total]]></xhtml:p></IL></body></pou>
<pou name="Outer" pouType="functionBlock"><interface>
<localVars><variable name="i"><type><derived name="Inner"/></type></variable></localVars>{outer}</interface>
<body><ST>{p}i();{add}]]></xhtml:p></ST></body></pou>
<pou name="main" pouType="program"><interface><localVars>
<variable name="o"><type><derived name="Outer"/></type></variable></localVars></interface>
<body><ST>{p}o();]]></xhtml:p></ST></body></pou>
</pous></types><instances><configurations><configuration name="c"><resource name="r">
<task name="t" priority="0" interval="T#10ms"><pouInstance name="m" typeName="main"/></task>
<globalVars><variable name="total"><type><INT/></type></variable></globalVars>
</resource></configuration></configurations></instances></project>"#
    )
}

#[test]
fn a_block_calling_a_block_passes_its_own_external_on() {
    // Inner adds 1 to Outer's copy, Outer 100 more, Outer's copy-out
    // gives the global both: 101 a scan.
    let mut plc = soft(&nested(true), None);
    scans(plc.as_mut(), 3);
    assert_eq!(get(plc.as_ref(), "total"), 303);
    // Without its own external Outer has no `total` to give Inner: the
    // call is refused at its ST line.
    let xml = nested(false);
    let got = refused(&xml);
    assert!(!got.is_empty());
    for (line, why) in &got {
        assert_eq!(*line, line_of(&xml, "i();"), "{why}");
    }
    assert!(
        got[0]
            .1
            .starts_with("Inner reaches `total` as an external variable, and Outer has no `total`"),
        "{got:?}"
    );
}
