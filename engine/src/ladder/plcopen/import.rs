//! PLCopen LD bodies to rungs. Every element becomes an edge between
//! electrical points (a connection list joins the points it names); each
//! group of coils fed from one point becomes a rung whose condition is the
//! series-parallel network between the left rail and that point.

use std::collections::{BTreeMap, HashMap};

use super::dom::{self, Node};
use super::{parse_time_literal, NS_V10, NS_V201};
use crate::error::Located;
use crate::io86a::{isa::parse_bit, Bit};
use crate::ladder::element::{CoilKind, ContactKind, Element, TimerKind};
use crate::ladder::grid::{Ladder, Pos};
use crate::ladder::net::{layout, network, Net, RungLogic};
use crate::ladder::target::check_element;
use crate::MachineId;

type Errors = Vec<Located<String>>;

/// Reads the LD bodies of a PLCopen TC6 project (v2.01 or v1.0) into a
/// ladder. Variables name the machine's devices (`X00`); the compiler
/// checks them. Anything Hashigo cannot represent is an error at its line,
/// never dropped.
pub fn import(text: &str) -> Result<Ladder, Errors> {
    import_for(text, None)
}

/// [`import`], also checking every element and device against `machine`
/// so that an unknown device is reported at its line of the XML.
pub fn import_for(text: &str, machine: Option<MachineId>) -> Result<Ladder, Errors> {
    let root = dom::parse(text).map_err(|e| vec![e])?;
    if root.name != "project" {
        return Err(vec![Located::new(
            root.line,
            format!("not a PLCopen project: the root element is <{}>", root.name),
        )]);
    }
    match root.attr("xmlns") {
        None | Some(NS_V201) | Some(NS_V10) => {}
        Some(other) => {
            return Err(vec![Located::new(
                root.line,
                format!("namespace \"{other}\" is not PLCopen TC6 ({NS_V201} or {NS_V10})"),
            )])
        }
    }
    let mut pous = Vec::new();
    root.descendants("pou", &mut pous);
    let bodies: Vec<&Node> = pous
        .iter()
        .filter_map(|p| p.child("body")?.child("LD"))
        .collect();
    if bodies.is_empty() {
        return Err(vec![Located::new(
            root.line,
            "the project has no POU with an LD body".to_string(),
        )]);
    }
    let mut ladder = Ladder::default();
    let mut errors = Vec::new();
    for ld in bodies {
        match Body::read(ld).and_then(|b| b.rungs(machine)) {
            Ok(rungs) => ladder.rungs.extend(rungs.iter().map(layout)),
            Err(e) => errors.extend(e),
        }
    }
    if errors.is_empty() {
        Ok(ladder)
    } else {
        Err(errors)
    }
}

/// One LD body as a graph of points.
#[derive(Default)]
struct Body {
    parent: Vec<usize>,
    points: HashMap<(String, String), usize>,
    rails: Vec<String>,
    kinds: HashMap<String, String>,
    literals: HashMap<String, (String, usize)>,
    /// Contacts and in-line blocks: (in point, out point, leaf, line).
    edges: Vec<(usize, usize, Net, usize)>,
    /// Outputs: (in point, element, place, line).
    outputs: Vec<(usize, Element, Pos, usize)>,
    /// Points some element takes power from (not the right rail).
    consumed: Vec<usize>,
    comments: Vec<(usize, String)>,
    errors: Errors,
}

const RAIL: usize = 0;

impl Body {
    fn read(ld: &Node) -> Result<Body, Errors> {
        let mut b = Body {
            parent: vec![RAIL],
            ..Body::default()
        };
        for n in &ld.children {
            if n.name == "comment" {
                let y = position(n).0;
                b.comments.push((y, n.deep_text()));
                continue;
            }
            let Some(id) = n.attr("localId") else {
                b.errors
                    .push(Located::new(n.line, format!("<{}> has no localId", n.name)));
                continue;
            };
            b.kinds.insert(id.to_string(), n.name.clone());
            match n.name.as_str() {
                "leftPowerRail" => b.rails.push(id.to_string()),
                "inVariable" => {
                    let expr = n
                        .child("expression")
                        .map(|e| e.text.clone())
                        .unwrap_or_default();
                    b.literals.insert(id.to_string(), (expr, n.line));
                }
                _ => {}
            }
        }
        for (seq, n) in ld.children.iter().enumerate() {
            if let Err(m) = b.element(n, seq) {
                b.errors.push(Located::new(n.line, m));
            }
        }
        if b.errors.is_empty() {
            Ok(b)
        } else {
            Err(b.errors)
        }
    }

    fn point(&mut self, id: &str, pin: &str) -> usize {
        if self.rails.iter().any(|r| r == id) {
            return RAIL;
        }
        let key = (id.to_string(), pin.to_string());
        if let Some(&p) = self.points.get(&key) {
            return p;
        }
        let p = self.parent.len();
        self.parent.push(p);
        self.points.insert(key, p);
        p
    }

    fn find(&mut self, mut x: usize) -> usize {
        while self.parent[x] != x {
            self.parent[x] = self.parent[self.parent[x]];
            x = self.parent[x];
        }
        x
    }

    fn union(&mut self, a: usize, b: usize) {
        let (a, b) = (self.find(a), self.find(b));
        if a < b {
            self.parent[b] = a;
        } else {
            self.parent[a] = b;
        }
    }

    /// The point a `connectionPointIn` joins, or an error when it joins none.
    fn join(&mut self, cpi: Option<&Node>, what: &str) -> Result<usize, String> {
        let conns: Vec<&Node> = cpi
            .map(|c| c.all("connection").collect())
            .unwrap_or_default();
        let mut joined = None;
        for c in conns {
            let Some(r) = c.attr("refLocalId") else {
                return Err(format!("a connection of the {what} has no refLocalId"));
            };
            let kind = self.kinds.get(r).cloned();
            let pin = match kind.as_deref() {
                None => return Err(format!("the {what} connects to localId {r}, which does not exist")),
                Some("block") => c.attr("formalParameter").unwrap_or("Q").to_string(),
                Some("inVariable") => {
                    return Err(format!("the {what} takes power from a variable box (localId {r}): wire it from the rail through a contact"))
                }
                Some(_) => String::new(),
            };
            let p = self.point(r, &pin);
            match joined {
                None => joined = Some(p),
                Some(j) => self.union(j, p),
            }
        }
        joined.ok_or_else(|| format!("the {what} is not connected on its left"))
    }

    fn element(&mut self, n: &Node, seq: usize) -> Result<(), String> {
        let id = n.attr("localId").unwrap_or_default().to_string();
        let (y, x) = position(n);
        let pos = Pos::new(y, x * 65_536 + seq);
        let variable = || n.child("variable").map(|v| v.text.trim().to_string());
        match n.name.as_str() {
            "contact" => {
                let device = variable()
                    .filter(|v| !v.is_empty())
                    .ok_or("a contact with no variable")?;
                let kind = match (n.attr("negated") == Some("true"), n.attr("edge")) {
                    (false, None | Some("none")) => ContactKind::No,
                    (true, None | Some("none")) => ContactKind::Nc,
                    (false, Some("rising")) => ContactKind::Rising,
                    (false, Some("falling")) => ContactKind::Falling,
                    _ => {
                        return Err(format!(
                            "contact {device}: a negated edge contact has no ladder form here"
                        ))
                    }
                };
                let input =
                    self.join(n.child("connectionPointIn"), &format!("contact {device}"))?;
                self.consumed.push(input);
                let out = self.point(&id, "");
                self.edges.push((
                    input,
                    out,
                    Net::Leaf(Element::Contact { kind, device }, pos),
                    n.line,
                ));
            }
            "coil" => {
                let device = variable()
                    .filter(|v| !v.is_empty())
                    .ok_or("a coil with no variable")?;
                let negated = n.attr("negated") == Some("true");
                let element = match (negated, n.attr("storage"), n.attr("edge")) {
                    (false, None | Some("none"), None | Some("none")) => coil(CoilKind::Normal, device),
                    (true, None | Some("none"), None | Some("none")) => coil(CoilKind::Inverted, device),
                    (false, Some("set"), None | Some("none")) => coil(CoilKind::Set, device),
                    (false, Some("reset"), None | Some("none")) => coil(CoilKind::Reset, device),
                    (false, None | Some("none"), Some(e @ ("rising" | "falling"))) => Element::Pulse {
                        falling: e == "falling",
                        device,
                    },
                    _ => return Err(format!("coil {device}: this mix of negated / storage / edge has no ladder form here")),
                };
                let input = self.join(n.child("connectionPointIn"), &format!("coil {element}"))?;
                self.consumed.push(input);
                // A coil passes power on: a coil wired after it sees the same.
                let out = self.point(&id, "");
                self.union(input, out);
                self.outputs.push((input, element, pos, n.line));
            }
            "block" => self.block(n, &id, pos)?,
            "leftPowerRail" | "rightPowerRail" | "inVariable" | "comment" => {}
            "outVariable" | "inOutVariable" => {
                return Err(format!(
                    "<{}> is not imported: Hashigo's ladders have no word outputs from blocks",
                    n.name
                ))
            }
            other => return Err(format!("<{other}> is not supported in LD bodies here")),
        }
        Ok(())
    }

    fn block(&mut self, n: &Node, id: &str, pos: Pos) -> Result<(), String> {
        let ty = n.attr("typeName").unwrap_or_default().to_ascii_uppercase();
        let instance = n.attr("instanceName").unwrap_or_default().to_string();
        let inputs: Vec<&Node> = n
            .child("inputVariables")
            .map(|v| v.all("variable").collect())
            .unwrap_or_default();
        let pin = |name: &str| {
            inputs
                .iter()
                .copied()
                .find(|v| v.attr("formalParameter") == Some(name))
        };
        let (power_in, power_out) = match ty.as_str() {
            "TON" | "TOF" | "TP" | "NOT" => ("IN", if ty == "NOT" { "OUT" } else { "Q" }),
            "R_TRIG" | "F_TRIG" => ("CLK", "Q"),
            "CTU" => ("CU", "Q"),
            _ => {
                return Err(format!(
                    "block {ty} is not supported: Hashigo imports TON, TOF, TP, CTU, R_TRIG, F_TRIG and NOT"
                ))
            }
        };
        let what = format!("{ty} block {instance}");
        let input = self.join(
            pin(power_in).and_then(|v| v.child("connectionPointIn")),
            &what,
        )?;
        self.consumed.push(input);
        let literal = |name: &str| -> Result<(String, usize), String> {
            let v = pin(name).ok_or(format!("{what}: its {name} input is not connected"))?;
            let r = v
                .child("connectionPointIn")
                .and_then(|c| c.child("connection"))
                .and_then(|c| c.attr("refLocalId"))
                .ok_or(format!("{what}: its {name} input is not connected"))?;
            self.literals.get(r).cloned().ok_or(format!(
                "{what}: its {name} input must come from a literal (an inVariable)"
            ))
        };
        let element = match ty.as_str() {
            "TON" | "TOF" | "TP" => {
                let (expr, _) = literal("PT")?;
                let preset_ms = parse_time_literal(&expr).ok_or(format!(
                    "{what}: PT \"{expr}\" is not a time literal like T#500ms"
                ))?;
                let kind = match ty.as_str() {
                    "TON" => TimerKind::Ton,
                    "TOF" => TimerKind::Tof,
                    _ => TimerKind::Tp,
                };
                Element::Timer {
                    kind,
                    name: instance.clone(),
                    preset_ms,
                }
            }
            "CTU" => {
                if pin("R")
                    .and_then(|v| v.child("connectionPointIn"))
                    .and_then(|c| c.child("connection"))
                    .is_some()
                {
                    return Err(format!("{what}: wire R to nothing and reset the counter with a reset coil on {instance}"));
                }
                let (expr, _) = literal("PV")?;
                let preset: u16 = expr
                    .trim()
                    .parse()
                    .map_err(|_| format!("{what}: PV \"{expr}\" is not a whole number 0..32767"))?;
                Element::CounterCoil {
                    device: instance.clone(),
                    preset,
                }
            }
            "R_TRIG" | "F_TRIG" => Element::Edge {
                falling: ty == "F_TRIG",
            },
            _ => Element::Not,
        };
        let out = self.point(id, power_out);
        self.edges
            .push((input, out, Net::Leaf(element, pos), n.line));
        Ok(())
    }

    fn rungs(mut self, machine: Option<MachineId>) -> Result<Vec<RungLogic>, Errors> {
        // A TON or CTU whose output drives nothing is the machine's timer
        // or counter coil (`OUT T00 K19`).
        let consumed: Vec<usize> = self
            .consumed
            .clone()
            .into_iter()
            .map(|p| self.find(p))
            .collect();
        let mut edges = Vec::new();
        let mut lines: HashMap<Pos, usize> = HashMap::new();
        for (a, b, net, line) in std::mem::take(&mut self.edges) {
            let (a, b) = (self.find(a), self.find(b));
            if let Net::Leaf(e, pos) = &net {
                lines.insert(*pos, line);
                let terminal = !consumed.contains(&b);
                match (e, terminal) {
                    (
                        Element::Timer {
                            kind: TimerKind::Ton,
                            name,
                            preset_ms,
                        },
                        true,
                    ) => {
                        let coil = timer_coil(name, *preset_ms)
                            .map_err(|m| vec![Located::new(line, m)])?;
                        self.outputs.push((a, coil, *pos, line));
                        continue;
                    }
                    (Element::CounterCoil { .. }, true) => {
                        self.outputs.push((a, e.clone(), *pos, line));
                        continue;
                    }
                    (Element::CounterCoil { device, .. }, false) => {
                        return Err(vec![Located::new(line, format!("CTU {device}: read the counter with a contact on {device} instead of wiring its Q on"))]);
                    }
                    _ => {}
                }
            }
            edges.push((a, b, net));
        }
        if let Some(m) = machine {
            let mut errors = Vec::new();
            let leaves = edges.iter().filter_map(|(_, _, n)| match n {
                Net::Leaf(e, p) => Some((e, lines.get(p).copied().unwrap_or(1))),
                _ => None,
            });
            let outs = self.outputs.iter().map(|(_, e, _, line)| (e, *line));
            for (e, line) in leaves.chain(outs) {
                if let Err(msg) = check_element(m, e) {
                    errors.push(Located::new(line, msg));
                }
            }
            if !errors.is_empty() {
                return Err(errors);
            }
        }
        let rail = self.find(RAIL);
        let mut groups: BTreeMap<usize, Vec<(Element, Pos, usize)>> = BTreeMap::new();
        for (input, e, pos, line) in std::mem::take(&mut self.outputs) {
            let bus = self.find(input);
            groups.entry(bus).or_default().push((e, pos, line));
        }
        let mut rungs = Vec::new();
        let mut errors = Vec::new();
        let mut used = Vec::new();
        for (bus, mut outs) in groups {
            outs.sort_by_key(|(_, p, _)| *p);
            let first_line = outs[0].2;
            if bus == rail {
                errors.push(Located::new(
                    first_line,
                    format!(
                        "{} is wired straight to the left rail: put a contact before it",
                        outs[0].0
                    ),
                ));
                continue;
            }
            match network(edges.clone(), rail, bus) {
                Ok(condition) => {
                    used.extend(condition.leaves().iter().map(|(_, p)| *p));
                    rungs.push(RungLogic {
                        condition,
                        outputs: outs.into_iter().map(|(e, p, _)| (e, p)).collect(),
                        comment: String::new(),
                    });
                }
                Err(None) => errors.push(Located::new(first_line, format!("no path joins the left rail to {}", outs[0].0))),
                Err(Some(p)) => errors.push(Located::new(
                    lines.get(&p).copied().unwrap_or(first_line),
                    "this network is not series-parallel: Hashigo's ladders are series and parallel blocks".to_string(),
                )),
            }
        }
        for (_, _, net) in &edges {
            if let Net::Leaf(e, p) = net {
                if !used.contains(p) && errors.is_empty() {
                    errors.push(Located::new(
                        lines.get(p).copied().unwrap_or(1),
                        format!("{e} leads to no coil"),
                    ));
                }
            }
        }
        if !errors.is_empty() {
            return Err(errors);
        }
        rungs.sort_by_key(top);
        // A comment belongs to the first rung at or below it.
        for (y, text) in std::mem::take(&mut self.comments) {
            let i = rungs
                .iter()
                .position(|r| top(r).row >= y)
                .unwrap_or(rungs.len().saturating_sub(1));
            if let Some(r) = rungs.get_mut(i) {
                if !r.comment.is_empty() {
                    r.comment.push('\n');
                }
                r.comment.push_str(&text);
            }
        }
        Ok(rungs)
    }
}

fn top(r: &RungLogic) -> Pos {
    r.outputs
        .iter()
        .map(|(_, p)| *p)
        .chain([r.condition.top_left()])
        .min()
        .unwrap_or(Pos::new(0, 0))
}

fn coil(kind: CoilKind, device: String) -> Element {
    Element::Coil { kind, device }
}

/// `OUT Tnn K…` from a TON named like an IO86A timer.
fn timer_coil(name: &str, preset_ms: u32) -> Result<Element, String> {
    let Ok(Bit::T(n)) = parse_bit(name) else {
        return Err(format!(
            "TON {name}: its Q drives nothing, which makes it a timer coil, and then it must be named like a timer (T00-T31)"
        ));
    };
    let base = if n < 24 { 100 } else { 10 };
    if !preset_ms.is_multiple_of(base) {
        return Err(format!(
            "TON {name}: {preset_ms} ms is not a whole number of {name}'s {base} ms units"
        ));
    }
    let preset = u16::try_from(preset_ms / base)
        .ok()
        .filter(|&k| k <= 32767)
        .ok_or(format!("TON {name}: {preset_ms} ms is too long"))?;
    Ok(Element::TimerCoil {
        device: name.to_string(),
        preset,
    })
}

/// An element's `<position x y>` (0, 0 when absent or odd), as (y, x).
fn position(n: &Node) -> (usize, usize) {
    let p = n.child("position");
    let num = |k: &str| {
        p.and_then(|p| p.attr(k))
            .and_then(|v| v.parse::<f64>().ok())
            .filter(|v| v.is_finite() && *v >= 0.0 && *v < 1e7)
            .map_or(0, |v| v as usize)
    };
    (num("y"), num("x"))
}
