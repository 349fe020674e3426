//! The program's own function blocks (`FUNCTION_BLOCK … END_FUNCTION_BLOCK`):
//! each instance gets its own variables (shown as `instance.name`) and
//! its own copy of the body's steps, after the program's; a `CAL` of an
//! instance copies its inputs in, runs that body as a subroutine and
//! copies its outputs out. A block stays a block: the calling program
//! keeps its `CAL`, the listing its section.

use std::collections::HashMap;

use super::{CallWhy, Errors, LoadError, Named, Program, Step};
use crate::error::Located;
use crate::iec::il::Line;
use crate::iec::vars::Direction;
use crate::iec::vars::Kind;
use crate::iec::vars::Variable;

/// How deeply instances may hold instances (a block holding an instance
/// of itself would never end).
pub const MAX_BLOCK_NESTING: usize = 8;

/// Most instances of the program's own blocks, and most steps their
/// bodies may add in all (each instance has its own copy): a text that
/// nests ten instances eight deep is refused, not built.
pub const MAX_INSTANCES: usize = 10_000;
pub const MAX_BODY_STEPS: usize = 2_000_000;

/// Most variables (values and block instances) the instances of the
/// program's own blocks may hold in all: counted before any is made, so
/// a short text of nested instances is refused, not built until memory
/// runs out.
pub const MAX_INSTANCE_VARIABLES: u64 = 200_000;

/// One of the program's own function blocks as read.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct UserType {
    pub name: String,
    pub vars: Vec<Variable>,
    /// The line declaring each of `vars`.
    pub var_lines: Vec<usize>,
    pub lines: Vec<Line>,
    /// The line of its `FUNCTION_BLOCK`.
    pub line: usize,
}

/// What one instance of a block holds, all its own instances with it.
#[derive(Clone, Copy, Debug)]
struct Size {
    variables: u64,
    instances: u64,
    /// How deep its instances nest (1: none).
    height: usize,
}

/// The block type a declaration names, if it is a block instance.
fn block_of(v: &Variable) -> Option<&str> {
    match &v.kind {
        Kind::Block(b) => Some(b),
        Kind::Value { .. } => None,
    }
}

/// One instance: its type, its names, its inputs' and outputs' slots.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct UserInstance {
    pub(in crate::softplc) ty: usize,
    /// Its name as the front ends show it (`c0`, `c0.inner`).
    name: String,
    scope: HashMap<String, Named>,
    pub(super) inputs: Vec<(String, usize)>,
    pub(super) outputs: Vec<(String, usize)>,
}

/// One instance of the program's own blocks and the steps of its body
/// (each instance runs a copy of its own): a step in `steps` runs in
/// that instance's call.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InstanceBody {
    /// The instance as the front ends name it (`c0`, `c0.inner`).
    pub name: String,
    /// Its block's name as declared (`Scale`).
    pub block: String,
    /// Its body's steps, its return included.
    pub steps: std::ops::Range<usize>,
}

impl Program {
    /// Each instance of the program's own blocks with its body's steps,
    /// in the order they were made (an instance's own instances just before
    /// it): the
    /// page tells by it which call a step runs in (issue #55).
    pub fn instance_bodies(&self) -> Vec<InstanceBody> {
        let ends = self.entries.iter().skip(1).copied();
        let ends = ends.chain(std::iter::once(self.steps.len()));
        self.instances
            .iter()
            .zip(self.entries.iter().zip(ends))
            .map(|(u, (&start, end))| InstanceBody {
                name: u.name.clone(),
                block: self
                    .user_types
                    .get(u.ty)
                    .map_or_else(String::new, |t| t.name.clone()),
                steps: start..end,
            })
            .collect()
    }

    /// The text line each step was read from, in step order (`None` for
    /// the steps the loader adds: the program's end before its blocks'
    /// bodies, each body's return). The page maps a step to its source
    /// line so (a Structured Text line through its IL, issue #55).
    pub fn step_lines(&self) -> Vec<Option<usize>> {
        let mut out: Vec<Option<usize>> = self.lines.iter().map(|l| Some(l.line)).collect();
        for (entry, instance) in self.entries.iter().zip(&self.instances) {
            out.resize(*entry, None);
            if let Some(t) = self.user_types.get(instance.ty) {
                out.extend(t.lines.iter().map(|l| Some(l.line)));
            }
        }
        out.resize(self.steps.len(), None);
        out
    }

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
            return Err(LoadError::Call(CallWhy::Instances(shown.to_string())));
        }
        if depth >= MAX_BLOCK_NESTING {
            return Err(LoadError::Call(CallWhy::Nesting {
                name: shown.to_string(),
                holds: Some(self.user_types[ty].name.clone()),
            }));
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
            name: shown.to_string(),
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
                errors.push(Located::new(t.line, LoadError::Call(CallWhy::BodySteps)));
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

    /// Checks, before any instance is made, that the program's
    /// declarations (`vars`, each with its line) hold no block that holds
    /// itself or nests too deep, and that their instances' variables and
    /// instances stay within the limits: the first declaration that does
    /// not, at its line.
    pub(super) fn budget(&self, vars: &[(Variable, usize)]) -> Result<(), Located<LoadError>> {
        let mut sizes: HashMap<usize, Size> = HashMap::new();
        let (mut variables, mut instances) = (0u64, 0u64);
        for (v, line) in vars {
            let Some(ty) = block_of(v).and_then(|b| self.user_type(b)) else {
                continue;
            };
            let size = self.size(ty, &mut sizes, &mut Vec::new())?;
            if size.height > MAX_BLOCK_NESTING {
                return Err(Located::new(
                    *line,
                    LoadError::Call(CallWhy::Nesting {
                        name: v.name.clone(),
                        holds: None,
                    }),
                ));
            }
            variables = variables.saturating_add(size.variables);
            instances = instances.saturating_add(size.instances);
            let over = if instances > MAX_INSTANCES as u64 {
                CallWhy::Instances(v.name.clone())
            } else if variables > MAX_INSTANCE_VARIABLES {
                CallWhy::Variables(v.name.clone())
            } else {
                continue;
            };
            return Err(Located::new(*line, LoadError::Call(over)));
        }
        Ok(())
    }

    /// What one instance of type `ty` holds (memoized in `sizes`;
    /// `inside` the types being counted, to find a block that holds
    /// itself, refused at that declaration's line).
    fn size(
        &self,
        ty: usize,
        sizes: &mut HashMap<usize, Size>,
        inside: &mut Vec<usize>,
    ) -> Result<Size, Located<LoadError>> {
        if let Some(&s) = sizes.get(&ty) {
            return Ok(s);
        }
        inside.push(ty);
        let t = &self.user_types[ty];
        let mut size = Size {
            variables: 0,
            instances: 1,
            height: 1,
        };
        for (v, &line) in t.vars.iter().zip(&t.var_lines) {
            size.variables = size.variables.saturating_add(1);
            let Some(inner) = block_of(v).and_then(|b| self.user_type(b)) else {
                continue;
            };
            if inside.contains(&inner) {
                return Err(Located::new(
                    line,
                    LoadError::Call(CallWhy::Nesting {
                        name: v.name.clone(),
                        holds: Some(self.user_types[inner].name.clone()),
                    }),
                ));
            }
            let s = self.size(inner, sizes, inside)?;
            size.variables = size.variables.saturating_add(s.variables);
            size.instances = size.instances.saturating_add(s.instances);
            size.height = size.height.max(s.height + 1);
        }
        inside.pop();
        sizes.insert(ty, size);
        Ok(size)
    }

    /// The program's own function blocks as read (for the listing).
    pub(crate) fn user_types(&self) -> &[UserType] {
        &self.user_types
    }
}
