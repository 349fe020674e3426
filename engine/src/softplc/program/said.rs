//! Errors each said once, found again by their line (issue #44): a long
//! run of untyped literals that do not fit their use gives an error at
//! each of its lines, and comparing each with every error before it
//! took N² (a hundred seconds for 100 000 lines in a debug build).

use std::collections::HashMap;

use super::{Errors, LoadError};
use crate::error::Located;

/// Errors in the order they were found, and where each line's are.
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct Said {
    errors: Errors,
    at: HashMap<usize, Vec<usize>>,
}

impl Said {
    /// `errors` as they are, indexed.
    pub fn new(errors: Errors) -> Said {
        let mut said = Said::default();
        for e in errors {
            said.push(e);
        }
        said
    }

    /// Whether `e` was said already (only its line's errors compared).
    pub fn contains(&self, e: &Located<LoadError>) -> bool {
        self.at
            .get(&e.line)
            .is_some_and(|ix| ix.iter().any(|&i| self.errors.get(i) == Some(e)))
    }

    /// `e` kept, said already or not.
    pub fn push(&mut self, e: Located<LoadError>) {
        self.at.entry(e.line).or_default().push(self.errors.len());
        self.errors.push(e);
    }

    /// `e` kept unless it was said already.
    pub fn push_new(&mut self, e: Located<LoadError>) {
        if !self.contains(&e) {
            self.push(e);
        }
    }

    /// `other`'s errors after these, as they are (`other` left empty).
    pub fn append(&mut self, other: &mut Said) {
        for e in std::mem::take(other).errors {
            self.push(e);
        }
    }

    /// Whether none was said.
    pub fn is_empty(&self) -> bool {
        self.errors.is_empty()
    }

    /// The errors, in the order they were found.
    pub fn into_errors(self) -> Errors {
        self.errors
    }
}

/// `late`'s errors after `errors`, each unless said already.
pub(super) fn after(errors: &mut Errors, late: Said) {
    if late.is_empty() {
        return;
    }
    let mut all = Said::new(std::mem::take(errors));
    for e in late.into_errors() {
        all.push_new(e);
    }
    *errors = all.into_errors();
}
