//! A block call's arguments beyond `name := value`: inputs by position
//! (IEC 61131-3 3rd edition's non-formal call: the inputs in their
//! declared order; TON's are IN, PT), `NOT Q => y` (y takes Q inverted
//! after the call) and an output to a STRUCT member or array element.

use crate::common::{load, shown};

const MS: i64 = 1_000_000;

#[test]
fn a_standard_blocks_inputs_by_position() {
    let mut p = load(
        "PROGRAM t\nVAR\n  go : BOOL := TRUE;\n  t0 : TON;\n  q : BOOL;\nEND_VAR\nt0(go, T#20ms);\nq := t0.Q;\nEND_PROGRAM\n",
    );
    p.scan(0);
    p.scan(10 * MS);
    assert_eq!(shown(&p, "q"), "FALSE", "10 ms of 20");
    p.scan(25 * MS);
    assert_eq!(
        shown(&p, "q"),
        "TRUE",
        "PT = T#20ms reached the second input"
    );
}

#[test]
fn an_own_blocks_inputs_by_position() {
    let mut p = load(
        "FUNCTION_BLOCK Lin\nVAR_INPUT a, b : INT; END_VAR\nVAR_OUTPUT y : INT; END_VAR\ny := a * 10 + b;\nEND_FUNCTION_BLOCK\n\
         PROGRAM t\nVAR\n  f : Lin;\n  r : INT;\nEND_VAR\nf(4, 2, y => r);\nEND_PROGRAM\n",
    );
    p.scan(0);
    // a = 4, b = 2 in their order.
    assert_eq!(shown(&p, "r"), "42");
}

#[test]
fn a_negated_output_and_one_to_a_member() {
    let mut p = load(
        "TYPE St : STRUCT done : BOOL; n : INT; END_STRUCT; END_TYPE\n\
         PROGRAM t\nVAR\n  b : BOOL;\n  c0 : CTU;\n  notfull : BOOL;\n  s : St;\n  a : ARRAY [1..2] OF INT;\nEND_VAR\n\
         b := NOT b;\nc0(CU := b, PV := 2, Q => s.done, NOT Q => notfull, CV => a[2]);\nEND_PROGRAM\n",
    );
    // Rising edges of b at scans 1 and 3: CV 1 then 2.
    p.scan(0);
    assert_eq!(shown(&p, "notfull"), "TRUE");
    assert_eq!(shown(&p, "a[2]"), "1");
    p.scan(0);
    p.scan(0);
    assert_eq!(shown(&p, "a[2]"), "2");
    assert_eq!(shown(&p, "s.done"), "TRUE");
    assert_eq!(shown(&p, "notfull"), "FALSE");
}
