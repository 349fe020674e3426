//! Example programs and opening them without losing the user's own work.

use engine::ladder::edit::Edit;
use engine::MachineId;
use leptos::prelude::*;

use crate::workspaces::Workspaces;

/// Opens example `id` of `machine` as a ladder in its editor (the old
/// ladder is one undo away; the text pane follows the ladder while it
/// holds the ladder's listing). A machine's own panel may take it too
/// (MINASEC-U's board, `Workspaces::open_example_on_panel`).
/// A machine that is not there yet is fetched first (its part).
pub fn open(machine: MachineId, id: &str, workspaces: Workspaces) {
    let id = id.to_string();
    workspaces.when_ready(machine, move || open_now(machine, &id, workspaces));
}

fn open_now(machine: MachineId, id: &str, workspaces: Workspaces) {
    let ladder = workspaces.ladders.of(machine);
    let Some(example) = engine::examples::examples_of(machine).find(|e| e.id == id) else {
        return;
    };
    let on_panel = workspaces.open_example_on_panel(machine, id);
    match ladder.ladder_of_text(example.text) {
        Ok(new) => {
            ladder.apply(Edit::Replace { ladder: new });
            ladder.clean_slate();
            ladder.titled(example.title_en, example.title_ja);
            if on_panel {
                // The pane holds the example's own text: the same program.
                ladder.adopt_text();
            }
        }
        Err(e) => ladder.panes.message.set(Some(e)),
    }
}
