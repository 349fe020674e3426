//! The running machine on the ladder: live colours through each cell's
//! probes, pulses, the watch table, and recording inputs into a case.

use super::*;
use crate::editor::on_screen::Due;

/// The machine as the ladder shows it running: the drawing it runs, the
/// device handles, the watch table, forcing and stepping.
#[derive(Clone, Copy)]
pub struct Live {
    /// The ladder the machine runs, compiled with its source map, from
    /// Run until the next edit: the colours come from it.
    pub(super) ladder: StoredValue<Option<engine::ladder::live::LiveLadder>>,
    /// Device handles on the machine, by name (cleared when the ladder or
    /// the program changes).
    pub(super) handles: StoredValue<std::collections::HashMap<String, Option<engine::plc::Device>>>,
    /// Bumped when device handles are forgotten: rungs resolve their
    /// probes again.
    pub(super) probe_generation: StoredValue<u64>,
    /// The watch table's devices and what they show.
    pub watch: RwSignal<Vec<String>>,
    pub watch_values: RwSignal<Vec<String>>,
    /// Per watched name the machine lacks, its plant's value at the scan
    /// shown (`tank.level`, issue #52), read before the machine's.
    pub(crate) plant_watch: StoredValue<Vec<Option<i64>>>,
    /// Each declared variable's value on the machine (the variables
    /// pane), by name; empty before a scan.
    pub variable_values: RwSignal<Vec<(String, String)>>,
    /// Whether each device of the phone's strip is on (`drawing.io`).
    pub io_values: RwSignal<Vec<(String, bool)>>,
    /// The machine's clock as the app bar shows it.
    pub clock: RwSignal<Clock>,
    /// The AVR PLC, which has no RUN switch, is powered off by Stop.
    pub powered_off: RwSignal<bool>,
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
    pub(crate) link:
        StoredValue<Option<std::rc::Rc<dyn crate::editor::machine::MachineLink>>, LocalStorage>,
    /// What waits for the machine to arrive with its part (issue #53):
    /// run when it is attached ([`LadderCtx::when_attached`]).
    pub(crate) on_arrival: StoredValue<Vec<Box<dyn FnOnce()>>, LocalStorage>,
    /// Counts the running frames, for the rungs and the panel's lamps off
    /// screen to be brought up to date in turn (`crate::editor::on_screen`,
    /// `LadderCtx::turn`).
    pub(crate) turn: StoredValue<u64>,
}

impl Live {
    /// Nothing running yet: no ladder written, no handles, the clock at 0.
    pub(super) fn new() -> Live {
        Live {
            ladder: StoredValue::new(None),
            handles: StoredValue::new(std::collections::HashMap::new()),
            probe_generation: StoredValue::new(0),
            watch: RwSignal::new(Vec::new()),
            watch_values: RwSignal::new(Vec::new()),
            plant_watch: StoredValue::new(Vec::new()),
            variable_values: RwSignal::new(Vec::new()),
            io_values: RwSignal::new(Vec::new()),
            clock: RwSignal::new(Clock::default()),
            powered_off: RwSignal::new(false),
            stepped: RwSignal::new(None),
            stepped_cell: RwSignal::new(None),
            monitor: RwSignal::new(false),
            unwritten: RwSignal::new(false),
            running: RwSignal::new(false),
            forced: RwSignal::new(Vec::new()),
            link: StoredValue::new_local(None),
            on_arrival: StoredValue::new_local(Vec::new()),
            turn: StoredValue::new(0),
        }
    }
}

impl LadderCtx {
    /// Starts recording the inputs the user changes into a new case.
    pub fn start_recording(&self, plc: &dyn engine::plc::Plc) {
        let rec = crate::editor::cases::Recorder::new(&self.ladder(), plc);
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
        let named = self.page.lang.get_untracked().words().case_names[1];
        let case = rec.finish(plc, &named.replace("{n}", &n.to_string()));
        self.cases.tests.update(|t| t.push(case));
        self.cases.results.update(|r| r.push(None));
        self.save();
    }

    /// The device `name` on `plc`, resolved once.
    pub(super) fn handle(
        &self,
        plc: &dyn engine::plc::Plc,
        name: &str,
    ) -> Option<engine::plc::Device> {
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
    pub(super) fn start_live(&self) -> bool {
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
    /// the ladder as drawn), and the watch table, on the rungs `due`
    /// names. Only the cells whose states changed are touched.
    pub fn show_live(&self, plc: &dyn engine::plc::Plc, due: &Due) {
        // A drawing that cannot be written shows nothing live: the states
        // would be another program's.
        let in_run = plc.running();
        if self.live.running.get_untracked() != in_run {
            self.live.running.set(in_run);
        }
        let powered = !self.live.powered_off.get_untracked();
        let clock = self.live.clock.get_untracked().next(
            plc.now().as_nanos(),
            plc.scans(),
            in_run && powered,
        );
        crate::state::put(self.live.clock, clock);
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
        let resolve = |c: &crate::editor::model::CellData| self.probe_of(plc, c);
        for view in self.drawing.rungs.get_untracked() {
            let number = view.number.get_untracked();
            if !due.covers(number) {
                continue;
            }
            match powers.iter().find(|(i, _)| *i == number) {
                Some((_, p)) => view.data.with_untracked(|d| {
                    view.update_each(|i| crate::editor::model::power_of(d, p, i), |s| &s.powered)
                }),
                None => view.update_each(|_| None, |s| &s.powered),
            }
            view.probe(generation, resolve, |probes| {
                let probe = |i: usize| probes.get(i);
                view.update_each(
                    |i| {
                        running
                            .then(|| probe(i)?.state.map(|h| plc.read(h).is_on()))
                            .flatten()
                    },
                    |s| &s.on,
                );
                view.update_each(
                    |i| {
                        running
                            .then(|| probe(i)?.value.map(|h| plc.read(h).as_i64()))
                            .flatten()
                    },
                    |s| &s.value,
                );
                view.update_each(
                    |i| {
                        let words = &probe(i)?.words;
                        (running && !words.is_empty()).then(|| box_values(plc, words))
                    },
                    |s| &s.words,
                );
            });
            self.show_conduction(plc.trace(), &view, number);
        }
        self.show_watch(plc);
    }

    /// Each frame, after the devices' states: whether each contact is
    /// closed (`data-conducts`, `crate::editor::conduct`); an edge
    /// contact's from the bit its step read in the traced scan (the
    /// relay its edge was computed into).
    fn show_conduction(
        &self,
        trace: Option<&engine::plc::ScanTrace>,
        view: &RungView,
        number: usize,
    ) {
        use crate::editor::model::CellKind;
        view.data.with_untracked(|d| {
            view.update_each_from(
                |i, slot| {
                    let c = d.cells.get(i)?;
                    let edge = match c.kind {
                        CellKind::Rise | CellKind::Fall => trace.map(|t| {
                            let pos = Pos::new(c.row, c.col);
                            let step = self.with_live(|l| l?.listing.step_of_leaf(number, pos));
                            step.is_some_and(|s| {
                                t.ran.get(s).copied().unwrap_or(false)
                                    && t.read.get(s).copied().unwrap_or(false)
                            })
                        }),
                        _ => None,
                    };
                    crate::editor::conduct::conducts(c.kind, slot.on.get_untracked(), edge)
                },
                |s| &s.conducts,
            );
        });
    }

    /// The machine's handles for cell `c`: its device's state, a timer's
    /// or counter's current value, a soft PLC box's operands.
    fn probe_of(&self, plc: &dyn engine::plc::Plc, c: &crate::editor::model::CellData) -> Probe {
        let look = c.kind.look();
        if c.device.is_empty() {
            let words = c
                .watched
                .iter()
                .filter_map(|(label, d)| Some((label.clone(), self.handle(plc, d)?)))
                .collect();
            return Probe {
                words,
                ..Probe::default()
            };
        }
        let counts = look.shows_value && (c.device.starts_with('T') || c.device.starts_with('C'));
        let state = look
            .shows_state
            .then(|| self.handle(plc, &c.device))
            .flatten();
        Probe {
            state,
            value: counts
                .then(|| self.current_of(plc, &c.device, state))
                .flatten(),
            words: Vec::new(),
        }
    }

    /// The handle of `name`'s current value (`name.v`: a timer's or
    /// counter's), when it is more than the device itself (`itself`): a
    /// soft PLC word's `.v` is the word.
    fn current_of(
        &self,
        plc: &dyn engine::plc::Plc,
        name: &str,
        itself: Option<engine::plc::Device>,
    ) -> Option<engine::plc::Device> {
        self.handle(plc, &format!("{name}.v"))
            .filter(|h| Some(*h) != itself)
    }

    /// Each frame: the watch table's values (a timer's or counter's
    /// current value and preset in brackets).
    fn show_watch(&self, plc: &dyn engine::plc::Plc) {
        let plant = self.live.plant_watch.get_value();
        let values: Vec<String> = self.live.watch.with_untracked(|w| {
            w.iter()
                .enumerate()
                .map(|(i, name)| {
                    let device = self.handle(plc, name);
                    let value = device.map(|h| plc.read(h));
                    let current = self.current_of(plc, name, device).map(|h| plc.read(h));
                    let preset = self.preset_of(name);
                    match (value, current) {
                        (Some(v), Some(c)) => match preset {
                            Some(k) => format!("{} ({c}/K{k})", v.watched()),
                            None => format!("{} ({c})", v.watched()),
                        },
                        (Some(v), None) => v.watched(),
                        (None, Some(c)) => c.to_string(),
                        (None, None) => match plant.get(i) {
                            Some(Some(v)) => v.to_string(),
                            _ => "?".to_string(),
                        },
                    }
                })
                .collect()
        });
        if self.live.watch_values.with_untracked(|old| *old != values) {
            self.live.watch_values.set(values);
        }
        let variables: Vec<(String, String)> = self.drawing.variables.with_untracked(|vs| {
            vs.iter()
                .filter_map(|v| {
                    let value = self.handle(plc, &v.name).map(|h| plc.read(h))?;
                    Some((v.name.clone(), value.watched()))
                })
                .collect()
        });
        crate::state::put(self.live.variable_values, variables);
        let io: Vec<(String, bool)> = self.drawing.io.with_untracked(|points| {
            points
                .iter()
                .map(|p| {
                    let on = self
                        .handle(plc, &p.name)
                        .is_some_and(|h| plc.read(h).is_on());
                    (p.name.clone(), on)
                })
                .collect()
        });
        crate::state::put(self.live.io_values, io);
    }

    /// Each frame: marks every cell whose power changed in some scan since
    /// the last frame, so a one-scan pulse shows at any speed (on the
    /// rungs `due` names: a rung off screen shows the pulses of the
    /// frames it is brought up to date in).
    pub fn show_pulses(&self, history: &engine::plc::TraceHistory, due: &Due) {
        let pulses = self
            .live
            .ladder
            .with_value(|l| l.as_ref().map(|l| l.pulses(history)));
        let pulses = pulses.unwrap_or_default();
        for view in self.drawing.rungs.get_untracked() {
            let number = view.number.get_untracked();
            if !due.covers(number) {
                continue;
            }
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
    pub(super) fn preset_of(&self, device: &str) -> Option<u16> {
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
}

/// A box's operands' values as its cell shows them: `a=5 c=6`.
fn box_values(plc: &dyn engine::plc::Plc, words: &[(String, engine::plc::Device)]) -> String {
    words
        .iter()
        .map(|(label, h)| format!("{label}={}", plc.read(*h)))
        .collect::<Vec<_>>()
        .join(" ")
}
