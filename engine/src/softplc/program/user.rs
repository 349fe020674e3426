//! The program's own function blocks (`FUNCTION_BLOCK … END_FUNCTION_BLOCK`):
//! each instance gets its own variables (shown as `instance.name`) and
//! its own copy of the body's steps, after the program's; a `CAL` of an
//! instance copies its inputs in, runs that body as a subroutine and
//! copies its outputs out. A block stays a block: the calling program
//! keeps its `CAL`, the listing its section.

use std::collections::HashMap;

use super::{Errors, LoadError, Named, Program, Step};
use crate::error::Located;
use crate::softplc::il::Line;
use crate::softplc::vars::{Direction, Variable};

/// How deeply instances may hold instances (a block holding an instance
/// of itself would never end).
pub(crate) const MAX_BLOCK_NESTING: usize = 8;

/// Most instances of the program's own blocks, and most steps their
/// bodies may add in all (each instance has its own copy): a text that
/// nests ten instances eight deep is refused, not built.
pub(crate) const MAX_INSTANCES: usize = 10_000;
pub(crate) const MAX_BODY_STEPS: usize = 2_000_000;

/// One of the program's own function blocks as read.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct UserType {
    pub name: String,
    pub vars: Vec<Variable>,
    pub lines: Vec<Line>,
    /// The line of its `FUNCTION_BLOCK`.
    pub line: usize,
}

/// One instance: its type, its names, its inputs' and outputs' slots.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct UserInstance {
    pub(super) ty: usize,
    scope: HashMap<String, Named>,
    pub(super) inputs: Vec<(String, usize)>,
    pub(super) outputs: Vec<(String, usize)>,
}

impl Program {
    /// The program's own block type named `name` (any case).
    pub(super) fn user_type(&self, name: &str) -> Option<usize> {
        self.user_types
            .iter()
            .position(|t| t.name.eq_ignore_ascii_case(name))
    }

    /// A new instance of type `ty` shown as `shown`: its variables,
    /// blocks and instances declared in a scope of their own.
    pub(super) fn instantiate(
        &mut self,
        shown: &str,
        ty: usize,
        depth: usize,
    ) -> Result<usize, LoadError> {
        if self.instances.len() >= MAX_INSTANCES {
            return Err(LoadError::Call(format!(
                "{shown}: more than {MAX_INSTANCES} instances of the program's own blocks (docs/limits.md)"
            )));
        }
        if depth >= MAX_BLOCK_NESTING {
            return Err(LoadError::Call(format!(
                "{shown}: function blocks hold instances more than {MAX_BLOCK_NESTING} deep (does {} hold itself?)",
                self.user_types[ty].name
            )));
        }
        let vars = self.user_types[ty].vars.clone();
        let outer = std::mem::take(&mut self.by_name);
        let declared = self.declare(&vars, &format!("{shown}."), depth + 1);
        let scope = std::mem::replace(&mut self.by_name, outer);
        declared?;
        let faced = |d: Direction| -> Vec<(String, usize)> {
            vars.iter()
                .filter(|v| v.direction == d)
                .filter_map(|v| match scope.get(&v.name.to_ascii_uppercase()) {
                    Some(&Named::Slot(s)) => Some((v.name.clone(), s)),
                    _ => None,
                })
                .collect()
        };
        let (inputs, outputs) = (faced(Direction::Input), faced(Direction::Output));
        // The front ends name what is inside: `c0.count`, `c0.t.Q`.
        let prefix = shown.to_ascii_uppercase();
        for (k, named) in &scope {
            self.by_name.insert(format!("{prefix}.{k}"), *named);
        }
        self.instances.push(UserInstance {
            ty,
            scope,
            inputs,
            outputs,
        });
        Ok(self.instances.len() - 1)
    }

    /// Each instance's body, after the program's steps, ending with
    /// [`Step::Return`]; a body's errors said once however many
    /// instances it has.
    pub(super) fn compile_bodies(&mut self, errors: &mut Errors) {
        let program = self.steps.len();
        for u in 0..self.instances.len() {
            if self.steps.len() - program > MAX_BODY_STEPS {
                let t = &self.user_types[self.instances[u].ty];
                errors.push(Located::new(
                    t.line,
                    LoadError::Call(format!(
                        "the blocks' bodies need more than {MAX_BODY_STEPS} steps for their instances (docs/limits.md)"
                    )),
                ));
                return;
            }
            self.entries.push(self.steps.len());
            let ty = self.instances[u].ty;
            let lines = self.user_types[ty].lines.clone();
            let scope = self.instances[u].scope.clone();
            let outer = std::mem::replace(&mut self.by_name, scope);
            let mut found = Vec::new();
            self.compile_lines(&lines, &mut found);
            self.by_name = outer;
            for e in found {
                if !errors.contains(&e) {
                    errors.push(e);
                }
            }
            self.steps.push(Step::Return);
        }
    }

    /// The program's own function blocks as read (for the listing).
    pub(crate) fn user_types(&self) -> &[UserType] {
        &self.user_types
    }
}
