//! A CAL's operand: the instance and its parameters, `input := value`
//! and `output => variable`, each input given once, no empty place.

use super::{operand, IlError, Line, Operand};
use crate::iec::is_identifier;

/// `instance` or `instance(IN := a, PT := T#1s, Q => b)`.
pub(super) fn call(text: &str, out: &mut Line) -> Result<(), IlError> {
    let bad = || IlError::BadCall(text.to_string());
    let (name, params) = match text.split_once('(') {
        Some((n, p)) => (n.trim(), Some(p.trim().strip_suffix(')').ok_or_else(bad)?)),
        None => (text.trim(), None),
    };
    if !is_identifier(name) {
        return Err(bad());
    }
    out.operand = Some(Operand::Name(name.to_string()));
    let params: Vec<&str> = params
        .filter(|p| !p.trim().is_empty())
        .map(split_params)
        .unwrap_or_default();
    for param in params.into_iter().map(str::trim) {
        if param.is_empty() {
            return Err(IlError::EmptyParameter);
        }
        // Each input once (which value would it take?); an output may
        // go to several variables (`Q => a, Q => b`: a ladder's box
        // writes its Q to its own variable and to the rung's power).
        if let Some((formal, _)) = param.split_once(":=") {
            let formal = formal.trim();
            if out
                .inputs
                .iter()
                .any(|(f, _)| f.eq_ignore_ascii_case(formal))
            {
                return Err(IlError::TwiceGiven(formal.to_string()));
            }
        }
        if let Some((formal, value)) = param.split_once(":=") {
            let formal = formal.trim();
            if !is_identifier(formal) {
                return Err(bad());
            }
            out.inputs
                .push((formal.to_string(), operand(value.trim())?));
        } else if let Some((formal, target)) = param.split_once("=>") {
            let (formal, target) = (formal.trim(), target.trim());
            if !is_identifier(formal) || !is_identifier(target) {
                return Err(bad());
            }
            out.outputs.push((formal.to_string(), target.to_string()));
        } else {
            return Err(bad());
        }
    }
    Ok(())
}

/// A call's parameters, split at the commas outside string literals.
pub(crate) fn split_params(params: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let (mut start, mut quoted, mut escaped) = (0, false, false);
    for (i, c) in params.char_indices() {
        match c {
            // `$'` in a literal is a quote, not its end.
            _ if escaped => escaped = false,
            '$' if quoted => escaped = true,
            '\'' => quoted = !quoted,
            ',' if !quoted => {
                out.push(&params[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    out.push(&params[start..]);
    out
}
