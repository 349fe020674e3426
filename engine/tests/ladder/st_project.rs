//! A project's Structured Text (issue #55): kept in the project file
//! (version 5) and carried by a share link (`6.`), with the plant or
//! without; projects and links without one stay what they were (older
//! versions), and older ones still open.

use engine::formats::project::{PlantSetup, ProgramText, Project, ProjectError};
use engine::formats::share::{decode, encode, PREFIX, PREFIX_PLANT, PREFIX_PROGRAM};
use engine::ladder::{Element, Ladder, Rung};
use engine::MachineId;

const ST: &str = "FUNCTION_BLOCK Scale\nVAR_INPUT x : INT; END_VAR\nVAR_OUTPUT y : INT; END_VAR\ny := x * 2; (* 'quoted' \"and\" ü *)\nEND_FUNCTION_BLOCK\n";

fn ladder() -> Ladder {
    let mut rung = Rung::default();
    rung.set(engine::ladder::Pos::new(0, 0), Some(Element::no("%IX0.0")));
    rung.set(
        engine::ladder::Pos::new(0, 1),
        Some(Element::coil("%QX0.0")),
    );
    Ladder {
        rungs: vec![rung],
        ..Ladder::default()
    }
}

fn with_st() -> Project {
    let mut p = Project::new(MachineId::SoftPlc, ladder());
    p.program = Some(ProgramText::st(ST));
    p
}

#[test]
fn the_st_text_round_trips_through_the_project_file() {
    let p = with_st();
    let json = p.to_json();
    assert!(json.contains("\"version\": 5"), "{json}");
    assert!(json.contains("\"language\": \"st\""), "{json}");
    let back = Project::from_json(&json).expect("reads");
    assert_eq!(back.program, p.program);
    assert_eq!(back.ladder, p.ladder);
    // Without it: the version it was (1), which older Hashigos open.
    let plain = Project::new(MachineId::SoftPlc, ladder());
    assert!(plain.to_json().contains("\"version\": 1"));
    assert_eq!(
        Project::from_json(&plain.to_json()).expect("reads").program,
        None
    );
}

#[test]
fn an_older_project_file_still_opens_and_a_program_elsewhere_is_refused() {
    let v4 = r#"{"format": "hashigo-project", "version": 4, "machine": "soft-plc",
  "ladder": {"rungs": []}, "plant": {"name": "tank"}}"#;
    let p = Project::from_json(v4).expect("a version 4 project");
    assert_eq!(p.program, None);
    assert_eq!(p.plant.map(|p| p.name), Some("tank".to_string()));
    let io = r#"{"format": "hashigo-project", "version": 5, "machine": "io86a",
  "ladder": {"rungs": []},
  "program": {"language": "st", "text": "PROGRAM p END_PROGRAM"}}"#;
    let e = Project::from_json(io).expect_err("only the soft PLC");
    assert_eq!(e.line, 3);
    assert_eq!(e.error, ProjectError::ProgramOn(MachineId::Io86a));
    let il = io.replace("io86a", "soft-plc").replace("\"st\"", "\"il\"");
    let e = Project::from_json(&il).expect_err("no such language");
    assert!(e.error.to_string().contains("il"), "{}", e.error);
}

#[test]
fn a_share_link_carries_the_st_text_with_and_without_a_plant() {
    let p = with_st();
    let link = encode(&p).expect("encodes");
    assert!(link.starts_with(PREFIX_PROGRAM), "{link}");
    let back = decode(&link).expect("decodes");
    assert_eq!(back.program, p.program);
    assert_eq!(back.plant, None);
    assert_eq!(back.ladder, p.ladder);
    let mut planted = with_st();
    planted.plant = Some(PlantSetup {
        name: "tank".into(),
        ..PlantSetup::default()
    });
    let back = decode(&encode(&planted).expect("encodes")).expect("decodes");
    assert_eq!(back, planted);
}

#[test]
fn older_links_still_open_as_they_were() {
    let plain = Project::new(MachineId::SoftPlc, ladder());
    let link = encode(&plain).expect("encodes");
    assert!(link.starts_with(PREFIX), "{link}");
    assert_eq!(decode(&link).expect("a version 1 link").program, None);
    let mut planted = plain.clone();
    planted.plant = Some(PlantSetup {
        name: "tank".into(),
        ..PlantSetup::default()
    });
    let link = encode(&planted).expect("encodes");
    assert!(
        link.starts_with(PREFIX_PLANT),
        "a project with no ST keeps its 5. link"
    );
    let back = decode(&link).expect("a version 5 link");
    assert_eq!((back.plant, back.program), (planted.plant, None));
}

#[test]
fn a_damaged_program_section_is_an_error_never_a_panic() {
    let link = encode(&with_st()).expect("encodes");
    // Every cut of the link's data is refused (or reads), never a panic.
    for n in (PREFIX_PROGRAM.len() + 1)..link.len() {
        let _ = decode(&link[..n]);
    }
}
