//! The ladder's autosave: the engine's versioned project JSON, one per
//! machine, written on every edit and read back on reload. A saved value
//! that does not read is kept aside and reported, never dropped.

use engine::formats::Project;
use engine::MachineId;
use leptos::prelude::*;

use crate::state::Ctx;
use crate::storage::{self, Restored};

/// Where `machine`'s ladder is saved.
pub fn key(machine: MachineId) -> String {
    format!("hashigo.ladder.{}.v1", machine.name())
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
/// machine) is kept aside and reported. The texts were read before the
/// page started ([`saved_texts`], `reading::read_saved`).
pub fn restore(page: Ctx, machine: MachineId) -> (Option<u64>, Option<Project>) {
    if let Some(id) = open_project(machine) {
        if let Some(ladder) = restore_from(page, machine, &crate::editor::projects::key_of(id)) {
            return (Some(id), Some(ladder));
        }
    }
    (None, restore_from(page, machine, &key(machine)))
}

/// The id of the project open in `machine`'s editor when the page was left.
fn open_project(machine: MachineId) -> Option<u64> {
    storage::saved_string(&open_key(machine)).and_then(|s| s.parse::<u64>().ok())
}

/// Every saved text [`restore`] may read (key, text): what is read
/// before the page starts.
pub fn saved_texts() -> Vec<(String, String)> {
    MachineId::ALL
        .iter()
        .flat_map(|&m| {
            let project = open_project(m).map(crate::editor::projects::key_of);
            project.into_iter().chain(std::iter::once(key(m)))
        })
        .filter_map(|key| storage::saved_string(&key).map(|text| (key, text)))
        .collect()
}

fn restore_from(page: Ctx, machine: MachineId, key: &str) -> Option<Project> {
    let restored = match super::reading::take(key) {
        Some(Some(project)) => Restored::Saved(project),
        Some(None) => match storage::saved_string(key) {
            Some(raw) => storage::keep_aside(key, &raw),
            None => Restored::Nothing,
        },
        // Not read before the page started: nothing was saved there.
        None => Restored::Nothing,
    };
    match restored {
        Restored::Saved(project) if project.machine == machine => Some(project),
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
