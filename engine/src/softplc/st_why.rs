//! Why? into Structured Text (issue #55): the statements of an ST POU
//! that write a variable, each with its line and the names its value
//! reads, for the page to show with their values at the scan explained
//! (a coil fed by an ST block's box follows into the block's statement
//! that wrote the box's output; a variable of an ST program names the
//! statement that wrote it). Read from the text alone: which of several
//! writes ran is the caller's to tell (the trace of the steps each line
//! lowers to, [`super::Program::source_line`]).

use crate::iec::st::ast::Variable;
use crate::iec::st::ast::{Arg, Expr, ExprKind, Item, Pou, PouKind, Selector, Stmt, StmtKind};
use crate::iec::st::parse_source;

/// One statement that writes the variable asked about.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StWrite {
    /// Its 1-based line in the text.
    pub line: usize,
    /// That line as written, trimmed.
    pub statement: String,
    /// The names its value reads, in order, each once (`c0.OUT` for a
    /// block's output, an array by its name).
    pub reads: Vec<String>,
}

/// The statements of POU `pou` (any case; `None`: the text's `PROGRAM`)
/// in ST `text` that write `variable` (any case; `inst.pin` for a
/// member), in text order: assignments, and calls giving it a block's
/// output (`c0(OUT => n)`). None when the text does not parse or has no
/// such POU.
pub fn st_writes(text: &str, pou: Option<&str>, variable: &str) -> Vec<StWrite> {
    let Ok(source) = parse_source(text) else {
        return Vec::new();
    };
    let found = source.items.iter().find_map(|i| match i {
        Item::Pou(p) if chosen(p, pou) => Some(p),
        _ => None,
    });
    let Some(p) = found else {
        return Vec::new();
    };
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    let mut walk = Walk {
        variable: variable.trim(),
        lines: &lines,
        out: &mut out,
    };
    walk.statements(&p.body);
    out
}

/// Whether `p` is the POU asked for.
fn chosen(p: &Pou, pou: Option<&str>) -> bool {
    match pou {
        Some(name) => p.name.name.eq_ignore_ascii_case(name.trim()),
        None => p.kind == PouKind::Program,
    }
}

/// The walk over a body: what it looks for and what it found.
struct Walk<'a> {
    variable: &'a str,
    lines: &'a [&'a str],
    out: &'a mut Vec<StWrite>,
}

impl Walk<'_> {
    fn statements(&mut self, body: &[Stmt]) {
        for s in body {
            self.statement(s);
        }
    }

    fn statement(&mut self, s: &Stmt) {
        match &s.kind {
            StmtKind::Assign { target, value } => {
                if self.is_asked(target) {
                    let mut reads = Vec::new();
                    expr_reads(value, &mut reads);
                    self.found(s, reads);
                }
            }
            StmtKind::Call(call) => {
                for a in &call.args {
                    if let Arg::Output { name, target, .. } = a {
                        if self.is_asked(target) {
                            self.found(s, vec![format!("{}.{}", call.callee.name, name.name)]);
                        }
                    }
                }
            }
            StmtKind::If {
                branches,
                otherwise,
            } => {
                for (_, body) in branches {
                    self.statements(body);
                }
                if let Some(body) = otherwise {
                    self.statements(body);
                }
            }
            StmtKind::Case {
                arms, otherwise, ..
            } => {
                for arm in arms {
                    self.statements(&arm.body);
                }
                if let Some(body) = otherwise {
                    self.statements(body);
                }
            }
            StmtKind::For { body, .. }
            | StmtKind::While { body, .. }
            | StmtKind::Repeat { body, .. } => self.statements(body),
            StmtKind::Exit | StmtKind::Return | StmtKind::Empty => {}
        }
    }

    /// Whether `target` is the variable asked about.
    fn is_asked(&self, target: &Variable) -> bool {
        name_of(target).is_some_and(|n| n.eq_ignore_ascii_case(self.variable))
    }

    fn found(&mut self, s: &Stmt, reads: Vec<String>) {
        let line = s.span.line as usize;
        let statement = self
            .lines
            .get(line.wrapping_sub(1))
            .map_or_else(String::new, |l| l.trim().to_string());
        self.out.push(StWrite {
            line,
            statement,
            reads,
        });
    }
}

/// A variable's name as the soft PLC names it: `a`, `inst.pin`; `None`
/// for an array's element (its index is not known here).
fn name_of(v: &Variable) -> Option<String> {
    let mut name = v.base.name.clone();
    for s in &v.path {
        match s {
            Selector::Member(m) => {
                name.push('.');
                name.push_str(&m.name);
            }
            Selector::Index(_) => return None,
        }
    }
    Some(name)
}

/// The names `e` reads, added to `out` once each, in order.
fn expr_reads(e: &Expr, out: &mut Vec<String>) {
    match &e.kind {
        ExprKind::Literal(_) => {}
        ExprKind::Variable(v) => {
            let name = name_of(v).unwrap_or_else(|| v.base.name.clone());
            if !out.iter().any(|n| n.eq_ignore_ascii_case(&name)) {
                out.push(name);
            }
            for s in &v.path {
                if let Selector::Index(ix) = s {
                    for i in ix {
                        expr_reads(i, out);
                    }
                }
            }
        }
        ExprKind::Call(call) => {
            for a in &call.args {
                match a {
                    Arg::Positional(x) | Arg::Input(_, x) => expr_reads(x, out),
                    Arg::Output { .. } => {}
                }
            }
        }
        ExprKind::Unary(_, x) => expr_reads(x, out),
        ExprKind::Binary(_, a, b) => {
            expr_reads(a, out);
            expr_reads(b, out);
        }
    }
}

#[cfg(test)]
mod tests;
