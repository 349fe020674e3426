//! The numeric standard functions (issue #54): `**` and EXPT, ABS, SQRT,
//! TRUNC, MUX. Expected values from IEC 61131-3's definitions: EXPT is
//! IN1 to the power IN2 (a REAL base), ABS the magnitude, SQRT the square
//! root, TRUNC toward zero, MUX the input K picks (0 the first).

use crate::common::{refusals, run_once, shown};

#[test]
fn power_and_expt() {
    let p = run_once(
        "x : REAL := 2.0; n : INT := 10; a, b, c, d, e, f : REAL;",
        "a := x ** n;\nb := x ** -1;\nc := 4.0 ** 0.5;\nd := -x ** 2;\ne := EXPT(3.0, 3) + 1.0;\nf := 2.0 ** 3 ** 2;",
    );
    assert_eq!(shown(&p, "a"), "1024");
    assert_eq!(shown(&p, "b"), "0.5");
    assert_eq!(shown(&p, "c"), "2");
    // The unary minus binds tighter than `**`: (-2) ** 2.
    assert_eq!(shown(&p, "d"), "4");
    assert_eq!(shown(&p, "e"), "28");
    // Left to right: (2 ** 3) ** 2.
    assert_eq!(shown(&p, "f"), "64");
}

#[test]
fn abs_sqrt_trunc() {
    let p = run_once(
        "i : INT := -5; m : INT := INT#-32768; u : UINT := 7; r : REAL := -2.5;
         ai, am, au : INT; ur : UINT; ar, s1, s2 : REAL; t1, t2, t3 : DINT;",
        "ai := ABS(i);\nam := ABS(m);\nur := ABS(u);\nar := ABS(r);\ns1 := SQRT(16.0);\ns2 := SQRT(ABS(r) * 2.0 + 4.0);\nt1 := TRUNC(2.7);\nt2 := TRUNC(r);\nt3 := TRUNC(-0.5);",
    );
    assert_eq!(shown(&p, "ai"), "5");
    // No INT is 32768: wrapped, as NEG wraps.
    assert_eq!(shown(&p, "am"), "-32768");
    assert_eq!(shown(&p, "ur"), "7");
    assert_eq!(shown(&p, "ar"), "2.5");
    assert_eq!(shown(&p, "s1"), "4");
    assert_eq!(shown(&p, "s2"), "3");
    // Toward zero, not down: -2.5 gives -2.
    assert_eq!(shown(&p, "t1"), "2");
    assert_eq!(shown(&p, "t2"), "-2");
    assert_eq!(shown(&p, "t3"), "0");
}

#[test]
fn mux_picks_by_k() {
    let p = run_once(
        "k : INT := 1; a : INT := 10; b : INT := 20; c : INT := 30; m0, m1, m2, lo, hi : INT;",
        "m0 := MUX(0, a, b, c);\nm1 := MUX(k, a, b, c);\nm2 := MUX(k + 1, a, b, c);\nlo := MUX(-1, a, b, c);\nhi := MUX(7, a, b, c);",
    );
    assert_eq!(shown(&p, "m0"), "10");
    assert_eq!(shown(&p, "m1"), "20");
    assert_eq!(shown(&p, "m2"), "30");
    // Outside 0 … 2: the nearest input (decided; IEC calls it an error).
    assert_eq!(shown(&p, "lo"), "10");
    assert_eq!(shown(&p, "hi"), "30");
}

#[test]
fn numeric_functions_refuse_what_they_do_not_take() {
    // EXPT's base is a REAL (IEC: ANY_REAL): an INT is refused.
    let e = refusals("PROGRAM t\nVAR n : INT; r : REAL; END_VAR\n  r := n ** 2;\nEND_PROGRAM\n");
    assert!(
        e.iter()
            .any(|m| m.starts_with("3:") && m.contains("`**`'s base must be a REAL")),
        "{e:?}"
    );
    let e =
        refusals("PROGRAM t\nVAR b : BOOL; r : REAL; END_VAR\n  r := SQRT(INT#4);\nEND_PROGRAM\n");
    assert!(
        e.iter()
            .any(|m| m.starts_with("3:") && m.contains("does not apply to INT")),
        "{e:?}"
    );
    let e = refusals(
        "PROGRAM t\nVAR n : INT; r : REAL; END_VAR\n  r := 2.0 ** (n + 1);\nEND_PROGRAM\n",
    );
    assert!(
        e[0].starts_with("3:16:") && e[0].contains("`**`'s power"),
        "{e:?}"
    );
}

#[test]
fn il_has_them_as_functions() {
    let il = "VAR
k : INT := 3;
r : REAL;
n : DINT;
m : INT;
END_VAR
LD 2.0
EXPT k
ST r
LD -7.9
TRUNC
ST n
LD k
MUX 1, 2, 3, 4, 5
ST m
";
    let mut p = engine::softplc::Program::load(il).unwrap_or_else(|e| panic!("{e:?}"));
    p.scan(0);
    assert_eq!(shown(&p, "r"), "8");
    assert_eq!(shown(&p, "n"), "-7");
    // K = 3 picks the fourth input.
    assert_eq!(shown(&p, "m"), "4");
    let e = engine::softplc::Program::load("VAR\nn : INT;\nEND_VAR\nLD n\nSQRT\nST n\n")
        .expect_err("SQRT of an INT");
    assert!(e[0].to_string().contains("does not apply to INT"), "{e:?}");
}
