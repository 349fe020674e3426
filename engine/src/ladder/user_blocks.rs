//! The project's own function blocks as ladder boxes (issue #55): the
//! Structured Text blocks a soft PLC ladder may call, by name, beside the
//! standard ones ([`crate::iec::pins`]).
//!
//! The page declares them ([`set`]) once the project's ST text loads
//! without errors; every layer of the ladder (the device entry, the
//! checks, the IL compiler, the live view) asks a box's pins through
//! [`inputs`] and [`outputs`], which answer the standard blocks first. A
//! box whose kind is no longer declared is an unknown kind: an error at
//! its cell, the ladder kept. The blocks' IL ([`code`]) follows the
//! ladder's when the soft PLC compiles it.
//!
//! The table is per thread: the page has one; each test thread its own.

use std::cell::RefCell;
use std::collections::HashSet;

use crate::iec::data::DataType;
use crate::iec::pins;

/// One function block of the project's own, as a box sees it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UserBlock {
    /// Its name, upper-case (the box's kind).
    pub name: String,
    /// Its `VAR_INPUT`s (name, type) in order.
    pub inputs: Vec<(String, DataType)>,
    /// Its `VAR_OUTPUT`s (name, type) in order.
    pub outputs: Vec<(String, DataType)>,
}

/// A block with its pins' names made `'static` (as the standard ones).
struct Known {
    name: String,
    inputs: Vec<(&'static str, DataType)>,
    outputs: Vec<(&'static str, DataType)>,
}

#[derive(Default)]
struct Table {
    blocks: Vec<Known>,
    declared: Vec<UserBlock>,
    code: String,
    /// Every pin name ever declared, kept once: a pin's `&'static str`.
    names: HashSet<&'static str>,
}

thread_local! {
    static TABLE: RefCell<Table> = RefCell::new(Table::default());
}

impl Table {
    fn intern(&mut self, name: &str) -> &'static str {
        if let Some(n) = self.names.get(name) {
            return n;
        }
        // Bounded by the pin names the user ever declares: leaked once,
        // so the pins read as the standard blocks' `&'static str`.
        let n: &'static str = Box::leak(name.to_string().into_boxed_str());
        self.names.insert(n);
        n
    }
}

/// Declares the project's own blocks and their IL (`FUNCTION_BLOCK`
/// sections), replacing those declared before; true when they changed.
/// A standard block's name (TON) is left out: the standard one stays
/// (the functions' names are left out by who declares them:
/// `softplc::st::st_blocks`).
pub fn set(blocks: Vec<UserBlock>, code: String) -> bool {
    TABLE.with(|t| {
        let mut t = t.borrow_mut();
        if t.declared == blocks && t.code == code {
            return false;
        }
        let mut known = Vec::new();
        for b in &blocks {
            let name = b.name.to_ascii_uppercase();
            if pins::is_block_type(&name) {
                continue;
            }
            let mut pins = |l: &[(String, DataType)]| -> Vec<(&'static str, DataType)> {
                l.iter().map(|(p, ty)| (t.intern(p), *ty)).collect()
            };
            let inputs = pins(&b.inputs);
            let outputs = pins(&b.outputs);
            known.push(Known {
                name,
                inputs,
                outputs,
            });
        }
        t.blocks = known;
        t.declared = blocks;
        t.code = code;
        true
    })
}

/// `text` as a `&'static str`, kept once (what a front end's tables of
/// `&'static str` show a block by: the palette's items).
pub fn intern(text: &str) -> &'static str {
    TABLE.with(|t| t.borrow_mut().intern(text))
}

/// The blocks declared ([`set`]), as given.
pub fn declared() -> Vec<UserBlock> {
    TABLE.with(|t| t.borrow().declared.clone())
}

/// The declared blocks' IL, to follow a program that calls them (empty
/// when none is declared).
pub fn code() -> String {
    TABLE.with(|t| t.borrow().code.clone())
}

/// Whether `kind` (any case) is one of the project's own blocks.
pub fn is_user_block(kind: &str) -> bool {
    TABLE.with(|t| {
        t.borrow()
            .blocks
            .iter()
            .any(|b| b.name.eq_ignore_ascii_case(kind))
    })
}

/// Whether `kind` (upper-case) is a function block: a standard one or
/// the project's own.
pub fn is_block_type(kind: &str) -> bool {
    pins::is_block_type(kind) || is_user_block(kind)
}

/// A block's inputs (name, type), in order: the standard block's, else
/// the project's own.
pub fn inputs(kind: &str) -> Vec<(&'static str, DataType)> {
    if pins::is_block_type(kind) {
        return pins::inputs(kind);
    }
    own(kind, |b| b.inputs.clone())
}

/// A block's outputs (name, type), in order: the standard block's, else
/// the project's own.
pub fn outputs(kind: &str) -> Vec<(&'static str, DataType)> {
    if pins::is_block_type(kind) {
        return pins::outputs(kind);
    }
    own(kind, |b| b.outputs.clone())
}

fn own(
    kind: &str,
    f: impl Fn(&Known) -> Vec<(&'static str, DataType)>,
) -> Vec<(&'static str, DataType)> {
    TABLE.with(|t| {
        t.borrow()
            .blocks
            .iter()
            .find(|b| b.name.eq_ignore_ascii_case(kind))
            .map(f)
            .unwrap_or_default()
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scale() -> UserBlock {
        UserBlock {
            name: "SCALE".into(),
            inputs: vec![("go".into(), DataType::Bool), ("x".into(), DataType::Int)],
            outputs: vec![("y".into(), DataType::Int)],
        }
    }

    #[test]
    fn the_projects_blocks_answer_after_the_standard_ones() {
        assert!(set(vec![scale()], "FUNCTION_BLOCK SCALE\n".into()));
        assert!(
            !set(vec![scale()], "FUNCTION_BLOCK SCALE\n".into()),
            "unchanged"
        );
        assert!(is_block_type("SCALE") && is_user_block("scale"));
        assert_eq!(
            inputs("SCALE"),
            [("go", DataType::Bool), ("x", DataType::Int)]
        );
        assert_eq!(outputs("SCALE"), [("y", DataType::Int)]);
        assert_eq!(inputs("TON"), pins::inputs("TON"));
        // A standard name is never taken over.
        let ton = UserBlock {
            name: "ton".into(),
            ..scale()
        };
        set(vec![ton], String::new());
        assert_eq!(inputs("TON"), pins::inputs("TON"));
        assert!(!is_user_block("TON"));
        set(Vec::new(), String::new());
        assert!(!is_block_type("SCALE") && inputs("SCALE").is_empty());
    }
}
