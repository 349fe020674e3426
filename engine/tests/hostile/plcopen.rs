//! PLCopen XML: depth, size, duplicate ids, booleans and edges.

use engine::ladder::plcopen::import;
use engine::ladder::{ContactKind, Element};

use crate::gen::{plcopen_alternating, plcopen_rails, plcopen_rungs};

#[test]
fn deep_nesting_is_refused_at_its_line() {
    let deep = format!(
        "<project>\n{}{}</project>",
        "<a>".repeat(200_000),
        "</a>".repeat(200_000)
    );
    let errors = import(&deep).expect_err("too deep");
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
    let ladder = import(&plcopen_rungs(5_000, "X00", "Y00")).expect("imports");
    assert_eq!(ladder.rungs.len(), 5_000);
    assert!(ladder
        .rungs
        .iter()
        .all(|r| r.cells == ladder.rungs[0].cells));
}

#[test]
fn fifty_thousand_rails_import() {
    let ladder = import(&plcopen_rails(50_000)).expect("imports");
    assert_eq!(ladder.rungs.len(), 1);
}

#[test]
fn a_network_nested_past_the_limit_is_refused_not_drawn() {
    let errors = import(&plcopen_alternating(6_000)).expect_err("too deep");
    assert!(
        errors[0]
            .error
            .to_string()
            .contains("nest more than 100 deep"),
        "{errors:?}"
    );
    // Shallow alternation draws fine.
    let ladder = import(&plcopen_alternating(40)).expect("imports");
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
    let errors = import(&xml).expect_err("duplicate");
    assert_eq!(errors[0].line, 4);
    assert!(
        errors[0]
            .error
            .to_string()
            .contains("localId \"2\" is used again (first on line 3)"),
        "{errors:?}"
    );
}

#[test]
fn negated_accepts_every_xml_boolean() {
    for (value, nc) in [("true", true), ("1", true), ("false", false), ("0", false)] {
        let xml = body(&format!(
            r#"<contact localId="2" negated="{value}"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>X00</variable></contact>
<coil localId="3" negated="{value}"><connectionPointIn><connection refLocalId="2"/></connectionPointIn><variable>Y00</variable></coil>"#
        ));
        let ladder = import(&xml).expect(value);
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
    let errors = import(&xml).expect_err("not a boolean");
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
    let errors = import(&xml).expect_err("bogus edge");
    assert_eq!(errors[0].line, 3);
    assert_eq!(
        errors[0].error,
        engine::ladder::plcopen::ImportError::BadEdge("bogus".into())
    );
    assert_eq!(
        errors[0].error.to_string(),
        "edge=\"bogus\" is not none, rising or falling"
    );
}

#[test]
fn a_few_hundred_blocks_lower_and_thousands_are_refused_not_slow() {
    let ladder = import(&crate::gen::plcopen_ors(300)).expect("imports");
    assert_eq!(ladder.rungs.len(), 300);
    let started = std::time::Instant::now();
    let errors = import(&crate::gen::plcopen_ors(2_000)).expect_err("refused");
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
