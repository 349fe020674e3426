//! Each left-out feature and each mistake is refused at its line and
//! column, in plain English.

use engine::iec::st::{parse_body, parse_source};

fn body_error(text: &str) -> String {
    parse_body(text).expect_err(text).to_string()
}

fn source_error(text: &str) -> String {
    parse_source(text).expect_err(text).to_string()
}

#[test]
fn left_out_features_are_named_at_their_place() {
    for (text, want) in [
        (
            "x := 1;\np := REF(x);",
            "line 2, column 6: `REF()` (references and pointers)",
        ),
        (
            "x := p^;",
            "line 1, column 7: `^` (references and pointers)",
        ),
        (
            "{attribute 'hide'}\nx := 1;",
            "line 1, column 1: a pragma `{…}`",
        ),
        (
            "x := 1;\n  {IF defined(x)}",
            "line 2, column 3: a pragma `{…}`",
        ),
        ("s := \"wide\";", "line 1, column 6: WSTRING"),
        ("fb.m(1);", "line 1, column 5: calling a member"),
    ] {
        let got = body_error(text);
        assert!(got.starts_with(want), "{text}: {got}");
        assert!(got.contains("not supported"), "{got}");
    }
    for (text, want) in [
        (
            "PROGRAM p VAR r : REF_TO INT; END_VAR END_PROGRAM",
            "line 1, column 19: `REF_TO`",
        ),
        (
            "FUNCTION_BLOCK b EXTENDS a END_FUNCTION_BLOCK",
            "line 1, column 18: `EXTENDS`",
        ),
        (
            "FUNCTION_BLOCK b IMPLEMENTS i END_FUNCTION_BLOCK",
            "line 1, column 18: `IMPLEMENTS`",
        ),
        (
            "FUNCTION_BLOCK b\nMETHOD m END_METHOD END_FUNCTION_BLOCK",
            "line 2, column 1: `METHOD`",
        ),
        ("INTERFACE i END_INTERFACE", "line 1, column 1: `INTERFACE`"),
        (
            "PROGRAM p VAR w : WSTRING; END_VAR END_PROGRAM",
            "line 1, column 19: WSTRING",
        ),
        (
            "TYPE e : (red, green); END_TYPE",
            "line 1, column 10: an enumerated type",
        ),
        (
            "PROGRAM p VAR w : INT (0..9); END_VAR END_PROGRAM",
            "line 1, column 23: a subrange",
        ),
    ] {
        let got = source_error(text);
        assert!(got.starts_with(want), "{text}: {got}");
    }
}

#[test]
fn mistakes_say_what_was_expected_and_found() {
    for (text, want) in [
        (
            "IF a := 1 THEN x := 1; END_IF;",
            "line 1, column 6: expected THEN after the IF condition, found ':='",
        ),
        (
            "x := ;",
            "line 1, column 6: expected an expression after ':=', found ';'",
        ),
        (
            "x := 1",
            "line 1, column 7: expected ';' after the statement, found the end of the text",
        ),
        (
            "IF a THEN x := 1;",
            "line 1, column 18: expected END_IF to close the statements",
        ),
        (
            "x := (1 + 2;",
            "line 1, column 12: expected ')' to close the parenthesis, found ';'",
        ),
        (
            "x := a[1;",
            "line 1, column 9: expected ']' to close the index",
        ),
        (
            "f(a := 1, 2);",
            "line 1, column 11: a positional argument cannot follow a named one",
        ),
        (
            "FOR i = 1 TO 2 DO END_FOR;",
            "line 1, column 7: expected ':=' after the FOR variable",
        ),
        (
            "CASE x OF 1 x := 1; END_CASE;",
            "line 1, column 13: expected ',' or ':' after a CASE label",
        ),
        ("x := 1 $ 2;", "line 1, column 8: unexpected character '$'"),
        (
            "x := 'open;",
            "line 1, column 6: this string is not closed on its line",
        ),
        (
            "(* (* *) x := 1;",
            "line 1, column 1: this (* comment is never closed",
        ),
        (
            "x := INT#40000;",
            "line 1, column 6: `INT#40000` is out of range for INT (-32768 … 32767)",
        ),
        (
            "x := SINT#-129;",
            "line 1, column 6: `SINT#-129` is out of range for SINT (-128 … 127)",
        ),
        (
            "x := %IX0.9;",
            "line 1, column 6: `%IX0.9`: a bit number is 0-7",
        ),
        ("x := %Z1;", "line 1, column 6: `%Z1` is not an address"),
        (
            "x := FOO#1;",
            "line 1, column 6: `FOO#` is not a type a literal can have",
        ),
        ("x := T#5parsecs;", "line 1, column 6: bad literal"),
        ("x := 1__0;", "line 1, column 6: bad literal `1__0`"),
        ("x := '$Q';", "line 1, column 6: bad literal"),
        (
            "END_IF;",
            "line 1, column 1: expected a statement here, found 'END_IF'",
        ),
    ] {
        let got = body_error(text);
        assert!(
            got.starts_with(want),
            "{text}:\n  got  {got}\n  want {want}"
        );
    }
    for (text, want) in [
        ("PROGRAM p VAR if : INT; END_VAR END_PROGRAM",
         "line 1, column 15: `if` is a keyword and cannot be used as a name"),
        ("FUNCTION f VAR END_VAR END_FUNCTION",
         "line 1, column 12: expected ':' and the result's type after the function's name"),
        ("PROGRAM p VAR a : ARRAY [3..1] OF INT; END_VAR END_PROGRAM",
         "line 1, column 26: the range 3..1 is empty: its low bound is above its high one"),
        ("PROGRAM p VAR s : STRING[0]; END_VAR END_PROGRAM",
         "line 1, column 26: `0` cannot be a length or a count"),
        ("PROGRAM p VAR s : STRING(-5); END_VAR END_PROGRAM",
         "line 1, column 26: `-5` cannot be a length or a count"),
        ("PROGRAM p VAR a : ARRAY [1..2] OF INT := [99999999999(0)]; END_VAR END_PROGRAM",
         "line 1, column 43: `99999999999` cannot be a length or a count"),
        ("PROGRAM p VAR a : ARRAY [1..n] OF INT; END_VAR END_PROGRAM",
         "line 1, column 29: expected a whole number as a bound, found 'n'"),
        ("CONFIGURATION c END_CONFIGURATION",
         "line 1, column 1: expected PROGRAM, FUNCTION, FUNCTION_BLOCK, TYPE or VAR_GLOBAL at the top level"),
        ("PROGRAM p\nVAR\n  a : INT\nEND_VAR END_PROGRAM",
         "line 4, column 1: expected ';' after the declaration, found 'END_VAR'"),
    ] {
        let got = source_error(text);
        assert!(got.contains(want), "{text}:\n  got  {got}\n  want {want}");
    }
}

#[test]
fn a_long_token_is_cut_in_the_message() {
    let long = format!("x := 1 '{}';", "a".repeat(1000));
    assert_eq!(
        body_error(&long),
        "line 1, column 8: expected ';' after the statement, found ''aaaaaaaaaaaaaaaaaaa…'"
    );
}

#[test]
fn deep_nesting_is_refused_not_a_stack_overflow() {
    let deep = format!("x := {}1{};", "(".repeat(10_000), ")".repeat(10_000));
    assert!(body_error(&deep).contains("nested more than"));
    let nots = format!("x := {}a;", "NOT ".repeat(10_000));
    assert!(body_error(&nots).contains("nested more than"));
    let ifs = "IF a THEN ".repeat(10_000);
    assert!(body_error(&ifs).contains("nested more than"));
    let arrays = format!(
        "TYPE t : {}INT; END_TYPE",
        "ARRAY [1..2] OF ".repeat(10_000)
    );
    assert!(source_error(&arrays).contains("nested more than"));
    let inits = format!("TYPE t : INT := {}1; END_TYPE", "[".repeat(10_000));
    assert!(source_error(&inits).contains("nested more than"));
}
