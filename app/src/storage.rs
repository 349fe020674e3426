//! Autosave: the program text and the panel's settings go to localStorage
//! on every change and come back on reload. A saved value that cannot be
//! read is moved aside under a key of its own and reported, never dropped.

use serde::{Deserialize, Serialize};

/// The key of the MINASEC-U workspace.
pub const KEY: &str = "hashigo.minasec-u.v1";
/// The key of the interface language.
pub const LANG_KEY: &str = "hashigo.lang";

/// What is saved for the MINASEC-U board.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Saved {
    /// The program pane's text, as typed (loaded or not).
    pub program: String,
    /// RV1's delay in ms (100..=1100).
    pub rv1_ms: u64,
    /// RV2's delay in ms (1000..=11000).
    pub rv2_ms: u64,
    /// The counter's rotary switches.
    pub preset_tens: u8,
    pub preset_ones: u8,
}

impl Saved {
    /// Why this value cannot be restored, if it cannot.
    fn problem(&self) -> Option<&'static str> {
        if !(100..=1100).contains(&self.rv1_ms) {
            Some("rv1_ms out of range")
        } else if !(1000..=11000).contains(&self.rv2_ms) {
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
pub enum Restored {
    /// Nothing saved yet.
    Nothing,
    /// A good saved workspace.
    Saved(Saved),
    /// A saved value that could not be read, now kept under `kept_as`.
    Corrupt { kept_as: String },
    /// No localStorage (private mode, disabled): nothing can be saved.
    Unavailable,
}

fn storage() -> Option<web_sys::Storage> {
    web_sys::window()?.local_storage().ok().flatten()
}

/// Reads the saved workspace.
pub fn restore() -> Restored {
    let Some(store) = storage() else {
        return Restored::Unavailable;
    };
    let raw = match store.get_item(KEY) {
        Ok(Some(raw)) => raw,
        Ok(None) => return Restored::Nothing,
        Err(_) => return Restored::Unavailable,
    };
    match serde_json::from_str::<Saved>(&raw) {
        Ok(saved) if saved.problem().is_none() => Restored::Saved(saved),
        _ => {
            // Keep the unreadable value under a key of its own, so the next
            // autosave cannot overwrite it.
            let kept_as = format!("{KEY}.corrupt.{}", js_sys::Date::now() as u64);
            if store.set_item(&kept_as, &raw).is_err() {
                return Restored::Unavailable;
            }
            let _ = store.remove_item(KEY);
            Restored::Corrupt { kept_as }
        }
    }
}

/// Saves the workspace; false when storage is unavailable or full.
pub fn save(saved: &Saved) -> bool {
    let Some(store) = storage() else {
        return false;
    };
    match serde_json::to_string(saved) {
        Ok(json) => store.set_item(KEY, &json).is_ok(),
        Err(_) => false,
    }
}

/// The remembered language code, if any.
pub fn saved_lang() -> Option<String> {
    storage()?.get_item(LANG_KEY).ok().flatten()
}

/// Remembers the language.
pub fn save_lang(code: &str) {
    if let Some(store) = storage() {
        let _ = store.set_item(LANG_KEY, code);
    }
}
