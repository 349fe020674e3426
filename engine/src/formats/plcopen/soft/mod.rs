//! PLCopen projects on the soft PLC as written (issue #30): no map, no
//! lowering. Declared names stay names, located variables keep their
//! addresses, and each drawn (LD or FBD) body of the programs the tasks
//! run becomes Instruction List that runs its graph (`super::graph`,
//! the one both pipelines read) as drawn (`emit.rs`): contacts, coils, every standard function and function
//! block the soft PLC has, wired ORs, connectors, EN / ENO. IL bodies are
//! copied as written (`il_body.rs`), and the project's own function
//! blocks become function blocks of the program. What it does not run
//! (SFC or ST bodies, vendor blocks) is refused at its line with the
//! reason.

mod declare;
mod emit;
mod emit_fn;
pub mod error;
mod execute;
mod formal;
mod il_body;
mod il_call;
mod infer;
mod st_body;

use super::dom::Node;
use super::graph::Graph;
use super::import::{choose_pous, drawn_body, language};
use super::ImportError;
use crate::error::Located;
use crate::formats::plcopen::warning::ImportWarning;
use crate::softplc::Program;
pub use error::SoftError;
use std::collections::HashMap;

/// A project as the soft PLC's program text.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SoftProgram {
    /// The Instruction List, with its declarations.
    pub text: String,
    /// What was left out, each at its line (POUs no task runs).
    pub warnings: Vec<Located<ImportWarning>>,
}

type Errors = Vec<Located<ImportError>>;

fn soft(errors: Vec<Located<SoftError>>) -> Errors {
    errors
        .into_iter()
        .map(|e| Located::new(e.line, ImportError::Soft(e.error)))
        .collect()
}

/// The programs the tasks run (or `pou` alone) of the project `root`
/// read from `text` (by [`super::Document`]) as one soft PLC program that
/// loads; every problem at its line of the file. IL bodies are copied
/// from the text as written.
pub(in crate::formats::plcopen) fn il_of(
    root: &Node,
    text: &str,
    pou: Option<&str>,
) -> Result<SoftProgram, Errors> {
    let mut pous = Vec::new();
    root.descendants("pou", &mut pous);
    let mut warnings = Vec::new();
    let chosen = choose_pous(root, &pous, pou, &mut warnings)?;
    let own = own_types(&pous);
    let mut declarations = declare::declarations(root, &chosen, &own).map_err(soft)?;
    let blocks = used_blocks(&pous, &declarations, &own).map_err(soft)?;
    // A block the programs use is not skipped, whatever the tasks say.
    warnings.retain(|w| !blocks.iter().any(|(p, _)| p.line == w.line));
    let user: HashMap<String, declare::Interface> = blocks
        .iter()
        .map(|(p, d)| {
            let name = p.attr("name").unwrap_or_default().to_ascii_uppercase();
            let mut interface = d.interface();
            interface.function = p.attr("pouType") == Some("function");
            (name, interface)
        })
        .collect();
    let mut errors = Vec::new();
    let mut sections = block_sections(blocks, &own, &user, text, &mut errors);
    let mut out = emit::Output::default();
    let mut drawn = 0;
    // The labels of the programs' IL bodies, one section for them all.
    let mut labels = std::collections::HashSet::new();
    for (index, p) in chosen.iter().enumerate() {
        if let Some(il) = il_body::il_body(p) {
            drawn += 1;
            let place = il_body::Place {
                decl: &declarations,
                out: &mut out,
                labels: Some(&mut labels),
                user: Some(&user),
                copy_out: Vec::new(),
            };
            errors.extend(il_body::write(p, il, text, place));
            continue;
        }
        if let Some(st) = st_body::st_body(p) {
            drawn += 1;
            let place = il_body::Place {
                decl: &declarations,
                out: &mut out,
                labels: Some(&mut labels),
                user: Some(&user),
                copy_out: Vec::new(),
            };
            errors.extend(st_body::write(p, st, text, place, &user));
            continue;
        }
        if drawn_body(p).is_none() {
            let what = format!("{} in {}", p.attr("name").unwrap_or_default(), language(p));
            errors.push(Located::new(p.line, SoftError::NotDrawn(what)));
            continue;
        }
        drawn += 1;
        let em = emitter(
            &mut declarations,
            &mut out,
            p,
            sections.len() + index,
            &own,
            &user,
        );
        errors.extend(emit_body(em, p));
    }
    if drawn == 0 && errors.is_empty() {
        errors.push(Located::new(root.line, SoftError::NotDrawn(String::new())));
    }
    if !errors.is_empty() {
        return Err(soft(errors));
    }
    for (_, _, o) in &mut sections {
        warnings.append(&mut o.warnings);
    }
    warnings.append(&mut out.warnings);
    let text = Text::of(&sections, &declarations, &out, root);
    text.loads(root.line)?;
    Ok(SoftProgram {
        text: text.text,
        warnings,
    })
}

type Section<'a> = (&'a Node, declare::Declarations, emit::Output);

/// The project's own function blocks' sections (from `source`), each
/// body written as the soft PLC's IL; their problems into `errors`.
fn block_sections<'a>(
    blocks: Vec<(&'a Node, declare::Declarations)>,
    own: &declare::OwnTypes,
    user: &HashMap<String, declare::Interface>,
    source: &str,
    errors: &mut Vec<Located<SoftError>>,
) -> Vec<Section<'a>> {
    let mut sections = Vec::new();
    for (index, (p, mut d)) in blocks.into_iter().enumerate() {
        let mut out = emit::Output::default();
        // Its externals copied back out when its body ends.
        let copy_out = d.copy_out();
        if let Some(il) = il_body::il_body(p) {
            let place = il_body::Place {
                decl: &d,
                out: &mut out,
                labels: None,
                user: Some(user),
                copy_out,
            };
            errors.extend(il_body::write(p, il, source, place));
        } else if let Some(st) = st_body::st_body(p) {
            let place = il_body::Place {
                decl: &d,
                out: &mut out,
                labels: None,
                user: Some(user),
                copy_out,
            };
            errors.extend(st_body::write(p, st, source, place, user));
        } else {
            let em = emitter(&mut d, &mut out, p, index, own, user);
            errors.extend(emit_body(em, p));
            // A drawn body has no RET: the copy follows its last line.
            let at = out.lines.last().map_or(p.line, |&(_, at)| at);
            out.lines.extend(copy_out.into_iter().map(|l| (l, at)));
        }
        sections.push((p, d, out));
    }
    sections
}

/// The project's own POUs, and which of them run as blocks.
fn own_types(pous: &[&Node]) -> declare::OwnTypes {
    declare::OwnTypes {
        names: pous
            .iter()
            .filter_map(|p| {
                let kind = match p.attr("pouType") {
                    Some("functionBlock") => "function block",
                    Some("function") => "function",
                    _ => "program",
                };
                Some((
                    p.attr("name")?.to_string(),
                    format!("{kind} in {}", language(p)),
                ))
            })
            .collect(),
        blocks: pous
            .iter()
            .filter(|p| p.attr("pouType") == Some("functionBlock") && runs(p))
            .filter_map(|p| p.attr("name").map(str::to_string))
            .collect(),
        functions: pous
            .iter()
            .filter(|p| p.attr("pouType") == Some("function"))
            .filter(|p| il_body::il_body(p).is_some() || st_body::st_body(p).is_some())
            .filter_map(|p| p.attr("name").map(str::to_string))
            .filter(|name| called(name, pous))
            .collect(),
    }
}

/// Whether another POU's body may call function `name`: a drawn block
/// of its type, or its name as a word of an ST or IL text (a comment's
/// mention too: a function taken in for nothing costs nothing). One no
/// body names is left out, so that an unused function the soft PLC
/// cannot run does not refuse the project.
fn called(name: &str, pous: &[&Node]) -> bool {
    let word = |text: &str| {
        text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .any(|w| w.eq_ignore_ascii_case(name))
    };
    pous.iter()
        .filter(|p| p.attr("name").is_none_or(|n| !n.eq_ignore_ascii_case(name)))
        .any(|p| {
            let mut blocks = Vec::new();
            p.descendants("block", &mut blocks);
            let drawn = blocks.iter().any(|b| {
                b.attr("typeName")
                    .is_some_and(|t| t.eq_ignore_ascii_case(name))
            });
            let text = il_body::il_body(p).or_else(|| st_body::st_body(p));
            // CODESYS's EXECUTE blocks hold ST in drawn bodies.
            let mut codes = Vec::new();
            p.descendants("STCode", &mut codes);
            drawn || text.is_some_and(|t| word(&t.text)) || codes.iter().any(|c| word(&c.text))
        })
}

/// Whether the soft PLC runs `pou`'s body: drawn (LD, FBD), IL or ST.
fn runs(pou: &Node) -> bool {
    drawn_body(pou).is_some() || il_body::il_body(pou).is_some() || st_body::st_body(pou).is_some()
}

/// `pou`'s drawn body emitted by `em`; its problems.
fn emit_body(mut em: emit::Emitter, pou: &Node) -> Vec<Located<SoftError>> {
    let Some(body) = drawn_body(pou) else {
        return Vec::new();
    };
    let g = Graph::read(body);
    match runnable(&g) {
        Ok(warnings) => {
            em.out.warnings.extend(warnings);
            let mut errors = em.body(&g).err().unwrap_or_default();
            // An EXECUTE block's ST problems, each at its own line.
            errors.append(&mut em.out.errors);
            errors.sort_by_key(|e| e.line);
            errors
        }
        Err(e) => e,
    }
}

/// Whether the soft PLC runs every child of body `g` (not SFC steps,
/// jumps, actions, vendor logic; every element with a `localId` of its
/// own): the warnings for the vendor elements it skips, or every
/// refusal at its line.
fn runnable(g: &Graph) -> Result<Vec<Located<ImportWarning>>, Vec<Located<SoftError>>> {
    use super::graph::{Kind, Read};
    use super::vendor::Vendor;
    let mut warnings = Vec::new();
    let mut errors = Vec::new();
    let other = |n: &Node| SoftError::Element(n.name.clone());
    for item in &g.items {
        let n = item.node;
        let error = match &item.read {
            Read::Comment | Read::Vendor(Vendor::Title(_) | Vendor::Cosmetic) => None,
            Read::Vendor(Vendor::Unknown(what)) => {
                let warning = ImportWarning::VendorSkipped(what.clone());
                warnings.push(Located::new(n.line, warning));
                None
            }
            Read::Vendor(Vendor::Logic(why)) => Some(SoftError::VendorLogic(why.clone())),
            Read::Element(i) => match &g.elements[*i].kind {
                Kind::Other(_) => Some(other(n)),
                _ => None,
            },
            Read::NoLocalId { known: false } | Read::Duplicate { known: false, .. } => {
                Some(other(n))
            }
            Read::NoLocalId { known: true } => Some(SoftError::NoLocalId(n.name.clone())),
            Read::Duplicate { id, .. } => {
                // An id first taken by an element refused already.
                let first = g.by_id.get(id).map(|&i| &g.elements[i].kind);
                match first {
                    Some(Kind::Other(_)) => None,
                    _ => Some(SoftError::DuplicateId(id.clone())),
                }
            }
        };
        errors.extend(error.map(|e| Located::new(n.line, e)));
    }
    if errors.is_empty() {
        Ok(warnings)
    } else {
        Err(errors)
    }
}

fn emitter<'a>(
    decl: &'a mut declare::Declarations,
    out: &'a mut emit::Output,
    pou: &Node,
    index: usize,
    own: &'a declare::OwnTypes,
    user: &'a HashMap<String, declare::Interface>,
) -> emit::Emitter<'a> {
    emit::Emitter {
        decl,
        out,
        pou: pou.attr("name").unwrap_or_default().to_string(),
        index,
        own_blocks: own,
        user,
        consumers: Default::default(),
        failed: Default::default(),
    }
}

/// The project's own function blocks the programs use (their instances'
/// types, and the types of the instances those hold), each with its
/// declarations, in the order first met.
fn used_blocks<'a>(
    pous: &[&'a Node],
    program: &declare::Declarations,
    own: &declare::OwnTypes,
) -> Result<Vec<(&'a Node, declare::Declarations)>, Vec<Located<SoftError>>> {
    // The functions in ST or IL run as blocks, called by hidden
    // instances: each is a section whether called or not.
    let mut todo: Vec<String> = program.user_types();
    todo.extend(own.functions.iter().rev().cloned());
    let mut out: Vec<(&Node, declare::Declarations)> = Vec::new();
    while let Some(t) = todo.pop() {
        let seen = out
            .iter()
            .any(|(p, _)| p.attr("name").is_some_and(|n| n.eq_ignore_ascii_case(&t)));
        if seen || out.len() > 1_000 {
            continue;
        }
        let Some(p) = pous
            .iter()
            .find(|p| p.attr("name").is_some_and(|n| n.eq_ignore_ascii_case(&t)))
        else {
            continue;
        };
        let d = declare::block_declarations(p, own)?;
        todo.extend(d.user_types());
        out.push((p, d));
    }
    Ok(out)
}

/// The program text being written, and the file line of each line.
#[derive(Default)]
struct Text {
    text: String,
    origin: Vec<usize>,
}

impl Text {
    /// The program's own function blocks' sections, then the program.
    fn of(
        sections: &[(&Node, declare::Declarations, emit::Output)],
        program: &declare::Declarations,
        out: &emit::Output,
        root: &Node,
    ) -> Text {
        let mut text = Text::default();
        text.push("(* from a PLCopen project by hashigo *)".into(), root.line);
        for (p, d, o) in sections {
            text.push(
                format!("FUNCTION_BLOCK {}", p.attr("name").unwrap_or_default()),
                p.line,
            );
            text.section(d, o, p.line);
            text.push("END_FUNCTION_BLOCK".into(), p.line);
        }
        text.section(program, out, root.line);
        text
    }

    /// Loads the text as a check: a problem is said at the file's line
    /// that made it (`root`: the project's, where none did).
    fn loads(&self, root: usize) -> Result<(), Errors> {
        Program::load(&self.text).map(|_| ()).map_err(|problems| {
            problems
                .into_iter()
                .map(|p| {
                    let line = self
                        .origin
                        .get(p.line.wrapping_sub(1))
                        .copied()
                        .unwrap_or(root);
                    Located::new(line, ImportError::Soft(SoftError::Load(p.error)))
                })
                .collect()
        })
    }

    fn push(&mut self, line: String, at: usize) {
        self.text.push_str(&line);
        self.text.push('\n');
        self.origin.push(at);
    }

    /// A section's declarations (inputs, outputs, locals with the
    /// generated ones, retained) and lines.
    fn section(&mut self, d: &declare::Declarations, out: &emit::Output, at: usize) {
        use crate::iec::vars::Direction;
        let blocks = [
            ("VAR_INPUT", Direction::Input, false),
            ("VAR_OUTPUT", Direction::Output, false),
            ("VAR", Direction::Local, false),
            ("VAR_RETAIN", Direction::Local, true),
        ];
        for (header, direction, retain) in blocks {
            let mut vars: Vec<(String, usize)> = d
                .list
                .iter()
                .filter(|v| v.direction == direction && v.retain == retain && !v.line.is_empty())
                .map(|v| (v.line.clone(), v.xml_line))
                .collect();
            if header == "VAR" {
                vars.extend(out.vars.iter().cloned());
            }
            if vars.is_empty() {
                continue;
            }
            self.push(header.into(), at);
            for (line, from) in vars {
                self.push(format!("  {line}"), from);
            }
            self.push("END_VAR".into(), at);
        }
        for (line, from) in &out.lines {
            self.push(line.clone(), *from);
        }
    }
}
