//! The lexer's tokens and spans, seen from inside the module.

use super::ast::{Literal, Span};
use super::lexer::{tokenize, Tok};

fn toks(text: &str) -> Vec<Tok> {
    tokenize(text)
        .expect("lexes")
        .into_iter()
        .map(|t| t.tok)
        .collect()
}

#[test]
fn a_range_is_not_a_real() {
    assert_eq!(
        toks("1..5"),
        [
            Tok::Literal(Literal::Integer(1, None)),
            Tok::Sym(".."),
            Tok::Literal(Literal::Integer(5, None)),
            Tok::Eof
        ]
    );
    assert_eq!(toks("1.5")[0], Tok::Literal(Literal::Real(1.5, None)));
}

#[test]
fn two_character_symbols_win() {
    assert_eq!(
        toks(":= => ** <= >= <> : = * < >"),
        [":=", "=>", "**", "<=", ">=", "<>", ":", "=", "*", "<", ">"]
            .map(Tok::Sym)
            .into_iter()
            .chain([Tok::Eof])
            .collect::<Vec<_>>()
    );
}

#[test]
fn keywords_any_case_names_kept() {
    assert_eq!(
        toks("end_if Motor_1"),
        [
            Tok::Keyword("END_IF"),
            Tok::Ident("Motor_1".into()),
            Tok::Eof
        ]
    );
}

#[test]
fn spans_count_lines_and_characters() {
    let spans: Vec<Span> = tokenize("(* é\n *) x\n\t'ü' ;")
        .expect("lexes")
        .into_iter()
        .map(|t| t.span)
        .collect();
    let at = |line, column| Span { line, column };
    assert_eq!(spans, [at(2, 5), at(3, 2), at(3, 6), at(3, 7)]);
}

#[test]
fn comments_nest() {
    assert_eq!(
        toks("(* a (* b *) c *) x"),
        [Tok::Ident("x".into()), Tok::Eof]
    );
    assert!(tokenize("(* a (* b *) c").is_err());
}
