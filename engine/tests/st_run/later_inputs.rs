//! An expression as a standard function's second or later input (issue
//! #54): computed first into a hidden variable of its type. Expected
//! values from the functions' definitions in IEC 61131-3 (MAX, MIN,
//! LIMIT, SEL, MUX, SHL), worked out by hand.

use crate::common::{load, run_once, shown};

#[test]
fn max_min_limit_take_an_expression_as_any_input() {
    let p = run_once(
        "n : INT := 7; a : INT; b : INT; c : INT; d : INT; r : REAL := 1.5; m : REAL;",
        // MAX(7, 8) = 8; MIN(7, 7 * 2 - 10) = MIN(7, 4) = 4;
        // LIMIT(0, 7 * 3, 10) = 10; MAX(7, MIN(7, 7 + 1) + 2) = MAX(7, 9) = 9.
        "a := MAX(n, n + 1);\nb := MIN(n, n * 2 - 10);\nc := LIMIT(0, n * 3, 10);\nd := MAX(n, MIN(n, n + 1) + 2);\nm := MIN(r * 4.0, r + 1.0);",
    );
    assert_eq!(shown(&p, "a"), "8");
    assert_eq!(shown(&p, "b"), "4");
    assert_eq!(shown(&p, "c"), "10");
    assert_eq!(shown(&p, "d"), "9");
    // MIN(6.0, 2.5) = 2.5.
    assert_eq!(shown(&p, "m"), "2.5");
}

#[test]
fn sel_mux_and_shl_take_typed_expressions_and_literals_beside_them() {
    let p = run_once(
        "g : BOOL := TRUE; k : INT := 2; a : INT := 10; s : INT; x : INT; w : WORD := 1; y : WORD; n : INT := 4; z : INT;",
        // SEL(TRUE, 10 + 1, 10 * 2) = 20; MUX(2, a+1, a+2, a+3) = 13;
        // SHL(1, 4 - 1) = 8; MAX(a, 2 * 3) takes 2 * 3 as an INT: 10.
        "s := SEL(g, a + 1, a * 2);\nx := MUX(k, a + 1, a + 2, a + 3);\ny := SHL(w, n - 1);\nz := MAX(a, 2 * 3);",
    );
    assert_eq!(shown(&p, "s"), "20");
    assert_eq!(shown(&p, "x"), "13");
    assert_eq!(shown(&p, "y"), "8");
    assert_eq!(shown(&p, "z"), "10");
}

#[test]
fn a_later_input_is_computed_again_each_time_a_loop_reads_it() {
    // WHILE MAX(i, i + 0) < 5: the condition's later input is computed
    // at each pass, not once before the loop: i ends at 5, not looping
    // for ever on a stale value.
    let mut p = load(
        "FUNCTION Sq : INT\nVAR_INPUT v : INT; END_VAR\nSq := v * v;\nEND_FUNCTION\nPROGRAM t\nVAR i : INT; q : INT; END_VAR\ni := 0;\nWHILE MAX(i, i + 0) < 5 DO\n  i := i + 1;\nEND_WHILE;\nq := MAX(i, Sq(i) + 1);\nEND_PROGRAM\n",
    );
    p.scan(0);
    assert!(!p.overran());
    assert_eq!(shown(&p, "i"), "5");
    // MAX(5, 5 * 5 + 1) = 26, the own function's call made first.
    assert_eq!(shown(&p, "q"), "26");
}
