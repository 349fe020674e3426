//! Structured Text (IEC 61131-3, 3rd edition): its lexer, a hand-written
//! recursive-descent parser and the syntax tree it builds ([`ast`]),
//! with a printer back to text ([`print`]) and a checker of names and
//! types ([`check_source`]), and its lowering to the soft PLC's
//! Instruction List ([`lower_source`]), which is how ST runs. Left out, and refused at their line
//! and column: references and pointers (`REF_TO`, `REF()`, `^`), the
//! object-oriented extensions (`METHOD`, `INTERFACE`, `EXTENDS`,
//! `IMPLEMENTS`…), `WSTRING`, pragmas `{…}`, enumerated and subrange
//! types (docs/soft-plc.md, "Structured Text").

pub mod ast;
mod body_text;
mod check;
mod decl;
pub mod error;
mod expr;
mod lexer;
pub mod lower;
mod lower_args;
mod lower_body;
mod lower_call;
mod lower_flat;
mod lower_io;
mod lower_programs;
mod lower_reals;
mod parser;
pub mod print;
pub mod rename;
mod stmt;
#[cfg(test)]
mod tests;
mod types;
mod typing;

pub use ast::Source;
pub use body_text::body_texts;
pub use check::check_source;
pub use error::{StError, StErrorKind};
pub use lexer::KEYWORDS;
pub use lower::{lower_source, Lowered};
pub use lower_body::{lower_body, LoweredBody};
pub(crate) use lower_io::io_pin;
pub use print::print_source;

use ast::Stmt;
use parser::Parser;

/// Parses a whole source: POUs, `TYPE` blocks and global variables.
pub fn parse_source(text: &str) -> Result<Source, StError> {
    Parser::new(lexer::tokenize(text)?).source()
}

/// Parses a POU's body alone (statements only), as PLCopen projects hold
/// them.
pub fn parse_body(text: &str) -> Result<Vec<Stmt>, StError> {
    let mut p = Parser::new(lexer::tokenize(text)?);
    p.body()
}

/// Parses one expression, the whole text.
pub fn parse_expr(text: &str) -> Result<ast::Expr, StError> {
    let mut p = Parser::new(lexer::tokenize(text)?);
    let e = p.expr("here")?;
    p.end()?;
    Ok(e)
}

/// A body's statements as text (four spaces' indent for none).
pub fn print_body(stmts: &[Stmt]) -> String {
    let mut out = String::new();
    print::print_stmts(&mut out, stmts, 0);
    out
}
