//! Control flow: IF/ELSIF/ELSE, CASE, FOR … BY, WHILE, REPEAT, EXIT,
//! RETURN.

use crate::common::{load, run_once, shown};

#[test]
fn if_elsif_else() {
    for (n, want) in [(1, "10"), (5, "20"), (9, "30")] {
        let p = run_once(
            &format!("n : INT := {n}; r : INT;"),
            "IF n < 3 THEN r := 10; ELSIF n < 7 THEN r := 20; ELSE r := 30; END_IF;",
        );
        assert_eq!(shown(&p, "r"), want, "n = {n}");
    }
}

#[test]
fn case_values_lists_ranges_else() {
    for (n, want) in [
        (1, "1"),
        (2, "2"),
        (4, "2"),
        (7, "3"),
        (10, "3"),
        (11, "9"),
        (-1, "9"),
    ] {
        let p = run_once(
            &format!("n : INT := {n}; r : INT;"),
            "CASE n OF\n 1: r := 1;\n 2, 4: r := 2;\n 5..10: r := 3;\nELSE r := 9;\nEND_CASE;",
        );
        assert_eq!(shown(&p, "r"), want, "n = {n}");
    }
}

#[test]
fn for_loops_count_both_ways() {
    let p = run_once(
        "i, s, d, e, j : INT;",
        "FOR i := 1 TO 10 DO s := s + i; END_FOR;\nFOR i := 10 TO 1 BY -3 DO d := d * 10 + i; END_FOR;\nj := 2;\nFOR i := 0 TO 20 BY j DO e := e + 1; IF i >= 8 THEN EXIT; END_IF; END_FOR;",
    );
    assert_eq!(shown(&p, "s"), "55");
    // i = 10, 7, 4, 1: d = 10, 107, 1074, 10741.
    assert_eq!(shown(&p, "d"), "10741");
    // 0, 2, 4, 6, 8 then EXIT.
    assert_eq!(shown(&p, "e"), "5");
    assert_eq!(shown(&p, "i"), "8");
}

#[test]
fn while_repeat_exit_return() {
    let p = run_once(
        "n : INT := 1; k : INT; r : INT; after : BOOL;",
        "WHILE n < 100 DO n := n * 3; END_WHILE;\nREPEAT k := k + 1; IF k = 4 THEN EXIT; END_IF; UNTIL k > 10 END_REPEAT;\nREPEAT r := r + 5; UNTIL r >= 12 END_REPEAT;\nRETURN;\nafter := TRUE;",
    );
    assert_eq!(shown(&p, "n"), "243");
    assert_eq!(shown(&p, "k"), "4");
    assert_eq!(shown(&p, "r"), "15");
    assert_eq!(shown(&p, "after"), "FALSE");
}

#[test]
fn an_endless_loop_is_cut_as_il_is() {
    let mut p = load(
        "PROGRAM t\nVAR n : DINT; END_VAR\nWHILE TRUE DO n := n + 1; END_WHILE;\nEND_PROGRAM\n",
    );
    p.scan(0);
    assert!(p.overran(), "the scan is cut");
    let n: i64 = shown(&p, "n").parse().unwrap();
    assert!(n > 1000, "it ran until cut: {n}");
}

#[test]
fn exit_leaves_the_innermost_loop_only() {
    let p = run_once(
        "i, j, n : INT;",
        "FOR i := 1 TO 3 DO\n  FOR j := 1 TO 10 DO\n    IF j > i THEN EXIT; END_IF;\n    n := n + 1;\n  END_FOR;\nEND_FOR;",
    );
    // 1 + 2 + 3 inner passes.
    assert_eq!(shown(&p, "n"), "6");
    assert_eq!(shown(&p, "i"), "4");
}

#[test]
fn return_in_a_block_ends_its_call_only() {
    let mut p = load(
        "FUNCTION_BLOCK Half\nVAR_INPUT x : INT; END_VAR\nVAR_OUTPUT y : INT; END_VAR\ny := 0;\nIF x < 0 THEN RETURN; END_IF;\ny := x / 2;\nEND_FUNCTION_BLOCK\nPROGRAM t\nVAR h : Half; a, b : INT; after : BOOL; END_VAR\nh(x := -4);\na := h.y;\nh(x := 9);\nb := h.y;\nafter := TRUE;\nEND_PROGRAM\n",
    );
    p.scan(0);
    assert_eq!(shown(&p, "a"), "0");
    assert_eq!(shown(&p, "b"), "4");
    assert_eq!(shown(&p, "after"), "TRUE");
}

#[test]
fn negative_literals_and_an_empty_program() {
    let p = run_once(
        "a : INT := 10; b, c : INT; d : DINT;",
        "b := a - -3;\nc := -a * -2 + INT#-5;\nd := -DINT#7 - 1;",
    );
    assert_eq!(shown(&p, "b"), "13");
    assert_eq!(shown(&p, "c"), "15");
    assert_eq!(shown(&p, "d"), "-8");
    let mut p = load("PROGRAM t\nVAR n : INT := 3; END_VAR\nEND_PROGRAM\n");
    p.scan(0);
    assert_eq!(shown(&p, "n"), "3");
}

#[test]
fn a_case_on_an_own_functions_result() {
    let mut p = load(
        "FUNCTION Next : INT\nVAR_INPUT x : INT; END_VAR\nVAR_OUTPUT calls : INT; END_VAR\nNext := x + 1;\nEND_FUNCTION\nPROGRAM t\nVAR n : INT := 4; r : INT; END_VAR\nCASE Next(n) OF\n  1..4: r := 1;\n  5: r := 5;\nELSE r := 9;\nEND_CASE;\nEND_PROGRAM\n",
    );
    p.scan(0);
    assert_eq!(shown(&p, "r"), "5");
}
