//! What the ST pane shows while a program runs (issue #55), as CODESYS's
//! online view does: the values beside the lines (a block's lines show
//! one instance's: the one chosen, or the one whose call the scan stands
//! in), the line the scan stands before and the call it is in, Step
//! statement, and Why? naming the statements that ran. The same for an
//! ST program and for a ladder calling the text's blocks.

use std::collections::BTreeSet;

use engine::machines::SoftPlc;
use engine::plc::{Plc, Value};
use engine::record::Recorded;
use engine::softplc::st::StRun;
use engine::softplc::st_online::{block_lines, StMap};
use engine::softplc::st_why::{st_writes, StWrite};
use leptos::prelude::*;

use super::st::{LineNames, Named, Sim, StState};
use crate::editor::panes::why::StCause;
use crate::state::put;

/// The most instructions "Step statement" runs looking for the next
/// line (a loop on one line ends its search there).
const MAX_STEPS: usize = 1_000_000;

/// The names each line of `source` uses that the machine knows: a line
/// of a block once per instance of it (`count` as `c0.count`), a line of
/// the programs' own (only with `program`, the ST loaded: a ladder has
/// none) as the IL names it (a later program's own may be renamed,
/// `StRun::il_name`).
pub fn line_names(
    plc: &Recorded<SoftPlc>,
    source: &str,
    map: &StMap,
    program: Option<&StRun>,
) -> Vec<LineNames> {
    let blocks = block_lines(source);
    let mut out = Vec::new();
    for (line, names) in super::st_lex::names_by_line(source) {
        let block = blocks.iter().find(|(_, lines)| lines.contains(&line));
        match block {
            Some((block, _)) => {
                let instances = map.instances.iter().enumerate();
                for (i, instance) in instances.filter(|(_, i)| i.block.eq_ignore_ascii_case(block))
                {
                    let found = resolve(plc, &names, &format!("{}.", instance.name));
                    if !found.is_empty() {
                        out.push((line, Some(i), found));
                    }
                }
            }
            None if program.is_some() => {
                let found: Vec<Named> = names
                    .iter()
                    .filter_map(|n| {
                        let il = program.map_or_else(|| n.clone(), |run| run.il_name(line, n));
                        plc.device(&il).ok().map(|d| (n.clone(), il, d))
                    })
                    .collect();
                if !found.is_empty() {
                    out.push((line, None, found));
                }
            }
            None => {}
        }
    }
    out
}

/// The `names` the machine knows as `prefix` + name, with their handles.
fn resolve(plc: &Recorded<SoftPlc>, names: &[String], prefix: &str) -> Vec<Named> {
    names
        .iter()
        .filter_map(|n| {
            let full = format!("{prefix}{n}");
            plc.device(&full).ok().map(|d| (n.clone(), full, d))
        })
        .collect()
}

/// The step the shown machine stands before, while a scan is stepped.
fn position_now(sim: Sim) -> Option<usize> {
    sim.with_value(|s| s.machine().shown_machine().machine().scan_position())
}

impl StState {
    /// `program`: the ST program loaded (its own lines show values too),
    /// `None` for a ladder calling the text's blocks.
    pub(super) fn follow(&self, sim: Sim, source: String, map: StMap, program: Option<&StRun>) {
        let devices = sim.with_value(|s| line_names(s.machine(), &source, &map, program));
        let instances = map
            .instances
            .iter()
            .map(|i| (i.name.clone(), i.block.clone()))
            .collect::<Vec<_>>();
        put(self.instances, instances);
        self.devices.set_value(devices);
        self.map.set_value(map);
        self.source.set_value(source);
        self.standing.set_value(None);
        self.hit.set(false);
        self.install_stop(sim);
    }

    /// The ST line and call of the step the shown machine stands before.
    fn place_now(&self, sim: Sim) -> Option<(usize, Option<usize>)> {
        let position = position_now(sim)?;
        self.map.with_value(|m| m.place(position))
    }

    /// The instances whose values their block's lines show: the one
    /// chosen for its block, each other block's first.
    fn shown_instances(&self) -> Vec<usize> {
        let chosen = self.chosen.get_untracked();
        self.map.with_value(|m| {
            let chosen = m.instance(&chosen);
            let block = |i: usize| m.instances.get(i).map(|b| b.block.to_ascii_uppercase());
            (0..m.instances.len())
                .filter(|&i| match chosen {
                    Some(c) if block(c) == block(i) => c == i,
                    _ => (0..i).all(|j| block(j) != block(i)),
                })
                .collect()
        })
    }

    /// The name of instance `i` of the program loaded.
    fn instance_name(&self, i: usize) -> Option<String> {
        self.map
            .with_value(|m| m.instances.get(i).map(|b| b.name.clone()))
    }

    /// After a frame, a step or a travel: a breakpoint met pauses the
    /// page; the current line, its call and the visible lines' values
    /// follow the machine shown.
    pub fn refresh(&self, sim: Sim) {
        if sim.try_update_value(|s| s.take_stopped()).unwrap_or(false) {
            self.page.paused.set(true);
            self.hit.set(true);
        }
        let place = self.place_now(sim);
        let call = place.and_then(|(_, owner)| owner);
        // Come to stand in a call (paused: a breakpoint, a step), its
        // instance is shown; a choice made while it stands there is kept.
        if self.page.paused.get_untracked() && call != self.standing.get_value() {
            self.standing.set_value(call);
            if let Some(name) = call.and_then(|i| self.instance_name(i)) {
                put(self.chosen, name);
            }
        }
        put(self.current, place.map(|(line, _)| line));
        put(self.current_call, call.and_then(|i| self.instance_name(i)));
        self.show_values(sim);
    }

    /// The values beside the lines scrolled into view.
    pub fn show_values(&self, sim: Sim) {
        let (first, last) = self.visible.get_untracked();
        let shown_instances = self.shown_instances();
        let values = sim.with_value(|s| {
            let plc = s.machine();
            self.devices.with_value(|devices| {
                devices
                    .iter()
                    .filter(|(line, _, _)| (first..=last).contains(line))
                    .filter(|(_, owner, _)| owner.is_none_or(|o| shown_instances.contains(&o)))
                    .map(|(line, _, found)| (*line, line_values(plc, found)))
                    .collect::<Vec<_>>()
            })
        });
        put(self.values, values);
    }

    /// "Step statement": runs the scan's steps until it stands before
    /// another statement (another line, or the same line in another
    /// call), or the scan ends; steps of no ST line (a ladder's own) run
    /// through. Outside a scan it starts the next one from its first
    /// step. The page pauses, as for a step of the run control.
    pub fn step_statement(&self, sim: Sim, ladder: crate::editor::LadderCtx) {
        self.page.paused.set(true);
        self.hit.set(false);
        let from = position_now(sim).unwrap_or(0);
        let start = self.map.with_value(|m| m.place(from));
        for _ in 0..MAX_STEPS {
            let ran = sim
                .try_update_value(|s| s.machine_mut().step_instruction())
                .flatten();
            if ran.is_none() {
                break;
            }
            let Some(position) = position_now(sim) else {
                break;
            };
            let place = self.map.with_value(|m| m.place(position));
            if place.is_some() && place != start {
                break;
            }
        }
        // Shown on the ladder and the board as a step of the run control.
        ladder.operate(|_| {});
    }

    /// The text the program loaded was mapped from (the pane's text when
    /// none is).
    fn mapped_text(&self) -> String {
        let source = self.source.get_value();
        if source.is_empty() {
            self.text.get_untracked()
        } else {
            source
        }
    }

    /// Why? on a box of ST block `kind` (instance `instance`): of the
    /// block's statements that write the first BOOL output (which the
    /// power leaves by; a block without one passes the power on: nothing
    /// to follow), the one that ran last in that instance's call in the
    /// scan explained; each write, marked as not run, when none ran; every
    /// write, unmarked, where no trace tells (the ladder not mapped to
    /// the text). Its operands' values are the instance's.
    pub fn why_box(&self, kind: &str, instance: &str, sim: Sim) -> Vec<StCause> {
        let pin = engine::ladder::user_blocks::outputs(kind)
            .into_iter()
            .find(|(_, t)| *t == engine::iec::data::DataType::Bool);
        let Some((pin, _)) = pin else {
            return Vec::new();
        };
        let writes = st_writes(&self.mapped_text(), Some(kind), pin);
        let at = |name: &str| format!("{instance}.{name}");
        let ran = sim.with_value(|s| s.machine().trace().map(|t| t.ran.clone()));
        let mapped = self.map.with_value(|m| m.instance(instance).is_some());
        let Some(ran) = ran.filter(|_| mapped) else {
            return causes(writes, sim, at, |_| None);
        };
        match self.map.with_value(|m| m.ran_last(&writes, instance, &ran)) {
            Some(i) => {
                let last = writes.into_iter().nth(i).into_iter().collect();
                causes(last, sim, at, |_| Some(true))
            }
            None => causes(writes, sim, at, |_| Some(false)),
        }
    }

    /// Why? on variable `name` of the ST program loaded: the statements
    /// that write it, each with its operands' values at the scan shown
    /// and whether it ran then (the trace of its line's steps).
    pub fn why_variable(&self, name: &str, sim: Sim) -> Vec<StCause> {
        let text = self.text.get_untracked();
        let writes = st_writes(&text, None, name);
        let ran = sim.with_value(|s| {
            let trace = s.machine().trace().map(|t| t.ran.clone());
            self.map.with_value(|m| {
                let mut ran = BTreeSet::new();
                for (step, line) in m.lines.iter().enumerate() {
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

/// A line's names with their values: `a = 1  b = TRUE`.
fn line_values(plc: &Recorded<SoftPlc>, found: &[Named]) -> String {
    found
        .iter()
        .map(|(name, full, d)| {
            // Mid-scan, the value now (a device reads the last scan's
            // image); a block's output by its handle.
            let now = plc.shown_machine().machine().program().value(full);
            let v = now.map_or_else(|| plc.read(*d), |v| v.to_value());
            format!("{name} = {}", shown(&v))
        })
        .collect::<Vec<_>>()
        .join("  ")
}

/// The statements `writes` with each operand's value (the operand as
/// `at` names it in the machine) and whether each ran (`ran`).
fn causes(
    writes: Vec<StWrite>,
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

/// A value as ST writes it (a bit as TRUE/FALSE).
fn shown(v: &Value) -> String {
    match v {
        Value::Bit(b) => if *b { "TRUE" } else { "FALSE" }.to_string(),
        Value::Text(t) => format!("'{t}'"),
        v => v.to_string(),
    }
}
