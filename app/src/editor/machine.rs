//! The machine an editor's ladder runs on, in one object-safe shape for
//! every machine: [`MachineLink`], implemented once generically over the
//! simulator ([`Linked`]). Each editor holds its own link (attached by the
//! page when it builds the workspaces), so editor views reach their
//! machine through their own [`LadderCtx`], never through the list of
//! workspaces; and no view is generic over the machine type.

use engine::plc::Plc;
use engine::record::{Recorded, TimeTravel};
use leptos::prelude::*;

use super::on_screen::Due;
use super::LadderCtx;
use crate::rig::RigSlot;
use crate::sim::{Pace, Simulator};

/// One machine as the editor and the frame loop drive it.
pub trait MachineLink {
    /// Operates the machine.
    fn operate(&self, f: &mut dyn FnMut(&mut dyn Plc));
    /// Runs `f` on its recording (time travel, breaks, the chart).
    fn travel(&self, f: &mut dyn FnMut(&mut dyn TimeTravel));
    /// Reads the machine (as shown: a past scan's while travelling).
    fn read(&self, f: &mut dyn FnMut(&dyn Plc));
    /// Advances it by one animation frame of `wall_ms` at `pace`.
    fn advance(&self, pace: Pace, wall_ms: f64);
    /// After a frame is drawn, `Speed::Max`'s simulation until
    /// `deadline_ms` on the wall clock `now_ms` ([`Simulator::after_frame`]).
    fn after_frame(&self, pace: Pace, deadline_ms: f64, now_ms: fn() -> f64);
    /// Copies its front panel into the panel's signals: all of it, or
    /// what is on screen and the rest in turn in a running frame of
    /// `turn` ([`Due::of`]).
    fn refresh_panel(&self, turn: Option<u64>);
    /// Runs `f` on the machine and the plant coupled to it (issue #52).
    fn rig(&self, f: &mut dyn FnMut(&mut dyn Plc, &mut RigSlot));
}

/// A machine's simulator and its panel's refresh: the one implementation
/// of [`MachineLink`].
pub struct Linked<M: 'static> {
    /// The simulator, outside the reactive graph.
    pub sim: StoredValue<Simulator<M>, LocalStorage>,
    /// Copies the machine's front into the panel's signals (the frame's
    /// turn: [`MachineLink::refresh_panel`]).
    pub refresh: Callback<Option<u64>>,
}

impl<M> MachineLink for Linked<M>
where
    M: Plc + Clone + 'static,
    Recorded<M>: Plc + TimeTravel,
{
    fn operate(&self, f: &mut dyn FnMut(&mut dyn Plc)) {
        self.sim.update_value(|s| f(s.machine_mut()));
    }

    fn travel(&self, f: &mut dyn FnMut(&mut dyn TimeTravel)) {
        self.sim.update_value(|s| f(s.machine_mut()));
    }

    fn read(&self, f: &mut dyn FnMut(&dyn Plc)) {
        self.sim.with_value(|s| f(s.machine()));
    }

    fn advance(&self, pace: Pace, wall_ms: f64) {
        self.sim.update_value(|s| s.frame(pace, wall_ms));
    }

    fn after_frame(&self, pace: Pace, deadline_ms: f64, now_ms: fn() -> f64) {
        self.sim
            .update_value(|s| s.after_frame(pace, deadline_ms, now_ms));
    }

    fn refresh_panel(&self, turn: Option<u64>) {
        self.refresh.run(turn);
    }

    fn rig(&self, f: &mut dyn FnMut(&mut dyn Plc, &mut RigSlot)) {
        self.sim.update_value(|s| {
            let (machine, rig) = s.machine_and_rig();
            f(machine, rig);
        });
    }
}

impl LadderCtx {
    /// Connects the editor to its machine.
    pub fn attach(&self, link: std::rc::Rc<dyn MachineLink>) {
        self.live.link.set_value(Some(link));
    }

    /// Whether the editor's machine is there (attached).
    pub fn attached(&self) -> bool {
        self.live.link.with_value(Option::is_some)
    }

    /// Runs `then` once the machine is attached: now, or when it arrives
    /// with its part (issue #53; `machines::arrival::wire`).
    pub fn when_attached(&self, then: impl FnOnce() + 'static) {
        if self.attached() {
            then();
        } else {
            self.live
                .on_arrival
                .update_value(|w| w.push(Box::new(then)));
        }
    }

    /// Runs what waited for the machine ([`LadderCtx::when_attached`]).
    pub fn arrived(&self) {
        let waiting = self.live.on_arrival.try_update_value(std::mem::take);
        for then in waiting.unwrap_or_default() {
            then();
        }
    }

    /// Power-up in STOP: nothing runs and simulated time stands still
    /// until Run (docs/app.md, "Stopped until Run"). A machine with a
    /// RUN switch is switched to STOP; the AVR PLC, which has none, stays
    /// powered off.
    pub fn stop_at_power_up(&self) {
        if self.machine.target().stoppable() {
            self.operate(|plc| {
                let _ = plc.apply(engine::plc::Command::Run(false));
            });
        } else {
            self.live.powered_off.set(true);
        }
        self.live.monitor.set(false);
    }

    /// The program pane's own Load: the program loaded is started, as the
    /// IO86A's and the Arduino's loads always did (a download to the
    /// PLC, then RUN); the AVR PLC is powered on.
    pub fn run_loaded(&self) {
        self.live.powered_off.set(false);
        if self.machine.target().stoppable() {
            self.operate(|plc| {
                let _ = plc.apply(engine::plc::Command::Run(true));
            });
        }
    }

    fn link(&self) -> Option<std::rc::Rc<dyn MachineLink>> {
        self.live.link.with_value(Clone::clone)
    }

    /// Operates the machine, then shows the result in its panel and on
    /// the ladder at once (even paused).
    pub fn operate(&self, f: impl FnOnce(&mut dyn Plc)) {
        let Some(link) = self.link() else {
            return;
        };
        let mut f = Some(f);
        link.operate(&mut |plc| {
            if let Some(f) = f.take() {
                f(plc);
            }
        });
        self.show_machine();
    }

    /// Runs `f` on the machine's recording; `None` without a machine.
    pub fn recorded<R>(&self, f: impl FnOnce(&mut dyn TimeTravel) -> R) -> Option<R> {
        let link = self.link()?;
        let mut f = Some(f);
        let mut out = None;
        link.travel(&mut |t| {
            if let Some(f) = f.take() {
                out = Some(f(t));
            }
        });
        out
    }

    /// Runs `f` on the machine and the plant coupled to it (nothing
    /// without a machine).
    pub fn with_rig(&self, f: impl FnOnce(&mut dyn Plc, &mut RigSlot)) {
        let Some(link) = self.link() else {
            return;
        };
        let mut f = Some(f);
        link.rig(&mut |machine, rig| {
            if let Some(f) = f.take() {
                f(machine, rig);
            }
        });
    }

    /// Reads the machine; `None` without a machine.
    pub fn with_plc<R>(&self, f: impl FnOnce(&dyn Plc) -> R) -> Option<R> {
        let link = self.link()?;
        let mut f = Some(f);
        let mut out = None;
        link.read(&mut |plc| {
            if let Some(f) = f.take() {
                out = Some(f(plc));
            }
        });
        out
    }

    /// Shows the machine as it now is (after a seek): its panel and the
    /// ladder's live state.
    pub fn show_machine(&self) {
        let Some(link) = self.link() else {
            return;
        };
        link.refresh_panel(None);
        self.read_plant_watch();
        self.with_plc(|plc| self.show_live(plc, &Due::All));
    }

    /// The plant's value of each watched name (`tank.level`) at the scan
    /// shown, for the watch table (issue #52); none without a plant.
    fn read_plant_watch(&self) {
        // Nothing to ask (the usual case): no reading, no allocation.
        let dotted = (self.live.watch).with_untracked(|w| w.iter().any(|n| n.contains('.')));
        if !dotted {
            if !self.live.plant_watch.with_value(Vec::is_empty) {
                self.live.plant_watch.set_value(Vec::new());
            }
            return;
        }
        let names = self.live.watch.get_untracked();
        let mut values = vec![None; names.len()];
        let at = self.recorded(|t| t.plc().now()).unwrap_or_default();
        self.with_rig(|_, rig| {
            let Some(rig) = rig else { return };
            for (v, name) in values.iter_mut().zip(&names) {
                *v = rig
                    .series(name, &[at])
                    .and_then(|s| s.first().copied().flatten());
            }
        });
        self.live.plant_watch.set_value(values);
    }

    /// One animation frame for this editor's machine: `wall_ms` of wall
    /// time at `pace`, then the recording, breaks, "why", pulses and live
    /// colours brought up to date.
    pub fn frame(&self, pace: Pace, wall_ms: f64, now_ms: fn() -> f64) {
        let Some(link) = self.link() else {
            return;
        };
        if !pace.paused && self.travel.shown.get_untracked().is_some() {
            // Running again from a past scan on show: live first (Resume
            // from here is the way to run on from the past).
            super::travel::travel_here(*self, |t| t.go_live());
        }
        let pace = self.pace_here(pace);
        link.advance(pace, wall_ms);
        let turn = self.turn(pace);
        link.refresh_panel(turn);
        let hit = self.recorded(|t| {
            let hit = t.take_break();
            super::travel::sync(*self, t, now_ms(), hit.is_some());
            hit
        });
        if let Some(Some(b)) = hit {
            // Paused at the end of the scan where the condition held.
            self.page.paused.set(true);
            self.travel.stopped_at.set(Some(b.mark));
        } else if !pace.paused && self.travel.stopped_at.get_untracked().is_some() {
            // Running again: the stop is over.
            self.travel.stopped_at.set(None);
        }
        super::why::follow(*self);
        let history = self.take_history().unwrap_or_default();
        let due = Due::of(turn, || {
            // The shown workspace's ladder (`LadderGrid`'s id): the frame
            // is its machine's.
            super::on_screen::rungs_on_screen(&crate::element_by_id("ladder")?)
        });
        self.show_pulses(&history, &due);
        self.read_plant_watch();
        self.with_plc(|plc| {
            if self.recording() {
                self.observe(plc);
            }
            self.show_live(plc, &due);
        });
    }

    /// After a frame is drawn: `Speed::Max`'s simulation until
    /// `deadline_ms` (`crate::sim::Display::deadline`); the next frame
    /// shows what it ran.
    pub fn after_frame(&self, pace: Pace, deadline_ms: f64, now_ms: fn() -> f64) {
        if let Some(link) = self.link() {
            link.after_frame(self.pace_here(pace), deadline_ms, now_ms);
        }
    }

    /// The page's `pace` for this machine: the AVR PLC powered off by
    /// Stop runs nothing until Run.
    fn pace_here(&self, pace: Pace) -> Pace {
        Pace {
            paused: pace.paused || self.live.powered_off.get_untracked(),
            ..pace
        }
    }

    /// This frame's turn (`crate::editor::on_screen`): the count of
    /// running frames, or none while the machine is paused, stopped or
    /// travelled to (the ladder and the panel are then brought up to
    /// date whole).
    fn turn(&self, pace: Pace) -> Option<u64> {
        let still = pace.paused
            || self.travel.shown.get_untracked().is_some()
            || !self.live.running.get_untracked();
        if still {
            return None;
        }
        let turn = self.live.turn.get_value().wrapping_add(1);
        self.live.turn.set_value(turn);
        Some(turn)
    }

    /// What the machine traced since the last frame.
    fn take_history(&self) -> Option<engine::plc::TraceHistory> {
        let link = self.link()?;
        let mut out = None;
        link.operate(&mut |plc| out = Some(plc.take_trace_history()));
        out
    }
}
