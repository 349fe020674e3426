//! The recursive-descent parser's cursor over the tokens: looking ahead,
//! taking what is expected, and the "expected …, found …" refusals.
//! The grammar itself is in [`super::expr`], [`super::stmt`] and
//! [`super::decl`].

use super::ast::{Ident, Span};
use super::error::{StError, StErrorKind, MAX_DEPTH};
use super::lexer::{Tok, Token};

/// The parser's state: the tokens, the one being looked at and how deep
/// the nesting is.
pub(super) struct Parser {
    tokens: Vec<Token>,
    pos: usize,
    depth: usize,
}

impl Parser {
    /// A parser over `tokens`, which end with [`Tok::Eof`].
    pub(super) fn new(tokens: Vec<Token>) -> Parser {
        Parser {
            tokens,
            pos: 0,
            depth: 0,
        }
    }

    /// The token `ahead` places on (the end, past the last).
    pub(super) fn look(&self, ahead: usize) -> &Token {
        let last = self.tokens.len().saturating_sub(1);
        &self.tokens[(self.pos + ahead).min(last)]
    }

    /// The current token.
    pub(super) fn peek(&self) -> &Tok {
        &self.look(0).tok
    }

    /// Where the current token starts.
    pub(super) fn span(&self) -> Span {
        self.look(0).span
    }

    /// Takes the current token.
    pub(super) fn advance(&mut self) -> Token {
        let t = self.look(0).clone();
        if self.pos + 1 < self.tokens.len() {
            self.pos += 1;
        }
        t
    }

    /// Whether the current token is keyword `kw`.
    pub(super) fn at_kw(&self, kw: &str) -> bool {
        matches!(self.peek(), Tok::Keyword(k) if *k == kw)
    }

    /// Whether the current token is symbol `sym`.
    pub(super) fn at_sym(&self, sym: &str) -> bool {
        matches!(self.peek(), Tok::Sym(s) if *s == sym)
    }

    /// Takes keyword `kw` if it is next.
    pub(super) fn eat_kw(&mut self, kw: &str) -> bool {
        let at = self.at_kw(kw);
        if at {
            self.advance();
        }
        at
    }

    /// Takes symbol `sym` if it is next.
    pub(super) fn eat_sym(&mut self, sym: &str) -> bool {
        let at = self.at_sym(sym);
        if at {
            self.advance();
        }
        at
    }

    /// The refusal "expected `what` `context`, found …" at the current
    /// token.
    pub(super) fn expected(&self, what: &'static str, context: &'static str) -> StError {
        let t = self.look(0);
        let found = match t.tok {
            Tok::Eof => "the end of the text".to_string(),
            // A long token (a string, a comment-like run) is cut: the
            // column already says where it is.
            _ if t.text.chars().count() > 24 => {
                let head: String = t.text.chars().take(20).collect();
                format!("'{head}…'")
            }
            _ => format!("'{}'", t.text),
        };
        StError {
            span: t.span,
            kind: StErrorKind::Expected {
                what,
                context,
                found,
            },
        }
    }

    /// Takes keyword `kw` or refuses.
    pub(super) fn expect_kw(
        &mut self,
        kw: &'static str,
        context: &'static str,
    ) -> Result<(), StError> {
        if self.eat_kw(kw) {
            Ok(())
        } else {
            Err(self.expected(kw, context))
        }
    }

    /// Takes symbol `sym` or refuses.
    pub(super) fn expect_sym(
        &mut self,
        sym: &'static str,
        what: &'static str,
        context: &'static str,
    ) -> Result<(), StError> {
        if self.eat_sym(sym) {
            Ok(())
        } else {
            Err(self.expected(what, context))
        }
    }

    /// Takes a name, or refuses (a keyword in its place is named as one).
    pub(super) fn ident(&mut self, context: &'static str) -> Result<Ident, StError> {
        match self.peek().clone() {
            Tok::Ident(name) => {
                let span = self.advance().span;
                Ok(Ident { name, span })
            }
            Tok::Keyword(_) => Err(StError {
                span: self.span(),
                kind: StErrorKind::ReservedWord(self.look(0).text.clone()),
            }),
            _ => Err(self.expected("a name", context)),
        }
    }

    /// Goes one level deeper, refusing past [`MAX_DEPTH`].
    pub(super) fn enter(&mut self) -> Result<(), StError> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(StError {
                span: self.span(),
                kind: StErrorKind::TooDeep,
            });
        }
        Ok(())
    }

    /// Comes back one level.
    pub(super) fn leave(&mut self) {
        self.depth = self.depth.saturating_sub(1);
    }
}

impl Parser {
    /// Statements to the end of the text.
    pub(super) fn body(&mut self) -> Result<Vec<super::ast::Stmt>, StError> {
        let mut out = Vec::new();
        while !matches!(self.peek(), Tok::Eof) {
            out.push(self.statement()?);
        }
        Ok(out)
    }

    /// Refuses anything left before the end.
    pub(super) fn end(&self) -> Result<(), StError> {
        match self.peek() {
            Tok::Eof => Ok(()),
            _ => Err(self.expected("the end of the text", "after the expression")),
        }
    }
}
