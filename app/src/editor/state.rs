//! One machine's ladder editor: the engine's [`Editor`] outside the
//! reactive graph, and the signals the view reads (one per rung, the
//! cursor, the listing, the problems). Every key, click and drop comes
//! here as an [`Action`] or an edit; after each change the ladder is
//! checked and compiled, the changed rungs repainted, the text pane
//! kept in step and the project autosaved.

use std::collections::BTreeMap;

use engine::cases::TestCase;
use engine::ladder::compile::{compile_listing, Listing, Options};
use engine::ladder::edit::{
    align_outputs, parse_entry, Clip, Cursor, Edit, Editor, EntryKind, COLUMNS,
};
use engine::ladder::{Element, Ladder, Pos};
use engine::MachineId;
use leptos::prelude::*;

use super::keys::{self, Action, Move};
use super::model::{entry_for, reuse, rung_data, RungData};
use super::store;
use crate::state::Ctx;

/// One rung's view: a stable id (the `<For>` key) and its signals.
#[derive(Clone)]
pub struct RungView {
    /// Stays with the rung while it is moved or edited.
    pub id: u64,
    /// Its index (0-based) in the ladder now.
    pub number: ArcRwSignal<usize>,
    /// Its first step in the listing, when it compiled to steps.
    pub first_step: ArcRwSignal<Option<usize>>,
    /// What it shows.
    pub data: ArcRwSignal<RungData>,
    /// One live slot per cell (by the cell's place in `data.cells`): a
    /// frame sets only the signals whose value changed, so only those
    /// cells repaint.
    pub slots: std::sync::Arc<std::sync::Mutex<Vec<CellSlot>>>,
    /// Each cell's devices on the machine, resolved once for this drawing
    /// and program (tagged with [`LadderCtx`]'s probe generation), so a
    /// frame reads the machine without a name lookup.
    probes: std::sync::Arc<std::sync::Mutex<Probes>>,
}

/// The machine's handles for a rung's cells.
#[derive(Default)]
struct Probes {
    /// The generation they were resolved in (`None`: not yet).
    generation: Option<u64>,
    cells: Vec<Probe>,
}

/// A cell's handles: its device's state, and a timer's or counter's
/// current value.
#[derive(Clone, Copy, Default)]
struct Probe {
    state: Option<engine::plc::Device>,
    value: Option<engine::plc::Device>,
}

/// A cell's live signals.
#[derive(Clone, Default)]
pub struct CellSlot {
    /// Its device's state on the running machine (`None`: no device).
    pub on: ArcRwSignal<Option<bool>>,
    /// Its power in the machine's last scan, while it runs the ladder as
    /// drawn.
    pub powered: ArcRwSignal<Option<bool>>,
    /// Its power changed in a scan since the last frame: how often its
    /// contact's device rose.
    pub pulsed: ArcRwSignal<Option<u32>>,
    /// A timer's or counter's current value, on its coil.
    pub value: ArcRwSignal<Option<i64>>,
}

impl RungView {
    /// The live slot of cell `index` (made when first asked for).
    pub fn slot(&self, index: usize) -> CellSlot {
        let Ok(mut slots) = self.slots.lock() else {
            return CellSlot::default();
        };
        if slots.len() <= index {
            slots.resize_with(index + 1, CellSlot::default);
        }
        slots[index].clone()
    }

    /// Sets each cell's value to `value_of(its place)`, touching only the
    /// signals whose value changes; nothing is allocated.
    fn update_each<T: PartialEq + Send + Sync + 'static>(
        &self,
        value_of: impl Fn(usize) -> Option<T>,
        field: impl Fn(&CellSlot) -> &ArcRwSignal<Option<T>>,
    ) {
        let Ok(slots) = self.slots.lock() else {
            return;
        };
        for (i, slot) in slots.iter().enumerate() {
            let new = value_of(i);
            let signal = field(slot);
            if signal.with_untracked(|old| *old != new) {
                signal.set(new);
            }
        }
    }

    /// This rung's probes, resolved on `plc` when they are not of
    /// `generation` (the drawing or the program changed since).
    fn probe<R>(
        &self,
        generation: u64,
        resolve: impl Fn(&super::model::CellData) -> Probe,
        f: impl FnOnce(&[Probe]) -> R,
    ) -> Option<R> {
        let mut probes = self.probes.lock().ok()?;
        if probes.generation != Some(generation) {
            let cells = self
                .data
                .with_untracked(|d| d.cells.iter().map(&resolve).collect());
            *probes = Probes {
                generation: Some(generation),
                cells,
            };
        }
        Some(f(&probes.cells))
    }
}

/// One problem of the ladder, where it is.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Problem {
    /// The rung (0-based).
    pub rung: usize,
    /// The cell, when it has one.
    pub pos: Option<Pos>,
    /// `rung 2, row 1, column 3: …` (1-based, the engine's words).
    pub text: String,
}

/// The device entry while it is open.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EntryState {
    /// What it places.
    pub kind: EntryKind,
    /// As an OR branch (Shift+F5 / Shift+F6).
    pub branch: bool,
    /// The cell it places at.
    pub at: Cursor,
    /// What is typed.
    pub text: String,
    /// Why the last commit was refused.
    pub error: Option<String>,
}

/// Where the editor sends the program: the machine's text pane and how
/// to load it into the machine.
#[derive(Clone, Copy)]
pub struct Program {
    /// The machine's text pane.
    pub text: RwSignal<String>,
    /// Loads the text pane into the machine (and saves it).
    pub load: Callback<()>,
    /// Saves the text pane (after the ladder changed it).
    pub save: Callback<()>,
    /// The machine's settings as a project keeps them (`T0` = `1100ms`).
    pub settings: Callback<(), Vec<(String, String)>>,
    /// Applies (and saves) settings from a project; returns the refusals.
    pub apply_settings: Callback<Vec<(String, String)>, Vec<String>>,
}

/// One machine's ladder editor; `Copy`. Its state comes in focused
/// parts, each `Copy`: the drawing, the panes, the program text, the
/// clipboard, the work (project, sharing, saving), the test cases, the
/// live view, the recording and "why".
#[derive(Clone, Copy)]
pub struct LadderCtx {
    /// The machine the ladder is for.
    pub machine: MachineId,
    /// The page (language, notices).
    pub page: Ctx,
    /// The ladder as drawn.
    pub drawing: Drawing,
    /// The device entry, the message and the panes shown.
    pub panes: Panes,
    /// The machine's program text and the compiler's settings.
    pub text: TextLink,
    /// This page's clipboard.
    pub clip: Clipboard,
    /// The project open, a shared one shown, the autosave.
    pub work: Work,
    /// The project's test cases.
    pub cases: Cases,
    /// The machine running the drawing: colours, watch, forcing, stepping.
    pub live: Live,
    /// The recording as shown: time travel, breaks, chart.
    pub travel: super::travel::TravelState,
    /// "Why is this cell off?".
    pub why: super::why::WhyState,
}

/// The ladder as drawn: the engine's [`Editor`] (outside the reactive
/// graph) and the signals the grid reads.
#[derive(Clone, Copy)]
pub struct Drawing {
    editor: StoredValue<Editor, LocalStorage>,
    next_id: StoredValue<u64>,
    /// The rungs, in order.
    pub rungs: RwSignal<Vec<RungView>>,
    /// The cursor (the rung after the last is the end line).
    pub cursor: RwSignal<Cursor>,
    /// The other corner of the selection, while there is one.
    pub anchor: RwSignal<Option<Cursor>>,
    /// The column outputs stand in.
    pub out_col: RwSignal<usize>,
    pub can_undo: RwSignal<bool>,
    pub can_redo: RwSignal<bool>,
    /// Counts the ladder's refreshes (an edit, undo, redo, a replaced
    /// ladder): views that follow the ladder's content without a signal of
    /// their own (the chart's devices) track it to follow at once.
    pub revision: RwSignal<u64>,
    /// The compiled program, when the ladder compiles.
    pub listing: RwSignal<Option<Listing>>,
    /// Every problem, rung by rung.
    pub problems: RwSignal<Vec<Problem>>,
    /// The ladder's device comments.
    pub comments: RwSignal<BTreeMap<String, String>>,
}

/// The device entry, the edit message and which panes are shown.
#[derive(Clone, Copy)]
pub struct Panes {
    /// The device entry, while open.
    pub entry: RwSignal<Option<EntryState>>,
    /// Why the last edit was refused.
    pub message: RwSignal<Option<String>>,
    /// The `?` key map is shown.
    pub help: RwSignal<bool>,
    /// The find / replace / cross-reference pane is shown.
    pub find_open: RwSignal<bool>,
    /// The projects pane is shown.
    pub projects_open: RwSignal<bool>,
    /// The Tests pane is shown.
    pub tests_open: RwSignal<bool>,
}

/// The machine's program text as the editor keeps it in step.
#[derive(Clone, Copy)]
pub struct TextLink {
    /// The program pane and loading.
    pane: StoredValue<Option<Program>>,
    /// The text last put in the pane from the ladder (or loaded from it):
    /// while the pane still holds it, the pane follows the ladder.
    synced: StoredValue<Option<String>>,
    /// The compiler's settings (the AVR scan period).
    pub options: RwSignal<Options>,
}

/// This page's clipboard, for when the system's is not offered.
#[derive(Clone, Copy)]
pub struct Clipboard {
    text: StoredValue<Option<String>>,
    /// Whether a paste event arrived since the last Ctrl+V.
    pub pasted: StoredValue<bool>,
}

/// The work edited here: the project open, a shared one shown, saving.
#[derive(Clone, Copy)]
pub struct Work {
    /// A shared project is shown, unsaved (docs/editor.md, "Share links").
    pub shared: RwSignal<bool>,
    /// The shared project's settings, applied when it is kept; and
    /// whether showing it replaced the ladder (so going back undoes it).
    shared_with: StoredValue<SharedWith>,
    /// The project open here (`None`: the machine's own ladder).
    pub project: RwSignal<Option<u64>>,
    /// Where the project is saved, and what another tab did there.
    pub saving: super::autosave::Autosave,
}

/// The project's test cases (docs/tests.md).
#[derive(Clone, Copy)]
pub struct Cases {
    /// The cases.
    pub tests: RwSignal<Vec<TestCase>>,
    /// The tests are an exercise: a link opens with them shown.
    pub exercise: RwSignal<bool>,
    /// The last run's result of each case (by index), when run.
    pub results: RwSignal<Vec<Option<CaseResult>>>,
    /// Inputs being recorded into a new case, while recording.
    recorder: StoredValue<Option<super::cases::Recorder>>,
}

/// The machine as the ladder shows it running: the drawing it runs, the
/// device handles, the watch table, forcing and stepping.
#[derive(Clone, Copy)]
pub struct Live {
    /// The ladder the machine runs, compiled with its source map, from
    /// Run until the next edit: the colours come from it.
    ladder: StoredValue<Option<engine::ladder::live::LiveLadder>>,
    /// Device handles on the machine, by name (cleared when the ladder or
    /// the program changes).
    handles: StoredValue<std::collections::HashMap<String, Option<engine::plc::Device>>>,
    /// Bumped when device handles are forgotten: rungs resolve their
    /// probes again.
    probe_generation: StoredValue<u64>,
    /// The watch table's devices and what they show.
    pub watch: RwSignal<Vec<String>>,
    pub watch_values: RwSignal<Vec<String>>,
    /// The step the last single step ran, and its rung.
    pub stepped: RwSignal<Option<(usize, Option<usize>)>>,
    /// The element the last single instruction came from.
    pub stepped_cell: RwSignal<Option<Cursor>>,
    /// Run was pressed: the machine runs the drawing (each edit is
    /// written to it at once) and a click on a contact drives its input
    /// (docs/editor.md, "Inputs from the ladder").
    pub monitor: RwSignal<bool>,
    /// The machine was running the drawing, and the drawing as it now
    /// stands cannot be written (it has errors): the ladder shows no live
    /// state until it can.
    pub unwritten: RwSignal<bool>,
    /// The machine is in RUN (as its last frame showed).
    pub running: RwSignal<bool>,
    /// Inputs held from the ladder at a value until released.
    pub forced: RwSignal<Vec<(String, bool)>>,
    /// The machine the ladder runs on (attached with its workspace).
    pub(super) link:
        StoredValue<Option<std::rc::Rc<dyn super::machine::MachineLink>>, LocalStorage>,
}

/// What a refresh follows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Change {
    /// Nothing was edited (a restore, a view change).
    Shown,
    /// An edit here: written to a machine that runs the drawing, saved.
    Edited,
    /// Another tab's save shown here: written to the machine, not saved
    /// again (it is what storage holds).
    Followed,
}

/// What showing a shared project set aside: its settings (applied when
/// kept), whether it replaced the ladder, and the cases it replaced.
#[derive(Clone, Debug, Default)]
struct SharedWith {
    settings: Vec<(String, String)>,
    replaced: bool,
    own_tests: Vec<TestCase>,
    own_exercise: bool,
}

/// How one case came out in the page.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CaseResult {
    /// Every expectation held.
    Pass,
    /// The first expectation that did not, and what was seen.
    Fail(String),
    /// The case could not run (a bad line, a device the machine lacks).
    Error(String),
}

impl LadderCtx {
    /// An editor for `machine` on `page`, restored from its autosave.
    pub fn restore(page: Ctx, machine: MachineId) -> LadderCtx {
        let (project, saved) = store::restore(page, machine);
        let (ladder, tests, exercise) = match saved {
            Some(p) => (Some(p.ladder), p.tests, p.exercise),
            None => (None, Vec::new(), false),
        };
        let ctx = LadderCtx {
            machine,
            page,
            drawing: Drawing {
                editor: StoredValue::new_local(Editor::new(ladder.clone().unwrap_or_default())),
                next_id: StoredValue::new(0),
                rungs: RwSignal::new(Vec::new()),
                cursor: RwSignal::new(Cursor::default()),
                anchor: RwSignal::new(None),
                out_col: RwSignal::new(COLUMNS - 1),
                can_undo: RwSignal::new(false),
                can_redo: RwSignal::new(false),
                revision: RwSignal::new(0),
                listing: RwSignal::new(None),
                problems: RwSignal::new(Vec::new()),
                comments: RwSignal::new(BTreeMap::new()),
            },
            panes: Panes {
                entry: RwSignal::new(None),
                message: RwSignal::new(None),
                help: RwSignal::new(false),
                find_open: RwSignal::new(false),
                projects_open: RwSignal::new(false),
                tests_open: RwSignal::new(exercise),
            },
            text: TextLink {
                pane: StoredValue::new(None),
                synced: StoredValue::new(None),
                options: RwSignal::new(Options::default()),
            },
            clip: Clipboard {
                text: StoredValue::new(None),
                pasted: StoredValue::new(true),
            },
            work: Work {
                shared: RwSignal::new(false),
                shared_with: StoredValue::new(SharedWith::default()),
                project: RwSignal::new(project),
                saving: super::autosave::Autosave::new(&store::slot(machine, project)),
            },
            cases: Cases {
                tests: RwSignal::new(tests),
                exercise: RwSignal::new(exercise),
                results: RwSignal::new(Vec::new()),
                recorder: StoredValue::new(None),
            },
            live: Live {
                ladder: StoredValue::new(None),
                handles: StoredValue::new(std::collections::HashMap::new()),
                probe_generation: StoredValue::new(0),
                watch: RwSignal::new(Vec::new()),
                watch_values: RwSignal::new(Vec::new()),
                stepped: RwSignal::new(None),
                stepped_cell: RwSignal::new(None),
                monitor: RwSignal::new(false),
                unwritten: RwSignal::new(false),
                running: RwSignal::new(false),
                forced: RwSignal::new(Vec::new()),
                link: StoredValue::new_local(None),
            },
            travel: super::travel::TravelState::new(),
            why: super::why::WhyState::new(),
        };
        ctx.refresh(false);
        ctx
    }

    /// The machine's settings as a project keeps them.
    pub fn settings(&self) -> Vec<(String, String)> {
        self.text
            .pane
            .get_value()
            .map(|p| p.settings.run(()))
            .unwrap_or_default()
    }

    /// Shows a shared project's ladder, unsaved, until it is kept or left.
    pub fn show_shared(&self, project: engine::ladder::Project) {
        if self.work.shared.get_untracked() {
            self.leave_shared();
        }
        self.work.shared.set(true);
        let own_tests = self.cases.tests.get_untracked();
        let own_exercise = self.cases.exercise.get_untracked();
        self.cases.tests.set(project.tests);
        self.cases.exercise.set(project.exercise);
        self.cases.results.set(Vec::new());
        if project.exercise {
            self.panes.tests_open.set(true);
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
        });
    }

    /// "Keep it": the shared ladder becomes this machine's ladder and is
    /// saved; the ladder saved before is set aside under a key of its own
    /// (named in the notice) and is one undo away.
    pub fn keep_shared(&self, projects: Option<super::projects::Projects>) {
        if !self.work.shared.get_untracked() {
            return;
        }
        let texts = super::texts::texts(self.page.lang.get_untracked());
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
        let refused = self
            .text
            .pane
            .get_value()
            .map(|p| p.apply_settings.run(settings))
            .unwrap_or_default();
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
    pub fn open_project(&self, id: Option<u64>, project: engine::ladder::Project) {
        self.set_project(id);
        self.cases.tests.set(project.tests);
        self.cases.exercise.set(project.exercise);
        self.cases.results.set(Vec::new());
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
        self.cases.tests.set(with.own_tests);
        self.cases.exercise.set(with.own_exercise);
        self.cases.results.set(Vec::new());
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
    fn set_project(&self, id: Option<u64>) {
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

    /// Shows a project saved by another tab, as an edit not saved again.
    fn show_saved(&self, json: &str) {
        let Ok(project) = engine::ladder::Project::from_json(json) else {
            return;
        };
        if project.machine != self.machine {
            return;
        }
        self.cases.tests.set(project.tests);
        self.cases.exercise.set(project.exercise);
        self.cases.results.set(Vec::new());
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
    pub fn keep_mine(&self, projects: super::projects::Projects) {
        let texts = super::texts::texts(self.page.lang.get_untracked());
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

    /// Connects the machine's text pane. The pane follows the ladder while
    /// it holds the ladder's listing or nothing; a fresh editor with no
    /// saved ladder starts from the pane's program when it decompiles.
    pub fn connect(&self, program: Program) {
        self.text.pane.set_value(Some(program));
        let text = program.text.get_untracked();
        let empty = self
            .drawing
            .editor
            .with_value(|e| e.ladder().rungs.is_empty());
        if empty && !text.trim().is_empty() {
            let scan = self.text.options.get_untracked().avr_scan_ms;
            if let Ok(ladder) = engine::ladder::decompile::decompile_text(self.machine, &text, scan)
            {
                self.drawing
                    .editor
                    .update_value(|e| *e = Editor::new(ladder));
                self.refresh(false);
            }
        }
        let listing = self
            .drawing
            .listing
            .with_untracked(|l| l.as_ref().map(|l| l.text.clone()));
        if text.trim().is_empty() || listing.as_deref() == Some(text.as_str()) || empty {
            self.text.synced.set_value(Some(text));
        }
    }

    /// The context provided for `machine`'s workspace.
    pub fn get() -> LadderCtx {
        expect_context::<LadderCtx>()
    }

    /// The ladder as it stands (a copy).
    pub fn ladder(&self) -> Ladder {
        self.drawing.editor.with_value(|e| e.ladder().clone())
    }

    /// Reads the editor without copying the ladder.
    pub fn with_editor<R>(&self, f: impl FnOnce(&Editor) -> R) -> R {
        self.drawing.editor.with_value(f)
    }

    /// Applies an edit to the editor; on success the message clears and
    /// the view is refreshed. The one place edits go in.
    fn try_apply(&self, edit: Edit) -> Result<(), engine::ladder::edit::EditError> {
        let result = self
            .drawing
            .editor
            .try_update_value(|e| e.apply(edit))
            .unwrap_or(Ok(()));
        if result.is_ok() {
            self.panes.message.set(None);
            self.refresh(true);
        }
        result
    }

    /// Applies an edit; a refusal is shown and changes nothing.
    pub fn apply(&self, edit: Edit) -> bool {
        match self.try_apply(edit) {
            Ok(()) => {
                self.drawing.anchor.set(None);
                true
            }
            Err(e) => {
                self.panes.message.set(Some(e.to_string()));
                false
            }
        }
    }

    /// Undoes the last edit.
    pub fn undo(&self) {
        if self
            .drawing
            .editor
            .try_update_value(Editor::undo)
            .unwrap_or(false)
        {
            self.drawing.anchor.set(None);
            self.refresh(true);
        }
    }

    /// Redoes the last undone edit.
    pub fn redo(&self) {
        if self
            .drawing
            .editor
            .try_update_value(Editor::redo)
            .unwrap_or(false)
        {
            self.drawing.anchor.set(None);
            self.refresh(true);
        }
    }

    /// Puts the cursor on a cell (a click, a problem, a find result).
    pub fn move_to(&self, to: Cursor) {
        self.drawing.editor.update_value(|e| e.move_to(to));
        self.drawing.anchor.set(None);
        self.drawing
            .cursor
            .set(self.drawing.editor.with_value(Editor::cursor));
    }

    /// Grows the selection to `to` (Shift+click).
    pub fn extend_to(&self, to: Cursor) {
        if self.drawing.anchor.get_untracked().is_none() {
            self.drawing
                .anchor
                .set(Some(self.drawing.cursor.get_untracked()));
        }
        self.drawing.editor.update_value(|e| e.move_to(to));
        self.drawing
            .cursor
            .set(self.drawing.editor.with_value(Editor::cursor));
    }

    /// The selection's corners, when there is one.
    pub fn selection(&self) -> Option<(Cursor, Cursor)> {
        let anchor = self.drawing.anchor.get_untracked()?;
        Some((anchor, self.drawing.cursor.get_untracked()))
    }

    /// A key on the ladder; false when the ladder leaves it alone.
    pub fn key(&self, key: &str, shift: bool, ctrl: bool, alt: bool) -> bool {
        match keys::action(key, shift, ctrl, alt) {
            Some(action) => {
                self.dispatch(action);
                true
            }
            None => false,
        }
    }

    /// Does what an action asks.
    pub fn dispatch(&self, action: Action) {
        let at = self.drawing.cursor.get_untracked();
        match action {
            Action::Move(mv, extend) => self.step(mv, extend),
            Action::Why => self.why.request.update(|n| *n += 1),
            Action::Entry {
                kind,
                branch,
                prefill,
            } => self.open_entry(kind, branch, prefill.to_string()),
            Action::EditCell => {
                let (kind, text) = self
                    .drawing
                    .editor
                    .with_value(|e| e.ladder().rungs.get(at.rung)?.get(at.pos()).map(entry_for))
                    .unwrap_or((EntryKind::Open, String::new()));
                self.open_entry(kind, false, text);
            }
            Action::Wire => {
                self.apply(Edit::Wire { at });
            }
            Action::ToggleLink => {
                self.apply(Edit::ToggleLink { at });
            }
            Action::DeleteWire => {
                self.apply(Edit::DeleteWire { at });
            }
            Action::DeleteLink => {
                self.apply(Edit::DeleteLink { at });
            }
            Action::Clear => {
                let edit = match self.selection() {
                    Some((a, b)) if a.rung == b.rung => Edit::ClearBlock { from: a, to: b },
                    Some((a, b)) => Edit::DeleteRungs {
                        first: a.rung.min(b.rung),
                        last: a.rung.max(b.rung).min(self.rung_count().saturating_sub(1)),
                    },
                    None => Edit::Clear { at },
                };
                self.apply(edit);
            }
            Action::InsertAbove => {
                self.apply(Edit::InsertRung { index: at.rung });
            }
            Action::InsertBelow => {
                let index = (at.rung + 1).min(self.rung_count());
                self.apply(Edit::InsertRung { index });
            }
            Action::DeleteRungs => {
                let (first, last) = match self.selection() {
                    Some((a, b)) => (a.rung.min(b.rung), a.rung.max(b.rung)),
                    None => (at.rung, at.rung),
                };
                let last = last.min(self.rung_count().saturating_sub(1));
                self.apply(Edit::DeleteRungs { first, last });
            }
            Action::RungUp | Action::RungDown => {
                self.apply(Edit::MoveRung {
                    index: at.rung,
                    up: action == Action::RungUp,
                });
            }
            Action::Undo => self.undo(),
            Action::Redo => self.redo(),
            // The clipboard events carry these; the keys only make sure a
            // copy works where the browser sends no event.
            Action::Copy => {
                self.copy_text();
            }
            Action::Cut | Action::Paste => {}
            Action::Find => self.panes.find_open.set(true),
            Action::Help => self.panes.help.update(|h| *h = !*h),
            Action::Cancel => {
                self.drawing.anchor.set(None);
                self.panes.help.set(false);
                self.panes.message.set(None);
            }
        }
    }

    fn rung_count(&self) -> usize {
        self.drawing.editor.with_value(|e| e.ladder().rungs.len())
    }

    fn step(&self, mv: Move, extend: bool) {
        let from = self.drawing.cursor.get_untracked();
        let to = self
            .drawing
            .editor
            .with_value(|e| keys::moved(e.ladder(), e.output_column(), from, mv));
        if extend {
            if self.drawing.anchor.get_untracked().is_none() {
                self.drawing.anchor.set(Some(from));
            }
        } else {
            self.drawing.anchor.set(None);
        }
        self.drawing.editor.update_value(|e| e.move_to(to));
        self.drawing.cursor.set(to);
    }

    /// Opens the device entry at the cursor.
    pub fn open_entry(&self, kind: EntryKind, branch: bool, text: String) {
        self.panes.entry.set(Some(EntryState {
            kind,
            branch,
            at: self.drawing.cursor.get_untracked(),
            text,
            error: None,
        }));
    }

    /// Enter in the device entry: the element goes in when the machine
    /// has it; otherwise the entry stays open with the engine's message.
    pub fn commit_entry(&self) -> bool {
        let Some(state) = self.panes.entry.get_untracked() else {
            return false;
        };
        let refuse = |message: String| {
            self.panes.entry.update(|e| {
                if let Some(e) = e {
                    e.error = Some(message);
                }
            });
            false
        };
        let element = match parse_entry(self.machine, state.kind, &state.text) {
            Ok(e) => e,
            Err(e) => return refuse(e.to_string()),
        };
        let edit = if state.branch {
            Edit::PlaceBranch {
                at: state.at,
                element,
            }
        } else {
            Edit::Place {
                at: state.at,
                element,
            }
        };
        match self.try_apply(edit) {
            Ok(()) => {
                self.panes.entry.set(None);
                true
            }
            Err(e) => refuse(e.to_string()),
        }
    }

    /// Places `element` at the cursor without the entry (the palette's
    /// wire, NOT, R_TRIG).
    pub fn place(&self, element: Element) -> bool {
        let at = self.drawing.cursor.get_untracked();
        self.apply(Edit::Place { at, element })
    }

    /// The selection (or the cursor's cell) as clipboard text, also kept
    /// as this page's clipboard.
    pub fn copy_text(&self) -> Option<String> {
        let at = self.drawing.cursor.get_untracked();
        let clip = self.drawing.editor.with_value(|e| match self.selection() {
            Some((a, b)) if a.rung == b.rung => Clip::cells(e.ladder(), a, b),
            Some((a, b)) => {
                let last = a
                    .rung
                    .max(b.rung)
                    .min(e.ladder().rungs.len().saturating_sub(1));
                Clip::rungs(e.ladder(), a.rung.min(b.rung), last)
            }
            None => Clip::cells(e.ladder(), at, at),
        });
        match clip {
            Ok(clip) => {
                let text = clip.to_text();
                self.clip.text.set_value(Some(text.clone()));
                Some(text)
            }
            Err(e) => {
                self.panes.message.set(Some(e.to_string()));
                None
            }
        }
    }

    /// Cut: copies, then clears what was copied.
    pub fn cut_text(&self) -> Option<String> {
        let text = self.copy_text()?;
        self.dispatch(Action::Clear);
        Some(text)
    }

    /// Pastes clipboard text at the cursor (this page's clipboard when
    /// `text` is `None`); what the machine lacks is refused, all of it.
    pub fn paste_text(&self, text: Option<String>) {
        let Some(text) = text.or_else(|| self.clip.text.get_value()) else {
            return;
        };
        let clip = match Clip::from_text(&text) {
            Ok(c) => c,
            Err(e) => {
                self.panes.message.set(Some(e.to_string()));
                return;
            }
        };
        match clip.for_machine(self.machine) {
            Ok(clip) => {
                let at = self.drawing.cursor.get_untracked();
                self.apply(Edit::Paste { at, clip });
            }
            Err(errors) => {
                let all: Vec<String> = errors.iter().map(ToString::to_string).collect();
                self.panes.message.set(Some(all.join("; ")));
            }
        }
    }

    /// The ladder of a program in the machine's text, drawn with its
    /// outputs in the output column; the engine's located error if not.
    pub fn ladder_of_text(&self, text: &str) -> Result<Ladder, String> {
        let scan = self.text.options.get_untracked().avr_scan_ms;
        let ladder = engine::ladder::decompile::decompile_text(self.machine, text, scan)
            .map_err(|e| e.to_string())?;
        Ok(align_outputs(&ladder, COLUMNS - 1))
    }

    /// "Load as ladder": the text pane's program becomes the ladder
    /// (one undo brings the old one back); the engine's located error
    /// otherwise, with nothing changed.
    pub fn load_text_as_ladder(&self) -> Result<(), String> {
        let Some(program) = self.text.pane.get_value() else {
            return Err("no program pane".into());
        };
        let text = program.text.get_untracked();
        let ladder = self.ladder_of_text(&text)?;
        // The pane holds the same program: it follows the ladder again.
        self.text.synced.set_value(Some(text));
        if self.ladder() != ladder {
            self.apply(Edit::Replace { ladder });
        }
        Ok(())
    }

    /// The text pane's program is the ladder's (it was opened from the
    /// same example): the pane follows the ladder from now on.
    pub fn adopt_text(&self) {
        if let Some(program) = self.text.pane.get_value() {
            self.text
                .synced
                .set_value(Some(program.text.get_untracked()));
        }
    }

    /// The drawing written to the machine with its source map for the
    /// live colours ([`LadderCtx::start_live`], then
    /// [`LadderCtx::write_to_machine`]): what Run, Write to PLC and an edit
    /// while running do. False while it does not compile.
    pub fn write_drawing(&self) -> bool {
        self.start_live() && self.write_to_machine()
    }

    /// The listing goes into the text pane and is loaded into the machine.
    /// False while the ladder does not compile.
    fn write_to_machine(&self) -> bool {
        let Some(listing) = self.drawing.listing.get_untracked() else {
            return false;
        };
        let Some(program) = self.text.pane.get_value() else {
            return false;
        };
        program.text.set(listing.text.clone());
        self.text.synced.set_value(Some(listing.text));
        program.load.run(());
        self.forget_handles();
        true
    }

    /// Re-reads the editor into the signals: problems and listing, the
    /// rungs whose drawing changed, cursor, undo state; then the text pane
    /// (when `edited` and it follows the ladder) and the autosave.
    pub fn refresh(&self, edited: bool) {
        self.refresh_as(if edited {
            Change::Edited
        } else {
            Change::Shown
        });
    }

    fn refresh_as(&self, change: Change) {
        let edited = change != Change::Shown;
        let options = self.text.options.get_untracked();
        let (listing, errors, out_col, comments, cursor, undo, redo) =
            self.drawing.editor.with_value(|e| {
                let (listing, errors) = match compile_listing(e.ladder(), self.machine, options) {
                    Ok(l) => (Some(l), Vec::new()),
                    Err(errors) => (None, errors),
                };
                (
                    listing,
                    errors,
                    e.output_column(),
                    e.ladder().device_comments.clone(),
                    e.cursor(),
                    e.can_undo(),
                    e.can_redo(),
                )
            });
        let problems: Vec<Problem> = errors
            .iter()
            .map(|err| Problem {
                rung: err.rung.saturating_sub(1),
                pos: err.pos,
                text: err.to_string(),
            })
            .collect();
        self.repaint(&problems, out_col, &comments, listing.as_ref());
        self.drawing.out_col.set(out_col);
        if self.drawing.comments.with_untracked(|c| *c != comments) {
            self.drawing.comments.set(comments);
        }
        if self.drawing.cursor.get_untracked() != cursor {
            self.drawing.cursor.set(cursor);
        }
        self.drawing.can_undo.set(undo);
        self.drawing.can_redo.set(redo);
        if self.drawing.problems.with_untracked(|p| *p != problems) {
            self.drawing.problems.set(problems);
        }
        // Before the drawing is written: writing takes the listing.
        if self.drawing.listing.with_untracked(|l| *l != listing) {
            self.drawing.listing.set(listing.clone());
        }
        if edited {
            self.live.ladder.set_value(None);
            // The machine runs the drawing: written at once, so what the
            // ladder shows is what runs (docs/editor.md, "The run model").
            let follows = self.live.monitor.get_untracked() || self.live.unwritten.get_untracked();
            if follows {
                let written = listing.is_some() && self.write_drawing();
                if !written && self.live.monitor.get_untracked() {
                    self.live.monitor.set(false);
                }
                if self.live.unwritten.get_untracked() == written {
                    self.live.unwritten.set(!written);
                }
            }
        }
        // A shared project is not saved until it is kept.
        if edited && !self.work.shared.get_untracked() {
            self.follow(listing.as_ref());
            if change == Change::Edited {
                self.save();
            }
        }
        self.drawing.revision.update(|n| *n += 1);
    }

    /// The project as it stands: the ladder, its cases, the exercise flag.
    pub fn project_now(&self) -> engine::ladder::Project {
        let mut project = engine::ladder::Project::new(self.machine, self.ladder());
        project.tests = self.cases.tests.get_untracked();
        project.exercise = self.cases.exercise.get_untracked();
        project
    }

    /// Autosaves the project (not while a shared one is shown).
    pub fn save(&self) {
        if !self.work.shared.get_untracked() {
            self.work.saving.save(&self.project_now().to_json());
        }
    }

    /// Starts recording the inputs the user changes into a new case.
    pub fn start_recording(&self, plc: &dyn engine::plc::Plc) {
        let rec = super::cases::Recorder::new(&self.ladder(), plc);
        self.cases.recorder.set_value(Some(rec));
    }

    /// Whether inputs are being recorded.
    pub fn recording(&self) -> bool {
        self.cases.recorder.with_value(Option::is_some)
    }

    /// Each frame while recording: notes the inputs that changed.
    pub fn observe(&self, plc: &dyn engine::plc::Plc) {
        self.cases.recorder.update_value(|r| {
            if let Some(r) = r {
                r.observe(plc);
            }
        });
    }

    /// Stops recording; the timeline becomes a new case, with what the
    /// outputs show now as its expectations.
    pub fn stop_recording(&self, plc: &dyn engine::plc::Plc) {
        let Some(rec) = self.cases.recorder.get_value() else {
            return;
        };
        self.cases.recorder.set_value(None);
        let n = self.cases.tests.with_untracked(Vec::len) + 1;
        let case = rec.finish(plc, &format!("recorded {n}"));
        self.cases.tests.update(|t| t.push(case));
        self.cases.results.update(|r| r.push(None));
        self.save();
    }

    /// The device `name` on `plc`, resolved once.
    fn handle(&self, plc: &dyn engine::plc::Plc, name: &str) -> Option<engine::plc::Device> {
        if let Some(h) = self.live.handles.with_value(|m| m.get(name).copied()) {
            return h;
        }
        let h = plc.device(name).ok();
        self.live.handles.update_value(|m| {
            m.insert(name.to_string(), h);
        });
        h
    }

    /// Run: the ladder compiled with its source map becomes what the
    /// colours are read against; false (with the problems shown) when it
    /// does not compile.
    fn start_live(&self) -> bool {
        let options = self.text.options.get_untracked();
        let live = self.drawing.editor.with_value(|e| {
            engine::ladder::live::LiveLadder::new(e.ladder(), self.machine, options)
        });
        match live {
            Ok(l) => {
                self.live.ladder.set_value(Some(l));
                self.live.monitor.set(true);
                true
            }
            Err(_) => false,
        }
    }

    /// Runs `f` with the ladder the machine runs (compiled at Run), if any.
    pub fn with_live<R>(
        &self,
        f: impl FnOnce(Option<&engine::ladder::live::LiveLadder>) -> R,
    ) -> R {
        self.live.ladder.with_value(|l| f(l.as_ref()))
    }

    /// Each frame: every contact's and coil's device state as the
    /// machine's last scan left it (`data-on`), every cell's power in
    /// that scan as the machine computed it (`data-powered`, while it runs
    /// the ladder as drawn), and the watch table. Only the rungs whose
    /// states changed are touched.
    pub fn show_live(&self, plc: &dyn engine::plc::Plc) {
        // A drawing that cannot be written shows nothing live: the states
        // would be another program's.
        let in_run = plc.running();
        if self.live.running.get_untracked() != in_run {
            self.live.running.set(in_run);
        }
        let running = plc.scans() > 0 && !self.live.unwritten.get_untracked();
        let powers: Vec<(usize, Vec<(Pos, bool)>)> = match plc.trace() {
            Some(trace) => self.live.ladder.with_value(|l| {
                l.as_ref().map_or_else(Vec::new, |l| {
                    l.power(trace)
                        .into_iter()
                        .map(|(i, r)| (i, r.iter().map(|e| (e.pos, e.power_out)).collect()))
                        .collect()
                })
            }),
            None => Vec::new(),
        };
        let generation = self.live.probe_generation.get_value();
        let resolve = |c: &super::model::CellData| {
            let look = c.kind.look();
            if c.device.is_empty() {
                return Probe::default();
            }
            let counts =
                look.shows_value && (c.device.starts_with('T') || c.device.starts_with('C'));
            Probe {
                state: look
                    .shows_state
                    .then(|| self.handle(plc, &c.device))
                    .flatten(),
                value: counts
                    .then(|| self.handle(plc, &format!("{}.v", c.device)))
                    .flatten(),
            }
        };
        for view in self.drawing.rungs.get_untracked() {
            let number = view.number.get_untracked();
            match powers.iter().find(|(i, _)| *i == number) {
                Some((_, p)) => view.data.with_untracked(|d| {
                    view.update_each(|i| super::model::power_of(d, p, i), |s| &s.powered)
                }),
                None => view.update_each(|_| None, |s| &s.powered),
            }
            view.probe(generation, resolve, |probes| {
                let probe = |i: usize| probes.get(i).copied().unwrap_or_default();
                view.update_each(
                    |i| {
                        running
                            .then(|| probe(i).state.map(|h| plc.read(h).is_on()))
                            .flatten()
                    },
                    |s| &s.on,
                );
                view.update_each(
                    |i| {
                        running
                            .then(|| probe(i).value.map(|h| plc.read(h).as_i64()))
                            .flatten()
                    },
                    |s| &s.value,
                );
            });
        }
        let values: Vec<String> = self.live.watch.with_untracked(|w| {
            w.iter()
                .map(|name| {
                    let value = self.handle(plc, name).map(|h| plc.read(h));
                    let current = self.handle(plc, &format!("{name}.v")).map(|h| plc.read(h));
                    let preset = self.preset_of(name);
                    match (value, current) {
                        (Some(v), Some(c)) => match preset {
                            Some(k) => format!("{v} ({c}/K{k})"),
                            None => format!("{v} ({c})"),
                        },
                        (Some(v), None) => v.to_string(),
                        (None, Some(c)) => c.to_string(),
                        (None, None) => "?".to_string(),
                    }
                })
                .collect()
        });
        if self.live.watch_values.with_untracked(|old| *old != values) {
            self.live.watch_values.set(values);
        }
    }

    /// Each frame: marks every cell whose power changed in some scan since
    /// the last frame, so a one-scan pulse shows at any speed.
    pub fn show_pulses(&self, history: &engine::plc::TraceHistory) {
        let pulses = self
            .live
            .ladder
            .with_value(|l| l.as_ref().map(|l| l.pulses(history)));
        let pulses = pulses.unwrap_or_default();
        for view in self.drawing.rungs.get_untracked() {
            let number = view.number.get_untracked();
            match pulses.iter().find(|(i, _)| *i == number) {
                Some((_, found)) if !found.is_empty() => view.data.with_untracked(|d| {
                    let rises = |i: usize| {
                        let c = d.cells.get(i)?;
                        found
                            .iter()
                            .find(|p| p.pos.row == c.row && p.pos.col == c.col)
                            .map(|p| p.rises)
                    };
                    view.update_each(rises, |s| &s.pulsed);
                }),
                _ => view.update_each(|_| None, |s| &s.pulsed),
            }
        }
    }

    /// The element step `step` reads or computes, by the source map.
    pub fn cell_of_step(&self, step: usize) -> Option<Cursor> {
        self.drawing.listing.with_untracked(|l| {
            let l = l.as_ref()?;
            let s = l
                .sources
                .iter()
                .find(|s| l.step_at_line(s.line) == Some(step))?;
            Some(Cursor::new(s.rung, s.pos.row, s.pos.col))
        })
    }

    /// The set value the ladder gives timer or counter `device`, if any.
    fn preset_of(&self, device: &str) -> Option<u16> {
        self.drawing.editor.with_value(|e| {
            e.ladder()
                .rungs
                .iter()
                .flat_map(|r| r.elements())
                .find_map(|(_, el)| match el {
                    Element::TimerCoil { device: d, preset }
                    | Element::CounterCoil { device: d, preset }
                        if d == device =>
                    {
                        Some(*preset)
                    }
                    _ => None,
                })
        })
    }

    /// Forgets resolved device handles (a new program was loaded).
    pub fn forget_handles(&self) {
        self.live
            .handles
            .update_value(std::collections::HashMap::clear);
        self.live.probe_generation.update_value(|g| *g += 1);
    }

    /// The text pane takes the new listing while it still holds the last.
    fn follow(&self, listing: Option<&Listing>) {
        let (Some(program), Some(listing)) = (self.text.pane.get_value(), listing) else {
            return;
        };
        let text = program.text.get_untracked();
        let follows = self
            .text
            .synced
            .with_value(|s| s.as_deref() == Some(text.as_str()));
        if follows && text != listing.text {
            program.text.set(listing.text.clone());
            self.text.synced.set_value(Some(listing.text.clone()));
            program.save.run(());
        }
    }

    /// Updates the rung views: same-drawn rungs keep theirs, edited ones
    /// get new data (their changed cells redraw), new ones are made.
    fn repaint(
        &self,
        problems: &[Problem],
        out_col: usize,
        comments: &BTreeMap<String, String>,
        listing: Option<&Listing>,
    ) {
        let data: Vec<RungData> = self.drawing.editor.with_value(|e| {
            e.ladder()
                .rungs
                .iter()
                .enumerate()
                .map(|(i, rung)| {
                    let errors: Vec<(Option<Pos>, String)> = problems
                        .iter()
                        .filter(|p| p.rung == i)
                        .map(|p| (p.pos, p.text.clone()))
                        .collect();
                    rung_data(rung, out_col, &errors, comments)
                })
                .collect()
        });
        let old = self.drawing.rungs.get_untracked();
        let plan = {
            let guards: Vec<_> = old.iter().map(|v| v.data.read_untracked()).collect();
            let refs: Vec<&RungData> = guards.iter().map(|g| &**g).collect();
            reuse(&refs, &data)
        };
        let mut views = Vec::with_capacity(data.len());
        for (number, (d, from)) in data.into_iter().zip(plan).enumerate() {
            let first = listing.and_then(|l| l.steps_of(number).map(|s| s.start));
            let view = match from {
                Some(i) => {
                    let v = old[i].clone();
                    if v.data.with_untracked(|old| *old != d) {
                        v.data.set(d);
                        if let Ok(mut p) = v.probes.lock() {
                            p.generation = None;
                        }
                    }
                    v
                }
                None => {
                    let id = self.drawing.next_id.get_value();
                    self.drawing.next_id.set_value(id + 1);
                    RungView {
                        id,
                        number: ArcRwSignal::new(number),
                        first_step: ArcRwSignal::new(first),
                        data: ArcRwSignal::new(d),
                        slots: Default::default(),
                        probes: Default::default(),
                    }
                }
            };
            if view.number.get_untracked() != number {
                view.number.set(number);
            }
            if view.first_step.get_untracked() != first {
                view.first_step.set(first);
            }
            views.push(view);
        }
        let same_order =
            views.len() == old.len() && views.iter().zip(&old).all(|(a, b)| a.id == b.id);
        if !same_order {
            self.drawing.rungs.set(views);
        }
    }
}
