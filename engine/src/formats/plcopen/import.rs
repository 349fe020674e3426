//! PLCopen LD bodies to rungs. Every element becomes an edge between
//! electrical points (a connection list joins the points it names); each
//! group of coils fed from one point becomes a rung whose condition is the
//! series-parallel network between the left rail and that point.

use std::collections::{HashMap, HashSet};

use super::declare::{self, Names, VarMap};
use super::dom::{self, Node};
use super::error::ImportError;
use super::graph::Graph;
use super::lower::body::Body;
use super::{NS_V10, NS_V200, NS_V201};
use crate::error::Located;
use crate::formats::plcopen::warning::ImportWarning;
use crate::iec::data::DataType;
use crate::ladder::element::Element;
use crate::ladder::grid::Ladder;
use crate::ladder::net::{attach_sides, try_layout, RungLogic};
use crate::ladder::user_blocks::UserBlock;
use crate::limits::MAX_RUNGS;
use crate::MachineId;

use super::error::Errors;

/// A file imported for a machine, with what is worth saying about it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Imported {
    /// The ladder.
    pub ladder: Ladder,
    /// Map entries the file does not use: (name, line of the map).
    pub unused_map_entries: Vec<(String, usize)>,
    /// What was dropped or skipped, at its line of the file.
    pub warnings: Vec<Located<ImportWarning>>,
}

/// The project `root` (read by [`super::Document`]) as a ladder for
/// `machine` (`None`: unchecked), its variables through `map` (issue #18:
/// located variables map by rule, the names become device comments):
/// `pou` alone, or the programs the configuration's tasks run
/// (`choose_pous`). Variables name the machine's devices (`X00`); anything
/// Hashigo cannot represent is an error at its line, never dropped.
pub(super) fn ladder_of(
    root: &Node,
    machine: Option<MachineId>,
    map: Option<&VarMap>,
    pou: Option<&str>,
) -> Result<Imported, Errors> {
    let mut pous = Vec::new();
    root.descendants("pou", &mut pous);
    let mut warnings = Vec::new();
    let chosen = choose_pous(root, &pous, pou, &mut warnings)?;
    let bodies = drawn_bodies(root, &pous, &chosen)?;
    let names = match machine {
        Some(m) => declare::names(root, m, map),
        None => Names::none(),
    };
    // Relays no variable uses: where a block's input is needed twice or
    // negated, a relay holds its power (gates.rs).
    let mut spares = match machine {
        Some(m) => names.spare_relays(m, &devices_named(&bodies, &names)),
        None => Vec::new(),
    };
    let mut helpers = Vec::new();
    let mut temps = Vec::new();
    // The project's own POUs a block may call: (name, language). Its ST
    // blocks that are boxes on the soft PLC are boxes here.
    let boxes = match machine {
        Some(crate::machines::IEC_MACHINE) => st_boxes(&pous),
        _ => HashSet::new(),
    };
    let own_blocks: HashMap<String, (String, String)> = pous
        .iter()
        .filter_map(|p| {
            let name = p.attr("name")?;
            Some((
                name.to_ascii_uppercase(),
                (name.to_string(), language(p).to_string()),
            ))
        })
        .filter(|(name, _)| !boxes.contains(name))
        .collect();
    let mut ladder = Ladder {
        variables: super::boxes::variables::declared_for(machine, root, &chosen)?,
        ..Ladder::default()
    };
    let mut errors = Vec::new();
    let mut carriers: Vec<String> = Vec::new();
    for ld in bodies {
        let read = Body::read(&Graph::read(ld), &names, &own_blocks, machine).and_then(|mut b| {
            b.spares = std::mem::take(&mut spares);
            let rungs = b.rungs(machine, &mut warnings);
            spares = std::mem::take(&mut b.spares);
            helpers.append(&mut b.helpers);
            temps.append(&mut b.temps);
            rungs
        });
        match read {
            Ok(rungs) => {
                for (logic, line) in joined_sides(rungs, &mut carriers) {
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
    super::boxes::variables::settle(&mut ladder.variables, &carriers, &temps, &names);
    super::boxes::variables::drop_edge_instances(&mut ladder);
    name_devices(&mut ladder, &names, helpers, machine, &mut warnings);
    crate::sort::by_key(&mut warnings, |w| w.line);
    Ok(Imported {
        ladder,
        unused_map_entries: names.unused_map_lines(),
        warnings,
    })
}

/// The project's Structured Text function blocks a soft PLC ladder
/// calls as boxes (upper-case names), declared as the ladder's boxes
/// ([`crate::ladder::user_blocks`]) by their interfaces alone: pins of
/// elementary types, no `VAR_IN_OUT`, no name of the soft PLC's own
/// boxes (as `softplc::st::st_blocks` offers them). Their IL is the ST
/// pane's to declare (the page applies the project's ST before its
/// ladder): the import does not lower ST, so the files worker does not
/// carry the ST compiler. With none, none is declared: a box of an
/// earlier file's block is no box of this one.
fn st_boxes(pous: &[&Node]) -> HashSet<String> {
    let blocks: Vec<UserBlock> = pous
        .iter()
        .filter(|p| p.attr("pouType") == Some("functionBlock") && language(p) == "ST")
        .filter_map(|p| box_of(p))
        .collect();
    let names = blocks.iter().map(|b| b.name.clone()).collect();
    crate::ladder::user_blocks::set(blocks, String::new());
    names
}

/// ST block `p` as a box, from its interface; `None` when it cannot be
/// one.
fn box_of(p: &Node) -> Option<UserBlock> {
    let name = p.attr("name")?.trim().to_ascii_uppercase();
    if crate::ladder::block::Shape::builtin(&name).is_some() {
        return None;
    }
    let interface = p.child("interface")?;
    let section = |kind: &'static str| interface.all(kind).flat_map(|s| s.all("variable"));
    if section("inOutVars").next().is_some() {
        return None;
    }
    let pins = |kind: &'static str| -> Option<Vec<(String, DataType)>> {
        section(kind)
            .map(|v| {
                let ty = v.child("type")?.children.first()?;
                let ty = DataType::from_name(&ty.name.to_ascii_uppercase())?;
                Some((v.attr("name")?.trim().to_string(), ty))
            })
            .collect()
    };
    Some(UserBlock {
        inputs: pins("inputVars")?,
        outputs: pins("outputVars")?,
        name,
    })
}

/// The rungs with the networks that feed soft PLC boxes' other inputs
/// joined to their boxes ([`attach_sides`]); the BOOLs that carried them
/// go to `carriers` (upper case).
fn joined_sides(
    rungs: Vec<(RungLogic, usize)>,
    carriers: &mut Vec<String>,
) -> Vec<(RungLogic, usize)> {
    let (mut logics, lines): (Vec<RungLogic>, Vec<usize>) = rungs.into_iter().unzip();
    let joined = attach_sides(&mut logics);
    let sides = logics.iter().flat_map(|l| l.sides.iter());
    carriers.extend(sides.map(|s| s.variable.to_ascii_uppercase()));
    logics
        .into_iter()
        .zip(lines)
        .enumerate()
        .filter(|(i, _)| !joined.contains(i))
        .map(|(_, r)| r)
        .collect()
}

/// The file read as a PLCopen project (its root), or why not.
pub(super) fn project(text: &str) -> Result<Node, Errors> {
    let root = dom::parse(text).map_err(|e| vec![Located::new(e.line, e.error.into())])?;
    check_project(&root)?;
    Ok(root)
}

/// The root is a PLCopen project in a namespace this reader knows.
fn check_project(root: &Node) -> Result<(), Errors> {
    if root.name != "project" {
        return Err(vec![Located::new(
            root.line,
            ImportError::NotAProject(root.name.clone()),
        )]);
    }
    match root.attr("xmlns") {
        None | Some(NS_V201) | Some(NS_V200) | Some(NS_V10) => Ok(()),
        Some(other) => Err(vec![Located::new(
            root.line,
            ImportError::Namespace(other.to_string()),
        )]),
    }
}

/// The drawn (LD or FBD) bodies of the `chosen` POUs; when there are
/// none, an error naming what the file has instead.
fn drawn_bodies<'a>(
    root: &Node,
    pous: &[&Node],
    chosen: &[&'a Node],
) -> Result<Vec<&'a Node>, Errors> {
    let bodies: Vec<&Node> = chosen.iter().filter_map(|p| drawn_body(p)).collect();
    if !bodies.is_empty() {
        return Ok(bodies);
    }
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
    Err(vec![Located::new(root.line, error)])
}

/// Names the ladder's devices: variable names and the spare relays'
/// purposes become device comments (each relay also a warning), and a
/// variable declared to start on is a warning (no machine here keeps a
/// power-up value for a bit device).
fn name_devices(
    ladder: &mut Ladder,
    names: &Names,
    helpers: Vec<super::lower::body::Helper>,
    machine: Option<MachineId>,
    warnings: &mut Vec<Located<ImportWarning>>,
) {
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
    for super::lower::body::Helper { relay, what, line } in helpers {
        warnings.push(Located::new(
            line,
            ImportWarning::Helper(relay.clone(), what.clone()),
        ));
        ladder.device_comments.entry(relay).or_insert(what);
    }
    // No machine here keeps a power-up value for a bit device (the soft
    // PLC's variables keep theirs).
    let bits_only = !machine.is_some_and(|m| m.target().capabilities().word_boxes);
    for (name, device, value, line) in names.starting_on().into_iter().filter(|_| bits_only) {
        if used.contains(&device) {
            let machine = machine.map_or("the machine", MachineId::name).to_string();
            warnings.push(Located::new(
                line,
                ImportWarning::StartsOff {
                    name,
                    value,
                    machine,
                    device,
                },
            ));
        }
    }
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
pub(super) fn language(p: &Node) -> &str {
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
pub(super) fn choose_pous<'a>(
    root: &Node,
    pous: &[&'a Node],
    only: Option<&str>,
    warnings: &mut Vec<Located<ImportWarning>>,
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
                ImportWarning::NoTask(
                    kind.to_string(),
                    p.attr("name").unwrap_or_default().to_string(),
                ),
            ));
        }
    }
    Ok(chosen)
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
