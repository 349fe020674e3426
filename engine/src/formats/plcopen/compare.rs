//! Comparison blocks (GT, GE, EQ, NE, LE, LT) on IO86A: each pair of
//! neighbouring inputs a `CMP` and the flag copied to a relay, the pairs
//! in series (issue #18, docs/ladder.md).

use super::body::{Body, Gate, GateKind};
use super::declare::Names;
use super::dom::Node;
use super::error::ImportError;
use super::kinds::BlockKind;
use super::parts::is_variable_name;
use crate::error::Located;
use crate::formats::plcopen::gate_why::{GateWhy, OperandWhy, COMPARED};
use crate::formats::plcopen::warning::ImportWarning;
use crate::iec::Comparison;
use crate::ladder::grid::Pos;

/// The blocks Hashigo has a ladder form for, and the comparisons
/// ([`compare_flag`]): checked before anything else about a block, so
/// that an unknown one is named as such, and listed in that message.
/// The flag IO86A's `CMP a b` leaves for a comparison block, and
/// whether the block is true when it is on (M60 a > b, M61 a = b, M62
/// a < b; GE is "not a < b").
pub(super) fn compare_flag(c: Comparison) -> (&'static str, bool) {
    match c {
        Comparison::Gt => ("M60", true),
        Comparison::Ge => ("M62", false),
        Comparison::Eq => ("M61", true),
        Comparison::Ne => ("M61", false),
        Comparison::Le => ("M60", false),
        Comparison::Lt => ("M62", true),
    }
}

impl Body {
    /// A comparison block (GT, GE, EQ, NE, LE, LT of words): its operands
    /// as IO86A's (`K465`, `D06`, `T00`), each neighbouring pair lowered to
    /// a `CMP` and a relay holding the flag (gates.rs). IEC extends all
    /// but NE to more inputs, each pair in turn (`GT(a, b, c)` is
    /// `a > b AND b > c`): the pairs' results meet in an AND.
    pub(super) fn compare(
        &mut self,
        n: &Node,
        id: &str,
        pos: Pos,
        flag: (&'static str, bool),
        ty: BlockKind,
        names: &Names,
    ) -> Result<(), ImportError> {
        let what = format!("{ty} block");
        let count = compare_pins(n, ty, &what)?;
        let operands = self.compare_operands(n, count, &what, names)?;
        let out = self.point(id, "OUT");
        let pairs = operands.len() - 1;
        let results: Vec<usize> = if pairs == 1 {
            vec![out]
        } else {
            (0..pairs).map(|_| self.fresh()).collect()
        };
        for (j, (pair, &result)) in operands.windows(2).zip(&results).enumerate() {
            self.gates.push(Gate {
                kind: GateKind::Compare {
                    a: pair[0].clone(),
                    b: pair[1].clone(),
                    flag: flag.0,
                    on: flag.1,
                },
                inputs: Vec::new(),
                out: result,
                // Each pair's CMP a place of its own (the order finds it by it).
                pos: Pos::new(pos.row + j, pos.col),
                line: n.line,
                what: what.clone(),
            });
        }
        if pairs > 1 {
            self.gates.push(Gate {
                kind: GateKind::And,
                inputs: results,
                out,
                pos,
                line: n.line,
                what,
            });
        }
        Ok(())
    }

    /// Each operand of a comparison as IO86A names it, saying where one is
    /// an analog input or a variable's declared value.
    fn compare_operands(
        &mut self,
        n: &Node,
        count: usize,
        what: &str,
        names: &Names,
    ) -> Result<Vec<String>, ImportError> {
        let mut operands = Vec::new();
        for pin in COMPARED.into_iter().take(count) {
            let expr = self.pin_literal(n, pin, what)?;
            let operand = self.word_operand(&expr, names).map_err(|why| {
                ImportError::Gate(what.to_string(), GateWhy::Operand(pin, expr.clone(), why))
            })?;
            if matches!(operand.0.as_str(), "D06" | "D07") && expr != operand.0 {
                let input = if operand.0 == "D06" { "X04" } else { "X05" };
                self.warnings.push(Located::new(
                    n.line,
                    ImportWarning::AnalogRange {
                        expr: expr.clone(),
                        register: operand.0.clone(),
                        input: input.to_string(),
                    },
                ));
            }
            if operand.1 {
                self.warnings.push(Located::new(
                    n.line,
                    ImportWarning::DeclaredValue {
                        what: what.to_string(),
                        pin,
                        register: operand.0.clone(),
                        expr: expr.clone(),
                    },
                ));
            }
            operands.push(operand.0);
        }
        Ok(operands)
    }

    /// A comparison's operand as IO86A names it, and whether it is a
    /// variable's declared value: a whole number `K…`; a variable mapped
    /// or located to a word (`D06`); else a variable's initial value.
    fn word_operand(&self, expr: &str, names: &Names) -> Result<(String, bool), OperandWhy> {
        let constant = |text: &str| -> Option<String> {
            // `INT#5`, `5`
            let digits = text.rsplit('#').next().unwrap_or(text).trim();
            digits
                .parse::<u16>()
                .ok()
                .filter(|&k| k <= 32767)
                .map(|k| format!("K{k}"))
        };
        if let Some(k) = constant(expr) {
            return Ok((k, false));
        }
        if !is_variable_name(expr) {
            return Err(OperandWhy::NotNumber);
        }
        if let Some(ty) = names.declared_type(expr).filter(|t| *t == "BOOL") {
            // IEC compares values of one type; CMP compares words.
            return Err(OperandWhy::Declared(ty.to_string()));
        }
        if let Ok(device) = names.device(expr) {
            if device.starts_with(['D', 'T', 'C']) && !device.contains('+') {
                return Ok((device, false));
            }
        }
        if let Some(k) = names.initial(expr).and_then(constant) {
            return Ok((k, true));
        }
        Err(OperandWhy::NoWord(expr.to_string()))
    }
}

/// How many operands a comparison block has: IN1, IN2, … in order (EN
/// aside); NE takes two, the others two or more.
fn compare_pins(n: &Node, ty: BlockKind, what: &str) -> Result<usize, ImportError> {
    let pins: Vec<&str> = n
        .child("inputVariables")
        .map(|v| {
            v.all("variable")
                .filter_map(|p| p.attr("formalParameter"))
                // EN is read with the body (`check_enable`).
                .filter(|p| *p != "EN")
                .collect()
        })
        .unwrap_or_default();
    let ne = ty == BlockKind::Compare(Comparison::Ne);
    if pins.len() < 2 || (ne && pins.len() != 2) {
        return Err(ImportError::Gate(
            what.to_string(),
            GateWhy::Inputs(pins.len(), ty.to_string(), ne),
        ));
    }
    if pins.len() > COMPARED.len() || pins.iter().zip(COMPARED).any(|(p, c)| *p != c) {
        return Err(ImportError::Gate(
            what.to_string(),
            GateWhy::InputsOrder(pins.join(", ")),
        ));
    }
    Ok(pins.len())
}
