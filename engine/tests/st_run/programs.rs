//! Several `PROGRAM`s in one ST text (issue #55): each runs in turn, in
//! text order, with its own variables (a later program's name that an
//! earlier one has is renamed `<program>_<name>` in the IL); `RETURN`
//! ends its own program; each step keeps its ST line.

use super::common::{load, shown};
use engine::softplc::st::st_run;

const TWO: &str = "\
VAR_GLOBAL
  shared : INT;
END_VAR
PROGRAM first
VAR
  n : INT;
  stop : BOOL;
END_VAR
VAR_EXTERNAL shared : INT; END_VAR
n := n + 1;
shared := n;
IF stop THEN
  RETURN;
END_IF;
stop := n >= 2;
END_PROGRAM
PROGRAM second
VAR
  n : DINT;
  seen : INT;
END_VAR
VAR_EXTERNAL shared : INT; END_VAR
n := n + 10;
seen := shared * 100;
END_PROGRAM
";

#[test]
fn two_programs_run_in_text_order_each_with_its_own_variables() {
    let mut p = load(TWO);
    for scan in 1..=3 {
        p.scan(scan * 10_000_000);
    }
    assert_eq!(shown(&p, "n"), "3", "the first program's n");
    assert_eq!(
        shown(&p, "second_n"),
        "30",
        "the second's, a DINT of its own"
    );
    // The second runs after the first: it sees this scan's `shared`, and
    // the first's RETURN (from its second scan on) did not end the scan.
    assert_eq!(shown(&p, "seen"), "300");
}

#[test]
fn each_programs_steps_keep_their_lines_and_names() {
    let run = st_run(TWO).expect("runs");
    let line = |text: &str| TWO.lines().position(|l| l.trim() == text).expect(text) + 1;
    for text in [
        "n := n + 1;",
        "RETURN;",
        "n := n + 10;",
        "seen := shared * 100;",
    ] {
        assert!(
            run.lines.contains(&Some(line(text))),
            "{text}: {:?}",
            run.lines
        );
    }
    // `n` on the second program's lines is its own; on the first's, and
    // a name not renamed, as written.
    assert_eq!(run.il_name(line("n := n + 10;"), "n"), "second_n");
    assert_eq!(run.il_name(line("n := n + 1;"), "n"), "n");
    assert_eq!(run.il_name(line("seen := shared * 100;"), "seen"), "seen");
    assert_eq!(
        run.il_name(line("seen := shared * 100;"), "shared"),
        "shared"
    );
}

#[test]
fn a_renamed_name_never_takes_a_declared_one() {
    // `second_n` is declared by the first program already.
    let text = TWO.replace("  stop : BOOL;", "  stop : BOOL;\n  second_n : INT;");
    let mut p = load(&text);
    p.scan(10_000_000);
    assert_eq!(shown(&p, "second_n"), "0", "the first program's own");
    assert_eq!(shown(&p, "second_n_"), "10", "the second's n");
}
