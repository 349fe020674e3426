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
    /// The tools shown at least once with the dock open, whose panes are
    /// drawn (a pane held in a part is fetched then, issue #53). Set in
    /// the same call that shows a tool, so that tabs chosen one after the
    /// other in one go each count.
    pub drawn: RwSignal<Vec<Tool>>,
    /// Notified when a pane held in a part has arrived and drawn: its
    /// size changes then (a phone's sheet grows to its height), and
    /// what is laid out around it follows.
    pub arrived: Trigger,
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
            drawn: RwSignal::new(if sizes.bottom_open {
                vec![sizes.tool]
            } else {
                Vec::new()
            }),
            sizes: RwSignal::new(sizes),
            sheet: RwSignal::new(false),
            arrived: Trigger::new(),
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
        self.mark_drawn();
        self.save();
    }

    /// Counts the tool shown as drawn when the dock is open.
    fn mark_drawn(&self) {
        let tool = self.tool.get_untracked();
        let open = self.sizes.with_untracked(|s| s.bottom_open);
        if open && !self.drawn.with_untracked(|d| d.contains(&tool)) {
            self.drawn.update(|d| d.push(tool));
        }
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
        self.mark_drawn();
        self.save();
    }

    /// Remembers the docks as they are.
    pub fn save(&self) {
        storage::save_string(KEY, &self.sizes.with_untracked(Sizes::to_text));
    }
}

/// A tool's panel drawn only once its tab is first shown with the dock
/// open, then kept (issue #53): a pane held in a part is fetched then,
/// not by the first screen. `draw` makes the panel.
pub fn when_first_shown(
    docks: Docks,
    tool: Tool,
    draw: impl Fn() -> AnyView + Send + Sync + 'static,
) -> AnyView {
    let seen = Memo::new(move |_| docks.drawn.with(|d| d.contains(&tool)));
    // Until then a mark says which tab draws it (the end-to-end tests'
    // `el()` shows such tabs when it looks for a control not drawn yet).
    (move || {
        if seen.get() {
            draw()
        } else {
            view! { <div hidden data-lazy-pane=tool.hook()></div> }.into_any()
        }
    })
    .into_any()
}
