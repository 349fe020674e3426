//! The editor's autosave: the one place its project is written, to the
//! slot of the project open in it, with the revision that save replaces
//! (`storage::slot`). Another tab's newer save is followed when this tab
//! has nothing unsaved, else shown as a conflict the user settles; a
//! storage that refuses is said once and the work stays in the page
//! (docs/editor.md, "Two tabs").

use leptos::prelude::*;

use crate::storage::slot::{Elsewhere, Saving, Slot};
use crate::storage::{backend, StorageFault};

/// The autosave of one editor; `Copy`.
#[derive(Clone, Copy)]
pub struct Autosave {
    slot: StoredValue<Slot>,
    /// Another tab saved newer work over this tab's unsaved work: nothing
    /// is written until the user chooses (`data-testid="storage-conflict"`).
    pub conflict: RwSignal<bool>,
    /// The storage refused the last save: the work is only in this page.
    pub trouble: RwSignal<Option<StorageFault>>,
}

impl Autosave {
    /// The autosave of the slot under `key`, as it now is.
    pub fn new(key: &str) -> Autosave {
        Autosave {
            slot: StoredValue::new(Slot::open(&*backend(), key)),
            conflict: RwSignal::new(false),
            trouble: RwSignal::new(None),
        }
    }

    /// Saves into the slot under `key` from now on (a project opened).
    pub fn switch_to(&self, key: &str) {
        self.slot.set_value(Slot::open(&*backend(), key));
        self.conflict.set(false);
    }

    /// Writes `json` unless another tab saved since; says what happened.
    pub fn save(&self, json: &str) {
        let saving = self
            .slot
            .try_update_value(|s| s.save(&*backend(), json))
            .unwrap_or(Saving::Conflict);
        self.show(saving);
    }

    fn show(&self, saving: Saving) {
        match saving {
            Saving::Saved(_) => {
                if self.trouble.get_untracked().is_some() {
                    self.trouble.set(None);
                }
            }
            Saving::Conflict => {
                if !self.conflict.get_untracked() {
                    self.conflict.set(true);
                }
            }
            // Said once: the notice stays until a save goes through.
            Saving::Failed { fault, first } => {
                if first {
                    self.trouble.set(Some(fault));
                }
            }
        }
    }

    /// A `storage` event for `key`: the newer value to show when this tab
    /// follows it (a conflict is shown instead when it has work of its
    /// own).
    pub fn elsewhere(&self, key: &str) -> Option<String> {
        if !self.slot.with_value(|s| s.is_about(key)) {
            return None;
        }
        let found = self
            .slot
            .try_update_value(|s| s.elsewhere(&*backend()))
            .unwrap_or(Elsewhere::Nothing);
        match found {
            Elsewhere::Nothing => None,
            Elsewhere::Follow(value) => Some(value),
            Elsewhere::Conflict => {
                self.conflict.set(true);
                None
            }
        }
    }

    /// "Load theirs": the slot's value; the conflict is over.
    pub fn theirs(&self) -> Option<String> {
        let value = self.slot.try_update_value(|s| s.theirs(&*backend()))?;
        self.conflict.set(false);
        value
    }
}

/// What the autosave has to say: a conflict with another tab's work (two
/// choices), or a storage that refuses (the project file offered).
#[component]
pub fn StorageBanner(ctx: crate::editor::LadderCtx) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let projects = use_context::<crate::editor::projects::Projects>();
    let trouble = move || match ctx.work.saving.trouble.get() {
        Some(StorageFault::Full) => Some(t().storage_full),
        Some(StorageFault::Unavailable) => Some(t().storage_blocked),
        None => None,
    };
    view! {
        <Show when=move || ctx.work.saving.conflict.get()>
            <div class="storage-conflict" role="alert" data-testid="storage-conflict">
                <span>{move || t().conflict_note}</span>
                <button type="button" data-testid="conflict-load-theirs" on:click=move |_| ctx.load_theirs()>
                    {move || t().conflict_theirs}
                </button>
                <button type="button" data-testid="conflict-keep-mine" on:click=move |_| {
                    if let Some(projects) = projects {
                        ctx.keep_mine(projects);
                    }
                }>{move || t().conflict_mine}</button>
            </div>
        </Show>
        <Show when=move || trouble().is_some()>
            <div class="storage-trouble" role="alert" data-testid="storage-trouble">
                <span>{move || trouble().unwrap_or_default()}</span>
                <button type="button" data-testid="storage-save-file" on:click=move |_| {
                    crate::editor::files::save_project_file(ctx);
                }>{move || t().save_json}</button>
            </div>
        </Show>
    }
}
