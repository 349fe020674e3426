//! One POU's ST body lowered alone, for a host that writes the POU's
//! declarations itself: a PLCopen project's `<ST>` body, CODESYS's
//! EXECUTE block. The host gets the IL lines (each with its ST place)
//! and the hidden variables they use, to declare where it declares.

use super::ast::{Item, Source, Span};
use super::error::{StError, StErrorKind};
use super::lower::{declared, signatures, Lower};
use super::types::at;

/// A POU's body as IL.
#[derive(Clone, Debug, PartialEq)]
pub struct LoweredBody {
    /// The hidden variables the lines use, as declarations
    /// (`st_t1 : INT;`).
    pub vars: Vec<String>,
    /// The IL lines, each with the ST place it comes from.
    pub lines: Vec<(String, Span)>,
}

/// Lowers the body of POU `pou` of a checked `source` (see
/// [`super::check_source`]) alone. `tag` starts every label and hidden
/// name it makes, so that several bodies lowered apart can share one IL
/// section.
pub fn lower_body(source: &Source, pou: &str, tag: &str) -> Result<LoweredBody, Vec<StError>> {
    let (functions, blocks) = signatures(source);
    let mut l = Lower::default();
    (l.functions, l.blocks) = (functions, blocks);
    l.taken = declared(source);
    l.tag = tag.to_string();
    l.know_in_outs(source);
    let found = source.items.iter().find_map(|i| match i {
        Item::Pou(p) if p.name.name.eq_ignore_ascii_case(pou) => Some(p),
        _ => None,
    });
    let Some(p) = found else {
        let what = format!("a body without its POU {pou}");
        return Err(vec![at(
            Span { line: 1, column: 1 },
            StErrorKind::NotYet(what),
        )]);
    };
    let hidden = l.body_alone(p);
    if !l.errors.is_empty() {
        l.errors.sort_by_key(|e| (e.span.line, e.span.column));
        return Err(l.errors);
    }
    Ok(LoweredBody {
        vars: hidden
            .into_iter()
            .map(|(name, ty)| format!("{name} : {ty};"))
            .collect(),
        lines: l.lines,
    })
}
