//! The plant a project holds (issue #50, docs/plants.md): its name, its
//! wiring (none: the plant's default wiring for the machine), its
//! parameters and its faults, as the command line's options write them,
//! so that a teacher can hand out a faulty machine to troubleshoot. The
//! names are checked when the plant is attached, not when read.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

/// The most wiring lines, parameters or faults a project's plant holds.
pub const MAX_PLANT_LINES: usize = 256;

/// A project's plant.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlantSetup {
    /// The plant (`conveyor`).
    pub name: String,
    /// `SIGNAL`, `DEVICE` pairs; `None`: the default wiring.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub wiring: Option<Vec<[String; 2]>>,
    /// Parameters as `--set NAME.KEY=VALUE` gives them, by key.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub params: BTreeMap<String, String>,
    /// Faults as `--fault` gives them (`motor dead from 20s`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub faults: Vec<String>,
}

impl PlantSetup {
    /// The most lines of any of its lists (checked against
    /// [`MAX_PLANT_LINES`]).
    pub fn lines(&self) -> usize {
        let wiring = self.wiring.as_ref().map_or(0, Vec::len);
        wiring.max(self.params.len()).max(self.faults.len())
    }
}
