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
