//! Autosave: the program text and the panel's settings go to localStorage
//! on every change and come back on reload. A saved value that cannot be
//! read is moved aside under a key of its own and reported, never dropped.
//!
//! - [`backend`]: where values live (localStorage, or memory in tests);
//! - [`slot`]: a slot shared by open tabs, saved with revisions.

pub mod backend;
pub mod slot;

pub use backend::{backend, StorageBackend, StorageFault};

use engine::minasec::TimerId;
use leptos::prelude::*;
use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};

/// The key of the MINASEC-U workspace.
pub const KEY: &str = "hashigo.minasec-u.v1";
/// The key of the IO86A workspace.
pub const IO86A_KEY: &str = "hashigo.io86a.v1";
/// The key of the interface language.
pub const LANG_KEY: &str = "hashigo.lang";
/// The key of the chosen machine.
pub const MACHINE_KEY: &str = "hashigo.machine";

/// What is saved for the IO86A workspace: the two devices' program texts.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct SavedIo86a {
    /// Device A's and device B's program pane text.
    pub programs: [String; 2],
}

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

/// What is saved for a workspace whose state is one program text (the
/// Arduino PLC, the AVR PLC).
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct SavedText {
    /// The program pane's text, as typed.
    pub program: String,
}

impl Checked for SavedText {
    fn problem(&self) -> Option<&'static str> {
        if self.program.len() > engine::limits::MAX_INPUT_BYTES {
            Some("program larger than any input may be")
        } else if self.program.lines().count() > engine::limits::MAX_PROGRAM_LINES {
            Some("program longer than any program may be")
        } else {
            None
        }
    }
}

/// A saved value that can say whether it is usable.
pub trait Checked {
    /// Why this value cannot be restored, if it cannot.
    fn problem(&self) -> Option<&'static str>;
}

impl Checked for SavedIo86a {
    fn problem(&self) -> Option<&'static str> {
        None
    }
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

/// What a reload found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Restored<T = Saved> {
    /// Nothing saved yet.
    Nothing,
    /// A good saved workspace.
    Saved(T),
    /// A saved value that could not be read, now kept under `kept_as`.
    Corrupt { kept_as: String },
    /// No localStorage (private mode, disabled): nothing can be saved.
    Unavailable,
}

/// Reads the saved MINASEC-U workspace.
pub fn restore() -> Restored {
    restore_from(KEY)
}

/// Reads the value saved under `key`.
pub fn restore_from<T: DeserializeOwned + Checked>(key: &str) -> Restored<T> {
    let store = backend();
    let raw = match store.get(key) {
        Ok(Some(raw)) => raw,
        Ok(None) => return Restored::Nothing,
        Err(_) => return Restored::Unavailable,
    };
    match read_saved::<T>(&raw) {
        Some(saved) => Restored::Saved(saved),
        None => {
            // Keep the unreadable value under a key of its own, so the next
            // autosave cannot overwrite it.
            let kept_as = format!("{key}.corrupt.{}", js_sys::Date::now() as u64);
            if store.set(&kept_as, &raw).is_err() {
                return Restored::Unavailable;
            }
            store.remove(key);
            Restored::Corrupt { kept_as }
        }
    }
}

/// A saved value read back: `None` when it does not parse or does not
/// pass its checks.
pub fn read_saved<T: DeserializeOwned + Checked>(raw: &str) -> Option<T> {
    serde_json::from_str::<T>(raw)
        .ok()
        .filter(|saved| saved.problem().is_none())
}

/// Reads a program text saved under `key`, or else the plain text an
/// earlier version saved under `legacy` (taken over as it is).
pub fn restore_text(key: &str, legacy: &str) -> Restored<SavedText> {
    match restore_from::<SavedText>(key) {
        Restored::Nothing => match saved_string(legacy) {
            Some(program) => Restored::Saved(SavedText { program }),
            None => Restored::Nothing,
        },
        other => other,
    }
}

/// The program text saved under `key` (or `legacy`), else `default`; a
/// saved value that does not read is kept aside and reported in `page`'s
/// notice.
pub fn restored_text(page: crate::state::Ctx, key: &str, legacy: &str, default: &str) -> String {
    match restore_text(key, legacy) {
        Restored::Saved(saved) => saved.program,
        Restored::Corrupt { kept_as } => {
            let texts = page.lang.get_untracked().texts();
            page.notice
                .set(Some(format!("{} {kept_as}", texts.corrupt_saved)));
            default.to_string()
        }
        Restored::Nothing | Restored::Unavailable => default.to_string(),
    }
}

/// Saves the MINASEC-U workspace; false when storage is unavailable or full.
pub fn save(saved: &Saved) -> bool {
    save_to(KEY, saved)
}

/// A plain string saved under `key`; `Err` when storage refused it.
pub fn write(key: &str, value: &str) -> Result<(), StorageFault> {
    backend().set(key, value)
}

/// Saves `value` under `key`; false when storage is unavailable or full.
pub fn save_to<T: Serialize>(key: &str, value: &T) -> bool {
    match serde_json::to_string(value) {
        Ok(json) => backend().set(key, &json).is_ok(),
        Err(_) => false,
    }
}

/// Forgets a remembered string.
pub fn remove(key: &str) {
    backend().remove(key);
}

/// A plain remembered string (language, machine).
pub fn saved_string(key: &str) -> Option<String> {
    backend().get(key).ok().flatten()
}

/// Remembers a plain string.
pub fn save_string(key: &str, value: &str) {
    let _ = backend().set(key, value);
}

/// The remembered language code, if any.
pub fn saved_lang() -> Option<String> {
    saved_string(LANG_KEY)
}

/// Remembers the language.
pub fn save_lang(code: &str) {
    save_string(LANG_KEY, code);
}

#[cfg(test)]
mod tests {
    use super::*;

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

    #[test]
    fn a_saved_text_reads_back_within_the_limits() {
        let ok = serde_json::to_string(&SavedText {
            program: "LD X000\nEND\n".into(),
        })
        .expect("json");
        assert!(read_saved::<SavedText>(&ok).is_some());
        let long = SavedText {
            program: "; x\n".repeat(engine::limits::MAX_PROGRAM_LINES + 1),
        };
        assert_eq!(
            long.problem(),
            Some("program longer than any program may be")
        );
        assert!(read_saved::<SavedText>(r#"{"text":"LD X000"}"#).is_none());
        let io86a = r#"{"programs":["LD X00","END"]}"#;
        assert!(read_saved::<SavedIo86a>(io86a).is_some());
        assert!(read_saved::<SavedIo86a>(r#"{"programs":["only one"]}"#).is_none());
    }
}
