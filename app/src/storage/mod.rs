//! Autosave: the program text and the panel's settings go to localStorage
//! on every change and come back on reload. A saved value that cannot be
//! read is moved aside under a key of its own and reported, never dropped.
//!
//! - [`backend`]: where values live (localStorage, or memory in tests);
//! - [`slot`]: a slot shared by open tabs, saved with revisions.

pub mod backend;
pub mod slot;

pub use backend::{backend, StorageBackend, StorageFault};

use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};

/// The key of the interface language.
pub const LANG_KEY: &str = "hashigo.lang";
/// The key of the chosen machine.
pub const MACHINE_KEY: &str = "hashigo.machine";

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

/// What a reload found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Restored<T> {
    /// Nothing saved yet.
    Nothing,
    /// A good saved workspace.
    Saved(T),
    /// A saved value that could not be read, now kept under `kept_as`.
    Corrupt { kept_as: String },
    /// No localStorage (private mode, disabled): nothing can be saved.
    Unavailable,
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
        None => keep_aside(key, &raw),
    }
}

/// Keeps the unreadable value `raw` saved under `key` under a key of its
/// own, so that the next autosave cannot overwrite it.
pub fn keep_aside<T>(key: &str, raw: &str) -> Restored<T> {
    let store = backend();
    let kept_as = format!("{key}.corrupt.{}", js_sys::Date::now() as u64);
    if store.set(&kept_as, raw).is_err() {
        return Restored::Unavailable;
    }
    store.remove(key);
    Restored::Corrupt { kept_as }
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
    }
}
