//! A project's blocks drawn as the soft PLC's boxes (issue #31): when the
//! ladder reader reads for the soft PLC, a block is a [`BlockCall`] with
//! its instance, its data inputs as operands (the variables and literals
//! wired to them), its data outputs as the variables they write, and a
//! function block's other Boolean inputs fed from contacts as networks of
//! their own ([`crate::ladder::net::Side`], joined to the box by
//! [`crate::ladder::net::attach_sides`]).
//!
//! - The power enters where the soft PLC's box takes it: a function's or
//!   comparison's EN (open: always runs, as IEC has it), a block's first
//!   Boolean input (IN, CU, CLK, S1).
//! - It leaves at a function's ENO, a comparison's OUT (a comparison's
//!   ENO carries its EN), a block's first Boolean output (Q, QU, Q1); a
//!   block's other Boolean outputs wired on written to BOOLs of their
//!   own (`_c0_QD`) and read by contacts.
//! - A data pin wired straight to another block's output has no operand
//!   to draw: refused at the block, asking for a variable between them.
//!
//! The folder is the soft PLC's ladder drawn from a PLCopen project:
//! [`index`] (a body's first look), this file (blocks as boxes),
//! [`rungs`] (boxes placed in rungs) and [`variables`] (the
//! declarations as the ladder's variables).

mod index;
pub(super) mod rungs;
pub(super) mod variables;

use super::declare::Names;
use super::dom::Node;
use super::error::ImportError;
use super::lower::blocks::pin_of;
use super::lower::body::{Body, Temp, RAIL};
use super::parts::SPLIT_PLACES;
use crate::iec::data::DataType;
use crate::iec::pins;
use crate::ladder::block::{BlockCall, Shape};
use crate::ladder::element::Element;
use crate::ladder::grid::Pos;
use crate::ladder::net::{carrier, Net};

/// Why a block cannot be drawn as a soft PLC box.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum BoxProblem {
    /// The box itself is not one the soft PLC runs.
    Box(crate::ladder::block::BoxError),
    /// A data input wired from another element's output (the pin).
    FedByElement(String),
    /// A data output wired to a contact or coil (the pin).
    OutputToPower(String),
    /// A negated variable on a data input (the pin).
    NegatedOperand(String),
    /// A block whose EN is wired: the soft PLC's block boxes always run.
    EnableWired,
}

impl std::fmt::Display for BoxProblem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            BoxProblem::Box(e) => e.fmt(f),
            BoxProblem::FedByElement(pin) => write!(
                f,
                "its {pin} input is wired straight from another element: the page draws a box's data inputs as operands, so put a variable between them (an outVariable and an inVariable)"
            ),
            BoxProblem::OutputToPower(pin) => write!(
                f,
                "its {pin} output feeds a contact or coil: write it to a variable (an outVariable) and read that"
            ),
            BoxProblem::NegatedOperand(pin) => write!(
                f,
                "the variable on its {pin} input is negated: put a NOT block on it instead"
            ),
            BoxProblem::EnableWired => f.write_str(
                "its EN is wired: the soft PLC's blocks run every scan; connect EN to the left rail or leave it open",
            ),
        }
    }
}

impl Body {
    /// The box block `block_id` is, if the body is read for the soft PLC
    /// and the block is one of its boxes: its call (no pins wired).
    fn soft_call(&self, block_id: &str) -> Option<BlockCall> {
        let kind = self.block_types.get(block_id)?;
        Shape::of(kind)?;
        Some(BlockCall {
            kind: kind.clone(),
            instance: String::new(),
            inputs: Vec::new(),
            outputs: Vec::new(),
        })
    }

    /// Whether an outVariable fed from `block_id`'s `pin` is one of the
    /// box's data outputs (taken by the box) rather than its power.
    pub(super) fn is_box_output(&self, block_id: &str, pin: &str) -> bool {
        self.soft_call(block_id)
            .is_some_and(|call| !is_power_out(&call, pin))
    }

    /// Block `n` (`localId` `id`, of `kind`, upper case) as a soft PLC box
    /// between the point its power comes from and its power out.
    pub(super) fn soft_block(
        &mut self,
        n: &Node,
        id: &str,
        pos: Pos,
        (kind, names): (&str, &Names),
    ) -> Result<(), ImportError> {
        let shape = Shape::of(kind).ok_or_else(|| {
            let unknown = crate::ladder::block::BoxError::UnknownKind(kind.into());
            ImportError::SoftBox(format!("block {kind}"), BoxProblem::Box(unknown))
        })?;
        let block = shape == Shape::FunctionBlock;
        let instance = n.attr("instanceName").unwrap_or_default().trim();
        let what = format!("{kind} block {instance}").trim().to_string();
        let fail = |p| ImportError::SoftBox(what.clone(), p);
        let mut call = BlockCall {
            kind: kind.to_string(),
            instance: if block {
                instance.into()
            } else {
                String::new()
            },
            inputs: Vec::new(),
            outputs: Vec::new(),
        };
        let power_in = call.power_in();
        if block && !self.always_runs(id) {
            return Err(fail(BoxProblem::EnableWired));
        }
        let input = match pin_of(n, power_in)
            .and_then(|v| v.child("connectionPointIn"))
            .filter(|c| c.child("connection").is_some())
        {
            Some(c) => self.join(Some(c), &what)?,
            // An open EN: the function always runs.
            None if power_in == "EN" => RAIL,
            None => return Err(ImportError::PinNotConnected(what, power_in)),
        };
        self.consumed.push(input);
        self.read_inputs(n, &mut call, pos, names)?;
        self.read_outputs(id, &mut call, names);
        self.read_other_outputs(id, &mut call, pos, n.line)?;
        // A comparison's third input and on are checked pair by pair.
        let first_two = BlockCall {
            inputs: call.inputs.iter().take(2).cloned().collect(),
            ..call.clone()
        };
        let checked = if shape == Shape::Compare {
            &first_two
        } else {
            &call
        };
        checked.check().map_err(|e| fail(BoxProblem::Box(e)))?;
        let out = self.point(id, call.power_out());
        if shape == Shape::Compare {
            // A comparison's ENO is its EN.
            let eno = self.point(id, "ENO");
            self.union(input, eno);
            if call.inputs.len() > 2 {
                return self.compare_chain(call, (input, out), pos, n.line);
            }
        }
        let element = as_timer(&call)
            .or_else(|| as_edge(&call))
            .unwrap_or(Element::Block(call));
        self.wire(input, out, Net::Leaf(element, pos), n.line);
        Ok(())
    }

    /// The box's data inputs (all but its power's) as operands.
    fn read_inputs(
        &mut self,
        n: &Node,
        call: &mut BlockCall,
        pos: Pos,
        names: &Names,
    ) -> Result<(), ImportError> {
        let power_in = call.power_in();
        let pins: Vec<&Node> = n
            .child("inputVariables")
            .map(|v| v.all("variable").collect())
            .unwrap_or_default();
        for (k, v) in pins.into_iter().enumerate() {
            let pin = v.attr("formalParameter").unwrap_or_default().trim();
            if pin.eq_ignore_ascii_case(power_in) || pin.eq_ignore_ascii_case("EN") {
                continue;
            }
            let below = Pos::new(pos.row + 1 + k, pos.col);
            if let Some(operand) = self.operand(v, call, pin, below, n.line)? {
                // A name Hashigo's export gave an address reads as it.
                let operand = names.device(&operand).unwrap_or(operand);
                call.inputs.push((pin.to_ascii_uppercase(), operand));
            }
        }
        Ok(())
    }

    /// The box's data outputs: the outVariables they feed, and a variable
    /// of their own for each another box's input reads ([`Temp`]).
    fn read_outputs(&mut self, id: &str, call: &mut BlockCall, names: &Names) {
        for out in self.block_outs.iter().filter(|o| o.block == id) {
            if !is_power_out(call, &out.pin) {
                let variable = names.device(&out.variable).unwrap_or(out.variable.clone());
                call.outputs.push((out.pin.clone(), variable));
            }
        }
        let mut chains: Vec<String> = self
            .chained
            .iter()
            .filter(|(b, p)| b == id && p != "ENO")
            .map(|(_, p)| p.clone())
            .collect();
        chains.sort();
        for pin in chains {
            let name = self.temp_name(id, &pin);
            self.temps.push(Temp {
                name: name.clone(),
                kind: call.kind(),
                pin: pin.clone(),
                inputs: call.inputs.clone(),
            });
            call.outputs.push((pin, name));
        }
    }

    /// A comparison of more than two inputs (`EQ(a, b, c)`: a = b AND
    /// b = c, as IEC has it) as two-input boxes in series, each on the
    /// next pair; one that also writes its result is refused (a box in
    /// the series does not run while an earlier one fails).
    fn compare_chain(
        &mut self,
        call: BlockCall,
        (input, out): (usize, usize),
        pos: Pos,
        line: usize,
    ) -> Result<(), ImportError> {
        if let Some((pin, _)) = call.outputs.first() {
            let what = format!("{} block", call.kind);
            return Err(ImportError::SoftBox(
                what,
                BoxProblem::OutputToPower(pin.clone()),
            ));
        }
        let operands: Vec<String> = call.inputs.iter().map(|(_, o)| o.clone()).collect();
        let mut from = input;
        for (k, pair) in operands.windows(2).enumerate() {
            let to = if k + 2 == operands.len() {
                out
            } else {
                self.fresh()
            };
            let pair_call = BlockCall {
                inputs: vec![
                    ("IN1".into(), pair[0].clone()),
                    ("IN2".into(), pair[1].clone()),
                ],
                ..call.clone()
            };
            let at = Pos::new(pos.row, pos.col.wrapping_add(k));
            self.wire(from, to, Net::Leaf(Element::Block(pair_call), at), line);
            // The next box takes its power from here.
            self.consumed.push(to);
            from = to;
        }
        Ok(())
    }

    /// Whether block `id`'s EN always carries power (open, the rail, TRUE).
    fn always_runs(&self, id: &str) -> bool {
        let refs = self.enables.get(id).map_or(&[][..], Vec::as_slice);
        self.always_enabled(refs, 0)
    }

    /// The operand of data pin `pin` (input variable `v`): the variable
    /// or literal wired to it, `TRUE` from the rail, or (a block's
    /// Boolean input fed from contacts) the BOOL its network is computed
    /// into; `None` when open.
    fn operand(
        &mut self,
        v: &Node,
        call: &BlockCall,
        pin: &str,
        below: Pos,
        line: usize,
    ) -> Result<Option<String>, ImportError> {
        let what = format!("{} block {}", call.kind, call.instance)
            .trim()
            .to_string();
        let Some(cpi) = v
            .child("connectionPointIn")
            .filter(|c| c.child("connection").is_some())
        else {
            return Ok(None);
        };
        let from = cpi
            .child("connection")
            .and_then(|c| c.attr("refLocalId"))
            .unwrap_or_default()
            .to_string();
        let single = cpi.all("connection").count() == 1;
        if single && self.rails.contains(&from) {
            return Ok(Some("TRUE".into()));
        }
        if single
            && self
                .kinds
                .get(&from)
                .is_some_and(|k| k.value == "inVariable")
        {
            if self.negated_variables.contains(&from) {
                return Err(ImportError::SoftBox(
                    what,
                    BoxProblem::NegatedOperand(pin.into()),
                ));
            }
            let text = self.literals.get(&from).map(|l| l.value.trim().to_string());
            return Ok(text);
        }
        let pin_from = cpi
            .child("connection")
            .and_then(|c| c.attr("formalParameter"))
            .unwrap_or_default()
            .trim()
            .to_ascii_uppercase();
        let from_box = self.soft_call(&from).is_some();
        if single && from_box && pin_from != "ENO" && !boolean_input(call, pin) {
            // Another box's output: the variable it is written to.
            return Ok(Some(self.temp_name(&from, &pin_from)));
        }
        if !boolean_input(call, pin) {
            return Err(ImportError::SoftBox(
                what,
                BoxProblem::FedByElement(pin.into()),
            ));
        }
        // Contacts feeding a block's R, LD, R1 …: a network of its own
        // into a BOOL the box reads, drawn below it.
        let p = self.join(Some(cpi), &what)?;
        self.consumed.push(p);
        let variable = carrier(&call.instance, pin);
        self.output(p, Element::coil(&variable), below, line);
        Ok(Some(variable))
    }

    /// A block's Boolean outputs other than its power out that contacts
    /// or coils take power from: the box writes each to a BOOL of its own
    /// (`_c0_QD`), read by a contact from the rail where the pin fed; a
    /// function's data output there is refused.
    fn read_other_outputs(
        &mut self,
        id: &str,
        call: &mut BlockCall,
        pos: Pos,
        line: usize,
    ) -> Result<(), ImportError> {
        let wired: Vec<String> = self
            .wired_pins
            .iter()
            .filter(|(b, p)| b == id && !is_power_out(call, p) && p != "ENO")
            .map(|(_, p)| p.clone())
            .collect();
        for pin in wired {
            let boolean = pins::outputs(&call.kind())
                .iter()
                .any(|(p, t)| p.eq_ignore_ascii_case(&pin) && *t == DataType::Bool);
            if call.shape() != Some(Shape::FunctionBlock) || !boolean {
                let what = call.kind.clone();
                return Err(ImportError::SoftBox(what, BoxProblem::OutputToPower(pin)));
            }
            let variable = carrier(&call.instance, &pin);
            call.outputs.push((pin.clone(), variable.clone()));
            let contact = Element::no(&variable);
            let at = Pos::new(pos.row, pos.col.wrapping_add(SPLIT_PLACES));
            let to = self.point(id, &pin);
            self.consumed.push(RAIL);
            self.wire(RAIL, to, Net::Leaf(contact, at), line);
        }
        Ok(())
    }
}

/// Whether `pin` is a function block's Boolean input other than its
/// power's (CTU's R, SR's R1): one a contact network may feed.
pub(super) fn boolean_input(call: &BlockCall, pin: &str) -> bool {
    call.shape() == Some(Shape::FunctionBlock)
        && pins::inputs(&call.kind())
            .iter()
            .skip(1)
            .any(|(p, t)| p.eq_ignore_ascii_case(pin) && *t == DataType::Bool)
}

/// A TON, TOF or TP box given only a literal PT and writing nothing:
/// the in-line timer the soft PLC's editor draws for it.
fn as_timer(call: &BlockCall) -> Option<Element> {
    use crate::ladder::element::TimerKind;
    let kind = match call.kind().as_str() {
        "TON" => TimerKind::Ton,
        "TOF" => TimerKind::Tof,
        "TP" => TimerKind::Tp,
        _ => return None,
    };
    let [(pin, pt)] = call.inputs.as_slice() else {
        return None;
    };
    let preset_ms = crate::iec::literal::parse_time_literal(pt).filter(|_| pin == "PT")?;
    (call.outputs.is_empty() && preset_ms > 0).then(|| Element::Timer {
        kind,
        name: call.instance.clone(),
        preset_ms,
    })
}

/// An R_TRIG or F_TRIG box on the power alone, its instance named as an
/// export names it (`R_TRIG3`): the in-line edge the editor draws for
/// it (a project's own instance keeps its box).
fn as_edge(call: &BlockCall) -> Option<Element> {
    let falling = match call.kind().as_str() {
        "R_TRIG" => false,
        "F_TRIG" => true,
        _ => return None,
    };
    let generated = call
        .instance
        .strip_prefix(if falling { "F_TRIG" } else { "R_TRIG" })
        .is_some_and(|n| !n.is_empty() && n.chars().all(|c| c.is_ascii_digit()));
    (generated && call.inputs.is_empty() && call.outputs.is_empty())
        .then_some(Element::Edge { falling })
}

/// An element standing at the end of its rung: a box as an output box.
pub(super) fn as_output(e: &Element) -> Element {
    match e {
        Element::Block(b) => Element::OutputBlock(b.clone()),
        other => other.clone(),
    }
}

/// Whether `pin` is where the box's power leaves (a function's ENO
/// too, and a comparison's).
fn is_power_out(call: &BlockCall, pin: &str) -> bool {
    pin.eq_ignore_ascii_case(call.power_out()) || pin.eq_ignore_ascii_case("ENO")
}

impl Body {
    /// The variable made to carry block `id`'s output `pin` into another
    /// box (`_MUL3_OUT`): an IEC name whatever the file's ids are.
    fn temp_name(&self, id: &str, pin: &str) -> String {
        let kind = self.block_types.get(id).map_or("", String::as_str);
        let clean = |s: &str| -> String {
            s.chars()
                .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
                .collect()
        };
        format!("_{}{}_{}", clean(kind), clean(id), clean(pin))
    }
}
