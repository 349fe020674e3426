//! The ladder's autosave: the engine's versioned project JSON, one per
//! machine, written on every edit and read back on reload. A saved value
//! that does not read is kept aside and reported, never dropped.

use engine::formats::Project;
use engine::MachineId;
use leptos::prelude::*;

use crate::state::Ctx;
use crate::storage::{self, Checked, Restored};

/// Where `machine`'s ladder is saved.
pub fn key(machine: MachineId) -> String {
    format!("hashigo.ladder.{}.v1", machine.name())
}

/// A project as saved: read through the engine's own reader, so a saved
/// value is held to what a project file is held to.
#[derive(Clone, Debug)]
struct Saved(Project);

impl<'de> serde::Deserialize<'de> for Saved {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Saved, D::Error> {
        let value = serde_json::Value::deserialize(d)?;
        Project::from_json(&value.to_string())
            .map(Saved)
            .map_err(|e| serde::de::Error::custom(e.to_string()))
    }
}

impl Checked for Saved {
    fn problem(&self) -> Option<&'static str> {
        None
    }
}

/// Where the id of the project open in `machine`'s editor is kept.
fn open_key(machine: MachineId) -> String {
    format!("hashigo.open-project.{}", machine.name())
}

/// Where `machine`'s ladder is saved: the open project's key, or the
/// machine's own.
pub fn slot(machine: MachineId, project: Option<u64>) -> String {
    project.map_or_else(|| key(machine), crate::editor::projects::key_of)
}

/// Remembers which project `machine`'s editor has open.
pub fn remember_open(machine: MachineId, project: Option<u64>) {
    match project {
        Some(id) => storage::save_string(&open_key(machine), &id.to_string()),
        None => storage::remove(&open_key(machine)),
    }
}

/// The project open in `machine`'s editor when the page was left (if it
/// is still there) and the ladder to edit: that project's, else the
/// machine's own. A saved value that does not read (or is for another
/// machine) is kept aside and reported.
pub fn restore(page: Ctx, machine: MachineId) -> (Option<u64>, Option<Project>) {
    let open = storage::saved_string(&open_key(machine)).and_then(|s| s.parse::<u64>().ok());
    if let Some(id) = open {
        if let Some(ladder) = restore_from(page, machine, &crate::editor::projects::key_of(id)) {
            return (Some(id), Some(ladder));
        }
    }
    (None, restore_from(page, machine, &key(machine)))
}

fn restore_from(page: Ctx, machine: MachineId, key: &str) -> Option<Project> {
    match storage::restore_from::<Saved>(key) {
        Restored::Saved(Saved(project)) if project.machine == machine => Some(project),
        Restored::Saved(_) => None,
        Restored::Corrupt { kept_as } => {
            let texts = page.lang.get_untracked().texts();
            page.notice
                .set(Some(format!("{} {kept_as}", texts.corrupt_saved)));
            None
        }
        Restored::Nothing | Restored::Unavailable => None,
    }
}

/// Moves the ladder saved for `machine` aside under
/// `<key>.before-shared.<ms>` (before a shared ladder replaces it);
/// returns that key, or `None` when nothing was saved.
pub fn set_aside(machine: MachineId) -> Option<String> {
    let key = key(machine);
    let raw = storage::saved_string(&key)?;
    let aside = format!("{key}.before-shared.{}", js_sys::Date::now() as u64);
    storage::write(&aside, &raw).ok()?;
    Some(aside)
}
