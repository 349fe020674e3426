//! Writes a syntax tree back as Structured Text that parses to the same
//! tree: keywords upper-case, four spaces a level, parentheses only where
//! the precedence needs them.

use std::fmt::Write;

use super::ast::{
    Arg, ArrayInit, CaseLabel, Expr, ExprKind, Init, Item, Literal, Pou, PouKind, Selector, Source,
    Stmt, StmtKind, TypeDef, TypeRef, UnaryOp, VarBlock, VarDecl, Variable,
};
use crate::iec::literal::text_literal;

/// The source as text.
pub fn print_source(source: &Source) -> String {
    let mut out = String::new();
    for item in &source.items {
        match item {
            Item::Pou(pou) => print_pou(&mut out, pou),
            Item::Globals(block) => print_block(&mut out, block, 0),
            Item::Types(types) => {
                out.push_str("TYPE\n");
                for t in types {
                    let _ = write!(out, "    {} : ", t.name.name);
                    match &t.def {
                        TypeDef::Struct(members) => {
                            out.push_str("STRUCT\n");
                            for m in members {
                                print_decl(&mut out, m, 2);
                            }
                            out.push_str("    END_STRUCT;\n");
                        }
                        TypeDef::Alias(ty, init) => {
                            out.push_str(&type_text(ty));
                            if let Some(init) = init {
                                let _ = write!(out, " := {}", init_text(init));
                            }
                            out.push_str(";\n");
                        }
                    }
                }
                out.push_str("END_TYPE\n");
            }
        }
        out.push('\n');
    }
    out
}

fn print_pou(out: &mut String, pou: &Pou) {
    let (kw, end) = match &pou.kind {
        PouKind::Program => ("PROGRAM", "END_PROGRAM"),
        PouKind::Function(_) => ("FUNCTION", "END_FUNCTION"),
        PouKind::FunctionBlock => ("FUNCTION_BLOCK", "END_FUNCTION_BLOCK"),
    };
    let _ = write!(out, "{kw} {}", pou.name.name);
    if let PouKind::Function(ty) = &pou.kind {
        let _ = write!(out, " : {}", type_text(ty));
    }
    out.push('\n');
    for block in &pou.vars {
        print_block(out, block, 1);
    }
    print_stmts(out, &pou.body, 1);
    let _ = writeln!(out, "{end}");
}

fn print_block(out: &mut String, block: &VarBlock, level: usize) {
    let pad = "    ".repeat(level.saturating_sub(1));
    let _ = write!(out, "{pad}{}", block.kind.keyword());
    if block.constant {
        out.push_str(" CONSTANT");
    }
    if block.retain {
        out.push_str(" RETAIN");
    }
    out.push('\n');
    for d in &block.decls {
        print_decl(out, d, level + 1);
    }
    let _ = writeln!(out, "{pad}END_VAR");
}

fn print_decl(out: &mut String, d: &VarDecl, level: usize) {
    let names: Vec<&str> = d.names.iter().map(|n| n.name.as_str()).collect();
    let _ = write!(
        out,
        "{}{}",
        "    ".repeat(level.saturating_sub(1)),
        names.join(", ")
    );
    if let Some(at) = &d.location {
        let _ = write!(out, " AT {at}");
    }
    let _ = write!(out, " : {}", type_text(&d.ty));
    if let Some(init) = &d.init {
        let _ = write!(out, " := {}", init_text(init));
    }
    out.push_str(";\n");
}

/// A type as written in a declaration.
pub fn type_text(ty: &TypeRef) -> String {
    match ty {
        TypeRef::Elementary(t) => t.name().to_string(),
        TypeRef::String(None) => "STRING".to_string(),
        TypeRef::String(Some(n)) => format!("STRING[{n}]"),
        TypeRef::Named(n) => n.name.clone(),
        TypeRef::Array { dims, of } => {
            let dims: Vec<String> = dims.iter().map(|(l, h)| format!("{l}..{h}")).collect();
            format!("ARRAY [{}] OF {}", dims.join(", "), type_text(of))
        }
    }
}

pub(super) fn init_text(init: &Init) -> String {
    match init {
        Init::Expr(e) => expr_text(e),
        Init::Array(items) => {
            let items: Vec<String> = items
                .iter()
                .map(|i| match i {
                    ArrayInit::One(v) => init_text(v),
                    ArrayInit::Repeat(n, v) => {
                        format!("{n}({})", v.as_ref().map(init_text).unwrap_or_default())
                    }
                })
                .collect();
            format!("[{}]", items.join(", "))
        }
        Init::Struct(members) => {
            let m: Vec<String> = members
                .iter()
                .map(|(n, v)| format!("{} := {}", n.name, init_text(v)))
                .collect();
            format!("({})", m.join(", "))
        }
    }
}

/// Statements, each on its own lines, at `level` (four spaces each).
pub fn print_stmts(out: &mut String, stmts: &[Stmt], level: usize) {
    for s in stmts {
        print_stmt(out, s, level);
    }
}

fn print_stmt(out: &mut String, s: &Stmt, level: usize) {
    let pad = "    ".repeat(level);
    out.push_str(&pad);
    match &s.kind {
        StmtKind::Assign { target, value } => {
            let _ = writeln!(out, "{} := {};", var_text(target), expr_text(value));
        }
        StmtKind::Call(call) => {
            let _ = writeln!(out, "{};", call_text(&call.callee.name, &call.args));
        }
        StmtKind::If {
            branches,
            otherwise,
        } => {
            for (i, (cond, body)) in branches.iter().enumerate() {
                let kw = if i == 0 { "IF" } else { "ELSIF" };
                if i > 0 {
                    out.push_str(&pad);
                }
                let _ = writeln!(out, "{kw} {} THEN", expr_text(cond));
                print_stmts(out, body, level + 1);
            }
            print_else(out, otherwise.as_deref(), level);
            let _ = writeln!(out, "{pad}END_IF;");
        }
        StmtKind::Case {
            selector,
            arms,
            otherwise,
        } => {
            let _ = writeln!(out, "CASE {} OF", expr_text(selector));
            for arm in arms {
                let labels: Vec<String> = arm.labels.iter().map(label_text).collect();
                let _ = writeln!(out, "{pad}{}:", labels.join(", "));
                print_stmts(out, &arm.body, level + 1);
            }
            print_else(out, otherwise.as_deref(), level);
            let _ = writeln!(out, "{pad}END_CASE;");
        }
        StmtKind::For {
            var,
            from,
            to,
            by,
            body,
        } => {
            let _ = write!(
                out,
                "FOR {} := {} TO {}",
                var.name,
                expr_text(from),
                expr_text(to)
            );
            if let Some(by) = by {
                let _ = write!(out, " BY {}", expr_text(by));
            }
            out.push_str(" DO\n");
            print_stmts(out, body, level + 1);
            let _ = writeln!(out, "{pad}END_FOR;");
        }
        StmtKind::While { cond, body } => {
            let _ = writeln!(out, "WHILE {} DO", expr_text(cond));
            print_stmts(out, body, level + 1);
            let _ = writeln!(out, "{pad}END_WHILE;");
        }
        StmtKind::Repeat { body, until } => {
            out.push_str("REPEAT\n");
            print_stmts(out, body, level + 1);
            let _ = writeln!(out, "{pad}UNTIL {}\n{pad}END_REPEAT;", expr_text(until));
        }
        StmtKind::Exit => out.push_str("EXIT;\n"),
        StmtKind::Return => out.push_str("RETURN;\n"),
        StmtKind::Empty => out.push_str(";\n"),
    }
}

fn print_else(out: &mut String, otherwise: Option<&[Stmt]>, level: usize) {
    if let Some(body) = otherwise {
        let _ = writeln!(out, "{}ELSE", "    ".repeat(level));
        print_stmts(out, body, level + 1);
    }
}

fn label_text(l: &CaseLabel) -> String {
    match l {
        CaseLabel::Value(v) => expr_text(v),
        CaseLabel::Range(a, b) => format!("{}..{}", expr_text(a), expr_text(b)),
    }
}

fn call_text(callee: &str, args: &[Arg]) -> String {
    let args: Vec<String> = args
        .iter()
        .map(|a| match a {
            Arg::Positional(e) => expr_text(e),
            Arg::Input(n, e) => format!("{} := {}", n.name, expr_text(e)),
            Arg::Output {
                name,
                negated,
                target,
            } => {
                let not = if *negated { "NOT " } else { "" };
                format!("{not}{} => {}", name.name, var_text(target))
            }
        })
        .collect();
    format!("{callee}({})", args.join(", "))
}

pub(super) fn var_text(v: &Variable) -> String {
    let mut s = v.base.name.clone();
    for step in &v.path {
        match step {
            Selector::Index(ix) => {
                let ix: Vec<String> = ix.iter().map(expr_text).collect();
                let _ = write!(s, "[{}]", ix.join(", "));
            }
            Selector::Member(m) => {
                let _ = write!(s, ".{}", m.name);
            }
        }
    }
    s
}

/// The binding strength of an expression (literals, variables, calls
/// bind tightest; the unary operators 9).
fn strength(e: &Expr) -> u8 {
    match &e.kind {
        ExprKind::Binary(op, ..) => op.precedence(),
        ExprKind::Unary(..) => 9,
        _ => 10,
    }
}

/// An expression as text.
pub fn expr_text(e: &Expr) -> String {
    match &e.kind {
        ExprKind::Literal(l) => literal_text(l),
        ExprKind::Variable(v) => var_text(v),
        ExprKind::Call(c) => call_text(&c.callee.name, &c.args),
        ExprKind::Unary(op, x) => {
            let inner = wrap(x, strength(x) < 9);
            match op {
                UnaryOp::Neg => format!("-{}", spaced(&inner, '-')),
                UnaryOp::Plus => format!("+{}", spaced(&inner, '+')),
                UnaryOp::Not => format!("NOT {inner}"),
            }
        }
        ExprKind::Binary(op, a, b) => {
            let p = op.precedence();
            let left = wrap(a, strength(a) < p);
            let right = wrap(b, strength(b) <= p);
            format!("{left} {} {right}", op.symbol())
        }
    }
}

/// `text`, a space before it when it starts with `sign` (`- -x`).
fn spaced(text: &str, sign: char) -> String {
    if text.starts_with(['-', '+']) && sign != ' ' {
        format!(" {text}")
    } else {
        text.to_string()
    }
}

fn wrap(e: &Expr, paren: bool) -> String {
    if paren {
        format!("({})", expr_text(e))
    } else {
        expr_text(e)
    }
}

/// A literal as text.
pub fn literal_text(l: &Literal) -> String {
    match l {
        Literal::Bool(b) => if *b { "TRUE" } else { "FALSE" }.to_string(),
        Literal::Integer(v, None) => v.to_string(),
        Literal::Integer(v, Some(t)) => format!("{}#{v}", t.name()),
        Literal::Real(v, t) => {
            let mut s = format!("{v:?}");
            if let Some(e) = s.find('e') {
                if !s[..e].contains('.') {
                    s.insert_str(e, ".0");
                }
                s = s.replace('e', "E");
            }
            match t {
                Some(t) => format!("{}#{s}", t.name()),
                None => s,
            }
        }
        Literal::Time(ns) => format!("T#{}", time_text(*ns)),
        Literal::String(s) => text_literal(s),
    }
}

/// A duration in the largest units that write it exactly.
fn time_text(ns: i64) -> String {
    let (sign, mut n) = if ns < 0 {
        ("-", ns.unsigned_abs())
    } else {
        ("", ns as u64)
    };
    if n == 0 {
        return "0ms".to_string();
    }
    let mut s = String::from(sign);
    for (unit, size) in [
        ("d", 86_400_000_000_000u64),
        ("h", 3_600_000_000_000),
        ("m", 60_000_000_000),
        ("s", 1_000_000_000),
        ("ms", 1_000_000),
        ("us", 1_000),
        ("ns", 1),
    ] {
        if n >= size {
            let _ = write!(s, "{}{unit}", n / size);
            n %= size;
        }
    }
    s
}
