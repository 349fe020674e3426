//! PLC-IO86A under the headless runner: `--set scan=`, input events and
//! watched devices.

use super::isa::{parse_bit, parse_word, Bit, Word};
use super::machine::Machine;
use super::peripherals::{InputMode, IrMode};
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
    /// `Y03.v` / `Y04.v`: the servo pulse in µs, the PWM duty in %, or the
    /// level in digital mode.
    Signal(usize),
}

impl Machine {
    /// Applies one `--set NAME=VALUE`: `scan=<time>`, `filter=<0..10>`, or
    /// a pin setting in the terminal's words: `X04=A:401:100`, `X05=D`,
    /// `X07=I:10EF`, `Y03=R` (S, M, H, D).
    pub fn apply_setting(&mut self, name: &str, value: &str) -> Result<(), String> {
        match name.to_ascii_uppercase().as_str() {
            "SCAN" => {
                let period = SimTime::parse(value).map_err(|e| e.to_string())?;
                self.set_scan_period(period)
            }
            "FILTER" => self
                .settings_mut()
                .apply(&format!("!{value}"))
                .map_err(|e| e.to_string()),
            "X04" | "X05" | "X07" | "Y03" | "Y04" => self
                .settings_mut()
                .apply(&format!("{name}{value}"))
                .map_err(|e| e.to_string()),
            _ => Err(format!(
                "unknown setting {}: io86a takes scan, filter, X04, X05, X07, Y03, Y04",
                crate::error::shown(name)
            )),
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
        match upper.as_str() {
            "Y03.V" => return Ok(Watch::Signal(0)),
            "Y04.V" => return Ok(Watch::Signal(1)),
            _ => {}
        }
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
            Watch::Signal(index) => self.output_signal(index).value(),
        }
    }

    fn check_input(&self, device: &str, value: InputValue) -> Result<(), String> {
        let n = input_number(device)?;
        let analog =
            matches!(n, 4 | 5) && self.settings().analog[usize::from(n - 4)] != InputMode::Digital;
        let ir = n == 7 && self.settings().ir != IrMode::Digital;
        match value {
            InputValue::Millivolts(_) if analog => Ok(()),
            InputValue::Millivolts(_) => Err(format!(
                "{device} is a digital input: a voltage needs analog mode (--set {device}=A:n1:n2)"
            )),
            InputValue::Int(frame) if ir => u32::try_from(frame).map(|_| ()).map_err(|_| {
                format!("{device} receives IR frames: 0 (none) or a 32-bit NEC frame")
            }),
            InputValue::Int(_) if analog => Err(format!(
                "{device} is in analog mode: give a voltage such as 2.5V"
            )),
            InputValue::Int(0 | 1) => Ok(()),
            InputValue::Int(_) => Err(format!("{device} is a bit: its value is 0 or 1")),
        }
    }

    fn apply_input(&mut self, device: &str, value: InputValue) {
        let Ok(n) = input_number(device) else {
            return;
        };
        match value {
            InputValue::Millivolts(mv) => self.set_analog(usize::from(n.saturating_sub(4)), mv),
            InputValue::Int(frame) if n == 7 && self.settings().ir != IrMode::Digital => {
                self.set_ir(u32::try_from(frame).ok().filter(|&f| f != 0));
            }
            InputValue::Int(v) => self.set_input(n, v == 1),
        }
    }

    fn run_before(&mut self, t: SimTime) {
        Machine::run_before(self, t);
    }

    fn run_until(&mut self, t: SimTime) {
        Machine::run_until(self, t);
    }
}
