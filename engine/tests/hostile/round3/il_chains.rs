//! Issue #44, item 1 at scale: a long run of untyped literals (`LD 1`
//! and then a line `ADD 1` after another, and the like through
//! parentheses and labels) loads in time about proportional to its
//! lines. The loader used to copy and retype every literal of the run
//! at each line: 20 000 lines took a minute in a debug build, the
//! chains here (just under the 100 000 lines of a program text) half
//! an hour. Each test checks what the chain computes, never a time.

use engine::iec::{Data, DataType};
use engine::limits::MAX_PROGRAM_LINES;
use engine::softplc::Program;

/// Lines of each chain: the program text stays within its limit.
const N: usize = MAX_PROGRAM_LINES - 1_000;

const VARS: &str = "VAR\n  n : DINT;\n  w : LINT;\n  b : BOOL;\nEND_VAR\n";

/// `body` loaded after the variables and run one scan.
fn run(body: &str) -> Program {
    let text = format!("{VARS}{body}");
    assert!(text.lines().count() <= MAX_PROGRAM_LINES);
    let mut p = Program::load(&text).unwrap_or_else(|e| panic!("{:?}", e.first()));
    p.scan(0);
    p
}

fn dint(v: i128) -> Option<Data> {
    Some(Data::integer(DataType::Dint, v))
}

#[test]
fn a_long_run_of_untyped_adds_takes_the_stores_type() {
    let body = format!("LD 1\n{}ST n\n", "ADD 1\n".repeat(N));
    assert_eq!(run(&body).value("n"), dint(N as i128 + 1));
}

#[test]
fn a_long_run_widened_by_its_last_literal_is_a_lint_throughout() {
    // 5 000 000 000 is a LINT: the whole run becomes LINTs at its line,
    // once, and the store takes them as they are.
    let body = format!("LD 1\n{}ADD 5000000000\nST w\n", "ADD 1\n".repeat(N));
    let want = Data::integer(DataType::Lint, N as i128 + 1 + 5_000_000_000);
    assert_eq!(run(&body).value("w"), Some(want));
}

#[test]
fn a_long_run_of_subs_and_muls_ends_in_a_comparison() {
    let body = format!(
        "LD 0\n{}MUL 2\nEQ {}\nST b\n",
        "SUB 1\n".repeat(N),
        -2 * N as i128
    );
    assert_eq!(run(&body).value("b"), Some(Data::Bool(true)));
    let body = body.replace("MUL 2", "MUL 3");
    assert_eq!(run(&body).value("b"), Some(Data::Bool(false)));
}

#[test]
fn a_long_run_through_parentheses_joins_both_sides_each_time() {
    let pairs = N / 2;
    let body = format!("LD 1\n{}ST n\n", "ADD( 1\n)\n".repeat(pairs));
    assert_eq!(run(&body).value("n"), dint(pairs as i128 + 1));
}

#[test]
fn a_long_run_through_labels_brings_its_literals_every_jump() {
    // `JMP l0` / `l0: ADD 1` / `JMP l1` / …: each label goes on with the
    // literals its jump brings.
    let pairs = N / 2;
    let mut body = String::from("LD 1\n");
    for i in 0..pairs {
        body.push_str(&format!("JMP l{i}\nl{i}: ADD 1\n"));
    }
    body.push_str("ST n\n");
    assert_eq!(run(&body).value("n"), dint(pairs as i128 + 1));
}

#[test]
fn a_long_run_that_does_not_fit_is_refused_at_each_of_its_lines() {
    // Every -1 is refused as a ULINT, the widest literal's type (one
    // error a line, each said once), and 2^64 - 1 as the store's LINT.
    let body = format!(
        "LD -1\n{}ADD 18446744073709551615\nST w\n",
        "ADD -1\n".repeat(N)
    );
    let Err(errors) = Program::load(&format!("{VARS}{body}")) else {
        panic!("loaded, should be refused");
    };
    let first = VARS.lines().count() + 1;
    let want: Vec<(usize, &str)> = (first..=first + N)
        .map(|line| (line, "out of range for ULINT"))
        .chain([(first + N + 1, "out of range for LINT")])
        .collect();
    assert_eq!(errors.len(), want.len());
    for (e, (line, says)) in errors.iter().zip(want) {
        assert_eq!(e.line, line, "{e:?}");
        assert!(e.error.to_string().contains(says), "{e:?}");
    }
}
