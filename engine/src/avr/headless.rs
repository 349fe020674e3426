//! The AVR simplified PLC under the headless runner.

use super::machine::Machine;
use crate::events::InputValue;
use crate::headless::Simulation;
use crate::time::SimTime;

/// A watched bit or timer word.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Watch {
    /// A named bit or `R4.2`.
    Bit(super::BitRef),
    /// `NAME.v`: a timer word's count (NAME is its `.dseg` label).
    Timer(usize),
}

impl Machine {
    /// Applies one `--set NAME=VALUE`: `scan=<time>`.
    pub fn apply_setting(&mut self, name: &str, value: &str) -> Result<(), String> {
        match name.to_ascii_lowercase().as_str() {
            "scan" => self.set_scan_period(SimTime::parse(value).map_err(|e| e.to_string())?),
            _ => Err(format!(
                "unknown setting {}: avr-plc takes scan",
                crate::error::shown(name)
            )),
        }
    }

    fn named_bit(&self, name: &str) -> Result<super::BitRef, String> {
        self.program().bit(name).ok_or_else(|| {
            format!(
                "unknown bit {}: name a bit defined by NAME_R and NAME_B, or write R4.2",
                crate::error::shown(name)
            )
        })
    }
}

impl Simulation for Machine {
    type Watch = Watch;

    fn setting(&mut self, name: &str, value: &str) -> Result<(), String> {
        Machine::apply_setting(self, name, value)
    }

    fn watch(&self, name: &str) -> Result<Watch, String> {
        if let Some(base) = name.strip_suffix(".v").or_else(|| name.strip_suffix(".V")) {
            return self.program().timer(base).map(Watch::Timer).ok_or_else(|| {
                format!(
                    "unknown timer {}: name its label after PLC_Timer_Top",
                    crate::error::shown(base)
                )
            });
        }
        self.named_bit(name).map(Watch::Bit)
    }

    fn value(&self, watch: Watch) -> i64 {
        match watch {
            Watch::Bit(b) => i64::from(self.bit(b)),
            Watch::Timer(i) => self.timer(i).map_or(0, |t| i64::from(t.count)),
        }
    }

    fn check_input(&self, device: &str, value: InputValue) -> Result<(), String> {
        self.named_bit(device)?;
        match value {
            InputValue::Int(0 | 1) => Ok(()),
            _ => Err(format!("{device} is a bit: its value is 0 or 1")),
        }
    }

    fn apply_input(&mut self, device: &str, value: InputValue) {
        if let Ok(b) = self.named_bit(device) {
            self.set_input(b, value == InputValue::Int(1));
        }
    }

    fn run_before(&mut self, t: SimTime) {
        Machine::run_before(self, t);
    }

    fn run_until(&mut self, t: SimTime) {
        Machine::run_until(self, t);
    }
}
