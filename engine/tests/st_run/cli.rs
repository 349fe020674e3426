//! `hashigo run` with a `.st` file (../shared/spec/cli.md): the soft PLC
//! without `--machine`, events on located inputs, `NAME.MEMBER` watched,
//! errors at file:line:column.

use crate::files::{hashigo, text, Temp};

const BLINK: &str = "PROGRAM blink
VAR
  start AT %IX0.0 : BOOL;
  lamp AT %QX0.0 : BOOL;
  t0 : TON;
  n : INT;
END_VAR
t0(IN := start, PT := T#100ms);
lamp := t0.Q;
IF lamp THEN n := n + 1; END_IF;
END_PROGRAM
";

#[test]
fn a_st_file_runs_on_the_soft_plc_with_events() {
    let dir = Temp::new("st-run-cli");
    let program = dir.file("blink.st", BLINK);
    let events = dir.file("ev.csv", "50ms,%IX0.0,1\n");
    let out = hashigo(
        &[
            "run",
            "--program",
            &program,
            "--input",
            &events,
            "--until",
            "200ms",
            "--every",
            "50ms",
            "--watch",
            "start,%QX0.0,n,t0.Q",
        ],
        "",
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    // Scans every 10 ms: IN from 50 ms, Q at 150 ms, n counts its scans.
    assert_eq!(
        text(&out.stdout),
        "time_ms,start,%QX0.0,n,t0.Q\n0,0,0,0,0\n50,1,0,0,0\n100,1,0,0,0\n150,1,1,1,1\n200,1,1,6,1\n"
    );
}

#[test]
fn a_st_files_errors_are_at_file_line_column() {
    let dir = Temp::new("st-run-cli-bad");
    let program = dir.file(
        "bad.st",
        "PROGRAM p\nVAR n : INT; END_VAR\nn := TRUE;\nEND_PROGRAM\n",
    );
    let out = hashigo(
        &[
            "run",
            "--program",
            &program,
            "--until",
            "10ms",
            "--watch",
            "n",
        ],
        "",
    );
    assert_eq!(out.status.code(), Some(2));
    let err = text(&out.stderr);
    assert!(
        err.contains("bad.st:3:6: the value assigned must be INT, not BOOL"),
        "{err}"
    );
    let out = hashigo(
        &[
            "run",
            "--machine",
            "io86a",
            "--program",
            &program,
            "--until",
            "10ms",
            "--watch",
            "n",
        ],
        "",
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("Structured Text runs on the soft PLC"));
}

#[test]
fn array_elements_and_members_are_watched_as_written() {
    let dir = Temp::new("st-run-cli-arrays");
    let program = dir.file(
        "arr.st",
        "TYPE Pt : STRUCT x : INT; END_STRUCT; END_TYPE\nPROGRAM p\nVAR\n  m : ARRAY [1..2, 0..1] OF INT := [1, 2, 3, 4];\n  s : Pt;\nEND_VAR\ns.x := m[2, 1] + 1;\nEND_PROGRAM\n",
    );
    let watch = ["--watch", "m[2,1],m[1, 0]", "--watch", "s.x"];
    let mut args = vec!["run", "--program", &program, "--until", "10ms"];
    args.extend(watch);
    let out = hashigo(&args, "");
    assert!(out.status.success(), "{}", text(&out.stderr));
    // The header keeps each name as given; m[2, 1] is 4, s.x 5.
    let stdout = text(&out.stdout);
    let first = stdout.lines().nth(1).unwrap_or_default().to_string();
    assert!(
        stdout.starts_with("time_ms,m[2,1],m[1, 0],s.x\n"),
        "{stdout}"
    );
    assert!(
        stdout.lines().last().is_some_and(|l| l.ends_with(",4,1,5")),
        "{stdout} {first}"
    );
}

#[test]
fn watch_prints_an_lreal_to_its_last_digit_and_events_set_one() {
    let dir = Temp::new("st-run-lreal");
    let program = dir.file(
        "l.st",
        "PROGRAM t\nVAR\n  a : LREAL := 0.1;\n  c : LREAL;\n  k : LREAL;\nEND_VAR\nc := a + 0.2;\nEND_PROGRAM\n",
    );
    // An event writes an LREAL at once, from its decimal text.
    let events = dir.file("ev.csv", "5ms,k,0.123456789012\n");
    let out = hashigo(
        &[
            "run",
            "--program",
            &program,
            "--input",
            &events,
            "--until",
            "20ms",
            "--watch",
            "c,k",
        ],
        "",
    );
    // binary64: 0.1 + 0.2 = 0.30000000000000004.
    assert_eq!(
        text(&out.stdout),
        "time_ms,c,k\n0,0.0,0.0\n20,0.30000000000000004,0.123456789012\n"
    );
}
