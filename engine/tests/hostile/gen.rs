//! Generators for large and deep inputs.

use std::fmt::Write as _;

/// A project for `machine` whose rungs are given as JSON text.
pub fn project(machine: &str, rungs: &[String]) -> String {
    format!(
        r#"{{"format":"hashigo-project","version":1,"machine":"{machine}","ladder":{{"rungs":[{}]}}}}"#,
        rungs.join(",")
    )
}

/// A contact's JSON.
pub fn contact(device: &str) -> String {
    format!(r#"{{"type":"contact","kind":"no","device":"{device}"}}"#)
}

/// A normal coil's JSON.
pub fn coil(device: &str) -> String {
    format!(r#"{{"type":"coil","kind":"normal","device":"{device}"}}"#)
}

/// One rung: rows of cell JSON and links.
pub fn rung(rows: &[Vec<String>], links: &str) -> String {
    let rows: Vec<String> = rows.iter().map(|r| format!("[{}]", r.join(","))).collect();
    format!(r#"{{"cells":[{}],"links":[{links}]}}"#, rows.join(","))
}

/// A rung of `n` contacts on `input` in series driving `output`.
pub fn series_rung(n: usize, input: &str, output: &str) -> String {
    let mut row = vec![contact(input); n];
    row.push(coil(output));
    rung(&[row], "")
}

const HEAD: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
<types><pous><pou name="main" pouType="program"><body><LD>
<leftPowerRail localId="1"><connectionPointOut formalParameter=""/></leftPowerRail>
"#;
const TAIL: &str = "</LD></body></pou></pous></types></project>\n";

fn conn(refs: &[usize]) -> String {
    let mut s = String::from("<connectionPointIn>");
    for r in refs {
        let _ = write!(s, r#"<connection refLocalId="{r}"/>"#);
    }
    s + "</connectionPointIn>"
}

/// A PLCopen LD body of `n` contact→coil rungs on one rail.
pub fn plcopen_rungs(n: usize, input: &str, output: &str) -> String {
    let mut s = String::from(HEAD);
    for i in 0..n {
        let (c, k) = (10 + 2 * i, 11 + 2 * i);
        let _ = writeln!(
            s,
            r#"<contact localId="{c}"><position x="10" y="{}"/>{}<variable>{input}</variable></contact>"#,
            i * 10,
            conn(&[1])
        );
        let _ = writeln!(
            s,
            r#"<coil localId="{k}"><position x="50" y="{}"/>{}<variable>{output}</variable></coil>"#,
            i * 10,
            conn(&[c])
        );
    }
    s + TAIL
}

/// A PLCopen network `levels` deep: a contact in series, then one in
/// parallel with everything so far, and so on.
pub fn plcopen_alternating(levels: usize) -> String {
    let mut s = String::from(HEAD);
    let mut current = vec![1];
    let mut id = 2;
    for level in 0..levels {
        if level % 2 == 0 {
            let _ = writeln!(
                s,
                r#"<contact localId="{id}">{}<variable>X00</variable></contact>"#,
                conn(&current)
            );
            current = vec![id];
        } else {
            let _ = writeln!(
                s,
                r#"<contact localId="{id}">{}<variable>X01</variable></contact>"#,
                conn(&[1])
            );
            current.push(id);
        }
        id += 1;
    }
    let _ = writeln!(
        s,
        r#"<coil localId="{id}">{}<variable>Y00</variable></coil>"#,
        conn(&current)
    );
    s + TAIL
}

/// A PLCopen file of `rails` left rails and one contact→coil rung.
pub fn plcopen_rails(rails: usize) -> String {
    let mut s = String::from(HEAD);
    for i in 0..rails {
        let _ = writeln!(s, r#"<leftPowerRail localId="{}"/>"#, 100 + i);
    }
    let _ = writeln!(
        s,
        r#"<contact localId="2">{}<variable>X00</variable></contact><coil localId="3">{}<variable>Y00</variable></coil>"#,
        conn(&[100 + rails - 1]),
        conn(&[2])
    );
    s + TAIL
}

/// A PLCopen LD body of `n` rungs, rung `i` written by `rung` from four
/// local ids of its own and its row.
fn plcopen_block_rungs(n: usize, rung: impl Fn([usize; 4], usize) -> String) -> String {
    let mut s = String::from(HEAD);
    for i in 0..n {
        let ids = [10 + 4 * i, 11 + 4 * i, 12 + 4 * i, 13 + 4 * i];
        let _ = writeln!(s, "{}", rung(ids, i * 10));
    }
    s + TAIL
}

/// Contact `id` of X00 on the left rail, at row `y`.
fn rail_contact(id: usize, y: usize) -> String {
    format!(
        r#"<contact localId="{id}"><position x="10" y="{y}"/>{}<variable>X00</variable></contact>"#,
        conn(&[1])
    )
}

/// Coil `id` of Y00 at row `y`, fed by pin `pin` of block `from`.
fn coil_after(id: usize, y: usize, from: usize, pin: &str) -> String {
    format!(
        r#"<coil localId="{id}"><position x="50" y="{y}"/><connectionPointIn><connection refLocalId="{from}" formalParameter="{pin}"/></connectionPointIn><variable>Y00</variable></coil>"#
    )
}

/// A PLCopen LD body of `n` blocks of `ty` (`OR`, `AND`), each of two
/// contacts, each to a coil.
pub fn plcopen_gates(n: usize, ty: &str) -> String {
    plcopen_block_rungs(n, |[a, b, g, k], y| {
        format!(
            r#"{}
{}
<block localId="{g}" typeName="{ty}"><position x="30" y="{y}"/><inputVariables><variable formalParameter="IN1">{}</variable><variable formalParameter="IN2">{}</variable></inputVariables><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>
{}"#,
            rail_contact(a, y),
            rail_contact(b, y),
            conn(&[a]),
            conn(&[b]),
            coil_after(k, y, g, "OUT")
        )
    })
}

/// `n` rungs, each X00 through two NOT blocks into Y00.
pub fn plcopen_double_nots(n: usize) -> String {
    plcopen_block_rungs(n, |[c, g, h, k], y| {
        let not = |id: usize, from: usize, pin: &str| {
            format!(
                r#"<block localId="{id}" typeName="NOT"><position x="30" y="{y}"/><inputVariables><variable formalParameter="IN"><connectionPointIn><connection refLocalId="{from}"{pin}/></connectionPointIn></variable></inputVariables><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>"#
            )
        };
        format!(
            "{}\n{}\n{}\n{}",
            rail_contact(c, y),
            not(g, c, ""),
            not(h, g, r#" formalParameter="OUT""#),
            coil_after(k, y, h, "OUT")
        )
    })
}

/// `n` rungs, each X00 into an in-line TON named T00 (PT 1 s) whose Q
/// lights Y00: on IO86A every one is split into `OUT T00` and a contact
/// of T00, all of them ordered writers before readers.
pub fn plcopen_timers(n: usize) -> String {
    plcopen_block_rungs(n, |[c, t, p, k], y| {
        format!(
            r#"{}
<inVariable localId="{p}"><position x="20" y="{y}"/><connectionPointOut/><expression>T#1s</expression></inVariable>
<block localId="{t}" typeName="TON" instanceName="T00"><position x="30" y="{y}"/><inputVariables><variable formalParameter="IN">{}</variable><variable formalParameter="PT">{}</variable></inputVariables><outputVariables><variable formalParameter="Q"><connectionPointOut/></variable></outputVariables></block>
{}"#,
            rail_contact(c, y),
            conn(&[c]),
            conn(&[p]),
            coil_after(k, y, t, "Q")
        )
    })
}

/// `n` rungs, each X00 counting into a CTU of its own (`c<i>`, PV 3)
/// whose Q lights Y00, its R fed by a contact of X01: on the soft PLC,
/// each reset a network under its box.
pub fn plcopen_counters(n: usize) -> String {
    plcopen_block_rungs(n, |[c, t, r, k], y| {
        format!(
            r#"{}
<contact localId="{r}"><position x="10" y="{}"/>{}<variable>X01</variable></contact>
<inVariable localId="{}"><position x="20" y="{y}"/><connectionPointOut/><expression>3</expression></inVariable>
<block localId="{t}" typeName="CTU" instanceName="c{t}"><position x="30" y="{y}"/><inputVariables><variable formalParameter="CU">{}</variable><variable formalParameter="R">{}</variable><variable formalParameter="PV">{}</variable></inputVariables><outputVariables><variable formalParameter="Q"><connectionPointOut/></variable></outputVariables></block>
{}"#,
            rail_contact(c, y),
            y + 5,
            conn(&[1]),
            t + 100_000,
            conn(&[c]),
            conn(&[r]),
            conn(&[t + 100_000]),
            coil_after(k, y, t, "Q")
        )
    })
}

/// A chain of `n` MUL boxes with open EN, each taking the one before's
/// OUT (the first a variable) times 1, the last into variable `out`.
pub fn plcopen_box_chain(n: usize) -> String {
    let mut s = String::from(HEAD);
    let _ = writeln!(
        s,
        r#"<inVariable localId="2"><position x="0" y="0"/><connectionPointOut/><expression>level</expression></inVariable><inVariable localId="3"><position x="0" y="0"/><connectionPointOut/><expression>INT#1</expression></inVariable>"#
    );
    for i in 0..n {
        let id = 10 + i;
        let from = if i == 0 {
            r#"<connection refLocalId="2"/>"#.to_string()
        } else {
            format!(
                r#"<connection refLocalId="{}" formalParameter="OUT"/>"#,
                id - 1
            )
        };
        let _ = writeln!(
            s,
            r#"<block localId="{id}" typeName="MUL"><position x="{}" y="0"/><inputVariables><variable formalParameter="IN1"><connectionPointIn>{from}</connectionPointIn></variable><variable formalParameter="IN2"><connectionPointIn><connection refLocalId="3"/></connectionPointIn></variable></inputVariables><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>"#,
            10 * i
        );
    }
    let _ = writeln!(
        s,
        r#"<outVariable localId="5"><position x="0" y="0"/><connectionPointIn><connection refLocalId="{}" formalParameter="OUT"/></connectionPointIn><expression>out</expression></outVariable>"#,
        9 + n
    );
    s + TAIL
}
