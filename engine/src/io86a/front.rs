//! The IO86A's front: what its pins show beyond its devices, for both
//! linked devices (the page's chip view), as [`crate::plc::Plc::front_into`]
//! fills it.

use super::peripherals::{InputMode, IrMode, OutputSignal};

/// Both devices' fronts: A, and B (at rest until one is linked).
pub type Fronts = [Io86aFront; 2];

/// One IO86A's pins as its front shows them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Io86aFront {
    /// The input pins as driven (bit n = X0n).
    pub inputs: u8,
    /// The output pins (bit n = Y0n).
    pub outputs: u8,
    /// D00-D07 after the last scan.
    pub d: [i16; 8],
    /// Volts on X04 / X05 in millivolts.
    pub analog_mv: [i64; 2],
    /// Whether X04 / X05 are analog inputs.
    pub analog: [bool; 2],
    /// Whether X07 is the IR receiver.
    pub ir: bool,
    /// What Y03 / Y04 put out.
    pub signals: [OutputSignal; 2],
    /// RUN (else STOP).
    pub running: bool,
}

impl Io86aFront {
    /// Device `m`'s front.
    pub fn of(m: &super::Machine) -> Io86aFront {
        let settings = m.settings();
        Io86aFront {
            inputs: m.input_terminals(),
            outputs: m.output_terminals(),
            d: m.last_scan().d,
            analog_mv: [m.analog(0), m.analog(1)],
            analog: settings.analog.map(|a| a != InputMode::Digital),
            ir: settings.ir != IrMode::Digital,
            signals: [m.output_signal(0), m.output_signal(1)],
            running: m.running(),
        }
    }
}
