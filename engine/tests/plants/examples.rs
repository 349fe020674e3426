//! The plants' examples: the book's conveyor on MINASEC-U (an exercise
//! with its task in English and Japanese), the same ladder on IO86A and
//! the soft PLC, the tank's level control on IO86A and the soft PLC, and
//! the exercises of issue #51 (every project with a plant is run).

use engine::formats::Project;
use engine::ladder::decompile::decompile_text;
use engine::MachineId;

use super::common::{hashigo, text, Temp};

const PROGRAMS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/programs");

fn program(path: &str) -> String {
    format!("{PROGRAMS}/{path}")
}

fn run(args: &[&str]) -> (i32, String, String) {
    let out = hashigo(args, "");
    (
        out.status.code().unwrap_or(-1),
        text(&out.stdout),
        text(&out.stderr),
    )
}

/// Every project in `engine/programs/` that holds a plant, by path.
fn projects_with_a_plant() -> Vec<String> {
    let mut found = Vec::new();
    for dir in std::fs::read_dir(PROGRAMS).unwrap() {
        let dir = dir.unwrap().path();
        for file in std::fs::read_dir(&dir).unwrap() {
            let path = file.unwrap().path();
            if path.extension().is_some_and(|e| e == "json") {
                let json = std::fs::read_to_string(&path).unwrap();
                if Project::from_json(&json).unwrap().plant.is_some() {
                    found.push(path.display().to_string());
                }
            }
        }
    }
    found.sort();
    found
}

/// Whether the project at `path` has a fault hidden from the student.
fn hides_a_fault(path: &str) -> bool {
    let json = std::fs::read_to_string(path).unwrap();
    let plant = Project::from_json(&json).unwrap().plant.unwrap_or_default();
    plant.faults.iter().any(|f| f.ends_with(" hidden"))
}

#[test]
fn each_reference_ladder_passes_its_tests_with_its_own_plant_on_every_machine() {
    let projects = projects_with_a_plant();
    // conveyor, tank x2, and the issue #51 exercises: four plants on
    // MINASEC-U, IO86A, the soft PLC and the AVR PLC, three on the
    // Arduino sketch (no timers: no traffic), the troubleshooting sorter.
    assert!(projects.len() >= 23, "{projects:?}");
    for plant in ["traffic", "door", "sorter", "room-light"] {
        for machine in ["minasec-u", "io86a", "soft-plc", "avr-plc"] {
            let path = program(&format!("{machine}/{plant}.json"));
            assert!(projects.contains(&path), "{path}");
        }
    }
    for path in &projects {
        // The project's own plant, wiring, parameters and faults.
        let (code, out, err) = run(&["test", "--program", path]);
        if hides_a_fault(path) {
            // A troubleshooting exercise: its right ladder fails until the
            // student names the hidden fault (the page repairs it then).
            assert_eq!((code, err.as_str()), (1, ""), "{path}: {out}");
            assert!(out.starts_with("fail "), "{path}: {out}");
            continue;
        }
        assert_eq!((code, err.as_str()), (0, ""), "{path}: {out}");
        assert!(out.ends_with(" passed, 0 failed\n"), "{path}: {out}");
        assert!(!out.starts_with("0 passed"), "{path}: {out}");
    }
}

#[test]
fn each_new_exercise_has_its_task_in_english_and_japanese() {
    for path in projects_with_a_plant() {
        let json = std::fs::read_to_string(&path).unwrap();
        let project = Project::from_json(&json).unwrap();
        let Some(exercise) = project.exercise else {
            continue;
        };
        let name = project.plant.map(|p| p.name).unwrap_or_default();
        assert!(exercise.task.en.contains(&format!("`{name}`")), "{path}");
        assert!(exercise.task.ja.contains(&format!("`{name}`")), "{path}");
        assert!(exercise.task.ja.contains("プラント"), "{path}");
    }
}

#[test]
fn the_troubleshooting_sorter_holds_its_fault_and_fails_the_ladder_that_trusted_the_switch() {
    let json = std::fs::read_to_string(program("minasec-u/sorter-fault.json")).unwrap();
    let mut project = Project::from_json(&json).unwrap();
    let task = &project.exercise.as_ref().expect("an exercise").task;
    assert!(task.en.contains("find which device is broken") && task.ja.contains("故障"));
    let sorter = std::fs::read_to_string(program("minasec-u/sorter.il")).unwrap();
    project.ladder = decompile_text(MachineId::MinasecU, &sorter, 10).unwrap();
    let tmp = Temp::new("plant-trouble");
    let trusting = tmp.file("trusting.json", &project.to_json());
    // No --plant: the project's own plant, with its fault.
    let (code, out, _) = run(&["test", "--program", &trusting]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("pass the broken switch is found"), "{out}");
    assert!(
        out.contains("fail sorts for two minutes with no hit: sorter.right >= 20"),
        "{out}"
    );
    // Without the fault the same ladder sorts: the fault is what breaks it.
    project.plant.as_mut().expect("a plant").faults.clear();
    let repaired = tmp.file("repaired.json", &project.to_json());
    let (_, out, _) = run(&["test", "--program", &repaired]);
    assert!(
        out.contains("pass sorts for two minutes with no hit"),
        "{out}"
    );
}

#[test]
fn the_conveyor_exercise_has_its_task_in_both_languages_and_fails_a_belt_started_at_once() {
    let json = std::fs::read_to_string(program("minasec-u/conveyor.json")).unwrap();
    let mut project = Project::from_json(&json).unwrap();
    let task = &project.exercise.as_ref().expect("an exercise").task;
    assert!(task.en.contains("one second later") && task.ja.contains("1秒後"));
    project.ladder = decompile_text(MachineId::MinasecU, "LD X00\nOR Y00\nST Y00\n", 10).unwrap();
    let tmp = Temp::new("plant-exercise");
    let wrong = tmp.file("wrong.json", &project.to_json());
    let (code, out, _) = run(&["test", "--program", &wrong, "--plant", "conveyor"]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("fail waits one second before starting: conveyor.motor = 0 at 1000ms: conveyor.motor was 1"), "{out}");
    assert!(out.contains("fail delivers parts for a minute: conveyor.alarms = 0 at 60000ms: conveyor.alarms was 1"), "{out}");
}

#[test]
fn the_reference_conveyor_delivers_as_many_parts_on_each_machine() {
    let delivered = |machine: &str, settings: &[&str]| {
        let path = program(&format!("{machine}/conveyor.il"));
        let args = [
            &[
                "run",
                "--machine",
                machine,
                "--program",
                &path,
                "--plant",
                "conveyor",
            ][..],
            settings,
            &[
                "--until",
                "60s",
                "--watch",
                "conveyor.delivered,conveyor.alarms",
            ],
        ]
        .concat();
        let (code, out, err) = run(&args);
        assert_eq!(code, 0, "{machine}: {err}");
        let last = out.lines().last().unwrap_or_default().to_string();
        let fields: Vec<i64> = last.split(',').map(|f| f.parse().unwrap()).collect();
        assert_eq!(fields[2], 0, "{machine}: no alarm");
        fields[1]
    };
    let minasec = delivered("minasec-u", &["--set", "T1=1s"]);
    assert!(minasec >= 8, "{minasec}");
    for (machine, n) in [
        ("io86a", delivered("io86a", &[])),
        ("soft-plc", delivered("soft-plc", &[])),
    ] {
        assert!(
            (n - minasec).abs() <= 1,
            "{machine} delivered {n}, MINASEC-U {minasec}"
        );
    }
}

#[test]
fn why_names_the_plant_signal_behind_an_input() {
    let (code, out, err) = run(&[
        "why",
        "--machine",
        "minasec-u",
        "--program",
        &program("minasec-u/conveyor.il"),
        "--set",
        "T1=1s",
        "--plant",
        "conveyor",
        "--at",
        "2s",
        "--device",
        "Y00",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("plant: X00 is conveyor.infeed (the PLC reads it)"),
        "{out}"
    );
    assert!(
        out.contains("plant: Y00 drives conveyor.motor (the PLC drives it)"),
        "{out}"
    );
}
