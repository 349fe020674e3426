//! Faults in the page (issue #52): the author's form writes what the
//! engine reads, refuses what it refuses, and a troubleshooting
//! exercise's hidden fault fails the correct ladder until the student
//! names it (then it is repaired for the cases).

use engine::formats::project::PlantSetup;
use engine::formats::Project;
use engine::plant::PlantError;

use super::faults::{add_fault, fault_text};
use crate::editor::panes::runner::{repaired, run_cases_with};
use crate::editor::state::CaseResult;

const TROUBLE: &str = include_str!("../../../engine/programs/minasec-u/conveyor-fault.json");
const CONVEYOR: &str = include_str!("../../../engine/programs/minasec-u/conveyor.il");

#[test]
fn the_form_writes_a_fault_as_the_engine_reads_it_or_says_why_not() {
    assert_eq!(
        fault_text("motor", "dead", "20", false),
        "motor dead from 20s"
    );
    assert_eq!(
        fault_text("infeed", "stuck 0", " ", true),
        "infeed stuck 0 hidden"
    );
    assert_eq!(
        fault_text("infeed", "stuck 1", "1.5", false),
        "infeed stuck 1 from 1.5s"
    );
    assert_eq!(
        fault_text("motor", "dead", "500ms", false),
        "motor dead from 500ms"
    );
    let mut setup = PlantSetup {
        name: "conveyor".into(),
        ..PlantSetup::default()
    };
    add_fault(&mut setup, fault_text("motor", "dead", "2", true)).unwrap();
    assert_eq!(setup.faults, vec!["motor dead from 2s hidden".to_string()]);
    let e = add_fault(&mut setup, fault_text("infeed", "dead", "", false)).unwrap_err();
    assert_eq!(e, PlantError::DeadSensor("conveyor.infeed".into()));
    let e = add_fault(&mut setup, fault_text("motor", "stuck 1", "soon", false)).unwrap_err();
    assert!(
        matches!(&e, PlantError::FaultTime(t, _) if t == "soon"),
        "{e:?}"
    );
    // Refused: the setup is left as it was.
    assert_eq!(setup.faults.len(), 1);
}

fn grade(named: Option<&str>) -> (Vec<CaseResult>, Option<bool>) {
    let project = Project::from_json(TROUBLE).unwrap();
    let settings: Vec<_> = project.settings.clone().into_iter().collect();
    let (plant, right) = repaired(project.plant.clone().unwrap(), named);
    let results = run_cases_with(
        engine::MachineId::MinasecU,
        &settings,
        CONVEYOR,
        &project.tests,
        Some(&plant),
    );
    (results, right)
}

#[test]
fn a_hidden_fault_fails_the_right_ladder_until_it_is_named() {
    let all_pass = |r: &[CaseResult]| r.iter().all(|r| matches!(r, CaseResult::Pass));
    let (results, right) = grade(None);
    assert_eq!(right, Some(false));
    assert!(!all_pass(&results), "{results:?}");
    // The wrong signal, or the right signal with the wrong kind: not it.
    for wrong in [
        "outfeed stuck 0",
        "infeed stuck 1",
        "motor dead",
        "infeed",
        "nonsense",
    ] {
        let (results, right) = grade(Some(wrong));
        assert_eq!(right, Some(false), "{wrong}");
        assert!(!all_pass(&results), "{wrong}: {results:?}");
    }
    // Named (with the plant's name, as the engine allows): repaired.
    for named in ["infeed stuck 0", "conveyor.infeed stuck 0"] {
        let (results, right) = grade(Some(named));
        assert_eq!(right, Some(true), "{named}");
        assert!(all_pass(&results), "{named}: {results:?}");
    }
}

#[test]
fn a_fault_not_hidden_is_not_graded_nor_repaired() {
    let setup = PlantSetup {
        name: "conveyor".into(),
        faults: vec!["infeed stuck 0".into()],
        ..PlantSetup::default()
    };
    let (after, right) = repaired(setup.clone(), Some("infeed stuck 0"));
    assert_eq!((after, right), (setup, None));
}

#[test]
fn by_hand_the_belt_moves_with_the_machine_stopped_and_run_keeps_it() {
    use super::rig;
    use engine::machines::MinasecPlc;
    use engine::plc::Plc;
    use engine::record::Recorded;
    use engine::SimTime;
    let mut m = Recorded::new(MinasecPlc::new());
    m.load_text(CONVEYOR).unwrap();
    let setup = PlantSetup {
        name: "conveyor".into(),
        ..PlantSetup::default()
    };
    let mut rig = rig::build(&setup, &mut m).unwrap();
    let leads = |rig: &dyn super::Rig, m: &dyn Plc| rig.show(m).figure[2..].to_vec();
    // Parts arrive on the plant's own clock; the motor off: they stay.
    rig.jog(&mut m, &[false, false, false], 3000);
    let placed = leads(rig.as_ref(), &m);
    assert!(!placed.is_empty(), "a part was placed");
    rig.jog(&mut m, &[false, false, false], 500);
    assert_eq!(leads(rig.as_ref(), &m), placed);
    // The motor (the third signal) on by hand: the belt moves, the
    // machine's time does not, the infeed eye reached its input.
    rig.jog(&mut m, &[false, false, true], 500);
    let moved = leads(rig.as_ref(), &m);
    assert!(moved[0] > placed[0], "{placed:?} -> {moved:?}");
    assert_eq!(m.now(), SimTime::ZERO);
    let shown = rig.show(&m);
    assert_eq!(shown.signals[2].value, 1, "the motor shown on");
    // Run: the plant goes on from where it stood (the ladder holds the
    // motor off until T1, so the parts stay where the hand left them).
    rig.advance(&mut m, SimTime::from_millis(10));
    assert_eq!(leads(rig.as_ref(), &m)[0], moved[0]);
    assert_eq!(
        rig.show(&m).signals[2].value,
        0,
        "the machine drives it again"
    );
}

/// The book's ladder on MINASEC-U (T1 one second) with the conveyor
/// coupled by its default wiring, at power-on.
fn books_conveyor() -> (
    engine::record::Recorded<engine::machines::MinasecPlc>,
    Box<dyn super::Rig>,
) {
    use engine::plc::{Command, Plc};
    let mut m = engine::record::Recorded::new(engine::machines::MinasecPlc::new());
    m.load_text(CONVEYOR).unwrap();
    let t1 = Command::Setting {
        name: "T1".into(),
        value: "1s".into(),
    };
    m.apply(t1).unwrap();
    let setup = PlantSetup {
        name: "conveyor".into(),
        ..PlantSetup::default()
    };
    let rig = super::rig::build(&setup, &mut m).unwrap();
    (m, rig)
}

#[test]
fn the_plant_at_a_past_scan_is_as_it_was_then() {
    use engine::plc::Plc;
    use engine::SimTime;
    let (mut m, mut rig) = books_conveyor();
    let mut then = Vec::new();
    for i in 1..=900 {
        rig.advance(&mut m, SimTime::from_millis(100));
        if i % 97 == 0 {
            let mut shown = rig.show(&m);
            shown.running = false;
            then.push((m.now(), shown));
        }
    }
    let delivered = |s: &super::Shown| s.quantities.iter().find(|q| q.0 == "delivered").unwrap().1;
    assert!(delivered(&rig.show(&m)) > delivered(&then[0].1));
    for (at, shown) in &then {
        assert_eq!(&rig.show_at(*at), shown, "at {at:?}");
    }
}

#[test]
fn resuming_from_a_past_scan_puts_the_plant_back_as_it_was_there() {
    use engine::plc::Plc;
    use engine::record::TimeTravel;
    use engine::SimTime;
    let (mut m, mut rig) = books_conveyor();
    for _ in 0..300 {
        rig.advance(&mut m, SimTime::from_millis(100));
    }
    let (_, last) = TimeTravel::marks(&m);
    assert!(m.show(last / 3));
    let at = TimeTravel::plc(&m).now();
    let then = rig.show_at(at);
    assert!(m.resume_here());
    assert_eq!(m.now(), at);
    rig.advance(&mut m, SimTime::ZERO);
    let mut now = rig.show(&m);
    now.running = false;
    assert_eq!(now.figure, then.figure);
    assert_eq!(now.quantities, then.quantities);
    assert!(now
        .alarms
        .iter()
        .all(|(t, _)| *t <= at.as_nanos() as i64 / 1_000_000));
}
