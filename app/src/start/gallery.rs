//! The example gallery's pictures (`web/start/gallery/<machine>-<id>.svg`):
//! each example drawn as the ladder's SVG picture is drawn. The files are
//! static, fetched only when the gallery shows; this test keeps them in
//! step with the examples and the drawing code, and writes them anew with
//! `HASHIGO_WRITE_PICTURES=1 cargo test -p app --lib gallery`.

use std::path::PathBuf;

use engine::examples::EXAMPLES;
use engine::ladder::decompile::decompile_text;
use engine::ladder::edit::{align_outputs, Editor, COLUMNS};

use crate::editor::model::{rung_data, RungData};
use crate::editor::picture;

/// The picture of example `id` of `machine` (at most its first eight
/// rungs: a thumbnail, not a listing).
fn picture_of(example: &engine::examples::Example) -> String {
    let ladder = decompile_text(example.machine, example.text, 10)
        .unwrap_or_else(|e| panic!("{} decompiles: {e}", example.id));
    let ladder = align_outputs(&ladder, COLUMNS - 1);
    let column = Editor::new(ladder.clone()).output_column();
    let data: Vec<RungData> = ladder
        .rungs
        .iter()
        .take(8)
        .map(|r| rung_data(r, column, &[], &ladder.device_comments))
        .collect();
    let refs: Vec<(usize, Option<usize>, &RungData)> =
        data.iter().enumerate().map(|(i, d)| (i, None, d)).collect();
    picture::svg(&refs)
}

fn folder() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../web/start/gallery")
}

/// The gallery's file name of an example.
pub fn file_name(example: &engine::examples::Example) -> String {
    format!("{}-{}.svg", example.machine.name(), example.id)
}

#[test]
fn every_example_has_its_current_picture() {
    let write = std::env::var_os("HASHIGO_WRITE_PICTURES").is_some();
    let mut stale = Vec::new();
    for example in EXAMPLES {
        let path = folder().join(file_name(example));
        let svg = picture_of(example);
        if write {
            std::fs::create_dir_all(folder()).expect("the gallery's folder");
            std::fs::write(&path, &svg).expect("the picture is written");
        } else if std::fs::read_to_string(&path).ok().as_deref() != Some(svg.as_str()) {
            stale.push(path.display().to_string());
        }
    }
    assert!(
        stale.is_empty(),
        "stale or missing (write them with HASHIGO_WRITE_PICTURES=1): {stale:?}"
    );
}

#[test]
fn the_start_screens_list_every_machine_and_example_in_both_languages() {
    let web = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../web");
    for lang in ["en", "ja"] {
        let page = std::fs::read_to_string(web.join(format!("start/{lang}.html")))
            .expect("the start screen's file");
        for testid in [
            "start-draw",
            "start-example",
            "start-open",
            "start-exercise",
        ] {
            assert!(
                page.contains(&format!("data-testid=\"{testid}\"")),
                "{lang}: {testid}"
            );
        }
        for machine in engine::MachineId::ALL {
            let card = format!("data-start=\"machine:{}\"", machine.name());
            assert!(page.contains(&card), "{lang}: {card}");
        }
        for example in EXAMPLES {
            let button = format!(
                "data-start=\"example:{}:{}\"",
                example.machine.name(),
                example.id
            );
            assert!(page.contains(&button), "{lang}: {button}");
            assert!(
                page.contains(&file_name(example)),
                "{lang}: {}",
                file_name(example)
            );
        }
        // Every picture it names is in web/.
        for src in page.split("src=\"").skip(1) {
            let path = src.split('"').next().unwrap_or_default();
            assert!(web.join(path).is_file(), "{lang}: {path} is missing");
        }
    }
}

/// Each plant's exercise (issue #52), as engine/tests/plants/exercises.rs
/// grades it: the plant and its project in `engine/programs/`.
const PLANT_EXERCISES: [(&str, &str); 6] = [
    ("conveyor", "minasec-u/conveyor.json"),
    ("tank", "minasec-u/tank.json"),
    ("traffic", "minasec-u/traffic.json"),
    ("door", "minasec-u/door.json"),
    ("sorter", "minasec-u/sorter.json"),
    ("room-light", "minasec-u/room-light.json"),
];

/// The share links of `page` marked `data-plant="<plant>"`, in order.
fn plant_links<'a>(page: &'a str, plant: &str) -> Vec<&'a str> {
    let mark = format!("data-plant=\"{plant}\"");
    page.split("<a href=\"./#")
        .skip(1)
        .filter(|a| a.split('>').next().is_some_and(|tag| tag.contains(&mark)))
        .filter_map(|a| a.split('"').next())
        .collect()
}

#[test]
fn each_plants_exercise_is_offered_twice_as_its_project_with_an_empty_ladder() {
    use engine::formats::{share, Project};
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
    for lang in ["en", "ja"] {
        let page = std::fs::read_to_string(root.join(format!("web/start/{lang}.html")))
            .expect("the start screen's file");
        for (plant, path) in PLANT_EXERCISES {
            let json = std::fs::read_to_string(root.join("engine/programs").join(path))
                .expect("the exercise's project");
            let mut project = Project::from_json(&json).expect("the project reads");
            // The student starts from no rungs; all else is the project's.
            project.ladder = Default::default();
            let links = plant_links(&page, plant);
            // In the exercises' list and in the gallery's plants.
            assert_eq!(links.len(), 2, "{lang}: {plant}");
            for link in links {
                let mut opened = share::decode(link).expect("the link decodes");
                // A link names no file version: the codec's own.
                opened.version = project.version;
                assert_eq!(opened, project, "{lang}: {plant}: remake the link");
            }
            let card = format!("data-testid=\"start-plant-{plant}\"");
            assert!(page.contains(&card), "{lang}: {card}");
            let picture = format!("start/img/plant-{plant}.svg");
            assert!(page.contains(&picture), "{lang}: {picture}");
        }
    }
}

/// The troubleshooting exercises (issue #52): the plant and the project,
/// which hands out its ladder as it is (the right ladder, misbehaving on
/// a hidden fault), so the link is the project itself.
const TROUBLESHOOTING: [(&str, &str); 1] = [("conveyor", "minasec-u/conveyor-fault.json")];

#[test]
fn each_troubleshooting_exercise_is_offered_in_the_exercises_and_the_gallery() {
    use engine::formats::{share, Project};
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
    for lang in ["en", "ja"] {
        let page = std::fs::read_to_string(root.join(format!("web/start/{lang}.html")))
            .expect("the start screen's file");
        for (plant, path) in TROUBLESHOOTING {
            let json = std::fs::read_to_string(root.join("engine/programs").join(path))
                .expect("the exercise's project");
            let project = Project::from_json(&json).expect("the project reads");
            assert!(!project.ladder.rungs.is_empty(), "{path}: its ladder");
            let mark = format!("data-trouble=\"{plant}\"");
            let links: Vec<&str> = page
                .split("<a href=\"./#")
                .skip(1)
                .filter(|a| a.split('>').next().is_some_and(|tag| tag.contains(&mark)))
                .filter_map(|a| a.split('"').next())
                .collect();
            // In the exercises' list and in the gallery's plants.
            assert_eq!(links.len(), 2, "{lang}: {plant}");
            for link in links {
                let mut opened = share::decode(link).expect("the link decodes");
                opened.version = project.version;
                assert_eq!(opened, project, "{lang}: {plant}: remake the link");
            }
            let card = format!("data-testid=\"start-plant-{plant}-fault\"");
            assert!(page.contains(&card), "{lang}: {card}");
        }
    }
}
