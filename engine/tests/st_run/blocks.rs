//! Standard blocks called from ST, keeping state over scans; the
//! program's own FUNCTION_BLOCKs in ST; located I/O driven by events.

use engine::iec::address::Address;
use engine::iec::data::Data;

use crate::common::{load, shown};

const MS: i64 = 1_000_000;

fn press(p: &mut engine::softplc::Program, address: &str, on: bool) {
    let a = Address::parse(address).expect("an address");
    assert!(p.set_input(a, Data::Bool(on)), "{address} is an input");
}

#[test]
fn a_ton_called_from_st_times_over_scans() {
    let mut p = load(
        "PROGRAM t\nVAR\n  start AT %IX0.0 : BOOL;\n  lamp AT %QX0.0 : BOOL;\n  t0 : TON;\n  el : TIME;\nEND_VAR\nt0(IN := start, PT := T#100ms);\nlamp := t0.Q;\nel := t0.ET;\nEND_PROGRAM\n",
    );
    p.scan(0);
    assert_eq!(shown(&p, "%QX0.0"), "FALSE");
    press(&mut p, "%IX0.0", true);
    p.scan(10 * MS);
    p.scan(60 * MS);
    assert_eq!(shown(&p, "lamp"), "FALSE", "50 ms of 100");
    assert_eq!(shown(&p, "el"), "50ms");
    p.scan(110 * MS);
    assert_eq!(shown(&p, "lamp"), "TRUE", "100 ms passed");
    assert_eq!(shown(&p, "%QX0.0"), "TRUE");
    press(&mut p, "%IX0.0", false);
    p.scan(120 * MS);
    assert_eq!(shown(&p, "lamp"), "FALSE", "IN off resets it");
}

#[test]
fn a_ctu_and_an_r_trig_count_rising_edges() {
    let mut p = load(
        "PROGRAM t\nVAR\n  b AT %IX0.1 : BOOL;\n  c0 : CTU;\n  e0 : R_TRIG;\n  edges, n : INT;\n  full : BOOL;\n  pulse : BOOL;\nEND_VAR\ne0(CLK := b, Q => pulse);\nIF pulse THEN edges := edges + 1; END_IF;\nc0(CU := b, PV := 3, Q => full);\nn := c0.CV;\nEND_PROGRAM\n",
    );
    for (i, on) in [true, true, false, true, false, true, true]
        .into_iter()
        .enumerate()
    {
        press(&mut p, "%IX0.1", on);
        p.scan(i as i64 * MS);
    }
    assert_eq!(shown(&p, "edges"), "3");
    assert_eq!(shown(&p, "n"), "3");
    assert_eq!(shown(&p, "full"), "TRUE");
}

#[test]
fn an_own_function_block_keeps_its_state() {
    let mut p = load(
        "FUNCTION_BLOCK Acc\nVAR_INPUT add : INT; END_VAR\nVAR_OUTPUT total : INT; calls : INT; END_VAR\nVAR kept : INT := 100; END_VAR\nkept := kept + add;\ntotal := kept;\ncalls := calls + 1;\nEND_FUNCTION_BLOCK\n\nPROGRAM t\nVAR a1, a2 : Acc; x, y, k : INT; END_VAR\na1(add := 5);\na2(add := -1, total => y);\nx := a1.total;\nk := a1.calls;\nEND_PROGRAM\n",
    );
    for i in 0..3 {
        p.scan(i * MS);
    }
    // Each instance its own state: 100 + 3 × 5, 100 − 3.
    assert_eq!(shown(&p, "x"), "115");
    assert_eq!(shown(&p, "y"), "97");
    assert_eq!(shown(&p, "k"), "3");
}

#[test]
fn a_function_block_declared_after_the_program_runs() {
    let mut p = load(
        "PROGRAM t\nVAR f : Flip; o : BOOL; END_VAR\nf();\no := f.q;\nEND_PROGRAM\nFUNCTION_BLOCK Flip\nVAR_OUTPUT q : BOOL; END_VAR\nq := NOT q;\nEND_FUNCTION_BLOCK\n",
    );
    p.scan(0);
    assert_eq!(shown(&p, "o"), "TRUE");
    p.scan(MS);
    assert_eq!(shown(&p, "o"), "FALSE");
}

#[test]
fn own_functions_are_called_in_expressions() {
    let mut p = load(
        "FUNCTION Square : DINT\nVAR_INPUT x : DINT; END_VAR\nSquare := x * x;\nEND_FUNCTION\n\
         FUNCTION Clamp : DINT\nVAR_INPUT v, hi : DINT; END_VAR\nClamp := v;\nIF v > hi THEN Clamp := hi; END_IF;\nEND_FUNCTION\n\
         PROGRAM t\nVAR a : DINT := 3; r, s, c : DINT; i : DINT; END_VAR\n\
         r := Square(a) + Square(x := 4) * 2;\n\
         c := Clamp(Square(a), 5);\n\
         FOR i := 1 TO Square(2) DO s := s + Clamp(v := i, hi := 2); END_FOR;\n\
         END_PROGRAM\n",
    );
    p.scan(0);
    // 9 + 16 × 2.
    assert_eq!(shown(&p, "r"), "41");
    assert_eq!(shown(&p, "c"), "5");
    // 1 + 2 + 2 + 2.
    assert_eq!(shown(&p, "s"), "7");
    assert_eq!(shown(&p, "i"), "5");
}

#[test]
fn expressions_as_inputs_of_blocks_and_own_functions() {
    let mut p = load(
        "FUNCTION Twice : INT\nVAR_INPUT x : INT; END_VAR\nTwice := x * 2;\nEND_FUNCTION\n\
         PROGRAM t\nVAR a AT %IX0.0 : BOOL; b : BOOL := TRUE; t0 : TON; c0 : CTU; n, k : INT; q, full : BOOL; END_VAR\n\
         t0(IN := a AND b, PT := T#10ms + T#20ms);\nq := t0.Q;\n\
         c0(CU := NOT q AND a, PV := Twice(n + 1) + 1, Q => full);\nk := c0.CV;\n\
         n := Twice(Twice(k) - 1);\n\
         END_PROGRAM\n",
    );
    p.scan(0);
    // n = Twice(Twice(0) - 1) = -2.
    assert_eq!(shown(&p, "n"), "-2");
    let a = engine::iec::address::Address::parse("%IX0.0").expect("address");
    assert!(p.set_input(a, engine::iec::data::Data::Bool(true)));
    p.scan(MS);
    // CU rose: CV 1; n = Twice(2 - 1) = 2.
    assert_eq!(shown(&p, "k"), "1");
    assert_eq!(shown(&p, "n"), "2");
    p.scan(20 * MS);
    assert_eq!(shown(&p, "q"), "FALSE", "20 ms of 30");
    p.scan(31 * MS);
    assert_eq!(shown(&p, "q"), "TRUE", "PT is 10 ms + 20 ms");
    // PV = Twice(n + 1) + 1 = 7 while n = 2: CV 1 is not there.
    assert_eq!(shown(&p, "full"), "FALSE");
}

#[test]
fn hidden_variables_take_no_declared_name() {
    let mut p = load(
        "PROGRAM t\nVAR a : BOOL := TRUE; st_t1 : BOOL := TRUE; st_t2 : INT := 7; t0 : TON; q : BOOL; END_VAR\nt0(IN := a AND st_t1, PT := T#0s);\nq := t0.Q;\nEND_PROGRAM\n",
    );
    p.scan(0);
    assert_eq!(shown(&p, "q"), "TRUE");
    assert_eq!(shown(&p, "st_t2"), "7");
}
