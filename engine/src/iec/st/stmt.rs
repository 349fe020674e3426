//! Statements: assignments, calls, `IF`, `CASE`, the three loops,
//! `EXIT`, `RETURN` and the empty statement.

use super::ast::{CaseArm, CaseLabel, Stmt, StmtKind};
use super::error::StError;
use super::lexer::Tok;
use super::parser::Parser;

impl Parser {
    /// Statements until one of the keywords in `ends` (not taken).
    pub(super) fn stmts(&mut self, ends: &[&'static str]) -> Result<Vec<Stmt>, StError> {
        let mut out = Vec::new();
        while !ends.iter().any(|e| self.at_kw(e)) {
            if matches!(self.peek(), Tok::Eof) {
                return Err(self.expected(ends[0], "to close the statements"));
            }
            out.push(self.statement()?);
        }
        Ok(out)
    }

    /// One statement, its `;` taken.
    pub(super) fn statement(&mut self) -> Result<Stmt, StError> {
        let span = self.span();
        self.enter()?;
        let kind = self.stmt_kind();
        self.leave();
        let kind = kind?;
        if !matches!(kind, StmtKind::Empty) {
            self.expect_sym(";", "';'", "after the statement")?;
        }
        Ok(Stmt { kind, span })
    }

    fn stmt_kind(&mut self) -> Result<StmtKind, StError> {
        let Tok::Keyword(kw) = self.peek().clone() else {
            if self.eat_sym(";") {
                return Ok(StmtKind::Empty);
            }
            return self.assign_or_call();
        };
        if !matches!(
            kw,
            "IF" | "CASE" | "FOR" | "WHILE" | "REPEAT" | "EXIT" | "RETURN"
        ) {
            return Err(self.expected("a statement", "here"));
        }
        self.advance();
        match kw {
            "IF" => self.if_stmt(),
            "CASE" => self.case_stmt(),
            "FOR" => self.for_stmt(),
            "WHILE" => {
                let cond = self.expr("after WHILE")?;
                self.expect_kw("DO", "after the WHILE condition")?;
                let body = self.stmts(&["END_WHILE"])?;
                self.advance();
                Ok(StmtKind::While { cond, body })
            }
            "REPEAT" => {
                let body = self.stmts(&["UNTIL"])?;
                self.advance();
                let until = self.expr("after UNTIL")?;
                self.expect_kw("END_REPEAT", "after the UNTIL condition")?;
                Ok(StmtKind::Repeat { body, until })
            }
            "EXIT" => Ok(StmtKind::Exit),
            _ => Ok(StmtKind::Return),
        }
    }

    /// `x := e` or `f(…)`.
    fn assign_or_call(&mut self) -> Result<StmtKind, StError> {
        if !matches!(self.peek(), Tok::Ident(_) | Tok::Direct(_)) {
            return Err(self.expected("a statement", "here"));
        }
        let target = self.variable("")?;
        if self.at_sym("(") {
            return self.call_of(target).map(StmtKind::Call);
        }
        self.expect_sym(":=", "':='", "after the variable assigned")?;
        let value = self.expr("after ':='")?;
        Ok(StmtKind::Assign { target, value })
    }

    fn if_stmt(&mut self) -> Result<StmtKind, StError> {
        let mut branches = Vec::new();
        let mut otherwise = None;
        loop {
            let cond = self.expr("after IF")?;
            self.expect_kw("THEN", "after the IF condition")?;
            let body = self.stmts(&["END_IF", "ELSIF", "ELSE"])?;
            branches.push((cond, body));
            if self.eat_kw("ELSIF") {
                continue;
            }
            if self.eat_kw("ELSE") {
                otherwise = Some(self.stmts(&["END_IF"])?);
            }
            self.expect_kw("END_IF", "to close the IF")?;
            return Ok(StmtKind::If {
                branches,
                otherwise,
            });
        }
    }

    fn case_stmt(&mut self) -> Result<StmtKind, StError> {
        let selector = self.expr("after CASE")?;
        self.expect_kw("OF", "after the CASE selector")?;
        let mut arms = Vec::new();
        while !self.at_kw("ELSE") && !self.at_kw("END_CASE") {
            let labels = self.case_labels()?;
            let mut body = Vec::new();
            while !self.at_kw("ELSE") && !self.at_kw("END_CASE") && !self.at_label() {
                if matches!(self.peek(), Tok::Eof) {
                    return Err(self.expected("END_CASE", "to close the CASE"));
                }
                body.push(self.statement()?);
            }
            arms.push(CaseArm { labels, body });
        }
        let otherwise = if self.eat_kw("ELSE") {
            Some(self.stmts(&["END_CASE"])?)
        } else {
            None
        };
        self.expect_kw("END_CASE", "to close the CASE")?;
        Ok(StmtKind::Case {
            selector,
            arms,
            otherwise,
        })
    }

    /// Whether a `CASE` label starts here: a `:` comes before any `:=`,
    /// `;`, keyword or the end.
    fn at_label(&self) -> bool {
        for ahead in 0.. {
            match &self.look(ahead).tok {
                Tok::Sym(":") => return true,
                Tok::Sym(":=" | ";") | Tok::Keyword(_) | Tok::Eof => return false,
                _ => {}
            }
        }
        false
    }

    /// `1, 3..5, 7 :`.
    fn case_labels(&mut self) -> Result<Vec<CaseLabel>, StError> {
        let mut labels = Vec::new();
        loop {
            let low = self.expr("as a CASE label")?;
            labels.push(if self.eat_sym("..") {
                CaseLabel::Range(low, self.expr("after '..'")?)
            } else {
                CaseLabel::Value(low)
            });
            if self.eat_sym(":") {
                return Ok(labels);
            }
            self.expect_sym(",", "',' or ':'", "after a CASE label")?;
        }
    }

    fn for_stmt(&mut self) -> Result<StmtKind, StError> {
        let var = self.ident("after FOR")?;
        self.expect_sym(":=", "':='", "after the FOR variable")?;
        let from = self.expr("after ':='")?;
        self.expect_kw("TO", "after the FOR start value")?;
        let to = self.expr("after TO")?;
        let by = if self.eat_kw("BY") {
            Some(self.expr("after BY")?)
        } else {
            None
        };
        self.expect_kw("DO", "after the FOR range")?;
        let body = self.stmts(&["END_FOR"])?;
        self.advance();
        Ok(StmtKind::For {
            var,
            from,
            to,
            by,
            body,
        })
    }
}
