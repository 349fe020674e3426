//! A drawn (LD or FBD) body read once as a graph, for every pipeline:
//! each child of the body in document order ([`Item`]: an element, a
//! comment, a vendor element, or one that cannot be an element), each
//! element by its `localId` with what it is, where it is drawn, which
//! outputs feed each of its inputs and its XML node, and the order the
//! elements run in ([`order()`]). Nothing is lowered or refused here: the
//! soft PLC runs the graph as the file draws it (`soft/`), the bit
//! machines lower it to rungs (`lower/`, then `rungs/`), and
//! each says what it does not take in its own words.

mod order;

use std::collections::HashMap;

pub(super) use order::order;

use super::dom::Node;
use super::vendor::{classify, Vendor};

/// What an element is.
#[derive(Clone, Debug, PartialEq)]
pub(in crate::formats::plcopen) enum Kind {
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
    /// An element no reader here knows (its XML name): SFC steps,
    /// jumps, actions; each pipeline refuses it in its own words.
    Other(String),
}

/// Where one input takes its value: an element's output (its pin, for a
/// block with several).
#[derive(Clone, Debug, PartialEq)]
pub(in crate::formats::plcopen) struct Source {
    pub from: String,
    pub pin: Option<String>,
}

/// One element of the body.
#[derive(Clone, Debug)]
pub(in crate::formats::plcopen) struct Element<'a> {
    /// Its XML node, for what a pipeline reads beyond the graph.
    pub node: &'a Node,
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

impl Element<'_> {
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

/// What one child of the body is read as.
#[derive(Clone, Debug)]
pub(in crate::formats::plcopen) enum Read {
    /// An element: its place in [`Graph::elements`].
    Element(usize),
    /// A `<comment>` box: it does not run.
    Comment,
    /// A tool's own element, sorted by what it does.
    Vendor(Vendor),
    /// An element without a `localId` (`known`: of a kind [`Kind`]
    /// names).
    NoLocalId { known: bool },
    /// An element whose `localId` an earlier one has, at line `first`.
    Duplicate {
        id: String,
        first: usize,
        known: bool,
    },
}

/// One child of the body, in document order: its node and what it is.
#[derive(Clone, Debug)]
pub(in crate::formats::plcopen) struct Item<'a> {
    pub node: &'a Node,
    pub read: Read,
}

/// A body read once: its elements, each one's place by id, its
/// connectors, and every child in document order.
pub(in crate::formats::plcopen) struct Graph<'a> {
    /// The elements, in document order.
    pub elements: Vec<Element<'a>>,
    pub by_id: HashMap<String, usize>,
    /// Connector name (lower-case) → the (last) connector's place.
    pub connectors: HashMap<String, usize>,
    /// Every child of the body, in document order.
    pub items: Vec<Item<'a>>,
}

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

impl<'a> Graph<'a> {
    /// Reads `body` (an `<LD>` or `<FBD>`), every child of it.
    pub(in crate::formats::plcopen) fn read(body: &'a Node) -> Graph<'a> {
        let mut g = Graph {
            elements: Vec::new(),
            by_id: HashMap::new(),
            connectors: HashMap::new(),
            items: Vec::new(),
        };
        for n in &body.children {
            let read = g.child(n);
            g.items.push(Item { node: n, read });
        }
        g
    }

    /// Reads child `n` of the body: an element is added to the graph.
    fn child(&mut self, n: &'a Node) -> Read {
        match n.name.as_str() {
            "comment" => return Read::Comment,
            "vendorElement" => return Read::Vendor(classify(n)),
            _ => {}
        }
        let (kind, inputs, outputs, modifiers) = parts(n);
        let known = !matches!(kind, Kind::Other(_));
        let Some(id) = n.attr("localId") else {
            return Read::NoLocalId { known };
        };
        if let Some(&first) = self.by_id.get(id) {
            let first = self.elements[first].line;
            let id = id.to_string();
            return Read::Duplicate { id, first, known };
        }
        let position = n.child("position");
        let coord = |a: &str| {
            position
                .and_then(|p| p.attr(a))
                .and_then(|v| v.parse::<f64>().ok())
                .map_or(0, |v| v as i64)
        };
        let at = self.elements.len();
        if let Kind::Connector(name) = &kind {
            self.connectors.insert(name.to_ascii_lowercase(), at);
        }
        self.by_id.insert(id.to_string(), at);
        self.elements.push(Element {
            node: n,
            id: id.to_string(),
            kind,
            line: n.line,
            x: coord("x"),
            y: coord("y"),
            inputs,
            outputs,
            modifiers,
        });
        Read::Element(at)
    }
}

/// Element `n` read (not a comment or a vendor element).
fn parts(n: &Node) -> Parts {
    let single = || vec![(String::new(), sources(n.child("connectionPointIn")))];
    let name = |attr: &str| n.attr(attr).unwrap_or_default().to_string();
    let (kind, inputs) = match n.name.as_str() {
        "block" => return block(n),
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
        other => (Kind::Other(other.to_string()), Vec::new()),
    };
    (kind, inputs, Vec::new(), Vec::new())
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

#[cfg(test)]
mod tests;
