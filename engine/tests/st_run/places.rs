//! The map from the soft PLC's steps back to the ST lines they come
//! from (`Program::source_line`): what the page needs for values beside
//! lines, breakpoints and stepping by statement.

use super::common::load;
use engine::softplc::Program;

/// The distinct ST lines the steps come from, in step order.
fn lines_of(p: &Program) -> Vec<u32> {
    let mut out: Vec<u32> = Vec::new();
    for s in 0..p.len() {
        if let Some((line, _)) = p.source_line(s) {
            if out.last() != Some(&line) {
                out.push(line);
            }
        }
    }
    out
}

#[test]
fn each_step_names_the_st_line_it_comes_from() {
    let p = load(
        "PROGRAM t\nVAR a, b : INT; END_VAR\na := 1;\nIF a > 0 THEN\n  b := a + 2;\nEND_IF;\nEND_PROGRAM\n",
    );
    // Statements on lines 3, 4 (the condition) and 5, then the IF's
    // end (its label, a step of the IF statement on line 4).
    assert_eq!(lines_of(&p), vec![3, 4, 5, 4]);
    // The first step loads `1`, at its column.
    assert_eq!(p.source_line(0), Some((3, 6)));
    assert_eq!(p.source_line(p.len()), None);
}

#[test]
fn a_block_body_maps_to_its_own_lines() {
    let p = load(
        "FUNCTION_BLOCK Inc\nVAR_INPUT x : INT; END_VAR\nVAR_OUTPUT y : INT; END_VAR\ny := x + 1;\nEND_FUNCTION_BLOCK\nPROGRAM t\nVAR i : Inc; r : INT; END_VAR\ni(x := 4, y => r);\nEND_PROGRAM\n",
    );
    let lines = lines_of(&p);
    assert!(lines.contains(&8), "{lines:?}");
    assert!(lines.contains(&4), "{lines:?}");
}

#[test]
fn an_il_program_has_no_st_lines() {
    let p =
        Program::load("VAR\n  a : INT;\nEND_VAR\nLD 1\nST a\n").unwrap_or_else(|e| panic!("{e:?}"));
    assert!((0..p.len()).all(|s| p.source_line(s).is_none()));
}
