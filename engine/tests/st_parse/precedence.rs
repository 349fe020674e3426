//! Precedence and grouping as the 3rd edition's table 71 gives them.

use engine::iec::st::parse_expr;

use super::grouping;

fn grouped(text: &str) -> String {
    grouping(&parse_expr(text).unwrap_or_else(|e| panic!("{text}: {e}")))
}

#[test]
fn the_standard_table_loosest_to_tightest() {
    for (text, want) in [
        ("a OR b AND c", "(a OR (b AND c))"),
        ("a OR b XOR c", "(a OR (b XOR c))"),
        ("a XOR b AND c", "(a XOR (b AND c))"),
        ("a & b OR c", "((a AND b) OR c)"),
        ("a AND b = c", "(a AND (b = c))"),
        ("a = b < c", "(a = (b < c))"),
        ("a <> b >= c", "(a <> (b >= c))"),
        ("a < b + c", "(a < (b + c))"),
        ("a + b * c", "(a + (b * c))"),
        ("a - b MOD c", "(a - (b MOD c))"),
        ("a * b ** c", "(a * (b ** c))"),
        // The unary operators bind tighter than `**`: the grammar reads
        // `power_expression ::= unary_expression {'**' unary_expression}`.
        ("-2 ** 2", "((-2) ** 2)"),
        ("NOT a = b", "((NOT a) = b)"),
        ("NOT a AND b", "((NOT a) AND b)"),
        ("- a * b", "((-a) * b)"),
        ("a ** -b", "(a ** (-b))"),
        ("- - a", "(-(-a))"),
    ] {
        assert_eq!(grouped(text), want, "{text}");
    }
}

#[test]
fn one_level_applies_left_to_right() {
    for (text, want) in [
        ("a - b - c", "((a - b) - c)"),
        ("a / b * c", "((a / b) * c)"),
        ("2 ** 3 ** 2", "((2 ** 3) ** 2)"),
        ("a = b <> c", "((a = b) <> c)"),
        ("a OR b OR c", "((a OR b) OR c)"),
    ] {
        assert_eq!(grouped(text), want, "{text}");
    }
}

#[test]
fn parentheses_and_operands() {
    assert_eq!(grouped("(a OR b) AND c"), "((a OR b) AND c)");
    assert_eq!(grouped("-(2 ** 2)"), "(-(2 ** 2))");
    assert_eq!(grouped("a[i + 1, j].m * f(x)"), "(a[(i + 1),j].m * f(…))");
    assert_eq!(
        grouped("%IX0.0 AND NOT %QX0.1"),
        "(%IX0.0 AND (NOT %QX0.1))"
    );
}

#[test]
fn keywords_are_case_insensitive() {
    assert_eq!(
        grouped("a or b and not c mod d"),
        grouped("a OR b AND NOT c MOD d")
    );
}
