//! Example programs and opening them without losing the user's own work.

use engine::ladder::edit::Edit;
use engine::MachineId;
use leptos::prelude::*;

use crate::workspaces::Workspaces;

/// Opens example `id` of `machine` as a ladder in its editor (the old
/// ladder is one undo away; the text pane follows the ladder while it
/// holds the ladder's listing). MINASEC-U's test program also goes to
/// the board as before (`machines::minasec::examples`).
pub fn open(machine: MachineId, id: &str, workspaces: Workspaces) {
    let ladder = workspaces.ladders.of(machine);
    let Some(example) = engine::examples::examples_of(machine).find(|e| e.id == id) else {
        return;
    };
    if machine == MachineId::MinasecU {
        crate::machines::minasec::examples::open(workspaces.minasec, id);
    }
    match ladder.ladder_of_text(example.text) {
        Ok(new) => {
            ladder.apply(Edit::Replace { ladder: new });
            ladder.clean_slate();
            if machine == MachineId::MinasecU {
                // The pane holds the example's own text: the same program.
                ladder.adopt_text();
            }
        }
        Err(e) => ladder.panes.message.set(Some(e)),
    }
}
