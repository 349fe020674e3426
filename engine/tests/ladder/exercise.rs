//! Exercises (issue #49): the task, hidden tests and hints in the project
//! file and in `4.` links; older files (`"exercise": true`) and `2.`
//! links made before them still open.

use engine::formats::project::{Exercise, Task, TestsShown, MAX_TASK_BYTES};
use engine::formats::share::{decode, encode, ShareError};
use engine::formats::{Project, ProjectError};
use engine::MachineId;

/// A `2.` exercise link made by the `hashigo share` of commit 4f69933
/// (before exercises had a task): an empty MINASEC-U ladder, the case
/// "X00 lights Y00" (`0ms,X00,1`, `Y00 = 1 at 100ms`), `"exercise": true`.
const OLD_LINK: &str =
    "2.ATIAzf8AAAAAAQEOWDAwIGxpZ2h0cyBZMDAKMG1zLFgwMCwxCgEQWTAwID0gMSBhdCAxMDBtcw";

const NEW: &str = r#"{
  "format": "hashigo-project",
  "version": 3,
  "machine": "minasec-u",
  "ladder": {"rungs": []},
  "tests": [
    {"name": "X00 lights Y00", "events": "0ms,X00,1\n", "expect": ["Y00 = 1 at 100ms"],
     "hint": "Y00 should follow X00: one contact, one coil."}
  ],
  "exercise": {"task": {"en": "Light **Y00** while X00 is on.", "ja": "X00 が入っている間 Y00 を点ける。"}, "tests": "hidden"}
}"#;

#[test]
fn an_old_two_dot_exercise_link_still_opens() {
    let p = decode(OLD_LINK).expect("an old link opens");
    assert_eq!(p.machine, MachineId::MinasecU);
    assert_eq!(p.exercise, Some(Exercise::default()));
    assert_eq!(p.tests.len(), 1);
    assert_eq!(p.tests[0].name, "X00 lights Y00");
    assert_eq!(p.tests[0].expect, vec!["Y00 = 1 at 100ms".to_string()]);
    assert!(p.tests[0].hint.is_empty());
    // And it is made again byte for byte: a plain exercise stays `2.`.
    assert_eq!(encode(&p).expect("encodes"), OLD_LINK);
}

#[test]
fn an_old_exercise_flag_reads_and_is_written_back_as_it_was() {
    let old = r#"{"format": "hashigo-project", "version": 1, "machine": "io86a",
        "ladder": {"rungs": []}, "tests": [{"name": "a", "expect": []}], "exercise": true}"#;
    let p = Project::from_json(old).expect("reads");
    assert_eq!(p.exercise, Some(Exercise::default()));
    let json = p.to_json();
    assert!(json.contains("\"exercise\": true"), "{json}");
    assert!(json.contains("\"version\": 1"), "{json}");
    let off = old.replace("\"exercise\": true", "\"exercise\": false");
    assert_eq!(Project::from_json(&off).expect("reads").exercise, None);
}

#[test]
fn the_task_hidden_tests_and_hints_read_and_write_back() {
    let p = Project::from_json(NEW).expect("reads");
    let e = p.exercise.clone().expect("an exercise");
    assert_eq!(e.tests, TestsShown::Hidden);
    assert!(e.hidden());
    assert_eq!(e.task.en, "Light **Y00** while X00 is on.");
    assert_eq!(e.task.in_lang("ja"), "X00 が入っている間 Y00 を点ける。");
    assert_eq!(
        p.tests[0].hint,
        "Y00 should follow X00: one contact, one coil."
    );
    let json = p.to_json();
    assert!(json.contains("\"version\": 3"), "{json}");
    assert_eq!(Project::from_json(&json), Ok(p));
}

#[test]
fn a_task_in_one_language_is_shown_in_both() {
    let task = Task {
        en: "Only English.".into(),
        ja: String::new(),
    };
    assert_eq!(task.in_lang("ja"), "Only English.");
    assert_eq!(task.in_lang("en"), "Only English.");
}

#[test]
fn a_bad_exercise_is_refused_at_its_line() {
    let bad = NEW.replace("\"hidden\"", "\"secret\"");
    let e = Project::from_json(&bad).expect_err("refused");
    assert_eq!(e.line, 10, "{e}");
    assert!(e.to_string().contains("secret"), "{e}");
    assert!(matches!(e.error, ProjectError::Json(_)), "{e}");
    let long = NEW.replace(
        "Light **Y00** while X00 is on.",
        &"x".repeat(MAX_TASK_BYTES + 1),
    );
    let e = Project::from_json(&long).expect_err("refused");
    assert!(e.to_string().contains("longer than"), "{e}");
}

#[test]
fn a_version_3_project_is_newer_than_version_2_readers() {
    // A project with only a plain exercise stays readable by older builds.
    let mut p = Project::from_json(NEW).expect("reads");
    assert_eq!(p.needed_version(), 3);
    p.exercise = Some(Exercise::default());
    assert_eq!(p.needed_version(), 3, "the hint still needs version 3");
    p.tests[0].hint.clear();
    assert_eq!(p.needed_version(), 1);
}

#[test]
fn exercises_travel_in_four_dot_links() {
    let p = Project::from_json(NEW).expect("reads");
    let link = encode(&p).expect("encodes");
    assert!(link.starts_with("4."), "{link:.10}");
    // A link does not carry the file's version (a decoded project is 1).
    let mut p = p;
    p.version = 1;
    assert_eq!(decode(&link), Ok(p.clone()));
    // A hint without an exercise travels too.
    let mut hinted = p.clone();
    hinted.exercise = None;
    let link = encode(&hinted).expect("encodes");
    assert!(link.starts_with("4."), "{link:.10}");
    assert_eq!(decode(&link), Ok(hinted));
    // Without any, it is the link it always was.
    let mut plain = p;
    plain.exercise = Some(Exercise::default());
    plain.tests[0].hint.clear();
    assert!(encode(&plain).expect("encodes").starts_with("2."));
}

#[test]
fn a_cut_four_dot_link_says_where() {
    let p = Project::from_json(NEW).expect("reads");
    let link = encode(&p).expect("encodes");
    use base64::engine::general_purpose::URL_SAFE_NO_PAD;
    use base64::Engine as _;
    let packed = URL_SAFE_NO_PAD.decode(&link[2..]).expect("b64");
    let raw = miniz_oxide::inflate::decompress_to_vec(&packed).expect("inflate");
    for cut in [raw.len() - 1, raw.len() - 20] {
        let short = format!(
            "4.{}",
            URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(&raw[..cut], 6))
        );
        assert!(
            matches!(decode(&short), Err(ShareError::Data { .. })),
            "{:?}",
            decode(&short)
        );
    }
}
