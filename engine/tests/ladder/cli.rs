//! `hashigo compile` and `hashigo run --program x.json|x.xml` (cli.md).

use crate::common::{hashigo, text, Temp, SEED_PANEL};

const SEED_JSON: &str = include_str!("../../programs/minasec-u/seed-test.json");
const EVENTS: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/programs/minasec-u/seed-test.events.csv"
);
const SEED_IL: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/programs/minasec-u/seed-test.il"
);

fn run_args<'a>(program: &'a str, extra: &[&'a str]) -> Vec<&'a str> {
    let mut v = vec![
        "run",
        "--program",
        program,
        "--input",
        EVENTS,
        "--until",
        "30s",
        "--every",
        "500ms",
        "--watch",
        "Y00,Y01,T0,C0.v",
    ];
    v.extend_from_slice(extra);
    v
}

#[test]
fn compile_prints_a_program_that_run_takes_back() {
    let tmp = Temp::new("ladder-compile");
    let json = tmp.file("seed.json", SEED_JSON);
    let out = hashigo(&["compile", "--program", &json], "");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let il = text(&out.stdout);
    assert!(il.contains("ST   C0R"), "{il}");
    let compiled = tmp.file("compiled.il", &il);
    // The compiled text, the project itself and the seed's listing (with
    // the project's panel settings) all run the same.
    let a = hashigo(&run_args(&compiled, &SEED_PANEL), "");
    let b = hashigo(&run_args(&json, &[]), "");
    let c = hashigo(&run_args(SEED_IL, &SEED_PANEL), "");
    for o in [&a, &b, &c] {
        assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    }
    assert_eq!(text(&a.stdout), text(&c.stdout));
    assert_eq!(text(&b.stdout), text(&c.stdout));
    assert!(
        text(&b.stdout).contains("\n24500,1,1,0,10\n"),
        "{}",
        text(&b.stdout)
    );
}

#[test]
fn projects_read_from_standard_input_and_set_overrides_the_project() {
    let out = hashigo(
        &[
            "run",
            "--program",
            "-",
            "--format",
            "json",
            "--input",
            EVENTS,
            "--until",
            "30s",
            "--every",
            "25s",
            "--watch",
            "Y01,C0.v",
            "--set",
            "C0=3",
        ],
        SEED_JSON,
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(
        text(&out.stdout),
        "time_ms,Y01,C0.v\n0,0,0\n25000,1,3\n30000,0,0\n"
    );
}

#[test]
fn ladder_errors_name_the_file_rung_and_cell() {
    let bad = SEED_JSON.replace("\"X02\"},", "\"X09\"},");
    assert_ne!(bad, SEED_JSON);
    let out = hashigo(&["compile", "--program", "-", "--format", "json"], &bad);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(out.stdout, b"");
    assert_eq!(
        text(&out.stderr),
        "error: <stdin>: rung 5, row 1, column 1: unknown device \"X09\": MINASEC-U has X00-X07, Y00-Y07, M00-M07, M10-M13, T0, T1, C0, C0R\n"
    );
    // The same ladder for another machine: every foreign device is named.
    let out = hashigo(
        &[
            "compile",
            "--machine",
            "arduino-plc",
            "--program",
            "-",
            "--format",
            "json",
        ],
        SEED_JSON,
    );
    assert_eq!(out.status.code(), Some(2));
    let err = text(&out.stderr);
    assert!(
        err.contains("rung 1, row 1, column 1: unknown device \"X00\": arduino-plc has X000-X005"),
        "{err}"
    );
    // Broken JSON names its line; a newer version says so.
    let out = hashigo(
        &["compile", "--program", "-", "--format", "json"],
        "{\n\"format\": \"hashigo-project\",\n",
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stderr).starts_with("error: <stdin>:3: not a Hashigo project"),
        "{}",
        text(&out.stderr)
    );
    let newer = SEED_JSON.replace("\"version\": 1", "\"version\": 9");
    let out = hashigo(&["compile", "--program", "-", "--format", "json"], &newer);
    assert!(
        text(&out.stderr).contains("project version 9"),
        "{}",
        text(&out.stderr)
    );
    // A run with a bad ladder prints nothing on standard output.
    let out = hashigo(&run_args("-", &["--format", "json"]), &bad);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(out.stdout, b"");
}

#[test]
fn compile_refuses_listings_and_xml_needs_a_machine() {
    let out = hashigo(
        &["compile", "--machine", "minasec-u", "--program", SEED_IL],
        "",
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("takes a ladder"));
    let out = hashigo(
        &["compile", "--program", "-", "--format", "xml"],
        "<project/>",
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stderr).contains("give --machine"),
        "{}",
        text(&out.stderr)
    );
}
