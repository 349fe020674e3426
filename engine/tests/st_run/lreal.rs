//! LREAL (IEC 61131-3's 64-bit real, IEC 60559 binary64; issue #54):
//! literals, arithmetic, comparisons, conversions and the numeric
//! functions. Expected values are binary64's, worked out by hand: they
//! differ from REAL's (binary32) where the tests look.

use crate::common::{load, refusals, run_once, shown};

#[test]
fn lreal_arithmetic_is_binary64() {
    let p = run_once(
        "a : LREAL := 0.1; b : LREAL := LREAL#0.2; c : LREAL; big : LREAL := 1.0E300; d : LREAL; n : LREAL := -2.5;",
        // 0.1 + 0.2 in binary64 is 0.30000000000000004 (binary32 gives
        // 0.3 exactly printed); 1E300 * 10 is beyond REAL's range.
        "c := a + b;\nbig := big * 10.0;\nd := (c - 0.3) * 1.0E17;\nn := -n / 2.0;",
    );
    assert_eq!(shown(&p, "c"), "0.30000000000000004");
    assert_eq!(shown(&p, "big").parse::<f64>(), Ok(1e301));
    // 0.30000000000000004 - 0.3 = 2^-54 = 5.551115123125783e-17.
    assert_eq!(shown(&p, "d"), "5.551115123125783");
    assert_eq!(shown(&p, "n"), "1.25");
}

#[test]
fn lreal_comparisons_see_its_precision() {
    let p = run_once(
        "a : LREAL := 0.1; b : LREAL := 0.2; gt : BOOL; eq : BOOL; ne : BOOL;",
        // binary64: 0.1 + 0.2 > 0.3; in binary32 they are equal.
        "gt := a + b > 0.3;\neq := a + b = LREAL#0.30000000000000004;\nne := a <> b;",
    );
    assert_eq!(shown(&p, "gt"), "TRUE");
    assert_eq!(shown(&p, "eq"), "TRUE");
    assert_eq!(shown(&p, "ne"), "TRUE");
}

#[test]
fn conversions_to_and_from_lreal() {
    let p = run_once(
        "r : REAL := 0.1; w : LREAL; x : LREAL := 2.5; i : INT; k : DINT; back : REAL; from_int : LREAL; t : TIME; neg : INT;",
        // REAL_TO_LREAL widens exactly: 0.1f32 is 0.10000000149011612.
        // LREAL_TO_INT rounds halves away from zero (as REAL_TO_INT):
        // 2.5 -> 3, -2.5 -> -3. INT_TO_LREAL(7) = 7. LREAL_TO_REAL(2.5).
        "w := REAL_TO_LREAL(r);\ni := LREAL_TO_INT(x);\nneg := LREAL_TO_INT(-x);\nk := TRUNC(x * 3.0);\nback := LREAL_TO_REAL(x);\nfrom_int := INT_TO_LREAL(7);\nt := LREAL_TO_TIME(x);",
    );
    assert_eq!(shown(&p, "w"), "0.10000000149011612");
    assert_eq!(shown(&p, "i"), "3");
    assert_eq!(shown(&p, "neg"), "-3");
    // TRUNC(7.5) = 7, toward zero.
    assert_eq!(shown(&p, "k"), "7");
    assert_eq!(shown(&p, "back"), "2.5");
    assert_eq!(shown(&p, "from_int"), "7");
    // 2.5 ms as TIME.
    assert_eq!(shown(&p, "t"), "2ms");
}

#[test]
fn numeric_functions_take_lreal() {
    let p = run_once(
        "x : LREAL := 2.0; s : LREAL; a : LREAL; e : LREAL; m : LREAL; l : LREAL;",
        // SQRT(2) in binary64; ABS(-2) = 2; 2 ** 0.5 = SQRT(2);
        // MAX(2, 2 * 1.5) = 3; LIMIT(0, 2 * 10, 5) = 5.
        "s := SQRT(x);\na := ABS(-x);\ne := x ** 0.5;\nm := MAX(x, x * 1.5);\nl := LIMIT(0.0, x * 10.0, 5.0);",
    );
    assert_eq!(shown(&p, "s"), "1.4142135623730951");
    assert_eq!(shown(&p, "a"), "2");
    assert_eq!(shown(&p, "e"), "1.4142135623730951");
    assert_eq!(shown(&p, "m"), "3");
    assert_eq!(shown(&p, "l"), "5");
}

#[test]
fn lreal_and_real_do_not_mix_without_a_conversion() {
    let e = refusals("PROGRAM t\nVAR a : LREAL; r : REAL; END_VAR\na := a + r;\nEND_PROGRAM\n");
    assert!(e[0].starts_with("3:10:"), "{e:?}");
}

#[test]
fn an_lreal_keeps_its_value_over_scans_and_in_a_block() {
    let mut p = load(
        "FUNCTION_BLOCK Acc\nVAR_INPUT x : LREAL; END_VAR\nVAR_OUTPUT sum : LREAL; END_VAR\nsum := sum + x;\nEND_FUNCTION_BLOCK\nPROGRAM t\nVAR acc : Acc; total : LREAL; END_VAR\nacc(x := 0.1);\ntotal := acc.sum;\nEND_PROGRAM\n",
    );
    for _ in 0..10 {
        p.scan(0);
    }
    // Ten binary64 additions of 0.1: 0.9999999999999999.
    assert_eq!(shown(&p, "total"), "0.9999999999999999");
}

#[test]
fn an_lreal_sits_at_a_long_word_as_a_real_at_a_double_word() {
    let p = run_once("m AT %ML0 : LREAL; x : LREAL := 1.5;", "m := x * 3.0;");
    assert_eq!(shown(&p, "m"), "4.5");
    assert_eq!(shown(&p, "%ML0"), "4.5");
}

#[test]
fn lreal_members_and_elements_take_untyped_real_literals() {
    let p = load(
        "TYPE P : STRUCT v : LREAL; END_STRUCT; END_TYPE\nPROGRAM t\nVAR\n  xs : ARRAY [1..2] OF LREAL;\n  p : P;\n  i : INT := 2;\n  y : LREAL;\nEND_VAR\nxs[1] := 2.5;\nxs[i] := xs[1] * 2.0;\np.v := 0.1;\ny := p.v + xs[i] + 1.0;\nEND_PROGRAM\n",
    );
    let mut p = p;
    p.scan(0);
    assert_eq!(shown(&p, "xs[2]"), "5");
    // 0.1 + 5.0 + 1.0 in binary64 is 6.1 exactly as printed.
    assert_eq!(shown(&p, "y"), "6.1");
    assert_eq!(shown(&p, "p.v"), "0.1");
}
