//! Named projects in the browser's storage: new, open, rename, duplicate,
//! delete (with undo). Each is the engine's project JSON under a key of
//! its own; the index names them. A machine's editor edits either its
//! own default ladder (`hashigo.ladder.<machine>.v1`) or the project open
//! in it, autosaved on every edit (docs/editor.md, "Projects").

use engine::formats::Project;
use engine::ladder::Ladder;
use engine::MachineId;
use leptos::prelude::*;
use serde::{Deserialize, Serialize};

use crate::editor::{LadderCtx, Ladders};
use crate::storage::{self, Checked, Restored};

/// Where the index is kept.
pub const INDEX_KEY: &str = "hashigo.projects.v1";

/// One project in the index.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct Entry {
    /// Its id (its key is `hashigo.project.<id>.v1`).
    pub id: u64,
    /// Its name, as the user gave it.
    pub name: String,
    /// The machine it is for.
    pub machine: MachineId,
}

/// The index as saved.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Index {
    /// The projects, in the order they were made.
    pub projects: Vec<Entry>,
}

impl Checked for Index {
    fn problem(&self) -> Option<&'static str> {
        None
    }
}

/// The storage key of project `id`.
pub fn key_of(id: u64) -> String {
    format!("hashigo.project.{id}.v1")
}

/// The projects page-wide: the index, and the last deletion (for undo).
#[derive(Clone, Copy)]
pub struct Projects {
    pub index: RwSignal<Index>,
    /// The entry deleted last, with its saved JSON, until undone.
    pub deleted: RwSignal<Option<(Entry, String)>>,
}

impl Projects {
    /// The index as saved (an unreadable one is kept aside and reported).
    pub fn restore(page: crate::state::Ctx) -> Projects {
        let index = match storage::restore_from::<Index>(INDEX_KEY) {
            Restored::Saved(i) => i,
            Restored::Corrupt { kept_as } => {
                let texts = page.lang.get_untracked().texts();
                page.notice
                    .set(Some(format!("{} {kept_as}", texts.corrupt_saved)));
                Index::default()
            }
            Restored::Nothing | Restored::Unavailable => Index::default(),
        };
        Projects {
            index: RwSignal::new(index),
            deleted: RwSignal::new(None),
        }
    }

    /// Changes the index as saved now (another tab may have changed it
    /// since this one read it: its entries stay), then shows it.
    fn change(&self, f: impl FnOnce(&mut Index)) {
        let mut index = match storage::restore_from::<Index>(INDEX_KEY) {
            Restored::Saved(i) => i,
            _ => self.index.get_untracked(),
        };
        f(&mut index);
        storage::save_to(INDEX_KEY, &index);
        self.index.set(index);
    }

    /// Another tab changed the index: show it as saved.
    pub fn reload(&self) {
        if let Restored::Saved(index) = storage::restore_from::<Index>(INDEX_KEY) {
            if self.index.with_untracked(|i| *i != index) {
                self.index.set(index);
            }
        }
    }

    fn next_id(&self) -> u64 {
        let now = js_sys::Date::now() as u64;
        let top = self
            .index
            .with_untracked(|i| i.projects.iter().map(|e| e.id).max().unwrap_or(0));
        now.max(top + 1)
    }

    /// Adds `project` under `name`; returns its id.
    pub fn create(&self, name: &str, project: &Project) -> Option<u64> {
        let id = self.next_id();
        let machine = project.machine;
        let json = project.to_json();
        if storage::write(&key_of(id), &json).is_err() {
            return None;
        }
        self.change(|i| {
            i.projects.push(Entry {
                id,
                name: name.to_string(),
                machine,
            })
        });
        Some(id)
    }

    /// The saved project `id`.
    pub fn load(&self, id: u64) -> Result<Project, String> {
        let raw = storage::saved_string(&key_of(id))
            .ok_or_else(|| format!("project {id} is not in storage"))?;
        Project::from_json(&raw).map_err(|e| format!("{}: {e}", key_of(id)))
    }

    /// Renames project `id`.
    pub fn rename(&self, id: u64, name: &str) {
        self.change(|i| {
            if let Some(e) = i.projects.iter_mut().find(|e| e.id == id) {
                e.name = name.to_string();
            }
        });
    }

    /// A copy of project `id` named "… (copy)".
    pub fn duplicate(&self, id: u64) -> Result<u64, String> {
        let project = self.load(id)?;
        let name = self
            .index
            .with_untracked(|i| {
                i.projects
                    .iter()
                    .find(|e| e.id == id)
                    .map(|e| e.name.clone())
            })
            .unwrap_or_default();
        self.create(&format!("{name} (copy)"), &project)
            .ok_or_else(|| "storage refused the copy".to_string())
    }

    /// Deletes project `id` (its JSON is held for [`Projects::undo_delete`]).
    pub fn delete(&self, id: u64) {
        let Some(entry) = self
            .index
            .with_untracked(|i| i.projects.iter().find(|e| e.id == id).cloned())
        else {
            return;
        };
        let json = storage::saved_string(&key_of(id)).unwrap_or_default();
        self.change(|i| i.projects.retain(|e| e.id != id));
        storage::remove(&key_of(id));
        self.deleted.set(Some((entry, json)));
    }

    /// Puts the last deleted project back.
    pub fn undo_delete(&self) {
        let Some((entry, json)) = self.deleted.get_untracked() else {
            return;
        };
        if storage::write(&key_of(entry.id), &json).is_ok() {
            self.change(|i| {
                i.projects.push(entry);
                engine::sort::by_key(&mut i.projects, |e| e.id);
            });
            self.deleted.set(None);
        }
    }
}

/// Opens project `id` in its machine's editor (the ladder there before is
/// one undo away), and shows that machine.
pub fn open(projects: Projects, ladders: Ladders, id: u64) -> Result<(), String> {
    let project = projects.load(id)?;
    let machine = project.machine;
    let ctx = ladders.of(machine);
    ctx.open_project(Some(id), project);
    ctx.page.machine.set(machine);
    Ok(())
}

/// `[data-testid=projects]`: the list and what can be done to each.
#[component]
pub fn ProjectsPane(ctx: LadderCtx) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let projects = expect_context::<Projects>();
    let ladders = expect_context::<Ladders>();
    let name = RwSignal::new(String::new());
    let fail = move |r: Result<(), String>| {
        if let Err(e) = r {
            ctx.panes.message.set(Some(e));
        }
    };
    view! {
        <section class="projects-pane" data-testid="projects">
            <div class="find-row">
                <span data-testid="project-open-name">
                    {move || {
                        let open = ctx.work.project.get();
                        projects.index.with(|i| {
                            open.and_then(|id| i.projects.iter().find(|e| e.id == id))
                                .map_or_else(|| t().project_default.to_string(), |e| e.name.clone())
                        })
                    }}
                </span>
                <input data-testid="project-name" placeholder=move || t().project_name
                    prop:value=move || name.get() on:input=move |e| name.set(event_target_value(&e)) />
                <button type="button" data-testid="project-new" on:click=move |_| {
                    let n = name.get_untracked();
                    let n = if n.trim().is_empty() { t().project_untitled.to_string() } else { n };
                    if let Some(id) = projects.create(&n, &Project::new(ctx.machine, Ladder::default())) {
                        fail(open(projects, ladders, id));
                        name.set(String::new());
                    }
                }>{move || t().project_new}</button>
                <button type="button" data-testid="project-save-as" on:click=move |_| {
                    let n = name.get_untracked();
                    let n = if n.trim().is_empty() { t().project_untitled.to_string() } else { n };
                    let now = ctx.project_now();
                    if let Some(id) = projects.create(&n, &now) {
                        ctx.open_project(Some(id), now);
                        name.set(String::new());
                    }
                }>{move || t().project_save_as}</button>
                <Show when=move || projects.deleted.with(Option::is_some)>
                    <button type="button" data-testid="project-undo-delete" on:click=move |_| projects.undo_delete()>
                        {move || t().project_undo_delete}
                    </button>
                </Show>
            </div>
            <ul>
                <For
                    each=move || projects.index.get().projects
                    key=|e| e.clone()
                    children=move |e: Entry| view! { <ProjectRow ctx e name /> }
                />
            </ul>
        </section>
    }
}

/// One project in the list: open, rename (to the name typed), duplicate,
/// delete (not while it is open in an editor).
#[component]
fn ProjectRow(ctx: LadderCtx, e: Entry, name: RwSignal<String>) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let projects = expect_context::<Projects>();
    let ladders = expect_context::<Ladders>();
    let fail = move |r: Result<(), String>| {
        if let Err(e) = r {
            ctx.panes.message.set(Some(e));
        }
    };
    let id = e.id;
    let is_open = move || ctx.work.project.get() == Some(id) && ctx.page.machine.get() == e.machine;
    let rename = move |_| {
        let n = name.get_untracked();
        if !n.trim().is_empty() {
            projects.rename(id, &n);
            name.set(String::new());
        }
    };
    let delete = move |_| {
        let open_somewhere = MachineId::ALL
            .iter()
            .any(|m| ladders.of(*m).work.project.get_untracked() == Some(id));
        if open_somewhere {
            ctx.panes
                .message
                .set(Some(t().project_delete_open.to_string()));
        } else {
            projects.delete(id);
        }
    };
    view! {
        <li data-testid=format!("project-{}", e.name) class:open=is_open>
            <b>{e.name.clone()}</b> " · " {crate::state::product_name(e.machine)} " "
            <button type="button" data-testid="project-open" on:click=move |_| fail(open(projects, ladders, id))>
                {move || t().project_open}
            </button>
            <button type="button" data-testid="project-rename" on:click=rename>{move || t().project_rename}</button>
            <button type="button" data-testid="project-duplicate" on:click=move |_| {
                fail(projects.duplicate(id).map(|_| ()));
            }>{move || t().project_duplicate}</button>
            <button type="button" data-testid="project-delete" on:click=delete>{move || t().project_delete}</button>
        </li>
    }
}
