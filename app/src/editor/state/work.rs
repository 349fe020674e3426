//! The work edited here: a project opened, a shared link shown and kept
//! or left, the autosave, and what another tab saved (docs/editor.md,
//! "Two tabs").

use super::*;
use engine::formats::project::{Exercise, PlantSetup};

/// What showing a shared project set aside: its settings (applied when
/// kept), whether it replaced the ladder, and the cases it replaced.
#[derive(Clone, Debug, Default)]
pub(super) struct SharedWith {
    settings: Vec<(String, String)>,
    replaced: bool,
    own_tests: Vec<TestCase>,
    own_exercise: Option<Exercise>,
    own_plant: Option<PlantSetup>,
}

impl LadderCtx {
    /// The machine's settings as a project keeps them.
    pub fn settings(&self) -> Vec<(String, String)> {
        self.text
            .pane
            .get_value()
            .map(|p| p.settings.run(()))
            .unwrap_or_default()
    }

    /// Applies settings to the machine as a project brings them; the
    /// refusals, each named. A machine not there yet (its part on its
    /// way) takes them when it arrives, and its refusals are said then.
    pub fn apply_settings(&self, settings: Vec<(String, String)>) -> Vec<String> {
        match self.text.pane.get_value() {
            Some(p) => p.apply_settings.run(settings),
            None => {
                self.text.queued.update_value(|q| q.extend(settings));
                Vec::new()
            }
        }
    }

    /// A project's program text (issue #55) goes to the machine's pane;
    /// a machine not there yet takes it when it arrives.
    pub fn apply_source(&self, source: Option<engine::formats::project::ProgramText>) {
        let Some(source) = source else {
            return;
        };
        match self.text.pane.get_value() {
            Some(p) => p.apply_source.run(source),
            None => self.text.queued_source.set_value(Some(source)),
        }
    }

    /// Why? into the ST of a box of an ST block (`kind`, `instance`):
    /// the statements the machine's program pane names (issue #55).
    pub fn why_st(
        &self,
        kind: String,
        instance: String,
    ) -> Vec<crate::editor::panes::why::StCause> {
        self.text
            .pane
            .get_value()
            .map_or_else(Vec::new, |p| p.why_st.run((kind, instance)))
    }

    /// Shows a shared project's ladder, unsaved, until it is kept or left.
    pub fn show_shared(&self, mut project: engine::formats::Project) {
        self.apply_source(project.program.take());
        if self.work.shared.get_untracked() {
            self.leave_shared();
        }
        // A fresh profile has no work of its own to go back to: an
        // exercise opened there is simply its work (no banner to answer).
        let adopt = project.exercise.is_some() && self.no_own_work();
        self.work.shared.set(true);
        // The link's ladder, even an empty one, is what the editor shows.
        self.text.fresh.set_value(false);
        let own_tests = self.cases.tests.get_untracked();
        let own_exercise = self.cases.exercise.get_untracked();
        let own_plant = self.cases.plant.get_untracked();
        let exercise = project.exercise.is_some();
        self.show_cases(project.tests, project.exercise, project.plant);
        if exercise {
            self.page.docks.show(crate::docks::Tool::Tests);
        }
        let replaced = self.apply(Edit::Replace {
            ladder: project.ladder,
        });
        self.panes.message.set(None);
        self.work.shared_with.set_value(SharedWith {
            settings: project.settings.into_iter().collect(),
            replaced,
            own_tests,
            own_exercise,
            own_plant,
        });
        if adopt {
            self.adopt_shared();
        }
    }

    /// Whether this machine has no work of its own here: no project
    /// open, no test, and no ladder drawn and saved (a fresh profile shows
    /// the machine's default program, which nobody saved).
    fn no_own_work(&self) -> bool {
        let drawn = self.with_editor(|e| {
            e.ladder()
                .rungs
                .iter()
                .any(|r| r.elements().next().is_some())
        });
        let saved = crate::storage::saved_string(&store::key(self.machine)).is_some();
        self.work.project.get_untracked().is_none()
            && self.cases.tests.with_untracked(Vec::is_empty)
            && !(drawn && saved)
    }

    /// The shared project becomes this machine's ladder without a word:
    /// there was nothing to set aside.
    fn adopt_shared(&self) {
        self.work.shared.set(false);
        let settings = self.work.shared_with.with_value(|w| w.settings.clone());
        let refused = self.apply_settings(settings);
        self.refresh(true);
        if !refused.is_empty() {
            self.page.notice.set(Some(refused.join(" ")));
        }
    }

    /// "Keep it": the shared ladder becomes this machine's ladder and is
    /// saved; the ladder saved before is set aside under a key of its own
    /// (named in the notice) and is one undo away.
    pub fn keep_shared(&self, projects: Option<crate::editor::projects::Projects>) {
        if !self.work.shared.get_untracked() {
            return;
        }
        let texts = self.page.lang.get_untracked().texts();
        // It becomes a project of its own; the ladder before stays where
        // it was saved, untouched.
        let made = projects.and_then(|p| {
            let name = format!(
                "{} {}",
                texts.shared_project,
                js_sys::Date::new_0().to_iso_string()
            );
            p.create(&name, &self.project_now()).map(|id| (id, name))
        });
        let kept_as = match made {
            Some((id, name)) => {
                self.set_project(Some(id));
                Some(name)
            }
            None => store::set_aside(self.machine),
        };
        self.work.shared.set(false);
        let settings = self.work.shared_with.with_value(|w| w.settings.clone());
        let refused = self.apply_settings(settings);
        self.refresh(true);
        let mut notice = match kept_as {
            Some(key) => format!("{} {key}", texts.shared_kept),
            None => String::new(),
        };
        for r in refused {
            notice.push_str(&format!(" {r}"));
        }
        self.page
            .notice
            .set((!notice.trim().is_empty()).then_some(notice));
    }

    /// Opens `ladder` as project `project` here (the ladder before is one
    /// undo away; it stays saved where it was).
    pub fn open_project(&self, id: Option<u64>, project: engine::formats::Project) {
        self.set_project(id);
        self.show_cases(project.tests, project.exercise, project.plant);
        if self.ladder() != project.ladder {
            self.apply(Edit::Replace {
                ladder: project.ladder,
            });
        } else {
            self.save();
        }
    }

    /// "Back to my work": the ladder as it was before the link opened.
    pub fn leave_shared(&self) {
        if !self.work.shared.get_untracked() {
            return;
        }
        let with = self.work.shared_with.get_value();
        self.show_cases(with.own_tests, with.own_exercise, with.own_plant);
        if with.replaced {
            self.drawing.editor.update_value(|e| {
                e.undo();
            });
        }
        // An edit as far as the machine is concerned (written at once
        // while it runs the drawing); not saved, as the link was not.
        self.refresh(with.replaced);
        self.work.shared.set(false);
        // Another tab may have saved while the link was shown.
        self.on_storage(&store::slot(
            self.machine,
            self.work.project.get_untracked(),
        ));
    }

    /// Project `id` (or the machine's own ladder) is edited here from now
    /// on: remembered for the next visit, saved in its slot.
    pub(super) fn set_project(&self, id: Option<u64>) {
        self.work.project.set(id);
        store::remember_open(self.machine, id);
        self.work.saving.switch_to(&store::slot(self.machine, id));
    }

    /// A `storage` event for `key`: another tab saved. This tab shows its
    /// work when it had nothing unsaved (undo brings back what it showed);
    /// a conflict is shown otherwise. Nothing while a shared ladder is
    /// shown (its own is compared when it is left).
    pub fn on_storage(&self, key: &str) {
        if self.work.shared.get_untracked() {
            return;
        }
        if let Some(json) = self.work.saving.elsewhere(key) {
            self.show_saved(&json);
        }
    }

    /// Shows a project saved by another tab, as an edit not saved again
    /// (once read: the reader is a part, issue #53).
    pub(super) fn show_saved(&self, json: &str) {
        let (ctx, json) = (*self, json.to_string());
        wasm_bindgen_futures::spawn_local(async move {
            if let Ok(Ok(project)) = crate::editor::files::reading::project(json).await {
                ctx.show_read(project);
            }
        });
    }

    /// [`Self::show_saved`] once read.
    fn show_read(&self, project: engine::formats::Project) {
        if project.machine != self.machine {
            return;
        }
        self.show_cases(project.tests, project.exercise, project.plant);
        let replaced = self
            .drawing
            .editor
            .try_update_value(|e| {
                e.apply(Edit::Replace {
                    ladder: project.ladder,
                })
            })
            .is_some_and(|r| r.is_ok());
        if replaced {
            self.refresh_as(Change::Followed);
        }
    }

    /// "Load theirs": the other tab's work replaces this tab's (one undo
    /// brings it back).
    pub fn load_theirs(&self) {
        if let Some(json) = self.work.saving.theirs() {
            self.show_saved(&json);
        }
    }

    /// "Keep mine as a copy": this tab's work becomes a project of its own,
    /// opened here; the other tab's work stays where it was saved.
    pub fn keep_mine(&self, projects: crate::editor::projects::Projects) {
        let texts = self.page.lang.get_untracked().texts();
        let from = self.work.project.get_untracked().and_then(|id| {
            projects.index.with_untracked(|i| {
                i.projects
                    .iter()
                    .find(|e| e.id == id)
                    .map(|e| e.name.clone())
            })
        });
        let base = from.unwrap_or_else(|| texts.project_default.to_string());
        let name = format!("{base} {}", texts.conflict_copy);
        let Some(id) = projects.create(&name, &self.project_now()) else {
            return;
        };
        self.set_project(Some(id));
        self.work.saving.conflict.set(false);
        self.save();
        self.page
            .notice
            .set(Some(format!("{} {name}", texts.conflict_kept)));
    }

    /// The project as it stands: the ladder, its cases, the exercise.
    pub fn project_now(&self) -> engine::formats::Project {
        let mut project = engine::formats::Project::new(self.machine, self.ladder());
        project.tests = self.cases.tests.get_untracked();
        project.exercise = self.cases.exercise.get_untracked();
        // The plant dock's choice (issue #52), kept with the project.
        project.plant = self.cases.plant.get_untracked();
        // The soft PLC's ST (issue #55).
        project.program = self.text.pane.get_value().and_then(|p| p.source.run(()));
        project
    }

    /// Autosaves the project (not while a shared one is shown).
    pub fn save(&self) {
        if !self.work.shared.get_untracked() {
            self.work.saving.save(&self.project_now().to_json());
        }
    }

    /// The cases shown: `tests`, as an exercise or not, on a clean slate
    /// (an exercise in the student's view).
    pub(crate) fn show_cases(
        &self,
        tests: Vec<TestCase>,
        exercise: Option<Exercise>,
        plant: Option<PlantSetup>,
    ) {
        self.cases.plant.set(plant);
        self.cases.tests.set(tests);
        self.cases.exercise.set(exercise);
        self.cases.authoring.set(false);
        self.clean_slate();
    }
}
