//! A standard function's second and later inputs that are expressions
//! (`MAX(a, b + 1)`, `SHL(w, n - 1)`): IL gives a function its first
//! input as the current result and the others as operands, so each such
//! expression is computed first, before the statement, into a hidden
//! variable (`st_t2`) of its type, as an own function's call is made
//! first. Its type is what the checker's one type per operation makes
//! it: a comparison's BOOL, a conversion's target, else any typed
//! operand's in it; an expression of untyped literals alone (`2 * 3`)
//! takes the type of the function's other inputs (not `SEL`'s or
//! `MUX`'s selector).

use super::ast::{BinaryOp, Call, Expr, ExprKind, Literal, Selector};
use super::lower::Lower;
use crate::iec::data::DataType;

impl Lower {
    /// Computes `call`'s later inputs that are expressions into hidden
    /// variables (read back by [`Lower::made_arg`]).
    pub(super) fn hoist_std_args(&mut self, call: &Call) {
        if crate::iec::il::Function::named(&call.callee.name).is_none() {
            return;
        }
        let values = call.input_values();
        let Some((first, rest)) = values.split_first() else {
            return;
        };
        let selector = matches!(
            call.callee.name.to_ascii_uppercase().as_str(),
            "SEL" | "MUX"
        );
        let others = rest.iter().find_map(|e| self.expr_type(e));
        let fallback = others.or_else(|| (!selector).then(|| self.expr_type(first)).flatten());
        for e in rest {
            if self.simple(e).is_some() {
                continue;
            }
            let Some(ty) = self.expr_type(e).or_else(|| fallback.clone()) else {
                continue;
            };
            let temp = self.fresh("st_t");
            self.hidden.push((temp.clone(), ty));
            self.expr(e);
            self.emit(format!("ST {temp}"), e.span);
            self.std_args.insert((e.span.line, e.span.column), temp);
        }
    }

    /// The hidden variable a later input `e` was computed into.
    pub(super) fn made_arg(&self, e: &Expr) -> Option<String> {
        self.std_args.get(&(e.span.line, e.span.column)).cloned()
    }

    /// `e`'s IL type, when its operands tell it.
    pub(super) fn expr_type(&self, e: &Expr) -> Option<String> {
        let named = |t: &str| Some(t.to_string());
        match &e.kind {
            ExprKind::Literal(l) => match l {
                Literal::Bool(_) => named("BOOL"),
                Literal::Integer(_, t) => t.map(|t| t.name().to_string()),
                // An untyped real fits REAL and LREAL: no type of its own.
                Literal::Real(_, t) => t.map(|t| t.name().to_string()),
                Literal::Time(_) => named("TIME"),
                Literal::String(_) => named("STRING"),
            },
            ExprKind::Variable(v) if self.is_flat(v) => self.flat_type(v),
            ExprKind::Variable(v) => {
                let base = v.base.name.to_ascii_uppercase();
                match v.path.as_slice() {
                    [] => self.scalars.get(&base).cloned(),
                    [Selector::Member(m)] => {
                        let block = self.instances.get(&base)?;
                        crate::iec::pins::outputs(block)
                            .into_iter()
                            .find(|(p, _)| p.eq_ignore_ascii_case(&m.name))
                            .map(|(_, t)| t.name().to_string())
                    }
                    _ => None,
                }
            }
            ExprKind::Unary(_, x) => self.expr_type(x),
            ExprKind::Binary(op, a, b) => match op {
                BinaryOp::Lt
                | BinaryOp::Gt
                | BinaryOp::Le
                | BinaryOp::Ge
                | BinaryOp::Eq
                | BinaryOp::Ne => named("BOOL"),
                _ => self.expr_type(a).or_else(|| self.expr_type(b)),
            },
            ExprKind::Call(c) => {
                let upper = c.callee.name.to_ascii_uppercase();
                let target = upper.rsplit_once("_TO_").map(|(_, t)| t);
                let target = target.or_else(|| upper.strip_prefix("TO_"))?;
                DataType::from_name(target).map(|t| t.name().to_string())
            }
        }
    }
}
