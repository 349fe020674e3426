use super::*;

const BLOCKS: &str = "FUNCTION_BLOCK Scale
VAR_INPUT
  go : BOOL;
  x : INT;
END_VAR
VAR_OUTPUT
  ok : BOOL;
  y : INT;
END_VAR
y := x * 2 + 1;
IF go THEN
  ok := go AND y > 10;
ELSE
  ok := FALSE;
END_IF;
END_FUNCTION_BLOCK

PROGRAM main
VAR
  s0 : Scale;
  n : INT;
  lamp : BOOL;
  t : ARRAY[1..3] OF INT;
END_VAR
s0(go := TRUE, x := n, y => n);
lamp := s0.ok OR MAX(n, t[n]) > 3;
END_PROGRAM
";

fn lines(found: &[StWrite]) -> Vec<usize> {
    found.iter().map(|w| w.line).collect()
}

#[test]
fn a_blocks_output_is_written_by_each_of_its_statements_with_what_they_read() {
    let found = st_writes(BLOCKS, Some("scale"), "OK");
    assert_eq!(lines(&found), [12, 14]);
    assert_eq!(found[0].statement, "ok := go AND y > 10;");
    assert_eq!(found[0].reads, ["go", "y"]);
    assert!(found[1].reads.is_empty(), "a literal reads nothing");
    let y = st_writes(BLOCKS, Some("Scale"), "y");
    assert_eq!(lines(&y), [10]);
    assert_eq!(y[0].reads, ["x"]);
}

#[test]
fn a_programs_variable_names_the_call_or_assignment_that_wrote_it() {
    // The PROGRAM by default: `y => n` writes n from the block's output.
    let n = st_writes(BLOCKS, None, "n");
    assert_eq!(lines(&n), [25]);
    assert_eq!(n[0].reads, ["s0.y"]);
    let lamp = st_writes(BLOCKS, None, "lamp");
    assert_eq!(lines(&lamp), [26]);
    // A member, a function's arguments, an element by its array and index.
    assert_eq!(lamp[0].reads, ["s0.ok", "n", "t"]);
}

#[test]
fn nothing_is_named_for_a_name_never_written_a_broken_text_or_no_such_pou() {
    assert!(st_writes(BLOCKS, None, "s0").is_empty());
    assert!(st_writes(BLOCKS, Some("Other"), "ok").is_empty());
    assert!(st_writes(
        "PROGRAM p VAR a : INT; END_VAR a := ; END_PROGRAM",
        None,
        "a"
    )
    .is_empty());
    assert!(st_writes("FUNCTION_BLOCK b END_FUNCTION_BLOCK", None, "a").is_empty());
}
