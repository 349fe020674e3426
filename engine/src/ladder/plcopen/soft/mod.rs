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
pub(crate) mod functions;
mod graph;

use std::fmt;

use super::dom::{self, Node};
use super::import::{check_project, choose_pous, drawn_body, language};
use super::ImportError;
use crate::error::Located;
use crate::softplc::Program;

/// Why part of a project does not run on the soft PLC.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SoftError {
    /// A declaration the soft PLC cannot hold (name, why).
    Declaration(String, String),
    /// An element of a drawn body it does not run (its XML name).
    Element(String),
    /// An element without a `localId` (its XML name).
    NoLocalId(String),
    /// A `localId` used twice.
    DuplicateId(String),
    /// A connection to an element that is not there.
    Missing(String),
    /// An input that needs a connection and has none (what).
    Unconnected(String),
    /// Connectors that feed themselves (a name).
    ConnectorLoop(String),
    /// A loop of wires through a block whose output type is not known
    /// yet (its type).
    Feedback(String),
    /// An expression that is no variable, address or literal.
    Expression(String),
    /// A name no declaration gives.
    Undeclared(String),
    /// A contact or coil on something that is not a BOOL variable.
    NotABit(String),
    /// A block instance declared as another type (instance, type).
    Instance(String, String),
    /// A function called with inputs it does not take (why).
    Function(String),
    /// A call of one of the project's own POUs.
    ProjectBlock(String),
    /// A block type the soft PLC does not have.
    Block(String),
    /// No program the tasks run has a drawn body: each POU and its
    /// language.
    NotDrawn(String),
    /// The generated program does not load (the loader's words).
    Load(String),
}

impl fmt::Display for SoftError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SoftError::Declaration(name, why) => write!(f, "variable {name}: {why}"),
            SoftError::Element(e) => {
                let what = match e.as_str() {
                    "vendorElement" => " (an element of the tool that wrote the file)",
                    "jump" | "label" | "return" => " (jumps are not run yet)",
                    "actionBlock"
                    | "step"
                    | "transition"
                    | "selectionDivergence"
                    | "selectionConvergence"
                    | "simultaneousDivergence"
                    | "simultaneousConvergence"
                    | "macroStep" => " (SFC is not run)",
                    _ => "",
                };
                write!(f, "<{e}> does not run on the soft PLC{what}")
            }
            SoftError::NoLocalId(e) => write!(f, "<{e}> has no localId"),
            SoftError::DuplicateId(id) => write!(f, "localId {id} is used twice"),
            SoftError::Missing(id) => write!(f, "a connection to {id}, which is not drawn"),
            SoftError::Unconnected(what) => write!(f, "{what} is not connected"),
            SoftError::ConnectorLoop(name) => write!(f, "connector {name} feeds itself"),
            SoftError::Feedback(ty) => write!(
                f,
                "a loop of wires through a {ty} block: break it with a variable"
            ),
            SoftError::Expression(x) => {
                write!(f, "`{x}` is not a variable, an address or a literal")
            }
            SoftError::Undeclared(name) => write!(f, "`{name}` is not declared"),
            SoftError::NotABit(name) => write!(f, "{name} is not a BOOL variable"),
            SoftError::Instance(name, ty) => {
                write!(f, "{name} is not declared as a {ty} instance")
            }
            SoftError::Function(why) => f.write_str(why),
            SoftError::ProjectBlock(name) => write!(
                f,
                "{name} is the project's own function block: the soft PLC does not run those yet"
            ),
            SoftError::Block(name) => write!(
                f,
                "{name} is not a standard block the soft PLC has (a vendor's or a library's block)"
            ),
            SoftError::NotDrawn(pous) => {
                write!(f, "no program the tasks run is drawn in LD or FBD: {pous}")
            }
            SoftError::Load(why) => f.write_str(why),
        }
    }
}

impl std::error::Error for SoftError {}

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
    let root = dom::parse(text).map_err(|e| vec![Located::new(e.line, e.error.into())])?;
    check_project(&root)?;
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
