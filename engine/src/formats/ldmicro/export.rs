//! A soft PLC ladder made of LDmicro's elements written back as an `.ld`
//! file in LDmicro 4.x's form (docs/ldmicro.md, "Writing it back"): each
//! rung's network as `SERIES` and `PARALLEL` groups, its outputs at its
//! end, each element as the line LDmicro writes for it. Read again, the
//! file gives the same ladder, element for element. An element LDmicro
//! has no form for is refused at its cell.

use std::collections::HashMap;
use std::fmt::Write as _;

use super::elements::OPEN;
use super::lower::MCR;
use crate::ladder::element::{CoilKind, ContactKind, Element};
use crate::ladder::grid::{Ladder, LadderError, Pos};
use crate::ladder::net::{Net, RungLogic};
use crate::ladder::BlockCall;

/// `ladder` as an `.ld` file whose scan is `cycle_us`; every element
/// without an LDmicro form is an error at its cell.
pub fn export(ladder: &Ladder, cycle_us: u64) -> Result<String, Vec<LadderError>> {
    let logic = ladder.logic(crate::machines::IEC_MACHINE)?;
    // A name the reader gave an LDmicro name that is no IEC name goes
    // back as it was; an address goes as the variable declared at it.
    let mut names: HashMap<String, String> = HashMap::new();
    for v in &ladder.variables {
        if let Some(original) = v.comment.strip_prefix("LDmicro name: ") {
            let original = original.split(';').next().unwrap_or(original).trim();
            names.insert(v.name.to_ascii_uppercase(), original.to_string());
        }
        if !v.address.is_empty() {
            names.insert(v.address.to_ascii_uppercase(), v.name.clone());
        }
    }
    let master = ladder.variables.iter().any(|v| v.name == MCR);
    let w = Writer { names, cycle_us };
    let mut body = String::new();
    let mut errors = Vec::new();
    let mut number = 0;
    for (i, rung) in logic.iter().enumerate() {
        let at = |pos: Pos, m: String| LadderError::at(i, pos, m);
        if !rung.sides.is_empty() {
            let why = "a block input wired as a network has no LDmicro form";
            errors.push(LadderError::rung(i, why));
            continue;
        }
        let (condition, relay) = match master {
            true => match through_master(rung) {
                Some(parts) => parts,
                // The scan's start turning the master relay on.
                None => continue,
            },
            false => (Some(rung.condition.clone()), false),
        };
        number += 1;
        let _ = writeln!(body, "RUNG {number}");
        if !rung.comment.is_empty() {
            let _ = writeln!(body, "    COMMENT {}", escape(&rung.comment));
        }
        let mut lines = Vec::new();
        if let Some(c) = &condition {
            if let Err((pos, m)) = w.series(c, 1, &mut lines) {
                errors.push(at(pos, m));
            }
        }
        let mut outs = Vec::new();
        for (e, pos) in &rung.outputs {
            match w.element(e) {
                Ok(_) if relay => outs.push("MASTER_RELAY".to_string()),
                Ok(line) => outs.push(line),
                Err(m) => errors.push(at(*pos, m)),
            }
        }
        side_by_side(outs, &mut lines);
        for l in lines {
            let _ = writeln!(body, "{l}");
        }
        body.push_str("END\n");
    }
    for v in ladder.variables.iter().filter(|v| v.retain) {
        let _ = writeln!(body, "RUNG\n    PERSIST {}\nEND", w.name(&v.name));
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    let mut out = header(ladder, &w);
    out.push_str(&body);
    Ok(out)
}

/// A rung's outputs at its end: one, or side by side in a `PARALLEL`.
fn side_by_side(outs: Vec<String>, lines: &mut Vec<String>) {
    if let [one] = outs.as_slice() {
        lines.push(format!("    {one}"));
        return;
    }
    lines.push("    PARALLEL".into());
    lines.extend(outs.iter().map(|o| format!("        {o}")));
    lines.push("    END".into());
}

/// The file's first lines: the version, the cycle, the `VAR LIST` of
/// the variables not of LDmicro's default two bytes, the `IO LIST` of
/// the ladder's inputs and outputs with their pins, up to `PROGRAM`.
fn header(ladder: &Ladder, w: &Writer) -> String {
    let mut out = format!(
        "LDmicro0.2\nCYCLE={} us at Timer1, YPlcCycleDuty:0, ConfigurationWord(s):0x0\n\n",
        w.cycle_us
    );
    let sizes = sizes(ladder);
    if !sizes.is_empty() {
        out.push_str("VAR LIST\n");
        for (name, bytes) in &sizes {
            let _ = writeln!(out, "    {bytes} bytes {}", w.name(name));
        }
        out.push_str("END\n\n");
    }
    out.push_str("IO LIST\n");
    let io = ladder
        .variables
        .iter()
        .filter(|v| v.name.starts_with(['X', 'Y']));
    for v in io {
        let pin = v.comment.strip_prefix("LDmicro pin: ").unwrap_or("at 0");
        let _ = writeln!(out, "    {} {pin}", w.name(&v.name));
    }
    out.push_str("END\n\nPROGRAM\n");
    out
}

/// The variables' sizes in bytes where they are not LDmicro's default
/// two, as the ladder's boxes give them: an `LD_` word operation's width
/// `W` for its destination, 4 for what a soft PLC function box (a DINT)
/// writes; the first box naming a variable decides, in rung order.
fn sizes(ladder: &Ladder) -> Vec<(String, u32)> {
    let mut sizes: Vec<(String, u32)> = Vec::new();
    let boxes = ladder.rungs.iter().flat_map(|r| {
        r.elements()
            .filter_map(|(_, e)| match e {
                Element::Block(b) | Element::OutputBlock(b) => Some(b.clone()),
                _ => None,
            })
            .collect::<Vec<_>>()
    });
    for b in boxes {
        let found = match (b.input("W"), b.input("D")) {
            (Some(w), Some(d)) => w
                .parse::<u32>()
                .ok()
                .map(|w| (d.to_string(), (w / 8).max(1))),
            _ if b.instance.is_empty() && !b.outputs.is_empty() => {
                b.outputs.first().map(|(_, v)| (v.trim().to_string(), 4))
            }
            _ => None,
        };
        if let Some((name, bytes)) = found {
            if !name.starts_with('%') && !sizes.iter().any(|(n, _)| *n == name) {
                sizes.push((name, bytes));
            }
        }
    }
    sizes.retain(|(_, bytes)| *bytes != 2);
    sizes
}

/// A rung of a ladder with LDmicro's master relay, as LDmicro has it:
/// its condition without the relay's contact every rung starts with, and
/// whether it is a `MASTER_RELAY` rung (`_MCR := NOT _MCR OR power`);
/// `None` for the rung turning the relay on at each scan's start.
fn through_master(rung: &RungLogic) -> Option<(Option<Net>, bool)> {
    let relay = |n: &Net, kind: ContactKind| matches!(n, Net::Leaf(Element::Contact { kind: k, device }, _) if *k == kind && device == MCR);
    let on_relay = matches!(
        rung.outputs.as_slice(),
        [(Element::Coil { kind: CoilKind::Normal, device }, _)] if device == MCR
    );
    let mut condition = rung.condition.clone();
    if on_relay {
        if matches!(&condition, Net::Leaf(Element::Contact { device, .. }, _) if device == OPEN) {
            return None;
        }
        if let Net::Parallel(branches) = &condition {
            if branches.len() == 2 && relay(&branches[0], ContactKind::Nc) {
                condition = branches[1].clone();
            }
        }
    }
    let rest = match condition {
        ref n if relay(n, ContactKind::No) => None,
        Net::Series(mut items) if items.first().is_some_and(|n| relay(n, ContactKind::No)) => {
            items.remove(0);
            match items.len() {
                1 => items.pop(),
                _ => Some(Net::Series(items)),
            }
        }
        other => Some(other),
    };
    Some((rest, on_relay))
}

/// What writing needs: the names to write back, the scan.
struct Writer {
    names: HashMap<String, String>,
    cycle_us: u64,
}

impl Writer {
    /// The name LDmicro knows `n` by.
    fn name(&self, n: &str) -> String {
        self.names
            .get(&n.trim().to_ascii_uppercase())
            .cloned()
            .unwrap_or_else(|| n.trim().to_string())
    }

    /// A network in series, each item a line (indented by `depth`).
    fn series(&self, net: &Net, depth: usize, out: &mut Vec<String>) -> Result<(), (Pos, String)> {
        let pad = "    ".repeat(depth);
        match net {
            Net::Leaf(e, pos) => {
                out.push(format!("{pad}{}", self.element(e).map_err(|m| (*pos, m))?))
            }
            Net::Series(items) => {
                for item in items {
                    self.series(item, depth, out)?;
                }
            }
            Net::Parallel(branches) => {
                out.push(format!("{pad}PARALLEL"));
                for b in branches {
                    match b {
                        Net::Series(_) => {
                            out.push(format!("{pad}    SERIES"));
                            self.series(b, depth + 2, out)?;
                            out.push(format!("{pad}    END"));
                        }
                        other => self.series(other, depth + 1, out)?,
                    }
                }
                out.push(format!("{pad}END"));
            }
        }
        Ok(())
    }

    /// One element's line.
    fn element(&self, e: &Element) -> Result<String, String> {
        let n = |s: &str| self.name(s);
        Ok(match e {
            Element::Wire => "SHORT".into(),
            Element::Contact { kind, device } if device == OPEN => match kind {
                ContactKind::Nc => "SHORT".into(),
                _ => "OPEN".into(),
            },
            Element::Contact { kind, device } => {
                let negated = match kind {
                    ContactKind::No => 0,
                    ContactKind::Nc => 1,
                    _ => {
                        return Err(format!(
                            "{e} has no LDmicro form: put an OSR or OSF after a contact"
                        ))
                    }
                };
                format!("CONTACTS {} {negated} 0", n(device))
            }
            Element::Coil { kind, device } => {
                let flags = match kind {
                    CoilKind::Normal => "0 0 0 0",
                    CoilKind::Inverted => "1 0 0 0",
                    CoilKind::Set => "0 1 0 0",
                    CoilKind::Reset => "0 0 1 0",
                };
                format!("COIL {} {flags}", n(device))
            }
            Element::Edge { falling } => if *falling { "OSF" } else { "OSR" }.into(),
            Element::Block(b) | Element::OutputBlock(b) => self.block(b)?,
            other => return Err(format!("{other} has no LDmicro form")),
        })
    }

    /// A box's line: LDmicro's blocks, the functions and comparisons its
    /// elements became.
    fn block(&self, b: &BlockCall) -> Result<String, String> {
        let kind = b.kind();
        let input = |pin: &str| b.input(pin).map(|o| self.name(o)).unwrap_or_default();
        let output = |pin: &str| {
            b.outputs
                .iter()
                .find(|(p, _)| p.eq_ignore_ascii_case(pin))
                .map(|(_, v)| self.name(v))
                .unwrap_or_default()
        };
        let none = || format!("{kind} has no LDmicro form");
        if let Some(name) = kind.strip_prefix("LD_") {
            return self.ld_block(b, name).ok_or_else(none);
        }
        let two = |word: &str, a: &str, b2: &str| {
            format!("{word} {} {} {}", output("OUT"), input(a), input(b2))
        };
        Ok(match kind.as_str() {
            "MOVE" => format!("MOVE {} {}", output("OUT"), input("IN")),
            "NOT" | "NEG" => format!("{kind} {} {}", output("OUT"), input("IN")),
            "ADD" | "SUB" | "MUL" | "DIV" | "MOD" | "AND" | "OR" | "XOR" => {
                two(&kind, "IN1", "IN2")
            }
            "SHL" | "SHR" | "ROL" | "ROR" => two(&kind, "IN", "N"),
            "INT_TO_DINT" if input("IN").starts_with("%IW") => {
                format!("READ_ADC {}", output("OUT"))
            }
            "DINT_TO_INT" if output("OUT").starts_with("%QW") => {
                format!("SET_PWM {} 1000", input("IN"))
            }
            "EQ" | "NE" | "GT" | "GE" | "LT" | "LE" => {
                let word = match kind.as_str() {
                    "EQ" => "EQU",
                    "NE" => "NEQ",
                    "GT" => "GRT",
                    "GE" => "GEQ",
                    "LT" => "LES",
                    _ => "LEQ",
                };
                format!("{word} {} {}", input("IN1"), input("IN2"))
            }
            _ => return Err(none()),
        })
    }
    /// The line of LDmicro's own block `LD_<name>`, if LDmicro has one.
    fn ld_block(&self, b: &BlockCall, name: &str) -> Option<String> {
        let input = |pin: &str| b.input(pin).map(|o| self.name(o)).unwrap_or_default();
        Some(match name {
            "TON" | "TOF" | "RTO" | "RTL" | "TCY" | "THI" | "TLO" => {
                let p = input("P");
                let delay = p
                    .parse::<u64>()
                    .map_or(p.clone(), |cycles| (cycles * self.cycle_us).to_string());
                format!("{name} {} {delay} 0", input("T"))
            }
            "CTU" | "CTD" | "CTC" | "CTR" => {
                let edge = match input("EDGE").as_str() {
                    "1" => '\\',
                    "2" => '-',
                    "3" => 'o',
                    _ => '/',
                };
                format!(
                    "{name} {} {} {} {edge}",
                    input("C"),
                    input("MAX"),
                    input("INIT")
                )
            }
            "OSL" | "OSC" => name.to_string(),
            "TOGGLE" => format!("COIL {} 0 0 0 1", input("V")),
            "BIN2BCD" | "BCD2BIN" | "SWAP" | "OPPOSITE" => {
                format!("{name} {} {}", input("D"), input("A"))
            }
            "SR0" | "ADD" | "SUB" | "MUL" | "DIV" | "MOD" | "AND" | "OR" | "XOR" | "SHL"
            | "SHR" | "ROL" | "ROR" => {
                format!("{name} {} {} {}", input("D"), input("A"), input("B"))
            }
            "MOVE" | "NOT" | "NEG" => format!("{name} {} {}", input("D"), input("A")),
            "SEG7" | "SEG9" | "SEG14" | "SEG16" => {
                let common = if input("B") == "0" { 'C' } else { 'A' };
                let n = &name[3..];
                format!("{n}SEGMENTS {} {} {common}", input("D"), input("A"))
            }
            "SETBIT" => format!("SET_BIT {} {}", input("D"), input("B")),
            "CLRBIT" => format!("CLEAR_BIT {} {}", input("D"), input("B")),
            "IFBIT" => format!("IF_BIT_SET {} {}", input("A"), input("B")),
            "IFNBIT" => format!("IF_BIT_CLEAR {} {}", input("A"), input("B")),
            "UART_SEND" | "UART_RECV" => {
                let n = input("N").parse::<u32>().unwrap_or(1).max(1);
                format!("{name} {} {n} 0", input("V"))
            }
            "UART_AVAIL" => "UART_RECV_AVAIL".into(),
            "UART_READY" => "UART_SEND_READY".into(),
            "FMTSTR" => formatted_string(b, "FORMATTED_STRING", &input("V"))?,
            "STRING" => formatted_string(b, &format!("STRING {}", input("D")), &input("V"))?,
            _ => return None,
        })
    }
}

/// A formatted string (or a STRING, `head` naming its destination) as
/// LDmicro saves it: its variable (or `(none)`), then its length and
/// character codes.
fn formatted_string(b: &BlockCall, head: &str, var: &str) -> Option<String> {
    let text = crate::iec::literal::parse_text(b.input("FMT")?).ok()?;
    let var = if var.is_empty() { "(none)" } else { var };
    let codes: Vec<String> = text.chars().map(|c| u32::from(c).to_string()).collect();
    let line = format!("{head} {var} {} {}", codes.len(), codes.join(" "));
    Some(line.trim_end().to_string())
}

/// A comment as LDmicro saves it: line ends and backslashes escaped.
fn escape(text: &str) -> String {
    text.replace('\\', "\\\\")
        .replace('\r', "\\r")
        .replace('\n', "\\n")
}
