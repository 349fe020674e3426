//! An untyped real literal (`2.5`) where an LREAL is needed, written as
//! `LREAL#2.5` before lowering (issue #54). IEC's real literal fits REAL
//! and LREAL alike (the checker lets it); the soft PLC's IL reads an
//! untyped one as a REAL, so where its operation, its target or its pin
//! is an LREAL it is given that type here, from the text's digits (no
//! REAL rounding on the way: `0.1` is binary64's 0.1).

use super::ast::{
    Arg, BinaryOp, Call, Elementary, Expr, ExprKind, Literal, Selector, Stmt, StmtKind,
};
use super::ast::{TypeDef, TypeRef, Variable};
use super::lower::Lower;

const LREAL: &str = "LREAL";

impl Lower {
    /// The elementary type of a member or element of a flattened STRUCT
    /// or ARRAY (`xs[i]`, `p.v`), whatever its indices.
    pub(super) fn flat_type(&self, v: &Variable) -> Option<String> {
        let mut ty = self.flat_types.get(&v.base.name.to_ascii_uppercase())?;
        for s in &v.path {
            ty = self.resolved(ty, None).0;
            ty = match (s, ty) {
                (Selector::Member(m), TypeRef::Named(n)) => {
                    let Some(TypeDef::Struct(ms)) = self.type_def(&n.name) else {
                        return None;
                    };
                    let named = |d: &&super::ast::VarDecl| {
                        d.names.iter().any(|x| x.name.eq_ignore_ascii_case(&m.name))
                    };
                    &ms.iter().find(named)?.ty
                }
                (Selector::Index(_), TypeRef::Array { of, .. }) => of,
                _ => return None,
            };
        }
        match self.resolved(ty, None).0 {
            TypeRef::Elementary(t) => Some(t.name().to_string()),
            _ => None,
        }
    }

    /// `stmts` with every untyped real literal in an LREAL place typed.
    pub(super) fn lreal_literals(&self, stmts: &[Stmt]) -> Vec<Stmt> {
        let mut out = stmts.to_vec();
        for s in &mut out {
            self.stmt_reals(s);
        }
        out
    }

    fn stmt_reals(&self, s: &mut Stmt) {
        match &mut s.kind {
            StmtKind::Assign { target, value } => {
                let want = self.expr_type(&Expr {
                    kind: ExprKind::Variable(target.clone()),
                    span: s.span,
                });
                self.var_reals(target);
                self.reals(value, want.as_deref() == Some(LREAL));
            }
            StmtKind::Call(call) => self.block_reals(call),
            StmtKind::If {
                branches,
                otherwise,
            } => {
                for (c, body) in branches {
                    self.reals(c, false);
                    body.iter_mut().for_each(|s| self.stmt_reals(s));
                }
                otherwise
                    .iter_mut()
                    .flatten()
                    .for_each(|s| self.stmt_reals(s));
            }
            StmtKind::Case {
                selector,
                arms,
                otherwise,
            } => {
                self.reals(selector, false);
                for arm in arms {
                    arm.body.iter_mut().for_each(|s| self.stmt_reals(s));
                }
                otherwise
                    .iter_mut()
                    .flatten()
                    .for_each(|s| self.stmt_reals(s));
            }
            StmtKind::For {
                from, to, by, body, ..
            } => {
                for e in [Some(from), Some(to), by.as_mut()].into_iter().flatten() {
                    self.reals(e, false);
                }
                body.iter_mut().for_each(|s| self.stmt_reals(s));
            }
            StmtKind::While { cond, body } | StmtKind::Repeat { body, until: cond } => {
                self.reals(cond, false);
                body.iter_mut().for_each(|s| self.stmt_reals(s));
            }
            StmtKind::Exit | StmtKind::Return | StmtKind::Empty => {}
        }
    }

    /// A block instance's call: each input as its pin's type wants.
    fn block_reals(&self, call: &mut Call) {
        let ty = self.instances.get(&call.callee.name.to_ascii_uppercase());
        let ty = ty.cloned().unwrap_or_default();
        let pins = self.pin_types(&ty);
        for (k, a) in call.args.iter_mut().enumerate() {
            let (pin, e) = match a {
                Arg::Input(n, e) => (Some(n.name.clone()), e),
                Arg::Positional(e) => (pins.get(k).map(|(n, _)| n.clone()), e),
                Arg::Output { target, .. } => {
                    self.var_reals(target);
                    continue;
                }
            };
            let want = pin.and_then(|p| {
                let t = pins.iter().find(|(n, _)| n.eq_ignore_ascii_case(&p));
                t.map(|(_, t)| t.eq_ignore_ascii_case(LREAL))
            });
            self.reals(e, want.unwrap_or(false));
        }
    }

    /// A block's or own function's inputs with their types.
    fn pin_types(&self, ty: &str) -> Vec<(String, String)> {
        let upper = ty.to_ascii_uppercase();
        match self
            .blocks
            .get(&upper)
            .or_else(|| self.functions.get(&upper))
        {
            Some(pins) => pins.clone(),
            None => crate::iec::pins::inputs(&upper)
                .into_iter()
                .map(|(n, t)| (n.to_string(), t.name().to_string()))
                .collect(),
        }
    }

    fn var_reals(&self, v: &mut super::ast::Variable) {
        for s in &mut v.path {
            if let Selector::Index(ix) = s {
                ix.iter_mut().for_each(|e| self.reals(e, false));
            }
        }
    }

    /// `e`'s untyped real literals typed LREAL where `lreal` (its place
    /// wants one) or its operation's other side is an LREAL.
    fn reals(&self, e: &mut Expr, lreal: bool) {
        let is = |t: Option<String>| t.as_deref() == Some(LREAL);
        match &mut e.kind {
            ExprKind::Literal(Literal::Real(_, t @ None)) if lreal => *t = Some(Elementary::Lreal),
            ExprKind::Literal(_) => {}
            ExprKind::Variable(v) => self.var_reals(v),
            ExprKind::Unary(_, x) => self.reals(x, lreal),
            ExprKind::Binary(op, a, b) => {
                let sides = is(self.expr_type(a)) || is(self.expr_type(b));
                let compare = matches!(
                    op,
                    BinaryOp::Lt
                        | BinaryOp::Gt
                        | BinaryOp::Le
                        | BinaryOp::Ge
                        | BinaryOp::Eq
                        | BinaryOp::Ne
                );
                let here = sides || (lreal && !compare);
                self.reals(a, here);
                self.reals(b, here);
            }
            ExprKind::Call(call) => self.call_reals(call, lreal),
        }
    }

    /// A function's inputs: a conversion's as its source type, an own
    /// function's as its pins, a standard one's as its typed inputs (or
    /// the place's), not `SEL`'s or `MUX`'s selector.
    fn call_reals(&self, call: &mut Call, lreal: bool) {
        let upper = call.callee.name.to_ascii_uppercase();
        if let Some(pins) = self.functions.get(&upper).cloned() {
            for (k, a) in call.args.iter_mut().enumerate() {
                let (pin, e) = match a {
                    Arg::Input(n, e) => (n.name.clone(), e),
                    Arg::Positional(e) => (pins.get(k).map(|p| p.0.clone()).unwrap_or_default(), e),
                    Arg::Output { .. } => continue,
                };
                let t = pins.iter().find(|(n, _)| n.eq_ignore_ascii_case(&pin));
                self.reals(e, t.is_some_and(|(_, t)| t.eq_ignore_ascii_case(LREAL)));
            }
            return;
        }
        let source = upper.split_once("_TO_").map(|(s, _)| s == LREAL);
        let selector = matches!(upper.as_str(), "SEL" | "MUX");
        let typed = call.args.iter().enumerate().any(|(k, a)| match a {
            Arg::Positional(e) | Arg::Input(_, e) => {
                !(selector && k == 0) && self.expr_type(e).as_deref() == Some(LREAL)
            }
            Arg::Output { .. } => false,
        });
        for (k, a) in call.args.iter_mut().enumerate() {
            if let Arg::Positional(e) | Arg::Input(_, e) = a {
                let want = match source {
                    Some(s) => s,
                    None => !(selector && k == 0) && (typed || lreal),
                };
                self.reals(e, want);
            }
        }
    }
}
