//! `hashigo` on hostile input: exit 2 with one short line per problem,
//! never a panic, an abort or a hang.

use crate::common::{hashigo, text, Temp};

const SEED: &str = include_str!("../../programs/minasec-u/seed-test.json");
const IO86A: &str = "LD X00\nOUT Y00\nEND\n";

fn fails_with(args: &[&str], stdin: &str) -> Vec<String> {
    let out = hashigo(args, stdin);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stderr));
    assert!(
        out.stdout.is_empty(),
        "no partial output: {}",
        text(&out.stdout)
    );
    text(&out.stderr).lines().map(String::from).collect()
}

#[test]
fn the_csv_cap_counts_columns() {
    let tmp = Temp::new("hostile-csv");
    let p = tmp.file("p.il", IO86A);
    let watch = vec!["Y00"; 200].join(",");
    let lines = fails_with(
        &[
            "run",
            "--machine",
            "io86a",
            "--program",
            &p,
            "--until",
            "10000s",
            "--every",
            "1ms",
            "--watch",
            &watch,
        ],
        "",
    );
    assert_eq!(
        lines,
        ["error: --every is so small that the run would print more than 50000000 values (rows × watched devices; docs/limits.md)"]
    );
}

#[test]
fn long_runs_stream_their_rows() {
    let tmp = Temp::new("hostile-stream");
    let p = tmp.file("p.il", IO86A);
    let out = hashigo(
        &[
            "run",
            "--machine",
            "io86a",
            "--program",
            &p,
            "--until",
            "20s",
            "--every",
            "1ms",
            "--watch",
            "Y00,X00",
        ],
        "",
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let csv = text(&out.stdout);
    assert_eq!(csv.lines().count(), 1 + 20_001);
    assert!(csv.ends_with("\n20000,0,0\n"));
}

#[test]
fn a_console_step_past_the_clock_limit_is_refused() {
    let lines = fails_with(
        &["console", "--machine", "io86a", "--step", "10000000000s"],
        "R\nY?\n",
    );
    assert_eq!(lines.len(), 1);
    assert!(
        lines[0].contains("--step: time \"10000000000s\" is past the simulated clock's limit"),
        "{lines:?}"
    );
}

#[test]
fn settings_after_a_bad_avr_program_are_checked_against_the_avr() {
    let tmp = Temp::new("hostile-avr-set");
    let p = tmp.file("bad.asm", ".db Bogus,0,0,0\n");
    let lines = fails_with(
        &[
            "run",
            "--machine",
            "avr-plc",
            "--program",
            &p,
            "--set",
            "filter=3",
            "--until",
            "1s",
            "--watch",
            "R4.2",
        ],
        "",
    );
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(
        lines[0].ends_with("bad.asm:1: unknown symbol \"Bogus\""),
        "{lines:?}"
    );
    assert_eq!(
        lines[1],
        "error: --set filter=3: unknown setting \"filter\": avr-plc takes scan"
    );
}

#[test]
fn a_zero_avr_scan_is_one_error() {
    let tmp = Temp::new("hostile-avr-scan");
    let p = tmp.file("p.asm", ".db Load_A,4,Bit0,0\n.db Coil_A,5,Bit0,0\n.db TON,0,LOW(1000/Scan),HIGH(1000/Scan)\n.db End_PLC,0,0,0\n");
    let lines = fails_with(
        &[
            "run",
            "--machine",
            "avr-plc",
            "--program",
            &p,
            "--set",
            "scan=0",
            "--until",
            "1s",
            "--watch",
            "R5.0",
        ],
        "",
    );
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(
            "error: --set scan=0: the AVR PLC's scan period is a whole number of milliseconds"
        ),
        "{lines:?}"
    );
    let lines = fails_with(
        &[
            "compile",
            "--machine",
            "avr-plc",
            "--program",
            "-",
            "--format",
            "json",
            "--set",
            "scan=1500us",
        ],
        &SEED.replace("minasec-u", "avr-plc"),
    );
    assert!(
        lines[0].starts_with("error: --set scan=1500us: the AVR PLC's scan period"),
        "{lines:?}"
    );
}

#[test]
fn program_and_events_cannot_both_be_standard_input() {
    let lines = fails_with(
        &[
            "run",
            "--machine",
            "io86a",
            "--program",
            "-",
            "--input",
            "-",
            "--until",
            "1s",
            "--watch",
            "Y00",
        ],
        IO86A,
    );
    assert_eq!(
        lines,
        ["error: --program - and --input - both read standard input: give one of them as a file"]
    );
}

#[test]
fn not_utf8_is_reported_at_its_line() {
    let path = std::env::temp_dir().join(format!("hashigo-notutf8-{}.il", std::process::id()));
    std::fs::write(&path, b"LD X00\nOUT Y00\n\xff\xfeEND\n").expect("write");
    let p = path.to_string_lossy().into_owned();
    let lines = fails_with(&["asm", "--machine", "io86a", "--program", &p], "");
    let _ = std::fs::remove_file(&path);
    assert_eq!(
        lines,
        [format!(
            "error: {p}:3: not UTF-8 text: byte 0xff at column 1 (byte offset 15)"
        )]
    );
}

#[test]
fn echoed_bytes_are_escaped_and_cut() {
    let tmp = Temp::new("hostile-echo");
    let p = tmp.file("esc.il", "LD X00\u{1b}[31m\u{0}\nOUT Y00\nEND\n");
    let lines = fails_with(&["asm", "--machine", "io86a", "--program", &p], "");
    assert!(
        lines[0].contains(r#"unknown device "X00\u{1b}[31m\u{0}""#),
        "{lines:?}"
    );
    let long = tmp.file(
        "long.il",
        &format!("LD X{}\nOUT Y00\nEND\n", "0".repeat(1 << 20)),
    );
    let lines = fails_with(&["asm", "--machine", "io86a", "--program", &long], "");
    assert!(
        lines.iter().all(|l| l.len() < 300),
        "{:.400}",
        lines.join("\n")
    );
    let lines = fails_with(
        &[
            "run",
            "--machine",
            "io86a",
            "--program",
            &p,
            "--until",
            "1",
            "--watch",
            "Y0\n1",
        ],
        "",
    );
    assert!(
        lines.iter().all(|l| l.starts_with("error: ")),
        "one line per problem: {lines:?}"
    );
}

#[test]
fn a_project_setting_error_names_its_line() {
    let tmp = Temp::new("hostile-setting");
    let p = tmp.file(
        "seed.json",
        &SEED.replace("\"T0\": \"1.1s\"", "\"T0\": \"9s\""),
    );
    let lines = fails_with(
        &["run", "--program", &p, "--until", "1s", "--watch", "Y00"],
        "",
    );
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(&format!("error: {p}:5: setting T0=9s: ")),
        "{lines:?}"
    );
}

#[test]
fn compile_checks_its_settings_against_the_machine() {
    let tmp = Temp::new("hostile-compile-set");
    let p = tmp.file("seed.json", SEED);
    let lines = fails_with(&["compile", "--program", &p, "--set", "filter=3"], "");
    assert_eq!(
        lines,
        ["error: --set filter=3: unknown setting \"filter\": minasec-u takes T0, T1, C0 and clock"]
    );
}
