//! The app's shared state: the simulator (outside the reactive graph), one
//! signal per panel element, and the editor's state. Components reach it
//! through [`Ctx`], a `Copy` handle in context.

use engine::minasec::{Command, Mode, Panel, Program, TimerId};
use engine::plc::{self, Front, MinasecPlc, Plc};
use engine::SimTime;
use leptos::prelude::*;

use crate::i18n::Lang;
use crate::sim::{Simulator, Speed};
use crate::storage::{self, Saved};

/// Sets `signal` to `value` only if it differs, so only the elements that
/// show a changed value repaint.
pub fn put<T: PartialEq + Send + Sync + 'static>(signal: RwSignal<T>, value: T) {
    if signal.with_untracked(|old| *old != value) {
        signal.set(value);
    }
}

fn bits() -> [RwSignal<bool>; 8] {
    std::array::from_fn(|_| RwSignal::new(false))
}

/// One signal per element of the front panel.
#[derive(Clone, Copy)]
pub struct PanelSignals {
    pub power: RwSignal<bool>,
    pub mode: RwSignal<Mode>,
    pub slow: RwSignal<bool>,
    /// PC LEDs, index = bit.
    pub pc: [RwSignal<bool>; 8],
    /// Instruction LEDs, index = bit.
    pub instruction: [RwSignal<bool>; 8],
    pub acc: RwSignal<bool>,
    /// Input switches X00..X07.
    pub inputs: [RwSignal<bool>; 8],
    /// Output lamps Y00..Y07.
    pub lamps: [RwSignal<bool>; 8],
    /// The 7-segment digits; `None` when dark.
    pub digits: RwSignal<Option<(u8, u8)>>,
    /// RV1, RV2 delays in ms.
    pub delays_ms: [RwSignal<u64>; 2],
    /// Rotary switches (tens, ones).
    pub preset: [RwSignal<u8>; 2],
    /// DIP switches, index = bit (7 = OP2).
    pub dip: [RwSignal<bool>; 8],
    pub write_held: RwSignal<bool>,
    pub clock_held: RwSignal<bool>,
    pub count_clear_held: RwSignal<bool>,
    /// Simulated time in whole ms, and completed scans.
    pub sim_ms: RwSignal<u64>,
    pub scans: RwSignal<u64>,
}

impl PanelSignals {
    fn new() -> PanelSignals {
        PanelSignals {
            power: RwSignal::new(false),
            mode: RwSignal::new(Mode::Halt),
            slow: RwSignal::new(false),
            pc: bits(),
            instruction: bits(),
            acc: RwSignal::new(false),
            inputs: bits(),
            lamps: bits(),
            digits: RwSignal::new(None),
            delays_ms: [RwSignal::new(0), RwSignal::new(0)],
            preset: [RwSignal::new(0), RwSignal::new(0)],
            dip: bits(),
            write_held: RwSignal::new(false),
            clock_held: RwSignal::new(false),
            count_clear_held: RwSignal::new(false),
            sim_ms: RwSignal::new(0),
            scans: RwSignal::new(0),
        }
    }

    /// Copies a panel snapshot into the signals that changed.
    pub fn sync(&self, panel: &Panel, sim_ms: u64, scans: u64) {
        put(self.power, panel.power);
        if let Some(mode) = panel.mode {
            put(self.mode, mode);
        }
        put(self.slow, panel.slow);
        for bit in 0..8 {
            put(self.pc[bit], panel.pc_leds >> bit & 1 != 0);
            put(
                self.instruction[bit],
                panel.instruction_leds >> bit & 1 != 0,
            );
            put(self.inputs[bit], panel.input_switches >> bit & 1 != 0);
            put(self.lamps[bit], panel.lamps >> bit & 1 != 0);
            put(self.dip[bit], panel.dip >> bit & 1 != 0);
        }
        put(self.acc, panel.acc_led);
        put(self.digits, panel.digits);
        for (signal, delay) in self.delays_ms.iter().zip(panel.delays) {
            put(*signal, delay.as_nanos() / 1_000_000);
        }
        put(self.preset[0], panel.preset.0);
        put(self.preset[1], panel.preset.1);
        put(self.write_held, panel.write_held);
        put(self.clock_held, panel.clock_held);
        put(self.count_clear_held, panel.count_clear_held);
        put(self.sim_ms, sim_ms);
        put(self.scans, scans);
    }
}

/// The result of parsing the program pane's text.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Parsed {
    /// A program, ready to load.
    Good(Box<Program>),
    /// Located errors: (line, message).
    Bad(Vec<(usize, String)>),
}

impl Parsed {
    /// Parses the program pane's text.
    pub fn of(text: &str) -> Parsed {
        match Program::parse(text) {
            Ok(program) => Parsed::Good(Box::new(program)),
            Err(errors) => Parsed::Bad(
                errors
                    .into_iter()
                    .map(|e| (e.line, e.error.to_string()))
                    .collect(),
            ),
        }
    }
}

/// Which machine the page shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MachineKind {
    MinasecU,
    Io86a,
    ArduinoPlc,
    AvrPlc,
}

impl MachineKind {
    /// The id used in the `machine` select, storage and the CLI.
    pub const fn code(self) -> &'static str {
        match self {
            MachineKind::MinasecU => "minasec-u",
            MachineKind::Io86a => "io86a",
            MachineKind::ArduinoPlc => "arduino-plc",
            MachineKind::AvrPlc => "avr-plc",
        }
    }

    /// The machine for an id.
    pub fn from_code(code: &str) -> Option<MachineKind> {
        match code {
            "minasec-u" => Some(MachineKind::MinasecU),
            "io86a" => Some(MachineKind::Io86a),
            "arduino-plc" => Some(MachineKind::ArduinoPlc),
            "avr-plc" => Some(MachineKind::AvrPlc),
            _ => None,
        }
    }
}

/// Everything components share; `Copy`, provided as context.
#[derive(Clone, Copy)]
pub struct Ctx {
    /// The simulator, outside the reactive graph.
    pub sim: StoredValue<Simulator<MinasecPlc>, LocalStorage>,
    pub panel: PanelSignals,
    pub lang: RwSignal<Lang>,
    /// The machine shown.
    pub machine: RwSignal<MachineKind>,
    pub speed: RwSignal<Speed>,
    pub paused: RwSignal<bool>,
    /// The program pane's text.
    pub text: RwSignal<String>,
    /// The text last loaded into the board.
    pub loaded: RwSignal<Option<String>>,
    /// The text before an example replaced it, for undo.
    pub before_example: RwSignal<Option<String>>,
    /// A message about saved data (corrupt, storage unavailable).
    pub notice: RwSignal<Option<String>>,
}

impl Ctx {
    /// A fresh context around `sim`.
    pub fn new(sim: Simulator<MinasecPlc>, lang: Lang) -> Ctx {
        let ctx = Ctx {
            sim: StoredValue::new_local(sim),
            panel: PanelSignals::new(),
            lang: RwSignal::new(lang),
            machine: RwSignal::new(MachineKind::MinasecU),
            speed: RwSignal::new(Speed::Times(1)),
            paused: RwSignal::new(false),
            text: RwSignal::new(String::new()),
            loaded: RwSignal::new(None),
            before_example: RwSignal::new(None),
            notice: RwSignal::new(None),
        };
        ctx.refresh();
        ctx
    }

    /// The context provided by [`crate::App`].
    pub fn get() -> Ctx {
        expect_context::<Ctx>()
    }

    /// Operates a panel control and shows the result at once (even paused).
    /// Returns whether the board took the command.
    pub fn send(&self, command: Command) -> bool {
        let ok = self
            .sim
            .try_update_value(|s| {
                s.machine_mut()
                    .apply(plc::Command::Minasec(command))
                    .is_ok()
            })
            .unwrap_or(false);
        self.refresh();
        ok
    }

    /// Copies the board's panel into the signals.
    pub fn refresh(&self) {
        self.sim.with_value(|s| {
            let machine = s.machine();
            let mut front = Front::Minasec(Panel::default());
            machine.front_into(&mut front);
            if let Front::Minasec(panel) = &front {
                self.panel
                    .sync(panel, machine.now().as_nanos() / 1_000_000, machine.scans());
            }
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
        if !storage::save(&saved) {
            let texts = self.lang.get_untracked().texts();
            self.notice.set(Some(texts.storage_unavailable.to_string()));
        }
    }

    /// Applies saved panel settings; values out of range are refused by the
    /// board and left as they were.
    pub fn apply_settings(&self, rv1_ms: u64, rv2_ms: u64, tens: u8, ones: u8) {
        self.send(Command::SetDelay(TimerId::T0, SimTime::from_millis(rv1_ms)));
        self.send(Command::SetDelay(TimerId::T1, SimTime::from_millis(rv2_ms)));
        self.send(Command::SetCounterPreset(tens, ones));
    }
}
