//! PLCopen LD bodies to rungs. Every element becomes an edge between
//! electrical points (a connection list joins the points it names); each
//! group of coils fed from one point becomes a rung whose condition is the
//! series-parallel network between the left rail and that point.

use std::collections::{BTreeMap, HashMap, HashSet};

use super::blocks;
use super::declare::{self, Names, VarMap};
use super::dom::{self, Node};
use super::error::{Connection, ImportError};
use super::gates::{Gate, GateKind};
use super::main_line::{off_main_line, Link};
use super::{NS_V10, NS_V200, NS_V201};
use crate::error::Located;
use crate::io86a::{isa::parse_bit, Bit};
use crate::ladder::element::{CoilKind, ContactKind, Element, TimerKind};
use crate::ladder::grid::{Ladder, Pos};
use crate::ladder::net::{reduce_all, try_layout, Edge, Net, NetError, RungLogic};
use crate::ladder::target::{capabilities, check_element};
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
/// programs the configuration's tasks run (`choose_pous`).
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
    let bodies: Vec<&Node> = chosen.iter().filter_map(|p| drawn_body(p)).collect();
    if bodies.is_empty() {
        let drawn: Vec<String> = pous
            .iter()
            .filter(|p| drawn_body(p).is_some())
            .map(|p| pou_and_language(p))
            .collect();
        let error = if drawn.is_empty() {
            let all: Vec<String> = pous.iter().map(|p| pou_and_language(p)).collect();
            ImportError::NoDrawnBody(all.join(", "))
        } else {
            let run: Vec<String> = chosen.iter().map(|p| pou_and_language(p)).collect();
            ImportError::NoDrawnInPrograms(run.join(", "), drawn.join(", "))
        };
        return Err(vec![Located::new(root.line, error)]);
    }
    let names = match machine {
        Some(m) => declare::names(&root, m, map),
        None => Names::none(),
    };
    // Relays no variable uses: where a block's input is needed twice or
    // negated, a relay holds its power (gates.rs).
    let mut spares = match machine {
        Some(m) => names.spare_relays(m, &devices_named(&bodies, &names)),
        None => Vec::new(),
    };
    let mut helpers = Vec::new();
    // The project's own POUs a block may call: (name, language).
    let own_blocks: HashMap<String, (String, String)> = pous
        .iter()
        .filter_map(|p| {
            let name = p.attr("name")?;
            Some((
                name.to_ascii_uppercase(),
                (name.to_string(), language(p).to_string()),
            ))
        })
        .collect();
    let mut ladder = Ladder::default();
    let mut errors = Vec::new();
    for ld in bodies {
        let read = Body::read(ld, &names, &own_blocks).and_then(|mut b| {
            b.spares = std::mem::take(&mut spares);
            let rungs = b.rungs(machine, &mut warnings);
            spares = std::mem::take(&mut b.spares);
            helpers.append(&mut b.helpers);
            rungs
        });
        match read {
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
    for (relay, what, line) in helpers {
        warnings.push(Located::new(
            line,
            format!("{relay} holds {what} (a relay the file does not use)"),
        ));
        ladder.device_comments.entry(relay).or_insert(what);
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

/// A POU's LD or FBD body, if it has one: both draw the same graph of
/// variables, blocks and connections (FBD without rails, contacts and
/// coils), so one reader serves both.
pub fn drawn_body(pou: &Node) -> Option<&Node> {
    let body = pou.child("body")?;
    body.child("LD").or_else(|| body.child("FBD"))
}

/// `name in LANGUAGE` for messages (`plc_prg in FBD`).
fn pou_and_language(p: &Node) -> String {
    format!("{} in {}", p.attr("name").unwrap_or_default(), language(p))
}

/// The language of a POU's body (`LD`, `ST`, `FBD`, `SFC`, `IL`).
fn language(p: &Node) -> &str {
    p.child("body")
        .and_then(|b| {
            b.children
                .iter()
                .find(|c| matches!(c.name.as_str(), "LD" | "ST" | "FBD" | "SFC" | "IL"))
        })
        .map_or("no body", |c| c.name.as_str())
}

/// Every device the elements of `bodies` name (as variables or as the
/// machine's own devices): not spare.
fn devices_named(bodies: &[&Node], names: &Names) -> HashSet<String> {
    let mut out = HashSet::new();
    for ld in bodies {
        for n in &ld.children {
            let text = match n.name.as_str() {
                "contact" | "coil" => n.child("variable"),
                "inVariable" | "outVariable" => n.child("expression"),
                _ => None,
            };
            if let Some(Ok(device)) = text.map(|t| names.device(&t.text)) {
                out.insert(device);
            }
        }
    }
    out
}

/// The POU of `root` named `wanted` (`--pou NAME`, any case), or an
/// error listing the POUs there are.
pub fn pou_named<'a>(root: &'a Node, wanted: &str) -> Result<&'a Node, ImportError> {
    let mut pous = Vec::new();
    root.descendants("pou", &mut pous);
    named_pou(&pous, wanted)
}

fn named_pou<'a>(pous: &[&'a Node], wanted: &str) -> Result<&'a Node, ImportError> {
    let wanted = wanted.trim();
    pous.iter()
        .copied()
        .find(|p| {
            p.attr("name")
                .is_some_and(|n| n.eq_ignore_ascii_case(wanted))
        })
        .ok_or_else(|| {
            let names: Vec<&str> = pous.iter().filter_map(|p| p.attr("name")).collect();
            ImportError::NoSuchPou(wanted.to_string(), names.join(", "))
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
        return named_pou(pous, only)
            .map(|p| vec![p])
            .map_err(|e| vec![Located::new(root.line, e)]);
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
        if drawn_body(p).is_some() && !chosen.iter().any(|c| std::ptr::eq(*c, *p)) {
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

/// Whether a variable box's expression is a variable's name (not a
/// literal: `T#1s`, `10`, `TRUE`).
pub(super) fn is_variable_name(expr: &str) -> bool {
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
    pub(super) rails: HashSet<String>,
    kinds: HashMap<String, (String, usize)>,
    /// Named connectors' inputs (by lower-case name) and lines; a
    /// continuation of the same name carries what feeds them.
    connectors: HashMap<String, (Node, usize)>,
    /// Each continuation's connector name (lower case), by localId.
    continuations: HashMap<String, String>,
    /// The connectors being followed (a loop of them is refused).
    following: HashSet<String>,
    pub(super) literals: HashMap<String, (String, usize)>,
    /// Each block's EN connections: (refLocalId, formalParameter).
    pub(super) enables: HashMap<String, Vec<(String, String)>>,
    /// Variable boxes that feed power: a contact of their device from
    /// the rail, NC when the box is negated (or why the variable has no
    /// device; its place).
    variables: HashMap<String, (Result<Element, String>, Pos)>,
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
    /// The element being read (its place and line), for the OR a join of
    /// wires at one of its inputs makes ([`Body::join`]).
    reading: (Pos, usize),
    /// Comment boxes: where they are drawn (row, column) and their text.
    comments: Vec<(usize, usize, String)>,
    /// Relays free to hold a network's power (the next is popped), and
    /// those taken: (relay, what it holds, line).
    pub(super) spares: Vec<String>,
    pub(super) helpers: Vec<(String, String, usize)>,
    /// Devices a block writes whose rungs run before any rung reading
    /// them (counters, split timers; helpers too), as the origin tool
    /// runs a block before what its outputs feed.
    pub(super) ordered: Vec<String>,
    /// Each comparison's `CMP` (its place), the relay its result is
    /// copied to (the copy runs right after the CMP) and its operands
    /// (what writes them runs before it).
    pub(super) compares: Vec<(Pos, String, [String; 2])>,
    /// The machine the body is read for.
    pub(super) machine: Option<MachineId>,
    /// What is worth saying but does not stop the import.
    pub(super) warnings: Vec<Located<String>>,
    errors: Errors,
}

pub(super) const RAIL: usize = 0;

impl Body {
    fn read(
        ld: &Node,
        names: &Names,
        own_blocks: &HashMap<String, (String, String)>,
    ) -> Result<Body, Errors> {
        let mut b = Body {
            parent: vec![RAIL],
            ..Body::default()
        };
        for n in &ld.children {
            if n.name == "comment" {
                let (y, x) = position(n);
                b.comments.push((y, x, n.deep_text()));
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
                "connector" => {
                    let name = connector_name(n);
                    let input = n.child("connectionPointIn").cloned().unwrap_or_default();
                    if let Some((_, first)) = b.connectors.get(&name) {
                        b.errors.push(Located::new(
                            n.line,
                            ImportError::DuplicateConnector {
                                name: n.attr("name").unwrap_or_default().to_string(),
                                first: *first,
                            },
                        ));
                    } else {
                        b.connectors.insert(name, (input, n.line));
                    }
                }
                "continuation" => {
                    let name = connector_name(n);
                    b.continuations.insert(id.to_string(), name);
                }
                "block" => {
                    let en = blocks::pin_of(n, "EN")
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
                        let at = place(y, x, b.kinds.len());
                        // A bad `negated` is refused at its line by `element`.
                        let contact = if negated(n).unwrap_or(false) {
                            Element::nc
                        } else {
                            Element::no
                        };
                        let device = names.device(expr.trim()).map(|d| contact(&d));
                        b.variables.insert(id.to_string(), (device, at));
                    }
                    b.literals.insert(id.to_string(), (expr, n.line));
                }
                _ => {}
            }
        }
        for (seq, n) in ld.children.iter().enumerate() {
            if let Err(m) = b.element(n, seq, names, own_blocks) {
                b.errors.push(Located::new(n.line, m));
            }
        }
        if b.errors.is_empty() {
            Ok(b)
        } else {
            Err(b.errors)
        }
    }

    pub(super) fn point(&mut self, id: &str, pin: &str) -> usize {
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

    /// A point fed from the rail by variable box `id`'s `contact`, one
    /// for each wire leaving the box: reading a variable has no side
    /// effect, so a box feeding two blocks reads as two contacts rather
    /// than one shared point that would need a spare relay.
    fn variable_point(&mut self, id: &str, contact: Element, at: Pos) -> usize {
        let p = self.fresh();
        let line = self.kinds.get(id).map_or(1, |(_, l)| *l);
        self.consumed.push(RAIL);
        self.edges.push((RAIL, p, Net::Leaf(contact, at), line));
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
    pub(super) fn join(&mut self, cpi: Option<&Node>, what: &str) -> Result<usize, ImportError> {
        let fail = |problem| ImportError::Connection {
            what: what.to_string(),
            problem,
        };
        let conns: Vec<&Node> = cpi
            .map(|c| c.all("connection").collect())
            .unwrap_or_default();
        let mut joined: Vec<usize> = Vec::new();
        for c in conns {
            let Some(r) = c.attr("refLocalId") else {
                return Err(fail(Connection::NoRef));
            };
            let kind = self.kinds.get(r).map(|(k, _)| k.clone());
            let p = match kind.as_deref() {
                None => return Err(fail(Connection::Missing(r.to_string()))),
                Some("continuation") => self.follow_connector(r, what)?,
                Some("block") => {
                    let pin = c.attr("formalParameter").unwrap_or("Q");
                    self.point(r, pin)
                }
                Some("inVariable") => match self.variables.get(r).cloned() {
                    // A BOOL variable feeding power: its contact.
                    Some((Ok(contact), at)) => self.variable_point(r, contact, at),
                    Some((Err(why), _)) => return Err(ImportError::Variable(why)),
                    None => return Err(fail(Connection::FromVariable(r.to_string()))),
                },
                Some(_) => self.point(r, ""),
            };
            let p = self.find(p);
            if !joined.contains(&p) {
                joined.push(p);
            }
        }
        match joined[..] {
            [] => Err(fail(Connection::Unconnected)),
            [p] => Ok(p),
            _ if joined.contains(&self.find(RAIL)) => Ok(RAIL),
            // Wires joined at an input: an OR of what each carries, as
            // the origin tools compute it. Not one point: a source that
            // also feeds elsewhere would be fed the other wires' power
            // back (lowered as an OR block: through a relay then).
            _ => {
                let out = self.fresh();
                self.consumed.extend(&joined);
                let (pos, line) = self.reading;
                self.gates.push(Gate {
                    kind: GateKind::Or,
                    inputs: joined,
                    out,
                    pos,
                    line,
                    what: format!("a wire joined at {what}"),
                });
                Ok(out)
            }
        }
    }

    /// The point continuation `id` carries: what feeds the connector of
    /// its name (a continuation is the connector's wire, drawn apart).
    fn follow_connector(&mut self, id: &str, what: &str) -> Result<usize, ImportError> {
        let fail = |problem| ImportError::Connection {
            what: what.to_string(),
            problem,
        };
        let name = self.continuations.get(id).cloned().unwrap_or_default();
        let Some((input, _)) = self.connectors.get(&name).cloned() else {
            return Err(fail(Connection::NoConnector(name)));
        };
        if self.following.len() >= crate::limits::MAX_CONNECTOR_CHAIN {
            return Err(fail(Connection::ConnectorChain(name)));
        }
        if !self.following.insert(name.clone()) {
            return Err(fail(Connection::ConnectorLoop(name)));
        }
        let joined = self.join(Some(&input), &format!("connector {name}"));
        self.following.remove(&name);
        joined
    }

    fn element(
        &mut self,
        n: &Node,
        seq: usize,
        names: &Names,
        own_blocks: &HashMap<String, (String, String)>,
    ) -> Result<(), ImportError> {
        let id = n.attr("localId").unwrap_or_default().to_string();
        let (y, x) = position(n);
        let pos = place(y, x, seq);
        self.reading = (pos, n.line);
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
                let input = self.join(n.child("connectionPointIn"), &element.to_string())?;
                self.consumed.push(input);
                // A coil passes power on: a coil wired after it sees the same.
                let out = self.point(&id, "");
                self.union(input, out);
                self.outputs.push((input, element, pos, n.line));
            }
            "block" => {
                let ty = n.attr("typeName").unwrap_or_default().to_ascii_uppercase();
                if let Some((name, language)) = own_blocks.get(&ty) {
                    return Err(ImportError::ProjectBlock(name.clone(), language.clone()));
                }
                if !blocks::is_known(&ty) {
                    return Err(ImportError::UnsupportedBlock(ty));
                }
                blocks::plain_pins(n, &ty)?;
                self.block(n, &id, pos, names)?
            }
            "inVariable" => {
                negated(n)?;
            }
            // Read where a continuation names them (`Body::join`).
            "connector" | "continuation" => {}
            "leftPowerRail" | "rightPowerRail" | "comment" => {}
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

    /// The rungs, each with the XML line of its first output.
    fn rungs(
        &mut self,
        machine: Option<MachineId>,
        warnings: &mut Vec<Located<String>>,
    ) -> Result<Vec<(RungLogic, usize)>, Errors> {
        warnings.append(&mut self.warnings);
        self.machine = machine;
        self.lower_gates()?;
        if let Some(m) = machine {
            self.fold_boxes_into_contacts(m);
        }
        let (mut edges, mut lines) = self.graph(machine)?;
        // An element whose output was joined to the rail (a wire joined
        // with an always-on output: OR TRUE), or a contact between one
        // point, changes no power: dropped (said as leading to no coil),
        // as the loop it makes would not reduce.
        let rail = self.find(RAIL);
        edges.retain(|e| {
            let shorted = e.from == e.to && matches!(e.net, Net::Leaf(Element::Contact { .. }, _));
            e.to != rail && !shorted
        });
        if let Some(m) = machine {
            self.check_machine(m, &edges, &lines)?;
        }
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
                let q = self.fresh();
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
        if !errors.is_empty() {
            return Err(errors);
        }
        // Logic that reaches no coil has no effect in the tool that drew
        // it either (the right rail is no output): said, not kept.
        warnings.extend(unused(&edges, &rungs, &lines));
        rungs.sort_by_key(|(top, _, _)| *top);
        self.attach_comments(&mut rungs);
        self.helpers_first(&mut rungs);
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
        let off_main = self.boxes_off_main_line(machine);
        let mut edges = Vec::new();
        let mut lines: HashMap<Pos, usize> = HashMap::new();
        for (index, (a, b, net, line)) in std::mem::take(&mut self.edges).into_iter().enumerate() {
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
                    (Element::Timer { .. }, _) if off_main.contains(&index) => {
                        // Off the rung's main line, where the machine
                        // takes timers in-line only: the timer gets a rung
                        // of its own into a spare relay, whose contact
                        // gives Q where Q went.
                        let what = format!("{e} box's output");
                        let relay = self.spare_relay(&what, line).map_err(|why| {
                            vec![Located::new(line, ImportError::Gate(e.to_string(), why))]
                        })?;
                        let q = self.fresh();
                        let at_coil = Pos::new(pos.row, pos.col.wrapping_add(1));
                        edges.push(Edge {
                            from: a,
                            to: q,
                            net,
                        });
                        let held = coil(CoilKind::Normal, relay.clone());
                        let split = (&mut edges, &mut lines);
                        self.split_box((q, b), held, Element::no(&relay), at_coil, line, split);
                        continue;
                    }
                    (Element::Not | Element::Edge { .. }, _)
                        if machine.is_some_and(|m| check_element(m, e).is_err())
                            || off_main.contains(&index) =>
                    {
                        // No in-line box on this machine, or not here (off
                        // the rung's main line): a relay holds the box's
                        // input, and its NC (NOT) or edge contact gives the
                        // box's output.
                        let what = match e {
                            Element::Not => "NOT block".to_string(),
                            Element::Edge { falling: true } => "F_TRIG block".to_string(),
                            _ => "R_TRIG block".to_string(),
                        };
                        let at = Pos::new(pos.row, pos.col.wrapping_sub(1));
                        let device = self
                            .hold_in_relay(a, &format!("{what}'s input"), line, at)
                            .map_err(|why| {
                                vec![Located::new(line, ImportError::Gate(what, why))]
                            })?;
                        let kind = match e {
                            Element::Not => ContactKind::Nc,
                            Element::Edge { falling: true } => ContactKind::Falling,
                            _ => ContactKind::Rising,
                        };
                        lines.insert(*pos, line);
                        let rail = self.find(RAIL);
                        edges.push(Edge {
                            from: rail,
                            to: b,
                            net: Net::Leaf(Element::Contact { kind, device }, *pos),
                        });
                        continue;
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

    /// The edges (by index) holding a NOT, edge or timer box that
    /// `machine` takes in-line but that would not stand on its rung's main
    /// line ([`super::main_line`]).
    fn boxes_off_main_line(&mut self, machine: Option<MachineId>) -> HashSet<usize> {
        if !machine.is_some_and(|m| capabilities(m).inline_boxes) {
            return HashSet::new();
        }
        let rail = self.find(RAIL);
        let mut links: Vec<Link> = Vec::with_capacity(self.edges.len());
        for i in 0..self.edges.len() {
            let (a, b) = (self.edges[i].0, self.edges[i].1);
            let relayable = matches!(
                self.edges[i].2,
                Net::Leaf(
                    Element::Not | Element::Edge { .. } | Element::Timer { .. },
                    _
                )
            );
            let (from, to) = (self.find(a), self.find(b));
            links.push(Link {
                from,
                to,
                relayable,
            });
        }
        let points = self.parent.len();
        off_main_line(&mut links, rail, points, self.spares.len())
    }

    /// An in-line timer or counter box from point `a` to `b` as IO86A
    /// has it: its `coil` where the box was fed, and its `contact`, from
    /// the rail, where its Q went (Q is on only while the coil's
    /// condition has held long enough), at a place of its own. Also an
    /// AVR timer off its rung's main line: `a` is then the timer's own
    /// output, the coil and contact a spare relay's.
    fn split_box(
        &mut self,
        (a, b): (usize, usize),
        coil: Element,
        contact: Element,
        pos: Pos,
        line: usize,
        (edges, lines): (&mut Vec<Edge>, &mut HashMap<Pos, usize>),
    ) {
        if let Some(d) = coil.written_device() {
            self.ordered.push(d.to_string());
        }
        self.outputs.push((a, coil, pos, line));
        let at = Pos::new(pos.row, pos.col.wrapping_add(SPLIT_PLACES));
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

    /// A block runs before what its outputs feed ([`super::order`]): the
    /// rungs writing a relay that holds a block's input or result
    /// ([`Body::helpers`]), or a device in [`Body::ordered`], run before
    /// the rungs reading it; then each comparison's `CMP` goes right
    /// before the copy of its flag.
    fn helpers_first(&self, rungs: &mut Vec<(Pos, RungLogic, usize)>) {
        let mut touches: BTreeMap<&str, (Vec<usize>, Vec<usize>)> = self
            .helpers
            .iter()
            .map(|(d, _, _)| d.as_str())
            .chain(self.ordered.iter().map(String::as_str))
            .map(|d| (d, (Vec::new(), Vec::new())))
            .collect();
        if touches.is_empty() {
            return;
        }
        for (i, (_, r, _)) in rungs.iter().enumerate() {
            for (e, _) in &r.outputs {
                if let Some(t) = e.written_device().and_then(|d| touches.get_mut(d)) {
                    t.0.push(i);
                }
            }
            for (e, _) in r.condition.leaves() {
                if let Some(t) = e.read_device().and_then(|d| touches.get_mut(d)) {
                    t.1.push(i);
                }
            }
        }
        // A reset wins over a count or a set in the same scan (CTU's R,
        // CTD's LD, R of a CTUD's QD relay): the rung resetting runs after
        // the rungs counting or setting.
        let mut wins: BTreeMap<&str, (Vec<usize>, Vec<usize>)> = BTreeMap::new();
        for (i, (_, r, _)) in rungs.iter().enumerate() {
            for (e, _) in &r.outputs {
                let Some(d) = e.written_device().filter(|d| touches.contains_key(d)) else {
                    continue;
                };
                let entry = wins.entry(d).or_default();
                match e {
                    Element::Coil {
                        kind: CoilKind::Reset,
                        ..
                    } => entry.1.push(i),
                    _ => entry.0.push(i),
                }
            }
        }
        // A comparison reads its operands after this scan's writes, and
        // its flag is copied after it.
        let mut compared = Vec::new();
        for (at, relay, [a, b]) in &self.compares {
            let Some(cmp) = rung_at(rungs, at) else {
                continue;
            };
            compared.push((vec![cmp], writing(rungs, &[relay])));
            compared.push((writing(rungs, &[a, b]), vec![cmp]));
        }
        let constraints: Vec<(Vec<usize>, Vec<usize>)> = touches
            .into_values()
            .chain(wins.into_values())
            .chain(compared)
            .collect();
        let order = super::order::writers_first(rungs.len(), &constraints);
        let mut taken: Vec<Option<(Pos, RungLogic, usize)>> =
            std::mem::take(rungs).into_iter().map(Some).collect();
        rungs.extend(order.into_iter().filter_map(|i| taken.get_mut(i)?.take()));
        for (at, relay, _) in &self.compares {
            let copy = writing(rungs, &[relay]).first().copied();
            if let (Some(c), Some(k)) = (rung_at(rungs, at), copy) {
                let rung = rungs.remove(c);
                let k = if c < k { k - 1 } else { k };
                rungs.insert(k, rung);
            }
        }
    }

    /// A comment belongs to the nearest rung that starts at or below it,
    /// distance being rows down (to the rung's top) plus columns across
    /// (to its leftmost element): a page of networks drawn side by side
    /// (OpenPLC's dancing-lights) puts each title above its own network,
    /// which may start lower than the next column's. Only the
    /// [`COMMENT_REACH`] rungs starting first below it are weighed (rungs
    /// are sorted by their top); below the last rung, the last rung
    /// takes it.
    fn attach_comments(&mut self, rungs: &mut [(Pos, RungLogic, usize)]) {
        if self.comments.is_empty() {
            return;
        }
        let lefts: Vec<usize> = rungs
            .iter()
            .map(|(_, r, _)| {
                let leaves = r.condition.leaves().into_iter().map(|(_, p)| p);
                let places = leaves.chain(r.outputs.iter().map(|(_, p)| *p));
                places.map(|p| drawn_x(p.col)).min().unwrap_or(0)
            })
            .collect();
        for (y, x, text) in std::mem::take(&mut self.comments) {
            let first = rungs.partition_point(|(top, _, _)| top.row < y);
            let distance = |i: usize| (rungs[i].0.row - y) + lefts[i].abs_diff(x);
            let i = (first..rungs.len().min(first + COMMENT_REACH))
                .min_by_key(|&i| distance(i))
                .unwrap_or(rungs.len().saturating_sub(1));
            if let Some((_, r, _)) = rungs.get_mut(i) {
                if !r.comment.is_empty() {
                    r.comment.push('\n');
                }
                r.comment.push_str(&text);
            }
        }
    }
}

/// How many rungs below a comment box may take it (side by side
/// networks; bounded so a hostile file's comments cost linear time).
const COMMENT_REACH: usize = 16;

/// The rungs that write one of `devices`, in order.
fn writing(rungs: &[(Pos, RungLogic, usize)], devices: &[&String]) -> Vec<usize> {
    (0..rungs.len())
        .filter(|&i| {
            rungs[i].1.outputs.iter().any(|(e, _)| {
                e.written_device()
                    .is_some_and(|d| devices.iter().any(|w| w.as_str() == d))
            })
        })
        .collect()
}

/// The rung with an output placed at `at`.
fn rung_at(rungs: &[(Pos, RungLogic, usize)], at: &Pos) -> Option<usize> {
    rungs
        .iter()
        .position(|(_, x, _)| x.outputs.iter().any(|(_, p)| p == at))
}

/// The elements no rung uses: they lead to no coil (a warning each).
fn unused(
    edges: &[Edge],
    rungs: &[(Pos, RungLogic, usize)],
    lines: &HashMap<Pos, usize>,
) -> Vec<Located<String>> {
    let used: HashSet<Pos> = rungs
        .iter()
        .flat_map(|(_, r, _)| r.condition.leaves().into_iter().map(|(_, p)| p))
        .collect();
    edges
        .iter()
        .filter_map(|e| match &e.net {
            Net::Leaf(leaf, p) if !used.contains(p) => Some(Located::new(
                lines.get(p).copied().unwrap_or(1),
                format!("{leaf} leads to no coil: dropped"),
            )),
            _ => None,
        })
        .collect()
}

fn top(r: &RungLogic) -> Pos {
    r.outputs
        .iter()
        .map(|(_, p)| *p)
        .chain([r.condition.top_left()])
        .min()
        .unwrap_or(Pos::new(0, 0))
}

pub(super) fn coil(kind: CoilKind, device: String) -> Element {
    Element::Coil { kind, device }
}

/// `OUT Tnn K…` from a TON named like an IO86A timer.
pub(super) fn timer_coil(name: &str, preset_ms: u32) -> Result<Element, ImportError> {
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

/// A connector's or continuation's name as they are matched: any case.
fn connector_name(n: &Node) -> String {
    n.attr("name")
        .unwrap_or_default()
        .trim()
        .to_ascii_lowercase()
}

/// An XML Schema boolean attribute (`true`, `false`, `1`, `0`); absent
/// is false.
pub(super) fn negated(n: &Node) -> Result<bool, ImportError> {
    match n.attr("negated").map(str::trim) {
        None | Some("false" | "0") => Ok(false),
        Some("true" | "1") => Ok(true),
        Some(other) => Err(ImportError::NotBoolean(other.to_string())),
    }
}

/// The `edge` attribute: `None` for none, else `rising` or `falling`.
pub(super) fn edge(n: &Node) -> Result<Option<&'static str>, ImportError> {
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

/// Where element number `seq` of the file, drawn at (`y`, `x`), sorts:
/// by row, then column, then file order. Saturating: on wasm32 a column
/// past what `usize` holds sorts last rather than wrap around.
fn place(y: usize, x: usize, seq: usize) -> Pos {
    Pos::new(y, x.saturating_mul(PLACES_PER_X).saturating_add(seq))
}

/// Places in one drawn column ([`place`]).
const PLACES_PER_X: usize = 65_536;

/// How far a split box's contact is placed from its coil
/// ([`Body::split_box`]): a place of its own, past every drawn one.
const SPLIT_PLACES: usize = usize::MAX / 2;

/// The drawn column a place sorts in ([`place`], [`SPLIT_PLACES`]).
fn drawn_x(col: usize) -> usize {
    col.checked_sub(SPLIT_PLACES).unwrap_or(col) / PLACES_PER_X
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
