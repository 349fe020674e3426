//! `CAL` resolved: of a standard block's instance (its parameters by
//! name, typed), or of an instance of the program's own blocks.

use super::check::find_pin;
use super::{CallWhy, LoadError, Named, Program, Src, Step, TypeWhy};
use crate::iec::data::{Data, DataType};
use crate::iec::il::{Line, Operand};
use crate::iec::pins::ldmicro::text_input;
use crate::iec::pins::{inputs, outputs};
use crate::runtime::instance::Printing;
use crate::runtime::ldmicro::format::Format;
use crate::runtime::ldmicro::printf::Printf;
use std::sync::Arc;

impl Program {
    /// `CAL instance(…)` resolved.
    pub(super) fn call(
        &mut self,
        line: &Line,
        cr: &mut Option<DataType>,
    ) -> Result<Step, LoadError> {
        if line.condition.is_some() && *cr != Some(DataType::Bool) {
            return Err(LoadError::NeedsBool("CALC"));
        }
        let Some(Operand::Name(name)) = &line.operand else {
            return Err(LoadError::Call(CallWhy::NeedsInstance));
        };
        let block = match self.by_name.get(&name.to_ascii_uppercase()) {
            Some(&Named::Block(block)) => block,
            Some(&Named::User(u)) => return self.call_user(line, u),
            _ => return Err(LoadError::NotAnInstance(name.clone())),
        };
        let kind = self.block_names[block].1.clone();
        let mut ins = Vec::new();
        for (pin, value) in &line.inputs {
            if text_input(&kind).is_some_and(|t| t.eq_ignore_ascii_case(pin)) {
                self.fix_text(block, &kind, pin, value)?;
                continue;
            }
            let (i, want) =
                find_pin(&inputs(&kind), pin).ok_or_else(|| no_pin(&kind, pin, false))?;
            ins.push((i, self.given(&kind, pin, value, want)?));
        }
        let mut outs = Vec::new();
        for (pin, target) in &line.outputs {
            let (i, t) = find_pin(&outputs(&kind), pin).ok_or_else(|| no_pin(&kind, pin, true))?;
            outs.push((i, self.taken(&kind, pin, target, t)?));
        }
        Ok(Step::Cal {
            when: line.condition,
            block,
            inputs: ins,
            outputs: outs,
        })
    }

    /// Instance `block`'s text input `pin := 'text'` (an LDmicro
    /// formatted string's), fixed at load: every call of the instance
    /// gives the same text, or none.
    fn fix_text(
        &mut self,
        block: usize,
        kind: &str,
        pin: &str,
        value: &Operand,
    ) -> Result<(), LoadError> {
        let Operand::Text(text) = value else {
            return Err(LoadError::Type(TypeWhy::TextInput {
                block: kind.to_string(),
                pin: pin.to_string(),
            }));
        };
        let pin_ = pin.to_string();
        let instance = &mut self.blocks[block];
        let before = if kind == "LD_STRING" {
            let printf = Printf::parse(text).map_err(|error| {
                LoadError::Call(CallWhy::Printf {
                    pin: pin_.clone(),
                    error,
                })
            })?;
            let before = instance
                .printing
                .as_ref()
                .map(|p| p.printf.text().to_string());
            instance
                .printing
                .get_or_insert_with(|| Box::new(Printing::new(printf)));
            before
        } else {
            let format = Format::parse(text).map_err(|error| {
                LoadError::Call(CallWhy::Format {
                    pin: pin_.clone(),
                    error,
                })
            })?;
            let before = instance.format.as_ref().map(|f| f.text().to_string());
            instance.format.get_or_insert_with(|| Arc::new(format));
            before
        };
        match before {
            Some(b) if b != *text => Err(LoadError::Call(CallWhy::TextTwice {
                instance: self.block_names[block].0.clone(),
                pin: pin_,
            })),
            _ => Ok(()),
        }
    }

    /// `CAL instance(input := value, output => variable)` of instance
    /// `u` of the program's own blocks.
    pub(super) fn call_user(&mut self, line: &Line, u: usize) -> Result<Step, LoadError> {
        let type_name = self.user_types[self.instances[u].ty].name.clone();
        let find = |list: &[(String, usize)], pin: &str| {
            list.iter()
                .find(|(n, _)| n.eq_ignore_ascii_case(pin))
                .map(|&(_, s)| s)
        };
        let mut inputs = Vec::new();
        for (pin, value) in &line.inputs {
            let slot = find(&self.instances[u].inputs, pin)
                .ok_or_else(|| no_pin(&type_name, pin, false))?;
            let want = self.values[slot].data_type();
            inputs.push((slot, self.given(&type_name, pin, value, want)?));
        }
        let mut outputs = Vec::new();
        for (pin, target) in &line.outputs {
            let from = find(&self.instances[u].outputs, pin)
                .ok_or_else(|| no_pin(&type_name, pin, true))?;
            let t = self.values[from].data_type();
            outputs.push((self.taken(&type_name, pin, target, t)?, from));
        }
        Ok(Step::CallUser {
            when: line.condition,
            instance: u,
            inputs,
            outputs,
        })
    }

    /// A call's input `pin := value` of block `owner`, which takes a
    /// `want` there: its slot or constant.
    fn given(
        &mut self,
        owner: &str,
        pin: &str,
        value: &Operand,
        want: DataType,
    ) -> Result<Src, LoadError> {
        let src = self.fitted(value, want, 0)?;
        if self.type_of(&src) != want {
            return Err(LoadError::Type(TypeWhy::Pin {
                block: owner.to_string(),
                pin: pin.to_string(),
                is: want,
            }));
        }
        Ok(src)
    }

    /// A call's output `pin => target` of block `owner`, which gives a
    /// `t` there: the target's slot.
    fn taken(
        &mut self,
        owner: &str,
        pin: &str,
        target: &str,
        t: DataType,
    ) -> Result<usize, LoadError> {
        let Src::Slot(slot) = self.slot(&Operand::Name(target.to_string()))? else {
            return Err(LoadError::Call(CallWhy::NotVariable(target.to_string())));
        };
        self.writable(slot, target)?;
        if self.values[slot].data_type() != t {
            return Err(LoadError::Type(TypeWhy::Pin {
                block: owner.to_string(),
                pin: pin.to_string(),
                is: t,
            }));
        }
        Ok(slot)
    }
}

impl Program {
    /// The digits the board draws: each variable an LDmicro segments
    /// block (`LD_SEG7` … `LD_SEG16`) writes, once, in program order,
    /// with its segments and whether the digit is common-anode (its `B`
    /// a constant other than 0).
    pub fn segment_displays(&self) -> Vec<crate::runtime::ldmicro::segments::Display> {
        let mut out: Vec<crate::runtime::ldmicro::segments::Display> = Vec::new();
        for step in &self.steps {
            let Step::Cal {
                block,
                inputs: ins,
                outputs: outs,
                ..
            } = step
            else {
                continue;
            };
            let kind = self.block_names[*block].1.as_str();
            let Some(segments) = kind.strip_prefix("LD_SEG").and_then(|n| n.parse().ok()) else {
                continue;
            };
            let (Some((d, _)), Some((b, _))) =
                (find_pin(&outputs(kind), "D"), find_pin(&inputs(kind), "B"))
            else {
                continue;
            };
            let Some(slot) = outs.iter().find(|(o, _)| *o == d).map(|(_, s)| *s) else {
                continue;
            };
            let Some((name, _)) = self.names.iter().find(|(_, s)| *s == slot) else {
                continue;
            };
            let anode = ins
                .iter()
                .any(|(i, src)| *i == b && matches!(src, Src::Const(Data::Int(_, v)) if *v != 0));
            if !out.iter().any(|d| d.name.eq_ignore_ascii_case(name)) {
                out.push(crate::runtime::ldmicro::segments::Display {
                    name: name.clone(),
                    segments,
                    anode,
                });
            }
        }
        out
    }
}

/// A block without parameter `pin` (an output when `output`).
fn no_pin(block: &str, pin: &str, output: bool) -> LoadError {
    LoadError::NoPin {
        block: block.to_string(),
        pin: pin.to_string(),
        output,
    }
}
