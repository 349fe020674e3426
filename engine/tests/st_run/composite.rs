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
fn an_index_computed_at_run_time_does_not_run_yet() {
    let e = refusals(
        "PROGRAM t\nVAR\n  a : ARRAY [1..3] OF INT;\n  i, r : INT;\nEND_VAR\nr := a[i];\nEND_PROGRAM\n",
    );
    assert_eq!(e.len(), 1, "{e:?}");
    assert!(
        e[0].starts_with("6:6:") && e[0].contains("computed"),
        "{e:?}"
    );
}
