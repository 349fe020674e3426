//! The project file: a versioned JSON document naming its machine, with
//! the ladder, its comments and the machine's settings.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use super::grid::Ladder;
use crate::error::Located;
use crate::MachineId;

/// The `format` field every project file carries.
pub const FORMAT: &str = "hashigo-project";
/// The newest project version this build reads and the one it writes.
pub const VERSION: u32 = 1;

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
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub settings: BTreeMap<String, String>,
    /// The ladder.
    pub ladder: Ladder,
}

impl Project {
    /// A project of `ladder` for `machine`, without settings.
    pub fn new(machine: MachineId, ladder: Ladder) -> Project {
        Project {
            format: FORMAT.to_string(),
            version: VERSION,
            machine,
            settings: BTreeMap::new(),
            ladder,
        }
    }

    /// Reads a project; errors name the line of the JSON text.
    pub fn from_json(text: &str) -> Result<Project, Located<String>> {
        let project: Project = serde_json::from_str(text)
            .map_err(|e| Located::new(e.line().max(1), format!("not a Hashigo project: {e}")))?;
        if project.format != FORMAT {
            return Err(Located::new(
                1,
                format!("\"format\" is \"{}\", not \"{FORMAT}\"", project.format),
            ));
        }
        if project.version == 0 || project.version > VERSION {
            return Err(Located::new(
                1,
                format!(
                    "project version {} is not one this Hashigo reads (1..={VERSION}): a newer Hashigo made it",
                    project.version
                ),
            ));
        }
        Ok(project)
    }

    /// The project as pretty JSON.
    pub fn to_json(&self) -> String {
        // Serialising plain data to a string cannot fail.
        serde_json::to_string_pretty(self).unwrap_or_default() + "\n"
    }
}
