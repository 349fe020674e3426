//! Reading a body for the bit machines: each element of the body's
//! [`Graph`] (read once, shared with the soft PLC) becomes edges between
//! electrical points of the [`Body`] graph (a connection list joins the
//! points it names), its blocks gates to lower later.

use std::collections::HashMap;

use super::blocks;
use super::body::{Body, CommentBox, Gate, GateKind, Lined, PinRef, VariableBox, RAIL};
use crate::error::Located;
use crate::formats::plcopen::declare::Names;
use crate::formats::plcopen::dom::Node;
use crate::formats::plcopen::error::{Connection, Errors, ImportError};
use crate::formats::plcopen::graph::{Element as GraphElement, Graph, Item, Kind, Read};
use crate::formats::plcopen::kinds::BlockKind;
use crate::formats::plcopen::parts::*;
use crate::formats::plcopen::vendor::Vendor;
use crate::formats::plcopen::warning::ImportWarning;
use crate::ladder::element::{CoilKind, ContactKind, Element};
use crate::ladder::grid::Pos;
use crate::ladder::net::Net;
use crate::MachineId;

impl Body {
    /// Lowers body `graph` (read once, [`Graph::read`]) for `machine`:
    /// a first pass notes what joining needs (rails, connectors,
    /// variable boxes), a second reads each element into edges, outputs
    /// and gates.
    pub(in crate::formats::plcopen) fn read(
        graph: &Graph,
        names: &Names,
        own_blocks: &HashMap<String, (String, String)>,
        machine: Option<MachineId>,
    ) -> Result<Body, Errors> {
        let mut b = Body {
            parent: vec![RAIL],
            machine,
            ..Body::default()
        };
        for item in &graph.items {
            b.first_pass(graph, item, names);
        }
        for (seq, item) in graph.items.iter().enumerate() {
            let n = item.node;
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

    /// Notes child `item` of the body: a comment box, a vendor element,
    /// an element without a `localId` of its own (refused), or an
    /// element's kind and what joining needs of it.
    fn first_pass(&mut self, graph: &Graph, item: &Item, names: &Names) {
        let n = item.node;
        let e = match &item.read {
            Read::Comment => {
                let (y, x) = position(n);
                self.comments.push(CommentBox {
                    row: y,
                    col: x,
                    text: n.deep_text(),
                    line: n.line,
                });
                return;
            }
            Read::Vendor(v) => return self.vendor_element(n, v),
            Read::NoLocalId { .. } => {
                let e = ImportError::NoLocalId(n.name.clone());
                return self.errors.push(Located::new(n.line, e));
            }
            Read::Duplicate { id, first, .. } => {
                let e = ImportError::DuplicateLocalId {
                    id: id.clone(),
                    first: *first,
                };
                return self.errors.push(Located::new(n.line, e));
            }
            Read::Element(i) => &graph.elements[*i],
        };
        self.kinds.insert(
            e.id.clone(),
            Lined {
                value: n.name.clone(),
                line: n.line,
            },
        );
        self.index(e, names);
        if self.soft() {
            self.index_soft(&e.id, n);
        }
    }

    /// Notes what a first pass over the body must know before any element
    /// is joined: rails, connectors and continuations, blocks' EN wires,
    /// variable boxes (their contacts) and literals.
    fn index(&mut self, e: &GraphElement, names: &Names) {
        let (id, n) = (e.id.as_str(), e.node);
        match &e.kind {
            Kind::LeftRail => {
                self.rails.insert(id.to_string());
            }
            Kind::Connector(_) => {
                let name = connector_name(n);
                let input = n.child("connectionPointIn").cloned().unwrap_or_default();
                if let Some(Lined { line: first, .. }) = self.connectors.get(&name) {
                    self.errors.push(Located::new(
                        n.line,
                        ImportError::DuplicateConnector {
                            name: n.attr("name").unwrap_or_default().to_string(),
                            first: *first,
                        },
                    ));
                } else {
                    let input = Lined {
                        value: input,
                        line: n.line,
                    };
                    self.connectors.insert(name, input);
                }
            }
            Kind::Continuation(_) => {
                let name = connector_name(n);
                self.continuations.insert(id.to_string(), name);
            }
            Kind::Block { .. } => {
                let en = blocks::pin_of(n, "EN")
                    .and_then(|p| p.child("connectionPointIn"))
                    .map(|c| {
                        c.all("connection")
                            .filter_map(|c| {
                                let id = c.attr("refLocalId")?.to_string();
                                let pin = c.attr("formalParameter").unwrap_or_default();
                                Some(PinRef {
                                    id,
                                    pin: pin.to_string(),
                                })
                            })
                            .collect()
                    })
                    .unwrap_or_default();
                self.enables.insert(id.to_string(), en);
                self.block_names
                    .insert(id.to_string(), type_and_instance(n));
            }
            Kind::InVariable(_) => self.index_variable(id, n, names),
            _ => {}
        }
    }

    /// Notes variable box `n` (`id`): the contact of its device when it
    /// names a variable, and its expression as a literal.
    fn index_variable(&mut self, id: &str, n: &Node, names: &Names) {
        let expr = n
            .child("expression")
            .map(|e| e.text.clone())
            .unwrap_or_default();
        if is_variable_name(&expr) {
            let (y, x) = position(n);
            let at = place(y, x, self.kinds.len());
            // A bad `negated` is refused at its line by `element`.
            let contact = if negated(n).unwrap_or(false) {
                Element::nc
            } else {
                Element::no
            };
            let device = names.device(expr.trim()).map(|d| contact(&d));
            self.variables.insert(
                id.to_string(),
                VariableBox {
                    contact: device,
                    pos: at,
                },
            );
        }
        let literal = Lined {
            value: expr,
            line: n.line,
        };
        self.literals.insert(id.to_string(), literal);
    }

    /// The point a `connectionPointIn` joins, or an error when it joins none.
    pub(in crate::formats::plcopen) fn join(
        &mut self,
        cpi: Option<&Node>,
        what: &str,
    ) -> Result<usize, ImportError> {
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
            let kind = self.kinds.get(r).map(|k| k.value.clone());
            let p = match kind.as_deref() {
                None => return Err(fail(Connection::Missing(r.to_string()))),
                Some("continuation") => self.follow_connector(r, what)?,
                Some("block") => {
                    let pin = c.attr("formalParameter").unwrap_or("Q");
                    self.has_output(r, pin).map_err(fail)?;
                    self.point(r, pin)
                }
                Some("inVariable") => match self.variables.get(r).cloned() {
                    // A BOOL variable feeding power: its contact.
                    Some(VariableBox {
                        contact: Ok(contact),
                        pos,
                    }) => self.variable_point(r, contact, pos),
                    Some(VariableBox {
                        contact: Err(why), ..
                    }) => return Err(ImportError::Variable(why)),
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
                let Lined { value: pos, line } = self.reading;
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
        let Some(Lined { value: input, .. }) = self.connectors.get(&name).cloned() else {
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
        self.reading = Lined {
            value: pos,
            line: n.line,
        };
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
                self.read_contact(n, &id, pos, device)?;
            }
            "coil" => {
                let device = variable()?
                    .filter(|v| !v.is_empty())
                    .ok_or(ImportError::NoVariable("coil"))?;
                self.read_coil(n, &id, pos, device)?;
            }
            "block" => {
                let ty = n.attr("typeName").unwrap_or_default().to_ascii_uppercase();
                if let Some((name, language)) = own_blocks.get(&ty) {
                    return Err(ImportError::ProjectBlock(name.clone(), language.clone()));
                }
                if self.soft() && !self.is_gate(n, &ty, names) {
                    return self.soft_block(n, &id, pos, (&ty, names));
                }
                let kind = BlockKind::parse(&ty).ok_or(ImportError::UnsupportedBlock(ty))?;
                blocks::plain_pins(n, kind)?;
                self.block(n, &id, pos, names, kind)?
            }
            "inVariable" => {
                negated(n)?;
            }
            // Read where a continuation names them (`Body::join`).
            "connector" | "continuation" => {}
            "leftPowerRail" | "rightPowerRail" | "comment" | "vendorElement" => {}
            "outVariable" => self.out_variable(n, pos, names)?,
            "inOutVariable" => return Err(ImportError::WordOutput(n.name.clone())),
            other => return Err(ImportError::Unsupported(other.to_string())),
        }
        Ok(())
    }

    /// A contact of `device`: an edge from the point its input joins to
    /// its own.
    fn read_contact(
        &mut self,
        n: &Node,
        id: &str,
        pos: Pos,
        device: String,
    ) -> Result<(), ImportError> {
        let kind = match (negated(n)?, edge(n)?) {
            (false, None) => ContactKind::No,
            (true, None) => ContactKind::Nc,
            (false, Some("rising")) => ContactKind::Rising,
            (false, Some(_)) => ContactKind::Falling,
            (true, Some(_)) => return Err(ImportError::NegatedEdge(device)),
        };
        let input = self.join(n.child("connectionPointIn"), &format!("contact {device}"))?;
        self.consumed.push(input);
        let out = self.point(id, "");
        self.wire(
            input,
            out,
            Net::Leaf(Element::Contact { kind, device }, pos),
            n.line,
        );
        Ok(())
    }

    /// A coil of `device`: an output on the point its input joins, which
    /// passes that power on to whatever is wired after it.
    fn read_coil(
        &mut self,
        n: &Node,
        id: &str,
        pos: Pos,
        device: String,
    ) -> Result<(), ImportError> {
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
        let out = self.point(id, "");
        self.union(input, out);
        self.output(input, element, pos, n.line);
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
        let block_id = from.and_then(|c| c.attr("refLocalId")).unwrap_or_default();
        let block = self.kinds.get(block_id).is_some_and(|k| k.value == "block");
        if block && self.soft() && self.is_box_output(block_id, &pin) {
            // The box writes it (`soft_block`).
            return Ok(());
        }
        if block && matches!(pin.as_str(), "ET" | "CV") {
            self.warnings.push(Located::new(
                n.line,
                ImportWarning::WordOutputDropped(pin, expr),
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
        self.output(input, element, pos, n.line);
        Ok(())
    }
}

impl Body {
    /// Reads vendor element `n` for the bit machines and the page: a
    /// network title is a comment at its place (its rung's, as a
    /// `<comment>` is), settings are nothing, an unknown element without
    /// wires or data is skipped with a warning, one carrying logic is
    /// refused at its line.
    pub(in crate::formats::plcopen) fn vendor_element(&mut self, n: &Node, vendor: &Vendor) {
        match vendor.clone() {
            Vendor::Title(text) => {
                let (row, col) = position(n);
                self.comments.push(CommentBox {
                    row,
                    col,
                    text,
                    line: n.line,
                });
            }
            Vendor::Cosmetic => {}
            Vendor::Unknown(what) => self.warnings.push(Located::new(
                n.line,
                ImportWarning::VendorSkipped(what.clone()),
            )),
            Vendor::Logic(why) => self
                .errors
                .push(Located::new(n.line, ImportError::VendorLogic(why))),
        }
    }
}

impl Body {
    /// Refuses a wire from output `pin` of block `id` when the block is a
    /// standard one without it (it made a point nothing drives: "no path
    /// joins the left rail"). Functions and others are left to their
    /// readers.
    fn has_output(&self, id: &str, pin: &str) -> Result<(), Connection> {
        let Some((ty, instance)) = self.block_names.get(id) else {
            return Ok(());
        };
        let has = crate::iec::pins::outputs(&ty.to_ascii_uppercase());
        let known =
            pin.eq_ignore_ascii_case("ENO") || has.iter().any(|(p, _)| p.eq_ignore_ascii_case(pin));
        if has.is_empty() || known || BlockKind::parse(ty).is_none() {
            return Ok(());
        }
        let list: Vec<&str> = has.iter().map(|(p, _)| *p).collect();
        Err(Connection::NoOutput {
            block: format!("{ty} block {instance}").trim_end().to_string(),
            pin: pin.to_string(),
            has: list.join(", "),
        })
    }
}

/// A block's type and instance as written (trimmed).
fn type_and_instance(n: &Node) -> (String, String) {
    let name = |a: &str| n.attr(a).unwrap_or_default().trim().to_string();
    (name("typeName"), name("instanceName"))
}
