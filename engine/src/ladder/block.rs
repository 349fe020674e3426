//! The soft PLC's functions and function blocks in a rung (issue #30):
//! a box with one power input and one power output, its other pins wired
//! to operands (a variable, an address, a literal).
//!
//! - A function (ADD, MOVE, SEL, INT_TO_DINT …) runs while power reaches
//!   its EN and passes the power on (ENO); while off it does not run and
//!   the variables its outputs write keep their values.
//! - A comparison (GT … LT) passes the power on while it holds (and may
//!   also write its result to a variable).
//! - A function block (TON, CTU, R_TRIG, SR …) takes the power at its
//!   first BOOL input (IN, CU, CD, CLK, S1, S) and gives out its first
//!   BOOL output (Q, QU, Q1); it runs every scan, its instance keeping
//!   its state.
//!
//! A box stands in a rung's condition ([`super::Element::Block`]) or at
//! its right end ([`super::Element::OutputBlock`], power out to nothing).

use std::fmt;

use serde::{Deserialize, Serialize};

use crate::iec::data::DataType;
use crate::iec::is_identifier;
use crate::iec::pins::ldmicro::text_input;
use crate::iec::{parse_literal, Address};
use crate::ladder::user_blocks as pins;

/// One box: what it calls and what its pins are wired to.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct BlockCall {
    /// The function or block type (`ADD`, `GT`, `TON`, `INT_TO_DINT`).
    pub kind: String,
    /// A function block's instance (`TON0`); empty for a function.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub instance: String,
    /// Input pins other than the power's, with their operands.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub inputs: Vec<(String, String)>,
    /// Output pins with the variables they write.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub outputs: Vec<(String, String)>,
}

/// What sort of box a kind is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// A function run while EN has power; its data inputs in order and
    /// whether it takes two or more of them (ADD IN1, IN2, IN3 …).
    Function(&'static [&'static str], bool),
    /// A comparison of IN1 and IN2.
    Compare,
    /// A standard function block.
    FunctionBlock,
}

impl Shape {
    /// What sort of box `kind` (upper-case) is; `None` for a kind the
    /// soft PLC lacks (neither standard nor one of the project's own
    /// blocks, [`super::user_blocks`]).
    pub fn of(kind: &str) -> Option<Shape> {
        Shape::builtin(kind).or_else(|| pins::is_user_block(kind).then_some(Shape::FunctionBlock))
    }

    /// [`Shape::of`] for the soft PLC's own functions and blocks only.
    pub fn builtin(kind: &str) -> Option<Shape> {
        if COMPARISONS.contains(&kind) {
            return Some(Shape::Compare);
        }
        if crate::iec::pins::is_block_type(kind) {
            return Some(Shape::FunctionBlock);
        }
        if let Some(&(_, pins, many)) = FUNCTIONS.iter().find(|(k, ..)| *k == kind) {
            return Some(Shape::Function(pins, many));
        }
        let (from, to) = kind.split_once("_TO_")?;
        (DataType::from_name(from).is_some() && DataType::from_name(to).is_some())
            .then_some(Shape::Function(&["IN"], false))
    }
}

/// The functions a box can call and their data inputs.
const FUNCTIONS: &[(&str, &[&str], bool)] = &[
    ("ADD", &["IN1", "IN2"], true),
    ("MUL", &["IN1", "IN2"], true),
    ("SUB", &["IN1", "IN2"], false),
    ("DIV", &["IN1", "IN2"], false),
    ("MOD", &["IN1", "IN2"], false),
    ("AND", &["IN1", "IN2"], true),
    ("OR", &["IN1", "IN2"], true),
    ("XOR", &["IN1", "IN2"], true),
    ("MAX", &["IN1", "IN2"], true),
    ("MIN", &["IN1", "IN2"], true),
    ("NOT", &["IN"], false),
    ("NEG", &["IN"], false),
    ("MOVE", &["IN"], false),
    ("SEL", &["G", "IN0", "IN1"], false),
    ("LIMIT", &["MN", "IN", "MX"], false),
    ("SHL", &["IN", "N"], false),
    ("SHR", &["IN", "N"], false),
    ("ROL", &["IN", "N"], false),
    ("ROR", &["IN", "N"], false),
];

/// The comparisons.
pub const COMPARISONS: [&str; 6] = ["GT", "GE", "EQ", "NE", "LE", "LT"];

impl BlockCall {
    /// The kind, upper-case.
    pub fn kind(&self) -> String {
        self.kind.trim().to_ascii_uppercase()
    }

    /// What sort of box it is; `None` for a kind the soft PLC lacks.
    pub fn shape(&self) -> Option<Shape> {
        Shape::of(&self.kind())
    }

    /// The pin the power enters: EN, or a block's first BOOL input.
    pub fn power_in(&self) -> &'static str {
        match self.shape() {
            Some(Shape::FunctionBlock) => block_power_in(&self.kind()).unwrap_or("EN"),
            _ => "EN",
        }
    }

    /// The pin the power leaves by: ENO, a comparison's OUT, a block's
    /// first BOOL output.
    pub fn power_out(&self) -> &'static str {
        match self.shape() {
            Some(Shape::FunctionBlock) => block_power_out(&self.kind()).unwrap_or("ENO"),
            Some(Shape::Compare) => "OUT",
            _ => "ENO",
        }
    }

    /// The operand of input `pin` (any case).
    pub fn input(&self, pin: &str) -> Option<&str> {
        self.inputs
            .iter()
            .find(|(p, _)| p.eq_ignore_ascii_case(pin))
            .map(|(_, o)| o.trim())
    }

    /// The data inputs in order: a function's IN1, IN2, … (as many as
    /// given, for one that takes more), a block's other inputs.
    pub fn data_pins(&self) -> Vec<String> {
        self.data_pins_for(self.inputs.len())
    }

    /// [`BlockCall::data_pins`] for a box given `given` inputs (what a
    /// function taking more than two makes of them).
    pub fn data_pins_for(&self, given: usize) -> Vec<String> {
        match self.shape() {
            Some(Shape::Function(pins, true)) => {
                let n = given.max(pins.len());
                (1..=n).map(|i| format!("IN{i}")).collect()
            }
            Some(Shape::Function(pins, false)) => pins.iter().map(|p| p.to_string()).collect(),
            Some(Shape::Compare) => vec!["IN1".into(), "IN2".into()],
            Some(Shape::FunctionBlock) => {
                let kind = self.kind();
                block_data_inputs(&kind)
                    .iter()
                    .map(|(p, _)| *p)
                    .chain(text_input(&kind))
                    .map(str::to_string)
                    .collect()
            }
            None => Vec::new(),
        }
    }

    /// Why the box is not one the soft PLC runs: an unknown kind, a
    /// missing or unknown pin, an operand that is no name, address or
    /// literal, a function block without an instance.
    pub fn check(&self) -> Result<(), BoxError> {
        let kind = self.kind();
        let shape = self
            .shape()
            .ok_or_else(|| BoxError::UnknownKind(kind.clone()))?;
        if shape == Shape::FunctionBlock {
            if !is_identifier(&self.instance) {
                return Err(BoxError::NoInstance(kind));
            }
        } else if !self.instance.is_empty() {
            return Err(BoxError::FunctionInstance(kind));
        }
        let pins = self.data_pins();
        for (pin, operand) in &self.inputs {
            if !pins.iter().any(|p| p.eq_ignore_ascii_case(pin)) {
                let takes = pins.join(", ");
                return Err(BoxError::NoSuchInput(kind, pin.clone(), takes));
            }
            if text_input(&kind).is_some_and(|t| t.eq_ignore_ascii_case(pin)) {
                // An LDmicro formatted string's text: '…'.
                crate::iec::literal::parse_text(operand.trim())
                    .map_err(|_| BoxError::BadOperand(operand.clone()))?;
            } else if !is_variable(operand)
                && !is_block_output(operand)
                && parse_literal(operand, None).is_err()
            {
                return Err(BoxError::BadOperand(operand.clone()));
            }
        }
        // A block's inputs may be left to keep their values; a
        // function's may not.
        if shape != Shape::FunctionBlock {
            if let Some(missing) = pins.iter().find(|p| self.input(p).is_none()) {
                return Err(BoxError::NotWired(kind, missing.clone()));
            }
        }
        for (pin, variable) in &self.outputs {
            let known = match shape {
                Shape::FunctionBlock => pins::outputs(&kind)
                    .iter()
                    .any(|(p, _)| p.eq_ignore_ascii_case(pin)),
                _ => pin.eq_ignore_ascii_case("OUT"),
            };
            if !known {
                return Err(BoxError::NoSuchOutput(kind, pin.clone()));
            }
            if !is_variable(variable) {
                return Err(BoxError::NotAVariable(kind, pin.clone(), variable.clone()));
            }
        }
        Ok(())
    }
}

impl BlockCall {
    /// The box as a cell shows it, short: the kind, then its operands in
    /// their pins' order, `→` before what it writes (`ADD a 1 → c`,
    /// `GT level 100`, `c0: CTU reset 10 → parts`).
    pub fn label(&self) -> String {
        let mut words = Vec::new();
        if !self.instance.is_empty() {
            words.push(format!("{}:", self.instance));
        }
        words.push(self.kind());
        for pin in self.data_pins() {
            let operand = self.input(&pin).unwrap_or("·");
            // INT is what an integer is taken as: its prefix says nothing.
            let shown = operand
                .strip_prefix("INT#")
                .filter(|n| !n.is_empty())
                .unwrap_or(operand);
            words.push(shown.to_string());
        }
        for (i, (_, v)) in self.outputs.iter().enumerate() {
            if i == 0 {
                words.push("→".into());
            }
            words.push(v.trim().to_string());
        }
        words.join(" ")
    }

    /// What the live view shows on the box while the machine runs: each
    /// variable it reads or writes, and a timer's elapsed time (`ET`) or a
    /// counter's count (`CV`): (label, the device to read).
    pub fn watched(&self) -> Vec<(String, String)> {
        let mut out: Vec<(String, String)> = Vec::new();
        let mut add = |label: String, device: String| {
            if !out.iter().any(|(_, d)| d.eq_ignore_ascii_case(&device)) {
                out.push((label, device));
            }
        };
        let kind = self.kind();
        let instance = self.instance.trim();
        if pins::is_user_block(&kind) {
            // The project's own block: each output, as its instance holds it.
            for (pin, _) in pins::outputs(&kind) {
                add(pin.to_string(), format!("{instance}.{pin}"));
            }
        } else if self.shape() == Some(Shape::FunctionBlock) {
            let v = pins::outputs(&kind)
                .iter()
                .find(|(p, _)| *p == "ET" || *p == "CV")
                .map(|(p, _)| *p);
            if let Some(pin) = v {
                add(pin.to_string(), format!("{instance}.v"));
            }
        }
        let operands = self.inputs.iter().chain(self.outputs.iter());
        for (_, o) in operands.filter(|(_, o)| is_variable(o)) {
            add(o.trim().to_string(), o.trim().to_string());
        }
        out
    }
}

/// The input the power enters block `kind` (upper-case) by: a standard
/// block's first, the project's own block's first BOOL one; `None` when
/// it has none (the power is its EN: it runs while powered).
pub fn block_power_in(kind: &str) -> Option<&'static str> {
    first_power(&pins::inputs(kind), kind)
}

/// The output the power leaves block `kind` by: a standard block's
/// first, the project's own block's first BOOL one; `None` when it has
/// none (the power passes through, as ENO).
pub fn block_power_out(kind: &str) -> Option<&'static str> {
    first_power(&pins::outputs(kind), kind)
}

/// Block `kind`'s inputs but the one the power enters by, in order.
pub fn block_data_inputs(kind: &str) -> Vec<(&'static str, DataType)> {
    let power = block_power_in(kind);
    let mut all = pins::inputs(kind);
    if let Some(i) = all.iter().position(|(p, _)| Some(*p) == power) {
        all.remove(i);
    }
    all
}

fn first_power(pins: &[(&'static str, DataType)], kind: &str) -> Option<&'static str> {
    if crate::iec::pins::is_block_type(kind) {
        return pins.first().map(|(p, _)| *p);
    }
    pins.iter()
        .find(|(_, t)| *t == DataType::Bool)
        .map(|(p, _)| *p)
}

/// Whether `text` reads a block instance's output (`c0.CV`, `t0.Q`): an
/// operand, never a box's output.
pub fn is_block_output(text: &str) -> bool {
    text.trim()
        .split_once('.')
        .is_some_and(|(instance, pin)| is_identifier(instance) && is_identifier(pin))
}

/// Whether `text` names a variable or a located address.
pub fn is_variable(text: &str) -> bool {
    let text = text.trim();
    if text.starts_with('%') {
        return Address::parse(text).is_ok();
    }
    is_identifier(text) && !text.eq_ignore_ascii_case("TRUE") && !text.eq_ignore_ascii_case("FALSE")
}

/// Why a box is not one the soft PLC runs.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum BoxError {
    /// No function or block of that kind.
    UnknownKind(String),
    /// A function block without an instance name.
    NoInstance(String),
    /// A function given an instance.
    FunctionInstance(String),
    /// An input the kind does not have (kind, pin, the pins it takes).
    NoSuchInput(String, String, String),
    /// An operand that is no variable, address or literal.
    BadOperand(String),
    /// A function's input left unwired (kind, pin).
    NotWired(String, String),
    /// An output the kind does not have (kind, pin).
    NoSuchOutput(String, String),
    /// An output wired to something that is no variable (kind, pin, text).
    NotAVariable(String, String, String),
}

impl fmt::Display for BoxError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BoxError::UnknownKind(k) => {
                write!(f, "{k} is not a function or block the soft PLC has")
            }
            BoxError::NoInstance(k) => write!(f, "a {k} box needs an instance name (TON0)"),
            BoxError::FunctionInstance(k) => write!(f, "{k} is a function: it has no instance"),
            BoxError::NoSuchInput(k, pin, takes) => {
                write!(f, "{k} has no input {pin} (it takes {takes})")
            }
            BoxError::BadOperand(t) => {
                write!(f, "`{t}` is not a variable, an address or a literal")
            }
            BoxError::NotWired(k, pin) => write!(f, "{k}'s {pin} is not wired"),
            BoxError::NoSuchOutput(k, pin) => write!(f, "{k} has no output {pin}"),
            BoxError::NotAVariable(k, pin, t) => {
                write!(f, "{k}'s {pin} writes {t:?}: a variable or an address")
            }
        }
    }
}

impl std::error::Error for BoxError {}

impl fmt::Display for BlockCall {
    /// `ADD(IN1 := a, IN2 := 1, OUT => b)`, a block's instance first
    /// (`TON0: TON(PT := T#1s)`).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if !self.instance.is_empty() {
            write!(f, "{}: ", self.instance)?;
        }
        let params: Vec<String> = self
            .inputs
            .iter()
            .map(|(p, o)| format!("{p} := {o}"))
            .chain(self.outputs.iter().map(|(p, v)| format!("{p} => {v}")))
            .collect();
        write!(f, "{}({})", self.kind(), params.join(", "))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn call(
        kind: &str,
        instance: &str,
        inputs: &[(&str, &str)],
        outputs: &[(&str, &str)],
    ) -> BlockCall {
        let pairs = |l: &[(&str, &str)]| {
            l.iter()
                .map(|(a, b)| (a.to_string(), b.to_string()))
                .collect()
        };
        BlockCall {
            kind: kind.into(),
            instance: instance.into(),
            inputs: pairs(inputs),
            outputs: pairs(outputs),
        }
    }

    #[test]
    fn a_box_shows_its_operands_short_and_watches_its_variables() {
        let add = call("add", "", &[("IN1", "a"), ("IN2", "1")], &[("OUT", "c")]);
        assert_eq!(add.label(), "ADD a 1 → c");
        assert_eq!(
            add.watched(),
            [("a".to_string(), "a".to_string()), ("c".into(), "c".into())],
            "the literal is not watched"
        );
        let ctu = call("CTU", "c0", &[("PV", "INT#10")], &[("CV", "parts")]);
        assert_eq!(
            ctu.label(),
            "c0: CTU · 10 → parts",
            "R left unwired, INT# not said"
        );
        assert_eq!(ctu.watched()[0], ("CV".to_string(), "c0.v".to_string()));
        let ton = call("TON", "t0", &[("PT", "T#2s")], &[]);
        assert_eq!(ton.watched(), [("ET".to_string(), "t0.v".to_string())]);
        let gt = call("GT", "", &[("IN1", "%IW0"), ("IN2", "%IW0")], &[]);
        assert_eq!(
            gt.watched().len(),
            1,
            "one operand read twice is shown once"
        );
    }
}
