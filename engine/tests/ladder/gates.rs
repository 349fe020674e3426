//! Boolean blocks from other tools lowered to ladder (issue #18): each
//! imported program runs on IO86A (and the AVR PLC) as the block's truth
//! table says.

use engine::events::InputValue;
use engine::formats::plcopen::Document;
use engine::formats::plcopen::VarMap;
use engine::ladder::compile::compile;
use engine::machines::{AvrPlc, Io86aPlc};
use engine::plc::{Command, Plc};
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
    run_both(xml, map, inputs)
        .into_iter()
        .map(|(y0, _)| y0)
        .collect()
}

/// `xml` imported for IO86A with `map`, compiled and loaded, its input
/// filter off (an input counts from the next scan); and the program text.
pub(crate) fn io86a_loaded(xml: &str, map: &VarMap) -> Result<(Io86aPlc, String), String> {
    let imported = Document::read(xml)
        .and_then(|document| document.import(Some(MachineId::Io86a), Some(map), None))
        .map_err(|e| format!("{e:?}"))?;
    let text = compile(&imported.ladder, MachineId::Io86a, Default::default())
        .map_err(|e| format!("{e:?}"))?;
    let mut m = Io86aPlc::new();
    m.load_text(&text).map_err(|e| format!("{e:?}"))?;
    m.apply(Command::Setting {
        name: "filter".into(),
        value: "0".into(),
    })
    .map_err(|e| format!("{e:?}"))?;
    Ok((m, text))
}

/// `xml` imported for the AVR PLC with `map`, compiled and loaded; and
/// the program text.
pub(crate) fn avr_loaded(xml: &str, map: &VarMap) -> Result<(AvrPlc, String), String> {
    let imported = Document::read(xml)
        .and_then(|document| document.import(Some(MachineId::AvrPlc), Some(map), None))
        .map_err(|e| format!("{e:?}"))?;
    let text = compile(&imported.ladder, MachineId::AvrPlc, Default::default())
        .map_err(|e| format!("{e:?}"))?;
    let mut m = AvrPlc::new();
    m.load_text(&text).map_err(|e| format!("{e:?}"))?;
    Ok((m, text))
}

/// (Y00, Y01) after each (X00, X01) in turn, 50 ms each.
fn run_both(xml: &str, map: &str, inputs: &[(bool, bool)]) -> Vec<(bool, bool)> {
    let map = VarMap::parse(map).expect("a map");
    let (mut m, _) = io86a_loaded(xml, &map).unwrap_or_else(|e| panic!("{e}"));
    let (x0, x1, y0) = (m.device("X00"), m.device("X01"), m.device("Y00"));
    let (x0, x1, y0) = (x0.expect("X00"), x1.expect("X01"), y0.expect("Y00"));
    let y1 = m.device("Y01").expect("Y01");
    let mut out = Vec::new();
    for &(a, b) in inputs {
        m.apply(Command::SetInput(x0, InputValue::Int(i64::from(a))))
            .expect("input");
        m.apply(Command::SetInput(x1, InputValue::Int(i64::from(b))))
            .expect("input");
        let t = m.now().saturating_add(SimTime::from_millis(50));
        m.run_until(t);
        out.push((m.read(y0) != 0, m.read(y1) != 0));
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
    let errors = Document::read(&xml)
        .and_then(|document| document.import(Some(MachineId::Io86a), None, None))
        .expect_err("no relay");
    assert!(
        errors[0]
            .error
            .to_string()
            .contains("map it (--map SR0,M10)"),
        "{errors:?}"
    );
}

#[test]
fn an_input_that_also_feeds_more_is_carried_by_a_spare_relay() {
    // OR(a, b) to q while b also lights Y01: joining b's point into the
    // OR would feed a's power to Y01, so a relay holds b's.
    let shared =
        project(&(gate_body("OR", "", ["IN1", "IN2"], "OUT") + &coil(6, 30, 3, "", "Y01")));
    let seen = run_both(&shared, "", &TABLE);
    assert_eq!(
        seen,
        [(false, false), (true, false), (true, true), (true, true)]
    );
    let imported = Document::read(&shared)
        .and_then(|document| document.import(Some(MachineId::Io86a), None, None))
        .expect("imports");
    assert_eq!(
        imported
            .ladder
            .device_comments
            .get("M55")
            .map(String::as_str),
        Some("OR block's input"),
        "the highest free relay, named"
    );
    assert!(
        imported
            .warnings
            .iter()
            .any(|w| w.error.to_string().contains("M55 holds OR block's input")),
        "{:?}",
        imported.warnings
    );
    // AND(a, b) to q, then OR(a, X02) to Y01: a's point feeds b's contact
    // after the AND, so the OR takes a through a relay too.
    let body = gate_body("AND", "", ["IN1", "IN2"], "OUT")
        + r#"
      <contact localId="8"><position x="10" y="60"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>X02</variable></contact>"#
        + &block(6, "OR", "", 60, &[("IN1", 2), ("IN2", 8)], "OUT")
        + &coil(7, 60, 6, "OUT", "Y01");
    let seen = run_both(&project(&body), "", &TABLE);
    assert_eq!(
        seen,
        [(false, false), (false, true), (false, false), (true, true)]
    );
}

/// `body` with the block's IN fed by contacts a and b both (a fan-in:
/// a OR b).
fn fed_by_a_or_b(body: &str) -> String {
    let one = r#"<variable formalParameter="IN"><connectionPointIn><connection refLocalId="2"/>"#;
    assert!(body.contains(one), "{body}");
    body.replace(
        one,
        r#"<variable formalParameter="IN"><connectionPointIn><connection refLocalId="2"/><connection refLocalId="3"/>"#,
    )
}

#[test]
fn a_box_io86a_lacks_in_line_is_its_input_contact_turned_or_a_relay() {
    let relays_said = |xml: &str| {
        let map = VarMap::default();
        let imported = Document::read(xml)
            .and_then(|document| document.import(Some(MachineId::Io86a), Some(&map), None))
            .expect("imports");
        let said = imported.warnings.iter().map(|w| w.error.to_string());
        said.filter(|w| w.contains(" holds ")).collect::<Vec<_>>()
    };
    // NOT a, R_TRIG a: a's NC and rising contacts, no relay.
    let not = block(4, "NOT", "", 10, &[("IN", 2)], "OUT") + &coil(5, 10, 4, "OUT", "q");
    let not = project(&not);
    assert_eq!(relays_said(&not), Vec::<String>::new());
    assert_eq!(run(&not, "", &TABLE), [true, false, true, false]);
    let trig = block(4, "R_TRIG", "", 10, &[("CLK", 2)], "Q") + &coil(5, 10, 4, "Q", "q");
    let trig = project(&trig);
    assert_eq!(relays_said(&trig), Vec::<String>::new());
    // One scan per value of a: the pulse lasts the scan a rises in.
    let (mut m, text) = io86a_loaded(&trig, &VarMap::default()).unwrap_or_else(|e| panic!("{e}"));
    let (x0, y0) = (m.device("X00").expect("X00"), m.device("Y00").expect("Y00"));
    let mut seen = Vec::new();
    for a in [false, true, true, false, true] {
        m.apply(Command::SetInput(x0, InputValue::Int(i64::from(a))))
            .expect("input");
        m.step_scan();
        seen.push(m.read(y0) != 0);
    }
    assert_eq!(seen, [false, true, false, false, true], "{text}");
    // NOT (a OR b): a relay holds the network, its NC contact is q.
    let network = block(4, "NOT", "", 10, &[("IN", 2)], "OUT") + &coil(5, 10, 4, "OUT", "q");
    let network = project(&fed_by_a_or_b(&network));
    let said = relays_said(&network);
    assert!(
        said.iter()
            .any(|w| w.starts_with("M55 holds NOT block's input")),
        "{said:?}"
    );
    assert_eq!(run(&network, "", &TABLE), [true, false, false, false]);
}

#[test]
fn a_tof_whose_input_is_a_network_holds_it_in_a_relay() {
    // IN is a then b in series (b's contact fed by a's).
    let body = r#"
      <contact localId="8"><position x="20" y="10"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><variable>b</variable></contact>"#
        .to_string()
        + &block(4, "TOF", "TOF0", 10, &[("IN", 8), ("PT", 7)], "Q")
        + r#"
      <inVariable localId="7"><position x="20" y="40"/><connectionPointOut/><expression>T#300ms</expression></inVariable>"#
        + &coil(5, 10, 4, "Q", "q");
    let xml = project(&body).replace(
        r#"<contact localId="3"><position x="10" y="30"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>b</variable></contact>"#,
        "",
    );
    let mut steps = vec![(true, false), (true, true), (true, true)];
    steps.extend([(true, false); 10]);
    let q = run(&xml, "TOF0,T01+M20\n", &steps);
    assert!(!q[0], "a alone is not IN: {q:?}");
    assert!(q[1..8].iter().all(|&on| on), "on, then held: {q:?}");
    assert!(q[10..].iter().all(|&on| !on), "off 300 ms after: {q:?}");
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
    let errors = Document::read(&timer_block("TOF"))
        .and_then(|document| {
            document.import(
                Some(MachineId::Io86a),
                Some(&VarMap::parse("TOF0,T01\n").expect("map")),
                None,
            )
        })
        .expect_err("no relay");
    assert!(errors[0].error.to_string().contains("TOF"), "{errors:?}");
}

/// A counter `ty` with its count pin on a and its second pin (`LD` or
/// `R`) on b, PV 2, its outputs `outs` to q and Y01.
fn counter(ty: &str, count: &str, other: &str, outs: [&str; 2]) -> String {
    let pins = [(count, 2), (other, 3), ("PV", 7)];
    let body = block(4, ty, &format!("{ty}0"), 10, &pins, outs[0]).replace(
        "</outputVariables>",
        &format!(
            r#"<variable formalParameter="{}"><connectionPointOut/></variable></outputVariables>"#,
            outs[1]
        ),
    ) + r#"
      <inVariable localId="7"><position x="20" y="40"/><connectionPointOut/><expression>2</expression></inVariable>"#
        + &coil(5, 10, 4, outs[0], "q")
        + &coil(6, 20, 4, outs[1], "Y01");
    project(&body)
}

#[test]
fn ctd_counts_down_from_its_load_on_io86a_s_up_counter() {
    // CTD: Q (CV <= 0) is on from power-up until LD loads PV; two rises of
    // CD bring CV to 0 again; LD again reloads. Y01 shows Q too.
    let xml = counter("CTD", "CD", "LD", ["Q", "Q"]);
    let steps = [
        (false, false),
        (false, true),
        (false, false),
        (true, false),
        (false, false),
        (true, false),
        (false, false),
        (false, true),
    ];
    let q = run(&xml, "CTD0,C01\n", &steps);
    assert_eq!(q, [true, false, false, false, false, true, true, false]);
}

#[test]
fn ctud_counting_up_gives_qu_and_qd_and_refuses_what_it_cannot_load() {
    // CU on a, R on b, PV 2: QU (q) at two rises; QD (Y01) until the first.
    let xml = counter("CTUD", "CU", "R", ["QU", "QD"]);
    let steps = [
        (false, false),
        (true, false),
        (false, false),
        (true, false),
        (true, true),
        (true, false),
    ];
    let seen = run_both(&xml, "CTUD0,C02\n", &steps);
    assert_eq!(
        seen,
        [
            (false, true),
            (false, false),
            (false, false),
            (true, false),
            (false, true),
            (false, true)
        ],
        "after R, a held on is no new rise"
    );
    // Its LD wired: IO86A's counters cannot be loaded.
    let loaded = counter("CTUD", "CU", "LD", ["QU", "QD"]);
    let map = VarMap::parse("CTUD0,C02\n").expect("map");
    let errors = Document::read(&loaded)
        .and_then(|document| document.import(Some(MachineId::Io86a), Some(&map), None))
        .expect_err("LD wired");
    assert!(
        errors[0].error.to_string().contains("its LD is wired"),
        "{errors:?}"
    );
}

#[test]
fn comparisons_run_as_cmp_and_a_relay_each() {
    // CTU0 (C00) counts a, b resets it; n is its count: q = n >= 2,
    // Y01 = n < 1. Two CMPs share M60-M62: each result is copied first.
    // Each result reaches its coil through an NC contact of X07 drawn at
    // the top: the rung reading it sorts first, and must still see this
    // scan's comparison.
    let compare = |id: u32, ty: &str, k: &str, y: u32, to: &str| {
        format!(
            r#"
      <contact localId="{}" negated="true"><position x="50" y="0"/><connectionPointIn><connection refLocalId="{id}" formalParameter="OUT"/></connectionPointIn><variable>X07</variable></contact>"#,
            id + 4
        ) + &format!(
            r#"
      <inVariable localId="{}"><position x="20" y="{y}"/><connectionPointOut/><expression>n</expression></inVariable>
      <inVariable localId="{}"><position x="20" y="{y}"/><connectionPointOut/><expression>{k}</expression></inVariable>"#,
            id + 1,
            id + 2
        ) + &block(id, ty, "", y, &[("IN1", id + 1), ("IN2", id + 2)], "OUT")
            + &coil(id + 3, y, id + 4, "", to)
    };
    let body = block(4, "CTU", "CTU0", 10, &[("CU", 2), ("R", 3), ("PV", 7)], "Q")
        + r#"
      <inVariable localId="7"><position x="20" y="40"/><connectionPointOut/><expression>9</expression></inVariable>"#
        + &compare(10, "GE", "2", 60, "q")
        + &compare(20, "LT", "1", 80, "Y01");
    let xml = project(&body).replace(
        "</localVars>",
        r#"<variable name="n"><type><INT/></type></variable></localVars>"#,
    );
    let steps = [
        (false, false),
        (true, false),
        (false, false),
        (true, false),
        (false, false),
        (false, true),
    ];
    let seen = run_both(&xml, "CTU0,C00\nn,C00\n", &steps);
    assert_eq!(
        seen,
        [
            (false, true),
            (false, false),
            (false, false),
            (true, false),
            (true, false),
            (false, true)
        ]
    );
    // A word with no device is refused, naming the map entry to add.
    let errors = Document::read(&xml)
        .and_then(|document| {
            document.import(
                Some(MachineId::Io86a),
                Some(&VarMap::parse("CTU0,C00\n").expect("map")),
                None,
            )
        })
        .expect_err("n unmapped");
    assert!(
        errors[0]
            .error
            .to_string()
            .contains(r#"IN1 "n": is no word: map it to a data register (--map n,D00)"#),
        "{errors:?}"
    );
    // On a machine without CMP: refused with the reason.
    let errors = Document::read(&xml)
        .and_then(|document| {
            document.import(
                Some(MachineId::MinasecU),
                Some(&VarMap::parse("n,C0\n").expect("map")),
                None,
            )
        })
        .expect_err("no CMP");
    assert!(
        errors
            .iter()
            .any(|e| e.error.to_string().contains("comparisons need IO86A's CMP")),
        "{errors:?}"
    );
}

#[test]
fn an_fbd_program_runs_as_its_blocks_say() {
    // FBD draws the same graph as LD without rails, contacts or coils:
    // variables feed blocks, blocks feed variables. Y00 = a AND b,
    // Y01 = NOT b (b feeds both: each reads its own contact of X01).
    let boxes = |ty: &str, id: u32, y: u32, pins: &[(&str, u32)], to: &str| {
        let pins: String = pins
            .iter()
            .map(|(pin, from)| {
                format!(
                    r#"<variable formalParameter="{pin}"><connectionPointIn><connection refLocalId="{from}"/></connectionPointIn></variable>"#
                )
            })
            .collect();
        format!(
            r#"
      <block localId="{id}" typeName="{ty}"><position x="50" y="{y}"/><inputVariables>{pins}</inputVariables>
        <outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>
      <outVariable localId="{}"><position x="100" y="{y}"/><connectionPointIn><connection refLocalId="{id}" formalParameter="OUT"/></connectionPointIn><expression>{to}</expression></outVariable>"#,
            id + 1
        )
    };
    let xml = format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <types><pous><pou name="main" pouType="program">
    <interface><localVars>
      <variable name="a" address="%IX0.0"><type><BOOL/></type></variable>
      <variable name="b" address="%IX0.1"><type><BOOL/></type></variable>
      <variable name="q" address="%QX0.0"><type><BOOL/></type></variable>
    </localVars></interface>
    <body><FBD>
      <inVariable localId="1"><position x="10" y="10"/><connectionPointOut/><expression>a</expression></inVariable>
      <inVariable localId="2"><position x="10" y="40"/><connectionPointOut/><expression>b</expression></inVariable>{}{}
    </FBD></body>
  </pou></pous></types>
</project>"#,
        boxes("AND", 3, 10, &[("IN1", 1), ("IN2", 2)], "q"),
        boxes("NOT", 5, 60, &[("IN", 2)], "Y01")
    );
    let map = VarMap::parse("").expect("a map");
    let imported = Document::read(&xml)
        .and_then(|document| document.import(Some(MachineId::Io86a), Some(&map), None))
        .expect("imports");
    assert!(imported.warnings.is_empty(), "{:?}", imported.warnings);
    let (_, text) = io86a_loaded(&xml, &map).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(text.matches("X01").count(), 2, "{text}");
    assert!(!text.contains('M'), "no spare relay: {text}");
    let seen = run_both(&xml, "", &TABLE);
    assert_eq!(
        seen,
        [(false, true), (false, true), (false, false), (true, false)]
    );
    // A negated variable box reads its NC contact: a AND NOT b, NOT NOT b.
    let b_box = r#"<inVariable localId="2">"#;
    assert!(xml.contains(b_box));
    let negated = xml.replace(b_box, r#"<inVariable localId="2" negated="true">"#);
    let seen = run_both(&negated, "", &TABLE);
    assert_eq!(
        seen,
        [(false, false), (true, false), (false, true), (false, true)]
    );
    // A negation circle or edge mark on a block's pin is refused by name.
    for (mark, why) in [
        (
            r#" negated="true""#,
            "its pin IN2 is negated: put a NOT block on it instead",
        ),
        (
            r#" edge="rising""#,
            "its pin IN2 is marked rising: put an R_TRIG or F_TRIG block on it instead",
        ),
    ] {
        let marked = xml.replacen(
            r#"<variable formalParameter="IN2">"#,
            &format!(r#"<variable formalParameter="IN2"{mark}>"#),
            1,
        );
        assert_ne!(marked, xml);
        let errors = Document::read(&marked)
            .and_then(|document| document.import(Some(MachineId::Io86a), None, None))
            .expect_err("marked pin");
        assert_eq!(errors[0].error.to_string(), format!("AND block: {why}"));
    }
    // A mark that is no XML boolean is refused as on a contact, not ignored.
    let garbled = xml.replacen(
        r#"<variable formalParameter="IN2">"#,
        r#"<variable formalParameter="IN2" negated="maybe">"#,
        1,
    );
    let errors = Document::read(&garbled)
        .and_then(|document| document.import(Some(MachineId::Io86a), None, None))
        .expect_err("garbled pin");
    assert_eq!(
        errors[0].error.to_string(),
        r#"negated="maybe" is not a boolean: true, false, 1 or 0"#
    );
    // A jump is refused at its line.
    let jump = xml.replace(
        "</FBD>",
        "<jump label=\"x\" localId=\"9\"><position x=\"1\" y=\"1\"/></jump>\n    </FBD>",
    );
    let errors = Document::read(&jump)
        .and_then(|document| document.import(Some(MachineId::Io86a), None, None))
        .expect_err("jump");
    let line = 1 + jump[..jump.find("<jump").expect("added")]
        .matches('\n')
        .count();
    assert_eq!(errors[0].line, line);
    assert_eq!(
        errors[0].error.to_string(),
        "<jump> is not supported in LD or FBD bodies here"
    );
}

#[test]
fn a_continuation_carries_what_feeds_its_connector() {
    // a → connector "from_a"; continuation "From_A" (names match in any
    // case) → AND IN1; b → IN2; the AND → q. And b → connector "nb" →
    // continuation → NOT → Y01.
    let body = |connector_a: &str| {
        format!(
            r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <types><pous><pou name="main" pouType="program">
    <interface><localVars>
      <variable name="a" address="%IX0.0"><type><BOOL/></type></variable>
      <variable name="b" address="%IX0.1"><type><BOOL/></type></variable>
      <variable name="q" address="%QX0.0"><type><BOOL/></type></variable>
    </localVars></interface>
    <body><FBD>
      <inVariable localId="1"><position x="10" y="10"/><connectionPointOut/><expression>a</expression></inVariable>
      {connector_a}
      <continuation name="From_A" localId="3"><position x="10" y="100"/><connectionPointOut/></continuation>
      <inVariable localId="4"><position x="10" y="120"/><connectionPointOut/><expression>b</expression></inVariable>
      <block localId="5" typeName="AND"><position x="50" y="100"/><inputVariables>
        <variable formalParameter="IN1"><connectionPointIn><connection refLocalId="3"/></connectionPointIn></variable>
        <variable formalParameter="IN2"><connectionPointIn><connection refLocalId="4"/></connectionPointIn></variable>
      </inputVariables><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>
      <outVariable localId="6"><position x="100" y="100"/><connectionPointIn><connection refLocalId="5" formalParameter="OUT"/></connectionPointIn><expression>q</expression></outVariable>
      <connector name="nb" localId="7"><position x="50" y="200"/><connectionPointIn><connection refLocalId="4"/></connectionPointIn></connector>
      <continuation name="nb" localId="8"><position x="10" y="300"/><connectionPointOut/></continuation>
      <block localId="9" typeName="NOT"><position x="50" y="300"/><inputVariables>
        <variable formalParameter="IN"><connectionPointIn><connection refLocalId="8"/></connectionPointIn></variable>
      </inputVariables><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>
      <outVariable localId="10"><position x="100" y="300"/><connectionPointIn><connection refLocalId="9" formalParameter="OUT"/></connectionPointIn><expression>Y01</expression></outVariable>
    </FBD></body>
  </pou></pous></types>
</project>"#
        )
    };
    let fed = r#"<connector name="from_a" localId="2"><position x="50" y="10"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn></connector>"#;
    let seen = run_both(&body(fed), "", &TABLE);
    assert_eq!(
        seen,
        [(false, true), (false, true), (false, false), (true, false)]
    );
    let refused = |xml: &str| {
        let errors = Document::read(xml)
            .and_then(|document| document.import(Some(MachineId::Io86a), None, None))
            .expect_err("refused");
        errors[0].error.to_string()
    };
    // No connector of that name; a connector fed by its own continuation.
    let missing = body(&fed.replace("from_a", "other"));
    assert!(
        refused(&missing).contains(r#"continuation "from_a", whose connector is not drawn"#),
        "{}",
        refused(&missing)
    );
    let looped = body(&fed.replace(r#"refLocalId="1""#, r#"refLocalId="3""#));
    assert!(
        refused(&looped).contains(r#"connector "from_a", which feeds itself"#),
        "{}",
        refused(&looped)
    );
    // The same name drawn twice.
    let twice = body(&format!(
        "{fed}\n{}",
        fed.replace(r#"localId="2""#, r#"localId="20""#)
    ));
    assert!(
        refused(&twice).contains(r#"connector "from_a" is drawn again (first on line 11)"#),
        "{}",
        refused(&twice)
    );
}

#[test]
fn a_comparison_of_more_inputs_compares_each_pair_in_turn() {
    // IEC: GT(9, n, 1) is 9 > n AND n > 1 (q); LE(1, n, 3) is
    // 1 <= n AND n <= 3 (Y01). n is C00, counting a's rises; b resets it.
    let compare = |id: u32, ty: &str, ks: [&str; 2], y: u32, to: &str| {
        let [first, last] = ks;
        format!(
            r#"
      <inVariable localId="{}"><position x="20" y="{y}"/><connectionPointOut/><expression>{first}</expression></inVariable>
      <inVariable localId="{}"><position x="20" y="{y}"/><connectionPointOut/><expression>n</expression></inVariable>
      <inVariable localId="{}"><position x="20" y="{y}"/><connectionPointOut/><expression>{last}</expression></inVariable>"#,
            id + 1,
            id + 2,
            id + 3
        ) + &block(
            id,
            ty,
            "",
            y,
            &[("IN1", id + 1), ("IN2", id + 2), ("IN3", id + 3)],
            "OUT",
        ) + &coil(id + 4, y, id, "OUT", to)
    };
    let body = block(4, "CTU", "CTU0", 10, &[("CU", 2), ("R", 3), ("PV", 7)], "Q")
        + r#"
      <inVariable localId="7"><position x="20" y="40"/><connectionPointOut/><expression>20</expression></inVariable>"#
        + &compare(10, "GT", ["9", "1"], 60, "q")
        + &compare(20, "LE", ["1", "3"], 80, "Y01");
    let xml = project(&body).replace(
        "</localVars>",
        r#"<variable name="n"><type><INT/></type></variable></localVars>"#,
    );
    // Count to 5, a rise at a time; then reset.
    let mut steps = Vec::new();
    for _ in 0..5 {
        steps.extend([(true, false), (false, false)]);
    }
    steps.push((false, true));
    let seen: Vec<(bool, bool)> = run_both(&xml, "CTU0,C00\nn,C00\n", &steps)
        .into_iter()
        .step_by(2)
        .collect();
    // n = 1, 2, 3, 4, 5, then 0.
    assert_eq!(
        seen,
        [
            (false, true),
            (true, true),
            (true, true),
            (true, false),
            (true, false),
            (false, false)
        ]
    );
    // OpenPLC lists EN among the inputs when it is drawn: from the rail,
    // the block always runs and compares the same.
    let in1 = r#"<variable formalParameter="IN1"><connectionPointIn><connection refLocalId="11"/>"#;
    assert!(xml.contains(in1));
    let enabled = xml.replace(
        in1,
        &(r#"<variable formalParameter="EN"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable>"#.to_string() + in1),
    );
    let again: Vec<(bool, bool)> = run_both(&enabled, "CTU0,C00\nn,C00\n", &steps)
        .into_iter()
        .step_by(2)
        .collect();
    assert_eq!(again, seen);
    // OpenPLC marks CU rising (CTU counts rises): the same count. A
    // falling mark would count falls, which Hashigo's counters do not.
    let cu = r#"<variable formalParameter="CU">"#;
    assert!(xml.contains(cu));
    let rising = xml.replace(cu, r#"<variable formalParameter="CU" edge="rising">"#);
    let again: Vec<(bool, bool)> = run_both(&rising, "CTU0,C00\nn,C00\n", &steps)
        .into_iter()
        .step_by(2)
        .collect();
    assert_eq!(again, seen);
    let falling = xml.replace(cu, r#"<variable formalParameter="CU" edge="falling">"#);
    let map = VarMap::parse("CTU0,C00\nn,C00\n").expect("map");
    let errors = Document::read(&falling)
        .and_then(|document| document.import(Some(MachineId::Io86a), Some(&map), None))
        .expect_err("falling CU");
    assert!(
        errors[0]
            .error
            .to_string()
            .contains("CTU block: its pin CU is marked falling"),
        "{errors:?}"
    );
    // NE takes two inputs only, and a BOOL is no number to compare.
    let refused = |xml: &str| {
        let map = VarMap::parse("CTU0,C00\nn,C00\n").expect("map");
        let errors = Document::read(xml)
            .and_then(|document| document.import(Some(MachineId::Io86a), Some(&map), None))
            .expect_err("refused");
        errors[0].error.to_string()
    };
    let ne = xml.replace(r#"typeName="GT""#, r#"typeName="NE""#);
    assert!(
        refused(&ne).contains("NE block: it has 3 inputs: NE compares two"),
        "{}",
        refused(&ne)
    );
    let bool_operand = xml.replacen(
        "<expression>9</expression>",
        "<expression>a</expression>",
        1,
    );
    assert!(
        refused(&bool_operand).contains(r#"IN1 "a": is declared BOOL: a comparison takes numbers"#),
        "{}",
        refused(&bool_operand)
    );
}

#[test]
fn a_relay_holding_an_input_is_written_before_the_rung_reading_it() {
    // q = NOT (a OR b), through an NC contact of X07 drawn above the
    // block: the rung reading the relay sorts first, and is moved after
    // its writer, so q follows a in the same scan (as the origin tool
    // runs it). b stays off.
    let body = block(4, "NOT", "", 40, &[("IN", 2)], "OUT")
        + r#"
      <contact localId="6" negated="true"><position x="50" y="0"/><connectionPointIn><connection refLocalId="4" formalParameter="OUT"/></connectionPointIn><variable>X07</variable></contact>"#
        + &coil(5, 40, 6, "", "q");
    let (mut m, text) = io86a_loaded(&project(&fed_by_a_or_b(&body)), &VarMap::default())
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(text.contains("M55"), "a relay holds a OR b: {text}");
    let (x0, y0) = (m.device("X00").expect("X00"), m.device("Y00").expect("Y00"));
    let mut seen = Vec::new();
    for a in [false, true, false] {
        m.apply(Command::SetInput(x0, InputValue::Int(i64::from(a))))
            .expect("input");
        // Two scans: the input is latched at a scan's start.
        m.step_scan();
        let first = m.read(y0) != 0;
        m.step_scan();
        seen.push((first, m.read(y0) != 0));
    }
    assert_eq!(seen, [(true, true), (false, false), (true, true)], "{text}");
}

#[test]
fn a_proposal_skips_the_relay_a_given_timer_and_relay_entry_holds() {
    use engine::formats::plcopen::{declare, dom};
    let xml = timer_block("TOF");
    let root = dom::parse(&xml).expect("parses");
    let given = VarMap::parse("other,T05+M00\n").expect("a map");
    let proposed = declare::propose(&root, MachineId::Io86a, Some(&given));
    assert_eq!(
        proposed,
        [("TOF0".to_string(), "T00+M01".to_string())],
        "M00 is other's relay"
    );
}

#[test]
fn on_the_avr_plc_a_box_off_the_main_line_goes_through_a_relay() {
    // q = TON(a, 100 ms) OR b: the AVR PLC's timers act on the running
    // result, so the timer gets a rung of its own into a spare relay.
    let body = block(4, "TON", "TON0", 10, &[("IN", 2), ("PT", 7)], "Q")
        + r#"
      <inVariable localId="7"><position x="20" y="40"/><connectionPointOut/><expression>T#100ms</expression></inVariable>
      <coil localId="5"><position x="60" y="10"/><connectionPointIn><connection refLocalId="4" formalParameter="Q"/><connection refLocalId="3"/></connectionPointIn><variable>q</variable></coil>"#;
    let (mut m, text) =
        avr_loaded(&project(&body), &VarMap::default()).unwrap_or_else(|e| panic!("{e}"));
    assert!(text.contains("Coil_A,15,Bit7"), "R15.7 holds Q: {text}");
    let (a, b, q) = (m.device("R4.0"), m.device("R4.1"), m.device("R5.0"));
    let (a, b, q) = (a.expect("R4.0"), b.expect("R4.1"), q.expect("R5.0"));
    let mut seen = Vec::new();
    for (at, a_on, b_on) in [
        (50, 1, 0),
        (150, 1, 0),
        (250, 0, 0),
        (300, 0, 1),
        (350, 0, 0),
    ] {
        m.apply(Command::SetInput(a, InputValue::Int(a_on)))
            .expect("input");
        m.apply(Command::SetInput(b, InputValue::Int(b_on)))
            .expect("input");
        m.run_until(SimTime::from_millis(at));
        seen.push(m.read(q) != 0);
    }
    assert_eq!(seen, [false, true, false, true, false], "{text}");
    // NOT(a) OR a: always on, the NOT through a relay's NC contact.
    let body = block(4, "NOT", "", 10, &[("IN", 2)], "OUT")
        + r#"
      <coil localId="5"><position x="60" y="10"/><connectionPointIn><connection refLocalId="4" formalParameter="OUT"/><connection refLocalId="2"/></connectionPointIn><variable>q</variable></coil>"#;
    let (mut m, text) =
        avr_loaded(&project(&body), &VarMap::default()).unwrap_or_else(|e| panic!("{e}"));
    let (a, q) = (
        m.device("R4.0").expect("R4.0"),
        m.device("R5.0").expect("R5.0"),
    );
    for (at, on) in [(20, 0), (40, 1), (60, 0)] {
        m.apply(Command::SetInput(a, InputValue::Int(on)))
            .expect("input");
        m.run_until(SimTime::from_millis(at));
        assert!(m.read(q) != 0, "a = {on}: {text}");
    }
}

#[test]
fn wires_joined_at_a_coil_do_not_feed_back_into_a_wire_that_goes_elsewhere() {
    // q = a; Y01 = a OR b. Read as one electrical node, b would light q
    // too; the origin tools compute each input from its wires.
    let body = coil(5, 10, 2, "", "q")
        + r#"
      <coil localId="6"><position x="60" y="30"/><connectionPointIn><connection refLocalId="2"/><connection refLocalId="3"/></connectionPointIn><variable>Y01</variable></coil>"#;
    let seen = run_both(&project(&body), "", &TABLE);
    assert_eq!(
        seen,
        [(false, false), (true, true), (false, true), (true, true)]
    );
    // Joins of the very same wires are one node: no relay for them.
    let body = r#"
      <coil localId="5"><position x="60" y="10"/><connectionPointIn><connection refLocalId="2"/><connection refLocalId="3"/></connectionPointIn><variable>q</variable></coil>
      <coil localId="6"><position x="60" y="30"/><connectionPointIn><connection refLocalId="3"/><connection refLocalId="2"/></connectionPointIn><variable>Y01</variable></coil>"#;
    let (_, text) =
        io86a_loaded(&project(body), &VarMap::default()).unwrap_or_else(|e| panic!("{e}"));
    assert!(!text.contains('M'), "{text}");
    let seen = run_both(&project(body), "", &TABLE);
    assert_eq!(
        seen,
        [(false, false), (true, true), (true, true), (true, true)]
    );
}

#[test]
fn an_or_of_a_flip_flop_never_sets_it_whatever_the_file_order() {
    // q = OR(SR0.Q1, X02), the OR block written before the SR: X02
    // lights q while it is on, and leaves SR0 (M10) as it was.
    let body = r#"
      <contact localId="8"><position x="10" y="50"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>X02</variable></contact>"#
        .to_string()
        + &block(6, "OR", "", 20, &[("IN1", 4), ("IN2", 8)], "OUT").replace(
            r#"<connection refLocalId="4"/>"#,
            r#"<connection refLocalId="4" formalParameter="Q1"/>"#,
        )
        + &block(4, "SR", "SR0", 10, &[("S1", 2), ("R", 3)], "Q1")
        + &coil(5, 20, 6, "OUT", "q");
    let (mut m, text) = io86a_loaded(&project(&body), &VarMap::parse("SR0,M10\n").expect("a map"))
        .unwrap_or_else(|e| panic!("{e}"));
    let (x2, q, m10) = (m.device("X02"), m.device("Y00"), m.device("M10"));
    let (x2, q, m10) = (x2.expect("X02"), q.expect("Y00"), m10.expect("M10"));
    let mut seen = Vec::new();
    for on in [1, 0] {
        m.apply(Command::SetInput(x2, InputValue::Int(on)))
            .expect("input");
        m.step_scan();
        seen.push((m.read(q) != 0, m.read(m10) != 0));
    }
    assert_eq!(seen, [(true, false), (false, false)], "{text}");
}
