//! The soft PLC's first look at a body (issue #31): which blocks are
//! boxes and which Boolean gates, and what each box's neighbours take
//! from it, noted before any element is read ([`super`]).

use super::boolean_input;
use crate::formats::plcopen::declare::Names;
use crate::formats::plcopen::dom::Node;
use crate::formats::plcopen::lower::body::{BlockOut, Body};
use crate::formats::plcopen::parts::negated;
use crate::ladder::block::BlockCall;

impl Body {
    /// Notes, in the first pass, what the soft PLC's boxes need of the
    /// elements around them: each block's type, the outVariables fed
    /// from a block's pin, and the block pins other elements take power
    /// from.
    pub(in crate::formats::plcopen) fn index_soft(&mut self, id: &str, n: &Node) {
        if n.name == "inVariable" && is_negated(n) {
            self.negated_variables.insert(id.to_string());
        }
        if n.name == "block" {
            let ty = n.attr("typeName").unwrap_or_default();
            self.block_types
                .insert(id.to_string(), ty.trim().to_ascii_uppercase());
        }
        if n.name == "block" {
            self.index_chains(id, n);
        }
        let mut conns = Vec::new();
        if n.name != "block" {
            n.descendants("connection", &mut conns);
        }
        for c in conns {
            let (Some(r), Some(pin)) = (c.attr("refLocalId"), c.attr("formalParameter")) else {
                continue;
            };
            let pin = pin.trim().to_ascii_uppercase();
            if n.name == "outVariable" {
                let variable = n
                    .child("expression")
                    .map(|e| e.text.trim().to_string())
                    .unwrap_or_default();
                self.block_outs.push(BlockOut {
                    block: r.to_string(),
                    pin,
                    variable,
                });
            } else {
                self.wired_pins.insert((r.to_string(), pin));
            }
        }
    }

    /// A block's input connections: from another block's pin into one of
    /// its data inputs, a chain ([`Body::chained`]); into its power or a
    /// block's Boolean input, power ([`Body::wired_pins`]).
    fn index_chains(&mut self, id: &str, n: &Node) {
        let kind = self.block_types.get(id).cloned().unwrap_or_default();
        let consumer = BlockCall {
            kind,
            instance: String::new(),
            inputs: Vec::new(),
            outputs: Vec::new(),
        };
        let pins = n
            .child("inputVariables")
            .map(|v| v.all("variable").collect::<Vec<_>>())
            .unwrap_or_default();
        for v in pins {
            let pin = v.attr("formalParameter").unwrap_or_default().trim();
            let data = !pin.eq_ignore_ascii_case(consumer.power_in())
                && !pin.eq_ignore_ascii_case("EN")
                && !boolean_input(&consumer, pin);
            let mut conns = Vec::new();
            v.descendants("connection", &mut conns);
            for c in conns {
                let (Some(r), Some(from)) = (c.attr("refLocalId"), c.attr("formalParameter"))
                else {
                    continue;
                };
                let key = (r.to_string(), from.trim().to_ascii_uppercase());
                if data {
                    self.chained.insert(key);
                } else {
                    self.wired_pins.insert(key);
                }
            }
        }
    }

    /// Whether the body is read for the soft PLC (its blocks are boxes).
    pub(in crate::formats::plcopen) fn soft(&self) -> bool {
        self.machine
            .is_some_and(|m| m.target().capabilities().word_boxes)
    }

    /// Whether block `n` of type `ty` (upper case) is a Boolean gate
    /// (AND, OR, XOR, NOT on power: lowered to contacts as on every
    /// machine) rather than a word function: no input of it reads a word
    /// variable or a number.
    pub(in crate::formats::plcopen) fn is_gate(&self, n: &Node, ty: &str, names: &Names) -> bool {
        if !matches!(ty, "AND" | "OR" | "XOR" | "NOT") {
            return false;
        }
        let mut conns = Vec::new();
        if let Some(inputs) = n.child("inputVariables") {
            inputs.descendants("connection", &mut conns);
        }
        conns.iter().all(|c| {
            let Some(text) = c
                .attr("refLocalId")
                .filter(|r| self.kinds.get(*r).is_some_and(|k| k.value == "inVariable"))
                .and_then(|r| self.literals.get(r))
            else {
                return true;
            };
            let text = text.value.trim();
            let word = names
                .declared_type(text)
                .is_some_and(|t| !t.eq_ignore_ascii_case("BOOL"));
            let bool_literal = ["TRUE", "FALSE", "BOOL#TRUE", "BOOL#FALSE"]
                .iter()
                .any(|b| b.eq_ignore_ascii_case(text));
            let literal = !crate::formats::plcopen::parts::is_variable_name(text);
            !word && (!literal || bool_literal)
        })
    }
}

/// Whether an inVariable is negated (a bad mark is refused where the
/// element is read).
fn is_negated(n: &Node) -> bool {
    negated(n).unwrap_or(false)
}
