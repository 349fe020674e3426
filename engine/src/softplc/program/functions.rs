//! An IL function line resolved (`SHL`, `MIN`, `SEL`, `INT_TO_DINT` …):
//! its operands joined with the current result's type (untyped literals
//! taking it), the type it leaves checked.

use super::check::need_cr;
use super::flex::Flow;
use super::{LoadError, Program, Step, TypeWhy};
use crate::iec::data::DataType;
use crate::iec::il::{Function, Line, Operand};

impl Program {
    /// A function call: its operands resolved and joined, the type it
    /// leaves checked.
    pub(super) fn function(
        &mut self,
        f: Function,
        line: &Line,
        flow: &mut Flow,
    ) -> Result<Step, LoadError> {
        let t = need_cr(flow.cr)?;
        let mut args = Vec::new();
        for a in &line.args {
            args.push(self.slot(a)?);
        }
        let placed: Vec<(Option<usize>, &Operand)> = line
            .args
            .iter()
            .enumerate()
            .map(|(i, a)| (Some(i), a))
            .collect();
        let wrong = |why: TypeWhy| Err(LoadError::Type(why));
        match f {
            Function::Neg if matches!(t, DataType::Bool | DataType::String) => {
                return wrong(TypeWhy::NegNumber)
            }
            // The result is the current result's type: its untyped
            // literals stay untyped.
            Function::Neg | Function::Move => {}
            Function::Shl | Function::Shr | Function::Rol | Function::Ror => {
                if t.bits().is_none() || self.type_of(&args[0]).bits().is_none() {
                    return wrong(TypeWhy::ShiftIntegers);
                }
            }
            Function::Min | Function::Max | Function::Limit => {
                let t = self.join(flow, line, &placed, &mut args)?;
                for a in &args {
                    if self.type_of(a) != t {
                        return Err(LoadError::Mix(t, self.type_of(a)));
                    }
                }
            }
            Function::Sel => self.select(flow, line, &placed, &mut args)?,
            Function::Mux => self.mux(flow, line, &placed, &mut args)?,
            Function::Abs | Function::Sqrt | Function::Trunc | Function::Expt => {
                self.numeric(f, flow, &mut args)?
            }
            Function::Convert { from, to } => {
                if from == DataType::String || to == DataType::String {
                    return wrong(TypeWhy::StringConversion);
                }
                self.settle(flow, from);
                let t = need_cr(flow.cr)?;
                if from != t {
                    return wrong(TypeWhy::Convert { current: t, from });
                }
                flow.flex.clear();
                flow.cr = Some(to);
            }
        }
        Ok(Step::Func(f, args))
    }

    /// ABS (an integer or a REAL, which it leaves), SQRT (a REAL), TRUNC
    /// (a REAL, leaving a DINT), EXPT (a REAL, to a REAL or integer
    /// power, leaving a REAL); untyped literals taken as the function
    /// needs. Another type: "this operation does not apply to INT".
    fn numeric(
        &mut self,
        f: Function,
        flow: &mut Flow,
        args: &mut [super::Src],
    ) -> Result<(), LoadError> {
        if f != Function::Abs {
            self.settle(flow, DataType::Real);
        }
        let t = need_cr(flow.cr)?;
        let real = matches!(t, DataType::Real | DataType::Lreal);
        let fits = match f {
            Function::Abs => t.bits().is_some() || real,
            _ => real,
        };
        if !fits {
            return Err(LoadError::NotFor(t));
        }
        if let (Function::Expt, Some(power)) = (f, args.first_mut()) {
            let p = self.type_of(power);
            if p.bits().is_none() && !matches!(p, DataType::Real | DataType::Lreal) {
                return Err(LoadError::NotFor(p));
            }
        }
        if f == Function::Trunc {
            flow.flex.clear();
            flow.cr = Some(DataType::Dint);
        }
        Ok(())
    }

    /// MUX: the current result (K) an integer, its inputs of one type
    /// (untyped literals joined between them), which it leaves.
    fn mux(
        &mut self,
        flow: &mut Flow,
        line: &Line,
        placed: &[(Option<usize>, &Operand)],
        args: &mut [super::Src],
    ) -> Result<(), LoadError> {
        self.settle(flow, DataType::Dint);
        let k = need_cr(flow.cr)?;
        if k.bits().is_none() {
            return Err(LoadError::NotFor(k));
        }
        let mut own = Flow::default();
        let t = self.join(&mut own, line, placed, args)?;
        flow.late.append(&mut own.late);
        if let Some(other) = args.iter().map(|a| self.type_of(a)).find(|&a| a != t) {
            return Err(LoadError::Mix(t, other));
        }
        flow.cr = Some(t);
        flow.flex = own.flex;
        Ok(())
    }

    /// SEL: the current result (G) a BOOL, its two values of one type
    /// (untyped literals joined between them), which it leaves.
    fn select(
        &mut self,
        flow: &mut Flow,
        line: &Line,
        placed: &[(Option<usize>, &Operand)],
        args: &mut [super::Src],
    ) -> Result<(), LoadError> {
        if need_cr(flow.cr)? != DataType::Bool || !flow.flex.is_empty() {
            return Err(LoadError::Type(TypeWhy::SelectBool));
        }
        let mut own = Flow::default();
        let t = self.join(&mut own, line, placed, args)?;
        flow.late.append(&mut own.late);
        if args.iter().any(|a| self.type_of(a) != t) {
            return Err(LoadError::Type(TypeWhy::SelectOneType));
        }
        flow.cr = Some(t);
        flow.flex = own.flex;
        Ok(())
    }
}
