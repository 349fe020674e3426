//! Ladder tests (issue #17): the expectation checker on hand-made
//! timelines, the seed program's cases, a mutated example, `hashigo test`
//! and its JUnit report, cases in share links.

#[path = "../common/mod.rs"]
mod common;

use engine::cases::{run_case, CaseError, Expectation, Outcome, TestCase};
use engine::formats::{share, Project};
use engine::machines::new_plc;
use engine::plc::Plc;
use engine::MachineId;

use common::{hashigo, text, Temp};

const SEED: &str = include_str!("../../programs/minasec-u/seed-test.json");

fn case(events: &str, expect: &[&str]) -> TestCase {
    TestCase {
        name: "case".into(),
        events: events.into(),
        expect: expect.iter().map(|s| s.to_string()).collect(),
        hint: String::new(),
    }
}

/// An IO86A with `program`, input filter off.
fn io86a(program: &str) -> Box<dyn Plc> {
    let mut plc = new_plc(MachineId::Io86a);
    plc.apply(engine::plc::Command::Setting {
        name: "filter".into(),
        value: "0".into(),
    })
    .expect("filter");
    plc.load_text(program).expect("program");
    plc
}

fn outcome(program: &str, c: &TestCase) -> Outcome {
    run_case(io86a(program).as_mut(), c).expect("runs")
}

const COPY: &str = "LD X00\nOUT Y00\nEND\n";

#[test]
fn an_expectation_at_an_event_time_sees_the_event() {
    // Scans run every millisecond; one at 5 ms runs after the event at 5 ms.
    let c = case("5ms,X00,1\n", &["Y00 = 0 at 4ms", "Y00 = 1 at 5ms"]);
    assert_eq!(outcome(COPY, &c), Outcome::Pass);
    let c = case("5ms,X00,1\n", &["Y00 = 1 at 4.999ms"]);
    assert_eq!(
        outcome(COPY, &c),
        Outcome::Fail {
            index: 0,
            expectation: "Y00 = 1 at 4.999ms".into(),
            observed: "Y00 was 0 at 4.999ms".into(),
            seen: engine::cases::Observed::Was {
                device: "Y00".into(),
                value: "0".into(),
                at: engine::SimTime::parse("4.999ms").expect("a time"),
            },
        }
    );
}

#[test]
fn a_one_scan_pulse_is_seen() {
    // PLS: M00 is on for exactly one scan after X00 rises.
    let pulse = "LD X00\nPLS M00\nLD M00\nOUT Y01\nEND\n";
    let c = case(
        "10ms,X00,1\n",
        &[
            "Y01 rises within 0ms..20ms",
            "Y01 falls within 0ms..20ms",
            "Y01 = 0 at 20ms",
        ],
    );
    assert_eq!(outcome(pulse, &c), Outcome::Pass);
    let c = case("", &["Y01 rises within 0ms..20ms"]);
    match outcome(pulse, &c) {
        Outcome::Fail { observed, .. } => assert_eq!(observed, "Y01 did not rise (it stayed 0)"),
        other => panic!("{other:?}"),
    }
}

#[test]
fn stays_checks_every_sample_and_reports_the_first_failing_expectation() {
    let c = case(
        "10ms,X00,1\n30ms,X00,0\n",
        &[
            "Y00 stays 1 from 10ms to 29ms",
            "Y00 stays 1 from 10ms to 31ms",
            "Y00 = 5 at 1ms",
        ],
    );
    match outcome(COPY, &c) {
        Outcome::Fail {
            index, observed, ..
        } => {
            assert_eq!(index, 1, "the first in the case's order");
            assert_eq!(observed, "Y00 was 0 at 30ms");
        }
        other => panic!("{other:?}"),
    }
    let c = case(
        "",
        &["D00 >= 0 at 1ms", "D00 < 1 at 1ms", "Y00 != 1 at 2ms"],
    );
    assert_eq!(outcome(COPY, &c), Outcome::Pass);
}

#[test]
fn bad_cases_say_where() {
    let mut plc = io86a(COPY);
    let err = |c: TestCase, plc: &mut Box<dyn Plc>| run_case(plc.as_mut(), &c).expect_err("bad");
    assert!(matches!(
        err(case("x", &[]), &mut plc),
        CaseError::Events(_)
    ));
    assert!(matches!(err(case("1ms,Y00,1\n", &[]), &mut plc), CaseError::Event(e) if e.line == 1));
    assert!(matches!(
        err(case("", &["Y00 = 1"]), &mut plc),
        CaseError::Expect(0, _)
    ));
    assert!(matches!(
        err(case("", &["Q9 = 1 at 1s"]), &mut plc),
        CaseError::Device(0, _)
    ));
    assert!(matches!(
        err(case("", &["Y00 stays 1 from 2s to 1s"]), &mut plc),
        CaseError::Expect(0, _)
    ));
    assert!(Expectation::parse("C0.v >= 5 at 20s").is_ok());
}

#[test]
fn the_seed_cases_pass_and_a_mutated_seed_fails_the_stop_case() {
    let tmp = Temp::new("cases-seed");
    let path = tmp.file("seed.json", SEED);
    let out = hashigo(&["test", "--program", &path], "");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let lines: Vec<String> = text(&out.stdout).lines().map(String::from).collect();
    assert_eq!(lines.len(), 6, "{lines:?}");
    assert!(
        lines[..5].iter().all(|l| l.starts_with("pass ")),
        "{lines:?}"
    );
    assert_eq!(lines[5], "5 passed, 0 failed");

    // The stop button wired to X03 instead of X01: only stopping breaks.
    let mutated = SEED.replacen(
        "\"nc\", \"device\": \"X01\"",
        "\"nc\", \"device\": \"X03\"",
        1,
    );
    assert_ne!(mutated, SEED);
    let path = tmp.file("mutated.json", &mutated);
    let junit = tmp.file("report.xml", "");
    let out = hashigo(&["test", "--program", &path, "--junit", &junit], "");
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    let failed: Vec<&str> = stdout.lines().filter(|l| l.starts_with("fail ")).collect();
    assert_eq!(failed.len(), 1, "{stdout}");
    assert!(
        failed[0].starts_with("fail stop keeps the count: Y00 falls within"),
        "{stdout}"
    );
    assert!(stdout.ends_with("4 passed, 1 failed\n"), "{stdout}");
    let report = std::fs::read_to_string(&junit).expect("report");
    assert!(report.contains("tests=\"5\" failures=\"1\""), "{report}");
    assert_eq!(report.matches("<failure ").count(), 1, "{report}");
}

#[test]
fn hashigo_test_refuses_bad_input() {
    let tmp = Temp::new("cases-bad");
    let project = Project::from_json(SEED).expect("seed");
    let mut bare = project.clone();
    bare.tests.clear();
    let path = tmp.file("bare.json", &bare.to_json());
    let out = hashigo(&["test", "--program", &path], "");
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("has no test cases"));
    let mut broken = project;
    broken.tests[0].expect.push("Y00 maybe".into());
    let path = tmp.file("broken.json", &broken.to_json());
    let out = hashigo(&["test", "--program", &path], "");
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty(), "no partial result");
    assert!(
        text(&out.stderr).contains("test \"start\": expectation 4:"),
        "{}",
        text(&out.stderr)
    );
}

#[test]
fn cases_and_the_exercise_flag_travel_in_share_links() {
    let mut project = Project::from_json(SEED).expect("seed");
    project.exercise = Some(Default::default());
    let link = share::encode(&project).expect("encodes");
    assert!(link.starts_with("2."), "{link:.10}");
    assert_eq!(share::decode(&link), Ok(project.clone()));
    // Without cases a link is what it always was.
    project.tests.clear();
    project.exercise = None;
    assert!(share::encode(&project).expect("encodes").starts_with("1."));
}

/// The other seeds' examples with their cases, and the case a mutation
/// (the first normally open contact made normally closed) must fail.
const EXAMPLES: &[(&str, &str, &str)] = &[
    (
        "io86a/timer.json",
        include_str!("../../programs/io86a/timer.json"),
        "X00 lights Y00",
    ),
    (
        "io86a/orb.json",
        include_str!("../../programs/io86a/orb.json"),
        "X00 and X01",
    ),
    (
        "io86a/push-on-off.json",
        include_str!("../../programs/io86a/push-on-off.json"),
        "each press toggles Y00",
    ),
    (
        "avr-plc/e-stop-timer.json",
        include_str!("../../programs/avr-plc/e-stop-timer.json"),
        "Run and Direct, then 1 s off-delay",
    ),
    (
        "avr-plc/self-hold.json",
        include_str!("../../programs/avr-plc/self-hold.json"),
        "INPUT1 and INPUT2 drive COIL1; COIL1 starts COIL2, which holds",
    ),
    (
        "arduino-plc/self-hold.json",
        include_str!("../../programs/arduino-plc/self-hold.json"),
        "start holds, stop drops",
    ),
];

#[test]
fn the_other_seeds_examples_pass_their_cases_and_a_mutation_fails_the_right_one() {
    let tmp = Temp::new("cases-examples");
    for (name, json, breaks) in EXAMPLES {
        let path = tmp.file("example.json", json);
        let out = hashigo(&["test", "--program", &path], "");
        let stdout = text(&out.stdout);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{name}: {stdout}{}",
            text(&out.stderr)
        );
        assert!(stdout.ends_with(" 0 failed\n"), "{name}: {stdout}");

        let at = json.find("\"kind\": \"no\"").expect("a NO contact");
        let mutated = format!("{}\"kind\": \"nc\"{}", &json[..at], &json[at + 12..]);
        let path = tmp.file("mutated.json", &mutated);
        let out = hashigo(&["test", "--program", &path], "");
        let stdout = text(&out.stdout);
        assert_eq!(out.status.code(), Some(1), "{name}: {stdout}");
        let failed: Vec<&str> = stdout.lines().filter(|l| l.starts_with("fail ")).collect();
        assert_eq!(failed.len(), 1, "{name}: {stdout}");
        assert!(
            failed[0].starts_with(&format!("fail {breaks}: ")),
            "{name}: {stdout}"
        );
    }
}
