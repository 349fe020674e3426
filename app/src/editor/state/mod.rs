//! One machine's ladder editor: the engine's [`Editor`] outside the
//! reactive graph, and the signals the view reads (one per rung, the
//! cursor, the listing, the problems). Every key, click and drop comes
//! here as an [`Action`] or an edit; after each change the ladder is
//! checked and compiled, the changed rungs repainted, the text pane
//! kept in step and the project autosaved.
//!
//! - this file: [`LadderCtx`] and its focused states, edits, refresh;
//! - [`rung_view`]: each rung's signals and its cells' live slots;
//! - [`actions`]: keys, the device entry, the clipboard;
//! - [`work`]: projects, shared links, the autosave and other tabs;
//! - [`text`]: the machine's program text kept in step with the ladder;
//! - [`live`]: the running machine shown on the ladder, recording cases.

mod actions;
mod classroom;
mod clock;
mod live;
mod rung_view;
mod text;
mod work;

pub use classroom::CaseResult;

pub use clock::Clock;
pub use live::Live;
use rung_view::Probe;
pub use rung_view::{CellSlot, EntryState, Problem, RungView};
use work::SharedWith;

use std::collections::BTreeMap;

use engine::cases::TestCase;
use engine::formats::project::ProgramText;
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
    /// The program text a project keeps beside the ladder (the soft
    /// PLC's Structured Text, issue #55); `None` for the others.
    pub source: Callback<(), Option<ProgramText>>,
    /// Takes a project's program text.
    pub apply_source: Callback<ProgramText>,
    /// Why? into Structured Text (issue #55): for a box of an ST block
    /// (its kind, its instance), the block's statements that wrote the
    /// output its power leaves by, with their operands' values; empty
    /// for every machine but the soft PLC.
    pub why_st: Callback<(String, String), Vec<crate::editor::panes::why::StCause>>,
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
    /// The soft PLC's declared variables (the variables pane).
    pub variables: RwSignal<Vec<engine::ladder::Variable>>,
    /// Each column's width (rem) over the whole ladder, so that the rungs
    /// line up and a contact's column is narrower than a box's.
    pub col_widths: RwSignal<Vec<f64>>,
    /// The inputs the ladder's contacts read and the outputs its coils
    /// write, in order of first use (the phone's strip).
    pub io: RwSignal<Vec<crate::editor::strip::IoPoint>>,
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
    /// A file read and waiting for its import dialog's answers.
    pub import: RwSignal<Option<crate::editor::import::Pending>>,
    /// The ladder's zoom (1.0: 100 %), see [`zoom`](crate::editor::zoom).
    pub zoom: RwSignal<f64>,
}

impl Panes {
    /// Shows one of the sheets (Projects, Find), closing the other:
    /// they open in the same place.
    pub fn show(&self, which: RwSignal<bool>) {
        for pane in [self.projects_open, self.find_open] {
            if pane != which && pane.get_untracked() {
                pane.set(false);
            }
        }
        which.set(true);
    }

    /// Shows `which` (see [`Panes::show`]), or closes it when it is shown.
    pub fn toggle(&self, which: RwSignal<bool>) {
        if which.get_untracked() {
            which.set(false);
        } else {
            self.show(which);
        }
    }
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
    /// Settings a project or file brought before the machine arrived with
    /// its part (issue #53): applied when its program pane connects.
    queued: StoredValue<Vec<(String, String)>>,
    /// A project's program text that came before its machine did.
    queued_source: StoredValue<Option<ProgramText>>,
    /// Nothing was saved for this editor and nothing opened or edited in
    /// it since: when its program pane connects (its machine arrived), the
    /// ladder starts from the pane's program.
    fresh: StoredValue<bool>,
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
    /// Bumped at each clean slate (another project opened, imported or
    /// begun): views with state of their own (the chart) start afresh.
    pub slate: RwSignal<u64>,
    /// What the ladder shown came from, when it is not a saved project:
    /// the file opened or the example (English, Japanese), for the app
    /// bar's title; `None` after New and on a clean slate.
    pub title: RwSignal<Option<(String, String)>>,
}

/// The project's test cases (docs/tests.md).
#[derive(Clone, Copy)]
pub struct Cases {
    /// The cases.
    pub tests: RwSignal<Vec<TestCase>>,
    /// The tests are an exercise (its task, whether they are hidden): a
    /// link opens with it shown (docs/tests.md, "Exercises").
    pub exercise: RwSignal<Option<engine::formats::project::Exercise>>,
    /// The author's view of an exercise: its task and tests editable.
    /// Off, an exercise shows the student's view.
    pub authoring: RwSignal<bool>,
    /// The project's plant, its wiring, parameters and faults: kept and
    /// saved with the project, not yet shown (issue #52).
    pub plant: RwSignal<Option<engine::formats::project::PlantSetup>>,
    /// The last run's result of each case (by index), when run.
    pub results: RwSignal<Vec<Option<CaseResult>>>,
    /// The fault a student names where the plant hides one
    /// (`fault-report`), and whether the last check found it right.
    pub report: RwSignal<(Option<String>, Option<bool>)>,
    /// Inputs being recorded into a new case, while recording.
    recorder: StoredValue<Option<super::cases::Recorder>>,
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

impl LadderCtx {
    /// An editor for `machine` on `page`, restored from its autosave.
    pub fn restore(page: Ctx, machine: MachineId) -> LadderCtx {
        let (project, saved) = store::restore(page, machine);
        let (ladder, tests, exercise, plant) = match saved {
            Some(p) => (Some(p.ladder), p.tests, p.exercise, p.plant),
            None => (None, Vec::new(), None, None),
        };
        if exercise.is_some() && page.machine.get_untracked() == machine {
            // An exercise opens with its tests shown.
            page.docks.show(crate::docks::Tool::Tests);
        }
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
                variables: RwSignal::new(Vec::new()),
                col_widths: RwSignal::new(vec![super::columns::WIRE_COL_REM; COLUMNS]),
                io: RwSignal::new(Vec::new()),
            },
            panes: Panes {
                entry: RwSignal::new(None),
                message: RwSignal::new(None),
                help: RwSignal::new(false),
                find_open: RwSignal::new(false),
                projects_open: RwSignal::new(false),
                import: RwSignal::new(None),
                zoom: RwSignal::new(1.0),
            },
            text: TextLink {
                pane: StoredValue::new(None),
                synced: StoredValue::new(None),
                options: RwSignal::new(Options::default()),
                queued: StoredValue::new(Vec::new()),
                queued_source: StoredValue::new(None),
                fresh: StoredValue::new(ladder.is_none()),
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
                slate: RwSignal::new(0),
                title: RwSignal::new(None),
            },
            cases: Cases {
                tests: RwSignal::new(tests),
                exercise: RwSignal::new(exercise),
                plant: RwSignal::new(plant),
                authoring: RwSignal::new(false),
                results: RwSignal::new(Vec::new()),
                report: RwSignal::new((None, None)),
                recorder: StoredValue::new(None),
            },
            live: Live::new(),
            travel: super::travel::TravelState::new(),
            why: super::why::WhyState::new(),
        };
        ctx.refresh(false);
        ctx
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

    /// Applies an edit; a refusal is returned (for a pane that shows
    /// it itself) and changes nothing.
    pub fn try_edit(&self, edit: Edit) -> Result<(), String> {
        let lang = self.page.lang.get_untracked();
        let done = self
            .try_apply(edit)
            .map_err(|e| crate::i18n::errors::edit_error(lang, &e));
        if done.is_ok() {
            self.drawing.anchor.set(None);
        }
        done
    }

    /// Applies an edit; a refusal is shown and changes nothing.
    pub fn apply(&self, edit: Edit) -> bool {
        match self.try_apply(edit) {
            Ok(()) => {
                self.drawing.anchor.set(None);
                true
            }
            Err(e) => {
                let lang = self.page.lang.get_untracked();
                let said = crate::i18n::errors::edit_error(lang, &e);
                self.panes.message.set(Some(said));
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
        if edited {
            self.text.fresh.set_value(false);
        }
        let options = self.text.options.get_untracked();
        let (listing, errors, out_col, comments, cursor, undo, redo, variables) =
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
                    e.ladder().variables.clone(),
                )
            });
        let problems: Vec<Problem> = errors
            .iter()
            .map(|err| Problem {
                rung: err.rung.saturating_sub(1),
                pos: err.pos,
                text: err.to_string(),
                ja: crate::i18n::engine::ladder_error(crate::i18n::Lang::Ja, err),
            })
            .collect();
        self.repaint(&problems, out_col, &comments, listing.as_ref());
        self.drawing.out_col.set(out_col);
        if self.drawing.comments.with_untracked(|c| *c != comments) {
            self.drawing.comments.set(comments);
        }
        crate::state::put(self.drawing.variables, variables);
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

    /// Updates the rung views: same-drawn rungs keep theirs, edited ones
    /// get new data (their changed cells redraw), new ones are made.
    fn repaint(
        &self,
        problems: &[Problem],
        out_col: usize,
        comments: &BTreeMap<String, String>,
        listing: Option<&Listing>,
    ) {
        // A cell's tooltip says its problem in the page's language of the
        // moment (issue #49).
        let ja = self.page.lang.get_untracked() == crate::i18n::Lang::Ja;
        let data: Vec<RungData> = self.drawing.editor.with_value(|e| {
            e.ladder()
                .rungs
                .iter()
                .enumerate()
                .map(|(i, rung)| {
                    let errors: Vec<(Option<Pos>, String)> = problems
                        .iter()
                        .filter(|p| p.rung == i)
                        .map(|p| (p.pos, if ja { &p.ja } else { &p.text }.clone()))
                        .collect();
                    rung_data(rung, out_col, &errors, comments)
                })
                .collect()
        });
        let cols = out_col + 1;
        let widths = super::columns::column_widths(&data.iter().collect::<Vec<_>>(), cols);
        crate::state::put(self.drawing.col_widths, widths);
        let io = self
            .drawing
            .editor
            .with_value(|e| crate::editor::strip::io_points(e.ladder()));
        crate::state::put(self.drawing.io, io);
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
                    RungView::new(id, number, first, d)
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
