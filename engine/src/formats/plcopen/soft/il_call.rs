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

use super::declare::{Declarations, Held, Interface};
use super::emit::Output;
use super::SoftError;
use crate::iec::functions::FunctionError;

/// The lines that call the project's own function when `code` (a body
/// line's code: no comment, no label) is a call of one, `None` when it
/// is not; the hidden instance (and first input) declared in `out`.
pub(super) fn own_function_call(
    code: &str,
    (user, decl): (&HashMap<String, Interface>, &Declarations),
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
    let mut args = if let Some(formal) = rest.strip_prefix('(') {
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
    let externals = match decl.external_args(pou, name, iface) {
        Ok(externals) => externals,
        Err(e) => return Some(Err(e)),
    };
    for external in externals {
        if !args.is_empty() {
            args.push_str(", ");
        }
        args.push_str(&external);
    }
    lines.push(format!("CAL {hidden}({args})"));
    lines.push(format!("LD {hidden}.{}", result.0));
    Some(Ok(lines))
}

/// `code` (an IL instruction, no label, no comment, its words the soft
/// PLC's) with the external arguments added when it calls an instance
/// of the project's own block that has externals (`CAL c0(Reset := r)`
/// → `CAL c0(Reset := r, ResetCounterValue := ResetCounterValue)`), in
/// POU `pou`; `None` when it calls no such block or gives them already.
/// Refused when `pou` has no variable for one.
pub(super) fn with_externals(
    code: &str,
    pou: &str,
    decl: &Declarations,
    user: &HashMap<String, Interface>,
) -> Option<Result<String, SoftError>> {
    let rest = code.trim_start();
    let op_end = rest.find(char::is_whitespace).unwrap_or(rest.len());
    let op = &rest[..op_end];
    if !["CAL", "CALC", "CALCN"]
        .iter()
        .any(|c| c.eq_ignore_ascii_case(op))
    {
        return None;
    }
    let after = rest[op_end..].trim_start();
    let name_end = after
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(after.len());
    let instance = &after[..name_end];
    let Some(Held::User(kind)) = decl.held(instance) else {
        return None;
    };
    let externals = match decl.external_args(pou, kind, user.get(&kind.to_ascii_uppercase())?) {
        Ok(externals) if externals.is_empty() => return None,
        Ok(externals) => externals,
        Err(e) => return Some(Err(e)),
    };
    let params = after[name_end..].trim();
    let mut args: Vec<String> = match params.strip_prefix('(').map(|p| p.strip_suffix(')')) {
        Some(Some(inner)) if !inner.trim().is_empty() => vec![inner.trim().to_string()],
        Some(Some(_)) => Vec::new(),
        None if params.is_empty() => Vec::new(),
        // Not a call the loader reads: it says why, as written.
        _ => return None,
    };
    // One the call gives already (an ST call's, lowered) is not given twice.
    let given: Vec<String> = args
        .iter()
        .flat_map(|a| a.split(','))
        .filter_map(|a| a.split([':', '=']).next())
        .map(|pin| pin.trim().to_ascii_uppercase())
        .collect();
    let pin = |a: &String| {
        a.split([':', '='])
            .next()
            .unwrap_or_default()
            .trim()
            .to_ascii_uppercase()
    };
    let missing: Vec<String> = externals
        .into_iter()
        .filter(|a| !given.contains(&pin(a)))
        .collect();
    if missing.is_empty() {
        return None;
    }
    args.extend(missing);
    Some(Ok(format!("{op} {instance}({})", args.join(", "))))
}

/// `line` without its `(* … *)` comments (a text's `(*` is no comment).
pub(super) fn without_comments(line: &str) -> String {
    let mut out = String::new();
    let (mut comment, mut text) = (false, false);
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        if comment {
            if c == '*' && chars.peek() == Some(&')') {
                chars.next();
                comment = false;
            }
            continue;
        }
        if !text && c == '(' && chars.peek() == Some(&'*') {
            chars.next();
            comment = true;
            continue;
        }
        if c == '\'' {
            text = !text;
        }
        out.push(c);
    }
    out
}
