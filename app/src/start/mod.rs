//! The first five minutes (issue #47, docs/app.md "Start"): the start
//! screen a fresh profile sees, the guided first rung, and the guide in
//! the page. The start screen's and the guide's words and pictures are
//! static files (`web/start/`, `web/guide/`) fetched on first use, so the
//! first screen's wasm carries only the code that shows them.
//!
//! - [`screen`]: the start screen;
//! - [`tour`], [`steps`]: the guided first rung, its checks in plain Rust;
//! - [`guide`]: the guide's panel, and the links to its sections;
//! - [`fetch`]: fetching those files once.

pub mod fetch;
#[cfg(test)]
mod gallery;
pub mod guide;
pub mod screen;
pub mod steps;
pub mod tour;

use leptos::prelude::*;

use crate::storage;
use steps::Step;

/// Remembers that the start screen was used or dismissed.
pub const START_KEY: &str = "hashigo.start";

/// The start screen, the tour and the guide as the page shows them.
#[derive(Clone, Copy)]
pub struct Start {
    /// The start screen shows.
    pub open: RwSignal<bool>,
    /// The tour's step, while the tour runs.
    pub tour: RwSignal<Option<Step>>,
    /// The guide shows, at this section (`""`: its top).
    pub guide: RwSignal<Option<String>>,
    /// An example chosen on the start screen, for the page to open
    /// (it holds the workspaces; the start screen does not).
    pub example: RwSignal<Option<(engine::MachineId, String)>>,
    /// The static files fetched so far.
    pub files: fetch::Files,
}

impl Start {
    /// Nothing shown.
    pub fn new() -> Start {
        Start {
            open: RwSignal::new(false),
            tour: RwSignal::new(None),
            guide: RwSignal::new(None),
            example: RwSignal::new(None),
            files: fetch::Files::new(),
        }
    }

    /// Closes the start screen for good (Help brings it back).
    pub fn close(&self) {
        self.open.set(false);
        storage::save_string(START_KEY, "closed");
    }

    /// The one provided by [`crate::App`].
    pub fn get() -> Start {
        expect_context::<Start>()
    }

    /// Opens the guide at `section` (an id of web/guide/*.html).
    pub fn open_guide(&self, section: &str) {
        self.guide.set(Some(section.to_string()));
    }
}

impl Default for Start {
    fn default() -> Start {
        Start::new()
    }
}

/// Whether this visit opens on the start screen: the bare page (no share
/// link or exercise in the address: `bare`), a start screen never used or
/// dismissed, and no work saved in this profile (`no_work`).
pub fn first_visit(bare: bool, no_work: bool) -> bool {
    bare && no_work && storage::saved_string(START_KEY).is_none()
}

/// The start screen and the guide stand under the app bar, whose height
/// depends on the window (it wraps): `--start-top` follows it.
pub fn place_below_bar() {
    let Some(document) = web_sys::window().and_then(|w| w.document()) else {
        return;
    };
    let bottom = document
        .query_selector("header.app-bar")
        .ok()
        .flatten()
        .map_or(48.0, |bar| bar.get_bounding_client_rect().bottom().max(0.0));
    if let Some(root) = document.document_element() {
        let _ = root.set_attribute("style", &format!("--start-top: {bottom:.0}px"));
    }
}

/// Whether a key went to a text field, where Escape cancels the field
/// rather than leaving the tour or the guide.
pub fn typed_in_a_field(e: &web_sys::KeyboardEvent) -> bool {
    use leptos::wasm_bindgen::JsCast;
    e.target()
        .and_then(|t| t.dyn_into::<web_sys::Element>().ok())
        .is_some_and(|el| matches!(el.tag_name().as_str(), "INPUT" | "TEXTAREA" | "SELECT"))
}
