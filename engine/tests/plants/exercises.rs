//! An exercise per plant (issue #52): each of the six plants has a
//! project that holds its task in both languages, its plant and tests
//! that grade it. `hashigo test` passes the reference ladder the project
//! holds and fails the empty ladder a student starts from (the start
//! screen's links carry that empty form: app/src/start/gallery.rs).

use engine::formats::Project;
use engine::ladder::Ladder;

use super::common::{hashigo, text, Temp};

/// Each plant's exercise: the plant and its project in `engine/programs/`,
/// on MINASEC-U, the book's machine, whose bit inputs and outputs suffice.
/// The tank has a second on IO86A, on its analog level, which MINASEC-U
/// has not (the page's IO86A takes no project's settings, so its analog
/// mode: that one is for `hashigo test`).
const EXERCISES: [(&str, &str); 7] = [
    ("conveyor", "minasec-u/conveyor.json"),
    ("tank", "minasec-u/tank.json"),
    ("tank", "io86a/tank.json"),
    ("traffic", "minasec-u/traffic.json"),
    ("door", "minasec-u/door.json"),
    ("sorter", "minasec-u/sorter.json"),
    ("room-light", "minasec-u/room-light.json"),
];

fn project(path: &str) -> Project {
    let path = format!("{}/programs/{path}", env!("CARGO_MANIFEST_DIR"));
    let json = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    Project::from_json(&json).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// `hashigo test` of `project`: its exit status and output.
fn graded(tmp: &Temp, name: &str, project: &Project) -> (i32, String) {
    let file = tmp.file(name, &project.to_json());
    let out = hashigo(&["test", "--program", &file], "");
    (out.status.code().unwrap_or(-1), text(&out.stdout))
}

#[test]
fn every_plant_has_an_exercise_with_its_task_and_its_plant() {
    for (plant, path) in EXERCISES {
        let p = project(path);
        assert_eq!(p.plant.as_ref().map(|s| s.name.as_str()), Some(plant));
        let exercise = p.exercise.as_ref().unwrap_or_else(|| panic!("{path}"));
        assert!(!exercise.task.en.is_empty() && !exercise.task.ja.is_empty());
        assert!(p.tests.len() >= 2, "{path}");
        // No hidden faults: these are programming exercises.
        assert!(p.plant.as_ref().is_some_and(|s| s.faults.is_empty()));
    }
    // Each tank's task says why its machine: MINASEC-U has no analog input.
    for path in ["io86a/tank.json", "minasec-u/tank.json"] {
        let tank = project(path).exercise.expect("the tank's exercise");
        assert!(
            tank.task.en.contains("MINASEC-U has no analog input"),
            "{path}"
        );
        assert!(tank.task.ja.contains("アナログ入力がない"), "{path}");
    }
}

#[test]
fn each_exercise_passes_its_reference_ladder_and_fails_the_empty_one() {
    let tmp = Temp::new("plant-exercises");
    for (plant, path) in EXERCISES {
        let mut p = project(path);
        let name = format!("{plant}.json");
        let (code, out) = graded(&tmp, &name, &p);
        assert_eq!(code, 0, "{path}: {out}");
        assert!(out.ends_with(" passed, 0 failed\n"), "{path}: {out}");
        // The student's start: no rungs. Every test case grades the
        // plant's behaviour, so an empty ladder fails at least one.
        p.ladder = Ladder::default();
        let (code, out) = graded(&tmp, &name, &p);
        assert_eq!(code, 1, "{path}: {out}");
        assert!(out.contains("fail "), "{path}: {out}");
        assert!(out.contains(&format!("{plant}.")), "{path}: {out}");
    }
}
