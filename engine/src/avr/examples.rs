//! The AVR PLC's example programs (the page's example menu, the
//! start screen's gallery and tests), in its own text.

use crate::plc::Example;
use crate::MachineId;

/// The AVR PLC's examples, in menu order.
pub const EXAMPLES: &[Example] = &[
    Example {
        id: "self-hold",
        machine: MachineId::AvrPlc,
        title_en: "Seed: self-holding rungs",
        title_ja: "自己保持回路",
        text: include_str!("../../programs/avr-plc/self-hold.asm"),
    },
    Example {
        id: "e-stop-timer",
        machine: MachineId::AvrPlc,
        title_en: "Seed: TOF timer (E_Stop)",
        title_ja: "TOFタイマ (E_Stop)",
        text: include_str!("../../programs/avr-plc/e-stop-timer.asm"),
    },
];
