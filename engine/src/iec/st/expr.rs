//! Expressions, with the standard's precedence (its grammar, B.3.1),
//! loosest first: `OR`; `XOR`; `AND`/`&`; `=` `<>`; `<` `>` `<=` `>=`;
//! `+` `-`; `*` `/` `MOD`; `**`; the unary `-` `+` `NOT`; then calls,
//! variables, literals and parentheses. Operators of one level apply
//! left to right (`2 ** 3 ** 2` is `(2 ** 3) ** 2`).

use super::ast::{Arg, BinaryOp, Call, Expr, ExprKind, Ident, Selector, UnaryOp, Variable};
use super::error::{StError, StErrorKind};
use super::lexer::Tok;
use super::parser::Parser;

/// The binary operators of each level, loosest first.
const LEVELS: [&[(&str, BinaryOp)]; 8] = [
    &[("OR", BinaryOp::Or)],
    &[("XOR", BinaryOp::Xor)],
    &[("AND", BinaryOp::And), ("&", BinaryOp::And)],
    &[("=", BinaryOp::Eq), ("<>", BinaryOp::Ne)],
    &[
        ("<", BinaryOp::Lt),
        (">", BinaryOp::Gt),
        ("<=", BinaryOp::Le),
        (">=", BinaryOp::Ge),
    ],
    &[("+", BinaryOp::Add), ("-", BinaryOp::Sub)],
    &[
        ("*", BinaryOp::Mul),
        ("/", BinaryOp::Div),
        ("MOD", BinaryOp::Mod),
    ],
    &[("**", BinaryOp::Pow)],
];

impl Parser {
    /// An expression; `context` says where, for the refusal when none is
    /// there (`after ':='`).
    pub(super) fn expr(&mut self, context: &'static str) -> Result<Expr, StError> {
        self.enter()?;
        let e = self.level(0, context);
        self.leave();
        e
    }

    /// The binary operator of `level` at the current token, if any.
    fn operator(&self, level: usize) -> Option<BinaryOp> {
        let text = match self.peek() {
            Tok::Sym(s) => *s,
            Tok::Keyword(k) => *k,
            _ => return None,
        };
        LEVELS[level]
            .iter()
            .find(|(t, _)| *t == text)
            .map(|(_, op)| *op)
    }

    fn level(&mut self, level: usize, context: &'static str) -> Result<Expr, StError> {
        if level == LEVELS.len() {
            return self.unary(context);
        }
        let mut lhs = self.level(level + 1, context)?;
        while let Some(op) = self.operator(level) {
            self.advance();
            let rhs = self.level(level + 1, "after an operator")?;
            let span = lhs.span;
            lhs = Expr {
                kind: ExprKind::Binary(op, Box::new(lhs), Box::new(rhs)),
                span,
            };
        }
        Ok(lhs)
    }

    fn unary(&mut self, context: &'static str) -> Result<Expr, StError> {
        let span = self.span();
        let op = if self.eat_sym("-") {
            UnaryOp::Neg
        } else if self.eat_sym("+") {
            UnaryOp::Plus
        } else if self.eat_kw("NOT") {
            UnaryOp::Not
        } else {
            return self.primary(context);
        };
        self.enter()?;
        let operand = self.unary("after a unary operator");
        self.leave();
        Ok(Expr {
            kind: ExprKind::Unary(op, Box::new(operand?)),
            span,
        })
    }

    fn primary(&mut self, context: &'static str) -> Result<Expr, StError> {
        let span = self.span();
        let kind = match self.peek().clone() {
            Tok::Literal(l) => {
                self.advance();
                ExprKind::Literal(l)
            }
            Tok::Sym("(") => {
                self.advance();
                let e = self.expr("after '('")?;
                self.expect_sym(")", "')'", "to close the parenthesis")?;
                return Ok(e);
            }
            Tok::Direct(text) => {
                self.advance();
                ExprKind::Variable(Variable {
                    base: Ident { name: text, span },
                    path: Vec::new(),
                })
            }
            Tok::Ident(name) if name.eq_ignore_ascii_case("REF") && self.look(1).text == "(" => {
                let what = "`REF()` (references and pointers)";
                return Err(StError {
                    span,
                    kind: StErrorKind::Unsupported(what),
                });
            }
            Tok::Ident(_) => self.named()?,
            _ => return Err(self.expected("an expression", context)),
        };
        Ok(Expr { kind, span })
    }

    /// A name in an expression: a call `f(…)` or a variable.
    fn named(&mut self) -> Result<ExprKind, StError> {
        let var = self.variable("")?;
        if self.at_sym("(") {
            return self.call_of(var).map(ExprKind::Call);
        }
        Ok(ExprKind::Variable(var))
    }

    /// A variable: a name (or direct address) with `[…]` and `.m` steps.
    pub(super) fn variable(&mut self, context: &'static str) -> Result<Variable, StError> {
        let base = match self.peek().clone() {
            Tok::Direct(text) => Ident {
                name: text,
                span: self.advance().span,
            },
            _ => self.ident(context)?,
        };
        let mut path = Vec::new();
        loop {
            if self.eat_sym("[") {
                let mut index = vec![self.expr("after '['")?];
                while self.eat_sym(",") {
                    index.push(self.expr("after ','")?);
                }
                self.expect_sym("]", "']'", "to close the index")?;
                path.push(Selector::Index(index));
            } else if self.eat_sym(".") {
                path.push(Selector::Member(self.ident("after '.'")?));
            } else {
                return Ok(Variable { base, path });
            }
        }
    }

    /// The arguments of a call of `var`, at its `(`.
    pub(super) fn call_of(&mut self, var: Variable) -> Result<Call, StError> {
        if !var.path.is_empty() {
            let what = "calling a member (methods, object-oriented extensions)";
            return Err(StError {
                span: self.span(),
                kind: StErrorKind::Unsupported(what),
            });
        }
        self.enter()?;
        let args = self.args();
        self.leave();
        Ok(Call {
            callee: var.base,
            args: args?,
        })
    }

    fn args(&mut self) -> Result<Vec<Arg>, StError> {
        self.expect_sym("(", "'('", "to open the arguments")?;
        let mut args = Vec::new();
        if self.eat_sym(")") {
            return Ok(args);
        }
        loop {
            let span = self.span();
            let arg = self.arg()?;
            if matches!(arg, Arg::Positional(_))
                && args.iter().any(|a| !matches!(a, Arg::Positional(_)))
            {
                return Err(StError {
                    span,
                    kind: StErrorKind::PositionalAfterNamed,
                });
            }
            args.push(arg);
            if self.eat_sym(")") {
                return Ok(args);
            }
            self.expect_sym(",", "',' or ')'", "after an argument")?;
        }
    }

    /// `IN := x`, `Q => y`, `NOT Q => y` or a positional `x`.
    fn arg(&mut self) -> Result<Arg, StError> {
        let named = |p: &Parser, at: usize| {
            matches!(p.look(at).tok, Tok::Ident(_))
                && matches!(p.look(at + 1).tok, Tok::Sym(":=" | "=>"))
        };
        let negated = self.at_kw("NOT") && named(self, 1);
        if !(negated || named(self, 0)) {
            return self.expr("as an argument").map(Arg::Positional);
        }
        if negated {
            self.advance();
        }
        let name = self.ident("")?;
        if self.eat_sym("=>") {
            let target = self.variable("after '=>'")?;
            return Ok(Arg::Output {
                name,
                negated,
                target,
            });
        }
        if negated {
            return Err(self.expected("'=>'", "after NOT and an output's name"));
        }
        self.advance();
        Ok(Arg::Input(name, self.expr("after ':='")?))
    }
}
