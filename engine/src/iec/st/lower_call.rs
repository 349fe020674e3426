//! The program's own FUNCTIONs, lowered: each becomes an IL function
//! block whose one output bears the function's name (its result), and
//! each call in an expression a `CAL` of a hidden instance made just
//! before the statement's expression is computed, the call then read as
//! the instance's output (`st_f3.Square`). IL has no call inside an
//! expression; this keeps the expression one run of operations.

use super::ast::{Arg, Expr, ExprKind, Pou, TypeRef};
use super::lower::{simple, Lower};

impl Lower {
    /// A FUNCTION as a function block: its inputs and locals as written,
    /// its result an output of its own name. Its locals keep their values
    /// between calls (IEC starts them afresh): a function that reads a
    /// local before writing it sees the last call's value.
    pub(super) fn function_pou(&mut self, p: &Pou, result: &TypeRef) {
        self.emit(format!("FUNCTION_BLOCK {}", p.name.name), p.span);
        for b in &p.vars {
            self.block(b);
        }
        let ty = super::print::type_text(result);
        self.emit("VAR_OUTPUT", p.span);
        self.emit(format!("  {} : {ty};", p.name.name), p.name.span);
        self.emit("END_VAR", p.span);
        self.body_with_io(p);
        self.emit("END_FUNCTION_BLOCK", p.span);
    }

    /// A POU's statements, then (before them) the hidden instances its
    /// function calls need.
    pub(super) fn body(&mut self, p: &Pou) {
        let at = self.lines.len();
        let hidden = self.body_alone(p);
        if hidden.is_empty() {
            return;
        }
        let mut block = vec![("VAR".to_string(), p.span)];
        for (name, ty) in hidden {
            block.push((format!("  {name} : {ty};"), p.span));
        }
        block.push(("END_VAR".to_string(), p.span));
        self.lines.splice(at..at, block);
    }

    /// A POU's statements; the hidden instances (name, type) its
    /// function calls need.
    pub(super) fn body_alone(&mut self, p: &Pou) -> Vec<(String, String)> {
        self.hidden.clear();
        self.instances = p
            .vars
            .iter()
            .flat_map(|b| &b.decls)
            .filter_map(|d| match &d.ty {
                TypeRef::Named(t) => Some(d.names.iter().map(|n| {
                    let ty = t.name.to_ascii_uppercase();
                    (n.name.to_ascii_uppercase(), ty)
                })),
                _ => None,
            })
            .flatten()
            .collect();
        let body = self.lreal_literals(&p.body);
        self.stmts(&body);
        std::mem::take(&mut self.hidden)
    }

    /// `a ** b`: IL's EXPT of `a`, its power a variable or a literal (an
    /// expression's type is not known to the lowering yet).
    pub(super) fn power(&mut self, a: &Expr, b: &Expr) {
        self.expr(a);
        match self.simple(b) {
            Some(t) => self.emit(format!("EXPT {t}"), b.span),
            None => self.not_yet(
                b.span,
                "an expression as `**`'s power (assign it to a variable first)",
            ),
        }
    }

    /// An IL operand for `e`: [`simple`]'s, or a call already made.
    pub(super) fn simple(&self, e: &Expr) -> Option<String> {
        if let ExprKind::Call(_) = e.kind {
            return self.hoisted.get(&(e.span.line, e.span.column)).cloned();
        }
        if let ExprKind::Variable(v) = &e.kind {
            if self.is_flat(v) {
                return self.leaf(v);
            }
        }
        simple(e)
    }

    /// A hidden variable's name: `prefix` and a number, no declared name.
    pub(super) fn fresh(&mut self, prefix: &str) -> String {
        let mut n = self.hidden.len() + 1;
        loop {
            let name = format!("{}{prefix}{n}", self.tag);
            if self.taken.insert(name.to_ascii_uppercase()) {
                return name;
            }
            n += 1;
        }
    }

    /// Makes the calls of own functions in `e`, innermost first.
    pub(super) fn hoist(&mut self, e: &Expr) {
        match &e.kind {
            ExprKind::Unary(_, x) => self.hoist(x),
            ExprKind::Binary(_, a, b) => {
                self.hoist(a);
                self.hoist(b);
            }
            ExprKind::Variable(v) => self.hoist_indices(v),
            ExprKind::Call(call) => {
                for a in &call.args {
                    if let Arg::Positional(x) | Arg::Input(_, x) = a {
                        self.hoist(x);
                    }
                }
                let upper = call.callee.name.to_ascii_uppercase();
                if let Some(inputs) = self.functions.get(&upper).cloned() {
                    self.call_function(call, &inputs, e);
                } else {
                    self.hoist_std_args(call);
                }
            }
            ExprKind::Literal(_) => {}
        }
    }

    /// An operand giving input `pin` of a block or function of type
    /// `ty` the value of `e`: `e` itself when it is one, else a hidden
    /// variable of the pin's type that `e` is stored to first; `None`
    /// when the pin's type is not known. `made`: `e`'s own-function calls
    /// are made already (a function's arguments are, before its call).
    pub(super) fn input(&mut self, ty: &str, pin: &str, e: &Expr, made: bool) -> Option<String> {
        if let Some(t) = self.simple(e) {
            return Some(t);
        }
        let own = self.blocks.get(ty).or_else(|| self.functions.get(ty));
        let pin_ty = match own {
            Some(pins) => pins
                .iter()
                .find(|(n, _)| n.eq_ignore_ascii_case(pin))
                .map(|(_, t)| t.clone()),
            None => crate::iec::pins::inputs(ty)
                .into_iter()
                .find(|(n, _)| n.eq_ignore_ascii_case(pin))
                .map(|(_, t)| t.name().to_string()),
        }?;
        let temp = self.fresh("st_t");
        self.hidden.push((temp.clone(), pin_ty));
        if !made {
            self.hoist(e);
        }
        self.expr(e);
        self.emit(format!("ST {temp}"), e.span);
        Some(temp)
    }

    fn call_function(&mut self, call: &super::ast::Call, inputs: &[(String, String)], e: &Expr) {
        let mut args = Vec::new();
        for (i, a) in call.args.iter().enumerate() {
            let (name, x) = match a {
                Arg::Positional(x) => match inputs.get(i) {
                    Some((n, _)) => (n.clone(), x),
                    None => return self.not_yet(x.span, "an argument past the function's inputs"),
                },
                Arg::Input(n, x) => (n.name.clone(), x),
                Arg::Output { name, .. } => {
                    return self.not_yet(name.span, "an output of a function call")
                }
            };
            let ty = call.callee.name.to_ascii_uppercase();
            if let Some(pair) = self.in_out(&ty, &name, x) {
                args.extend(pair);
                continue;
            }
            match self.input(&ty, &name, x, true) {
                Some(t) => args.push(format!("{name} := {t}")),
                None => return self.not_yet(x.span, "this function's input as an expression"),
            }
        }
        args.extend(self.external_args(&call.callee.name));
        let instance = self.fresh("st_f");
        self.hidden
            .push((instance.clone(), call.callee.name.clone()));
        self.emit(format!("CAL {instance}({})", args.join(", ")), e.span);
        let read = format!("{instance}.{}", call.callee.name);
        self.hoisted.insert((e.span.line, e.span.column), read);
    }
}
