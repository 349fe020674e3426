//! Structured Text's tokens: names, keywords (any case), literals,
//! direct addresses and symbols, with the comments (`(* *)` nested as the
//! 3rd edition allows, and `//`) skipped.

use super::ast::{Elementary, Literal, Span};
use super::error::{StError, StErrorKind};
use crate::iec::address::Address;
use crate::iec::data::Data;
use crate::iec::literal::{parse_literal, parse_text, untyped_integer, LiteralError};

/// One token.
#[derive(Clone, Debug, PartialEq)]
pub enum Tok {
    /// A name.
    Ident(String),
    /// A keyword, upper-cased.
    Keyword(&'static str),
    /// A literal's value.
    Literal(Literal),
    /// `%IX0.0` and the like, as written.
    Direct(String),
    /// An operator or punctuation.
    Sym(&'static str),
    /// The end of the text.
    Eof,
}

/// A token with where it starts and its text as written.
#[derive(Clone, Debug, PartialEq)]
pub struct Token {
    /// The token.
    pub tok: Tok,
    /// Where it starts.
    pub span: Span,
    /// Its text as written (for messages).
    pub text: String,
}

/// The words the language reserves (what a keyword token may be).
pub const KEYWORDS: [&str; 48] = [
    "IF",
    "THEN",
    "ELSIF",
    "ELSE",
    "END_IF",
    "CASE",
    "OF",
    "END_CASE",
    "FOR",
    "TO",
    "BY",
    "DO",
    "END_FOR",
    "WHILE",
    "END_WHILE",
    "REPEAT",
    "UNTIL",
    "END_REPEAT",
    "EXIT",
    "RETURN",
    "NOT",
    "MOD",
    "AND",
    "OR",
    "XOR",
    "PROGRAM",
    "END_PROGRAM",
    "FUNCTION",
    "END_FUNCTION",
    "FUNCTION_BLOCK",
    "END_FUNCTION_BLOCK",
    "VAR",
    "VAR_INPUT",
    "VAR_OUTPUT",
    "VAR_IN_OUT",
    "VAR_TEMP",
    "VAR_GLOBAL",
    "VAR_EXTERNAL",
    "END_VAR",
    "CONSTANT",
    "RETAIN",
    "NON_RETAIN",
    "AT",
    "TYPE",
    "END_TYPE",
    "STRUCT",
    "END_STRUCT",
    "ARRAY",
];

/// Words of the parts of the language left out, refused where written.
const LEFT_OUT: [(&str, &str); 12] = [
    ("REF_TO", "`REF_TO` (references and pointers)"),
    ("POINTER", "`POINTER` (references and pointers)"),
    ("METHOD", "`METHOD` (object-oriented extensions)"),
    ("END_METHOD", "`END_METHOD` (object-oriented extensions)"),
    ("INTERFACE", "`INTERFACE` (object-oriented extensions)"),
    ("EXTENDS", "`EXTENDS` (object-oriented extensions)"),
    ("IMPLEMENTS", "`IMPLEMENTS` (object-oriented extensions)"),
    ("PROPERTY", "`PROPERTY` (object-oriented extensions)"),
    ("CLASS", "`CLASS` (object-oriented extensions)"),
    ("THIS", "`THIS` (object-oriented extensions)"),
    ("SUPER", "`SUPER` (object-oriented extensions)"),
    ("WSTRING", "WSTRING (wide strings)"),
];

const SYMBOLS2: [&str; 7] = [":=", "=>", "..", "**", "<=", ">=", "<>"];
const SYMBOLS1: [&str; 16] = [
    "(", ")", "[", "]", ",", ";", ":", ".", "+", "-", "*", "/", "<", ">", "=", "&",
];

struct Lexer {
    chars: Vec<char>,
    pos: usize,
    line: u32,
    column: u32,
}

/// The tokens of `text`, ending with [`Tok::Eof`].
pub fn tokenize(text: &str) -> Result<Vec<Token>, StError> {
    let mut lx = Lexer {
        chars: text.chars().collect(),
        pos: 0,
        line: 1,
        column: 1,
    };
    let mut out = Vec::new();
    loop {
        lx.skip_blanks()?;
        let span = lx.span();
        let Some(c) = lx.peek(0) else {
            out.push(Token {
                tok: Tok::Eof,
                span,
                text: String::new(),
            });
            return Ok(out);
        };
        let start = lx.pos;
        let tok = lx.token(c, span)?;
        let text = lx.chars[start..lx.pos].iter().collect();
        out.push(Token { tok, span, text });
    }
}

fn err(span: Span, kind: StErrorKind) -> StError {
    StError { span, kind }
}

impl Lexer {
    fn span(&self) -> Span {
        Span {
            line: self.line,
            column: self.column,
        }
    }

    fn peek(&self, ahead: usize) -> Option<char> {
        self.chars.get(self.pos + ahead).copied()
    }

    fn bump(&mut self) -> Option<char> {
        let c = self.peek(0)?;
        self.pos += 1;
        if c == '\n' {
            self.line += 1;
            self.column = 1;
        } else {
            self.column += 1;
        }
        Some(c)
    }

    fn eat_while(&mut self, keep: impl Fn(char) -> bool) -> String {
        let mut s = String::new();
        while let Some(c) = self.peek(0).filter(|&c| keep(c)) {
            s.push(c);
            self.bump();
        }
        s
    }

    /// Skips white space and comments.
    fn skip_blanks(&mut self) -> Result<(), StError> {
        loop {
            match (self.peek(0), self.peek(1)) {
                (Some(c), _) if c.is_whitespace() => {
                    self.bump();
                }
                (Some('/'), Some('/')) => {
                    self.eat_while(|c| c != '\n');
                }
                (Some('('), Some('*')) => self.comment()?,
                _ => return Ok(()),
            }
        }
    }

    /// A `(* … *)` comment, nested ones inside it.
    fn comment(&mut self) -> Result<(), StError> {
        let span = self.span();
        let mut depth = 0usize;
        loop {
            match (self.peek(0), self.peek(1)) {
                (Some('('), Some('*')) => {
                    depth += 1;
                    self.bump();
                    self.bump();
                }
                (Some('*'), Some(')')) => {
                    depth -= 1;
                    self.bump();
                    self.bump();
                    if depth == 0 {
                        return Ok(());
                    }
                }
                (Some(_), _) => {
                    self.bump();
                }
                (None, _) => return Err(err(span, StErrorKind::UnclosedComment)),
            }
        }
    }

    fn token(&mut self, c: char, span: Span) -> Result<Tok, StError> {
        if c.is_ascii_alphabetic() || c == '_' {
            return self.word(span);
        }
        if c.is_ascii_digit() {
            return self.number(span);
        }
        match c {
            '\'' => return self.string(span).map(Tok::Literal),
            '%' => {
                self.bump();
                let rest = self.eat_while(|c| c.is_ascii_alphanumeric() || c == '.');
                let text = format!("%{rest}");
                return match Address::parse(&text) {
                    Ok(_) => Ok(Tok::Direct(text)),
                    Err(e) => Err(err(span, StErrorKind::BadAddress(e))),
                };
            }
            '"' => {
                return Err(err(
                    span,
                    StErrorKind::Unsupported("WSTRING (wide strings)"),
                ))
            }
            '^' => {
                let what = "`^` (references and pointers)";
                return Err(err(span, StErrorKind::Unsupported(what)));
            }
            '{' => return Err(err(span, StErrorKind::Unsupported("a pragma `{…}`"))),
            _ => {}
        }
        let two: String = [Some(c), self.peek(1)].iter().flatten().collect();
        let sym = SYMBOLS2
            .iter()
            .find(|s| **s == two)
            .or_else(|| SYMBOLS1.iter().find(|s| s.starts_with(c)));
        let Some(sym) = sym else {
            return Err(err(span, StErrorKind::UnexpectedChar(c)));
        };
        for _ in 0..sym.len() {
            self.bump();
        }
        Ok(Tok::Sym(sym))
    }

    /// A name, a keyword, `TRUE`/`FALSE` or a typed literal (`INT#5`).
    fn word(&mut self, span: Span) -> Result<Tok, StError> {
        let word = self.eat_while(|c| c.is_ascii_alphanumeric() || c == '_');
        let upper = word.to_ascii_uppercase();
        if self.peek(0) == Some('#') {
            self.bump();
            return self.typed(&word, span).map(Tok::Literal);
        }
        if let Some((_, what)) = LEFT_OUT.iter().find(|(w, _)| *w == upper) {
            return Err(err(span, StErrorKind::Unsupported(what)));
        }
        Ok(match upper.as_str() {
            "TRUE" => Tok::Literal(Literal::Bool(true)),
            "FALSE" => Tok::Literal(Literal::Bool(false)),
            _ => match KEYWORDS.iter().find(|k| **k == upper) {
                Some(k) => Tok::Keyword(k),
                None => Tok::Ident(word),
            },
        })
    }

    /// The digits of a number in some base, `_` between them kept.
    fn digits(&mut self) -> String {
        self.eat_while(|c| c.is_ascii_alphanumeric() || c == '_')
    }

    /// An untyped number: `42`, `16#FF`, `1.5`, `2.0E-3`.
    fn number(&mut self, span: Span) -> Result<Tok, StError> {
        let start = self.pos;
        self.unsigned_number();
        let text: String = self.chars[start..self.pos].iter().collect();
        number_value(&text, None, span).map(Tok::Literal)
    }

    /// Moves over an unsigned number (integer, based or real).
    fn unsigned_number(&mut self) {
        self.eat_while(|c| c.is_ascii_digit() || c == '_');
        if self.peek(0) == Some('#') {
            self.bump();
            self.digits();
            return;
        }
        if self.peek(0) == Some('.') && self.peek(1).is_some_and(|c| c.is_ascii_digit()) {
            self.bump();
            self.eat_while(|c| c.is_ascii_digit() || c == '_');
            let sign = matches!(self.peek(1), Some('+' | '-')) as usize;
            if matches!(self.peek(0), Some('e' | 'E'))
                && self.peek(1 + sign).is_some_and(|c| c.is_ascii_digit())
            {
                for _ in 0..=sign {
                    self.bump();
                }
                self.eat_while(|c| c.is_ascii_digit());
            }
        }
    }

    /// `'…'` with its `$` escapes.
    fn string(&mut self, span: Span) -> Result<Literal, StError> {
        let mut text = String::from("'");
        self.bump();
        loop {
            match self.bump() {
                None | Some('\n') => return Err(err(span, StErrorKind::UnclosedString)),
                Some('\'') => break,
                Some('$') => {
                    text.push('$');
                    match self.bump() {
                        None | Some('\n') => return Err(err(span, StErrorKind::UnclosedString)),
                        Some(e) => text.push(e),
                    }
                }
                Some(c) => text.push(c),
            }
        }
        text.push('\'');
        parse_text(&text)
            .map(Literal::String)
            .map_err(|e| err(span, StErrorKind::BadLiteral(text, e)))
    }

    /// The literal after `prefix#`.
    fn typed(&mut self, prefix: &str, span: Span) -> Result<Literal, StError> {
        let upper = prefix.to_ascii_uppercase();
        if upper == "STRING" && self.peek(0) == Some('\'') {
            return self.string(span);
        }
        if matches!(upper.as_str(), "T" | "TIME") {
            let sign = if self.peek(0) == Some('-') {
                self.bump();
                "-"
            } else {
                ""
            };
            let body = self.eat_while(|c| c.is_ascii_alphanumeric() || c == '_' || c == '.');
            let text = format!("T#{sign}{body}");
            return match parse_literal(&text, None) {
                Ok(Data::Time(ns)) => Ok(Literal::Time(ns)),
                Ok(_) => Err(err(
                    span,
                    StErrorKind::BadLiteral(text.clone(), bad_time(text)),
                )),
                Err(e) => Err(err(span, StErrorKind::BadLiteral(text, e))),
            };
        }
        let ty = match upper.as_str() {
            "BOOL" => None,
            _ => match Elementary::from_name(&upper) {
                Some(t) if t != Elementary::Time => Some(t),
                _ => return Err(err(span, StErrorKind::BadLiteralType(prefix.to_string()))),
            },
        };
        let negative = match self.peek(0) {
            Some(s @ ('+' | '-')) => {
                self.bump();
                s == '-'
            }
            _ => false,
        };
        let start = self.pos;
        if self.peek(0).is_some_and(|c| c.is_ascii_alphabetic()) {
            self.digits();
        } else {
            self.unsigned_number();
        }
        let body: String = self.chars[start..self.pos].iter().collect();
        let text = format!("{prefix}#{}{body}", if negative { "-" } else { "" });
        let Some(ty) = ty else {
            return bool_literal(&body, &text, span);
        };
        let lit = number_value(&body, Some(ty), span)?;
        typed_value(lit, negative, ty, &text, span)
    }
}

fn bad_time(text: String) -> LiteralError {
    LiteralError::BadTime(text)
}

fn bool_literal(body: &str, text: &str, span: Span) -> Result<Literal, StError> {
    match body.to_ascii_uppercase().as_str() {
        "1" | "TRUE" => Ok(Literal::Bool(true)),
        "0" | "FALSE" => Ok(Literal::Bool(false)),
        _ => Err(err(
            span,
            StErrorKind::BadLiteral(text.to_string(), LiteralError::BadNumber(body.to_string())),
        )),
    }
}

/// An unsigned number's value: an integer (any base) or a real.
fn number_value(text: &str, ty: Option<Elementary>, span: Span) -> Result<Literal, StError> {
    let bad = || {
        let e = LiteralError::BadNumber(text.to_string());
        err(span, StErrorKind::BadLiteral(text.to_string(), e))
    };
    if text.contains('.') {
        let v: f64 = text.replace('_', "").parse().map_err(|_| bad())?;
        if !v.is_finite() {
            return Err(bad());
        }
        return Ok(Literal::Real(v, ty));
    }
    if text.ends_with('_') || text.contains("__") {
        return Err(bad());
    }
    untyped_integer(text)
        .filter(|v| *v >= 0)
        .map(|v| Literal::Integer(v, ty))
        .ok_or_else(bad)
}

/// A typed literal's value checked against its type, its sign applied.
fn typed_value(
    lit: Literal,
    negative: bool,
    ty: Elementary,
    text: &str,
    span: Span,
) -> Result<Literal, StError> {
    let wrong = |e| err(span, StErrorKind::BadLiteral(text.to_string(), e));
    let sign = if negative { -1 } else { 1 };
    match (lit, ty) {
        (Literal::Real(v, _), Elementary::Real | Elementary::Lreal) => {
            Ok(Literal::Real(v * f64::from(sign), Some(ty)))
        }
        (Literal::Integer(v, _), Elementary::Real | Elementary::Lreal) => {
            Ok(Literal::Real(v as f64 * f64::from(sign), Some(ty)))
        }
        (Literal::Integer(v, _), _) => {
            let v = v * i128::from(sign);
            match ty.range() {
                Some((lo, hi)) if v >= lo && v <= hi => Ok(Literal::Integer(v, Some(ty))),
                _ => Err(err(
                    span,
                    StErrorKind::LiteralOutOfRange(text.to_string(), ty),
                )),
            }
        }
        _ => Err(wrong(LiteralError::BadNumber(text.to_string()))),
    }
}
