//! MINASEC-U's example: its text also goes to the board's program pane
//! and the panel takes the book's settings; the replaced text is kept.

use engine::minasec::SEED_TEST_PROGRAM;
use leptos::prelude::*;

use super::MinasecCtx;

/// Opens MINASEC-U example `id` (`seed-test`): its text replaces the
/// pane's, it is loaded into the board, and the panel takes the example's
/// settings. The replaced text is kept for [`undo`].
pub fn open(board: MinasecCtx, id: &str) {
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
