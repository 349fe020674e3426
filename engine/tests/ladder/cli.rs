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

fn why(
    program: &str,
    events: &str,
    at: &str,
    device: &str,
    extra: &[&str],
) -> (i32, String, String) {
    let mut args = vec![
        "why",
        "--program",
        program,
        "--input",
        events,
        "--at",
        at,
        "--device",
        device,
    ];
    args.extend_from_slice(extra);
    let out = hashigo(&args, "");
    (
        out.status.code().unwrap_or(-1),
        text(&out.stdout),
        text(&out.stderr),
    )
}

#[test]
fn why_names_the_stop_button_that_turned_the_seeds_lamp_off() {
    let tmp = Temp::new("why-seed");
    let events = tmp.file("stop.csv", "0.5s,X00,1\n0.7s,X00,0\n3s,X01,1\n");
    let json = tmp.file("seed.json", SEED_JSON);
    // Running, then stopped: the NC X01 contact is what blocks Y00.
    let (code, before, err) = why(&json, &events, "2s", "Y00", &[]);
    assert_eq!(code, 0, "{err}");
    assert!(before.starts_with("Y00 = 1 at 2000 ms"), "{before}");
    assert!(
        before.contains("would lose power if any one of these changed"),
        "{before}"
    );
    assert!(before.contains("contact Y00; Y00 = 1"), "{before}");
    assert!(before.contains("driven by rung 1"), "{before}");
    let (code, after, err) = why(&json, &events, "4s", "Y00", &[]);
    assert_eq!(code, 0, "{err}");
    assert!(after.starts_with("Y00 = 0 at 4000 ms"), "{after}");
    assert!(after.contains("gets no power"), "{after}");
    let x01 = after
        .lines()
        .find(|l| l.contains("NC contact X01"))
        .unwrap_or_else(|| panic!("X01 named: {after}"));
    assert!(
        x01.contains("X01 = 1, since 30"),
        "changed at about 3 s: {x01}"
    );
    assert!(x01.contains("an input"), "{x01}");
    // The same program as text is explained through its ladder.
    let (code, text_out, err) = why(SEED_IL, &events, "4s", "Y00", &["--machine", "minasec-u"]);
    assert_eq!(code, 0, "{err}");
    assert!(text_out.contains("NC contact X01"), "{text_out}");
}

#[test]
fn why_follows_a_timer_upstream_and_refuses_an_unknown_device() {
    let tmp = Temp::new("why-timer");
    let program = concat!(env!("CARGO_MANIFEST_DIR"), "/programs/io86a/timer.il");
    let events = tmp.file("x00.csv", "100ms,X00,1\n");
    let io = ["--machine", "io86a"];
    // 1 s after X00: T00 (1.9 s) not yet up, so Y01 waits for it.
    let (code, out, err) = why(program, &events, "1100ms", "Y01", &io);
    assert_eq!(code, 0, "{err}");
    assert!(out.starts_with("Y01 = 0"), "{out}");
    let t00 = out
        .lines()
        .find(|l| l.contains("contact T00"))
        .unwrap_or_else(|| panic!("T00 named: {out}"));
    assert!(
        t00.contains("driven by rung"),
        "the timer coil's rung: {t00}"
    );
    let (code, out, err) = why(program, &events, "2500ms", "Y01", &io);
    assert_eq!(code, 0, "{err}");
    assert!(out.starts_with("Y01 = 1"), "{out}");
    let (code, out, err) = why(program, &events, "1s", "Q7", &io);
    assert_eq!(code, 2, "{out}");
    assert!(err.starts_with("error: --device: unknown device"), "{err}");
    assert!(out.is_empty());
}
