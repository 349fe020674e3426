//! SINT, USINT, BYTE and LWORD (issue #54): 8-bit and 64-bit integers
//! and bit strings, wrapping in their width as every integer of the
//! soft PLC does (docs/soft-plc.md, "Arithmetic").

use crate::common::{refusals, run_once, shown};

#[test]
fn eight_bit_integers_wrap_in_their_width() {
    let p = run_once(
        "s : SINT := 127; u : USINT; b : BYTE := 16#F0; i : INT := 300; s2, s3 : SINT; i2 : INT; u2 : USINT;",
        "s := s + 1;\nu := u - 1;\nb := NOT b;\ns2 := INT_TO_SINT(i);\ns3 := SINT#-100 - 50;\ni2 := SINT_TO_INT(s3) * 2;\nu2 := BYTE_TO_USINT(b) * 16;",
    );
    // 127 + 1 wraps to -128; 0 - 1 to 255; NOT 16#F0 is 16#0F.
    assert_eq!(shown(&p, "s"), "-128");
    assert_eq!(shown(&p, "u"), "255");
    assert_eq!(shown(&p, "b"), "15");
    // 300 = 256 + 44; -150 wraps to 106.
    assert_eq!(shown(&p, "s2"), "44");
    assert_eq!(shown(&p, "s3"), "106");
    assert_eq!(shown(&p, "i2"), "212");
    // 15 * 16 = 240, in range.
    assert_eq!(shown(&p, "u2"), "240");
}

#[test]
fn lword_is_64_bits() {
    let p = run_once(
        "w : LWORD := 1; top AT %ML0 : LWORD; n : LINT;",
        "top := SHL(w, 63);\nn := LWORD_TO_LINT(top);\nw := ROR(w, 1);",
    );
    assert_eq!(shown(&p, "n"), i64::MIN.to_string());
    assert_eq!(shown(&p, "w"), i64::MIN.to_string());
}

#[test]
fn small_types_refuse_what_does_not_fit() {
    let e = refusals("PROGRAM t\nVAR s : SINT; END_VAR\n  s := 200;\nEND_PROGRAM\n");
    assert!(e[0].starts_with("3:") && e[0].contains("SINT"), "{e:?}");
    let e = refusals("PROGRAM t\nVAR s : SINT; i : INT; END_VAR\n  i := i + s;\nEND_PROGRAM\n");
    assert!(e[0].starts_with("3:"), "{e:?}");
}
