//! The four machines' workspaces, listed in this one place: adding a
//! machine means a context here, its view here, and its frame here.

use leptos::prelude::*;

use crate::components::board::Board;
use crate::components::program::ProgramPane;
use crate::minasec::MinasecCtx;
use crate::sim::Pace;
use crate::state::{Ctx, MachineKind};
use crate::{arduino, avr, io86a};

/// Every workspace's context; `Copy`.
#[derive(Clone, Copy)]
pub struct Workspaces {
    pub minasec: MinasecCtx,
    pub io86a: io86a::Io86aCtx,
    pub arduino: arduino::ArduinoCtx,
    pub avr: avr::AvrCtx,
}

impl Workspaces {
    /// Every workspace on `page`, each restored from its autosave.
    pub fn restore(page: Ctx) -> Workspaces {
        Workspaces {
            minasec: MinasecCtx::restore(page),
            io86a: io86a::Io86aCtx::new(),
            arduino: arduino::ArduinoCtx::restore(page),
            avr: avr::AvrCtx::restore(page),
        }
    }

    /// Provides every workspace's context to the components below.
    pub fn provide(&self) {
        provide_context(self.minasec);
        provide_context(self.io86a);
        provide_context(self.arduino);
        provide_context(self.avr);
    }

    /// One animation frame for the workspace of `kind`: `wall_ms` of wall
    /// time at `pace`, then its signals refreshed. The others rest.
    pub fn frame(&self, kind: MachineKind, pace: Pace, wall_ms: f64, now_ms: fn() -> f64) {
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

    /// The workspace of `kind`.
    pub fn view(&self, kind: MachineKind) -> AnyView {
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
