//! Structured Text in the soft PLC's workspace (issue #55): the pane's
//! language, the ST text (saved apart from the IL text, which follows the
//! ladder), the program loaded from it with each step's ST line, and what
//! the pane shows while it runs: the values beside the lines, the line
//! the scan stands before, breakpoints and stepping by statement.

use std::collections::BTreeSet;

use engine::machines::SoftPlc;
use engine::plc::{Device, Plc, Value};
use leptos::prelude::*;

use crate::editor::panes::why::StCause;
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

/// The most instructions "Step statement" runs looking for the next
/// line (a loop on one line ends its search there).
const MAX_STEPS: usize = 1_000_000;

type Sim = StoredValue<Simulator<SoftPlc>, LocalStorage>;

/// A line (1-based) and the names it uses, with their handles.
/// A line's variables: each as written, as the IL knows it (a second
/// program's own may be renamed, `StRun::il_name`), and its device.
type LineNames = (usize, Vec<(String, String, Device)>);

/// The ST side of the soft PLC's workspace.
#[derive(Clone, Copy)]
pub struct StState {
    page: Ctx,
    /// The pane shows (and Load, Run load) the ST text.
    pub on: RwSignal<bool>,
    pub text: RwSignal<String>,
    /// `lines[step]`: the ST line of each step of the program loaded
    /// (empty while the program loaded is not ST).
    lines: StoredValue<Vec<Option<usize>>>,
    /// The names each line of the program loaded uses, with their handles.
    devices: StoredValue<Vec<LineNames>>,
    /// The values shown beside the lines: (line, `a = 1  b = TRUE`).
    pub values: RwSignal<Vec<(usize, String)>>,
    /// The lines shown (first, last; 1-based): only their values are read.
    pub visible: RwSignal<(usize, usize)>,
    pub breakpoints: RwSignal<BTreeSet<usize>>,
    /// The line the scan stands before, while a scan is stepped.
    pub current: RwSignal<Option<usize>>,
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
            lines: StoredValue::new(Vec::new()),
            devices: StoredValue::new(Vec::new()),
            values: RwSignal::new(Vec::new()),
            visible: RwSignal::new((1, 60)),
            breakpoints: RwSignal::new(BTreeSet::new()),
            current: RwSignal::new(None),
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
            self.declare_blocks(engine::softplc::st::st_blocks(&text).as_ref().ok());
        }
    }

    /// The function blocks of a text that loads become the ladder's
    /// boxes (issue #55; a text with errors leaves the last ones, so a
    /// box does not fail while its block is being typed); the ladder is
    /// checked again when they change (a box whose block is gone is an
    /// error at its cell).
    pub fn declare_blocks(&self, blocks: Option<&engine::softplc::st::StBlocks>) {
        let Some(b) = blocks else {
            return;
        };
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
        self.declare_blocks(engine::softplc::st::st_blocks(text).as_ref().ok());
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
        let Ok(run) = engine::softplc::st::st_run(&text) else {
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
        let devices = sim.with_value(|s| {
            let plc = s.machine();
            super::st_lex::names_by_line(&text)
                .into_iter()
                .map(|(line, names)| {
                    let found = names
                        .into_iter()
                        .filter_map(|n| {
                            let il = run.il_name(line, &n);
                            plc.device(&il).ok().map(|d| (n, il, d))
                        })
                        .collect::<Vec<_>>();
                    (line, found)
                })
                .filter(|(_, found)| !found.is_empty())
                .collect::<Vec<_>>()
        });
        self.devices.set_value(devices);
        self.lines.set_value(run.lines);
        self.hit.set(false);
        self.install_stop(sim);
        true
    }

    /// An IL program was loaded: nothing of the ST one stays.
    pub fn forget(&self, sim: Sim) {
        self.lines.set_value(Vec::new());
        self.devices.set_value(Vec::new());
        put(self.values, Vec::new());
        put(self.current, None);
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
    fn install_stop(&self, sim: Sim) {
        let breakpoints = self.breakpoints.get_untracked();
        let stops = self
            .lines
            .with_value(|lines| stop_steps(lines, &breakpoints));
        let stop: Option<crate::sim::StopAt<SoftPlc>> = stops.contains(&true).then(|| {
            Box::new(move |m: &SoftPlc| {
                m.machine()
                    .scan_position()
                    .map(|p| stops.get(p).copied().unwrap_or(false))
            }) as crate::sim::StopAt<SoftPlc>
        });
        sim.update_value(|s| s.set_stop(stop));
    }

    /// The ST line of the step the shown machine stands before.
    fn line_now(&self, sim: Sim) -> Option<usize> {
        let position = sim.with_value(|s| s.machine().shown_machine().machine().scan_position());
        position.and_then(|p| self.lines.with_value(|l| l.get(p).copied().flatten()))
    }

    /// After a frame, a step or a travel: a breakpoint met pauses the
    /// page; the current line and the visible lines' values follow the
    /// machine shown.
    pub fn refresh(&self, sim: Sim) {
        if sim.try_update_value(|s| s.take_stopped()).unwrap_or(false) {
            self.page.paused.set(true);
            self.hit.set(true);
        }
        put(self.current, self.line_now(sim));
        let (first, last) = self.visible.get_untracked();
        let values = sim.with_value(|s| {
            let plc = s.machine();
            self.devices.with_value(|devices| {
                devices
                    .iter()
                    .filter(|(line, _)| (first..=last).contains(line))
                    .map(|(line, found)| {
                        let shown = found
                            .iter()
                            .map(|(name, il, d)| {
                                // Mid-scan, the value now (a device reads the
                                // last scan's image); a block's output by its
                                // handle.
                                let now = plc.shown_machine().machine().program().value(il);
                                let v = now.map_or_else(|| plc.read(*d), |v| v.to_value());
                                format!("{name} = {}", shown(&v))
                            })
                            .collect::<Vec<_>>()
                            .join("  ");
                        (*line, shown)
                    })
                    .collect::<Vec<_>>()
            })
        });
        put(self.values, values);
    }

    /// "Step statement": runs the scan's steps until it stands before
    /// another line's first step, or the scan ends. Outside a scan it
    /// starts the next one and runs its first statement. The page pauses,
    /// as for a step of the run control.
    pub fn step_statement(&self, sim: Sim, ladder: crate::editor::LadderCtx) {
        self.page.paused.set(true);
        self.hit.set(false);
        let start = self.line_now(sim).or_else(|| {
            self.lines
                .with_value(|l| l.iter().flatten().next().copied())
        });
        for _ in 0..MAX_STEPS {
            let ran = sim
                .try_update_value(|s| s.machine_mut().step_instruction())
                .flatten();
            if ran.is_none() {
                break;
            }
            match self.line_now(sim) {
                None => break,
                Some(line) if Some(line) != start => break,
                Some(_) => {}
            }
        }
        // Shown on the ladder and the board as a step of the run control.
        ladder.operate(|_| {});
    }
}

impl StState {
    /// Why? on a box of ST block `kind` (instance `instance`): the
    /// block's statements that wrote the first BOOL output, which the
    /// power leaves by (a block without one passes the power on: nothing
    /// to follow), each with its operands' values in that instance.
    pub fn why_box(&self, kind: &str, instance: &str, sim: Sim) -> Vec<StCause> {
        let pin = engine::ladder::user_blocks::outputs(kind)
            .into_iter()
            .find(|(_, t)| *t == engine::iec::data::DataType::Bool);
        let Some((pin, _)) = pin else {
            return Vec::new();
        };
        let text = self.text.get_untracked();
        let writes = engine::softplc::st_why::st_writes(&text, Some(kind), pin);
        let at = |name: &str| format!("{instance}.{name}");
        causes(writes, sim, at, |_| None)
    }

    /// Why? on variable `name` of the ST program loaded: the statements
    /// that write it, each with its operands' values at the scan shown
    /// and whether it ran then (the trace of its line's steps).
    pub fn why_variable(&self, name: &str, sim: Sim) -> Vec<StCause> {
        let text = self.text.get_untracked();
        let writes = engine::softplc::st_why::st_writes(&text, None, name);
        let ran = sim.with_value(|s| {
            let trace = s.machine().trace().map(|t| t.ran.clone());
            self.lines.with_value(|lines| {
                let mut ran = BTreeSet::new();
                for (step, line) in lines.iter().enumerate() {
                    let went = trace.as_ref().and_then(|r| r.get(step).copied());
                    if let (Some(line), Some(true)) = (line, went) {
                        ran.insert(*line);
                    }
                }
                trace.map(|_| ran)
            })
        });
        causes(writes, sim, str::to_string, |line| {
            ran.as_ref().map(|r| r.contains(&line))
        })
    }
}

/// The statements `writes` with each operand's value (the operand as
/// `at` names it in the machine) and whether each ran (`ran`).
fn causes(
    writes: Vec<engine::softplc::st_why::StWrite>,
    sim: Sim,
    at: impl Fn(&str) -> String,
    ran: impl Fn(usize) -> Option<bool>,
) -> Vec<StCause> {
    sim.with_value(|s| {
        let plc = s.machine();
        writes
            .into_iter()
            .map(|w| StCause {
                line: w.line,
                ran: ran(w.line),
                statement: w.statement,
                values: w
                    .reads
                    .iter()
                    .filter_map(|r| {
                        let name = at(r);
                        let now = plc.shown_machine().machine().program().value(&name);
                        let v = now
                            .map(|v| v.to_value())
                            .or_else(|| plc.device(&name).ok().map(|d| plc.read(d)))?;
                        Some(format!("{r} = {}", shown(&v)))
                    })
                    .collect(),
            })
            .collect()
    })
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

/// A value as ST writes it (a bit as TRUE/FALSE).
fn shown(v: &Value) -> String {
    match v {
        Value::Bit(b) => if *b { "TRUE" } else { "FALSE" }.to_string(),
        Value::Text(t) => format!("'{t}'"),
        v => v.to_string(),
    }
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
