//! A drawn (LD or FBD) body read as a graph: each element by its
//! `localId`, with what it is, where it is drawn and which outputs feed
//! each of its inputs. Nothing is lowered: the soft PLC runs the graph
//! as the file draws it.

use std::collections::HashMap;

use super::SoftError;
use crate::error::Located;
use crate::formats::plcopen::dom::Node;

/// What an element is.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Kind {
    LeftRail,
    RightRail,
    Contact {
        variable: String,
        negated: bool,
        /// `Some(false)` rising, `Some(true)` falling.
        edge: Option<bool>,
    },
    Coil {
        variable: String,
        negated: bool,
        /// `Some(true)` set, `Some(false)` reset.
        storage: Option<bool>,
        edge: Option<bool>,
    },
    Block {
        type_name: String,
        instance: String,
    },
    InVariable(String),
    OutVariable(String),
    InOutVariable(String),
    Connector(String),
    Continuation(String),
}

/// Where one input takes its value: an element's output (its pin, for a
/// block with several).
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Source {
    pub from: String,
    pub pin: Option<String>,
}

/// One element of the body.
#[derive(Clone, Debug)]
pub(super) struct Element {
    pub id: String,
    pub kind: Kind,
    pub line: usize,
    pub x: i64,
    pub y: i64,
    /// Each input pin (`""` for the one input of a contact, coil or
    /// variable) with its sources (several: a wired OR).
    pub inputs: Vec<(String, Vec<Source>)>,
    /// A block's output pins, in order.
    pub outputs: Vec<String>,
    /// A block's inputs drawn negated or on an edge: pin, negated, edge
    /// (`Some(false)` rising).
    pub modifiers: Vec<(String, bool, Option<bool>)>,
}

impl Element {
    /// The element in words, with its input `pin` when there is one
    /// (`TON block T1's PT`).
    pub fn describe(&self, pin: &str) -> String {
        let what = match &self.kind {
            Kind::Contact { variable, .. } => format!("contact {variable}"),
            Kind::Coil { variable, .. } => format!("coil {variable}"),
            Kind::Block {
                type_name,
                instance,
            } => format!("{type_name} block {instance}")
                .trim_end()
                .to_string(),
            Kind::OutVariable(x) => format!("output variable {x}"),
            _ => format!("element {}", self.id),
        };
        if pin.is_empty() {
            what
        } else {
            format!("{what}'s {pin}")
        }
    }

    /// The type a block element calls (empty for any other element).
    pub fn block_type(&self) -> String {
        match &self.kind {
            Kind::Block { type_name, .. } => type_name.clone(),
            _ => String::new(),
        }
    }
}

/// The body's elements in document order, and each one's place by id.
pub(super) struct Graph {
    pub elements: Vec<Element>,
    pub by_id: HashMap<String, usize>,
    /// Connector name (lower-case) → the connector's place.
    pub connectors: HashMap<String, usize>,
    /// Vendor elements skipped (neither wired nor holding data), each at
    /// its line.
    pub warnings: Vec<Located<String>>,
}

type Errors = Vec<Located<SoftError>>;

fn flag(n: &Node, name: &str) -> bool {
    n.attr(name) == Some("true")
}

fn edge(n: &Node) -> Option<bool> {
    match n.attr("edge") {
        Some("rising") => Some(false),
        Some("falling") => Some(true),
        _ => None,
    }
}

fn sources(point: Option<&Node>) -> Vec<Source> {
    point
        .map(|p| {
            p.all("connection")
                .map(|c| Source {
                    from: c.attr("refLocalId").unwrap_or_default().to_string(),
                    pin: c.attr("formalParameter").map(str::to_string),
                })
                .collect()
        })
        .unwrap_or_default()
}

fn text_of(n: &Node, child: &str) -> String {
    n.child(child)
        .map(|c| c.text.trim().to_string())
        .unwrap_or_default()
}

/// What an element is read as: its kind, inputs, outputs and input
/// modifiers.
type Parts = (
    Kind,
    Vec<(String, Vec<Source>)>,
    Vec<String>,
    Vec<(String, bool, Option<bool>)>,
);

/// Reads `body` (an `<LD>` or `<FBD>`); refuses, at its line, what the
/// soft PLC does not run (SFC steps, jumps, actions in a drawn body).
pub(super) fn read(body: &Node) -> Result<Graph, Errors> {
    let mut g = Graph {
        elements: Vec::new(),
        by_id: HashMap::new(),
        connectors: HashMap::new(),
        warnings: Vec::new(),
    };
    let mut errors = Vec::new();
    for n in &body.children {
        if n.name == "vendorElement" {
            use crate::formats::plcopen::vendor::{classify, Vendor};
            // Titles and settings do not run; IL has no rung comments.
            match classify(n) {
                Vendor::Title(_) | Vendor::Cosmetic => {}
                Vendor::Unknown(what) => g.warnings.push(Located::new(
                    n.line,
                    format!("{what} skipped: a vendor's own element"),
                )),
                Vendor::Logic(why) => {
                    errors.push(Located::new(n.line, SoftError::VendorLogic(why)))
                }
            }
            continue;
        }
        let (kind, inputs, outputs, modifiers) = match parts(n) {
            Ok(Some(parts)) => parts,
            Ok(None) => continue,
            Err(e) => {
                errors.push(Located::new(n.line, e));
                continue;
            }
        };
        let Some(id) = n.attr("localId") else {
            errors.push(Located::new(n.line, SoftError::NoLocalId(n.name.clone())));
            continue;
        };
        if g.by_id.contains_key(id) {
            errors.push(Located::new(n.line, SoftError::DuplicateId(id.to_string())));
            continue;
        }
        let position = n.child("position");
        let coord = |a: &str| {
            position
                .and_then(|p| p.attr(a))
                .and_then(|v| v.parse::<f64>().ok())
                .map_or(0, |v| v as i64)
        };
        if let Kind::Connector(name) = &kind {
            g.connectors
                .insert(name.to_ascii_lowercase(), g.elements.len());
        }
        g.by_id.insert(id.to_string(), g.elements.len());
        g.elements.push(Element {
            id: id.to_string(),
            kind,
            line: n.line,
            x: coord("x"),
            y: coord("y"),
            inputs,
            outputs,
            modifiers,
        });
    }
    if errors.is_empty() {
        Ok(g)
    } else {
        Err(errors)
    }
}

/// Element `n` read (`None`: a comment, which does not run).
fn parts(n: &Node) -> Result<Option<Parts>, SoftError> {
    let single = || vec![(String::new(), sources(n.child("connectionPointIn")))];
    let name = |attr: &str| n.attr(attr).unwrap_or_default().to_string();
    let (kind, inputs) = match n.name.as_str() {
        "comment" => return Ok(None),
        "block" => return Ok(Some(block(n))),
        "leftPowerRail" => (Kind::LeftRail, Vec::new()),
        "rightPowerRail" => (Kind::RightRail, Vec::new()),
        "contact" => (
            Kind::Contact {
                variable: text_of(n, "variable"),
                negated: flag(n, "negated"),
                edge: edge(n),
            },
            single(),
        ),
        "coil" => (
            Kind::Coil {
                variable: text_of(n, "variable"),
                negated: flag(n, "negated"),
                storage: match n.attr("storage") {
                    Some("set") => Some(true),
                    Some("reset") => Some(false),
                    _ => None,
                },
                edge: edge(n),
            },
            single(),
        ),
        "inVariable" => (Kind::InVariable(text_of(n, "expression")), Vec::new()),
        "outVariable" => (Kind::OutVariable(text_of(n, "expression")), single()),
        "inOutVariable" => (Kind::InOutVariable(text_of(n, "expression")), single()),
        "connector" => (Kind::Connector(name("name")), single()),
        "continuation" => (Kind::Continuation(name("name")), Vec::new()),
        other => return Err(SoftError::Element(other.to_string())),
    };
    Ok(Some((kind, inputs, Vec::new(), Vec::new())))
}

/// A `<block>`: its type and instance, its input pins with their
/// sources (and any drawn negated or on an edge), its output pins.
fn block(n: &Node) -> Parts {
    let pins = |group: &str, point: &str| -> Vec<(String, Vec<Source>)> {
        n.child(group)
            .map(|g| {
                g.all("variable")
                    .map(|v| {
                        let pin = v.attr("formalParameter").unwrap_or_default();
                        (pin.to_string(), sources(v.child(point)))
                    })
                    .collect()
            })
            .unwrap_or_default()
    };
    let mut modifiers = Vec::new();
    for v in n
        .child("inputVariables")
        .iter()
        .flat_map(|g| g.all("variable"))
    {
        let (negated, edge) = (flag(v, "negated"), edge(v));
        if negated || edge.is_some() {
            let pin = v.attr("formalParameter").unwrap_or_default();
            modifiers.push((pin.to_string(), negated, edge));
        }
    }
    let outputs = pins("outputVariables", "connectionPointOut")
        .into_iter()
        .map(|(p, _)| p)
        .collect();
    (
        Kind::Block {
            type_name: n.attr("typeName").unwrap_or_default().to_string(),
            instance: n.attr("instanceName").unwrap_or_default().to_string(),
        },
        pins("inputVariables", "connectionPointIn"),
        outputs,
        modifiers,
    )
}
