//! VAR_GLOBAL at run time: a file's globals are the PROGRAM's
//! variables (its `VAR_EXTERNAL` names them, as IEC asks; a name the
//! PROGRAM declares itself shadows the global there).

use crate::common::{load, refusals, shown};

#[test]
fn a_global_is_read_and_written_by_the_program() {
    let mut p = load(
        "VAR_GLOBAL\n  limit : INT := 3;\n  count : INT;\n  flags : ARRAY [1..2] OF BOOL;\nEND_VAR\n\
         VAR_GLOBAL RETAIN\n  total : DINT;\nEND_VAR\n\
         PROGRAM t\nVAR_EXTERNAL\n  limit : INT;\n  count : INT;\n  flags : ARRAY [1..2] OF BOOL;\n  total : DINT;\nEND_VAR\n\
         IF count < limit THEN count := count + 1; END_IF;\nflags[2] := count = limit;\ntotal := total + 10;\nEND_PROGRAM\n",
    );
    for _ in 0..4 {
        p.scan(0);
    }
    // Counts to the limit (3) and stays; total adds 10 a scan.
    assert_eq!(shown(&p, "count"), "3");
    assert_eq!(shown(&p, "flags[2]"), "TRUE");
    assert_eq!(shown(&p, "total"), "40");
}

#[test]
fn the_programs_own_name_shadows_a_global() {
    let mut p = load(
        "VAR_GLOBAL\n  n : INT := 5;\n  g : INT := 1;\nEND_VAR\nPROGRAM t\nVAR\n  n : INT := 100;\nEND_VAR\nn := n + g;\nEND_PROGRAM\n",
    );
    p.scan(0);
    assert_eq!(shown(&p, "n"), "101");
}

#[test]
fn var_external_in_a_block_does_not_run_yet() {
    let e = refusals(
        "VAR_GLOBAL\n  g : INT;\nEND_VAR\nFUNCTION_BLOCK b\nVAR_EXTERNAL\n  g : INT;\nEND_VAR\ng := 1;\nEND_FUNCTION_BLOCK\nPROGRAM t\nVAR\n  i : b;\nEND_VAR\ni();\nEND_PROGRAM\n",
    );
    assert!(
        e[0].starts_with("5:1:") && e[0].contains("VAR_EXTERNAL"),
        "{e:?}"
    );
}
