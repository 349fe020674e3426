//! VAR_IN_OUT in the program's own FUNCTION_BLOCKs and FUNCTIONs (issue
//! #54): the variable given is read and written by the call, as IEC's
//! reference gives (lowered as copy in, copy out), a RETURN included.

use crate::common::{load, refusals, shown};

const SOURCE: &str = "FUNCTION_BLOCK Acc
VAR_INPUT step : INT; END_VAR
VAR_IN_OUT total : INT; END_VAR
VAR_OUTPUT calls : INT; END_VAR
calls := calls + 1;
IF step < 0 THEN
  total := total * 10;
  RETURN;
END_IF;
total := total + step;
END_FUNCTION_BLOCK

FUNCTION Swap : BOOL
VAR_IN_OUT a, b : INT; END_VAR
VAR t : INT; END_VAR
t := a;
a := b;
b := t;
Swap := TRUE;
END_FUNCTION

PROGRAM t
VAR
  acc, tens : Acc;
  x : INT := 5; y : INT := 7; s : INT := 1; r : INT := 2;
  ok : BOOL;
END_VAR
acc(step := 2, total := s);
tens(step := -1, total := r);
ok := Swap(x, y);
END_PROGRAM
";

#[test]
fn an_in_out_is_read_and_written_by_the_call() {
    let mut p = load(SOURCE);
    p.scan(0);
    // s: 1 + 2; r: 2 * 10, written back though the block RETURNs.
    assert_eq!(shown(&p, "s"), "3");
    assert_eq!(shown(&p, "r"), "20");
    // Swap by position: a is x, b is y.
    assert_eq!(shown(&p, "x"), "7");
    assert_eq!(shown(&p, "y"), "5");
    assert_eq!(shown(&p, "ok"), "TRUE");
    p.scan(10);
    assert_eq!(shown(&p, "s"), "5");
    assert_eq!(shown(&p, "r"), "200");
    assert_eq!(shown(&p, "x"), "5");
    assert_eq!(shown(&p, "y"), "7");
    assert_eq!(shown(&p, "acc.calls"), "2");
}

#[test]
fn an_in_out_takes_a_variable() {
    let bad = SOURCE.replace(
        "acc(step := 2, total := s);",
        "acc(step := 2, total := s + 1);",
    );
    let e = refusals(&bad);
    assert!(
        e.iter()
            .any(|m| m.starts_with("28:25:") && m.contains("VAR_IN_OUT total takes a variable")),
        "{e:?}"
    );
}

#[test]
fn a_program_has_no_in_out() {
    let e = refusals("PROGRAM t\nVAR_IN_OUT k : INT; END_VAR\nk := k + 1;\nEND_PROGRAM\n");
    assert!(
        e.iter()
            .any(|m| m.starts_with("2:") && m.contains("VAR_IN_OUT in a PROGRAM")),
        "{e:?}"
    );
}
