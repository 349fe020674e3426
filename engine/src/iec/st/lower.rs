//! Structured Text lowered to the soft PLC's Instruction List: a checked
//! source becomes IL text (one `PROGRAM`, its own `FUNCTION_BLOCK`s),
//! which the soft PLC loads as it loads any IL, so ST runs through the
//! one scan, at IL's speed, with its I/O, tracing and recording, and an
//! endless loop is cut as IL's backward jumps are. Every IL line keeps the
//! ST place it comes from ([`Lowered::spans`]), so what the IL loader
//! refuses is said at the ST line and column. Control flow becomes
//! labels and jumps (`JMPC`/`JMPCN`), an expression nested operations
//! (`ADD(` … `)`). What does not fit IL yet is refused at its place
//! ([`StErrorKind::NotYet`]).

use super::ast::{
    BinaryOp, CaseArm, CaseLabel, Expr, ExprKind, Item, Pou, PouKind, Source, Span, Stmt, StmtKind,
    UnaryOp, VarKind,
};
use super::error::{StError, StErrorKind};
use super::types::at;

/// A source as IL text, each IL line with the ST place it comes from.
#[derive(Clone, Debug, PartialEq)]
pub struct Lowered {
    /// The IL text.
    pub text: String,
    /// `spans[n]`: where IL line `n + 1` comes from in the ST text.
    pub spans: Vec<Span>,
    /// The variables of a second and later `PROGRAM` the IL knows by
    /// another name ([`super::rename`]).
    pub renamed: Vec<super::rename::Renamed>,
}

impl Lowered {
    /// The ST place of a 1-based IL line (the last line's for one past
    /// the end).
    pub fn place(&self, il_line: usize) -> Span {
        let i = il_line
            .saturating_sub(1)
            .min(self.spans.len().saturating_sub(1));
        self.spans.get(i).copied().unwrap_or_default()
    }
}

/// Lowers a checked source (see [`super::check_source`]) to IL: its
/// function blocks, then its one `PROGRAM`.
pub fn lower_source(source: &Source) -> Result<Lowered, Vec<StError>> {
    let (functions, blocks) = signatures(source);
    let mut l = Lower {
        functions,
        blocks,
        taken: declared(source),
        ..Lower::default()
    };
    l.know_in_outs(source);
    l.types = source
        .items
        .iter()
        .filter_map(|i| match i {
            Item::Types(ts) => Some(ts),
            _ => None,
        })
        .flatten()
        .map(|t| (t.name.name.to_ascii_uppercase(), t.def.clone()))
        .collect();
    for item in &source.items {
        match item {
            Item::Pou(p) => match p.kind {
                PouKind::FunctionBlock => l.pou(p, "FUNCTION_BLOCK"),
                // All of them after the blocks (`super::rename`).
                PouKind::Program => {}
                PouKind::Function(ref ty) => l.function_pou(p, ty),
            },
            // Known before any POU (`l.types`): flattened where used.
            Item::Types(_) => {}
            // Declared in the PROGRAM (`pou`), which every call starts from.
            Item::Globals(b) => l.globals.push(b.clone()),
        }
    }
    let (programs, renamed) = super::rename::programs(source, &mut l.taken);
    match programs.as_slice() {
        [] => l.errors.push(at(
            Span { line: 1, column: 1 },
            StErrorKind::NotYet("a file without a PROGRAM".to_string()),
        )),
        [one] => l.pou(one, "PROGRAM"),
        many => l.programs(many),
    }
    if !l.errors.is_empty() {
        l.errors.sort_by_key(|e| (e.span.line, e.span.column));
        return Err(l.errors);
    }
    let mut text = String::new();
    let mut spans = Vec::new();
    for (line, span) in l.lines {
        text.push_str(&line);
        text.push('\n');
        spans.push(span);
    }
    Ok(Lowered {
        text,
        spans,
        renamed,
    })
}

/// Each own function's and block's inputs in order (name, type as
/// written), by upper-case name: functions first, blocks second.
type Pins = std::collections::HashMap<String, Vec<(String, String)>>;

pub(super) fn declared(source: &Source) -> std::collections::HashSet<String> {
    let pous = source.items.iter().filter_map(|i| match i {
        Item::Pou(p) => Some(p),
        _ => None,
    });
    pous.flat_map(|p| &p.vars)
        .flat_map(|b| &b.decls)
        .flat_map(|d| &d.names)
        .map(|n| n.name.to_ascii_uppercase())
        .collect()
}

pub(super) fn signatures(source: &Source) -> (Pins, Pins) {
    let (mut functions, mut blocks) = (Pins::new(), Pins::new());
    for item in &source.items {
        let Item::Pou(p) = item else { continue };
        let inputs = p
            .vars
            .iter()
            .filter(|b| matches!(b.kind, VarKind::Input | VarKind::InOut))
            .flat_map(|b| &b.decls)
            .flat_map(|d| {
                d.names
                    .iter()
                    .map(|n| (n.name.clone(), super::print::type_text(&d.ty)))
            })
            .collect();
        let name = p.name.name.to_ascii_uppercase();
        match p.kind {
            PouKind::Function(_) => functions.insert(name, inputs),
            PouKind::FunctionBlock => blocks.insert(name, inputs),
            PouKind::Program => None,
        };
    }
    (functions, blocks)
}

#[derive(Default)]
pub(super) struct Lower {
    pub(super) lines: Vec<(String, Span)>,
    pub(super) errors: Vec<StError>,
    labels: usize,
    /// The end label of each enclosing loop, innermost last (`EXIT`).
    exits: Vec<String>,
    /// The program's own functions and blocks (upper-case) and their
    /// inputs in order.
    pub(super) functions: Pins,
    pub(super) blocks: Pins,
    /// The block instances the POU being lowered declares: upper-case
    /// name to type.
    pub(super) instances: std::collections::HashMap<String, String>,
    /// Own-function calls already made (by their place): the operand that
    /// reads their result.
    pub(super) hoisted: std::collections::HashMap<(u32, u32), String>,
    /// The hidden instances the POU being lowered calls its functions by.
    pub(super) hidden: Vec<(String, String)>,
    /// Every name the source declares (upper-case): a hidden name is
    /// none of them.
    pub(super) taken: std::collections::HashSet<String>,
    /// Starts every label and hidden name (a host's bodies share names).
    pub(super) tag: String,
    /// Each own block's and function's VAR_EXTERNALs (by upper-case
    /// POU): each name, and whether it is copied back out.
    pub(super) externals: std::collections::HashMap<String, Vec<(String, bool)>>,
    /// Each own block's and function's VAR_IN_OUT: (POU, pin), upper-case.
    pub(super) inouts: std::collections::HashSet<(String, String)>,
    /// Where `RETURN` goes in a POU with VAR_IN_OUT (its copy-out).
    pub(super) ret: Option<String>,
    /// A standard function's later inputs computed into hidden
    /// variables, by place (`lower_args`).
    pub(super) std_args: std::collections::HashMap<(u32, u32), String>,
    /// Index expressions computed into hidden variables, by place.
    pub(super) indexed: std::collections::HashMap<(u32, u32), String>,
    /// The POU's (and, in the PROGRAM, the globals') elementary
    /// variables' IL types, by upper-case name.
    pub(super) scalars: std::collections::HashMap<String, String>,
    /// Whether the POU being lowered is the PROGRAM.
    pub(super) in_program: bool,
    /// The source's `VAR_GLOBAL` blocks, declared in its PROGRAM.
    pub(super) globals: Vec<super::ast::VarBlock>,
    /// Whether they are declared (by the first of several programs).
    pub(super) globals_declared: bool,
    /// The source's `TYPE`s, by upper-case name.
    pub(super) types: std::collections::HashMap<String, super::ast::TypeDef>,
    /// The POU being lowered's flattened values: key (`A[1].M`) to
    /// hidden variable; its flattened variables (upper-case); the hidden
    /// variables in order.
    pub(super) flat: std::collections::HashMap<String, String>,
    pub(super) flat_bases: std::collections::HashSet<String>,
    pub(super) shown: Vec<String>,
    pub(super) leaf_count: usize,
    /// Each hidden leaf's place among the POU's leaves, and each
    /// flattened variable's type (upper-case).
    pub(super) order: std::collections::HashMap<String, usize>,
    pub(super) flat_types: std::collections::HashMap<String, super::ast::TypeRef>,
}

impl Lower {
    pub(super) fn emit(&mut self, text: impl Into<String>, span: Span) {
        let text = text.into();
        // `ST x` leaves x's value the current result: a `LD x` right after
        // it (one statement reading what the last wrote) is left out, as a
        // hand-written IL would.
        if let (Some(t), Some((last, _))) = (text.strip_prefix("LD "), self.lines.last()) {
            if last.strip_prefix("ST ") == Some(t) {
                return;
            }
        }
        self.lines.push((text, span));
    }

    pub(super) fn not_yet(&mut self, span: Span, what: impl Into<String>) {
        self.errors.push(at(span, StErrorKind::NotYet(what.into())));
    }

    /// A fresh label (IL labels are their own names: no variable's).
    pub(super) fn label(&mut self) -> String {
        self.labels += 1;
        format!("{}st_{}", self.tag, self.labels)
    }

    pub(super) fn place(&mut self, label: &str, span: Span) {
        self.emit(format!("{label}:"), span);
    }

    pub(super) fn pou(&mut self, p: &Pou, keyword: &str) {
        self.emit(format!("{keyword} {}", p.name.name), p.span);
        self.pou_inside(p);
        self.emit(format!("END_{keyword}"), p.span);
    }

    /// A POU's declarations and body, without its header and end.
    pub(super) fn pou_inside(&mut self, p: &Pou) {
        self.flat.clear();
        self.flat_bases.clear();
        self.shown.clear();
        self.order.clear();
        self.flat_types.clear();
        self.in_program = p.kind == PouKind::Program;
        self.know_scalars(p);
        for b in &p.vars {
            self.block(b);
        }
        if p.kind == PouKind::Program {
            self.global_blocks(p);
        }
        self.body_with_io(p);
    }

    pub(super) fn stmts(&mut self, stmts: &[Stmt]) {
        for s in stmts {
            self.stmt(s);
        }
    }

    fn stmt(&mut self, s: &Stmt) {
        let span = s.span;
        match &s.kind {
            StmtKind::Assign { target, value } => {
                if self.is_flat(target) {
                    return self.flat_assign(target, value, span);
                }
                if !target.path.is_empty() {
                    return self.not_yet(span, "an assignment to a member or element");
                }
                self.value(value);
                self.emit(format!("ST {}", target.base.name), span);
            }
            StmtKind::Call(call) => self.block_call(call, span),
            StmtKind::If {
                branches,
                otherwise,
            } => self.if_stmt(branches, otherwise.as_deref(), span),
            StmtKind::Case {
                selector,
                arms,
                otherwise,
            } => self.case(selector, arms, otherwise.as_deref(), span),
            StmtKind::For {
                var,
                from,
                to,
                by,
                body,
            } => self.for_loop(&var.name, (from, to, by.as_ref()), body, span),
            StmtKind::While { cond, body } => {
                let (top, end) = (self.label(), self.label());
                self.place(&top, span);
                self.value(cond);
                self.emit(format!("JMPCN {end}"), span);
                self.in_loop(&end, body);
                self.emit(format!("JMP {top}"), span);
                self.place(&end, span);
            }
            StmtKind::Repeat { body, until } => {
                let (top, end) = (self.label(), self.label());
                self.place(&top, span);
                self.in_loop(&end, body);
                self.value(until);
                self.emit(format!("JMPCN {top}"), until.span);
                self.place(&end, span);
            }
            StmtKind::Exit => match self.exits.last().cloned() {
                Some(end) => self.emit(format!("JMP {end}"), span),
                None => self.errors.push(at(span, StErrorKind::ExitOutsideLoop)),
            },
            StmtKind::Return => self.return_stmt(span),
            StmtKind::Empty => {}
        }
    }

    fn in_loop(&mut self, end: &str, body: &[Stmt]) {
        self.exits.push(end.to_string());
        self.stmts(body);
        self.exits.pop();
    }

    fn if_stmt(&mut self, branches: &[(Expr, Vec<Stmt>)], otherwise: Option<&[Stmt]>, span: Span) {
        let end = self.label();
        for (cond, body) in branches {
            let next = self.label();
            self.value(cond);
            self.emit(format!("JMPCN {next}"), cond.span);
            self.stmts(body);
            self.emit(format!("JMP {end}"), span);
            self.place(&next, span);
        }
        self.stmts(otherwise.unwrap_or_default());
        self.place(&end, span);
    }

    /// Each label tested in order (the selector read again for each:
    /// only a function could make that differ, and none has effects);
    /// the first arm that matches runs.
    fn case(&mut self, sel: &Expr, arms: &[CaseArm], otherwise: Option<&[Stmt]>, span: Span) {
        let (other, end) = (self.label(), self.label());
        let targets: Vec<String> = arms.iter().map(|_| self.label()).collect();
        self.hoist(sel);
        for (arm, target) in arms.iter().zip(&targets) {
            for l in &arm.labels {
                self.expr(sel);
                match l {
                    CaseLabel::Value(v) => self.operand("EQ", v),
                    CaseLabel::Range(lo, hi) => {
                        self.operand("GE", lo);
                        self.emit("AND(", span);
                        self.expr(sel);
                        self.operand("LE", hi);
                        self.emit(")", span);
                    }
                }
                self.emit(format!("JMPC {target}"), span);
            }
        }
        self.emit(format!("JMP {other}"), span);
        for (arm, target) in arms.iter().zip(&targets) {
            self.place(target, span);
            self.stmts(&arm.body);
            self.emit(format!("JMP {end}"), span);
        }
        self.place(&other, span);
        self.stmts(otherwise.unwrap_or_default());
        self.place(&end, span);
    }

    /// `FOR v := a TO b BY c`: the end and step read at each pass (as
    /// CODESYS does); the loop ends when `v` passes the end in the step's
    /// direction (a step of 0 never ends, and is cut as an endless loop).
    fn for_loop(
        &mut self,
        v: &str,
        (from, to, by): (&Expr, &Expr, Option<&Expr>),
        body: &[Stmt],
        span: Span,
    ) {
        let (top, end, down, run) = (self.label(), self.label(), self.label(), self.label());
        self.value(from);
        self.emit(format!("ST {v}"), span);
        self.place(&top, span);
        match by.map(step_sign) {
            None | Some(Some(false)) => self.past(v, "GT", to, &end, span),
            Some(Some(true)) => self.past(v, "LT", to, &end, span),
            Some(None) => {
                if let Some(step) = by {
                    self.value(step);
                }
                self.emit("LT 0", span);
                self.emit(format!("JMPC {down}"), span);
                self.past(v, "GT", to, &end, span);
                self.emit(format!("JMP {run}"), span);
                self.place(&down, span);
                self.past(v, "LT", to, &end, span);
                self.place(&run, span);
            }
        }
        self.in_loop(&end, body);
        self.emit(format!("LD {v}"), span);
        match by {
            Some(step) => {
                self.hoist(step);
                self.operand("ADD", step)
            }
            None => self.emit("ADD 1", span),
        }
        self.emit(format!("ST {v}"), span);
        self.emit(format!("JMP {top}"), span);
        self.place(&end, span);
    }

    fn past(&mut self, v: &str, cmp: &str, to: &Expr, end: &str, span: Span) {
        self.hoist(to);
        self.emit(format!("LD {v}"), span);
        self.operand(cmp, to);
        self.emit(format!("JMPC {end}"), span);
    }

    /// Leaves `e`'s value as the current result, its own-function calls
    /// made first.
    pub(super) fn value(&mut self, e: &Expr) {
        self.hoist(e);
        self.expr(e);
    }

    /// Leaves `e`'s value as the current result.
    pub(super) fn expr(&mut self, e: &Expr) {
        if let Some(t) = self.simple(e) {
            return self.emit(format!("LD {t}"), e.span);
        }
        if let Some(t) = self.negated(e) {
            return self.emit(format!("LDN {t}"), e.span);
        }
        match &e.kind {
            ExprKind::Unary(UnaryOp::Plus, x) => self.expr(x),
            ExprKind::Unary(UnaryOp::Neg, x) => {
                self.expr(x);
                self.emit("NEG", e.span);
            }
            ExprKind::Unary(UnaryOp::Not, x) => {
                self.expr(x);
                self.emit("NOT", e.span);
            }
            ExprKind::Binary(BinaryOp::Pow, a, b) => self.power(a, b),
            ExprKind::Binary(op, a, b) => {
                self.expr(a);
                self.operand(il_op(*op), b);
            }
            ExprKind::Call(call) => self.function(call, e.span),
            ExprKind::Variable(v) if self.is_flat(v) => self.flat_load(v, e.span),
            ExprKind::Variable(_) => self.not_yet(e.span, "an array element"),
            ExprKind::Literal(_) => {}
        }
    }

    /// `OP b`, or `OP(` … `)` around `b`'s instructions.
    fn operand(&mut self, op: &str, b: &Expr) {
        // `a AND NOT b` is IL's one `ANDN b`, as a hand-written IL has it.
        if let (true, Some(t)) = (matches!(op, "AND" | "OR" | "XOR"), self.negated(b)) {
            return self.emit(format!("{op}N {t}"), b.span);
        }
        match self.simple(b) {
            Some(t) => self.emit(format!("{op} {t}"), b.span),
            None => {
                let open = self.lines.len();
                self.emit(format!("{op}("), b.span);
                self.expr(b);
                // `OP(` / `LD x` is IL's one `OP( x` (not an element:
                // only LD and ST take one).
                if let Some(t) = self
                    .lines
                    .get(open + 1)
                    .and_then(|(l, _)| l.strip_prefix("LD "))
                    .filter(|t| !t.contains('['))
                {
                    self.lines[open].0 = format!("{op}( {t}");
                    self.lines.remove(open + 1);
                }
                self.emit(")", b.span);
            }
        }
    }

    /// A standard function IL has: its first argument the current
    /// result, the others operands.
    fn function(&mut self, call: &super::ast::Call, span: Span) {
        if self
            .functions
            .contains_key(&call.callee.name.to_ascii_uppercase())
        {
            // An own function's call not made: its refusal is said, or
            // it stands where no call is made first (a CASE label).
            if self.errors.is_empty() {
                self.not_yet(span, "a call of the program's own function here");
            }
            return;
        }
        if crate::iec::il::Function::named(&call.callee.name).is_none() {
            let what = format!("the function {}", call.callee.name.to_ascii_uppercase());
            return self.not_yet(call.callee.span, what);
        }
        let values = call.input_values();
        let Some((first, rest)) = values.split_first() else {
            return self.not_yet(span, "a function called without inputs");
        };
        self.expr(first);
        let mut ops = Vec::new();
        for e in rest {
            match self.simple(e).or_else(|| self.made_arg(e)) {
                Some(t) => ops.push(t),
                None => self.not_yet(
                    e.span,
                    "an expression of no known type as a function's second or later input (assign it to a variable first)",
                ),
            }
        }
        let name = call.callee.name.to_ascii_uppercase();
        self.emit(
            format!("{name} {}", ops.join(", ")).trim_end().to_string(),
            span,
        );
    }
}

/// An IL operand for `e`, when it is one: a literal, a variable, a
/// block's output.
pub(super) fn simple(e: &Expr) -> Option<String> {
    use super::ast::{Literal, Selector};
    match &e.kind {
        ExprKind::Literal(l) => Some(super::print::literal_text(l)),
        // A negative number is one operand (`-1`, `INT#-5`), not `NEG`.
        ExprKind::Unary(UnaryOp::Neg, x) => match &x.kind {
            ExprKind::Literal(Literal::Integer(v, t)) => {
                Some(super::print::literal_text(&Literal::Integer(-v, *t)))
            }
            ExprKind::Literal(Literal::Real(v, t)) => {
                Some(super::print::literal_text(&Literal::Real(-v, *t)))
            }
            _ => None,
        },
        ExprKind::Variable(v) => match v.path.as_slice() {
            [] => Some(v.base.name.clone()),
            [Selector::Member(m)] => Some(format!("{}.{}", v.base.name, m.name)),
            _ => None,
        },
        _ => None,
    }
}

/// The operand under `NOT`, when `e` is `NOT operand` of a BOOL or bit
/// string (a variable: `LDN x`, `ANDN x` invert it, as `NOT` does).
impl Lower {
    fn negated(&self, e: &Expr) -> Option<String> {
        match &e.kind {
            ExprKind::Unary(UnaryOp::Not, x) if matches!(x.kind, ExprKind::Variable(_)) => {
                self.simple(x)
            }
            _ => None,
        }
    }
}

/// Whether a FOR step is known negative (`Some(true)`), known not
/// negative (`Some(false)`) or known only when it runs.
fn step_sign(e: &Expr) -> Option<bool> {
    use super::ast::Literal;
    match &e.kind {
        ExprKind::Literal(Literal::Integer(v, _)) => Some(*v < 0),
        ExprKind::Unary(UnaryOp::Neg, x) => step_sign(x).map(|neg| !neg),
        ExprKind::Unary(UnaryOp::Plus, x) => step_sign(x),
        _ => None,
    }
}

fn il_op(op: BinaryOp) -> &'static str {
    match op {
        BinaryOp::Pow => "EXPT",
        BinaryOp::Mul => "MUL",
        BinaryOp::Div => "DIV",
        BinaryOp::Mod => "MOD",
        BinaryOp::Add => "ADD",
        BinaryOp::Sub => "SUB",
        BinaryOp::Lt => "LT",
        BinaryOp::Gt => "GT",
        BinaryOp::Le => "LE",
        BinaryOp::Ge => "GE",
        BinaryOp::Eq => "EQ",
        BinaryOp::Ne => "NE",
        BinaryOp::And => "AND",
        BinaryOp::Xor => "XOR",
        BinaryOp::Or => "OR",
    }
}
