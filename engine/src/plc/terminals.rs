//! A machine's terminals as a plant (crate::plant) sees them: the digital
//! inputs and outputs in the order a plant's default wiring takes them,
//! and the analog inputs with their scale. Each machine says its own in
//! its folder ([`super::Plc::terminals`]), so the plants name no machine.

/// How an analog input takes a value: the unit a plant's 0–100 % maps to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AnalogScale {
    /// Millivolts, 0 % = 0 mV and 100 % = this many (IO86A's 0–5 V).
    Millivolts(i64),
    /// A word, 0 % = 0 and 100 % = this value (the soft PLC's `%IW`).
    Word(i64),
}

/// The terminals a plant wires to by default.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Terminals {
    /// Digital inputs, in order (`X00`, `X01`, …).
    pub inputs: Vec<String>,
    /// Digital outputs, in order (`Y00`, …).
    pub outputs: Vec<String>,
    /// Analog inputs, in order, each with its scale.
    pub analog: Vec<(String, AnalogScale)>,
    /// The machine has no fixed terminals but named bits (the AVR PLC):
    /// a plant's signal wires by default to the program's bit of the same
    /// name in capitals (`INFEED`), when it has one.
    pub by_name: bool,
}

impl Terminals {
    /// `n` terminals, the `i`-th named `name(i)` (`X00`, `X01`, …).
    pub fn numbered(n: usize, name: impl Fn(usize) -> String) -> Vec<String> {
        (0..n).map(name).collect()
    }

    /// The scale of the analog input `device`, if it is one.
    pub fn analog_scale(&self, device: &str) -> Option<AnalogScale> {
        self.analog
            .iter()
            .find(|(name, _)| name.eq_ignore_ascii_case(device))
            .map(|(_, scale)| *scale)
    }
}
