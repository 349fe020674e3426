//! Structured Text on the soft PLC: a `.st` text read, checked and
//! lowered to IL (`iec::st::lower`), then loaded as IL is, so it runs
//! through the one scan. What the IL loader refuses is said at the ST
//! line and column the IL line comes from.

use std::fmt;

use super::{LoadError, Program};
use crate::iec::data::DataType;
use crate::iec::st::ast::{Item, Pou, PouKind, VarKind};
use crate::iec::st::print::type_text;
use crate::iec::st::rename::Renamed;
use crate::iec::st::{check_source, lower_source, parse_source, Lowered, StError, StErrorKind};
use crate::ladder::user_blocks::UserBlock;

/// Why a Structured Text program does not load: where (1-based line and
/// column of the ST text) and what.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StLoadError {
    /// 1-based line.
    pub line: usize,
    /// 1-based column, in characters.
    pub column: usize,
    /// The reason.
    pub message: String,
    /// The reason as a value, for a front end that says it in another
    /// language.
    pub why: StWhy,
}

/// Why a Structured Text program does not load: the ST checker's or
/// lowering's reason, or the IL loader's at the ST place.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum StWhy {
    /// Read, checked or lowered.
    St(StErrorKind),
    /// The lowered IL refused by the soft PLC's loader.
    Load(LoadError),
}

impl fmt::Display for StLoadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}: {}", self.line, self.column, self.message)
    }
}

fn from_st(e: StError) -> StLoadError {
    StLoadError {
        line: e.span.line as usize,
        column: e.span.column as usize,
        message: e.kind.to_string(),
        why: StWhy::St(e.kind),
    }
}

/// A Structured Text source as the Instruction List the soft PLC runs
/// (what `hashigo run` loads for a `.st` file), checked to load: every
/// refusal at its ST line and column.
pub fn st_to_il(text: &str) -> Result<String, Vec<StLoadError>> {
    let (_, lowered) = load(text)?;
    Ok(lowered.text)
}

/// A Structured Text program as the page runs it (issue #55): the IL it
/// loads as, and where each of that program's steps comes from in the ST
/// text, for breakpoints and the current line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StRun {
    /// The IL text (loads to the same program as the ST text).
    pub il: String,
    /// `lines[step]`: the 1-based ST line the step comes from (`None`
    /// for the steps the loader adds).
    pub lines: Vec<Option<usize>>,
    /// The variables of a second and later `PROGRAM` the IL knows by
    /// another name (a name an earlier program has too).
    pub renamed: Vec<Renamed>,
}

impl StRun {
    /// The IL's name of variable `name` as ST line `line` writes it:
    /// its program's own when renamed, else `name`.
    pub fn il_name(&self, line: usize, name: &str) -> String {
        self.renamed
            .iter()
            .find(|r| (r.first..=r.last).contains(&line) && r.name.eq_ignore_ascii_case(name))
            .map_or_else(|| name.to_string(), |r| r.il_name.clone())
    }
}

/// [`st_to_il`] with each step's ST line ([`Program::source_line`]).
pub fn st_run(text: &str) -> Result<StRun, Vec<StLoadError>> {
    let (program, lowered) = load(text)?;
    let lines = (0..program.len())
        .map(|step| program.source_line(step).map(|(line, _)| line as usize))
        .collect();
    Ok(StRun {
        il: lowered.text,
        lines,
        renamed: lowered.renamed,
    })
}

impl Program {
    /// Loads a Structured Text source: its one `PROGRAM` and its own
    /// `FUNCTION_BLOCK`s. Every refusal at its line and column.
    pub fn load_st(text: &str) -> Result<Program, Vec<StLoadError>> {
        load(text).map(|(p, _)| p)
    }

    /// The ST line and column (1-based) step `step` comes from, for a
    /// program loaded from Structured Text (`None` for IL, or a step no
    /// ST statement wrote: the return between the program and its
    /// blocks' bodies). The page shows values beside lines, stops at
    /// breakpoints and steps by statement with it.
    pub fn source_line(&self, step: usize) -> Option<(u32, u32)> {
        self.st_places.get(step).copied().filter(|&(l, _)| l > 0)
    }
}

fn load(text: &str) -> Result<(Program, Lowered), Vec<StLoadError>> {
    let source = parse_source(text).map_err(|e| vec![from_st(e)])?;
    check_source(&source).map_err(|es| es.into_iter().map(from_st).collect::<Vec<_>>())?;
    let lowered =
        lower_source(&source).map_err(|es| es.into_iter().map(from_st).collect::<Vec<_>>())?;
    let mut program = Program::load(&lowered.text).map_err(|es| {
        es.into_iter()
            .map(|e| {
                let span = lowered.place(e.line);
                StLoadError {
                    line: span.line as usize,
                    column: span.column as usize,
                    message: e.error.to_string(),
                    why: StWhy::Load(e.error),
                }
            })
            .collect::<Vec<_>>()
    })?;
    program.st_places = program
        .step_lines()
        .into_iter()
        .map(|il| match il {
            None | Some(0) => (0, 0),
            Some(il) => {
                let span = lowered.place(il);
                (span.line, span.column)
            }
        })
        .collect();
    Ok((program, lowered))
}

/// The function blocks of a Structured Text source as the ladder's boxes
/// (issue #55), with their IL to follow the ladder's.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StBlocks {
    /// Each `FUNCTION_BLOCK` whose inputs and outputs are all of
    /// elementary types (a box pin holds one value), in text order.
    pub blocks: Vec<UserBlock>,
    /// The `FUNCTION_BLOCK` sections of the IL the source lowers to.
    pub il: String,
    /// `places[n]`: the 1-based ST line line `n + 1` of `il` comes from
    /// (0 for none), to tell a ladder's steps in these blocks by their
    /// ST lines ([`StBlocks::step_lines`]).
    pub places: Vec<usize>,
    /// The source has a `PROGRAM` (else it is a library of blocks).
    pub program: bool,
}

/// The program a library (blocks without a `PROGRAM`) is lowered with:
/// the lowering needs one; its section is then left out.
const LIBRARY_PROGRAM: &str = "\nPROGRAM _hashigo_library\nEND_PROGRAM\n";

/// The function blocks `text` declares, once it loads as a whole (every
/// refusal at its line, as [`st_run`]'s). A text of blocks without a
/// `PROGRAM` loads too: the ladder calls them.
pub fn st_blocks(text: &str) -> Result<StBlocks, Vec<StLoadError>> {
    let source = parse_source(text).map_err(|e| vec![from_st(e)])?;
    let pous = || {
        source.items.iter().filter_map(|i| match i {
            Item::Pou(p) => Some(p),
            _ => None,
        })
    };
    let program = pous().any(|p| p.kind == PouKind::Program);
    let whole = if program {
        text.to_string()
    } else {
        format!("{text}{LIBRARY_PROGRAM}")
    };
    let (_, lowered) = load(&whole)?;
    let blocks = pous()
        .filter(|p| p.kind == PouKind::FunctionBlock)
        .filter_map(box_of)
        .collect();
    let (il, il_lines) = block_sections(&lowered.text);
    let places = il_lines
        .into_iter()
        .map(|n| lowered.place(n).line as usize)
        .collect();
    Ok(StBlocks {
        blocks,
        il,
        places,
        program,
    })
}

/// Whether `text` reads as Structured Text with a `PROGRAM` (what Load
/// and Run run; a text of blocks only leaves the ladder to run).
pub fn declares_program(text: &str) -> bool {
    parse_source(text).is_ok_and(|s| {
        s.items
            .iter()
            .any(|i| matches!(i, Item::Pou(p) if p.kind == PouKind::Program))
    })
}

/// Block `p`'s box: `None` when a pin is not of an elementary type, or
/// it has a `VAR_IN_OUT` (a box's pin gives or takes one value), or a box
/// of the soft PLC's own has its name (ADD, TON: that one stays).
fn box_of(p: &Pou) -> Option<UserBlock> {
    let name = p.name.name.to_ascii_uppercase();
    if crate::ladder::block::Shape::builtin(&name).is_some() {
        return None;
    }
    let mut inputs = Vec::new();
    let mut outputs = Vec::new();
    for block in &p.vars {
        let to = match block.kind {
            VarKind::Input => &mut inputs,
            VarKind::Output => &mut outputs,
            VarKind::InOut => return None,
            _ => continue,
        };
        for d in &block.decls {
            let ty = DataType::from_name(&type_text(&d.ty))?;
            to.extend(d.names.iter().map(|n| (n.name.clone(), ty)));
        }
    }
    Some(UserBlock {
        name,
        inputs,
        outputs,
    })
}

/// The `FUNCTION_BLOCK … END_FUNCTION_BLOCK` sections of a lowered text,
/// with the 1-based line of the lowered text each of their lines was.
fn block_sections(il: &str) -> (String, Vec<usize>) {
    let mut out = String::new();
    let mut lines = Vec::new();
    let mut inside = false;
    for (n, line) in il.lines().enumerate() {
        let word = line.split_whitespace().next().unwrap_or("");
        if word.eq_ignore_ascii_case("FUNCTION_BLOCK") {
            inside = true;
        }
        if inside {
            out.push_str(line);
            out.push('\n');
            lines.push(n + 1);
        }
        if word.eq_ignore_ascii_case("END_FUNCTION_BLOCK") {
            inside = false;
        }
    }
    (out, lines)
}
