//! The Arduino PLC under the headless runner.

use super::isa::parse_io;
use super::machine::{Chip, Machine, PopOrder};
use crate::events::InputValue;
use crate::headless::Simulation;
use crate::time::SimTime;

impl Machine {
    /// Applies one `--set NAME=VALUE`: `step=<time>`, `quirk=sketch`
    /// (or `none`), `chip=168|328`.
    pub fn apply_setting(&mut self, name: &str, value: &str) -> Result<(), String> {
        match name.to_ascii_lowercase().as_str() {
            "step" => self.set_step_time(SimTime::parse(value).map_err(|e| e.to_string())?),
            "quirk" => match value.to_ascii_lowercase().as_str() {
                "sketch" => {
                    self.set_pop_order(PopOrder::Sketch);
                    Ok(())
                }
                "none" => {
                    self.set_pop_order(PopOrder::Intended);
                    Ok(())
                }
                _ => Err(format!(
                    "unknown quirk {}: sketch or none",
                    crate::error::shown(value)
                )),
            },
            "chip" => {
                let chip = match value {
                    "168" | "atmega168" => Chip::Atmega168,
                    "328" | "atmega328" => Chip::Atmega328,
                    _ => {
                        return Err(format!(
                            "unknown chip {}: 168 or 328",
                            crate::error::shown(value)
                        ))
                    }
                };
                self.set_chip(chip)
            }
            _ => Err(format!(
                "unknown setting {}: arduino-plc takes step, quirk, chip",
                crate::error::shown(name)
            )),
        }
    }
}

/// A pin the runner can watch: an input or an output.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Watch(u8);

fn input_number(device: &str) -> Result<u8, String> {
    match parse_io(device) {
        Some(n @ 0..=5) => Ok(n),
        Some(_) => Err(format!("{device} is an output: events drive X000-X005")),
        None => Err(format!(
            "unknown device {}: the Arduino PLC has X000-X005, Y000-Y005",
            crate::error::shown(device)
        )),
    }
}

impl Simulation for Machine {
    type Watch = Watch;

    fn setting(&mut self, name: &str, value: &str) -> Result<(), String> {
        Machine::apply_setting(self, name, value)
    }

    fn watch(&self, name: &str) -> Result<Watch, String> {
        parse_io(name).map(Watch).ok_or_else(|| {
            format!(
                "unknown device {}: the Arduino PLC has X000-X005, Y000-Y005",
                crate::error::shown(name)
            )
        })
    }

    /// The pins now: the sketch has no scan, every step drives its pin.
    fn value(&self, watch: Watch) -> i64 {
        let Watch(n) = watch;
        let pins = if n >= 8 {
            self.outputs() >> (n - 8)
        } else {
            self.inputs() >> n
        };
        i64::from(pins & 1)
    }

    fn check_input(&self, device: &str, value: InputValue) -> Result<(), String> {
        input_number(device)?;
        match value {
            InputValue::Int(0 | 1) => Ok(()),
            _ => Err(format!("{device} is a bit: its value is 0 or 1")),
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
