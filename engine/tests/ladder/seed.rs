//! The seed's MINASEC-U test program drawn as a ladder compiles to a
//! program that behaves like the seed's own listing.

use engine::formats::Project;
use engine::headless::{run_csv as run, Schedule};
use engine::ladder::compile::{compile, Options};
use engine::machines::MinasecPlc;
use engine::minasec::Program;
use engine::plc::{Command, Plc};
use engine::{events, MachineId, SimTime};

const SEED_JSON: &str = include_str!("../../programs/minasec-u/seed-test.json");
const SEED_IL: &str = include_str!("../../programs/minasec-u/seed-test.il");
const EVENTS: &str = include_str!("../../programs/minasec-u/seed-test.events.csv");

fn run_program(program: &Program, settings: &[(String, String)]) -> String {
    let mut m = MinasecPlc::new();
    m.load_text(&program.to_text()).expect("loads");
    for (name, value) in settings {
        let setting = Command::Setting {
            name: name.clone(),
            value: value.clone(),
        };
        m.apply(setting).expect("seed setting");
    }
    let events = events::parse_events(EVENTS).expect("events");
    let watch: Vec<String> = ["X00", "Y00", "Y01", "T0", "T1", "C0.v"]
        .map(String::from)
        .to_vec();
    let schedule = Schedule {
        until: SimTime::from_secs(30),
        every: SimTime::from_millis(100),
    };
    run(&mut m, &events, schedule, &watch).expect("run")
}

#[test]
fn the_seed_ladder_compiles_to_a_program_that_behaves_like_the_seed() {
    let project = Project::from_json(SEED_JSON).expect("seed project");
    assert_eq!(project.machine, MachineId::MinasecU);
    let text = compile(&project.ladder, MachineId::MinasecU, Options::default()).expect("compiles");
    let compiled = Program::parse(&text).expect("the compiler's output parses");
    let seed = Program::parse(SEED_IL).expect("seed parses");
    let settings: Vec<(String, String)> = project.settings.clone().into_iter().collect();
    let ours = run_program(&compiled, &settings);
    let theirs = run_program(&seed, &settings);
    assert_eq!(ours, theirs, "compiled:\n{text}");
    // And the behaviour is the book's: the count reaches 10 and Y01 lights.
    let last = ours.lines().last().expect("rows");
    assert!(last.contains(",0,0,") || last.ends_with(",0"), "{last}");
    let at_25s = ours
        .lines()
        .find(|l| l.starts_with("25000,") || l.starts_with("25000.0,"))
        .unwrap_or_else(|| panic!("no 25 s row in\n{ours}"));
    assert!(at_25s.ends_with(",10"), "count 10 at 25 s: {at_25s}");
    // No temporary is needed: the parallel block goes first.
    assert!(!text.contains("M10"), "{text}");
}
