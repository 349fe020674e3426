//! STRUCT and ARRAY variables at run time (flattened: each value its own
//! slot). Expected values from IEC 61131-3's rules: a member's initial
//! value is the declaration's `(m := v)`, else the STRUCT's own; an
//! array's initial list fills elements in order, the last index running
//! fastest (row-major), `n(v)` repeating v n times and `n()` leaving n
//! elements at their type's default (0); elements past the list keep the
//! default too.

use crate::common::{load, refusals, shown};

const POINT: &str =
    "TYPE\n  Point : STRUCT\n    x : INT;\n    y : INT := 5;\n  END_STRUCT;\nEND_TYPE\n";

#[test]
fn struct_members_are_read_and_written() {
    let mut p = load(&format!(
        "{POINT}PROGRAM t\nVAR\n  p : Point;\n  q : Point := (x := 2);\n  r : INT;\nEND_VAR\n\
         p.x := 3;\nq.y := q.y + p.x;\nr := q.x + q.y;\nEND_PROGRAM\n"
    ));
    p.scan(0);
    // q.x = 2 (the declaration's), q.y = 5 (the STRUCT's) + 3.
    assert_eq!(shown(&p, "p.x"), "3");
    assert_eq!(shown(&p, "p.y"), "5");
    assert_eq!(shown(&p, "q.y"), "8");
    assert_eq!(shown(&p, "r"), "10");
}

#[test]
fn a_whole_struct_is_copied_member_by_member() {
    let mut p = load(&format!(
        "{POINT}PROGRAM t\nVAR\n  p : Point := (x := 7, y := 9);\n  q : Point;\nEND_VAR\n\
         q := p;\np.x := 1;\nEND_PROGRAM\n"
    ));
    p.scan(0);
    assert_eq!(shown(&p, "q.x"), "7");
    assert_eq!(shown(&p, "q.y"), "9");
    assert_eq!(shown(&p, "p.x"), "1");
}

#[test]
fn array_initial_values_repeat_and_default() {
    let p = load(
        "PROGRAM t\nVAR\n  a : ARRAY [1..7] OF INT := [1, 2(7), 3()];\nEND_VAR\nEND_PROGRAM\n",
    );
    // 1, then 7 twice, then three defaults, then one past the list.
    let got: Vec<String> = (1..=7).map(|i| shown(&p, &format!("a[{i}]"))).collect();
    assert_eq!(got, ["1", "7", "7", "0", "0", "0", "0"]);
}

#[test]
fn two_dimensions_run_row_major() {
    let mut p = load(
        "PROGRAM t\nVAR\n  m : ARRAY [1..2, 0..1] OF DINT := [10, 11, 20, 21];\n  r : DINT;\nEND_VAR\n\
         r := m[2, 1] - m[1, 0];\nm[1, 1] := r * 2;\nEND_PROGRAM\n",
    );
    p.scan(0);
    assert_eq!(shown(&p, "m[2, 0]"), "20");
    // 21 - 10 = 11; written back to m[1, 1] doubled.
    assert_eq!(shown(&p, "r"), "11");
    assert_eq!(shown(&p, "m[1,1]"), "22");
}

#[test]
fn nested_arrays_of_structs_and_typed_aliases() {
    let mut p = load(
        "TYPE\n  Row : ARRAY [0..2] OF INT := [4, 5, 6];\n  S : STRUCT\n    m : Row;\n    on : BOOL;\n  END_STRUCT;\n  Count : DINT := 3;\nEND_TYPE\n\
         PROGRAM t\nVAR\n  arr : ARRAY [1..2] OF S;\n  n : Count;\n  r : INT;\nEND_VAR\n\
         arr[1].m[2] := 9;\narr[2].on := NOT arr[1].on;\nr := arr[1].m[2] + arr[2].m[0];\nn := n + 1;\nEND_PROGRAM\n",
    );
    p.scan(0);
    assert_eq!(shown(&p, "arr[1].m[2]"), "9");
    assert_eq!(shown(&p, "arr[2].m[1]"), "5");
    assert_eq!(shown(&p, "arr[2].on"), "TRUE");
    // 9 + 4; the alias Count's default 3, plus 1.
    assert_eq!(shown(&p, "r"), "13");
    assert_eq!(shown(&p, "n"), "4");
}

#[test]
fn a_constant_index_outside_the_array_is_refused_at_its_place() {
    let e = refusals(
        "PROGRAM t\nVAR\n  a : ARRAY [1..3] OF INT;\n  r : INT;\nEND_VAR\nr := a[4];\nEND_PROGRAM\n",
    );
    assert_eq!(e.len(), 1, "{e:?}");
    assert!(
        e[0].starts_with("6:6:") && e[0].contains("outside"),
        "{e:?}"
    );
}

#[test]
fn an_index_with_a_call_does_not_run_yet() {
    let e = refusals(
        "PROGRAM t\nVAR\n  a : ARRAY [1..3] OF INT;\n  i, r : INT;\nEND_VAR\nr := a[ABS(i)];\nEND_PROGRAM\n",
    );
    assert_eq!(e.len(), 1, "{e:?}");
    assert!(
        e[0].starts_with("6:6:") && e[0].contains("expression"),
        "{e:?}"
    );
}

#[test]
fn an_index_expression_is_computed_first() {
    let mut p = load(
        "PROGRAM t\nVAR\n  a : ARRAY [0..4] OF DINT := [10, 11, 12, 13, 14];\n  b : ARRAY [0..4] OF DINT;\n  i : SINT := 1;\n  r : DINT;\nEND_VAR\n\
         r := a[i + 1] + a[i * 3];\nb[4 - i] := a[i - 1];\nEND_PROGRAM\n",
    );
    p.scan(0);
    // a[2] + a[3] = 12 + 13; b[3] := a[0].
    assert_eq!(shown(&p, "r"), "25");
    assert_eq!(shown(&p, "b[3]"), "10");
}

#[test]
fn run_time_indices_read_and_write_elements() {
    let mut p = load(
        "PROGRAM t\nVAR\n  a : ARRAY [1..5] OF INT := [1, 2, 3, 4, 5];\n  b : ARRAY [1..5] OF INT;\n  i, j, s : INT;\nEND_VAR\n\
         s := 0;\nFOR i := 1 TO 5 DO\n  s := s + a[i];\n  j := 6 - i;\n  b[j] := a[i] * 10;\nEND_FOR;\nEND_PROGRAM\n",
    );
    p.scan(0);
    // 1 + 2 + 3 + 4 + 5; b is a reversed and times ten.
    assert_eq!(shown(&p, "s"), "15");
    let b: Vec<String> = (1..=5).map(|k| shown(&p, &format!("b[{k}]"))).collect();
    assert_eq!(b, ["50", "40", "30", "20", "10"]);
    assert_eq!(p.fault(), None);
}

#[test]
fn run_time_indices_reach_into_arrays_of_structs() {
    let mut p = load(
        "TYPE\n  S : STRUCT\n    on : BOOL;\n    m : ARRAY [0..2] OF DINT;\n  END_STRUCT;\nEND_TYPE\n\
         PROGRAM t\nVAR\n  arr : ARRAY [-1..1] OF S;\n  i, j : INT;\n  r : DINT;\nEND_VAR\n\
         FOR i := -1 TO 1 DO\n  FOR j := 0 TO 2 DO\n    arr[i].m[j] := INT_TO_DINT(i * 10 + j);\n  END_FOR;\n  arr[i].on := i > 0;\nEND_FOR;\n\
         i := 0; j := 2;\nr := arr[i].m[j] + arr[1].m[0];\nEND_PROGRAM\n",
    );
    p.scan(0);
    assert_eq!(shown(&p, "arr[-1].m[2]"), "-8");
    assert_eq!(shown(&p, "arr[1].m[1]"), "11");
    assert_eq!(shown(&p, "arr[1].on"), "TRUE");
    assert_eq!(shown(&p, "arr[0].on"), "FALSE");
    // arr[0].m[2] = 2, arr[1].m[0] = 10.
    assert_eq!(shown(&p, "r"), "12");
}

#[test]
fn an_index_outside_its_array_at_run_time_stops_the_scan_at_its_line() {
    let mut p = load(
        "PROGRAM t\nVAR\n  a : ARRAY [1..3] OF INT;\n  i, before, after : INT;\nEND_VAR\n\
         before := before + 1;\na[i] := 7;\nafter := after + 1;\nEND_PROGRAM\n",
    );
    // i is 0: below the array's 1..3.
    p.scan(0);
    let step = p.fault().expect("a fault");
    assert_eq!(p.source_line(step).map(|(l, _)| l), Some(7));
    assert_eq!(shown(&p, "before"), "1");
    assert_eq!(shown(&p, "after"), "0");
    // Each scan runs again from the start and stops there again.
    p.scan(0);
    assert_eq!(shown(&p, "before"), "2");
    assert!(p.fault().is_some());
}

#[test]
fn the_element_operand_in_il_is_checked_at_load() {
    use engine::softplc::Program;
    let vars = "VAR\n  a0 : INT;\n  a1 : INT;\n  f : BOOL;\n  i : INT;\nEND_VAR\n";
    let mut p = Program::load(&format!("{vars}LD 1\nST i\nLD 5\nST a0[i:0:2:1]\n"))
        .unwrap_or_else(|e| panic!("{e:?}"));
    p.scan(0);
    assert_eq!(shown(&p, "a1"), "5");
    // Reaching f (a BOOL) from a0 (an INT), or elsewhere than LD/ST.
    let bad = |text: &str| match Program::load(&format!("{vars}{text}")) {
        Ok(_) => panic!("loaded {text}"),
        Err(e) => e[0].to_string(),
    };
    assert!(bad("LD a0[i:0:3:1]\n").contains("one type"));
    assert!(bad("LD 1\nADD a0[i:0:2:1]\n").contains("element operand"));
}

#[test]
fn a_blocks_own_arrays_keep_their_state_and_names() {
    let mut p = load(
        "FUNCTION_BLOCK Ring\nVAR_INPUT x : INT; END_VAR\nVAR_OUTPUT sum : INT; END_VAR\n\
         VAR\n  buf : ARRAY [0..2] OF INT;\n  k, n : INT;\nEND_VAR\n\
         buf[k] := x;\nk := (k + 1) MOD 3;\nsum := 0;\nFOR n := 0 TO 2 DO sum := sum + buf[n]; END_FOR;\n\
         END_FUNCTION_BLOCK\n\
         PROGRAM t\nVAR\n  r : Ring;\n  v, total : INT;\nEND_VAR\nv := v + 1;\nr(x := v, sum => total);\nEND_PROGRAM\n",
    );
    // Scans give 1, 2, 3, 4: the ring keeps the last three.
    for _ in 0..4 {
        p.scan(0);
    }
    assert_eq!(shown(&p, "total"), "9");
    assert_eq!(shown(&p, "r.buf[0]"), "4");
    assert_eq!(shown(&p, "r.buf[2]"), "3");
}

#[test]
fn an_array_of_more_than_4096_values_is_refused_at_its_name() {
    let e = refusals("PROGRAM t\nVAR\n  big : ARRAY [1..5000] OF INT;\nEND_VAR\nEND_PROGRAM\n");
    assert_eq!(e.len(), 1, "{e:?}");
    assert!(e[0].starts_with("3:3:") && e[0].contains("4096"), "{e:?}");
    // 64 × 64 is 4096 values: it runs.
    let p = load("PROGRAM t\nVAR\n  m : ARRAY [1..64, 1..64] OF BOOL;\nEND_VAR\nEND_PROGRAM\n");
    assert_eq!(shown(&p, "m[64, 64]"), "FALSE");
}
