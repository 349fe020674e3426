//! The Arduino PLC's example programs (the page's example menu, the
//! start screen's gallery and tests), in its own text.

use crate::plc::Example;
use crate::MachineId;

/// The Arduino PLC's examples, in menu order.
pub const EXAMPLES: &[Example] = &[Example {
    id: "self-hold",
    machine: MachineId::ArduinoPlc,
    title_en: "Seed: self-hold",
    title_ja: "自己保持回路",
    text: include_str!("../../programs/arduino-plc/self-hold.txt"),
}];
