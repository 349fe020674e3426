//! Structured Text in the soft PLC's workspace (issue #55): the pane's
//! language, the ST text (saved apart from the IL text, which follows the
//! ladder), the program loaded from it (or the ladder calling its
//! blocks) with each step's ST line and call, and breakpoints. What the
//! pane shows while it runs is `st_online`'s.

use std::collections::BTreeSet;

use engine::machines::SoftPlc;
use engine::plc::{Device, Plc};
use engine::softplc::st::StBlocks;
use engine::softplc::st_online::StMap;
use leptos::prelude::*;

use crate::sim::Simulator;
use crate::state::{put, Ctx};
use crate::storage;

/// Where the ST text is saved (`SavedText`).
const TEXT_KEY: &str = "hashigo.soft-plc.st.v1";
/// Where the ST text before a project's is set aside.
const SET_ASIDE_KEY: &str = "hashigo.soft-plc.st.set-aside.v1";
/// Where the pane's language is saved: `st`, or absent for IL (every
/// save from before issue #55 reads as IL, as it was).
const LANGUAGE_KEY: &str = "hashigo.soft-plc.language.v1";

pub(super) type Sim = StoredValue<Simulator<SoftPlc>, LocalStorage>;

/// A name a line uses, as shown (`count`), as the machine names it
/// (`c0.count` in instance `c0`'s call), and its handle.
pub(super) type Named = (String, String, Device);

/// A line (1-based), the instance whose values it shows (`None`: the
/// program's own line), and the names it uses.
pub(super) type LineNames = (usize, Option<usize>, Vec<Named>);

/// The ST side of the soft PLC's workspace.
#[derive(Clone, Copy)]
pub struct StState {
    pub(super) page: Ctx,
    /// The pane shows (and Load, Run load) the ST text.
    pub on: RwSignal<bool>,
    pub text: RwSignal<String>,
    /// Each step of the program loaded with its ST line and the instance
    /// whose call runs it (empty while no ST is loaded: an IL program, a
    /// ladder calling no ST block).
    pub(super) map: StoredValue<StMap>,
    /// The text the map's lines are of (the ST program loaded, or the
    /// blocks' text the ladder was compiled with).
    pub(super) source: StoredValue<String>,
    /// The names each line of the program loaded uses, with their
    /// handles: a block's lines once per instance.
    pub(super) devices: StoredValue<Vec<LineNames>>,
    /// The text and blocks last declared to the ladder.
    declared: StoredValue<Option<(String, StBlocks)>>,
    /// The program's instances of the text's blocks: (name, block).
    pub instances: RwSignal<Vec<(String, String)>>,
    /// The instance chosen to show (empty: each block's first).
    pub chosen: RwSignal<String>,
    /// The instance whose call the scan stood in at the last look.
    pub(super) standing: StoredValue<Option<usize>>,
    /// The values shown beside the lines: (line, `a = 1  b = TRUE`).
    pub values: RwSignal<Vec<(usize, String)>>,
    /// The lines shown (first, last; 1-based): only their values are read.
    pub visible: RwSignal<(usize, usize)>,
    pub breakpoints: RwSignal<BTreeSet<usize>>,
    /// The line the scan stands before, while a scan is stepped.
    pub current: RwSignal<Option<usize>>,
    /// The instance whose call that line runs in, if any.
    pub current_call: RwSignal<Option<String>>,
    /// A breakpoint stopped the scan (until it runs on).
    pub hit: RwSignal<bool>,
    /// The ladder, checked again when the text's blocks change.
    ladder: StoredValue<Option<crate::editor::LadderCtx>>,
}

impl StState {
    /// The saved ST text and language.
    pub fn restore(page: Ctx) -> StState {
        let text = crate::machines::restored_text(page, TEXT_KEY, "", "");
        StState {
            page,
            on: RwSignal::new(storage::saved_string(LANGUAGE_KEY).as_deref() == Some("st")),
            text: RwSignal::new(text),
            map: StoredValue::new(StMap::default()),
            source: StoredValue::new(String::new()),
            devices: StoredValue::new(Vec::new()),
            declared: StoredValue::new(None),
            instances: RwSignal::new(Vec::new()),
            chosen: RwSignal::new(String::new()),
            standing: StoredValue::new(None),
            values: RwSignal::new(Vec::new()),
            visible: RwSignal::new((1, 60)),
            breakpoints: RwSignal::new(BTreeSet::new()),
            current: RwSignal::new(None),
            current_call: RwSignal::new(None),
            hit: RwSignal::new(false),
            ladder: StoredValue::new(None),
        }
    }

    /// The ladder the text's function blocks are boxes of: declared from
    /// the saved text now, if it loads.
    pub fn attach(&self, ladder: crate::editor::LadderCtx) {
        self.ladder.set_value(Some(ladder));
        let text = self.text.get_untracked();
        if !text.trim().is_empty() {
            self.declare_blocks(&text, engine::softplc::st::st_blocks(&text).as_ref().ok());
        }
    }

    /// The function blocks of a text that loads become the ladder's
    /// boxes (issue #55; a text with errors leaves the last ones, so a
    /// box does not fail while its block is being typed); the ladder is
    /// checked again when they change (a box whose block is gone is an
    /// error at its cell).
    pub fn declare_blocks(&self, text: &str, blocks: Option<&StBlocks>) {
        let Some(b) = blocks else {
            return;
        };
        // Kept with its text: the ladder's program is mapped by them.
        self.declared.set_value(Some((text.to_string(), b.clone())));
        let changed = engine::ladder::user_blocks::set(b.blocks.clone(), b.il.clone());
        if changed {
            if let Some(ladder) = self.ladder.get_value() {
                ladder.refresh(false);
            }
        }
    }

    /// Whether Load and Run run the ST text: it is chosen and has a
    /// `PROGRAM` (a text of blocks only leaves the ladder to run, calling
    /// them).
    pub fn runs(&self) -> bool {
        self.on.get_untracked()
            && self
                .text
                .with_untracked(|t| engine::softplc::st::declares_program(t))
    }

    /// Chooses the pane's language, remembered.
    pub fn set_on(&self, on: bool) {
        put(self.on, on);
        if on {
            storage::save_string(LANGUAGE_KEY, "st");
        } else {
            storage::remove(LANGUAGE_KEY);
        }
    }

    /// A `.st` file opened: its text in the pane, ST chosen, the last
    /// text's breakpoints gone.
    pub fn open(&self, text: &str, sim: Sim) {
        self.set_on(true);
        self.text.set(text.to_string());
        self.save();
        self.breakpoints.set(BTreeSet::new());
        self.install_stop(sim);
        // Its blocks are the ladder's boxes at once, pane shown or not.
        self.declare_blocks(text, engine::softplc::st::st_blocks(text).as_ref().ok());
    }

    /// The ST text as a project keeps it (issue #55); `None` while empty.
    pub fn source(&self) -> Option<engine::formats::project::ProgramText> {
        let text = self.text.get_untracked();
        (!text.trim().is_empty()).then(|| engine::formats::project::ProgramText::st(&text))
    }

    /// A project's ST text: in the pane, in ST, as a `.st` file opens
    /// (not loaded until Load or Run); a different text typed before is
    /// set aside under a key of its own, which the notice names.
    pub fn take_source(&self, source: engine::formats::project::ProgramText, sim: Sim) {
        let before = self.text.get_untracked();
        if before == source.text {
            return;
        }
        if !before.trim().is_empty() {
            storage::save_to(SET_ASIDE_KEY, &storage::SavedText { program: before });
            let said = self.page.lang.get_untracked().st().set_aside;
            self.page
                .notice
                .set(Some(format!("{said} {SET_ASIDE_KEY}")));
        }
        self.open(&source.text, sim);
    }

    /// Saves the ST text.
    pub fn save(&self) {
        let program = self.text.get_untracked();
        storage::save_to(TEXT_KEY, &storage::SavedText { program });
    }

    /// Loads the ST text into the machine (from power-up); false when it
    /// does not load (its errors are the pane's).
    pub fn load(&self, sim: Sim) -> bool {
        let text = self.text.get_untracked();
        let Ok(mut run) = engine::softplc::st::st_run(&text) else {
            return false;
        };
        // Traced, as Run traces a ladder: Why? tells which statement ran.
        let loaded = sim
            .try_update_value(|s| {
                let m = s.machine_mut();
                let loaded = m.load_text(&run.il);
                if loaded.is_ok() {
                    m.set_tracing(true);
                }
                loaded
            })
            .is_some_and(|r| r.is_ok());
        if !loaded {
            return false;
        }
        let lines = std::mem::take(&mut run.lines);
        let map =
            sim.with_value(|s| StMap::new(s.machine().shown_machine().machine().program(), lines));
        self.follow(sim, text, map, Some(&run));
        true
    }

    /// A ladder's IL `text` was loaded: the steps of the ST blocks it
    /// calls (the blocks last declared, when it ends with their IL) are
    /// followed in the pane as an ST program's are.
    pub fn load_ladder(&self, sim: Sim, text: &str) {
        let Some((source, blocks)) = self.declared.get_value() else {
            self.forget(sim);
            return;
        };
        let map = sim.with_value(|s| {
            let program = s.machine().shown_machine().machine().program();
            StMap::for_ladder(program, text, &blocks)
        });
        if map.lines.iter().all(Option::is_none) {
            self.forget(sim);
            return;
        }
        self.follow(sim, source, map, None);
    }

    /// Follows the program loaded by `map`, its lines those of `source`
    /// (`program`: its own lines show values too, else only its blocks').
    /// An IL program was loaded: nothing of the ST one stays.
    pub fn forget(&self, sim: Sim) {
        self.map.set_value(StMap::default());
        self.source.set_value(String::new());
        self.devices.set_value(Vec::new());
        put(self.instances, Vec::new());
        put(self.values, Vec::new());
        put(self.current, None);
        put(self.current_call, None);
        sim.update_value(|s| s.set_stop(None));
    }

    /// Sets or clears a breakpoint on `line`.
    pub fn toggle_breakpoint(&self, line: usize, sim: Sim) {
        self.breakpoints.update(|b| {
            if !b.remove(&line) {
                b.insert(line);
            }
        });
        self.install_stop(sim);
    }

    /// The machine's frames stop before the first step of a breakpoint's
    /// line (none set: they run whole scans).
    pub(super) fn install_stop(&self, sim: Sim) {
        let breakpoints = self.breakpoints.get_untracked();
        let stops = self.map.with_value(|m| stop_steps(&m.lines, &breakpoints));
        let stop: Option<crate::sim::StopAt<SoftPlc>> = stops.contains(&true).then(|| {
            Box::new(move |m: &SoftPlc| {
                m.machine()
                    .scan_position()
                    .map(|p| stops.get(p).copied().unwrap_or(false))
            }) as crate::sim::StopAt<SoftPlc>
        });
        sim.update_value(|s| s.set_stop(stop));
    }
}

/// The steps a scan stops before: the first step of each breakpoint's
/// line (a line lowers to several steps; the scan stops once, before
/// the line runs, not before each of its steps).
pub fn stop_steps(lines: &[Option<usize>], breakpoints: &BTreeSet<usize>) -> Vec<bool> {
    lines
        .iter()
        .enumerate()
        .map(|(p, l)| {
            let first = p == 0 || lines[p - 1] != *l;
            first && l.is_some_and(|l| breakpoints.contains(&l))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_scan_stops_before_a_breakpoints_line_once() {
        let lines = [Some(7), Some(7), Some(8), Some(8), Some(8), Some(9), None];
        let stops = stop_steps(&lines, &BTreeSet::from([8, 9]));
        assert_eq!(stops, [false, false, true, false, false, true, false]);
    }
}
