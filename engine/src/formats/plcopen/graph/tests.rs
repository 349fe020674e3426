use super::{Graph, Kind, Read};
use crate::formats::plcopen::dom;
use crate::formats::plcopen::vendor::Vendor;

const BODY: &str = r#"<LD>
<leftPowerRail localId="1"/>
<comment localId="9"><content>note</content></comment>
<contact localId="2"><variable>A</variable><connectionPointIn><connection refLocalId="1"/></connectionPointIn></contact>
<connector localId="3" name="Wire"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></connector>
<contact localId="2"><variable>B</variable></contact>
<coil><variable>C</variable></coil>
<step localId="7"/>
<vendorElement localId="8"><alternativeText>x</alternativeText></vendorElement>
<continuation localId="4" name="wire"/>
</LD>"#;

#[test]
fn every_child_is_read_once_in_document_order() {
    let body = dom::parse(BODY).expect("the body parses");
    let g = Graph::read(&body);
    let reads: Vec<String> = g
        .items
        .iter()
        .map(|i| match &i.read {
            Read::Element(e) => format!("element {}", g.elements[*e].id),
            Read::Comment => "comment".into(),
            Read::Vendor(Vendor::Unknown(_)) => "vendor".into(),
            Read::Vendor(v) => format!("{v:?}"),
            Read::NoLocalId { known } => format!("no id {known}"),
            Read::Duplicate { id, first, known } => format!("dup {id} of {first} {known}"),
        })
        .collect();
    assert_eq!(
        reads,
        [
            "element 1",
            "comment",
            "element 2",
            "element 3",
            "dup 2 of 4 true",
            "no id true",
            "element 7",
            "vendor",
            "element 4",
        ]
    );
    // Each item keeps its node, each element its place and line.
    assert_eq!(g.items[5].node.name, "coil");
    let contact = &g.elements[g.by_id["2"]];
    assert_eq!((contact.line, contact.node.name.as_str()), (4, "contact"));
    assert_eq!(contact.inputs[0].1[0].from, "1");
    assert_eq!(g.elements[g.by_id["7"]].kind, Kind::Other("step".into()));
    // Connectors are found by name in any case.
    assert_eq!(g.elements[g.connectors["wire"]].id, "3");
}

#[test]
fn the_running_order_follows_the_wires_not_the_file() {
    let body = dom::parse(
        r#"<LD>
<leftPowerRail localId="1"/>
<coil localId="3"><position x="0" y="0"/><variable>C</variable><connectionPointIn><connection refLocalId="2"/></connectionPointIn></coil>
<contact localId="2"><position x="0" y="50"/><variable>A</variable><connectionPointIn><connection refLocalId="1"/></connectionPointIn></contact>
</LD>"#,
    )
    .expect("the body parses");
    let g = Graph::read(&body);
    let ids: Vec<&str> = super::order(&g)
        .into_iter()
        .map(|i| g.elements[i].id.as_str())
        .collect();
    assert_eq!(ids, ["2", "3"]);
}

/// The ids of `body`'s elements in their running order.
fn running(body: &str) -> Vec<String> {
    let body = dom::parse(body).expect("the body parses");
    let g = Graph::read(&body);
    super::order(&g)
        .into_iter()
        .map(|i| g.elements[i].id.clone())
        .collect()
}

/// An ADD block `id` at height `y` adding `1` (element 90) and `from`.
fn add(id: &str, y: i64, from: &str) -> String {
    format!(
        r#"<block localId="{id}" typeName="ADD"><position x="0" y="{y}"/><inputVariables><variable formalParameter="IN1"><connectionPointIn><connection refLocalId="90"/></connectionPointIn></variable><variable formalParameter="IN2"><connectionPointIn><connection refLocalId="{from}"/></connectionPointIn></variable></inputVariables><inOutVariables/><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>"#
    )
}

/// A variable element `id` (`inOutVariable`, `outVariable`) at height
/// `y` naming `name`, fed by `from`'s OUT.
fn variable(kind: &str, id: &str, y: i64, name: &str, from: &str) -> String {
    format!(
        r#"<{kind} localId="{id}"><position x="0" y="{y}"/><connectionPointIn><connection refLocalId="{from}" formalParameter="OUT"/></connectionPointIn><expression>{name}</expression></{kind}>"#
    )
}

const ONE: &str = r#"<inVariable localId="90"><expression>1</expression></inVariable>"#;

#[test]
fn a_loop_through_an_in_out_variable_breaks_at_its_readers() {
    // ADD 2 reads Cnt (3) and feeds ADD 4, which writes Cnt; output
    // variable 1, drawn above everything, reads Cnt too. Only ADD 2 is
    // in the loop with Cnt: it reads the last scan's Cnt, output 1 reads
    // it after ADD 4 wrote it.
    let body = format!(
        "<FBD>{ONE}{}{}{}{}</FBD>",
        variable("outVariable", "1", 0, "Out", "3"),
        add("4", 10, "2"),
        add("2", 20, "3"),
        variable("inOutVariable", "3", 30, "Cnt", "4"),
    );
    assert_eq!(running(&body), ["2", "4", "3", "1"]);
}

#[test]
fn a_loop_through_two_variables_breaks_once_at_the_first_drawn() {
    // X (1) feeds ADD 2, which feeds Y (3), which feeds ADD 4, which
    // feeds X: the loop breaks at X's reader (ADD 2, which reads X's
    // last value); ADD 4 then reads Y after it is written.
    let body = format!(
        "<FBD>{ONE}{}{}{}{}</FBD>",
        variable("inOutVariable", "1", 0, "X", "4"),
        add("2", 10, "1"),
        variable("inOutVariable", "3", 20, "Y", "2"),
        add("4", 30, "3"),
    );
    assert_eq!(running(&body), ["2", "3", "4", "1"]);
}

#[test]
fn a_loop_with_no_variable_breaks_at_its_first_element_as_drawn() {
    // ADD 4 and ADD 2 feed each other; ADD 4 is drawn first and reads
    // ADD 2's last output. Output variable 1 reads ADD 2.
    let body = format!(
        "<FBD>{ONE}{}{}{}</FBD>",
        variable("outVariable", "1", 50, "Out", "2"),
        add("4", 10, "2"),
        add("2", 20, "4"),
    );
    assert_eq!(running(&body), ["4", "2", "1"]);
}

#[test]
fn thousands_of_variables_in_one_loop_are_broken_in_bounded_work() {
    // A ring of ADDs, each also feeding an inOutVariable X it reads back:
    // one loop with 5000 variables in it, each breaking only its own
    // side of it. Broken one variable at a time this takes minutes; past
    // MAX_LOOP_WORK every variable breaks its loop at once. Each ADD then
    // reads its X's last value and runs before it; the ring itself (no
    // variable in it) breaks at its first ADD drawn.
    let m = 5000;
    let mut body = String::from("<FBD>");
    body.push_str(r#"<inVariable localId="one"><expression>1</expression></inVariable>"#);
    for i in 0..m {
        let (b, v) = (2 * i + 1, 2 * i + 2);
        let prev = if i == 0 { 2 * m - 1 } else { b - 2 };
        body.push_str(&format!(
            r#"<block localId="{b}" typeName="ADD"><position x="0" y="{b}"/><inputVariables><variable formalParameter="IN1"><connectionPointIn><connection refLocalId="{prev}" formalParameter="OUT"/></connectionPointIn></variable><variable formalParameter="IN2"><connectionPointIn><connection refLocalId="{v}"/></connectionPointIn></variable></inputVariables><inOutVariables/><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>"#
        ));
        body.push_str(&variable(
            "inOutVariable",
            &v.to_string(),
            v,
            "X",
            &b.to_string(),
        ));
    }
    body.push_str("</FBD>");
    let ids = running(&body);
    assert_eq!(ids.len(), 2 * m as usize);
    let place: std::collections::HashMap<&str, usize> = (ids.iter().enumerate())
        .map(|(i, id)| (id.as_str(), i))
        .collect();
    let at = |id: i64| place[id.to_string().as_str()];
    assert_eq!(ids[0], "1");
    for i in 0..m {
        let (b, v) = (at(2 * i + 1), at(2 * i + 2));
        assert!(b < v, "ADD {} after its variable", 2 * i + 1);
        if i > 0 {
            assert!(
                at(2 * i - 1) < b,
                "ADD {} before the one it feeds",
                2 * i + 1
            );
        }
    }
}
