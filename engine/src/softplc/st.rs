//! Structured Text on the soft PLC: a `.st` text read, checked and
//! lowered to IL (`iec::st::lower`), then loaded as IL is, so it runs
//! through the one scan. What the IL loader refuses is said at the ST
//! line and column the IL line comes from.

use std::fmt;

use super::{LoadError, Program};
use crate::iec::st::{check_source, lower_source, parse_source, StError, StErrorKind};

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
    let (_, il) = load(text)?;
    Ok(il)
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
}

/// [`st_to_il`] with each step's ST line ([`Program::source_line`]).
pub fn st_run(text: &str) -> Result<StRun, Vec<StLoadError>> {
    let (program, il) = load(text)?;
    let lines = (0..program.len())
        .map(|step| program.source_line(step).map(|(line, _)| line as usize))
        .collect();
    Ok(StRun { il, lines })
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

fn load(text: &str) -> Result<(Program, String), Vec<StLoadError>> {
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
    Ok((program, lowered.text))
}
