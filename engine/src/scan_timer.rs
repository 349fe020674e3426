//! IEC timers that count scans: the AVR PLC's in-line TON / TOF / TP
//! (docs/avr-plc.md), and the reference evaluator's, which must behave
//! the same. Neither owns them: both use this module.

use serde::{Deserialize, Serialize};

/// The IEC timer kinds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum TimerKind {
    /// On-delay.
    Ton,
    /// Off-delay (on for its time after power-up: the AVR seed's warning).
    Tof,
    /// Pulse, not retriggerable.
    Tp,
}

impl TimerKind {
    /// The IEC name: `TON`, `TOF`, `TP`.
    pub const fn name(self) -> &'static str {
        match self {
            TimerKind::Ton => "TON",
            TimerKind::Tof => "TOF",
            TimerKind::Tp => "TP",
        }
    }
}

/// A scan-counting timer: the count (the AVR PLC's 2-byte RAM word,
/// zero after power-up) plus the pulse timer's state.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ScanTimer {
    /// Scans counted (the 2-byte RAM word; zero after power-up).
    pub count: u16,
    /// TP: the input in the last scan, for its rising edge.
    prev_in: bool,
    /// TP: a pulse is running.
    pulsing: bool,
    /// TP: the pulse ended while the input was still on.
    done: bool,
}

impl ScanTimer {
    /// Runs one scan: takes IN, returns Q; `preset` counts scans
    /// (docs/avr-plc.md).
    pub fn run(&mut self, kind: TimerKind, input: bool, preset: u16) -> bool {
        match kind {
            // Q once IN has been on for `preset` scans.
            TimerKind::Ton => {
                if input {
                    let q = self.count >= preset;
                    if !q {
                        self.count += 1;
                    }
                    q
                } else {
                    self.count = 0;
                    false
                }
            }
            // Q while IN, and for `preset` scans after IN drops. The count
            // starts at zero after power-up, so Q is on then too.
            TimerKind::Tof => {
                if input {
                    self.count = 0;
                    true
                } else {
                    let q = self.count < preset;
                    if q {
                        self.count += 1;
                    }
                    q
                }
            }
            // Q for `preset` scans from a rising edge of IN; a new pulse
            // needs IN to drop after the last one ended.
            TimerKind::Tp => {
                let rising = input && !self.prev_in;
                self.prev_in = input;
                if !self.pulsing && !self.done && rising {
                    self.pulsing = true;
                    self.count = 0;
                }
                if self.pulsing {
                    if self.count < preset {
                        self.count += 1;
                        return true;
                    }
                    self.pulsing = false;
                    self.done = input;
                    return false;
                }
                if !input {
                    self.done = false;
                }
                false
            }
        }
    }
}
