//! What a machine's front shows beyond its devices (MINASEC-U's panel of
//! LEDs, switches and knobs; the IO86A's pin modes and output signals),
//! copied each frame into a value the caller keeps.

use crate::io86a::peripherals::{InputMode, IrMode, OutputSignal};
use crate::minasec::Panel;

/// A machine's front, as [`super::Plc::front_into`] fills it.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub enum Front {
    /// Nothing beyond the devices (the Arduino sketch, the AVR PLC), or
    /// nothing copied yet.
    #[default]
    None,
    /// MINASEC-U's front panel.
    Minasec(Panel),
    /// The IO86A: device A, and device B when two are linked.
    Io86a([Io86aFront; 2]),
}

/// One IO86A's pins as its front shows them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
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
    pub fn of(m: &crate::io86a::Machine) -> Io86aFront {
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
