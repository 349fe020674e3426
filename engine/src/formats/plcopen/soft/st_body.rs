//! A POU's Structured Text body (`<body><ST>`, issue #54) on the soft
//! PLC, and the ST of CODESYS's EXECUTE block (ST inside a drawn body). The ST is read
//! and checked in a source of its own, made of the POU's declarations
//! (as the soft PLC's lines already written for them) and the interfaces
//! of the project's own blocks, then lowered to IL (`iec::st::lower_body`)
//! and written as an IL body is (`il_body::write_lines`: renamed names,
//! unique labels, a program's RET ending that program). Every problem is
//! said at its line of the file, with its column in the ST. CODESYS's
//! EXECUTE block is `execute.rs`'s.

use std::collections::HashMap;

use super::declare::{Declarations, Interface};
use super::il_body::{first_line, write_lines, Place};
use super::SoftError;
use crate::error::Located;
use crate::formats::plcopen::dom::Node;
use crate::iec::st::{check_source, lower_body, parse_source, StError};

/// The text node of `pou`'s ST body, if it has one.
pub(super) fn st_body(pou: &Node) -> Option<&Node> {
    let st = pou.child("body")?.child("ST")?;
    Some(st.child("p").unwrap_or(st))
}

/// What an ST text is read in: the POU (its name as the file writes it),
/// its declarations, the project's own blocks' interfaces (upper-case).
pub(super) struct Scope<'a> {
    pub pou: &'a str,
    pub decl: &'a Declarations,
    pub user: &'a HashMap<String, Interface>,
}

/// Writes `pou`'s ST body `text_node` (from file `source`) to `place`,
/// its hidden variables among the generated ones; every problem at its
/// line of the file.
pub(super) fn write(
    pou: &Node,
    text_node: &Node,
    source: &str,
    place: Place,
    user: &HashMap<String, Interface>,
) -> Vec<Located<SoftError>> {
    let name = pou.attr("name").unwrap_or_default();
    let text = text_node.text.as_str();
    let first = first_line(text, text_node.line, source);
    let scope = Scope {
        pou: name,
        decl: place.decl,
        user,
    };
    match lower(&scope, text, first, &format!("{name}_")) {
        Ok((vars, lines)) => {
            place.out.vars.extend(vars);
            write_lines(name, lines, place)
        }
        Err(errors) => errors,
    }
}

pub(super) type Lines = Vec<(String, usize)>;

/// `text`, whose first line is the file's line `first`, as IL lines and
/// the hidden variables they use (declarations), each with its file
/// line. `tag` starts every label and hidden name made.
pub(super) fn lower(
    scope: &Scope,
    text: &str,
    first: usize,
    tag: &str,
) -> Result<(Lines, Lines), Vec<Located<SoftError>>> {
    let (source, body_line) = source_of(scope, text);
    // A line of the made-up head (never the file's) is said at the body.
    let file_line = |line: u32| first + (line as usize).saturating_sub(body_line);
    let located = |es: Vec<StError>| -> Vec<Located<SoftError>> {
        es.into_iter()
            .map(|e| {
                let why = SoftError::St(e.span.column as usize, e.kind);
                Located::new(file_line(e.span.line), why)
            })
            .collect()
    };
    let parsed = parse_source(&source).map_err(|e| located(vec![e]))?;
    check_source(&parsed).map_err(located)?;
    let lowered = lower_body(&parsed, scope.pou, tag).map_err(located)?;
    let vars = lowered.vars.into_iter().map(|v| (v, first)).collect();
    let lines = lowered
        .lines
        .into_iter()
        .map(|(l, span)| (l, file_line(span.line)))
        .collect();
    Ok((vars, lines))
}

/// The ST source the body is read in, and the line its body starts at:
/// the project's own blocks' interfaces (but the POU's own), then the
/// POU as a PROGRAM of its declarations and the body.
fn source_of(scope: &Scope, text: &str) -> (String, usize) {
    let mut out = String::new();
    let mut blocks: Vec<_> = scope.user.iter().collect();
    blocks.sort_by(|a, b| a.0.cmp(b.0));
    for (name, iface) in blocks {
        if name.eq_ignore_ascii_case(scope.pou) {
            continue;
        }
        // A function's result is its output of its own name.
        let result = iface
            .outputs
            .iter()
            .find(|(pin, _)| iface.function && pin.eq_ignore_ascii_case(name));
        let end = match result {
            Some((_, ty)) => {
                out.push_str(&format!("FUNCTION {name} : {}\n", ty.name()));
                "END_FUNCTION"
            }
            None => {
                out.push_str(&format!("FUNCTION_BLOCK {name}\n"));
                "END_FUNCTION_BLOCK"
            }
        };
        for (keyword, pins) in [("VAR_INPUT", &iface.inputs), ("VAR_OUTPUT", &iface.outputs)] {
            out.push_str(keyword);
            out.push('\n');
            for (pin, ty) in pins {
                if result.is_none() || !pin.eq_ignore_ascii_case(name) {
                    out.push_str(&format!("  {pin} : {};\n", ty.name()));
                }
            }
            out.push_str("END_VAR\n");
        }
        // Its externals, which an ST call then passes (`iec::st::lower_io`).
        for (keyword, copied_out) in [("VAR_EXTERNAL", true), ("VAR_EXTERNAL CONSTANT", false)] {
            let of_kind: Vec<_> = iface
                .externals
                .iter()
                .filter(|e| e.copied_out == copied_out)
                .collect();
            if of_kind.is_empty() {
                continue;
            }
            out.push_str(keyword);
            out.push('\n');
            for e in of_kind {
                out.push_str(&format!("  {} : {};\n", e.name, e.ty.name()));
            }
            out.push_str("END_VAR\n");
        }
        out.push_str(end);
        out.push('\n');
    }
    out.push_str(&format!("PROGRAM {}\nVAR\n", scope.pou));
    // The POU's renamed variables under the names its body writes (the
    // IL's words are renamed back on the way out); the other programs'
    // variables of those names are not this POU's.
    let renamed = scope.decl.renamings(scope.pou);
    for d in scope.decl.list.iter().filter(|d| !d.line.is_empty()) {
        let lower = d.name.to_ascii_lowercase();
        if renamed.iter().any(|(file, _)| *file == lower) {
            continue;
        }
        let line = match renamed
            .iter()
            .find(|(_, soft)| soft.eq_ignore_ascii_case(&d.name))
        {
            Some((file, _)) => d.line.replacen(&d.name, file, 1),
            None => d.line.clone(),
        };
        out.push_str(&format!("  {line}\n"));
    }
    out.push_str("END_VAR\n");
    let body_line = out.lines().count() + 1;
    out.push_str(text);
    out.push_str("\nEND_PROGRAM\n");
    (out, body_line)
}
