//! One folder (or file) per machine: its workspace's state and view.

pub mod arduino;
pub mod arrival;
pub mod avr;
pub mod io86a;
pub mod minasec;
pub mod soft;
pub mod workspace;

use std::rc::Rc;

use leptos::prelude::*;

use crate::storage;

use crate::editor::machine::{Linked, MachineLink};
use crate::editor::Program;
use crate::sim::Simulator;

/// A machine's simulator and its panel's refresh (given the frame's
/// turn, [`MachineLink::refresh_panel`]), as its editor's link.
pub fn link<M>(
    sim: StoredValue<Simulator<M>, LocalStorage>,
    refresh: impl Fn(Option<u64>) + Send + Sync + 'static,
) -> Rc<dyn MachineLink>
where
    M: engine::plc::Plc + Clone + 'static,
    engine::record::Recorded<M>: engine::plc::Plc + engine::record::TimeTravel,
{
    Rc::new(Linked {
        sim,
        refresh: Callback::new(refresh),
    })
}

/// The program pane of a workspace whose only state is its text (it
/// keeps no settings of a project's): loading loads it (`load` says
/// whether it could) and saves it.
pub fn text_program(
    text: RwSignal<String>,
    load: impl Fn() -> bool + Send + Sync + 'static,
    save: impl Fn() + Send + Sync + Copy + 'static,
) -> Program {
    Program {
        text,
        load: Callback::new(move |()| {
            // Whether it loaded is shown by the pane itself.
            let _ = load();
            save();
        }),
        save: Callback::new(move |()| save()),
        settings: Callback::new(|()| Vec::new()),
        apply_settings: Callback::new(not_applied),
        source: Callback::new(|()| None),
        apply_source: Callback::new(|_| ()),
        why_st: Callback::new(|_| Vec::new()),
    }
}

/// The settings a project brings to a workspace that keeps none of its
/// own: each is reported, none is dropped silently.
fn not_applied(settings: Vec<(String, String)>) -> Vec<String> {
    settings
        .into_iter()
        .map(|(name, value)| {
            format!("{name}={value}: this workspace keeps no settings; not applied.")
        })
        .collect()
}

/// The program text saved under `key` (or `legacy`), else `default`; a
/// saved value that does not read is kept aside and reported in `page`'s
/// notice.
pub fn restored_text(page: crate::state::Ctx, key: &str, legacy: &str, default: &str) -> String {
    match storage::restore_text(key, legacy) {
        storage::Restored::Saved(saved) => saved.program,
        storage::Restored::Corrupt { kept_as } => {
            let texts = page.lang.get_untracked().texts();
            page.notice
                .set(Some(format!("{} {kept_as}", texts.corrupt_saved)));
            default.to_string()
        }
        storage::Restored::Nothing | storage::Restored::Unavailable => default.to_string(),
    }
}
