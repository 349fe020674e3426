//! The soft PLC's boxes in IL (issue #30), with the same meaning the
//! reference evaluator gives them (`ladder::block`):
//!
//! ```text
//! comparison   LD a / GT b / AND power         (power out: it holds)
//! function     LD power / JMPCN skip / LD a / ADD b / ST out /
//!              skip: LD power                  (power out: EN)
//! block        CAL t(IN := power, PT := …, Q => q, ET => e) / LD q
//! ```
//!
//! The variables a ladder declares head the program; a block instance
//! used undeclared is declared with its box's kind.

use super::{Compiler, Pin};
use crate::iec::data::DataType;
use crate::iec::functions::{Function, Operand};
use crate::iec::pins::ldmicro::text_input;
use crate::iec::{literal_type, Address};
use crate::ladder::block::{BlockCall, Shape};
use crate::ladder::grid::{LadderError, Pos};
use crate::ladder::user_blocks as pins;
use crate::ladder::variables::Variable;

impl Compiler {
    /// Declares the ladder's variables; their problems (rung 1, as the
    /// ladder's own).
    pub(super) fn declare(&mut self, variables: &[Variable]) -> Vec<LadderError> {
        let mut errors = Vec::new();
        for v in variables {
            let upper = v.name.to_ascii_uppercase();
            let problem = v.check().err().map(|e| e.to_string()).or_else(|| {
                (self.types.contains_key(&upper) || self.blocks.contains_key(&upper))
                    .then(|| format!("{} is declared twice", v.name))
            });
            if let Some(why) = problem {
                errors.push(LadderError::rung(0, format!("variable {why}")));
                continue;
            }
            match v.elementary() {
                Some(t) => {
                    self.types.insert(upper.clone(), t);
                    if let Ok(a) = Address::parse(&v.address) {
                        self.types.insert(a.to_string(), t);
                    }
                }
                None => {
                    self.blocks
                        .insert(upper.clone(), v.data_type.trim().to_ascii_uppercase());
                }
            }
            self.taken.insert(upper);
            if v.retain {
                self.retained.push(v.declaration());
            } else {
                self.vars.push(v.declaration());
            }
        }
        errors
    }

    /// An operand of a box: its text as the IL writes it and its type.
    fn operand(&self, text: &str) -> Result<Operand, String> {
        let text = text.trim();
        if text.starts_with('%') {
            let a = Address::parse(text).map_err(|e| e.to_string())?;
            let ty = self
                .types
                .get(&a.to_string())
                .copied()
                .or_else(|| a.default_type())
                .ok_or_else(|| format!("{a}: the soft PLC has no byte type"))?;
            return Ok(Operand::temp(a.to_string(), ty));
        }
        if let Some(&t) = self.types.get(&text.to_ascii_uppercase()) {
            return Ok(Operand::temp(text.to_string(), t));
        }
        // A block instance's output read (`c0.CV`): the IL reads it so.
        if let Some((instance, pin)) = text.split_once('.') {
            let kind = self
                .blocks
                .get(&instance.to_ascii_uppercase())
                .ok_or_else(|| format!("`{instance}` is not a block instance: declare it"))?;
            let (_, t) = pins::outputs(kind)
                .into_iter()
                .find(|(p, _)| p.eq_ignore_ascii_case(pin))
                .ok_or_else(|| format!("{kind} has no output `{pin}`"))?;
            return Ok(Operand::temp(text.to_string(), t));
        }
        match literal_type(text) {
            Ok((_, ty)) => Ok(Operand {
                text: text.to_string(),
                ty,
                literal: true,
            }),
            Err(_) => Err(format!(
                "`{text}` is not declared: declare it with its type"
            )),
        }
    }

    /// Emits box `b` with the power `pin` at its left; its power out is
    /// then the current result.
    pub(super) fn block(&mut self, b: &BlockCall, pos: Pos, pin: Pin) -> Result<(), String> {
        let power = match pin {
            Pin::Rail => None,
            Pin::Current => {
                let p = self.fresh("_p", "BOOL");
                self.emit(format!("ST {p}"));
                Some(p)
            }
            Pin::Held(p) => Some(p),
        };
        let kind = b.kind();
        match b
            .shape()
            .ok_or_else(|| format!("{kind} is no box the soft PLC has"))?
        {
            Shape::FunctionBlock => return self.function_block(b, pos, power),
            Shape::Compare => {
                let (code, _) = self.function_code(b, &kind, None)?;
                self.lines.extend(code);
                if let Some(p) = &power {
                    self.emit(format!("AND {p}"));
                }
                self.sources
                    .push((self.rung_index, pos, self.lines.len() - 1));
                return Ok(());
            }
            Shape::Function(..) => {}
        }
        let wanted = b
            .outputs
            .first()
            .and_then(|(_, v)| self.operand(v).ok())
            .and_then(|o| o.ty);
        let (code, result) = self.function_code(b, &kind, wanted)?;
        let skip = self.fresh("_skip", "");
        if let Some(p) = &power {
            self.emit(format!("LD {p}"));
            self.emit(format!("JMPCN {skip}"));
        }
        self.lines.extend(code);
        for (_, variable) in &b.outputs {
            let v = self.operand(variable)?;
            if v.literal || v.ty != Some(result) {
                return Err(format!(
                    "{kind} gives {}: {variable} is {}",
                    result.name(),
                    v.ty.map_or("a literal", |t| t.name())
                ));
            }
            self.emit(format!("ST {}", v.text));
        }
        self.sources.push((self.rung_index, pos, self.lines.len()));
        match &power {
            Some(p) => self.emit(format!("{skip}: LD {p}")),
            None => self.emit("LD TRUE".into()),
        }
        Ok(())
    }

    /// A function's IL (its operands loaded and applied) and its type.
    fn function_code(
        &self,
        b: &BlockCall,
        kind: &str,
        wanted: Option<DataType>,
    ) -> Result<(Vec<String>, DataType), String> {
        let f = Function::named(kind).ok_or_else(|| format!("{kind} is no function here"))?;
        let mut args = Vec::new();
        for pin in b.data_pins() {
            let text = b
                .input(&pin)
                .ok_or_else(|| format!("{kind}'s {pin} is not wired"))?;
            args.push((pin, self.operand(text)?));
        }
        f.code(&args, wanted).map_err(|e| format!("{kind}: {e}"))
    }

    fn function_block(
        &mut self,
        b: &BlockCall,
        pos: Pos,
        power: Option<String>,
    ) -> Result<(), String> {
        let kind = b.kind();
        let upper = b.instance.to_ascii_uppercase();
        match self.blocks.get(&upper) {
            Some(k) if *k == kind => {}
            Some(k) => return Err(format!("{} is a {k}, not a {kind}", b.instance)),
            None => {
                self.vars.push(format!("{} : {kind};", b.instance));
                self.blocks.insert(upper.clone(), kind.clone());
                self.taken.insert(upper);
            }
        }
        // The power enters the block's power input; a block of the
        // project's own with no BOOL input runs only while powered (EN).
        let power_in = crate::ladder::block::block_power_in(&kind);
        let mut params = Vec::new();
        if let Some(pin) = power_in {
            params.push(format!("{pin} := {}", power.as_deref().unwrap_or("TRUE")));
        }
        for (pin, ty) in crate::ladder::block::block_data_inputs(&kind) {
            if let Some(text) = b.input(pin) {
                let o = self.operand(text)?.at(Some(ty));
                params.push(format!("{pin} := {}", o.text));
            }
        }
        // An LDmicro formatted string's text, as written ('…').
        if let Some(text) = text_input(&kind).and_then(|pin| Some((pin, b.input(pin)?))) {
            params.push(format!("{} := {}", text.0, text.1));
        }
        for (pin, variable) in &b.outputs {
            params.push(format!("{pin} => {}", variable.trim()));
        }
        let skip = match (power_in, &power) {
            (None, Some(p)) => {
                let skip = self.fresh("_skip", "");
                self.emit(format!("LD {p}"));
                self.emit(format!("JMPCN {skip}"));
                Some(skip)
            }
            _ => None,
        };
        let q = match crate::ladder::block::block_power_out(&kind) {
            Some(pin) => {
                let q = self.fresh("_q", "BOOL");
                params.push(format!("{pin} => {q}"));
                q
            }
            // No BOOL output: the power passes through (ENO).
            None => power.clone().unwrap_or_else(|| "TRUE".into()),
        };
        self.emit(format!("CAL {}({})", b.instance, params.join(", ")));
        self.sources.push((self.rung_index, pos, self.lines.len()));
        match skip {
            Some(skip) => self.emit(format!("{skip}: LD {q}")),
            None => self.emit(format!("LD {q}")),
        }
        Ok(())
    }
}
