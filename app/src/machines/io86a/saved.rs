//! What the IO86A workspace saves: the two devices' program texts.

use serde::{Deserialize, Serialize};

use crate::storage::Checked;

/// The key of the IO86A workspace.
pub const IO86A_KEY: &str = "hashigo.io86a.v1";
/// What is saved for the IO86A workspace: the two devices' program texts.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct SavedIo86a {
    /// Device A's and device B's program pane text.
    pub programs: [String; 2],
}

impl Checked for SavedIo86a {
    fn problem(&self) -> Option<&'static str> {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::storage::read_saved;

    #[test]
    fn saved_programs_read_back_only_as_two() {
        let io86a = r#"{"programs":["LD X00","END"]}"#;
        assert!(read_saved::<SavedIo86a>(io86a).is_some());
        assert!(read_saved::<SavedIo86a>(r#"{"programs":["only one"]}"#).is_none());
    }
}
