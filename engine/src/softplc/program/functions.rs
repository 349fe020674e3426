//! An IL function line resolved (`SHL`, `MIN`, `SEL`, `INT_TO_DINT` …):
//! its operands fitted to the current result's type, the type it leaves
//! checked.

use super::check::need_cr;
use super::{LoadError, Program, Step};
use crate::softplc::data::DataType;
use crate::softplc::il::{Function, Line};

impl Program {
    /// A function call: its operands resolved and fitted, the type it
    /// leaves checked.
    pub(super) fn function(
        &mut self,
        f: Function,
        line: &Line,
        cr: &mut Option<DataType>,
    ) -> Result<Step, LoadError> {
        let t = need_cr(*cr)?;
        let mut args = Vec::new();
        for a in &line.args {
            args.push(self.slot(a)?);
        }
        let wrong = |why: String| Err(LoadError::Type(why));
        let result = match f {
            Function::Neg if matches!(t, DataType::Bool | DataType::String) => {
                return wrong("NEG needs a number".into())
            }
            Function::Neg | Function::Move => t,
            Function::Shl | Function::Shr | Function::Rol | Function::Ror => {
                if t.bits().is_none() || self.type_of(&args[0]).bits().is_none() {
                    return wrong("SHL, SHR, ROL and ROR shift an integer by an integer".into());
                }
                t
            }
            Function::Min | Function::Max | Function::Limit => {
                for a in &mut args {
                    *a = Program::fit(a.clone(), t);
                    if self.type_of(a) != t {
                        return wrong(format!(
                            "{} and {} do not mix: convert one (*_TO_*)",
                            t.name(),
                            self.type_of(a).name()
                        ));
                    }
                }
                t
            }
            Function::Sel => {
                if t != DataType::Bool {
                    return wrong("SEL's first input (the current result) is a BOOL".into());
                }
                let first = self.type_of(&args[0]);
                args[1] = Program::fit(args[1].clone(), first);
                if self.type_of(&args[1]) != first {
                    return wrong("SEL's two values have one type".into());
                }
                first
            }
            Function::Convert { from, to } => {
                if from == DataType::String || to == DataType::String {
                    return wrong(
                        "conversions to and from STRING do not run on the soft PLC yet".into(),
                    );
                }
                if from != t {
                    return wrong(format!(
                        "the current result is {}, not {}",
                        t.name(),
                        from.name()
                    ));
                }
                to
            }
        };
        *cr = Some(result);
        Ok(Step::Func(f, args))
    }
}
