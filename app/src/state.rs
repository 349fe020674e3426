//! The page's own state, shared by every workspace: the language, the
//! machine shown, the pace and the notice. Components reach it through
//! [`Ctx`], a `Copy` handle in context; each machine's state is its own
//! (`crate::machines`).

use leptos::prelude::*;

use crate::i18n::Lang;
use crate::sim::Speed;

/// Sets `signal` to `value` only if it differs, so only the elements that
/// show a changed value repaint.
pub fn put<T: PartialEq + Send + Sync + 'static>(signal: RwSignal<T>, value: T) {
    if signal.with_untracked(|old| *old != value) {
        signal.set(value);
    }
}

/// Which machine the page shows: the engine's own list of machines (the
/// `machine` select, storage and the CLI share their names).
pub type MachineKind = engine::MachineId;

/// A machine's product name, as its maker writes it (its ladder target
/// says it).
pub fn product_name(kind: MachineKind) -> &'static str {
    kind.target().product_name()
}

/// The page's own state, shared by every workspace; `Copy`, provided as
/// context. Each machine's workspace has a context of its own
/// (`crate::workspaces`).
#[derive(Clone, Copy)]
pub struct Ctx {
    pub lang: RwSignal<Lang>,
    /// The machine shown.
    pub machine: RwSignal<MachineKind>,
    pub speed: RwSignal<Speed>,
    pub paused: RwSignal<bool>,
    /// A message about saved data (corrupt, storage unavailable).
    pub notice: RwSignal<Option<String>>,
    /// The workbench's docks: which tool is shown, which dock is open,
    /// their sizes (`crate::docks`).
    pub docks: crate::docks::Docks,
    /// How contacts are coloured (View menu; remembered).
    pub colouring: RwSignal<crate::editor::conduct::Colouring>,
}

impl Ctx {
    /// The page in `lang`, showing MINASEC-U, at ×1, running.
    pub fn new(lang: Lang) -> Ctx {
        Ctx {
            lang: RwSignal::new(lang),
            machine: RwSignal::new(MachineKind::MinasecU),
            speed: RwSignal::new(Speed::Times(1)),
            paused: RwSignal::new(false),
            notice: RwSignal::new(None),
            docks: crate::docks::Docks::restore(),
            colouring: RwSignal::new(crate::editor::conduct::Colouring::parse(
                crate::storage::saved_string(crate::editor::conduct::COLOURING_KEY).as_deref(),
            )),
        }
    }

    /// The context provided by [`crate::App`].
    pub fn get() -> Ctx {
        expect_context::<Ctx>()
    }

    /// The pace the frame loop runs the shown workspace at.
    pub fn pace(&self) -> crate::sim::Pace {
        crate::sim::Pace {
            speed: self.speed.get_untracked(),
            paused: self.paused.get_untracked(),
        }
    }
}
