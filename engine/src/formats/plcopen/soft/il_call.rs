//! The project's own FUNCTIONs called from an IL body (issue #54), as
//! IEC's IL calls a function: its name as the operator, the current
//! result its first input and the operands the next ones (`LD n` /
//! `Plus 10` / `ST r`), or a formal list that leaves the current result
//! out (`Plus(a := n, b := 10)`); the current result after it is the
//! function's. The soft PLC's IL knows no function of the project's, so
//! each call becomes its block's call through a hidden instance, as an
//! ST call does (`iec::st::lower_call`):
//!
//! ```text
//! ST  main_il_f1_in            (the current result, as the 1st input)
//! CAL main_il_f1(a := main_il_f1_in, b := 10)
//! LD  main_il_f1.Plus          (its result)
//! ```

use std::collections::HashMap;

use super::declare::Interface;
use super::emit::Output;
use super::SoftError;
use crate::iec::functions::FunctionError;

/// The lines that call the project's own function when `code` (a body
/// line's code: no comment, no label) is a call of one, `None` when it
/// is not; the hidden instance (and first input) declared in `out`.
pub(super) fn own_function_call(
    code: &str,
    user: &HashMap<String, Interface>,
    pou: &str,
    out: &mut Output,
    at: usize,
) -> Option<Result<Vec<String>, SoftError>> {
    let code = code.trim();
    let end = code
        .find(|c: char| c.is_whitespace() || c == '(')
        .unwrap_or(code.len());
    let name = &code[..end];
    let iface = user.get(&name.to_ascii_uppercase())?;
    if !iface.function {
        return None;
    }
    let result = iface
        .outputs
        .iter()
        .find(|(o, _)| o.eq_ignore_ascii_case(name))?;
    let rest = code[end..].trim();
    let k = out.vars.len() + 1;
    let hidden = format!("{pou}_il_f{k}");
    out.vars.push((format!("{hidden} : {name};"), at));
    let mut lines = Vec::new();
    let args = if let Some(formal) = rest.strip_prefix('(') {
        // The formal list, as written (a `)` closes it).
        formal.trim_end().trim_end_matches(')').trim().to_string()
    } else {
        let operands: Vec<&str> = rest
            .split(',')
            .map(str::trim)
            .filter(|o| !o.is_empty())
            .collect();
        if operands.len() + 1 > iface.inputs.len() {
            let why = FunctionError::Inputs(operands.len() + 1);
            return Some(Err(SoftError::Function(name.to_string(), why)));
        }
        let mut args = Vec::new();
        if let Some((first, ty)) = iface.inputs.first() {
            let input = format!("{hidden}_in");
            out.vars.push((format!("{input} : {};", ty.name()), at));
            lines.push(format!("ST {input}"));
            args.push(format!("{first} := {input}"));
        }
        for ((pin, _), operand) in iface.inputs.iter().skip(1).zip(operands) {
            args.push(format!("{pin} := {operand}"));
        }
        args.join(", ")
    };
    lines.push(format!("CAL {hidden}({args})"));
    lines.push(format!("LD {hidden}.{}", result.0));
    Some(Ok(lines))
}
