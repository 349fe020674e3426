//! Several `PROGRAM`s in one Structured Text source (issue #55): they
//! run one after the other in one IL program, in text order (a PLCopen
//! project's ST is written in its tasks' order, `formats::plcopen::
//! st_source`), and each keeps its own variables. A later program's
//! variable whose name an earlier program or a global already declares
//! is renamed `<program>_<name>` (as a PLCopen project's programs are on
//! the soft PLC, `formats::plcopen::soft::declare`), everywhere its
//! program uses it; [`Renamed`] tells a front end which name of which
//! lines is which variable.

use std::collections::{HashMap, HashSet};

use super::ast::{Arg, Call, CaseLabel, Expr, ExprKind, Item, Pou, Selector, Source, Stmt};
use super::ast::{StmtKind, VarKind, Variable};

/// A variable of one program renamed in the IL: on the ST lines
/// `first..=last` (its program's), `name` is `il_name`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Renamed {
    /// The program's first line (1-based).
    pub first: usize,
    /// Its last line (the line before the next item; `usize::MAX` for
    /// the last item of the text).
    pub last: usize,
    /// The name as the ST writes it.
    pub name: String,
    /// The name the IL program knows it by.
    pub il_name: String,
}

/// The source's programs in text order, each later one with its
/// variables renamed where an earlier program or a global has their
/// names; the renames. `taken`: every name the source declares (upper
/// case), which gets the new names too.
pub(super) fn programs(source: &Source, taken: &mut HashSet<String>) -> (Vec<Pou>, Vec<Renamed>) {
    let mut seen: HashSet<String> = source
        .items
        .iter()
        .filter_map(|i| match i {
            Item::Globals(b) => Some(b),
            _ => None,
        })
        .flat_map(|b| &b.decls)
        .flat_map(|d| &d.names)
        .map(|n| n.name.to_ascii_uppercase())
        .collect();
    let starts = item_starts(source);
    let mut out = Vec::new();
    let mut renames = Vec::new();
    for (index, item) in source.items.iter().enumerate() {
        let Item::Pou(p) = item else { continue };
        if p.kind != super::ast::PouKind::Program {
            continue;
        }
        let own = own_names(p);
        let mut map = HashMap::new();
        if !out.is_empty() {
            for name in own
                .iter()
                .filter(|n| seen.contains(&n.to_ascii_uppercase()))
            {
                let il_name = fresh(&format!("{}_{name}", p.name.name), taken);
                map.insert(name.to_ascii_uppercase(), il_name.clone());
                renames.push(Renamed {
                    first: p.span.line as usize,
                    last: starts[index + 1..]
                        .iter()
                        .flatten()
                        .next()
                        .map_or(usize::MAX, |s| s.saturating_sub(1)),
                    name: name.clone(),
                    il_name,
                });
            }
        }
        seen.extend(own.iter().map(|n| n.to_ascii_uppercase()));
        let mut p = p.clone();
        if !map.is_empty() {
            rename_pou(&mut p, &map);
        }
        out.push(p);
    }
    (out, renames)
}

/// The first line of each item (`None`: an empty `TYPE` block).
fn item_starts(source: &Source) -> Vec<Option<usize>> {
    source
        .items
        .iter()
        .map(|i| match i {
            Item::Pou(p) => Some(p.span.line),
            Item::Globals(b) => Some(b.span.line),
            Item::Types(ts) => ts.first().map(|t| t.name.span.line),
        })
        .map(|l| l.map(|l| l as usize))
        .collect()
}

/// A program's own variables (not the globals it reaches), as written.
fn own_names(p: &Pou) -> Vec<String> {
    p.vars
        .iter()
        .filter(|b| b.kind != VarKind::External)
        .flat_map(|b| &b.decls)
        .flat_map(|d| &d.names)
        .map(|n| n.name.clone())
        .collect()
}

/// `wanted`, or it with `_` added until no name of the source is it.
fn fresh(wanted: &str, taken: &mut HashSet<String>) -> String {
    let mut name = wanted.to_string();
    while !taken.insert(name.to_ascii_uppercase()) {
        name.push('_');
    }
    name
}

type Map = HashMap<String, String>;

fn rename_name(name: &mut String, map: &Map) {
    if let Some(to) = map.get(&name.to_ascii_uppercase()) {
        *name = to.clone();
    }
}

fn rename_pou(p: &mut Pou, map: &Map) {
    for b in &mut p.vars {
        if b.kind == VarKind::External {
            continue;
        }
        for d in &mut b.decls {
            for n in &mut d.names {
                rename_name(&mut n.name, map);
            }
        }
    }
    rename_stmts(&mut p.body, map);
}

fn rename_stmts(stmts: &mut [Stmt], map: &Map) {
    for s in stmts {
        rename_stmt(s, map);
    }
}

fn rename_stmt(s: &mut Stmt, map: &Map) {
    match &mut s.kind {
        StmtKind::Assign { target, value } => {
            rename_variable(target, map);
            rename_expr(value, map);
        }
        StmtKind::Call(call) => rename_call(call, map),
        StmtKind::If {
            branches,
            otherwise,
        } => {
            for (cond, body) in branches {
                rename_expr(cond, map);
                rename_stmts(body, map);
            }
            rename_stmts(otherwise.as_deref_mut().unwrap_or_default(), map);
        }
        StmtKind::Case {
            selector,
            arms,
            otherwise,
        } => {
            rename_expr(selector, map);
            for arm in arms {
                for label in &mut arm.labels {
                    match label {
                        CaseLabel::Value(e) => rename_expr(e, map),
                        CaseLabel::Range(a, b) => {
                            rename_expr(a, map);
                            rename_expr(b, map);
                        }
                    }
                }
                rename_stmts(&mut arm.body, map);
            }
            rename_stmts(otherwise.as_deref_mut().unwrap_or_default(), map);
        }
        StmtKind::For {
            var,
            from,
            to,
            by,
            body,
        } => {
            rename_name(&mut var.name, map);
            for e in [Some(from), Some(to), by.as_mut()].into_iter().flatten() {
                rename_expr(e, map);
            }
            rename_stmts(body, map);
        }
        StmtKind::While { cond, body } | StmtKind::Repeat { body, until: cond } => {
            rename_expr(cond, map);
            rename_stmts(body, map);
        }
        StmtKind::Exit | StmtKind::Return | StmtKind::Empty => {}
    }
}

/// A call: its callee when it is an instance the program declares (a
/// function's name is no variable's), its arguments' values; the pins
/// are the callee's names.
fn rename_call(call: &mut Call, map: &Map) {
    rename_name(&mut call.callee.name, map);
    for a in &mut call.args {
        match a {
            Arg::Positional(e) | Arg::Input(_, e) => rename_expr(e, map),
            Arg::Output { target, .. } => rename_variable(target, map),
        }
    }
}

fn rename_variable(v: &mut Variable, map: &Map) {
    rename_name(&mut v.base.name, map);
    for s in &mut v.path {
        if let Selector::Index(es) = s {
            for e in es {
                rename_expr(e, map);
            }
        }
    }
}

fn rename_expr(e: &mut Expr, map: &Map) {
    match &mut e.kind {
        ExprKind::Literal(_) => {}
        ExprKind::Variable(v) => rename_variable(v, map),
        ExprKind::Call(call) => rename_call(call, map),
        ExprKind::Unary(_, a) => rename_expr(a, map),
        ExprKind::Binary(_, a, b) => {
            rename_expr(a, map);
            rename_expr(b, map);
        }
    }
}
