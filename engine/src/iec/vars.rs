//! The variables a soft PLC program declares: its text's `VAR … END_VAR`
//! header (IEC 61131-3), one declaration a line:
//!
//! ```text
//! VAR
//!   start AT %IX0.0 : BOOL;      (* start button *)
//!   count : INT := 5;
//!   delay : TON;
//! END_VAR
//! VAR_RETAIN
//!   total : UDINT;
//! END_VAR
//! ```
//!
//! Names are compared without regard to case, as IEC does; each error
//! names its line.

use std::fmt;

use crate::error::Located;
use crate::iec::address::{Address, AddressError};
use crate::iec::data::{Data, DataType, STRING_CAPACITY};
use crate::iec::is_identifier;
use crate::iec::literal::{parse_literal, LiteralError};
use crate::iec::pins::is_block_type;

/// What a variable holds.
#[derive(Clone, Debug, PartialEq)]
pub enum Kind {
    /// A value of an elementary type, starting at `init`.
    Value { data_type: DataType, init: Data },
    /// An instance of a standard function block (its name upper-case).
    Block(String),
}

/// Which way a function block's variable faces (a program's are local).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Direction {
    /// `VAR`, `VAR_RETAIN`, `VAR_TEMP`.
    #[default]
    Local,
    /// `VAR_INPUT`: a call's `name := value`.
    Input,
    /// `VAR_OUTPUT`: a call's `name => variable`.
    Output,
}

/// One declared variable.
#[derive(Clone, Debug, PartialEq)]
pub struct Variable {
    /// As written.
    pub name: String,
    pub kind: Kind,
    /// Where it is located, for `AT %…`.
    pub address: Option<Address>,
    /// Declared in `VAR_RETAIN` (or `VAR RETAIN`): kept over a power cycle.
    pub retain: bool,
    /// A function block's input or output (its `VAR_INPUT` /
    /// `VAR_OUTPUT`).
    pub direction: Direction,
    /// The `(* … *)` after it on its line, trimmed.
    pub comment: String,
}

/// Why a declaration is not one.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum VarError {
    /// Not `name [AT address] : TYPE [:= value];`.
    Syntax(String),
    /// A name that is not an IEC identifier.
    BadName(String),
    /// The name was declared before (on the line given).
    Duplicate {
        name: String,
        first: usize,
    },
    /// No elementary type or standard block of that name.
    UnknownType(String),
    /// `STRING[n]`: the soft PLC's STRINGs all hold up to
    /// [`STRING_CAPACITY`] characters.
    StringLength(String),
    Address(AddressError),
    Literal(LiteralError),
    /// A block instance cannot be located or given a value.
    BlockWithValue(String),
    /// `VAR` with no `END_VAR`, or `END_VAR` with no `VAR`.
    Unbalanced(String),
}

impl fmt::Display for VarError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            VarError::Syntax(l) => write!(
                f,
                "`{l}` is not a declaration (name [AT %address] : TYPE [:= value];)"
            ),
            VarError::BadName(n) => write!(
                f,
                "`{n}` is not a name (a letter or _, then letters, digits, _)"
            ),
            VarError::Duplicate { name, first } => {
                write!(f, "`{name}` is declared twice (first on line {first})")
            }
            VarError::UnknownType(t) => write!(f, "unknown type `{t}`"),
            VarError::StringLength(t) => write!(
                f,
                "`{t}`: write STRING without a length (every STRING holds up to {STRING_CAPACITY} characters)"
            ),
            VarError::Address(e) => e.fmt(f),
            VarError::Literal(e) => e.fmt(f),
            VarError::BlockWithValue(n) => {
                write!(f, "`{n}` is a function block: it has no address or value")
            }
            VarError::Unbalanced(w) => write!(f, "`{w}` without its pair"),
        }
    }
}

impl std::error::Error for VarError {}

/// Reads the `VAR … END_VAR` blocks of `text` (lines outside them are not
/// looked at: the program's body). Every error is given, at its line
/// (1-based); the variables only when there is none.
pub fn parse_vars(text: &str) -> Result<Vec<Variable>, Vec<Located<VarError>>> {
    parse_vars_with(text, &[])
}

/// [`parse_vars`] where `blocks` are the text's own function blocks
/// (types a variable may have besides the standard ones).
pub fn parse_vars_with(
    text: &str,
    blocks: &[String],
) -> Result<Vec<Variable>, Vec<Located<VarError>>> {
    parse_vars_at(text, blocks).map(|vars| vars.into_iter().map(|(v, _)| v).collect())
}

/// [`parse_vars_with`], each variable with the line that declares it.
pub fn parse_vars_at(
    text: &str,
    blocks: &[String],
) -> Result<Vec<(Variable, usize)>, Vec<Located<VarError>>> {
    let mut vars: Vec<(Variable, usize)> = Vec::new();
    let mut errors = Vec::new();
    let mut open: Option<(bool, Direction, usize)> = None; // (retain, direction, line)
    let text = super::comments::blank_long_comments(text);
    // Each name (upper-case) and the line that declares it.
    let mut seen: std::collections::HashMap<String, usize> = std::collections::HashMap::new();
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let (code, comment) = split_comment(raw);
        let code = code.trim();
        let word = code.trim_end_matches(';').to_ascii_uppercase();
        if let Some(header) = header(&word) {
            if open.is_some() {
                errors.push(Located::new(line, VarError::Unbalanced(code.to_string())));
            } else {
                open = Some((header.0, header.1, line));
            }
            continue;
        }
        if word == "END_VAR" {
            if open.take().is_none() {
                errors.push(Located::new(line, VarError::Unbalanced(code.to_string())));
            }
            continue;
        }
        let Some((retain, direction, _)) = open else {
            continue;
        };
        if code.is_empty() {
            continue;
        }
        match declaration(code, retain, comment, blocks) {
            Ok(mut v) => {
                v.direction = direction;
                if let Some(&first) = seen.get(&v.name.to_ascii_uppercase()) {
                    errors.push(Located::new(
                        line,
                        VarError::Duplicate {
                            name: v.name,
                            first,
                        },
                    ));
                } else {
                    seen.insert(v.name.to_ascii_uppercase(), line);
                    vars.push((v, line));
                }
            }
            Err(e) => errors.push(Located::new(line, e)),
        }
    }
    if let Some((retain, _, line)) = open {
        let word = if retain { "VAR_RETAIN" } else { "VAR" };
        errors.push(Located::new(line, VarError::Unbalanced(word.to_string())));
    }
    if errors.is_empty() {
        Ok(vars)
    } else {
        Err(errors)
    }
}

/// A declaration block's header: whether it retains, which way it faces.
pub(super) fn header(word: &str) -> Option<(bool, Direction)> {
    Some(match word {
        "VAR" | "VAR_TEMP" => (false, Direction::Local),
        "VAR_RETAIN" | "VAR RETAIN" => (true, Direction::Local),
        "VAR_INPUT" => (false, Direction::Input),
        "VAR_OUTPUT" => (false, Direction::Output),
        _ => return None,
    })
}

/// `code` without a trailing `(* … *)`, and that comment's text.
fn split_comment(line: &str) -> (&str, String) {
    match line.find("(*") {
        Some(at) => {
            let inner = &line[at + 2..];
            let inner = inner.split("*)").next().unwrap_or(inner);
            (&line[..at], inner.trim().to_string())
        }
        None => (line, String::new()),
    }
}

/// One `name [AT address] : TYPE [:= value];`.
fn declaration(
    code: &str,
    retain: bool,
    comment: String,
    blocks: &[String],
) -> Result<Variable, VarError> {
    let syntax = || VarError::Syntax(code.to_string());
    let body = code.strip_suffix(';').ok_or_else(syntax)?.trim();
    let (head, value) = match body.split_once(":=") {
        Some((h, v)) => (h.trim(), Some(v.trim())),
        None => (body, None),
    };
    let (left, type_name) = head.rsplit_once(':').ok_or_else(syntax)?;
    let type_name = type_name.trim();
    let mut words = left.split_whitespace();
    let name = words.next().ok_or_else(syntax)?.to_string();
    if !is_identifier(&name) {
        return Err(VarError::BadName(name));
    }
    let address = match (words.next(), words.next(), words.next()) {
        (None, _, _) => None,
        (Some(at), Some(addr), None) if at.eq_ignore_ascii_case("AT") => {
            Some(Address::parse(addr).map_err(VarError::Address)?)
        }
        _ => return Err(syntax()),
    };
    let kind = match DataType::from_name(type_name) {
        Some(data_type) => {
            let init = match value {
                Some(v) => parse_literal(v, Some(data_type)).map_err(VarError::Literal)?,
                None => data_type.zero(),
            };
            if let Some(a) = address {
                a.for_type(data_type).map_err(VarError::Address)?;
            }
            Kind::Value { data_type, init }
        }
        None => {
            let upper = type_name.to_ascii_uppercase();
            let own = blocks.iter().any(|b| b.eq_ignore_ascii_case(type_name));
            if !is_block_type(&upper) && !own {
                return Err(match upper.strip_prefix("STRING") {
                    Some(length) if length.trim_start().starts_with('[') => {
                        VarError::StringLength(type_name.to_string())
                    }
                    _ => VarError::UnknownType(type_name.to_string()),
                });
            }
            if address.is_some() || value.is_some() {
                return Err(VarError::BlockWithValue(name));
            }
            Kind::Block(upper)
        }
    };
    Ok(Variable {
        name,
        kind,
        address,
        retain,
        direction: Direction::Local,
        comment,
    })
}

#[cfg(test)]
mod tests;
