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
