//! CODESYS's vendor elements (issue #44 item 4).

use super::*;

/// An LD program as CODESYS V3 exports it: every element at 0,0, each
/// network with its title as a `vendorElement`, then `extra`.
fn codesys(extra: &str) -> String {
    let at = r#"<position x="0" y="0"/>"#;
    let title = |id: u32, text: &str| {
        format!(
            r#"<vendorElement localId="{id}">{at}<alternativeText><xhtml xmlns="http://www.w3.org/1999/xhtml">{text}</xhtml></alternativeText><addData><data name="http://www.3s-software.com/plcopenxml/fbdelementtype" handleUnknown="implementation"><ElementType xmlns="">networktitle</ElementType></data></addData></vendorElement>
"#
        )
    };
    let contact = |id: u32, v: &str| {
        format!("<contact localId=\"{id}\">{at}<connectionPointIn><connection refLocalId=\"0\"/></connectionPointIn><connectionPointOut/><variable>{v}</variable></contact>\n")
    };
    let coil = |id: u32, from: u32, v: &str| {
        format!("<coil localId=\"{id}\">{at}<connectionPointIn><connection refLocalId=\"{from}\"/></connectionPointIn><connectionPointOut/><variable>{v}</variable></coil>\n")
    };
    let body = [
        format!("<leftPowerRail localId=\"0\">{at}<connectionPointOut formalParameter=\"none\"/></leftPowerRail>\n"),
        title(2, "Pump on"),
        contact(4, "start"),
        coil(5, 4, "pump"),
        title(8, "Lamp follows stop"),
        contact(10, "stop"),
        coil(11, 10, "lamp"),
        extra.to_string(),
        format!("<rightPowerRail localId=\"2147483647\">{at}<connectionPointIn/></rightPowerRail>\n"),
    ]
    .concat();
    let vars = [
        var("start", "BOOL", "%IX0.0"),
        var("stop", "BOOL", "%IX0.1"),
        var("pump", "BOOL", "%QX0.0"),
        var("lamp", "BOOL", "%QX0.1"),
    ]
    .concat();
    project(&vars, &body, "")
        .replace("<FBD>", "<LD>")
        .replace("</FBD>", "</LD>")
}

/// CODESYS's FBD implementation attributes, a vendor element of the body.
const ATTRIBUTES: &str = r#"<vendorElement localId="10000000000"><position x="0" y="0"/><alternativeText><xhtml xmlns="http://www.w3.org/1999/xhtml">FBD Implementation Attributes</xhtml></alternativeText><addData><data name="http://www.3s-software.com/plcopenxml/fbd/implementationattributes" handleUnknown="implementation"><fbdattributes xmlns=""><attribute name="BoxInputFlagsSupported" value="true"/></fbdattributes></data></addData></vendorElement>
"#;

/// Issue #44 item 4: CODESYS's network titles and implementation
/// attributes were refused on the soft PLC ("<vendorElement> does not
/// run"); they are cosmetic: the project runs.
#[test]
fn codesys_network_titles_and_attributes_run_on_the_soft_plc() {
    let xml = codesys(ATTRIBUTES);
    let mut plc = soft_plc(&xml);
    let start = plc.device("start").expect("start");
    plc.apply(engine::plc::Command::SetInput(
        start,
        engine::events::InputValue::Int(1),
    ))
    .expect("input");
    plc.run_until(SimTime::from_millis(50));
    assert_eq!(read(plc.as_ref(), "pump"), 1);
    assert_eq!(read(plc.as_ref(), "lamp"), 0);
}

/// Issue #44 item 4: drawn for a bit machine (and in the page), a network
/// title is its rung's comment, not a skipped element; the attributes
/// are nothing to say.
#[test]
fn a_codesys_network_title_is_its_rungs_comment() {
    let xml = codesys(ATTRIBUTES);
    let imported = engine::formats::plcopen::Document::read(&xml)
        .and_then(|document| document.import(Some(MachineId::Io86a), None, None))
        .unwrap_or_else(|e| panic!("{e:?}"));
    let comments: Vec<&str> = imported
        .ladder
        .rungs
        .iter()
        .map(|r| r.comment.as_str())
        .collect();
    assert_eq!(comments, ["Pump on", "Lamp follows stop"]);
    assert!(imported.warnings.is_empty(), "{:?}", imported.warnings);
}

/// Issue #44 item 4: a vendor element wired into the network, or holding
/// code, carries logic: still refused at its line, on every reader.
#[test]
fn a_vendor_element_carrying_logic_is_refused_at_its_line() {
    let wired = r#"<vendorElement localId="20"><position x="0" y="0"/><alternativeText>motor start</alternativeText><connectionPointIn><connection refLocalId="4"/></connectionPointIn><connectionPointOut/></vendorElement>
"#;
    let code = r#"<vendorElement localId="21"><position x="0" y="0"/><alternativeText>inline</alternativeText><addData><data name="http://www.3s-software.com/plcopenxml/stcode" handleUnknown="implementation"><STCode xmlns="">pump := TRUE;</STCode></data></addData></vendorElement>
"#;
    for (element, id) in [(wired, "20"), (code, "21")] {
        let xml = codesys(element);
        let at = line_of(&xml, &format!("<vendorElement localId=\"{id}\""));
        let said = soft_errors(&xml);
        assert_eq!(said.len(), 1, "{said:?}");
        assert!(
            said[0].starts_with(&format!("{at}: <vendorElement> ")),
            "{said:?}"
        );
        assert!(said[0].contains("carries logic"), "{said:?}");
        let errors = refused(
            engine::formats::plcopen::Document::read(&xml)
                .and_then(|document| document.import(Some(MachineId::Io86a), None, None)),
            "refused",
        );
        assert_eq!(errors[0].line, at, "{errors:?}");
        assert!(
            errors[0].error.to_string().contains("carries logic"),
            "{errors:?}"
        );
    }
}

/// Issue #44 item 4: with every element at 0,0, each of 40 networks keeps
/// its own title (past the 16 rungs a comment weighs by place).
#[test]
fn forty_codesys_network_titles_each_go_to_their_own_rung() {
    let at = r#"<position x="0" y="0"/>"#;
    let mut body = format!("<leftPowerRail localId=\"0\">{at}<connectionPointOut formalParameter=\"none\"/></leftPowerRail>\n");
    let mut vars = var("start", "BOOL", "%IX0.0");
    for k in 0..40u32 {
        let (title, contact, coil) = (100 + 3 * k, 101 + 3 * k, 102 + 3 * k);
        body.push_str(&format!(
            r#"<vendorElement localId="{title}">{at}<alternativeText><xhtml xmlns="http://www.w3.org/1999/xhtml">network {k}</xhtml></alternativeText><addData><data name="http://www.3s-software.com/plcopenxml/fbdelementtype" handleUnknown="implementation"><ElementType xmlns="">networktitle</ElementType></data></addData></vendorElement>
<contact localId="{contact}">{at}<connectionPointIn><connection refLocalId="0"/></connectionPointIn><connectionPointOut/><variable>start</variable></contact>
<coil localId="{coil}">{at}<connectionPointIn><connection refLocalId="{contact}"/></connectionPointIn><connectionPointOut/><variable>m{k}</variable></coil>
"#
        ));
        vars.push_str(&var(&format!("m{k}"), "BOOL", ""));
    }
    let xml = project(&vars, &body, "")
        .replace("<FBD>", "<LD>")
        .replace("</FBD>", "</LD>");
    let imported = engine::formats::plcopen::Document::read(&xml)
        .and_then(|document| document.import(Some(MachineId::SoftPlc), None, None))
        .unwrap_or_else(|e| panic!("{e:?}"));
    let comments: Vec<String> = imported
        .ladder
        .rungs
        .iter()
        .map(|r| r.comment.clone())
        .collect();
    let expected: Vec<String> = (0..40).map(|k| format!("network {k}")).collect();
    assert_eq!(comments, expected);
}
