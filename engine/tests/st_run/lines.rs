//! Each step of an ST program's IL knows its ST line (issue #55: the
//! page's breakpoints and current line), through a block's body too.

use engine::softplc::st::st_run;
use engine::softplc::Program;

const TEXT: &str = "FUNCTION_BLOCK Twice\nVAR_INPUT x : INT; END_VAR\nVAR_OUTPUT y : INT; END_VAR\ny := x * 2;\nEND_FUNCTION_BLOCK\nPROGRAM main\nVAR\n  a : INT;\n  b : INT;\n  t : Twice;\nEND_VAR\na := a + 1;\nt(x := a);\nb := t.y;\nEND_PROGRAM\n";

#[test]
fn every_step_has_the_st_line_it_comes_from() {
    let run = st_run(TEXT).expect("loads");
    let program = Program::load(&run.il).expect("its IL loads");
    assert_eq!(run.lines.len(), program.len(), "{:?}", run.lines);
    let lines: Vec<usize> = run.lines.iter().flatten().copied().collect();
    // The program's statements, in order, then the block's body.
    let first_of = |n: usize| lines.iter().position(|&l| l == n);
    let (a, call, b, body) = (first_of(12), first_of(13), first_of(14), first_of(4));
    assert!(
        a.is_some() && call.is_some() && b.is_some() && body.is_some(),
        "{lines:?}"
    );
    assert!(a < call && call < b && b < body, "{lines:?}");
    // No step is placed on a declaration or outside any statement.
    assert!(
        lines.iter().all(|l| [4, 12, 13, 14].contains(l)),
        "{lines:?}"
    );
    // The steps the loader adds (the program's end, the body's return).
    assert_eq!(run.lines.iter().filter(|l| l.is_none()).count(), 2);
}
