//! Declarations: the POUs (`PROGRAM`, `FUNCTION name : TYPE`,
//! `FUNCTION_BLOCK`), their `VAR…` blocks, `TYPE … END_TYPE` (arrays,
//! structures, other names for a type) and the initial values.

use super::ast::{
    ArrayInit, Elementary, Init, Item, Literal, Pou, PouKind, Source, Span, TypeDecl, TypeDef,
    TypeRef, VarBlock, VarDecl, VarKind,
};
use super::error::{StError, StErrorKind};
use super::lexer::Tok;
use super::parser::Parser;

/// The `VAR…` keywords and the section each opens.
const SECTIONS: [(&str, VarKind); 7] = [
    ("VAR_INPUT", VarKind::Input),
    ("VAR_OUTPUT", VarKind::Output),
    ("VAR_IN_OUT", VarKind::InOut),
    ("VAR", VarKind::Local),
    ("VAR_TEMP", VarKind::Temp),
    ("VAR_GLOBAL", VarKind::Global),
    ("VAR_EXTERNAL", VarKind::External),
];

impl Parser {
    /// A whole source, to its end.
    pub(super) fn source(&mut self) -> Result<Source, StError> {
        let mut items = Vec::new();
        while !matches!(self.peek(), Tok::Eof) {
            items.push(self.item()?);
        }
        Ok(Source { items })
    }

    fn item(&mut self) -> Result<Item, StError> {
        let span = self.span();
        let (kind, end) = if self.eat_kw("PROGRAM") {
            (PouKind::Program, "END_PROGRAM")
        } else if self.eat_kw("FUNCTION_BLOCK") {
            (PouKind::FunctionBlock, "END_FUNCTION_BLOCK")
        } else if self.eat_kw("FUNCTION") {
            (
                PouKind::Function(TypeRef::Elementary(Elementary::Bool)),
                "END_FUNCTION",
            )
        } else if self.eat_kw("TYPE") {
            return self.types().map(Item::Types);
        } else if self.at_kw("VAR_GLOBAL") {
            return self.var_block().map(Item::Globals);
        } else {
            let what = "PROGRAM, FUNCTION, FUNCTION_BLOCK, TYPE or VAR_GLOBAL";
            return Err(self.expected(what, "at the top level"));
        };
        let name = self.ident("after the POU's keyword")?;
        let kind = match kind {
            PouKind::Function(_) => {
                self.expect_sym(
                    ":",
                    "':' and the result's type",
                    "after the function's name",
                )?;
                PouKind::Function(self.type_ref("as the function's result")?)
            }
            k => k,
        };
        let mut vars = Vec::new();
        while SECTIONS.iter().any(|(k, _)| self.at_kw(k)) {
            vars.push(self.var_block()?);
        }
        let body = self.stmts(&[end])?;
        self.advance();
        Ok(Item::Pou(Pou {
            kind,
            name,
            vars,
            body,
            span,
        }))
    }

    /// `VAR_… [CONSTANT] [RETAIN] decls END_VAR`.
    fn var_block(&mut self) -> Result<VarBlock, StError> {
        let span = self.span();
        let kind = SECTIONS
            .iter()
            .find(|(k, _)| self.at_kw(k))
            .map(|(_, kind)| *kind)
            .ok_or_else(|| self.expected("VAR", "here"))?;
        self.advance();
        let (mut constant, mut retain) = (false, false);
        loop {
            if self.eat_kw("CONSTANT") {
                constant = true;
            } else if self.eat_kw("RETAIN") {
                retain = true;
            } else if !self.eat_kw("NON_RETAIN") {
                break;
            }
        }
        let mut decls = Vec::new();
        while !self.eat_kw("END_VAR") {
            decls.push(self.var_decl("END_VAR")?);
        }
        Ok(VarBlock {
            kind,
            constant,
            retain,
            decls,
            span,
        })
    }

    /// `a, b AT %IX0.0 : T := init;`; `end` names the block's end for
    /// the refusal when neither comes.
    fn var_decl(&mut self, end: &'static str) -> Result<VarDecl, StError> {
        let span = self.span();
        // A keyword followed by `:` or `,` was meant as a name: say so.
        let misnamed = matches!(self.peek(), Tok::Keyword(_))
            && matches!(self.look(1).tok, Tok::Sym(":" | ","));
        if !matches!(self.peek(), Tok::Ident(_)) && !misnamed {
            return Err(self.expected(
                "a name",
                if end == "END_VAR" {
                    "to declare, or END_VAR"
                } else {
                    "to declare, or END_STRUCT"
                },
            ));
        }
        let mut names = vec![self.ident("")?];
        while self.eat_sym(",") {
            names.push(self.ident("after ','")?);
        }
        let location = if self.eat_kw("AT") {
            match self.peek().clone() {
                Tok::Direct(text) => {
                    self.advance();
                    Some(text)
                }
                _ => return Err(self.expected("an address (%IX0.0)", "after AT")),
            }
        } else {
            None
        };
        self.expect_sym(":", "':' and a type", "after the declared name")?;
        let ty = self.type_ref("in the declaration")?;
        let init = self.init_opt()?;
        self.expect_sym(";", "';'", "after the declaration")?;
        Ok(VarDecl {
            names,
            location,
            ty,
            init,
            span,
        })
    }

    /// `:= init` when written.
    fn init_opt(&mut self) -> Result<Option<Init>, StError> {
        if self.eat_sym(":=") {
            Ok(Some(self.init()?))
        } else {
            Ok(None)
        }
    }

    /// A type: elementary, `STRING[n]`, `ARRAY […] OF T` or a name.
    fn type_ref(&mut self, context: &'static str) -> Result<TypeRef, StError> {
        if self.eat_kw("ARRAY") {
            return self.array_type();
        }
        let name = self.ident(context)?;
        if name.name.eq_ignore_ascii_case("STRING") {
            return self.string_type();
        }
        let ty = match Elementary::from_name(&name.name) {
            Some(t) => TypeRef::Elementary(t),
            None => TypeRef::Named(name),
        };
        if self.at_sym("(") {
            return Err(self.unsupported("a subrange type `T (low..high)`"));
        }
        Ok(ty)
    }

    fn string_type(&mut self) -> Result<TypeRef, StError> {
        let close = if self.eat_sym("[") {
            "]"
        } else if self.eat_sym("(") {
            ")"
        } else {
            return Ok(TypeRef::String(None));
        };
        let span = self.span();
        let n = self.bound()?;
        let n = u32::try_from(n)
            .ok()
            .filter(|n| *n > 0)
            .ok_or_else(|| Self::bad_bound(span, n))?;
        self.expect_sym(close, "the closing bracket", "after the STRING's length")?;
        Ok(TypeRef::String(Some(n)))
    }

    fn array_type(&mut self) -> Result<TypeRef, StError> {
        self.expect_sym("[", "'['", "after ARRAY")?;
        let mut dims = Vec::new();
        loop {
            let span = self.span();
            let low = self.bound()?;
            self.expect_sym("..", "'..'", "between an array's bounds")?;
            let high = self.bound()?;
            if high < low {
                let kind = StErrorKind::EmptyRange(low, high);
                return Err(StError { span, kind });
            }
            dims.push((low, high));
            if self.eat_sym("]") {
                break;
            }
            self.expect_sym(",", "',' or ']'", "after an array's bounds")?;
        }
        self.expect_kw("OF", "after the array's bounds")?;
        self.enter()?;
        let of = self.type_ref("after OF");
        self.leave();
        Ok(TypeRef::Array {
            dims,
            of: Box::new(of?),
        })
    }

    /// A whole number written as a literal, maybe negative.
    fn bound(&mut self) -> Result<i128, StError> {
        let negative = self.eat_sym("-");
        match self.peek().clone() {
            Tok::Literal(Literal::Integer(v, _)) => {
                self.advance();
                Ok(if negative { -v } else { v })
            }
            _ => Err(self.expected("a whole number", "as a bound")),
        }
    }

    fn bad_bound(span: Span, n: i128) -> StError {
        StError {
            span,
            kind: StErrorKind::BadBound(n.to_string()),
        }
    }

    pub(super) fn unsupported(&self, what: &'static str) -> StError {
        StError {
            span: self.span(),
            kind: StErrorKind::Unsupported(what),
        }
    }

    /// An initial value: `[…]` for an array, `(m := v, …)` for a
    /// structure, an expression otherwise.
    fn init(&mut self) -> Result<Init, StError> {
        self.enter()?;
        let init = if self.eat_sym("[") {
            self.array_init().map(Init::Array)
        } else if self.at_sym("(")
            && matches!(self.look(1).tok, Tok::Ident(_))
            && matches!(self.look(2).tok, Tok::Sym(":="))
        {
            self.advance();
            self.struct_init().map(Init::Struct)
        } else {
            self.expr("as the initial value").map(Init::Expr)
        };
        self.leave();
        init
    }

    fn array_init(&mut self) -> Result<Vec<ArrayInit>, StError> {
        let mut out = Vec::new();
        loop {
            let repeat = matches!(self.peek(), Tok::Literal(Literal::Integer(..)))
                && matches!(self.look(1).tok, Tok::Sym("("));
            if repeat {
                let span = self.span();
                let n = self.bound()?;
                let n = u32::try_from(n).map_err(|_| Self::bad_bound(span, n))?;
                self.advance();
                let value = if self.at_sym(")") {
                    None
                } else {
                    Some(self.init()?)
                };
                self.expect_sym(")", "')'", "after the repeated value")?;
                out.push(ArrayInit::Repeat(n, value));
            } else {
                out.push(ArrayInit::One(self.init()?));
            }
            if self.eat_sym("]") {
                return Ok(out);
            }
            self.expect_sym(",", "',' or ']'", "after an array element")?;
        }
    }

    fn struct_init(&mut self) -> Result<Vec<(super::ast::Ident, Init)>, StError> {
        let mut out = Vec::new();
        loop {
            let name = self.ident("in the structure's value")?;
            self.expect_sym(":=", "':='", "after the member's name")?;
            out.push((name, self.init()?));
            if self.eat_sym(")") {
                return Ok(out);
            }
            self.expect_sym(",", "',' or ')'", "after a member's value")?;
        }
    }

    /// `TYPE name : … ; … END_TYPE` (its `TYPE` taken).
    fn types(&mut self) -> Result<Vec<TypeDecl>, StError> {
        let mut out = Vec::new();
        while !self.eat_kw("END_TYPE") {
            let name = self.ident("to declare, or END_TYPE")?;
            self.expect_sym(":", "':'", "after the type's name")?;
            let def = if self.eat_kw("STRUCT") {
                let mut members = Vec::new();
                while !self.eat_kw("END_STRUCT") {
                    members.push(self.var_decl("END_STRUCT")?);
                }
                TypeDef::Struct(members)
            } else if self.at_sym("(") {
                return Err(self.unsupported("an enumerated type `(a, b, …)`"));
            } else {
                let ty = self.type_ref("after ':'")?;
                TypeDef::Alias(ty, self.init_opt()?)
            };
            self.expect_sym(";", "';'", "after the type")?;
            out.push(TypeDecl { name, def });
        }
        Ok(out)
    }
}
