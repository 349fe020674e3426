//! Expressions: precedence, integer division and MOD (truncating, as
//! IEC's DIV and MOD on integers), comparisons, logic.

use crate::common::{run_once, shown};

#[test]
fn precedence_and_arithmetic() {
    let p = run_once(
        "a, b, c, d, e : INT; x : DINT := 7;",
        "a := 2 + 3 * 4;\nb := (2 + 3) * 4;\nc := 17 MOD 5 - -7 / 2;\nd := -a + 10 * (b - a) / 4;\ne := DINT_TO_INT(x * 3);",
    );
    assert_eq!(shown(&p, "a"), "14");
    assert_eq!(shown(&p, "b"), "20");
    // 17 MOD 5 = 2; -7 / 2 = -3 (truncated); 2 - -3 = 5.
    assert_eq!(shown(&p, "c"), "5");
    // -14 + 10 * 6 / 4 = -14 + 15 = 1.
    assert_eq!(shown(&p, "d"), "1");
    assert_eq!(shown(&p, "e"), "21");
}

#[test]
fn logic_and_comparisons() {
    let p = run_once(
        "a : BOOL := TRUE; b : BOOL; n : INT := 5; r1, r2, r3, r4 : BOOL;",
        "r1 := a AND NOT b OR b;\nr2 := n > 3 AND n <= 5 XOR b;\nr3 := NOT (n = 5) OR n <> 5;\nr4 := a & (n >= 6 OR b = FALSE);",
    );
    assert_eq!(shown(&p, "r1"), "TRUE");
    assert_eq!(shown(&p, "r2"), "TRUE");
    assert_eq!(shown(&p, "r3"), "FALSE");
    assert_eq!(shown(&p, "r4"), "TRUE");
}

#[test]
fn functions_and_reals() {
    let p = run_once(
        "x : REAL := 2.5; y : REAL; m, l : INT; k : INT := 40;",
        "y := x * 4.0 - 1.0;\nm := MAX(k, 12);\nl := k * 3;\nl := LIMIT(0, l, 100) - MIN(l, 7);",
    );
    assert_eq!(shown(&p, "y"), "9");
    assert_eq!(shown(&p, "m"), "40");
    // LIMIT(0, 120, 100) - MIN(120, 7) = 100 - 7.
    assert_eq!(shown(&p, "l"), "93");
}
