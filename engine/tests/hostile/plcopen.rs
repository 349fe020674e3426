//! PLCopen XML: depth, size, duplicate ids, booleans and edges.

use engine::formats::plcopen::Document;
use engine::ladder::{ContactKind, Element};

use crate::gen::{plcopen_alternating, plcopen_rails, plcopen_rungs};

#[test]
fn deep_nesting_is_refused_at_its_line() {
    let deep = format!(
        "<project>\n{}{}</project>",
        "<a>".repeat(200_000),
        "</a>".repeat(200_000)
    );
    let errors = Document::read(&deep)
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
        .expect_err("too deep");
    assert_eq!(errors.len(), 1);
    assert_eq!(errors[0].line, 2);
    assert!(
        errors[0]
            .error
            .to_string()
            .contains("nest more than 256 deep"),
        "{errors:?}"
    );
}

#[test]
fn five_thousand_rungs_on_one_rail_import() {
    let ladder = Document::read(&plcopen_rungs(5_000, "X00", "Y00"))
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
        .expect("imports");
    assert_eq!(ladder.rungs.len(), 5_000);
    assert!(ladder
        .rungs
        .iter()
        .all(|r| r.cells == ladder.rungs[0].cells));
}

#[test]
fn fifty_thousand_comments_over_five_thousand_rungs_import() {
    // Every title above the first rung: each weighs the few rungs that
    // start first below it, not all 5 000, and the nearest takes it.
    let comments: String = (0..50_000)
        .map(|i| {
            format!(
                r#"<comment localId="{}"><position x="10" y="0"/><content><xhtml:p xmlns:xhtml="http://www.w3.org/1999/xhtml">c{i}</xhtml:p></content></comment>"#,
                100_000 + i
            )
        })
        .collect();
    let xml = plcopen_rungs(5_000, "X00", "Y00").replacen(
        "<leftPowerRail",
        &format!("{comments}\n<leftPowerRail"),
        1,
    );
    let ladder = Document::read(&xml)
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
        .expect("imports");
    assert_eq!(ladder.rungs.len(), 5_000);
    assert_eq!(ladder.rungs[0].comment.lines().count(), 50_000);
    assert!(ladder.rungs[1..].iter().all(|r| r.comment.is_empty()));
}

#[test]
fn fifty_thousand_rails_import() {
    let ladder = Document::read(&plcopen_rails(50_000))
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
        .expect("imports");
    assert_eq!(ladder.rungs.len(), 1);
}

#[test]
fn a_network_nested_past_the_limit_is_refused_not_drawn() {
    let errors = Document::read(&plcopen_alternating(6_000))
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
        .expect_err("too deep");
    assert!(
        errors[0]
            .error
            .to_string()
            .contains("nest more than 100 deep"),
        "{errors:?}"
    );
    // Shallow alternation draws fine.
    let ladder = Document::read(&plcopen_alternating(40))
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
        .expect("imports");
    assert_eq!(ladder.rungs.len(), 1);
}

fn body(elements: &str) -> String {
    format!(
        r#"<project xmlns="http://www.plcopen.org/xml/tc6_0201"><types><pous><pou name="m" pouType="program"><body><LD>
<leftPowerRail localId="1"/>
{elements}
</LD></body></pou></pous></types></project>"#
    )
}

#[test]
fn a_local_id_used_twice_is_an_error() {
    let xml = body(
        r#"<contact localId="2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>X00</variable></contact>
<contact localId="2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>X01</variable></contact>
<coil localId="3"><connectionPointIn><connection refLocalId="2"/></connectionPointIn><variable>Y00</variable></coil>"#,
    );
    let errors = Document::read(&xml)
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
        .expect_err("duplicate");
    assert_eq!(errors[0].line, 4);
    assert!(
        errors[0]
            .error
            .to_string()
            .contains("localId \"2\" is used again (first on line 3)"),
        "{errors:?}"
    );
}

/// One body graph for both pipelines (issue #48): an SFC step taking a
/// localId, then a contact reusing it. The bit machines read both and
/// refuse the id used again and the step; the soft PLC refuses the step
/// alone (the contact after it is not the problem).
#[test]
fn both_pipelines_read_the_same_body_and_refuse_it_in_their_words() {
    let xml = body(
        r#"<step localId="2" name="S0"/>
<contact localId="2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>X00</variable></contact>
<coil localId="3"><connectionPointIn><connection refLocalId="2"/></connectionPointIn><variable>Y00</variable></coil>"#,
    );
    let document = Document::read(&xml).expect("a project");
    let bits = document
        .import(None, None, None)
        .map(|_| ())
        .expect_err("refused");
    let said: Vec<(usize, String)> = bits.iter().map(|e| (e.line, e.error.to_string())).collect();
    assert!(
        said.iter()
            .any(|(l, e)| *l == 4 && e.contains("localId \"2\" is used again (first on line 3)")),
        "{said:?}"
    );
    assert!(
        said.iter().any(|(l, e)| *l == 3 && e.contains("step")),
        "{said:?}"
    );
    let soft = document
        .soft_program(None)
        .map(|_| ())
        .expect_err("refused");
    let said: Vec<(usize, String)> = soft.iter().map(|e| (e.line, e.error.to_string())).collect();
    assert_eq!(said.len(), 1, "{said:?}");
    assert_eq!(said[0].0, 3);
    assert!(
        said[0]
            .1
            .contains("<step> does not run on the soft PLC (SFC is not run)"),
        "{said:?}"
    );
}

#[test]
fn negated_accepts_every_xml_boolean() {
    for (value, nc) in [("true", true), ("1", true), ("false", false), ("0", false)] {
        let xml = body(&format!(
            r#"<contact localId="2" negated="{value}"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>X00</variable></contact>
<coil localId="3" negated="{value}"><connectionPointIn><connection refLocalId="2"/></connectionPointIn><variable>Y00</variable></coil>"#
        ));
        let ladder = Document::read(&xml)
            .and_then(|document| document.import(None, None, None))
            .map(|i| i.ladder)
            .expect(value);
        let cells = &ladder.rungs[0].cells[0];
        let kind = if nc { ContactKind::Nc } else { ContactKind::No };
        assert!(
            matches!(&cells[0], Some(Element::Contact { kind: k, .. }) if *k == kind),
            "{value}: {cells:?}"
        );
        let coil = if nc { "coil-not" } else { "coil" };
        let is_inverted = matches!(
            &cells[1],
            Some(Element::Coil {
                kind: engine::ladder::CoilKind::Inverted,
                ..
            })
        );
        assert_eq!(is_inverted, nc, "{value} {coil}: {cells:?}");
    }
    let xml = body(
        r#"<contact localId="2" negated="yes"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>X00</variable></contact>"#,
    );
    let errors = Document::read(&xml)
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
        .expect_err("not a boolean");
    assert!(
        errors[0]
            .error
            .to_string()
            .contains("negated=\"yes\" is not a boolean"),
        "{errors:?}"
    );
}

#[test]
fn an_unknown_edge_is_called_what_it_is() {
    let xml = body(
        r#"<contact localId="2" edge="bogus"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>X00</variable></contact>
<coil localId="3"><connectionPointIn><connection refLocalId="2"/></connectionPointIn><variable>Y00</variable></coil>"#,
    );
    let errors = Document::read(&xml)
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
        .expect_err("bogus edge");
    assert_eq!(errors[0].line, 3);
    assert_eq!(
        errors[0].error,
        engine::formats::plcopen::ImportError::BadEdge("bogus".into())
    );
    assert_eq!(
        errors[0].error.to_string(),
        "edge=\"bogus\" is not none, rising or falling"
    );
}

#[test]
fn a_few_hundred_blocks_lower_and_thousands_are_refused_not_slow() {
    // ANDs: each moves its inputs' networks, a search of the body.
    let ladder = Document::read(&crate::gen::plcopen_gates(300, "AND"))
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
        .expect("imports");
    assert_eq!(ladder.rungs.len(), 300);
    let started = std::time::Instant::now();
    let errors = Document::read(&crate::gen::plcopen_gates(2_000, "AND"))
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
        .expect_err("refused");
    assert!(
        errors[0]
            .error
            .to_string()
            .contains("steps to lower (docs/limits.md)"),
        "{errors:?}"
    );
    // Not a speed test: the refusal comes long before minutes of work.
    assert!(started.elapsed().as_secs() < 120);
}

#[test]
fn thousands_of_or_blocks_lower_in_one_pass() {
    // ORs are lowered with the joins of wires, all at once: linear.
    let started = std::time::Instant::now();
    let ladder = Document::read(&crate::gen::plcopen_gates(5_000, "OR"))
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
        .expect("imports");
    assert_eq!(ladder.rungs.len(), 5_000);
    // Not a speed test: one search of the body per OR would take minutes.
    assert!(started.elapsed().as_secs() < 60);
}

/// `xml` imported for IO86A, or a panic with its first errors.
fn imported_for_io86a(xml: &str) -> engine::ladder::Ladder {
    engine::formats::plcopen::Document::read(xml)
        .and_then(|document| document.import(Some(engine::MachineId::Io86a), None, None))
        .map(|i| i.ladder)
        .unwrap_or_else(|e| panic!("{:?}", &e[..e.len().min(3)]))
}

#[test]
fn thousands_of_not_blocks_fold_into_their_contacts_in_one_pass() {
    // IO86A has no in-line NOT: each NOT NOT X00 folds into X00's NO
    // contact (no spare relay, of which there are far fewer than 10 000).
    let started = std::time::Instant::now();
    let ladder = imported_for_io86a(&crate::gen::plcopen_double_nots(5_000));
    assert_eq!(ladder.rungs.len(), 5_000);
    let contact = Element::Contact {
        kind: ContactKind::No,
        device: "X00".into(),
    };
    assert!(ladder
        .rungs
        .iter()
        .all(|r| r.elements().any(|(_, e)| *e == contact)));
    // Not a speed test: a fold searching every edge per block would
    // take minutes here.
    assert!(started.elapsed().as_secs() < 60);
}

#[test]
fn thousands_of_split_timers_are_ordered_without_quadratic_work() {
    // 3 000 in-line TONs on one timer: 3 000 writers and 3 000 readers of
    // T00 to order (each reader after every writer).
    let started = std::time::Instant::now();
    let ladder = imported_for_io86a(&crate::gen::plcopen_timers(3_000));
    assert_eq!(
        ladder.rungs.len(),
        6_000,
        "a coil rung and a contact rung each"
    );
    let first_reader = ladder
        .rungs
        .iter()
        .position(|r| r.elements().any(|(_, e)| e.read_device() == Some("T00")));
    assert_eq!(first_reader, Some(3_000), "every OUT T00 first");
    // Not a speed test: quadratic ordering would take minutes here.
    assert!(started.elapsed().as_secs() < 60);
}

#[test]
fn a_long_chain_of_connectors_is_refused_not_followed_to_the_end() {
    // X00 feeds connector c0; continuation k(i) carries c(i) into
    // connector c(i+1); the last one feeds a coil. Followed recursively
    // without a limit, a long enough chain overflows the page's stack.
    let chain = |n: usize| {
        let mut e = String::from(
            r#"<contact localId="x"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>X00</variable></contact>
<connector name="c0" localId="c0"><connectionPointIn><connection refLocalId="x"/></connectionPointIn></connector>"#,
        );
        for i in 0..n {
            e.push_str(&format!(
                r#"
<continuation name="c{i}" localId="k{i}"><connectionPointOut/></continuation>
<connector name="c{}" localId="c{}"><connectionPointIn><connection refLocalId="k{i}"/></connectionPointIn></connector>"#,
                i + 1,
                i + 1
            ));
        }
        e.push_str(&format!(
            r#"
<continuation name="c{n}" localId="last"><connectionPointOut/></continuation>
<coil localId="y"><connectionPointIn><connection refLocalId="last"/></connectionPointIn><variable>Y00</variable></coil>"#
        ));
        body(&e)
    };
    let errors = Document::read(&chain(5_000))
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
        .expect_err("too long");
    assert!(
        errors[0]
            .error
            .to_string()
            .contains("passes through more than 64 connectors in a row"),
        "{errors:?}"
    );
    // A few in a row carry the rail's power to the coil.
    let ladder = Document::read(&chain(5))
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
        .expect("imports");
    let text =
        engine::ladder::compile::compile(&ladder, engine::MachineId::Io86a, Default::default())
            .expect("compiles");
    assert!(text.contains("LD X00\nOUT Y00\n"), "{text}");
}

#[test]
fn large_and_deep_projects_run_on_the_soft_plc_or_are_refused_at_a_line() {
    let started = std::time::Instant::now();
    let rungs = Document::read(&plcopen_rungs(5_000, "X00", "Y00"))
        .and_then(|document| document.soft_program(None))
        .expect("5 000 rungs");
    assert!(rungs.text.lines().count() > 5_000);
    let ors = Document::read(&crate::gen::plcopen_gates(5_000, "OR"))
        .and_then(|document| document.soft_program(None))
        .expect("5 000 ORs");
    let mut plc = engine::machines::new_plc(engine::MachineId::SoftPlc);
    engine::plc::Plc::load_text(plc.as_mut(), &ors.text).expect("loads");
    for levels in [1, 50, 400] {
        // Nesting is only wiring here: nothing recurses on it.
        Document::read(&plcopen_alternating(levels))
            .and_then(|document| document.soft_program(None))
            .expect("any depth");
    }
    // Not a speed test: a search per element would take minutes.
    assert!(started.elapsed().as_secs() < 60);
    let looped = plcopen_rungs(1, "X00", "Y00").replacen(
        "<leftPowerRail",
        r#"<connector localId="900" name="a"><position x="0" y="0"/><connectionPointIn><connection refLocalId="901"/></connectionPointIn></connector><continuation localId="901" name="a"><position x="0" y="0"/><connectionPointOut/></continuation><outVariable localId="902"><position x="0" y="0"/><connectionPointIn><connection refLocalId="901"/></connectionPointIn><expression>Y01</expression></outVariable><leftPowerRail"#,
        1,
    );
    let errors = Document::read(&looped)
        .and_then(|document| document.soft_program(None))
        .expect_err("a connector feeding itself");
    assert!(
        errors.iter().all(|e| e.line > 0) && !errors.is_empty(),
        "{errors:?}"
    );
}

#[test]
fn thousands_of_boxes_are_drawn_on_the_soft_plc_in_linear_work() {
    let soft = Some(engine::MachineId::SoftPlc);
    let started = std::time::Instant::now();
    // Every counter's reset network joined to its own box.
    let ladder = Document::read(&crate::gen::plcopen_counters(3_000))
        .and_then(|document| document.import(soft, None, None))
        .map(|i| i.ladder)
        .unwrap_or_else(|e| panic!("{:?}", &e[..e.len().min(3)]));
    assert_eq!(ladder.rungs.len(), 3_000);
    assert!(ladder.rungs.iter().all(|r| r
        .elements()
        .any(|(_, e)| matches!(e, Element::BoxInput { .. }))));
    // A chain of 3 000 boxes, each into the next through a variable of
    // its own, typed from the first's INT operand, the writer first.
    let ladder = Document::read(&crate::gen::plcopen_box_chain(3_000))
        .and_then(|document| document.import(soft, None, None))
        .map(|i| i.ladder)
        .unwrap_or_else(|e| panic!("{:?}", &e[..e.len().min(3)]));
    assert_eq!(ladder.rungs.len(), 3_000);
    let carried: Vec<_> = ladder
        .variables
        .iter()
        .filter(|v| v.name.starts_with("_MUL"))
        .collect();
    assert_eq!(carried.len(), 2_999);
    // The first is typed from INT#1; those after it from the one before,
    // past the depth followed back (DINT beyond it, said by the compiler).
    assert_eq!(carried[0].data_type, "INT");
    // Not a speed test: a search of the ladder per box would take minutes.
    assert!(started.elapsed().as_secs() < 60);
}
