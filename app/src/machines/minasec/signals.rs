//! MINASEC-U's front panel as signals (one per element, set only when its
//! value changes) and its program pane's parse.

use engine::minasec::{Mode, Panel, Program};
use leptos::prelude::*;

use crate::state::put;

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

impl Default for PanelSignals {
    fn default() -> Self {
        PanelSignals::new()
    }
}

impl PanelSignals {
    /// Every element dark, switches off.
    pub fn new() -> PanelSignals {
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
    /// Located errors: (line, why), said in the page's language when
    /// shown (issue #49).
    Bad(Vec<(usize, engine::minasec::AsmError)>),
}

impl Parsed {
    /// Parses the program pane's text.
    pub fn of(text: &str) -> Parsed {
        match Program::parse(text) {
            Ok(program) => Parsed::Good(Box::new(program)),
            Err(errors) => Parsed::Bad(errors.into_iter().map(|e| (e.line, e.error)).collect()),
        }
    }
}
