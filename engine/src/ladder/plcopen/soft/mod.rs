//! PLCopen projects on the soft PLC as written (issue #30): no map, no
//! lowering. Declared names stay names, located variables keep their
//! addresses, and each drawn (LD or FBD) body of the programs the tasks
//! run becomes Instruction List that runs its graph as drawn
//! ([`emit`]): contacts, coils, every standard function and function
//! block the soft PLC has, wired ORs, connectors, EN / ENO. What it does
//! not run (SFC, ST or IL bodies, the project's own function blocks,
//! vendor blocks) is refused at its line with the reason.

mod declare;
mod emit;
pub mod error;
pub(crate) mod functions;
mod graph;
mod order;

use super::dom::Node;
use super::import::{choose_pous, drawn_body, language, project};
use super::ImportError;
use crate::error::Located;
use crate::softplc::Program;
pub use error::SoftError;

/// A project as the soft PLC's program text.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SoftProgram {
    /// The Instruction List, with its declarations.
    pub text: String,
    /// What was left out, each at its line (POUs no task runs).
    pub warnings: Vec<Located<String>>,
}

type Errors = Vec<Located<ImportError>>;

fn soft(errors: Vec<Located<SoftError>>) -> Errors {
    errors
        .into_iter()
        .map(|e| Located::new(e.line, ImportError::Soft(e.error)))
        .collect()
}

/// The programs the tasks run (or `pou` alone) as one soft PLC program
/// that loads; every problem at its line of the file.
pub fn to_il(text: &str, pou: Option<&str>) -> Result<SoftProgram, Errors> {
    let root = project(text)?;
    let mut pous = Vec::new();
    root.descendants("pou", &mut pous);
    let mut warnings = Vec::new();
    let chosen = choose_pous(&root, &pous, pou, &mut warnings)?;
    let own: Vec<String> = pous
        .iter()
        .filter_map(|p| p.attr("name").map(str::to_string))
        .collect();
    let mut declarations = declare::declarations(&root, &chosen, &own).map_err(soft)?;
    let mut out = emit::Output::default();
    let mut errors = Vec::new();
    let mut drawn = 0;
    for (index, p) in chosen.iter().enumerate() {
        let Some(body) = drawn_body(p) else {
            errors.push(Located::new(
                p.line,
                SoftError::NotDrawn(format!(
                    "{} in {}",
                    p.attr("name").unwrap_or_default(),
                    language(p)
                )),
            ));
            continue;
        };
        drawn += 1;
        let g = match graph::read(body) {
            Ok(g) => g,
            Err(e) => {
                errors.extend(e);
                continue;
            }
        };
        let mut emitter = emit::Emitter {
            decl: &mut declarations,
            out: &mut out,
            pou: p.attr("name").unwrap_or_default().to_string(),
            index,
            own_blocks: &own,
            consumers: Default::default(),
        };
        if let Err(e) = emitter.body(&g) {
            errors.extend(e);
        }
    }
    if drawn == 0 && errors.is_empty() {
        errors.push(Located::new(root.line, SoftError::NotDrawn(String::new())));
    }
    if !errors.is_empty() {
        return Err(soft(errors));
    }
    warnings.append(&mut out.warnings);
    let (text, origin) = write(&declarations, &out, &root);
    if let Err(problems) = Program::load(&text) {
        return Err(problems
            .into_iter()
            .map(|p| {
                let line = origin
                    .get(p.line.wrapping_sub(1))
                    .copied()
                    .unwrap_or(root.line);
                Located::new(
                    line,
                    ImportError::Soft(SoftError::Load(p.error.to_string())),
                )
            })
            .collect());
    }
    Ok(SoftProgram { text, warnings })
}

/// The program text, and the file line of each of its lines.
fn write(d: &declare::Declarations, out: &emit::Output, root: &Node) -> (String, Vec<usize>) {
    let mut text = String::from("(* from a PLCopen project by hashigo *)\n");
    let mut origin = vec![root.line];
    let mut push = |line: String, at: usize| {
        text.push_str(&line);
        text.push('\n');
        origin.push(at);
    };
    for retain in [false, true] {
        let vars: Vec<(String, usize)> = d
            .list
            .iter()
            .filter(|v| v.retain == retain && !v.line.is_empty())
            .map(|v| (v.line.clone(), v.xml_line))
            .chain(if retain { Vec::new() } else { out.vars.clone() })
            .collect();
        if vars.is_empty() {
            continue;
        }
        push(if retain { "VAR_RETAIN" } else { "VAR" }.into(), root.line);
        for (line, at) in vars {
            push(format!("  {line}"), at);
        }
        push("END_VAR".into(), root.line);
    }
    for (line, at) in &out.lines {
        push(line.clone(), *at);
    }
    (text, origin)
}
