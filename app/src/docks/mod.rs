//! The workbench's docks as data (issue #45, docs/app.md "The
//! workbench"; drawn by `crate::workbench::docks`): the
//! machine's panel in a dock on the right, the tools (watch, chart, tests,
//! Why?, listing and problems, variables, program text, the CPU view) as
//! tabs in a dock under the ladder. Docks resize by their splitters,
//! collapse, and remember both in storage. On a phone the docks become a
//! bottom sheet (the ladder's inputs and outputs are a strip beside the
//! ladder: `crate::editor::strip`).

pub mod sizes;

pub use sizes::{Sizes, Tool};

use leptos::prelude::*;

use crate::storage;

/// Where the docks' sizes and tabs are kept.
pub const KEY: &str = "hashigo.docks";

/// The docks' state, page-wide (every machine's workspace shows the same
/// docks); `Copy`, part of [`crate::state::Ctx`].
#[derive(Clone, Copy)]
pub struct Docks {
    /// The tool shown in the bottom dock (on a phone: in the sheet).
    pub tool: RwSignal<Tool>,
    /// Widths, heights and which docks are open.
    pub sizes: RwSignal<Sizes>,
    /// On a phone: the bottom sheet is up.
    pub sheet: RwSignal<bool>,
}

impl Docks {
    /// The docks as storage remembers them (the defaults where it holds
    /// nothing that reads).
    pub fn restore() -> Docks {
        let sizes = storage::saved_string(KEY)
            .and_then(|s| Sizes::parse(&s))
            .unwrap_or_default();
        Docks {
            tool: RwSignal::new(sizes.tool),
            sizes: RwSignal::new(sizes),
            sheet: RwSignal::new(false),
        }
    }

    /// Shows `tool` in the bottom dock, opening the dock (and on a phone
    /// the sheet).
    pub fn show(&self, tool: Tool) {
        self.tool.set(tool);
        self.sheet.set(true);
        self.sizes.update(|s| {
            s.tool = tool;
            s.bottom_open = true;
        });
        self.save();
    }

    /// Shows `tool`, or closes the dock when it already shows it.
    pub fn toggle(&self, tool: Tool) {
        let shown = self.tool.get_untracked() == tool
            && self.sizes.with_untracked(|s| s.bottom_open)
            && self.sheet.get_untracked();
        if shown {
            self.sheet.set(false);
            self.sizes.update(|s| s.bottom_open = false);
            self.save();
        } else {
            self.show(tool);
        }
    }

    /// Changes the sizes (a splitter moved, a dock opened or closed) and
    /// remembers them.
    pub fn resize(&self, f: impl FnOnce(&mut Sizes)) {
        self.sizes.update(f);
        self.save();
    }

    /// Remembers the docks as they are.
    pub fn save(&self) {
        storage::save_string(KEY, &self.sizes.with_untracked(Sizes::to_text));
    }
}
