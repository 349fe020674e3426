//! Refusals at their line and column: the checker's, the lowering's
//! (what does not run yet) and the IL loader's, said at the ST place.

use crate::common::refusals;

#[test]
fn a_type_error_is_at_its_line_and_column() {
    let e = refusals("PROGRAM t\nVAR n : INT; END_VAR\n  n := TRUE;\nEND_PROGRAM\n");
    assert_eq!(e.len(), 1, "{e:?}");
    assert!(e[0].starts_with("3:8:"), "{e:?}");
}

#[test]
fn what_does_not_run_yet_says_so_at_its_place() {
    let e =
        refusals("PROGRAM t\nVAR n : INT; r : REAL; END_VAR\n  r := r ** (n + 1);\nEND_PROGRAM\n");
    assert_eq!(e.len(), 1, "{e:?}");
    assert!(e[0].starts_with("3:14:"), "{e:?}");
    assert!(e[0].contains("does not run on the soft PLC yet"), "{e:?}");
    // Untyped literals alone beside SEL's selector: no type to hold them.
    let e = refusals(
        "PROGRAM t\nVAR n : INT; g : BOOL; END_VAR\nn := SEL(g, 1 + 1, 2);\nEND_PROGRAM\n",
    );
    assert_eq!(e.len(), 1, "{e:?}");
    assert!(
        e[0].starts_with("3:13:") && e[0].contains("function's second or later input"),
        "{e:?}"
    );
    let e = refusals("FUNCTION_BLOCK b\nEND_FUNCTION_BLOCK\n");
    assert!(e[0].contains("without a PROGRAM"), "{e:?}");
}

#[test]
fn the_il_loaders_refusal_is_at_the_st_declaration() {
    // A byte address parses and checks; the soft PLC has none.
    let e = refusals(
        "PROGRAM t\nVAR\n  n : INT;\n  s AT %IB0 : BYTE;\nEND_VAR\nn := 1;\nEND_PROGRAM\n",
    );
    assert_eq!(e.len(), 1, "{e:?}");
    assert!(e[0].starts_with("4:3:"), "{e:?}");
}

#[test]
fn a_syntax_error_is_at_its_place() {
    let e = refusals("PROGRAM t\nVAR n : INT; END_VAR\nIF n THEN\nEND_PROGRAM\n");
    assert!(e[0].starts_with("3:") || e[0].starts_with("4:"), "{e:?}");
}

#[test]
fn an_own_function_in_a_case_label_is_refused() {
    let e = refusals(
        "FUNCTION f : INT\nVAR_INPUT x : INT; END_VAR\nf := x;\nEND_FUNCTION\nPROGRAM t\nVAR n : INT; END_VAR\nCASE n OF\n  1: n := 2;\nEND_CASE;\nCASE n OF f(n): n := 1; END_CASE;\nEND_PROGRAM\n",
    );
    assert!(e.iter().any(|m| m.starts_with("10:")), "{e:?}");
}
