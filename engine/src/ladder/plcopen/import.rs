//! PLCopen LD bodies to rungs. Every element becomes an edge between
//! electrical points (a connection list joins the points it names); each
//! group of coils fed from one point becomes a rung whose condition is the
//! series-parallel network between the left rail and that point.

use std::collections::{BTreeMap, HashMap, HashSet};

use super::declare::{self, Names, VarMap};
use super::dom::{self, Node};
use super::error::{Connection, ImportError};
use super::gates::{Gate, GateKind};
use super::{parse_time_literal, NS_V10, NS_V200, NS_V201};
use crate::error::Located;
use crate::io86a::{isa::parse_bit, Bit};
use crate::ladder::element::{CoilKind, ContactKind, Element, TimerKind};
use crate::ladder::grid::{Ladder, Pos};
use crate::ladder::net::{reduce_all, try_layout, Edge, Net, NetError, RungLogic};
use crate::ladder::target::check_element;
use crate::limits::MAX_RUNGS;
use crate::MachineId;

type Errors = Vec<Located<ImportError>>;

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
    import_mapped(text, machine, None).map(|i| i.ladder)
}

/// A file imported for a machine, with what is worth saying about it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Imported {
    /// The ladder.
    pub ladder: Ladder,
    /// Map entries the file does not use: (name, line of the map).
    pub unused_map_entries: Vec<(String, usize)>,
    /// What was dropped or skipped, at its line of the file.
    pub warnings: Vec<Located<String>>,
}

/// [`import_for`] reading the file's declarations (issue #18): located
/// variables map by rule, others through `map` ([`VarMap`]); the
/// variables' names become device comments.
pub fn import_mapped(
    text: &str,
    machine: Option<MachineId>,
    map: Option<&VarMap>,
) -> Result<Imported, Errors> {
    import_pou(text, machine, map, None)
}

/// [`import_mapped`] of one POU (`--pou NAME`), or, with `None`, of the
/// programs the configuration's tasks run ([`choose_pous`]).
pub fn import_pou(
    text: &str,
    machine: Option<MachineId>,
    map: Option<&VarMap>,
    pou: Option<&str>,
) -> Result<Imported, Errors> {
    let root = dom::parse(text).map_err(|e| vec![Located::new(e.line, e.error.into())])?;
    if root.name != "project" {
        return Err(vec![Located::new(
            root.line,
            ImportError::NotAProject(root.name.clone()),
        )]);
    }
    match root.attr("xmlns") {
        None | Some(NS_V201) | Some(NS_V200) | Some(NS_V10) => {}
        Some(other) => {
            return Err(vec![Located::new(
                root.line,
                ImportError::Namespace(other.to_string()),
            )])
        }
    }
    let mut pous = Vec::new();
    root.descendants("pou", &mut pous);
    let mut warnings = Vec::new();
    let chosen = choose_pous(&root, &pous, pou, &mut warnings)?;
    let bodies: Vec<&Node> = chosen
        .iter()
        .filter_map(|p| p.child("body")?.child("LD"))
        .collect();
    if bodies.is_empty() {
        let with_ld: Vec<&str> = pous
            .iter()
            .filter(|p| p.child("body").and_then(|b| b.child("LD")).is_some())
            .filter_map(|p| p.attr("name"))
            .collect();
        let error = if with_ld.is_empty() {
            ImportError::NoLdBody
        } else {
            let run: Vec<&str> = chosen.iter().filter_map(|p| p.attr("name")).collect();
            ImportError::NoLdInPrograms(run.join(", "), with_ld.join(", "))
        };
        return Err(vec![Located::new(root.line, error)]);
    }
    let names = match machine {
        Some(m) => declare::names(&root, m, map),
        None => Names::none(),
    };
    let mut ladder = Ladder::default();
    let mut errors = Vec::new();
    for ld in bodies {
        match Body::read(ld, &names).and_then(|b| b.rungs(machine, &mut warnings)) {
            Ok(rungs) => {
                for (logic, line) in rungs {
                    match try_layout(&logic) {
                        Ok(rung) => ladder.rungs.push(rung),
                        Err(m) => errors.push(Located::new(line, ImportError::Drawing(m))),
                    }
                }
                if ladder.rungs.len() > MAX_RUNGS {
                    return Err(vec![Located::new(ld.line, ImportError::TooManyRungs)]);
                }
            }
            Err(e) => errors.extend(e),
        }
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    let used: std::collections::BTreeSet<String> = ladder
        .rungs
        .iter()
        .flat_map(|r| r.elements().filter_map(|(_, e)| bit_device(e)))
        .collect();
    for (device, name) in names.comments() {
        if used.contains(&device) {
            ladder.device_comments.entry(device).or_insert(name);
        }
    }
    // No machine here keeps a power-up value for a bit device.
    for (name, device, value, line) in names.starting_on() {
        if used.contains(&device) {
            let machine = machine.map_or("the machine", MachineId::name);
            warnings.push(Located::new(
                line,
                format!(
                    "{name} starts at {value} in the file, but {machine} starts {device} off at power-up"
                ),
            ));
        }
    }
    warnings.sort_by_key(|w| w.line);
    Ok(Imported {
        ladder,
        unused_map_entries: names.unused_map_lines(),
        warnings,
    })
}

/// The POUs that run: `only` if given; else the programs the
/// configurations instance (tasks' and resources' `pouInstance`), in that
/// order; else every program; else every POU. Other POUs with an LD body
/// (function blocks no task runs, unused programs) are skipped with a
/// warning.
fn choose_pous<'a>(
    root: &Node,
    pous: &[&'a Node],
    only: Option<&str>,
    warnings: &mut Vec<Located<String>>,
) -> Result<Vec<&'a Node>, Errors> {
    let name = |p: &Node| p.attr("name").unwrap_or_default().to_ascii_lowercase();
    if let Some(only) = only {
        let wanted = only.trim().to_ascii_lowercase();
        return match pous.iter().find(|p| name(p) == wanted) {
            Some(p) => Ok(vec![*p]),
            None => {
                let names: Vec<&str> = pous.iter().filter_map(|p| p.attr("name")).collect();
                Err(vec![Located::new(
                    root.line,
                    ImportError::NoSuchPou(only.to_string(), names.join(", ")),
                )])
            }
        };
    }
    let mut instances = Vec::new();
    root.descendants("pouInstance", &mut instances);
    let mut chosen: Vec<&Node> = Vec::new();
    for i in instances {
        let ty = i.attr("typeName").unwrap_or_default().to_ascii_lowercase();
        if let Some(p) = pous.iter().find(|p| name(p) == ty) {
            if !chosen.iter().any(|c| std::ptr::eq(*c, *p)) {
                chosen.push(p);
            }
        }
    }
    if chosen.is_empty() {
        chosen = pous
            .iter()
            .copied()
            .filter(|p| p.attr("pouType") == Some("program"))
            .collect();
    }
    if chosen.is_empty() {
        return Ok(pous.to_vec());
    }
    for p in pous {
        let has_ld = p.child("body").and_then(|b| b.child("LD")).is_some();
        if has_ld && !chosen.iter().any(|c| std::ptr::eq(*c, *p)) {
            let kind = p.attr("pouType").unwrap_or("POU");
            warnings.push(Located::new(
                p.line,
                format!(
                    "{kind} {} skipped: no task runs it (--pou {} imports it alone)",
                    p.attr("name").unwrap_or_default(),
                    p.attr("name").unwrap_or_default()
                ),
            ));
        }
    }
    Ok(chosen)
}

/// The boolean block `ty` as a gate, if it is one; a flip-flop needs a
/// relay from the map for its instance.
fn gate_kind(ty: &str, relay: &str, written: &str) -> Result<Option<GateKind>, ImportError> {
    Ok(Some(match ty {
        "AND" => GateKind::And,
        "OR" => GateKind::Or,
        "XOR" => GateKind::Xor,
        "SR" | "RS" => {
            if relay == written {
                return Err(ImportError::Gate(
                    format!("{ty} block {written}"),
                    format!("its state needs a relay: map it (--map {written},M10)"),
                ));
            }
            GateKind::Flip {
                relay: relay.to_string(),
                set_wins: ty == "SR",
            }
        }
        _ => return Ok(None),
    }))
}

/// A pin's name for messages ('static, as the errors keep it).
fn pin_name(name: &str) -> &'static str {
    match name {
        "S1" => "S1",
        "S" => "S",
        "R" => "R",
        "R1" => "R1",
        _ => "IN",
    }
}

/// Whether a variable box's expression is a variable's name (not a
/// literal: `T#1s`, `10`, `TRUE`).
fn is_variable_name(expr: &str) -> bool {
    let e = expr.trim();
    let first = e.chars().next();
    first.is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && !e.contains('#')
        && !matches!(e.to_ascii_uppercase().as_str(), "TRUE" | "FALSE")
        && e.chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '.')
}

/// The bit device a contact or output names.
fn bit_device(e: &Element) -> Option<String> {
    match e {
        Element::Contact { device, .. }
        | Element::Coil { device, .. }
        | Element::Pulse { device, .. }
        | Element::TimerCoil { device, .. }
        | Element::CounterCoil { device, .. } => Some(device.clone()),
        _ => None,
    }
}

/// One LD body as a graph of points.
#[derive(Default)]
pub(super) struct Body {
    pub(super) parent: Vec<usize>,
    points: HashMap<(String, String), usize>,
    rails: HashSet<String>,
    kinds: HashMap<String, (String, usize)>,
    literals: HashMap<String, (String, usize)>,
    /// Each block's EN connections: (refLocalId, formalParameter).
    enables: HashMap<String, Vec<(String, String)>>,
    /// Variable boxes that feed power: a contact of their device from
    /// the rail (the device, or why it has none; its place).
    variables: HashMap<String, (Result<String, String>, Pos)>,
    /// Contacts and in-line blocks: (in point, out point, leaf, line).
    pub(super) edges: Vec<(usize, usize, Net, usize)>,
    /// Outputs: (in point, element, place, line).
    pub(super) outputs: Vec<(usize, Element, Pos, usize)>,
    /// Points some element takes power from (not the right rail).
    pub(super) consumed: Vec<usize>,
    /// Boolean blocks to lower once every element is read, and the steps
    /// lowering them has taken ([`crate::limits::MAX_GATE_WORK`]).
    pub(super) gates: Vec<Gate>,
    pub(super) gate_work: usize,
    comments: Vec<(usize, String)>,
    /// What is worth saying but does not stop the import.
    warnings: Vec<Located<String>>,
    errors: Errors,
}

pub(super) const RAIL: usize = 0;

impl Body {
    fn read(ld: &Node, names: &Names) -> Result<Body, Errors> {
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
                    .push(Located::new(n.line, ImportError::NoLocalId(n.name.clone())));
                continue;
            };
            if let Some((_, first)) = b.kinds.get(id) {
                b.errors.push(Located::new(
                    n.line,
                    ImportError::DuplicateLocalId {
                        id: id.to_string(),
                        first: *first,
                    },
                ));
                continue;
            }
            b.kinds.insert(id.to_string(), (n.name.clone(), n.line));
            match n.name.as_str() {
                "leftPowerRail" => {
                    b.rails.insert(id.to_string());
                }
                "block" => {
                    let en = n
                        .child("inputVariables")
                        .and_then(|v| {
                            v.all("variable")
                                .find(|p| p.attr("formalParameter") == Some("EN"))
                        })
                        .and_then(|p| p.child("connectionPointIn"))
                        .map(|c| {
                            c.all("connection")
                                .filter_map(|c| {
                                    let r = c.attr("refLocalId")?.to_string();
                                    Some((
                                        r,
                                        c.attr("formalParameter").unwrap_or_default().to_string(),
                                    ))
                                })
                                .collect()
                        })
                        .unwrap_or_default();
                    b.enables.insert(id.to_string(), en);
                }
                "inVariable" => {
                    let expr = n
                        .child("expression")
                        .map(|e| e.text.clone())
                        .unwrap_or_default();
                    if is_variable_name(&expr) {
                        let (y, x) = position(n);
                        let at = Pos::new(y, x * 65_536 + b.kinds.len());
                        b.variables
                            .insert(id.to_string(), (names.device(expr.trim()), at));
                    }
                    b.literals.insert(id.to_string(), (expr, n.line));
                }
                _ => {}
            }
        }
        for (seq, n) in ld.children.iter().enumerate() {
            if let Err(m) = b.element(n, seq, names) {
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
        if self.rails.contains(id) {
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

    /// The point after variable box `id`'s contact of `device` (made
    /// once, from the rail).
    fn variable_point(&mut self, id: &str, device: String, at: Pos) -> usize {
        let key = (id.to_string(), "var".to_string());
        if let Some(&p) = self.points.get(&key) {
            return p;
        }
        let p = self.point(id, "var");
        let line = self.kinds.get(id).map_or(1, |(_, l)| *l);
        self.consumed.push(RAIL);
        self.edges
            .push((RAIL, p, Net::Leaf(Element::no(&device), at), line));
        p
    }

    pub(super) fn find(&mut self, mut x: usize) -> usize {
        while self.parent[x] != x {
            self.parent[x] = self.parent[self.parent[x]];
            x = self.parent[x];
        }
        x
    }

    pub(super) fn union(&mut self, a: usize, b: usize) {
        let (a, b) = (self.find(a), self.find(b));
        if a < b {
            self.parent[b] = a;
        } else {
            self.parent[a] = b;
        }
    }

    /// The point a `connectionPointIn` joins, or an error when it joins none.
    fn join(&mut self, cpi: Option<&Node>, what: &str) -> Result<usize, ImportError> {
        let fail = |problem| ImportError::Connection {
            what: what.to_string(),
            problem,
        };
        let conns: Vec<&Node> = cpi
            .map(|c| c.all("connection").collect())
            .unwrap_or_default();
        let mut joined = None;
        for c in conns {
            let Some(r) = c.attr("refLocalId") else {
                return Err(fail(Connection::NoRef));
            };
            let kind = self.kinds.get(r).map(|(k, _)| k.clone());
            let pin = match kind.as_deref() {
                None => return Err(fail(Connection::Missing(r.to_string()))),
                Some("block") => c.attr("formalParameter").unwrap_or("Q").to_string(),
                Some("inVariable") => match self.variables.get(r).cloned() {
                    // A BOOL variable feeding power: its contact.
                    Some((Ok(device), at)) => {
                        let p = self.variable_point(r, device, at);
                        match joined {
                            None => joined = Some(p),
                            Some(j) => self.union(j, p),
                        }
                        continue;
                    }
                    Some((Err(why), _)) => return Err(ImportError::Variable(why)),
                    None => return Err(fail(Connection::FromVariable(r.to_string()))),
                },
                Some(_) => String::new(),
            };
            let p = self.point(r, &pin);
            match joined {
                None => joined = Some(p),
                Some(j) => self.union(j, p),
            }
        }
        joined.ok_or_else(|| fail(Connection::Unconnected))
    }

    fn element(&mut self, n: &Node, seq: usize, names: &Names) -> Result<(), ImportError> {
        let id = n.attr("localId").unwrap_or_default().to_string();
        let (y, x) = position(n);
        let pos = Pos::new(y, x * 65_536 + seq);
        // A declared name stands for its device (located or mapped).
        let variable = || -> Result<Option<String>, ImportError> {
            match n.child("variable").map(|v| v.text.trim().to_string()) {
                Some(v) if !v.is_empty() => {
                    names.device(&v).map(Some).map_err(ImportError::Variable)
                }
                other => Ok(other),
            }
        };
        match n.name.as_str() {
            "contact" => {
                let device = variable()?
                    .filter(|v| !v.is_empty())
                    .ok_or(ImportError::NoVariable("contact"))?;
                let kind = match (negated(n)?, edge(n)?) {
                    (false, None) => ContactKind::No,
                    (true, None) => ContactKind::Nc,
                    (false, Some("rising")) => ContactKind::Rising,
                    (false, Some(_)) => ContactKind::Falling,
                    (true, Some(_)) => return Err(ImportError::NegatedEdge(device)),
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
                let device = variable()?
                    .filter(|v| !v.is_empty())
                    .ok_or(ImportError::NoVariable("coil"))?;
                let element = match (negated(n)?, storage(n)?, edge(n)?) {
                    (false, None, None) => coil(CoilKind::Normal, device),
                    (true, None, None) => coil(CoilKind::Inverted, device),
                    (false, Some("set"), None) => coil(CoilKind::Set, device),
                    (false, Some(_), None) => coil(CoilKind::Reset, device),
                    (false, None, Some(e)) => Element::Pulse {
                        falling: e == "falling",
                        device,
                    },
                    _ => return Err(ImportError::CoilMix(device)),
                };
                let input = self.join(n.child("connectionPointIn"), &format!("coil {element}"))?;
                self.consumed.push(input);
                // A coil passes power on: a coil wired after it sees the same.
                let out = self.point(&id, "");
                self.union(input, out);
                self.outputs.push((input, element, pos, n.line));
            }
            "block" => self.block(n, &id, pos, names)?,
            "leftPowerRail" | "rightPowerRail" | "inVariable" | "comment" => {}
            "outVariable" => self.out_variable(n, pos, names)?,
            "vendorElement" => {
                let what = n
                    .child("alternativeText")
                    .map(|t| t.deep_text().trim().to_string())
                    .filter(|t| !t.is_empty())
                    .unwrap_or_else(|| "a vendor element".to_string());
                self.warnings.push(Located::new(
                    n.line,
                    format!("{} skipped: a vendor's own element", crate::shown(&what)),
                ));
            }
            "inOutVariable" => return Err(ImportError::WordOutput(n.name.clone())),
            other => return Err(ImportError::Unsupported(other.to_string())),
        }
        Ok(())
    }

    /// A block's EN (its connections read with the body, `enables`):
    /// open, or from the rail, a literal TRUE or an always-running
    /// block's ENO, it always runs, as Hashigo's blocks do; wired to
    /// anything else it is refused (never ignored).
    fn check_enable(&self, id: &str, ty: &str, instance: &str) -> Result<(), ImportError> {
        let refs = self.enables.get(id).map_or(&[][..], Vec::as_slice);
        if self.always_enabled(refs, 0) {
            return Ok(());
        }
        Err(ImportError::Gate(
            format!("{ty} block {instance}").trim().to_string(),
            "its EN is wired: Hashigo's blocks always run; connect EN to the left rail or leave it open".into(),
        ))
    }

    /// Whether EN connections `refs` always carry power: from the rail, a
    /// literal TRUE, or another block's ENO whose own EN always does
    /// (OpenPLC Editor chains EN to ENO); `depth` bounds the chain.
    fn always_enabled(&self, refs: &[(String, String)], depth: usize) -> bool {
        depth < 64
            && refs.iter().all(|(r, pin)| {
                self.rails.contains(r)
                    || self
                        .literals
                        .get(r)
                        .is_some_and(|(e, _)| e.trim().eq_ignore_ascii_case("TRUE"))
                    || (pin.eq_ignore_ascii_case("ENO")
                        && self
                            .enables
                            .get(r)
                            .is_some_and(|en| self.always_enabled(en, depth + 1)))
            })
    }

    /// A boolean block: its inputs joined, its output a point, lowered
    /// once the whole body is read ([`super::gates`]).
    fn gate(
        &mut self,
        n: &Node,
        id: &str,
        pos: Pos,
        kind: GateKind,
        ty: &str,
        instance: &str,
    ) -> Result<(), ImportError> {
        let what = format!("{ty} block {instance}").trim().to_string();
        let pins: Vec<&Node> = n
            .child("inputVariables")
            .map(|v| v.all("variable").collect())
            .unwrap_or_default();
        let order: Vec<&str> = match kind {
            GateKind::Flip { .. } => vec![
                if ty == "SR" { "S1" } else { "S" },
                if ty == "SR" { "R" } else { "R1" },
            ],
            _ => pins
                .iter()
                .filter_map(|v| v.attr("formalParameter"))
                .collect(),
        };
        let mut inputs = Vec::new();
        for name in order {
            let v = pins
                .iter()
                .find(|v| v.attr("formalParameter") == Some(name))
                .ok_or_else(|| ImportError::PinNotConnected(what.clone(), pin_name(name)))?;
            let p = self.join(v.child("connectionPointIn"), &what)?;
            self.consumed.push(p);
            inputs.push(p);
        }
        if inputs.len() < 2 {
            return Err(ImportError::Gate(what, "it needs two inputs".into()));
        }
        let out_pin = if matches!(kind, GateKind::Flip { .. }) {
            "Q1"
        } else {
            "OUT"
        };
        let out = self.point(id, out_pin);
        self.gates.push(Gate {
            kind,
            inputs,
            out,
            pos,
            line: n.line,
            what,
        });
        Ok(())
    }

    /// An output variable box: fed with power (a contact's, a block's
    /// Q), a coil on its variable; fed from a timer's ET or a counter's
    /// CV, which Hashigo's ladders do not carry, dropped with a warning.
    fn out_variable(&mut self, n: &Node, pos: Pos, names: &Names) -> Result<(), ImportError> {
        let expr = n
            .child("expression")
            .map(|e| e.text.trim().to_string())
            .unwrap_or_default();
        let cpi = n.child("connectionPointIn");
        let from = cpi.and_then(|c| c.child("connection"));
        let pin = from
            .and_then(|c| c.attr("formalParameter"))
            .unwrap_or_default()
            .to_ascii_uppercase();
        let block = from
            .and_then(|c| c.attr("refLocalId"))
            .and_then(|r| self.kinds.get(r))
            .is_some_and(|(k, _)| k == "block");
        if block && matches!(pin.as_str(), "ET" | "CV") {
            self.warnings.push(Located::new(
                n.line,
                format!(
                    "the block's {pin} feeds only the variable {}: dropped (Hashigo's ladders carry no word outputs)",
                    crate::shown(&expr)
                ),
            ));
            return Ok(());
        }
        if expr.is_empty() {
            return Err(ImportError::NoVariable("output variable"));
        }
        let device = names.device(&expr).map_err(ImportError::Variable)?;
        let kind = if negated(n)? {
            CoilKind::Inverted
        } else {
            CoilKind::Normal
        };
        let element = coil(kind, device);
        let input = self.join(cpi, &format!("output variable {expr}"))?;
        self.consumed.push(input);
        self.outputs.push((input, element, pos, n.line));
        Ok(())
    }

    fn block(&mut self, n: &Node, id: &str, pos: Pos, names: &Names) -> Result<(), ImportError> {
        let ty = n.attr("typeName").unwrap_or_default().to_ascii_uppercase();
        let written = n.attr("instanceName").unwrap_or_default();
        // A map may give the instance a device (`TON0,T00`).
        let instance = names
            .instance(written)
            .unwrap_or_else(|| written.to_string());
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
        self.check_enable(id, &ty, written)?;
        if let Some(kind) = gate_kind(&ty, &instance, written)? {
            return self.gate(n, id, pos, kind, &ty, written);
        }
        let (power_in, power_out) = match ty.as_str() {
            "TON" | "TOF" | "TP" | "NOT" => ("IN", if ty == "NOT" { "OUT" } else { "Q" }),
            "R_TRIG" | "F_TRIG" => ("CLK", "Q"),
            "CTU" => ("CU", "Q"),
            _ => return Err(ImportError::UnsupportedBlock(ty)),
        };
        let what = format!("{ty} block {instance}");
        let input = self.join(
            pin(power_in).and_then(|v| v.child("connectionPointIn")),
            &what,
        )?;
        self.consumed.push(input);
        // A counter's R: a reset coil on the counter, fed as R is (a
        // literal FALSE resets nothing).
        let reset = pin("R")
            .and_then(|v| v.child("connectionPointIn"))
            .filter(|c| c.child("connection").is_some());
        if ty == "CTU" {
            if let Some(cpi) = reset {
                let constant = cpi
                    .child("connection")
                    .and_then(|c| c.attr("refLocalId"))
                    .and_then(|r| self.literals.get(r))
                    .is_some_and(|(e, _)| e.trim().eq_ignore_ascii_case("FALSE"));
                if !constant {
                    let p = self.join(Some(cpi), &what)?;
                    self.consumed.push(p);
                    let at = Pos::new(pos.row, pos.col.wrapping_add(1));
                    self.outputs
                        .push((p, coil(CoilKind::Reset, instance.clone()), at, n.line));
                }
            }
        }
        let literal = |name: &'static str| -> Result<(String, usize), ImportError> {
            let unconnected = || ImportError::PinNotConnected(what.clone(), name);
            let v = pin(name).ok_or_else(unconnected)?;
            let r = v
                .child("connectionPointIn")
                .and_then(|c| c.child("connection"))
                .and_then(|c| c.attr("refLocalId"))
                .ok_or_else(unconnected)?;
            self.literals
                .get(r)
                .cloned()
                .ok_or_else(|| ImportError::PinNotLiteral(what.clone(), name))
        };
        let element = match ty.as_str() {
            "TON" | "TOF" | "TP" => {
                let (expr, _) = literal("PT")?;
                // A literal, or a variable declared with one.
                let preset_ms = parse_time_literal(&expr)
                    .or_else(|| names.initial(&expr).and_then(parse_time_literal))
                    .ok_or_else(|| ImportError::BadTimeLiteral(what.clone(), expr.to_string()))?;
                let kind = match ty.as_str() {
                    "TON" => TimerKind::Ton,
                    "TOF" => TimerKind::Tof,
                    _ => TimerKind::Tp,
                };
                // A TOF or TP mapped to a timer and a relay (`T01+M20`):
                // built from the machine's on-delay timer coil.
                if let (Some((timer, relay)), false) = (instance.split_once('+'), ty == "TON") {
                    let coil = timer_coil(timer.trim(), preset_ms)?;
                    let kind = GateKind::Delay {
                        coil,
                        timer: timer.trim().to_string(),
                        relay: relay.trim().to_string(),
                        pulse: ty == "TP",
                    };
                    let out = self.point(id, "Q");
                    self.gates.push(Gate {
                        kind,
                        inputs: vec![input],
                        out,
                        pos,
                        line: n.line,
                        what,
                    });
                    return Ok(());
                }
                Element::Timer {
                    kind,
                    name: instance.clone(),
                    preset_ms,
                }
            }
            "CTU" => {
                let (expr, _) = literal("PV")?;
                let value = names.initial(&expr).unwrap_or(&expr).trim().to_string();
                let preset: u16 = value
                    .parse()
                    .ok()
                    .filter(|&k| k <= 32767)
                    .ok_or_else(|| ImportError::BadCounterPreset(what.clone(), expr.clone()))?;
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

    /// The rungs, each with the XML line of its first output.
    fn rungs(
        mut self,
        machine: Option<MachineId>,
        warnings: &mut Vec<Located<String>>,
    ) -> Result<Vec<(RungLogic, usize)>, Errors> {
        warnings.append(&mut self.warnings);
        self.lower_gates()?;
        let (mut edges, mut lines) = self.graph(machine)?;
        if let Some(m) = machine {
            self.check_machine(m, &edges, &lines)?;
        }
        let rail = self.find(RAIL);
        let mut groups: BTreeMap<usize, Vec<(Element, Pos, usize)>> = BTreeMap::new();
        for (input, e, pos, line) in std::mem::take(&mut self.outputs) {
            let bus = self.find(input);
            groups.entry(bus).or_default().push((e, pos, line));
        }
        let mut buses = Vec::new();
        let mut errors = Vec::new();
        let mut moved = Vec::new();
        for (bus, outs) in &mut groups {
            outs.sort_by_key(|(_, p, _)| *p);
            if *bus == rail && machine == Some(MachineId::Io86a) {
                // Always on: IO86A's M57 (ON) carries the rail to it.
                let q = self.parent.len();
                self.parent.push(q);
                let (_, p, line) = &outs[0];
                let at = Pos::new(p.row, p.col.wrapping_sub(1));
                lines.insert(at, *line);
                edges.push(Edge {
                    from: rail,
                    to: q,
                    net: Net::Leaf(Element::no("M57"), at),
                });
                moved.push((*bus, q));
                buses.push(q);
            } else if *bus == rail {
                let on_rail = ImportError::OnRail(outs[0].0.to_string());
                errors.push(Located::new(outs[0].2, on_rail));
            } else {
                buses.push(*bus);
            }
        }
        for (from, to) in moved {
            if let Some(outs) = groups.remove(&from) {
                groups.insert(to, outs);
            }
        }
        // Every group's network at once, each from the part of the graph
        // that leads to it (linear in the sum of their sizes).
        let conditions = reduce_all(&edges, self.parent.len(), rail, &buses);
        let mut rungs = Vec::new();
        for (bus, condition) in buses.iter().zip(conditions) {
            let outs = groups.remove(bus).unwrap_or_default();
            let first_line = outs.first().map_or(1, |o| o.2);
            match condition {
                Ok(condition) => {
                    let logic = RungLogic {
                        condition,
                        outputs: outs.into_iter().map(|(e, p, _)| (e, p)).collect(),
                        comment: String::new(),
                    };
                    rungs.push((top(&logic), logic, first_line));
                }
                Err(NetError::NoPath) => {
                    let what = outs.first().map(|o| o.0.to_string()).unwrap_or_default();
                    errors.push(Located::new(first_line, ImportError::NoPath(what)))
                }
                Err(e @ (NetError::NotSeriesParallel(p) | NetError::TooDeep(p))) => {
                    let line = lines.get(&p).copied().unwrap_or(first_line);
                    errors.push(Located::new(line, ImportError::Net(e)))
                }
            }
        }
        if errors.is_empty() {
            errors.extend(unused(&edges, &rungs, &lines));
        }
        if !errors.is_empty() {
            return Err(errors);
        }
        rungs.sort_by_key(|(top, _, _)| *top);
        self.attach_comments(&mut rungs);
        Ok(rungs.into_iter().map(|(_, r, line)| (r, line)).collect())
    }

    /// The elements as edges between their (joined) points, and each
    /// leaf's line. A TON or CTU whose output drives nothing becomes the
    /// machine's timer or counter coil (`OUT T00 K19`).
    #[allow(clippy::type_complexity)] // a pair of plain collections, named at the call
    fn graph(
        &mut self,
        machine: Option<MachineId>,
    ) -> Result<(Vec<Edge>, HashMap<Pos, usize>), Errors> {
        // IO86A's timers and counters are coils (`OUT T00 K19`) with
        // contacts: an in-line TON or CTU is split ([`Body::split_box`]).
        let timer_coils = machine == Some(MachineId::Io86a);
        let consumed: HashSet<usize> = self
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
                    (
                        Element::Timer {
                            kind: TimerKind::Ton,
                            name,
                            preset_ms,
                        },
                        false,
                    ) if timer_coils => {
                        let coil = timer_coil(name, *preset_ms)
                            .map_err(|m| vec![Located::new(line, m)])?;
                        let contact = Element::no(name);
                        self.split_box((a, b), coil, contact, *pos, line, (&mut edges, &mut lines));
                        continue;
                    }
                    (Element::CounterCoil { .. }, true) => {
                        self.outputs.push((a, e.clone(), *pos, line));
                        continue;
                    }
                    (Element::CounterCoil { device, .. }, false) if timer_coils => {
                        // Q is the counter's count-reached bit.
                        let contact = Element::no(device);
                        self.split_box(
                            (a, b),
                            e.clone(),
                            contact,
                            *pos,
                            line,
                            (&mut edges, &mut lines),
                        );
                        continue;
                    }
                    (Element::CounterCoil { device, .. }, false) => {
                        let wired = ImportError::CounterQWired(device.clone());
                        return Err(vec![Located::new(line, wired)]);
                    }
                    _ => {}
                }
            }
            edges.push(Edge {
                from: a,
                to: b,
                net,
            });
        }
        Ok((edges, lines))
    }

    /// An in-line timer or counter box from point `a` to `b` as IO86A
    /// has it: its `coil` where the box was fed, and its `contact`, from
    /// the rail, where its Q went (Q is on only while the coil's
    /// condition has held long enough), at a place of its own.
    fn split_box(
        &mut self,
        (a, b): (usize, usize),
        coil: Element,
        contact: Element,
        pos: Pos,
        line: usize,
        (edges, lines): (&mut Vec<Edge>, &mut HashMap<Pos, usize>),
    ) {
        self.outputs.push((a, coil, pos, line));
        let at = Pos::new(pos.row, pos.col.wrapping_add(usize::MAX / 2));
        lines.insert(at, line);
        let rail = self.find(RAIL);
        edges.push(Edge {
            from: rail,
            to: b,
            net: Net::Leaf(contact, at),
        });
    }

    /// Every element and device checked against `machine`, at its line.
    fn check_machine(
        &self,
        machine: MachineId,
        edges: &[Edge],
        lines: &HashMap<Pos, usize>,
    ) -> Result<(), Errors> {
        let leaves = edges.iter().filter_map(|e| match &e.net {
            Net::Leaf(e, p) => Some((e, lines.get(p).copied().unwrap_or(1))),
            _ => None,
        });
        let outs = self.outputs.iter().map(|(_, e, _, line)| (e, *line));
        let errors: Errors = leaves
            .chain(outs)
            .filter_map(|(e, line)| {
                check_element(machine, e)
                    .err()
                    .map(|e| Located::new(line, ImportError::Element(e)))
            })
            .collect();
        if errors.is_empty() {
            Ok(())
        } else {
            Err(errors)
        }
    }

    /// A comment belongs to the first rung at or below it.
    fn attach_comments(&mut self, rungs: &mut [(Pos, RungLogic, usize)]) {
        for (y, text) in std::mem::take(&mut self.comments) {
            let i = rungs
                .partition_point(|(top, _, _)| top.row < y)
                .min(rungs.len().saturating_sub(1));
            if let Some((_, r, _)) = rungs.get_mut(i) {
                if !r.comment.is_empty() {
                    r.comment.push('\n');
                }
                r.comment.push_str(&text);
            }
        }
    }
}

/// The first element that no rung uses: it leads to no coil.
fn unused(
    edges: &[Edge],
    rungs: &[(Pos, RungLogic, usize)],
    lines: &HashMap<Pos, usize>,
) -> Option<Located<ImportError>> {
    let used: HashSet<Pos> = rungs
        .iter()
        .flat_map(|(_, r, _)| r.condition.leaves().into_iter().map(|(_, p)| p))
        .collect();
    edges.iter().find_map(|e| match &e.net {
        Net::Leaf(leaf, p) if !used.contains(p) => Some(Located::new(
            lines.get(p).copied().unwrap_or(1),
            ImportError::LeadsNowhere(leaf.to_string()),
        )),
        _ => None,
    })
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
fn timer_coil(name: &str, preset_ms: u32) -> Result<Element, ImportError> {
    let Ok(Bit::T(n)) = parse_bit(name) else {
        return Err(ImportError::TimerName(name.to_string()));
    };
    let base = if n < 24 { 100 } else { 10 };
    if !preset_ms.is_multiple_of(base) {
        return Err(ImportError::TimerUnits {
            name: name.to_string(),
            ms: preset_ms,
            base,
        });
    }
    let preset = u16::try_from(preset_ms / base)
        .ok()
        .filter(|&k| k <= 32767)
        .ok_or_else(|| ImportError::TimerTooLong(name.to_string(), preset_ms))?;
    Ok(Element::TimerCoil {
        device: name.to_string(),
        preset,
    })
}

/// An XML Schema boolean attribute (`true`, `false`, `1`, `0`); absent
/// is false.
fn negated(n: &Node) -> Result<bool, ImportError> {
    match n.attr("negated").map(str::trim) {
        None | Some("false" | "0") => Ok(false),
        Some("true" | "1") => Ok(true),
        Some(other) => Err(ImportError::NotBoolean(other.to_string())),
    }
}

/// The `edge` attribute: `None` for none, else `rising` or `falling`.
fn edge(n: &Node) -> Result<Option<&'static str>, ImportError> {
    match n.attr("edge").map(str::trim) {
        None | Some("none") => Ok(None),
        Some("rising") => Ok(Some("rising")),
        Some("falling") => Ok(Some("falling")),
        Some(other) => Err(ImportError::BadEdge(other.to_string())),
    }
}

/// The coil `storage` attribute: `None` for none, else `set` or `reset`.
fn storage(n: &Node) -> Result<Option<&'static str>, ImportError> {
    match n.attr("storage").map(str::trim) {
        None | Some("none") => Ok(None),
        Some("set") => Ok(Some("set")),
        Some("reset") => Ok(Some("reset")),
        Some(other) => Err(ImportError::BadStorage(other.to_string())),
    }
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
