//! The four machines' workspaces, listed in this one place: adding a
//! machine means a context here, its view here, and its frame here.

use leptos::prelude::*;

use engine::MachineId;

use crate::editor::{LadderCtx, LadderEditor, Ladders, Program};
use crate::machines::minasec::board::Board;
use crate::machines::minasec::program::ProgramPane;
use crate::machines::minasec::MinasecCtx;
use crate::machines::{arduino, avr, io86a};
use crate::sim::Pace;
use crate::state::{Ctx, MachineKind};

/// Every workspace's context; `Copy`.
#[derive(Clone, Copy)]
pub struct Workspaces {
    pub minasec: MinasecCtx,
    pub io86a: io86a::Io86aCtx,
    pub arduino: arduino::ArduinoCtx,
    pub avr: avr::AvrCtx,
    /// Each machine's ladder editor.
    pub ladders: Ladders,
    /// The named projects.
    pub projects: crate::editor::projects::Projects,
}

impl Workspaces {
    /// Every workspace on `page`, each restored from its autosave.
    pub fn restore(page: Ctx) -> Workspaces {
        let minasec = MinasecCtx::restore(page);
        let io86a = io86a::Io86aCtx::new();
        let arduino = arduino::ArduinoCtx::restore(page);
        let avr = avr::AvrCtx::restore(page);
        Workspaces::around(page, minasec, io86a, arduino, avr)
    }

    /// The workspaces of these machines, each with its ladder editor
    /// connected to its program pane.
    pub fn around(
        page: Ctx,
        minasec: MinasecCtx,
        io86a: io86a::Io86aCtx,
        arduino: arduino::ArduinoCtx,
        avr: avr::AvrCtx,
    ) -> Workspaces {
        let editor = |machine| LadderCtx::restore(page, machine);
        let ladders = Ladders {
            minasec: editor(MachineId::MinasecU),
            io86a: editor(MachineId::Io86a),
            avr: editor(MachineId::AvrPlc),
            arduino: editor(MachineId::ArduinoPlc),
        };
        ladders.minasec.connect(Program {
            text: minasec.text,
            load: Callback::new(move |()| {
                minasec.load_text();
                minasec.save();
            }),
            save: Callback::new(move |()| minasec.save()),
            settings: Callback::new(move |()| minasec.project_settings()),
            apply_settings: Callback::new(move |settings| minasec.apply_project_settings(settings)),
        });
        ladders.io86a.connect(Program {
            text: io86a.texts[0],
            load: Callback::new(move |()| {
                io86a.load(0);
                io86a.save();
            }),
            save: Callback::new(move |()| io86a.save()),
            settings: Callback::new(|()| Vec::new()),
            apply_settings: Callback::new(not_applied),
        });
        ladders.arduino.connect(Program {
            text: arduino.text,
            load: Callback::new(move |()| {
                arduino.load();
                arduino.save();
            }),
            save: Callback::new(move |()| arduino.save()),
            settings: Callback::new(|()| Vec::new()),
            apply_settings: Callback::new(not_applied),
        });
        ladders
            .avr
            .options
            .update(|o| o.avr_scan_ms = avr::scan_ms_default());
        ladders.avr.connect(Program {
            text: avr.text,
            load: Callback::new(move |()| {
                avr.load();
                avr.save();
            }),
            save: Callback::new(move |()| avr.save()),
            settings: Callback::new(|()| Vec::new()),
            apply_settings: Callback::new(not_applied),
        });
        Workspaces {
            minasec,
            io86a,
            arduino,
            avr,
            ladders,
            projects: crate::editor::projects::Projects::restore(page),
        }
    }

    /// Provides every workspace's context to the components below.
    pub fn provide(&self) {
        provide_context(self.minasec);
        provide_context(self.io86a);
        provide_context(self.arduino);
        provide_context(self.avr);
        provide_context(self.ladders);
        provide_context(self.projects);
        provide_context(*self);
    }

    /// Operates the machine of `kind`'s workspace, then shows the result
    /// in its panel and on its ladder at once (even paused).
    pub fn operate(&self, kind: MachineKind, f: impl FnOnce(&mut dyn engine::plc::Plc)) {
        match kind {
            MachineKind::MinasecU => {
                self.minasec.sim.update_value(|s| f(s.machine_mut()));
                self.minasec.refresh();
            }
            MachineKind::Io86a => {
                self.io86a.sim.update_value(|s| f(s.machine_mut()));
                self.io86a.refresh();
            }
            MachineKind::ArduinoPlc => {
                self.arduino.sim.update_value(|s| f(s.machine_mut()));
                self.arduino.refresh();
            }
            MachineKind::AvrPlc => {
                self.avr.sim.update_value(|s| f(s.machine_mut()));
                self.avr.refresh();
            }
        }
        let ladder = self.ladders.of(kind);
        self.with_plc(kind, |plc| ladder.show_live(plc));
    }

    /// Runs `f` on the recording of `kind`'s machine (time travel, the
    /// timing chart, breaks).
    pub fn travel<R>(
        &self,
        kind: MachineKind,
        f: impl FnOnce(&mut dyn engine::record::TimeTravel) -> R,
    ) -> Option<R> {
        match kind {
            MachineKind::MinasecU => self.minasec.sim.try_update_value(|s| f(s.machine_mut())),
            MachineKind::Io86a => self.io86a.sim.try_update_value(|s| f(s.machine_mut())),
            MachineKind::ArduinoPlc => self.arduino.sim.try_update_value(|s| f(s.machine_mut())),
            MachineKind::AvrPlc => self.avr.sim.try_update_value(|s| f(s.machine_mut())),
        }
    }

    /// Shows the machine of `kind` as it now is (after a seek): its panel
    /// and its ladder.
    pub fn show(&self, kind: MachineKind) {
        match kind {
            MachineKind::MinasecU => self.minasec.refresh(),
            MachineKind::Io86a => self.io86a.refresh(),
            MachineKind::ArduinoPlc => self.arduino.refresh(),
            MachineKind::AvrPlc => self.avr.refresh(),
        }
        let ladder = self.ladders.of(kind);
        self.with_plc(kind, |plc| ladder.show_live(plc));
    }

    /// What the machine of `kind` traced since the last frame.
    fn take_history(&self, kind: MachineKind) -> engine::plc::TraceHistory {
        use engine::plc::Plc;
        let take = |f: &mut dyn Plc| f.take_trace_history();
        match kind {
            MachineKind::MinasecU => self.minasec.sim.try_update_value(|s| take(s.machine_mut())),
            MachineKind::Io86a => self.io86a.sim.try_update_value(|s| take(s.machine_mut())),
            MachineKind::ArduinoPlc => self.arduino.sim.try_update_value(|s| take(s.machine_mut())),
            MachineKind::AvrPlc => self.avr.sim.try_update_value(|s| take(s.machine_mut())),
        }
        .unwrap_or_default()
    }

    /// Runs `f` on the machine of `kind`'s workspace.
    pub fn with_plc(&self, kind: MachineKind, f: impl FnOnce(&dyn engine::plc::Plc)) {
        match kind {
            MachineKind::MinasecU => self.minasec.sim.with_value(|s| f(s.machine())),
            MachineKind::Io86a => self.io86a.sim.with_value(|s| f(s.machine())),
            MachineKind::ArduinoPlc => self.arduino.sim.with_value(|s| f(s.machine())),
            MachineKind::AvrPlc => self.avr.sim.with_value(|s| f(s.machine())),
        }
    }

    /// One animation frame for the workspace of `kind`: `wall_ms` of wall
    /// time at `pace`, then its signals refreshed. The others rest.
    pub fn frame(&self, kind: MachineKind, pace: Pace, wall_ms: f64, now_ms: fn() -> f64) {
        let ladder = self.ladders.of(kind);
        if !pace.paused && ladder.travel.shown.get_untracked().is_some() {
            // Running again from a past scan on show: live first (Resume
            // from here is the way to run on from the past).
            crate::editor::travel::travel_with(*self, ladder, |t| t.go_live());
        }
        self.advance(kind, pace, wall_ms, now_ms);
        let hit = self.travel(kind, |t| {
            let hit = t.take_break();
            crate::editor::travel::sync(ladder, t, now_ms(), hit.is_some());
            hit
        });
        if let Some(Some(b)) = hit {
            // Paused at the end of the scan where the condition held.
            ladder.page.paused.set(true);
            ladder.travel.stopped_at.set(Some(b.mark));
        } else if !pace.paused && ladder.travel.stopped_at.get_untracked().is_some() {
            // Running again: the stop is over.
            ladder.travel.stopped_at.set(None);
        }
        crate::editor::why::follow(ladder, *self);
        let history = self.take_history(kind);
        ladder.show_pulses(&history);
        self.with_plc(kind, |plc| {
            if ladder.recording() {
                ladder.observe(plc);
            }
            ladder.show_live(plc);
        });
    }

    fn advance(&self, kind: MachineKind, pace: Pace, wall_ms: f64, now_ms: fn() -> f64) {
        match kind {
            MachineKind::MinasecU => {
                let w = self.minasec;
                w.sim.update_value(|s| s.frame(pace, wall_ms, now_ms));
                w.refresh();
            }
            MachineKind::Io86a => {
                let w = self.io86a;
                w.sim.update_value(|s| s.frame(pace, wall_ms, now_ms));
                w.refresh();
            }
            MachineKind::ArduinoPlc => {
                let w = self.arduino;
                w.sim.update_value(|s| s.frame(pace, wall_ms, now_ms));
                w.refresh();
            }
            MachineKind::AvrPlc => {
                let w = self.avr;
                w.sim.update_value(|s| s.frame(pace, wall_ms, now_ms));
                w.refresh();
            }
        }
    }

    /// The workspace of `kind`: its ladder editor above its panel and
    /// program pane (which find the editor in context for "Load as ladder").
    pub fn view(&self, kind: MachineKind) -> AnyView {
        let ladder = self.ladders.of(kind);
        provide_context(ladder);
        let machine = self.machine_view(kind);
        view! {
            <div class="machine-view">
                <LadderEditor ctx=ladder />
                <div class="machine-side">{machine}</div>
            </div>
        }
        .into_any()
    }

    fn machine_view(&self, kind: MachineKind) -> AnyView {
        match kind {
            MachineKind::MinasecU => view! {
                <main class="workspace">
                    <Board />
                    <ProgramPane />
                </main>
            }
            .into_any(),
            MachineKind::Io86a => {
                view! { <io86a::view::Io86aWorkspace io=self.io86a /> }.into_any()
            }
            MachineKind::ArduinoPlc => {
                view! { <arduino::ArduinoWorkspace ard=self.arduino /> }.into_any()
            }
            MachineKind::AvrPlc => view! { <avr::AvrWorkspace avr=self.avr /> }.into_any(),
        }
    }
}

/// The settings a project brings to a workspace that keeps none of its
/// own: each is reported, none is dropped silently.
fn not_applied(settings: Vec<(String, String)>) -> Vec<String> {
    settings
        .into_iter()
        .map(|(name, value)| {
            format!("{name}={value}: this workspace keeps no settings; not applied.")
        })
        .collect()
}
