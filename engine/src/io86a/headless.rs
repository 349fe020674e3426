//! PLC-IO86A under the headless runner: `--set scan=`, input events and
//! watched devices.

use super::isa::{parse_bit, parse_word, Bit, Word};
use super::machine::Machine;
use crate::events::InputValue;
use crate::headless::Simulation;
use crate::time::SimTime;

/// A device `hashigo run --watch` can print for the IO86A.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Watch {
    /// A bit: `X00`, `Y05`, `M61`, `S00`, `T00`, `C00`.
    Bit(Bit),
    /// A value: `T00.v`, `C00.v`, `D00` (or `D00.v`).
    Value(Word),
}

impl Machine {
    /// Applies one `--set NAME=VALUE`: `scan=<time>`.
    pub fn apply_setting(&mut self, name: &str, value: &str) -> Result<(), String> {
        match name.to_ascii_lowercase().as_str() {
            "scan" => {
                let period = SimTime::parse(value).map_err(|e| e.to_string())?;
                self.set_scan_period(period)
            }
            _ => Err(format!("unknown setting \"{name}\": io86a takes scan")),
        }
    }
}

fn input_number(device: &str) -> Result<u8, String> {
    match parse_bit(device).map_err(|e| e.to_string())? {
        Bit::X(n) => Ok(n),
        other => Err(format!("{other} is not an input: events drive X00-X07")),
    }
}

impl Simulation for Machine {
    type Watch = Watch;

    fn setting(&mut self, name: &str, value: &str) -> Result<(), String> {
        Machine::apply_setting(self, name, value)
    }

    fn watch(&self, name: &str) -> Result<Watch, String> {
        let upper = name.to_ascii_uppercase();
        if let Some(base) = upper.strip_suffix(".V") {
            return match parse_word(base).map_err(|e| e.to_string())? {
                Word::K(_) => Err(format!("{name} is a constant, not a device")),
                word => Ok(Watch::Value(word)),
            };
        }
        if upper.starts_with('D') {
            return parse_word(&upper)
                .map(Watch::Value)
                .map_err(|e| e.to_string());
        }
        parse_bit(name).map(Watch::Bit).map_err(|e| e.to_string())
    }

    fn value(&self, watch: Watch) -> i64 {
        let scan = self.last_scan();
        match watch {
            Watch::Bit(Bit::Y(n)) => i64::from(self.output_terminals() >> n & 1),
            Watch::Bit(bit) => i64::from(scan.bit(bit)),
            Watch::Value(word) => i64::from(scan.word(word)),
        }
    }

    fn check_input(&self, device: &str, value: InputValue) -> Result<(), String> {
        input_number(device)?;
        match value {
            InputValue::Int(0 | 1) => Ok(()),
            InputValue::Millivolts(_) => Err(format!(
                "{device}: analog inputs are not emulated yet (X04/X05 AD mode comes with the peripherals)"
            )),
            InputValue::Int(_) => Err(format!("{device} is a bit: its value is 0 or 1")),
        }
    }

    fn apply_input(&mut self, device: &str, value: InputValue) {
        if let Ok(n) = input_number(device) {
            self.set_input(n, value == InputValue::Int(1));
        }
    }

    fn run_before(&mut self, t: SimTime) {
        Machine::run_before(self, t);
    }

    fn run_until(&mut self, t: SimTime) {
        Machine::run_until(self, t);
    }
}
