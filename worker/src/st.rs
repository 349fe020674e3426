//! A PLCopen project's Structured Text for the soft PLC's ST pane (issue
//! #55): the ladder takes what the project draws (LD, FBD), the pane its
//! ST POUs as one `.st` text (`Document::st_text`). A project whose
//! programs are all in ST opens with an empty ladder and its ST in the
//! pane, which runs it; docs/soft-plc.md, "Structured Text in the page".

use engine::formats::plcopen::dom::Node;
use engine::formats::plcopen::{Document, ImportError, Imported};
use engine::ladder::Ladder;
use engine::Located;

/// A POU whose body is ST.
fn in_st(p: &Node) -> bool {
    p.child("body").and_then(|b| b.child("ST")).is_some()
}

/// The project's ST POUs as one `.st` text (its types and globals
/// first), when it has any.
pub fn text(document: &Document) -> Option<String> {
    let mut pous = Vec::new();
    document.root().descendants("pou", &mut pous);
    pous.iter().any(|p| in_st(p)).then(|| document.st_text())
}

/// The soft PLC's ladder of a project whose whole import was refused
/// (`errors`) because of its ST: nothing it runs drawn while a program
/// is in ST (an empty ladder: the pane runs the ST), or its one drawn
/// program alone (the ST programs' variables, of the ST blocks' types,
/// are the pane's, not the ladder's). Else the refusal as it was.
pub fn drawn_apart(
    document: &Document,
    errors: Vec<Located<ImportError>>,
) -> Result<Imported, Vec<Located<ImportError>>> {
    if text(document).is_none() {
        return Err(errors);
    }
    if runs_in_st(document, &errors) {
        return Ok(Imported {
            ladder: Ladder::default(),
            unused_map_entries: Vec::new(),
            warnings: Vec::new(),
        });
    }
    let mut pous = Vec::new();
    document.root().descendants("pou", &mut pous);
    let drawn: Vec<&str> = pous
        .iter()
        .filter(|p| p.attr("pouType") == Some("program"))
        .filter(|p| engine::formats::plcopen::drawn_body(p).is_some())
        .filter_map(|p| p.attr("name"))
        .collect();
    match drawn.as_slice() {
        [one] => document
            .import(Some(engine::machines::IEC_MACHINE), None, Some(one))
            .map_err(|_| errors),
        _ => Err(errors),
    }
}

/// Whether the import was refused only because nothing it runs is drawn
/// while a program of the project is in ST: the ST pane runs that one,
/// the ladder is empty.
fn runs_in_st(document: &Document, errors: &[Located<ImportError>]) -> bool {
    let undrawn = !errors.is_empty()
        && errors.iter().all(|e| {
            matches!(
                e.error,
                ImportError::NoDrawnBody(_) | ImportError::NoDrawnInPrograms(..)
            )
        });
    let mut pous = Vec::new();
    document.root().descendants("pou", &mut pous);
    undrawn
        && pous
            .iter()
            .any(|p| in_st(p) && p.attr("pouType") == Some("program"))
}
