//! The sections of a soft PLC text (IEC 61131-3 POUs): the program's
//! own function blocks, `FUNCTION_BLOCK name` … `END_FUNCTION_BLOCK`,
//! and the program (everything else). Each section comes as the whole
//! text with every line of the others blanked, so every line keeps its
//! number for the readers of declarations and IL.

use std::fmt;

use crate::error::Located;
use crate::iec::is_identifier;

/// A function block the text defines.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BlockText {
    /// Its name as written.
    pub name: String,
    /// The text with only its section's lines (between its first and
    /// last line, both blanked).
    pub text: String,
    /// The line of `FUNCTION_BLOCK`.
    pub line: usize,
}

/// The text's sections.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Sections {
    /// The program: every line outside the function blocks.
    pub program: String,
    pub blocks: Vec<BlockText>,
}

/// Why the sections do not pair.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PouError {
    /// `FUNCTION_BLOCK` with no name, or not an IEC name.
    BadName(String),
    /// A function block inside another.
    Nested,
    /// `END_FUNCTION_BLOCK` with no `FUNCTION_BLOCK`.
    NoStart,
    /// A function block never ended (its name).
    NeverEnded(String),
    /// Two function blocks of one name (first on the line given).
    Duplicate { name: String, first: usize },
}

impl fmt::Display for PouError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PouError::BadName(n) => write!(f, "`{n}` is not a function block's name"),
            PouError::Nested => f.write_str("a FUNCTION_BLOCK inside another"),
            PouError::NoStart => f.write_str("END_FUNCTION_BLOCK without FUNCTION_BLOCK"),
            PouError::NeverEnded(n) => write!(f, "FUNCTION_BLOCK {n} has no END_FUNCTION_BLOCK"),
            PouError::Duplicate { name, first } => {
                write!(
                    f,
                    "function block {name} is defined twice (first on line {first})"
                )
            }
        }
    }
}

impl std::error::Error for PouError {}

/// The sections of `text`; every problem at its line.
pub fn split(text: &str) -> Result<Sections, Vec<Located<PouError>>> {
    let plain = crate::iec::comments::blank_long_comments(text);
    let lines: Vec<&str> = text.lines().collect();
    let mut owner: Vec<Option<usize>> = vec![None; lines.len()];
    let mut blocks: Vec<(String, usize, usize)> = Vec::new();
    let mut open: Option<(String, usize)> = None;
    let mut errors = Vec::new();
    for (i, raw) in plain.lines().enumerate() {
        let code = raw.split("(*").next().unwrap_or("").trim();
        let mut words = code.split_whitespace();
        let first = words.next().unwrap_or("").to_ascii_uppercase();
        match (first.as_str(), &open) {
            ("FUNCTION_BLOCK", None) => {
                let name = words.next().unwrap_or("").trim_end_matches(';').to_string();
                if !is_identifier(&name) || words.next().is_some() {
                    errors.push(Located::new(i + 1, PouError::BadName(name)));
                } else if let Some(first) = blocks.iter().find(|b| b.0.eq_ignore_ascii_case(&name))
                {
                    let first = first.1;
                    errors.push(Located::new(i + 1, PouError::Duplicate { name, first }));
                } else {
                    open = Some((name, i));
                }
            }
            ("FUNCTION_BLOCK", Some(_)) => errors.push(Located::new(i + 1, PouError::Nested)),
            ("END_FUNCTION_BLOCK", None) => errors.push(Located::new(i + 1, PouError::NoStart)),
            ("END_FUNCTION_BLOCK", Some(_)) => {
                if let Some((name, start)) = open.take() {
                    blocks.push((name, start + 1, i + 1));
                    for o in &mut owner[start..=i] {
                        *o = Some(blocks.len() - 1);
                    }
                }
            }
            _ => {}
        }
    }
    if let Some((name, start)) = open {
        errors.push(Located::new(start + 1, PouError::NeverEnded(name)));
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    let keep = |which: Option<usize>, bounds: Option<(usize, usize)>| -> String {
        let mut out = String::with_capacity(text.len());
        for (i, line) in lines.iter().enumerate() {
            let inside = owner[i] == which
                && bounds.is_none_or(|(first, last)| i + 1 != first && i + 1 != last);
            if inside {
                out.push_str(line);
            }
            out.push('\n');
        }
        out
    };
    Ok(Sections {
        program: keep(None, None),
        blocks: blocks
            .iter()
            .enumerate()
            .map(|(k, (name, first, last))| BlockText {
                name: name.clone(),
                text: keep(Some(k), Some((*first, *last))),
                line: *first,
            })
            .collect(),
    })
}
