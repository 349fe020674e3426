//! Issue #43, round 3: files — PLCopen projects, the XML reader and `why`
//! (issue #44's CODESYS vendor elements too).

use engine::formats::plcopen::Document;
use engine::machines::new_plc;
use engine::plc::Plc;
use engine::{MachineId, SimTime};

mod plcopen;
mod vendor;
mod why;
mod xml;

/// The error of `result`, which must be one (the value is not printed:
/// it may be a tree of 200 000 attributes).
fn refused<T, E>(result: Result<T, E>, what: &str) -> E {
    match result {
        Ok(_) => panic!("{what}: accepted"),
        Err(e) => e,
    }
}

/// A project of one FBD program `main` (the task runs it) with these
/// local variables and elements, and any other POUs before it.
fn project(vars: &str, body: &str, pous: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
<types>
<pous>
{pous}<pou name="main" pouType="program">
<interface>
<localVars>
{vars}</localVars>
</interface>
<body>
<FBD>
{body}</FBD>
</body>
</pou>
</pous>
</types>
<instances><configurations><configuration name="config"><resource name="cpu">
<task name="cyclic" interval="T#10ms" priority="0"><pouInstance name="main0" typeName="main"/></task>
</resource></configuration></configurations></instances>
</project>
"#
    )
}

/// A variable declaration.
fn var(name: &str, ty: &str, address: &str) -> String {
    let at = if address.is_empty() {
        String::new()
    } else {
        format!(" address=\"{address}\"")
    };
    let ty = if ty.chars().all(|c| c.is_ascii_uppercase()) && !ty.contains("_TRIG") && ty.len() < 6
    {
        format!("<{ty}/>")
    } else {
        format!("<derived name=\"{ty}\"/>")
    };
    format!("<variable name=\"{name}\"{at}><type>{ty}</type></variable>\n")
}

/// An element's line of text: an input variable box.
fn input(id: u32, expression: &str) -> String {
    format!("<inVariable localId=\"{id}\"><position x=\"0\" y=\"{id}0\"/><connectionPointOut/><expression>{expression}</expression></inVariable>\n")
}

/// An output variable box fed by `from` (its pin `pin`, if any).
fn output(id: u32, from: u32, pin: &str, expression: &str) -> String {
    format!("<outVariable localId=\"{id}\"><position x=\"400\" y=\"{id}0\"/><connectionPointIn>{}</connectionPointIn><expression>{expression}</expression></outVariable>\n", connection(from, pin))
}

fn connection(from: u32, pin: &str) -> String {
    if pin.is_empty() {
        format!("<connection refLocalId=\"{from}\"/>")
    } else {
        format!("<connection refLocalId=\"{from}\" formalParameter=\"{pin}\"/>")
    }
}

/// A block: its inputs (pin, source element, source pin) and outputs.
fn block(
    id: u32,
    ty: &str,
    instance: &str,
    inputs: &[(&str, u32, &str)],
    outputs: &[&str],
) -> String {
    let instance = if instance.is_empty() {
        String::new()
    } else {
        format!(" instanceName=\"{instance}\"")
    };
    let ins: String = inputs
        .iter()
        .map(|(pin, from, fp)| {
            format!(
                "<variable formalParameter=\"{pin}\"><connectionPointIn>{}</connectionPointIn></variable>",
                connection(*from, fp)
            )
        })
        .collect();
    let outs: String = outputs
        .iter()
        .map(|pin| format!("<variable formalParameter=\"{pin}\"><connectionPointOut/></variable>"))
        .collect();
    format!("<block localId=\"{id}\" typeName=\"{ty}\"{instance}><position x=\"200\" y=\"{id}0\"/><inputVariables>{ins}</inputVariables><inOutVariables/><outputVariables>{outs}</outputVariables></block>\n")
}

/// The 1-based line of the first line holding `needle`.
fn line_of(xml: &str, needle: &str) -> usize {
    xml.lines()
        .position(|l| l.contains(needle))
        .map(|i| i + 1)
        .unwrap_or_else(|| panic!("{needle} not in the file"))
}

/// The soft PLC's errors for `xml`, each as `LINE: message`.
fn soft_errors(xml: &str) -> Vec<String> {
    match Document::read(xml).and_then(|document| document.soft_program(None)) {
        Ok(p) => panic!("runs:\n{}", p.text),
        Err(errors) => errors
            .iter()
            .map(|e| format!("{}: {}", e.line, e.error))
            .collect(),
    }
}

/// A function block of the project's own, drawn in LD: `Latch` (set,
/// reset → q).
const LATCH: &str = r#"<pou name="Latch" pouType="functionBlock">
<interface>
<inputVars><variable name="set"><type><BOOL/></type></variable><variable name="reset"><type><BOOL/></type></variable></inputVars>
<outputVars><variable name="q"><type><BOOL/></type></variable></outputVars>
</interface>
<body>
<LD>
<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut/></leftPowerRail>
<contact localId="2"><position x="40" y="20"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>set</variable></contact>
<contact localId="3"><position x="40" y="60"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>q</variable></contact>
<contact localId="4" negated="true"><position x="120" y="20"/><connectionPointIn><connection refLocalId="2"/><connection refLocalId="3"/></connectionPointIn><connectionPointOut/><variable>reset</variable></contact>
<coil localId="5"><position x="200" y="20"/><connectionPointIn><connection refLocalId="4"/></connectionPointIn><connectionPointOut/><variable>q</variable></coil>
</LD>
</body>
</pou>
"#;

/// Runs `xml` on a new soft PLC.
fn soft_plc(xml: &str) -> Box<dyn Plc> {
    let program = Document::read(xml)
        .and_then(|document| document.soft_program(None))
        .unwrap_or_else(|e| panic!("{e:?}"));
    let mut plc = new_plc(MachineId::SoftPlc);
    plc.load_text(&program.text).expect("loads");
    plc
}

fn read(plc: &dyn Plc, device: &str) -> i64 {
    plc.read(plc.device(device).expect(device)).as_i64()
}
