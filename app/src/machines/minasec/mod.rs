//! The MINASEC-U workspace's state: the board (outside the reactive
//! graph), one signal per panel element, and the program pane.

pub mod board;
pub mod cpu_view;
pub mod examples;
pub mod header;
pub mod program;
pub mod saved;
pub mod signals;

use engine::machines::MinasecPlc;
use engine::minasec::{Command, Panel, TimerId};
use engine::plc::{self, Front, Plc};
use engine::SimTime;
use leptos::prelude::*;

use crate::sim::Simulator;
use crate::state::Ctx;
use crate::storage::Restored;
use saved::Saved;
pub use signals::{PanelSignals, Parsed};

/// The MINASEC-U workspace: the board, one signal per panel element,
/// the program pane; `Copy`, provided as context.
#[derive(Clone, Copy)]
pub struct MinasecCtx {
    /// The page it belongs to (language, notices).
    pub page: Ctx,
    /// The simulator, outside the reactive graph.
    pub sim: StoredValue<Simulator<MinasecPlc>, LocalStorage>,
    pub panel: PanelSignals,
    /// The program pane's text.
    pub text: RwSignal<String>,
    /// The text last loaded into the board.
    pub loaded: RwSignal<Option<String>>,
    /// The text before an example replaced it, for undo.
    pub before_example: RwSignal<Option<String>>,
    /// The view inside the CPU (issue #33).
    pub cpu: cpu_view::CpuSignals,
}

impl MinasecCtx {
    /// A workspace on `page` around `sim`.
    pub fn new(page: Ctx, sim: Simulator<MinasecPlc>) -> MinasecCtx {
        let ctx = MinasecCtx {
            page,
            sim: StoredValue::new_local(sim),
            panel: PanelSignals::new(),
            text: RwSignal::new(String::new()),
            loaded: RwSignal::new(None),
            before_example: RwSignal::new(None),
            cpu: cpu_view::CpuSignals::new(),
        };
        ctx.refresh();
        ctx
    }

    /// A workspace restored from autosave (or fresh): the board as it
    /// comes out of its box, powered, switch at HALT.
    pub fn restore(page: Ctx) -> MinasecCtx {
        let mut board = MinasecPlc::new();
        let _ = board.apply(plc::Command::Run(false));
        let ctx = MinasecCtx::new(page, Simulator::new(board));
        let texts = page.lang.get_untracked().texts();
        match saved::restore() {
            Restored::Saved(saved) => {
                ctx.text.set(saved.program);
                ctx.apply_settings(
                    saved.rv1_ms,
                    saved.rv2_ms,
                    saved.preset_tens,
                    saved.preset_ones,
                );
                // Program memory is battery-backed: the board keeps what
                // was loaded. A text with errors stays in the pane, unloaded.
                ctx.load_text();
            }
            Restored::Corrupt { kept_as } => {
                page.notice
                    .set(Some(format!("{} {kept_as}", texts.corrupt_saved)));
            }
            Restored::Unavailable => page.notice.set(Some(texts.storage_unavailable.to_string())),
            Restored::Nothing => {}
        }
        ctx
    }

    /// The context provided by [`crate::App`].
    pub fn get() -> MinasecCtx {
        expect_context::<MinasecCtx>()
    }

    /// Operates a panel control and shows the result at once (even paused).
    /// Returns whether the board took the command.
    pub fn send(&self, command: Command) -> bool {
        let ok = self
            .sim
            .try_update_value(|s| {
                // The panel's switch turned on (from off): a power cycle,
                // which puts the plant back at its start.
                let on = matches!(command, Command::Power(true));
                let ok = (s.machine_mut())
                    .apply(plc::Command::Own(plc::Own::new(command)))
                    .is_ok();
                if ok && on {
                    s.power_cycled();
                }
                ok
            })
            .unwrap_or(false);
        self.refresh();
        ok
    }

    /// Copies the board's panel into the signals.
    pub fn refresh(&self) {
        self.sim.with_value(|s| {
            let machine = s.machine();
            let mut front = Front::none();
            machine.front_into(&mut front);
            if let Some(panel) = front.get::<Panel>() {
                self.panel
                    .sync(panel, machine.now().as_nanos() / 1_000_000, machine.scans());
            }
            // The board shown (a past one while travelling in time).
            self.cpu.sync(machine.shown_machine().machine());
        });
    }

    /// Loads the pane's text into the board if it parses; true if loaded.
    pub fn load_text(&self) -> bool {
        let text = self.text.get_untracked();
        let loaded = self
            .sim
            .try_update_value(|s| s.machine_mut().load_text(&text).is_ok())
            .unwrap_or(false);
        if loaded {
            self.loaded.set(Some(text));
            self.refresh();
        }
        loaded
    }

    /// Saves the program text and the panel settings.
    pub fn save(&self) {
        let saved = Saved {
            program: self.text.get_untracked(),
            rv1_ms: self.panel.delays_ms[0].get_untracked(),
            rv2_ms: self.panel.delays_ms[1].get_untracked(),
            preset_tens: self.panel.preset[0].get_untracked(),
            preset_ones: self.panel.preset[1].get_untracked(),
        };
        if !saved::save(&saved) {
            let texts = self.page.lang.get_untracked().texts();
            self.page
                .notice
                .set(Some(texts.storage_unavailable.to_string()));
        }
    }

    /// The panel's settings as a project keeps them (`T0`, `T1`, `C0`).
    pub fn project_settings(&self) -> Vec<(String, String)> {
        let p = self.panel;
        vec![
            ("T0".into(), format!("{}ms", p.delays_ms[0].get_untracked())),
            ("T1".into(), format!("{}ms", p.delays_ms[1].get_untracked())),
            (
                "C0".into(),
                (p.preset[0].get_untracked() * 10 + p.preset[1].get_untracked()).to_string(),
            ),
        ]
    }

    /// Applies a project's settings to the board (through the engine, so
    /// a bad value is refused with its message) and saves them; returns
    /// the refusals.
    pub fn apply_project_settings(&self, settings: Vec<(String, String)>) -> Vec<String> {
        let mut refused = Vec::new();
        for (name, value) in settings {
            let result = self
                .sim
                .try_update_value(|s| {
                    s.machine_mut().apply(plc::Command::Setting {
                        name: name.clone(),
                        value: value.clone(),
                    })
                })
                .unwrap_or(Ok(()));
            if let Err(e) = result {
                refused.push(format!("{name}={value}: {e}"));
            }
        }
        self.refresh();
        self.save();
        refused
    }

    /// Applies saved panel settings; values out of range are refused by the
    /// board and left as they were.
    pub fn apply_settings(&self, rv1_ms: u64, rv2_ms: u64, tens: u8, ones: u8) {
        self.send(Command::SetDelay(TimerId::T0, SimTime::from_millis(rv1_ms)));
        self.send(Command::SetDelay(TimerId::T1, SimTime::from_millis(rv2_ms)));
        self.send(Command::SetCounterPreset(tens, ones));
    }
}
