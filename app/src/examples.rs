//! Example programs and opening them without losing the user's own work.

use engine::ladder::edit::Edit;
use engine::minasec::SEED_TEST_PROGRAM;
use engine::MachineId;
use leptos::prelude::*;

use crate::editor::LadderCtx;
use crate::machines::minasec::MinasecCtx;

/// Opens example `id` of `machine` as a ladder in `ladder` (the old
/// ladder is one undo away; the text pane follows the ladder while it
/// holds the ladder's listing). MINASEC-U's test program also goes to
/// the board as before, see [`open_minasec`].
pub fn open(machine: MachineId, id: &str, board: MinasecCtx, ladder: LadderCtx) {
    let Some(example) = engine::examples::examples_of(machine).find(|e| e.id == id) else {
        return;
    };
    if machine == MachineId::MinasecU {
        open_minasec(board, id);
    }
    match ladder.ladder_of_text(example.text) {
        Ok(new) => {
            ladder.apply(Edit::Replace { ladder: new });
            if machine == MachineId::MinasecU {
                // The pane holds the example's own text: the same program.
                ladder.adopt_text();
            }
        }
        Err(e) => ladder.message.set(Some(e)),
    }
}

/// Opens MINASEC-U example `id` (`seed-test`): its text replaces the
/// pane's, it is loaded into the board, and the panel takes the example's
/// settings. The replaced text is kept for [`undo`].
pub fn open_minasec(board: MinasecCtx, id: &str) {
    if id != "seed-test" {
        return;
    }
    let previous = board.text.get_untracked();
    // Keep the replaced text for undo when there is something to lose.
    if !previous.trim().is_empty() && previous != SEED_TEST_PROGRAM {
        board.before_example.set(Some(previous));
    }
    board.text.set(SEED_TEST_PROGRAM.to_string());
    board.load_text();
    // The book's panel: RV1 almost fully on (≈ 1.1 s), RV2 at 0 (1 s),
    // rotary switches at 1 and 0.
    board.apply_settings(1100, 1000, 1, 0);
    board.save();
}

/// Puts back the text an example replaced.
pub fn undo(board: MinasecCtx) {
    if let Some(previous) = board.before_example.get_untracked() {
        board.text.set(previous);
        board.before_example.set(None);
        board.save();
    }
}
