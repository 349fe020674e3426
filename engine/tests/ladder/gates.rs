//! Boolean blocks from other tools lowered to ladder (issue #18): each
//! imported program runs on IO86A as the block's truth table says.

use engine::events::InputValue;
use engine::ladder::compile::compile;
use engine::ladder::plcopen::{import_mapped, VarMap};
use engine::plc::{Command, Io86aPlc, Plc};
use engine::{MachineId, SimTime};

/// A project whose one program's LD body is `body` (OpenPLC's dialect).
fn project(body: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <types><pous><pou name="main" pouType="program">
    <interface><localVars>
      <variable name="a" address="%IX0.0"><type><BOOL/></type></variable>
      <variable name="b" address="%IX0.1"><type><BOOL/></type></variable>
      <variable name="q" address="%QX0.0"><type><BOOL/></type></variable>
    </localVars></interface>
    <body><LD>
      <leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut/></leftPowerRail>
      <contact localId="2"><position x="10" y="10"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>a</variable></contact>
      <contact localId="3"><position x="10" y="30"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>b</variable></contact>
{body}
    </LD></body>
  </pou></pous></types>
</project>"#
    )
}

/// A block of `ty` at row `y`, each input pin fed from an element
/// (`(pin, localId)`), its output pin `out`.
fn block(id: u32, ty: &str, instance: &str, y: u32, inputs: &[(&str, u32)], out: &str) -> String {
    let pins: String = inputs
        .iter()
        .map(|(pin, from)| {
            format!(
                r#"
          <variable formalParameter="{pin}"><connectionPointIn><connection refLocalId="{from}"/></connectionPointIn></variable>"#
            )
        })
        .collect();
    format!(
        r#"
      <block localId="{id}" typeName="{ty}" instanceName="{instance}"><position x="30" y="{y}"/>
        <inputVariables>{pins}
        </inputVariables>
        <outputVariables><variable formalParameter="{out}"><connectionPointOut/></variable></outputVariables>
      </block>"#
    )
}

/// A coil of `variable` at row `y`, fed from element `from` (its pin
/// `pin`, empty for a contact or rail).
fn coil(id: u32, y: u32, from: u32, pin: &str, variable: &str) -> String {
    let pin = if pin.is_empty() {
        String::new()
    } else {
        format!(r#" formalParameter="{pin}""#)
    };
    format!(
        r#"
      <coil localId="{id}"><position x="60" y="{y}"/><connectionPointIn><connection refLocalId="{from}"{pin}/></connectionPointIn><variable>{variable}</variable></coil>"#
    )
}

/// A two-input block of `ty` fed by contacts a and b, its output to q.
fn gate_body(ty: &str, instance: &str, pins: [&str; 2], out: &str) -> String {
    block(4, ty, instance, 10, &[(pins[0], 2), (pins[1], 3)], out) + &coil(5, 10, 4, out, "q")
}

fn gate(ty: &str, instance: &str, pins: [&str; 2], out: &str) -> String {
    project(&gate_body(ty, instance, pins, out))
}

/// Y00 after each (X00, X01) in turn, a scan or two each.
fn run(xml: &str, map: &str, inputs: &[(bool, bool)]) -> Vec<bool> {
    let map = VarMap::parse(map).expect("a map");
    let imported =
        import_mapped(xml, Some(MachineId::Io86a), Some(&map)).unwrap_or_else(|e| panic!("{e:?}"));
    let text = compile(&imported.ladder, MachineId::Io86a, Default::default())
        .unwrap_or_else(|e| panic!("{e:?}"));
    let mut m = Io86aPlc::new();
    m.load_text(&text).expect("loads");
    m.apply(Command::Setting {
        name: "filter".into(),
        value: "0ms".into(),
    })
    .ok();
    let (x0, x1, y0) = (m.device("X00"), m.device("X01"), m.device("Y00"));
    let (x0, x1, y0) = (x0.expect("X00"), x1.expect("X01"), y0.expect("Y00"));
    let mut out = Vec::new();
    for &(a, b) in inputs {
        m.apply(Command::SetInput(x0, InputValue::Int(i64::from(a))))
            .expect("input");
        m.apply(Command::SetInput(x1, InputValue::Int(i64::from(b))))
            .expect("input");
        let t = m.now().saturating_add(SimTime::from_millis(50));
        m.run_until(t);
        out.push(m.read(y0) != 0);
    }
    out
}

const TABLE: [(bool, bool); 4] = [(false, false), (true, false), (false, true), (true, true)];

#[test]
fn and_or_xor_follow_their_truth_tables() {
    let and = run(&gate("AND", "", ["IN1", "IN2"], "OUT"), "", &TABLE);
    assert_eq!(and, [false, false, false, true]);
    let or = run(&gate("OR", "", ["IN1", "IN2"], "OUT"), "", &TABLE);
    assert_eq!(or, [false, true, true, true]);
    let xor = run(&gate("XOR", "", ["IN1", "IN2"], "OUT"), "", &TABLE);
    assert_eq!(xor, [false, true, true, false]);
}

#[test]
fn sr_sets_and_holds_and_set_wins_rs_lets_reset_win() {
    // a sets, b resets; both at once: SR stays set, RS resets.
    let steps = [
        (true, false),
        (false, false),
        (true, true),
        (false, false),
        (false, true),
    ];
    let sr = run(&gate("SR", "SR0", ["S1", "R"], "Q1"), "SR0,M10\n", &steps);
    assert_eq!(sr, [true, true, true, true, false]);
    let rs = run(&gate("RS", "RS0", ["S", "R1"], "Q1"), "RS0,M11\n", &steps);
    assert_eq!(rs, [true, true, false, false, false]);
}

#[test]
fn what_does_not_fit_is_refused_with_the_reason() {
    let xml = gate("SR", "SR0", ["S1", "R"], "Q1");
    let errors = import_mapped(&xml, Some(MachineId::Io86a), None).expect_err("no relay");
    assert!(
        errors[0]
            .error
            .to_string()
            .contains("map it (--map SR0,M10)"),
        "{errors:?}"
    );
    // An OR whose input also feeds a coil would feed power back: refused.
    let shared =
        project(&(gate_body("OR", "", ["IN1", "IN2"], "OUT") + &coil(6, 30, 3, "", "Y01")));
    let errors = import_mapped(&shared, Some(MachineId::Io86a), None).expect_err("shared input");
    assert!(
        errors[0]
            .error
            .to_string()
            .contains("OR block: an input also feeds another element"),
        "{errors:?}"
    );
}

#[test]
fn a_counter_in_line_and_a_coil_on_the_rail_run_on_io86a() {
    // a counts CTU0 (PV 2 from a variable declared with it), its Q lights
    // q; Y01 hangs on the rail itself (always on).
    let body = block(4, "CTU", "CTU0", 10, &[("CU", 2), ("R", 3), ("PV", 7)], "Q")
        + r#"
      <inVariable localId="7"><position x="20" y="40"/><connectionPointOut/><expression>limit</expression></inVariable>"#
        + &coil(5, 10, 4, "Q", "q")
        + &coil(6, 50, 1, "", "Y01");
    let xml = project(&body)
    .replace(
        "</localVars>",
        r#"<variable name="limit"><type><INT/></type><initialValue><simpleValue value="2"/></initialValue></variable></localVars>"#,
    );
    // a pulses twice: the count reaches 2 and q lights; b resets it.
    let steps = [
        (true, false),
        (false, false),
        (true, false),
        (false, false),
        (false, true),
    ];
    let q = run(&xml, "CTU0,C00\n", &steps);
    assert_eq!(q, [false, false, true, true, false]);
}

#[test]
fn an_and_input_moved_after_another_counts_as_taking_its_power() {
    // AND(a, b) to q, then OR(a, c) to Y01: a's point now also feeds b's
    // contact, so joining it into the OR would feed power back: refused.
    let body = gate_body("AND", "", ["IN1", "IN2"], "OUT")
        + r#"
      <contact localId="8"><position x="10" y="60"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>X02</variable></contact>"#
        + &block(6, "OR", "", 60, &[("IN1", 2), ("IN2", 8)], "OUT")
        + &coil(7, 60, 6, "OUT", "Y01");
    let xml = project(&body);
    let errors =
        import_mapped(&xml, Some(MachineId::Io86a), None).expect_err("shared after the AND");
    assert!(
        errors[0]
            .error
            .to_string()
            .contains("OR block: an input also feeds"),
        "{errors:?}"
    );
}

/// A timer block from `a` to `q`, with PT 300 ms.
fn timer_block(ty: &str) -> String {
    let body = block(4, ty, &format!("{ty}0"), 10, &[("IN", 2), ("PT", 7)], "Q")
        + r#"
      <inVariable localId="7"><position x="20" y="40"/><connectionPointOut/><expression>T#300ms</expression></inVariable>"#
        + &coil(5, 10, 4, "Q", "q")
        + &coil(9, 30, 3, "", "Y01");
    project(&body)
}

#[test]
fn tof_and_tp_on_io86a_use_its_on_delay_timer_and_a_relay() {
    // 50 ms a step. TOF: on with a, held 300 ms after a falls.
    let mut steps = vec![(true, false), (true, false)];
    steps.extend([(false, false); 10]);
    let q = run(&timer_block("TOF"), "TOF0,T01+M20\n", &steps);
    assert!(q[..6].iter().all(|&on| on), "held after a falls: {q:?}");
    assert!(q[9..].iter().all(|&on| !on), "off 300 ms after: {q:?}");
    // TP: 300 ms from a's rise, however long a stays on; again after a
    // falls and rises.
    let mut steps = vec![(true, false); 10];
    steps.extend([(false, false), (true, false)]);
    let q = run(&timer_block("TP"), "TP0,T02+M21\n", &steps);
    assert!(q[0] && q[3], "the pulse: {q:?}");
    assert!(!q[8] && !q[9], "over while a is still on: {q:?}");
    assert!(q[11], "a new rise, a new pulse: {q:?}");
    // Mapped to a timer alone, a TOF is refused as before.
    let errors = import_mapped(
        &timer_block("TOF"),
        Some(MachineId::Io86a),
        Some(&VarMap::parse("TOF0,T01\n").expect("map")),
    )
    .expect_err("no relay");
    assert!(errors[0].error.to_string().contains("TOF"), "{errors:?}");
}
