//! Name resolution and type checking of a parsed source: every name
//! declared, every type known, one type per operation, conditions BOOL,
//! assignments of a fitting type, `EXIT` inside a loop, constants not
//! written; each refusal at its line and column. What the checker cannot
//! know yet (a standard function's result) fits anywhere.

use std::collections::HashMap;

use super::ast::{Item, Literal, Pou, PouKind, Source, Stmt, StmtKind, TypeDef, VarBlock, VarKind};
use super::error::{StError, StErrorKind};
use super::types::{at, Decls, Ty, Var};

/// The names a POU's body sees, by upper-case name.
pub(super) type Scope = HashMap<String, Var>;

/// The checker's state: the declarations and the refusals found.
pub(super) struct Checker {
    pub(super) decls: Decls,
    pub(super) errors: Vec<StError>,
    /// How many loops enclose the statement being checked.
    pub(super) loops: usize,
}

/// Checks `source`; every refusal, in the order of the text.
pub fn check_source(source: &Source) -> Result<(), Vec<StError>> {
    let mut c = Checker {
        decls: Decls::default(),
        errors: Vec::new(),
        loops: 0,
    };
    c.declare_types(source);
    let mut globals = Scope::new();
    for item in &source.items {
        if let Item::Globals(block) = item {
            c.declare_block(&mut globals, block);
        }
    }
    for item in &source.items {
        if let Item::Pou(pou) = item {
            c.pou(pou, &globals);
        }
    }
    if c.errors.is_empty() {
        return Ok(());
    }
    c.errors.sort_by_key(|e| (e.span.line, e.span.column));
    Err(c.errors)
}

impl Checker {
    pub(super) fn refuse(&mut self, span: super::ast::Span, kind: StErrorKind) {
        self.errors.push(at(span, kind));
    }

    /// Names every structure, alias and POU first (any order of
    /// declaration works), then resolves their members' types.
    fn declare_types(&mut self, source: &Source) {
        let mut seen = HashMap::new();
        for item in &source.items {
            let names: Vec<&super::ast::Ident> = match item {
                Item::Types(ts) => ts.iter().map(|t| &t.name).collect(),
                Item::Pou(p) => vec![&p.name],
                Item::Globals(_) => Vec::new(),
            };
            for n in names {
                if seen.insert(n.name.to_ascii_uppercase(), ()).is_some() {
                    self.refuse(n.span, StErrorKind::DuplicateName(n.name.clone()));
                }
            }
        }
        for item in &source.items {
            match item {
                Item::Types(ts) => {
                    for t in ts {
                        let name = t.name.name.to_ascii_uppercase();
                        match &t.def {
                            TypeDef::Struct(_) => {
                                self.decls.structs.insert(name, Vec::new());
                            }
                            TypeDef::Alias(ty, _) => {
                                self.decls.aliases.insert(name, ty.clone());
                            }
                        }
                    }
                }
                Item::Pou(p) if p.kind == PouKind::FunctionBlock => {
                    self.decls
                        .blocks
                        .insert(p.name.name.to_ascii_uppercase(), Vec::new());
                }
                _ => {}
            }
        }
        self.resolve_members(source);
    }

    fn resolve_members(&mut self, source: &Source) {
        for item in &source.items {
            match item {
                Item::Types(ts) => {
                    for t in ts {
                        let name = t.name.name.to_ascii_uppercase();
                        if let TypeDef::Struct(members) = &t.def {
                            let mut scope = Scope::new();
                            for d in members {
                                self.declare(&mut scope, d, VarKind::Local, false);
                            }
                            let m = members
                                .iter()
                                .flat_map(|d| &d.names)
                                .filter_map(|n| {
                                    let v = scope.get(&n.name.to_ascii_uppercase())?;
                                    Some((n.name.to_ascii_uppercase(), v.ty.clone()))
                                })
                                .collect();
                            self.decls.structs.insert(name, m);
                        } else if let TypeDef::Alias(ty, _) = &t.def {
                            if let Err(e) = self.decls.resolve(ty) {
                                self.errors.push(e);
                            }
                        }
                    }
                }
                Item::Pou(p) => self.signature(p),
                Item::Globals(_) => {}
            }
        }
    }

    /// A block's pins or a function's result and inputs.
    fn signature(&mut self, p: &Pou) {
        let name = p.name.name.to_ascii_uppercase();
        let mut pins = Vec::new();
        for b in &p.vars {
            if matches!(b.kind, VarKind::Input | VarKind::Output | VarKind::InOut) {
                for d in &b.decls {
                    let ty = self.decls.resolve(&d.ty).unwrap_or(Ty::Unknown);
                    for n in &d.names {
                        pins.push((n.name.to_ascii_uppercase(), ty.clone(), b.kind));
                    }
                }
            }
        }
        match &p.kind {
            PouKind::FunctionBlock => {
                self.decls.blocks.insert(name, pins);
            }
            PouKind::Function(ret) => {
                let ret = self.decls.resolve(ret).unwrap_or(Ty::Unknown);
                let ins = pins
                    .into_iter()
                    .filter(|(_, _, k)| *k != VarKind::Output)
                    .map(|(n, t, _)| (n, t))
                    .collect();
                self.decls.functions.insert(name, (ret, ins));
            }
            PouKind::Program => {}
        }
    }

    /// Declares a block's variables in `scope`.
    fn declare_block(&mut self, scope: &mut Scope, block: &VarBlock) {
        for d in &block.decls {
            self.declare(scope, d, block.kind, block.constant);
        }
    }

    fn declare(
        &mut self,
        scope: &mut Scope,
        d: &super::ast::VarDecl,
        kind: VarKind,
        constant: bool,
    ) {
        let ty = match self.decls.resolve(&d.ty) {
            Ok(t) => t,
            Err(e) => {
                self.errors.push(e);
                Ty::Unknown
            }
        };
        if let Some(init) = &d.init {
            self.init(scope, init, &ty);
        }
        for n in &d.names {
            let var = Var {
                ty: ty.clone(),
                kind,
                constant,
            };
            let upper = n.name.to_ascii_uppercase();
            let shadows_global = scope.get(&upper).is_some_and(|v| v.kind == VarKind::Global);
            if scope.insert(upper, var).is_some() && !shadows_global {
                self.refuse(n.span, StErrorKind::DuplicateName(n.name.clone()));
            }
        }
    }

    /// An initial value's expressions fit the declared type.
    fn init(&mut self, scope: &Scope, init: &super::ast::Init, ty: &Ty) {
        use super::ast::{ArrayInit, Init};
        match (init, ty) {
            (Init::Expr(e), _) => self.expect(scope, e, ty, "the initial value"),
            (Init::Array(items), Ty::Array(_, of)) => {
                for item in items {
                    match item {
                        ArrayInit::One(v) | ArrayInit::Repeat(_, Some(v)) => {
                            self.init(scope, v, of)
                        }
                        ArrayInit::Repeat(_, None) => {}
                    }
                }
            }
            (Init::Struct(members), _) => {
                let known = self.decls.members(ty).unwrap_or_default();
                for (name, v) in members {
                    match known
                        .iter()
                        .find(|(m, _, _)| m.eq_ignore_ascii_case(&name.name))
                    {
                        Some((_, t, _)) => self.init(scope, v, &t.clone()),
                        None => self.refuse(
                            name.span,
                            StErrorKind::NoMember {
                                member: name.name.clone(),
                                of: ty.describe(),
                            },
                        ),
                    }
                }
            }
            (Init::Array(_), _) => {}
        }
    }

    fn pou(&mut self, pou: &Pou, globals: &Scope) {
        let mut scope = globals.clone();
        if let PouKind::Function(ret) = &pou.kind {
            let ty = self.decls.resolve(ret).unwrap_or(Ty::Unknown);
            let var = Var {
                ty,
                kind: VarKind::Output,
                constant: false,
            };
            scope.insert(pou.name.name.to_ascii_uppercase(), var);
        }
        for b in &pou.vars {
            self.declare_block(&mut scope, b);
        }
        self.loops = 0;
        self.stmts(&scope, &pou.body);
    }

    /// Checks statements.
    pub(super) fn stmts(&mut self, scope: &Scope, stmts: &[Stmt]) {
        for s in stmts {
            self.stmt(scope, s);
        }
    }

    fn stmt(&mut self, scope: &Scope, s: &Stmt) {
        let bool_ty = Ty::Elem(super::ast::Elementary::Bool);
        match &s.kind {
            StmtKind::Assign { target, value } => {
                let (ty, read_only) = self.variable(scope, target);
                if read_only {
                    let name = super::print::var_text(target);
                    self.refuse(target.base.span, StErrorKind::ReadOnly(name));
                }
                self.expect(scope, value, &ty, "the value assigned");
            }
            StmtKind::Call(call) => {
                self.call(scope, call, s.span);
            }
            StmtKind::If {
                branches,
                otherwise,
            } => {
                for (cond, body) in branches {
                    self.expect(scope, cond, &bool_ty, "the IF condition");
                    self.stmts(scope, body);
                }
                self.stmts(scope, otherwise.as_deref().unwrap_or_default());
            }
            StmtKind::Case {
                selector,
                arms,
                otherwise,
            } => {
                self.case(scope, selector, arms);
                self.stmts(scope, otherwise.as_deref().unwrap_or_default());
            }
            StmtKind::For {
                var,
                from,
                to,
                by,
                body,
            } => {
                let v = super::ast::Variable {
                    base: var.clone(),
                    path: Vec::new(),
                };
                let (ty, _) = self.variable(scope, &v);
                if !ty.is_integer() {
                    self.mismatch(var.span, "the FOR variable", "an integer", &ty);
                }
                for e in [Some(from), Some(to), by.as_ref()].into_iter().flatten() {
                    self.expect(scope, e, &ty, "a FOR bound or step");
                }
                self.in_loop(scope, body);
            }
            StmtKind::While { cond, body } => {
                self.expect(scope, cond, &bool_ty, "the WHILE condition");
                self.in_loop(scope, body);
            }
            StmtKind::Repeat { body, until } => {
                self.in_loop(scope, body);
                self.expect(scope, until, &bool_ty, "the UNTIL condition");
            }
            StmtKind::Exit if self.loops == 0 => self.refuse(s.span, StErrorKind::ExitOutsideLoop),
            StmtKind::Exit | StmtKind::Return | StmtKind::Empty => {}
        }
    }

    fn in_loop(&mut self, scope: &Scope, body: &[Stmt]) {
        self.loops += 1;
        self.stmts(scope, body);
        self.loops -= 1;
    }

    fn case(&mut self, scope: &Scope, selector: &super::ast::Expr, arms: &[super::ast::CaseArm]) {
        use super::ast::CaseLabel;
        let ty = self.expr(scope, selector);
        if !ty.is_integer() {
            self.mismatch(selector.span, "the CASE selector", "an integer", &ty);
        }
        for arm in arms {
            for label in &arm.labels {
                match label {
                    CaseLabel::Value(v) => self.expect(scope, v, &ty, "a CASE label"),
                    CaseLabel::Range(a, b) => {
                        self.expect(scope, a, &ty, "a CASE label");
                        self.expect(scope, b, &ty, "a CASE label");
                    }
                }
            }
            self.stmts(scope, &arm.body);
        }
    }

    /// Refuses unless `e`'s type fits `want`.
    pub(super) fn expect(
        &mut self,
        scope: &Scope,
        e: &super::ast::Expr,
        want: &Ty,
        place: &'static str,
    ) {
        let found = self.expr(scope, e);
        if !found.fits(want) {
            self.mismatch(e.span, place, &want.describe(), &found);
        } else if let (super::ast::ExprKind::Literal(Literal::Integer(v, None)), Ty::Elem(t)) =
            (&e.kind, want)
        {
            // An untyped literal must fit the type of its use.
            if let Some((lo, hi)) = t.range().filter(|(lo, hi)| v < lo || v > hi) {
                self.refuse(
                    e.span,
                    StErrorKind::Mismatch {
                        place,
                        want: format!("within {}'s range {lo} … {hi}", t.name()),
                        found: v.to_string(),
                    },
                );
            }
        }
    }

    pub(super) fn mismatch(
        &mut self,
        span: super::ast::Span,
        place: &'static str,
        want: &str,
        found: &Ty,
    ) {
        self.refuse(
            span,
            StErrorKind::Mismatch {
                place,
                want: want.to_string(),
                found: found.describe(),
            },
        );
    }
}
