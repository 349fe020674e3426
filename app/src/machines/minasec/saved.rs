//! What MINASEC-U's workspace saves: the program text and the panel's
//! settings, checked against the engine's ranges when read back.

use engine::minasec::TimerId;
use serde::{Deserialize, Serialize};

use crate::storage::{restore_from, save_to, Checked, Restored};

/// The key of the MINASEC-U workspace.
pub const KEY: &str = "hashigo.minasec-u.v1";
/// What is saved for the MINASEC-U board.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Saved {
    /// The program pane's text, as typed (loaded or not).
    pub program: String,
    /// RV1's delay in ms (T0's range, 100..=1100).
    pub rv1_ms: u64,
    /// RV2's delay in ms (T1's range, 1000..=11000).
    pub rv2_ms: u64,
    /// The counter's rotary switches.
    pub preset_tens: u8,
    pub preset_ones: u8,
}

/// Whether `ms` is a delay timer `id`'s potentiometer gives (the
/// engine's range, not a copy of it).
fn pot_gives(id: TimerId, ms: u64) -> bool {
    let (low, high) = id.range();
    (low.as_nanos() / 1_000_000..=high.as_nanos() / 1_000_000).contains(&ms)
}

impl Checked for Saved {
    fn problem(&self) -> Option<&'static str> {
        if !pot_gives(TimerId::T0, self.rv1_ms) {
            Some("rv1_ms out of range")
        } else if !pot_gives(TimerId::T1, self.rv2_ms) {
            Some("rv2_ms out of range")
        } else if self.preset_tens > 9 || self.preset_ones > 9 {
            Some("counter preset out of range")
        } else {
            None
        }
    }
}

/// Reads the saved MINASEC-U workspace.
pub fn restore() -> Restored<Saved> {
    restore_from(KEY)
}

/// Saves the MINASEC-U workspace; false when storage is unavailable or full.
pub fn save(saved: &Saved) -> bool {
    save_to(KEY, saved)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::storage::read_saved;

    fn saved(rv1_ms: u64, tens: u8) -> String {
        format!(
            r#"{{"program":"LD X00","rv1_ms":{rv1_ms},"rv2_ms":1000,"preset_tens":{tens},"preset_ones":0}}"#
        )
    }

    #[test]
    fn a_saved_board_reads_back_only_when_it_is_in_range() {
        assert!(read_saved::<Saved>(&saved(1100, 1)).is_some());
        assert!(
            read_saved::<Saved>(&saved(99, 1)).is_none(),
            "below RV1's range"
        );
        assert!(
            read_saved::<Saved>(&saved(1101, 1)).is_none(),
            "above RV1's range"
        );
        assert!(
            read_saved::<Saved>(&saved(500, 10)).is_none(),
            "a rotary past 9"
        );
        assert!(read_saved::<Saved>("{not json").is_none());
        assert!(read_saved::<Saved>(r#"{"program":"LD X00"}"#).is_none());
    }
}
