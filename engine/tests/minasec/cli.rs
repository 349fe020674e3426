//! The `hashigo` command per ../shared/spec/cli.md, run as a process.

use super::common::{hashigo, text, Temp, SEED_PANEL};

const SEED: &str = engine::minasec::SEED_TEST_PROGRAM;

#[test]
fn run_reproduces_the_seed_test_program() {
    let tmp = Temp::new("seed");
    let program = tmp.file("seed.il", SEED);
    let events = tmp.file(
        "events.csv",
        "time,device,value\n0.5s,X00,1\n0.7s,X00,0\n# stop, then clear\n25s,X01,1\n25.2s,X01,0\n27s,X02,1\n27.2s,X02,0\n",
    );
    let out = hashigo(
        &[
            &["run", "--program", &program][..],
            &SEED_PANEL,
            &[
                "--input",
                &events,
                "--until",
                "28s",
                "--every",
                "500ms",
                "--watch",
                "Y00,Y01,C0.v,C0",
            ],
        ]
        .concat(),
        "",
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let csv = text(&out.stdout);
    let rows: Vec<Vec<&str>> = csv.lines().map(|l| l.split(',').collect()).collect();
    assert_eq!(rows[0], ["time_ms", "Y00", "Y01", "C0.v", "C0"]);
    assert_eq!(rows.len(), 1 + 57, "rows at 0, 500, ..., 28000 ms");
    let at = |ms: u64| -> Vec<&str> {
        rows.iter()
            .find(|r| r[0] == ms.to_string())
            .unwrap_or_else(|| panic!("no row at {ms}"))[1..]
            .to_vec()
    };
    assert_eq!(at(0), ["0", "0", "0", "0"], "power-on state");
    assert_eq!(at(1000), ["1", "0", "0", "0"], "start latched Y00");
    // The count rises about every 2.1 s: each of 1..=9 is shown on four or
    // five rows (2.0-2.5 s), then it holds at 10 with Y01 and C0 lit.
    for n in 1..=9 {
        let shown = rows[1..].iter().filter(|r| r[3] == n.to_string()).count();
        assert!((4..=5).contains(&shown), "count {n} shown on {shown} rows");
    }
    assert_eq!(at(20000)[2], "9");
    assert_eq!(at(21000), ["1", "1", "10", "1"], "stops at 10, Y01 lit");
    assert_eq!(at(25000), ["1", "1", "10", "1"]);
    assert_eq!(at(26000), ["0", "1", "10", "1"], "stop keeps the count");
    assert_eq!(at(27500), ["0", "0", "0", "0"], "X02 clears it");
    assert_eq!(at(28000), ["0", "0", "0", "0"]);
}

#[test]
fn run_reads_the_program_from_stdin_and_watches_every_kind_of_device() {
    let out = hashigo(
        &[
            "run",
            "--machine",
            "minasec-u",
            "--program",
            "-",
            "--until",
            "100ms",
            "--every",
            "50ms",
            "--watch",
            "X00,Y00,M10,T0,T0.v,C0R,C0.v",
        ],
        "LD X00\nSTI Y00\nSTI M10\nSTI T0\n",
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    // Rows show the last completed scan: at 50 ms that is scan 5, ending at
    // 42.24 ms, 42.12 ms after STI T0 (step 3 of scan 0) started the timer.
    assert_eq!(
        text(&out.stdout),
        "time_ms,X00,Y00,M10,T0,T0.v,C0R,C0.v\n0,0,0,0,0,0,0,0\n50,0,1,1,0,42,0,0\n100,0,1,1,0,92,0,0\n"
    );
}

#[test]
fn bad_program_lines_are_reported_with_file_and_line() {
    let tmp = Temp::new("badprog");
    let program = tmp.file("bad.il", "LD X00\nFOO Y00\nST Y09\n");
    let out = hashigo(
        &[
            "run",
            "--machine",
            "minasec-u",
            "--program",
            &program,
            "--until",
            "1s",
            "--watch",
            "Y00",
        ],
        "",
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty(), "no partial output");
    let err = text(&out.stderr);
    let lines: Vec<&str> = err.lines().collect();
    assert_eq!(lines.len(), 2, "{err}");
    assert!(
        lines[0].starts_with(&format!("error: {program}:2: unknown opcode \"FOO\"")),
        "{err}"
    );
    assert!(
        lines[1].starts_with(&format!("error: {program}:3: unknown device \"Y09\"")),
        "{err}"
    );
}

#[test]
fn too_many_steps_is_located() {
    let out = hashigo(
        &["asm", "--machine", "minasec-u", "--program", "-"],
        &"LD X00\n".repeat(300),
    );
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        text(&out.stderr),
        "error: <stdin>:257: too many steps: the program needs 257 but MINASEC-U has 256\n"
    );
}

#[test]
fn bad_events_settings_watches_and_times_are_all_reported() {
    let tmp = Temp::new("badinput");
    let program = tmp.file("p.il", "LD X00\nST Y00\n");
    let events = tmp.file(
        "e.csv",
        "time,device,value\n1s,Y00,1\n2s,X00,5\nsoon,X00,1\n",
    );
    let out = hashigo(
        &[
            "run",
            "--machine",
            "minasec-u",
            "--program",
            &program,
            "--input",
            &events,
            "--set",
            "T0=5s",
            "--set",
            "C0=100",
            "--set",
            "clock=warp",
            "--set",
            "bogus",
            "--until",
            "1x",
            "--watch",
            "Y00",
        ],
        "",
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let err = text(&out.stderr);
    // Parse errors in the events file come first and stop the event checks.
    assert!(
        err.contains(&format!("error: {events}:4: bad time \"soon\"")),
        "{err}"
    );
    assert!(
        err.contains("error: --set T0=5s: T0 delay 5s is out of range"),
        "{err}"
    );
    assert!(
        err.contains("error: --set C0=100: counter set value 100 is out of range"),
        "{err}"
    );
    assert!(err.contains("error: --set clock=warp: bad clock"), "{err}");
    assert!(
        err.contains("error: --set bogus: expected NAME=VALUE"),
        "{err}"
    );
    assert!(err.contains("error: --until: bad time"), "{err}");
    assert!(err.lines().all(|l| l.starts_with("error: ")), "{err}");

    // With the events file parsing, each event is checked against the machine.
    let events = tmp.file("e2.csv", "1s,Y00,1\n2s,X00,5\n3s,X09,1\n");
    let out = hashigo(
        &[
            "run",
            "--machine",
            "minasec-u",
            "--program",
            &program,
            "--input",
            &events,
            "--until",
            "5s",
            "--watch",
            "Y00,Q7",
        ],
        "",
    );
    assert_eq!(out.status.code(), Some(2));
    let err = text(&out.stderr);
    assert!(
        err.contains("error: --watch: unknown device \"Q7\""),
        "{err}"
    );
    assert!(
        err.contains(&format!("error: {events}:1: Y00 is not an input")),
        "{err}"
    );
    assert!(
        err.contains(&format!("error: {events}:2: X00 is a bit")),
        "{err}"
    );
    assert!(
        err.contains(&format!("error: {events}:3: unknown device \"X09\"")),
        "{err}"
    );
}

#[test]
fn asm_prints_the_programming_sheet() {
    let out = hashigo(&["asm", "--machine", "minasec-u", "--program", "-"], SEED);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let sheet = text(&out.stdout);
    let lines: Vec<&str> = sheet.lines().collect();
    assert_eq!(lines.len(), 13);
    assert_eq!(lines[0], "000 LD X00 000 00000");
    assert_eq!(
        lines[1], "001 OR Y00 100 01000",
        "the seed's own example row"
    );
    assert_eq!(lines[12], "012 ST C0R 110 11111");
}

#[test]
fn bench_prints_steps_seconds_and_rate() {
    let out = hashigo(
        &[
            "bench",
            "--machine",
            "minasec-u",
            "--program",
            "-",
            "--steps",
            "100000",
        ],
        SEED,
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let line = text(&out.stdout);
    let fields: Vec<(&str, &str)> = line
        .trim()
        .split(' ')
        .filter_map(|f| f.split_once('='))
        .collect();
    assert_eq!(fields.len(), 3, "{line}");
    assert_eq!(fields[0], ("steps", "100000"));
    assert_eq!(fields[1].0, "seconds");
    assert!(fields[1].1.parse::<f64>().is_ok(), "{line}");
    assert_eq!(fields[2].0, "steps_per_second");
    assert!(fields[2].1.parse::<f64>().unwrap() > 0.0, "{line}");
    let bad = hashigo(
        &[
            "bench",
            "--machine",
            "minasec-u",
            "--program",
            "-",
            "--steps",
            "0",
        ],
        SEED,
    );
    assert_eq!(bad.status.code(), Some(2));
}

#[test]
fn unknown_machines_and_commands() {
    let out = hashigo(&["run", "--machine", "plc5", "--program", "-"], "");
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).starts_with("error: unknown machine \"plc5\""));
    let out = hashigo(&["frobnicate"], "");
    assert_eq!(out.status.code(), Some(2));
    // compile takes ladders only (its own tests: tests/ladder/cli.rs).
    let out = hashigo(
        &["compile", "--machine", "minasec-u", "--program", "x.il"],
        "",
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stderr).contains("takes a ladder"),
        "{}",
        text(&out.stderr)
    );
}

#[test]
fn the_readme_command_with_the_shipped_events_file() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/programs/minasec-u/");
    let (program, events) = (
        format!("{dir}seed-test.il"),
        format!("{dir}seed-test.events.csv"),
    );
    let out = hashigo(
        &[
            &["run", "--program", &program][..],
            &SEED_PANEL,
            &[
                "--input",
                &events,
                "--until",
                "30s",
                "--every",
                "3s",
                "--watch",
                "Y00,Y01,C0.v",
            ],
        ]
        .concat(),
        "",
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let csv = text(&out.stdout);
    assert!(
        csv.contains("\n21000,1,1,10\n"),
        "counted to 10 with Y01: {csv}"
    );
    assert!(
        csv.contains("\n27000,0,1,10\n"),
        "stop kept the count: {csv}"
    );
    assert!(csv.ends_with("\n30000,0,0,0\n"), "X02 cleared it: {csv}");
}
