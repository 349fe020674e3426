//! The project file: a versioned JSON document naming its machine, with
//! the ladder, its comments and the machine's settings.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use crate::error::{shown, Located};
use crate::ladder::grid::Ladder;
use crate::limits::{MAX_EXPECTATIONS, MAX_INPUT_BYTES, MAX_RUNGS, MAX_TEST_CASES};
use crate::MachineId;

mod exercise;
mod plant;
mod program;
pub use exercise::{Exercise, Task, TestsShown, MAX_TASK_BYTES};
pub use plant::{PlantSetup, MAX_PLANT_LINES};
pub use program::{Language, ProgramText};

/// The `format` field every project file carries.
pub const FORMAT: &str = "hashigo-project";
/// The newest project version this build reads. A project is written as
/// version 1 unless it has the soft PLC's boxes or variables (version 2,
/// issue #30) or an exercise's task, hidden tests or hints (version 3,
/// issue #49) or a plant (version 4, issue #50) or a program text
/// (version 5, issue #55), so that older Hashigos open every project they
/// can.
pub const VERSION: u32 = 5;

/// A saved project.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Project {
    /// Always [`FORMAT`].
    pub format: String,
    /// The file's version (see [`VERSION`]).
    pub version: u32,
    /// The machine the ladder is for.
    pub machine: MachineId,
    /// Machine settings as `--set` takes them (`T0` = `1.1s`, `scan` = `10ms`).
    #[serde(
        default,
        skip_serializing_if = "BTreeMap::is_empty",
        deserialize_with = "crate::ladder::grid::each_name_once"
    )]
    pub settings: BTreeMap<String, String>,
    /// The ladder.
    pub ladder: Ladder,
    /// Test cases that travel with the ladder (docs/tests.md).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub tests: Vec<crate::cases::TestCase>,
    /// The tests are an exercise (its task, whether its tests are
    /// shown): a link opens with it shown and the ladder as its author
    /// left it. Older files say `"exercise": true`.
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        deserialize_with = "exercise::read",
        serialize_with = "exercise::write"
    )]
    pub exercise: Option<Exercise>,
    /// The plant the ladder controls, with its wiring, parameters and
    /// faults (docs/plants.md).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plant: Option<PlantSetup>,
    /// The soft PLC's Structured Text beside the ladder (issue #55).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub program: Option<ProgramText>,
}

impl Project {
    /// A project of `ladder` for `machine`, without settings.
    pub fn new(machine: MachineId, ladder: Ladder) -> Project {
        Project {
            format: FORMAT.to_string(),
            version: 1,
            machine,
            settings: BTreeMap::new(),
            ladder,
            tests: Vec::new(),
            exercise: None,
            plant: None,
            program: None,
        }
    }

    /// Reads a project; errors name the line of the JSON text. A leading
    /// byte-order mark (some Windows editors write one) is skipped.
    pub fn from_json(text: &str) -> Result<Project, Located<ProjectError>> {
        if text.len() > MAX_INPUT_BYTES {
            return Err(Located::new(1, ProjectError::TooLarge(text.len())));
        }
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let project: Project = serde_json::from_str(text).map_err(|e| {
            Located::new(
                e.line().max(1),
                ProjectError::Json(one_line(&e.to_string())),
            )
        })?;
        let at = |key: &str, e: ProjectError| Err(Located::new(key_line(text, key), e));
        if project.format != FORMAT {
            return at("format", ProjectError::Format(project.format));
        }
        if project.version == 0 {
            return at("version", ProjectError::VersionZero);
        }
        if project.version > VERSION {
            return at("version", ProjectError::Newer(project.version));
        }
        if project.ladder.rungs.len() > MAX_RUNGS {
            return at(
                "rungs",
                ProjectError::TooManyRungs(project.ladder.rungs.len()),
            );
        }
        if project.tests.len() > MAX_TEST_CASES {
            return at("tests", ProjectError::TooManyCases(project.tests.len()));
        }
        if let Some(case) = project
            .tests
            .iter()
            .find(|c| c.expect.len() > MAX_EXPECTATIONS)
        {
            return at(
                "expect",
                ProjectError::TooManyExpectations(shown(&case.name), case.expect.len()),
            );
        }
        if let Some(plant) = project
            .plant
            .as_ref()
            .filter(|p| p.lines() > MAX_PLANT_LINES)
        {
            return at("plant", ProjectError::TooManyPlantLines(plant.lines()));
        }
        if project.program.is_some() && project.machine != MachineId::SoftPlc {
            return at("program", ProjectError::ProgramOn(project.machine));
        }
        Ok(project)
    }

    /// The 1-based line of setting `name` in the project's JSON `text`
    /// (1 when it cannot be found), for errors about its value.
    pub fn setting_line(text: &str, name: &str) -> usize {
        let start = key_line(text, "settings");
        let key = format!("\"{name}\"");
        text.lines()
            .enumerate()
            .skip(start.saturating_sub(1))
            .find(|(_, l)| l.contains(&key))
            .map_or(start, |(i, _)| i + 1)
    }

    /// The project as pretty JSON, at the oldest version that holds it.
    pub fn to_json(&self) -> String {
        let mut out = self.clone();
        out.version = self.needed_version();
        // Serialising plain data to a string cannot fail.
        serde_json::to_string_pretty(&out).unwrap_or_default() + "\n"
    }

    /// The oldest version that holds the project: 5 with a program text;
    /// 4 with a plant; 3 with an exercise's
    /// task, hidden tests or a case's hint; 2 with the soft PLC's boxes or
    /// variables; else 1.
    pub fn needed_version(&self) -> u32 {
        if self.program.is_some() {
            return 5;
        }
        if self.plant.is_some() {
            return 4;
        }
        if self.exercise.as_ref().is_some_and(|e| !e.is_plain())
            || self.tests.iter().any(|c| !c.hint.is_empty())
        {
            return 3;
        }
        let words = !self.ladder.variables.is_empty()
            || self
                .ladder
                .rungs
                .iter()
                .any(|r| r.elements().any(|(_, e)| e.block().is_some()));
        if words {
            2
        } else {
            1
        }
    }
}

/// Why a text is not a project this build reads.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ProjectError {
    /// Larger than [`MAX_INPUT_BYTES`] (its size).
    TooLarge(usize),
    /// Not JSON of a project's shape (the parser's words, on one line).
    Json(String),
    /// The `format` field is not [`FORMAT`] (as written).
    Format(String),
    /// `"version": 0`.
    VersionZero,
    /// A version newer than [`VERSION`].
    Newer(u32),
    /// More rungs than [`MAX_RUNGS`] (how many).
    TooManyRungs(usize),
    /// More test cases than [`MAX_TEST_CASES`] (how many).
    TooManyCases(usize),
    /// A case (its name, shown) with more than [`MAX_EXPECTATIONS`].
    TooManyExpectations(String, usize),
    /// A plant with more wiring lines, parameters or faults than
    /// [`MAX_PLANT_LINES`] (how many).
    TooManyPlantLines(usize),
    /// A program text for a machine that runs none (only the soft PLC
    /// runs Structured Text).
    ProgramOn(MachineId),
}

impl std::fmt::Display for ProjectError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ProjectError::TooLarge(n) => write!(
                f,
                "the file is {n} bytes, more than the {MAX_INPUT_BYTES} a project may have (docs/limits.md)"
            ),
            ProjectError::Json(e) => write!(f, "not a Hashigo project: {e}"),
            ProjectError::Format(v) => {
                write!(f, "\"format\" is {}, not \"{FORMAT}\"", shown(v))
            }
            ProjectError::VersionZero => write!(
                f,
                "project version 0 does not exist: versions start at 1 (this Hashigo reads 1..={VERSION})"
            ),
            ProjectError::Newer(v) => write!(
                f,
                "project version {v} is newer than this Hashigo reads (1..={VERSION}): a newer Hashigo made it"
            ),
            ProjectError::TooManyRungs(n) => write!(
                f,
                "the ladder has {n} rungs, more than the {MAX_RUNGS} a ladder may have (docs/limits.md)"
            ),
            ProjectError::TooManyCases(n) => write!(
                f,
                "the project has {n} test cases, more than the {MAX_TEST_CASES} a project may have (docs/limits.md)"
            ),
            ProjectError::TooManyExpectations(name, n) => write!(
                f,
                "test {name} has {n} expectations, more than the {MAX_EXPECTATIONS} a case may have (docs/limits.md)"
            ),
            ProjectError::TooManyPlantLines(n) => write!(
                f,
                "the plant has {n} wiring lines, parameters or faults, more than the {MAX_PLANT_LINES} a project may have (docs/limits.md)"
            ),
            ProjectError::ProgramOn(m) => write!(
                f,
                "a project for {m} has a program text: only the soft PLC runs Structured Text"
            ),
        }
    }
}

impl std::error::Error for ProjectError {}

/// The 1-based line where `"key"` first appears in `text` (1 if nowhere):
/// the place to point at for an error about that field.
fn key_line(text: &str, key: &str) -> usize {
    let key = format!("\"{key}\"");
    text.lines()
        .position(|l| l.contains(&key))
        .map_or(1, |i| i + 1)
}

/// An error message on one line, shortened (serde repeats input in them).
fn one_line(message: &str) -> String {
    let flat: String = message
        .chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .take(300)
        .collect();
    flat
}
