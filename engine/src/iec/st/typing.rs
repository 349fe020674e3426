//! The types of expressions, variables and calls, for the checker.

use super::ast::{
    Arg, BinaryOp, Call, Elementary, Expr, ExprKind, Literal, Selector, Span, UnaryOp, Variable,
};
use super::check::{Checker, Scope};
use super::error::StErrorKind;
use super::types::{elem_of, Ty};
use crate::iec::address::Address;
use crate::iec::functions::Function;

/// Standard functions the soft PLC will have beside
/// [`Function::named`]'s and the conversions; their results are typed
/// when they run.
const STANDARD: [&str; 24] = [
    "ABS", "SQRT", "LN", "LOG", "EXP", "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "EXPT", "MUX",
    "TRUNC", "LEN", "LEFT", "RIGHT", "MID", "CONCAT", "INSERT", "DELETE", "REPLACE", "FIND",
    "MOVE",
];

fn literal_ty(l: &Literal) -> Ty {
    match l {
        Literal::Bool(_) => Ty::Elem(Elementary::Bool),
        Literal::Integer(_, None) => Ty::AnyInt,
        Literal::Real(_, None) => Ty::AnyReal,
        Literal::Integer(_, Some(t)) | Literal::Real(_, Some(t)) => Ty::Elem(*t),
        Literal::Time(_) => Ty::Elem(Elementary::Time),
        Literal::String(_) => Ty::Str,
    }
}

/// The one type two operands share, when they share one.
fn join(a: &Ty, b: &Ty) -> Option<Ty> {
    if !a.fits(b) || !b.fits(a) {
        return None;
    }
    Some(match (a, b) {
        (Ty::Unknown, t) | (t, Ty::Unknown) => t.clone(),
        (Ty::AnyInt, t) | (t, Ty::AnyInt) => t.clone(),
        (Ty::AnyReal, t) | (t, Ty::AnyReal) => t.clone(),
        (t, _) => t.clone(),
    })
}

impl Checker {
    /// The type of `e` (unknown where a refusal was made, so that one
    /// mistake is said once).
    pub(super) fn expr(&mut self, scope: &Scope, e: &Expr) -> Ty {
        match &e.kind {
            ExprKind::Literal(l) => literal_ty(l),
            ExprKind::Variable(v) => self.variable(scope, v).0,
            ExprKind::Call(c) => self.call(scope, c, e.span),
            ExprKind::Unary(op, x) => {
                let t = self.expr(scope, x);
                let ok = match op {
                    UnaryOp::Not => t.is_bool() || t.is_integer(),
                    UnaryOp::Neg | UnaryOp::Plus => {
                        t.is_number() && t != Ty::Elem(Elementary::Bool)
                    }
                };
                if ok {
                    t
                } else {
                    self.mismatch(x.span, "the operand", "a number or BOOL", &t);
                    Ty::Unknown
                }
            }
            ExprKind::Binary(op, a, b) => {
                let (ta, tb) = (self.expr(scope, a), self.expr(scope, b));
                if *op == BinaryOp::Pow {
                    return self.power(&ta, &tb, (a.span, b.span));
                }
                self.binary(*op, &ta, &tb, b.span)
            }
        }
    }

    /// `a ** b`, IEC's EXPT: a REAL base (ANY_REAL), a power of any
    /// number type, the base's type (an untyped integer base is taken as
    /// a real literal).
    fn power(&mut self, a: &Ty, b: &Ty, (sa, sb): (Span, Span)) -> Ty {
        use Elementary::{Lreal, Real};
        let base = match a {
            Ty::Elem(Real | Lreal) | Ty::AnyReal | Ty::Unknown => a.clone(),
            Ty::AnyInt => Ty::AnyReal,
            _ => {
                let want = "a REAL (EXPT's base: convert an integer, INT_TO_REAL)";
                self.mismatch(sa, "`**`'s base", want, a);
                return Ty::Unknown;
            }
        };
        if !b.is_number() || *b == Ty::Elem(Elementary::Time) {
            self.mismatch(sb, "`**`'s power", "a number", b);
            return Ty::Unknown;
        }
        base
    }

    fn binary(&mut self, op: BinaryOp, a: &Ty, b: &Ty, span: Span) -> Ty {
        use BinaryOp::*;
        let Some(t) = join(a, b) else {
            self.mismatch(span, "the right operand", &a.describe(), b);
            return Ty::Unknown;
        };
        let ok = match op {
            Lt | Gt | Le | Ge | Eq | Ne => return Ty::Elem(Elementary::Bool),
            And | Or | Xor => t.is_bool() || t.is_integer(),
            Add | Sub => t.is_number(),
            Mul | Div | Pow => t.is_number() && t != Ty::Elem(Elementary::Time),
            Mod => t.is_integer(),
        };
        let ok = ok && (t != Ty::Elem(Elementary::Bool) || matches!(op, And | Or | Xor));
        if !ok {
            self.mismatch(
                span,
                "an operand of this operator",
                "of a type it applies to",
                &t,
            );
            return Ty::Unknown;
        }
        t
    }

    /// A variable's type and whether it is read-only (a constant, or a
    /// block instance's output).
    pub(super) fn variable(&mut self, scope: &Scope, v: &Variable) -> (Ty, bool) {
        let (mut ty, mut read_only) = match scope.get(&v.base.name.to_ascii_uppercase()) {
            Some(var) => (var.ty.clone(), var.constant),
            // A direct address has its size's type (%IX0.0 a BOOL).
            None if v.base.name.starts_with('%') => {
                let ty = Address::parse(&v.base.name)
                    .ok()
                    .and_then(|a| a.default_type());
                (ty.map_or(Ty::Unknown, |t| elem_of(t.name())), false)
            }
            None => {
                self.refuse(v.base.span, StErrorKind::UnknownName(v.base.name.clone()));
                return (Ty::Unknown, false);
            }
        };
        for step in &v.path {
            ty = match step {
                Selector::Index(ix) => self.index(scope, v, &ty, ix),
                Selector::Member(m) => {
                    let members = self.decls.members(&ty);
                    let found = members
                        .as_ref()
                        .and_then(|ms| ms.iter().find(|(n, ..)| n.eq_ignore_ascii_case(&m.name)));
                    match found {
                        Some((_, t, out)) => {
                            // A block's output is its own to write.
                            read_only |= *out && matches!(ty, Ty::Block(_));
                            t.clone()
                        }
                        // An unknown type was refused already.
                        None if ty == Ty::Unknown => Ty::Unknown,
                        None => {
                            let (member, of) = (m.name.clone(), ty.describe());
                            self.refuse(m.span, StErrorKind::NoMember { member, of });
                            Ty::Unknown
                        }
                    }
                }
            };
        }
        (ty, read_only)
    }

    fn index(&mut self, scope: &Scope, v: &Variable, ty: &Ty, ix: &[Expr]) -> Ty {
        for i in ix {
            let t = self.expr(scope, i);
            if !t.is_integer() {
                self.mismatch(i.span, "an index", "an integer", &t);
            }
        }
        match ty {
            Ty::Array(n, of) if *n == ix.len() => (**of).clone(),
            Ty::Unknown => Ty::Unknown,
            _ => {
                let dims = match ty {
                    Ty::Array(n, _) => *n,
                    _ => 0,
                };
                let kind = StErrorKind::BadIndex {
                    name: v.base.name.clone(),
                    dims,
                    given: ix.len(),
                };
                self.refuse(ix.first().map_or(v.base.span, |e| e.span), kind);
                Ty::Unknown
            }
        }
    }

    /// A call's result type, its arguments checked against the callee.
    pub(super) fn call(&mut self, scope: &Scope, call: &Call, span: Span) -> Ty {
        let upper = call.callee.name.to_ascii_uppercase();
        if let Some(var) = scope.get(&upper) {
            let ty = var.ty.clone();
            let Some(pins) = self
                .decls
                .members(&ty)
                .filter(|_| matches!(ty, Ty::Block(_)))
            else {
                self.refuse(
                    call.callee.span,
                    StErrorKind::NotCallable(call.callee.name.clone()),
                );
                return Ty::Unknown;
            };
            self.args(scope, call, &pins);
            return Ty::Unknown;
        }
        if let Some((ret, ins)) = self.decls.functions.get(&upper).cloned() {
            let pins: Vec<(String, Ty, bool)> =
                ins.into_iter().map(|(n, t)| (n, t, false)).collect();
            self.args(scope, call, &pins);
            return ret;
        }
        for a in &call.args {
            match a {
                Arg::Positional(e) | Arg::Input(_, e) => {
                    self.expr(scope, e);
                }
                Arg::Output { target, .. } => {
                    self.variable(scope, target);
                }
            }
        }
        standard_result(&upper).unwrap_or_else(|| {
            self.refuse(span, StErrorKind::UnknownName(call.callee.name.clone()));
            Ty::Unknown
        })
    }

    /// Each argument names an input or output `pins` has, of a fitting
    /// type; positional ones go to the inputs in order.
    fn args(&mut self, scope: &Scope, call: &Call, pins: &[(String, Ty, bool)]) {
        let inputs: Vec<&(String, Ty, bool)> = pins.iter().filter(|p| !p.2).collect();
        for (i, a) in call.args.iter().enumerate() {
            let (name, output) = match a {
                Arg::Positional(e) => {
                    let want = inputs.get(i).map_or(Ty::Unknown, |p| p.1.clone());
                    self.expect(scope, e, &want, "an argument");
                    continue;
                }
                Arg::Input(n, _) => (n, false),
                Arg::Output { name, .. } => (name, true),
            };
            let Some((_, ty, _)) = pins
                .iter()
                .find(|(p, _, out)| p.eq_ignore_ascii_case(&name.name) && *out == output)
            else {
                let kind = StErrorKind::NoSuchArg {
                    callee: call.callee.name.clone(),
                    arg: name.name.clone(),
                };
                self.refuse(name.span, kind);
                continue;
            };
            match a {
                Arg::Input(_, e) => self.expect(scope, e, &ty.clone(), "an input's value"),
                Arg::Output { target, .. } => {
                    let (t, _) = self.variable(scope, target);
                    if !ty.fits(&t) {
                        self.mismatch(target.base.span, "an output's target", &ty.describe(), &t);
                    }
                }
                Arg::Positional(_) => {}
            }
        }
    }
}

/// A standard function's result type: known for conversions and
/// comparisons, unknown (fits anywhere) for the others; `None` for a
/// name that is no standard function.
fn standard_result(upper: &str) -> Option<Ty> {
    if let Some((from, to)) = upper.split_once("_TO_") {
        let known = |n: &str| {
            Elementary::from_name(n)
                .map(Ty::Elem)
                .or((n == "STRING").then_some(Ty::Str))
        };
        return known(from).and(known(to));
    }
    if let Some(to) = upper.strip_prefix("TO_") {
        return Elementary::from_name(to).map(Ty::Elem);
    }
    match Function::named(upper) {
        Some(Function::Compare(_)) => Some(Ty::Elem(Elementary::Bool)),
        Some(_) => Some(Ty::Unknown),
        None => STANDARD.contains(&upper).then_some(Ty::Unknown),
    }
}
