//! MINASEC-U under the headless runner: `--set` settings, input events and
//! watched devices.

use super::control::{ClockSpeed, Command, Mode, TimerId};
use super::isa::Address;
use super::machine::Machine;
use crate::events::InputValue;
use crate::headless::Simulation;
use crate::time::SimTime;

/// A device `hashigo run --watch` can print for MINASEC-U.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Watch {
    /// Any address read as a bit (`X00`, `Y01`, `M10`, `T0`, `C0`, `C0R`).
    Bit(Address),
    /// `C0.v`: the count, 0..=99.
    Count,
    /// `T0.v` / `T1.v`: how long the coil has been on, in ms, capped at
    /// the delay.
    TimerValue(TimerId),
}

/// An input a timeline can drive.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Input {
    Terminal(u8),
    CountClearButton,
}

fn parse_input(device: &str) -> Result<Input, String> {
    if device.eq_ignore_ascii_case("CNTCLR") {
        return Ok(Input::CountClearButton);
    }
    let address = Address::parse(device).map_err(|e| e.to_string())?;
    match address.device() {
        super::isa::Device::Input(n) => Ok(Input::Terminal(n)),
        _ => Err(format!(
            "{address} is not an input: events drive X00-X07 and the CNTCLR button"
        )),
    }
}

impl Machine {
    /// A machine as `hashigo run` starts it: powered, switch at RUN, FAST.
    pub fn for_run() -> Machine {
        let mut m = Machine::new();
        m.apply_run_mode();
        m
    }

    fn apply_run_mode(&mut self) {
        // SetMode cannot fail; the result is only for value-carrying commands.
        let _ = self.apply(Command::SetMode(Mode::Run));
    }

    /// Applies one `--set NAME=VALUE`: `T0=<delay>`, `T1=<delay>`,
    /// `C0=<0..99>`, `clock=fast|slow|<Hz>`. Nothing changes on error.
    pub fn apply_setting(&mut self, name: &str, value: &str) -> Result<(), String> {
        let command = match name.to_ascii_uppercase().as_str() {
            "T0" | "T00" | "T1" | "T01" => {
                let id = if name.ends_with('0') {
                    TimerId::T0
                } else {
                    TimerId::T1
                };
                let delay = SimTime::parse(value).map_err(|e| e.to_string())?;
                Command::SetDelay(id, delay)
            }
            "C0" | "C00" => {
                let preset: u32 = value
                    .trim()
                    .parse()
                    .map_err(|_| format!("C0={value}: the counter set value is a number 0..99"))?;
                if preset > 99 {
                    return Err(super::SettingError::PresetOutOfRange(preset).to_string());
                }
                Command::SetCounterPreset((preset / 10) as u8, (preset % 10) as u8)
            }
            "CLOCK" => Command::SetClock(ClockSpeed::parse(value).map_err(|e| e.to_string())?),
            _ => {
                return Err(format!(
                    "unknown setting {}: minasec-u takes T0, T1, C0 and clock",
                    crate::error::shown(name)
                ))
            }
        };
        self.apply(command).map_err(|e| e.to_string())
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
            "C0.V" | "C00.V" => return Ok(Watch::Count),
            "T0.V" | "T00.V" => return Ok(Watch::TimerValue(TimerId::T0)),
            "T1.V" | "T01.V" => return Ok(Watch::TimerValue(TimerId::T1)),
            _ => {}
        }
        Address::parse(name)
            .map(Watch::Bit)
            .map_err(|e| e.to_string())
    }

    fn value(&self, watch: Watch) -> i64 {
        let scan = self.last_scan();
        match watch {
            Watch::Bit(address) => i64::from(scan.bit(address)),
            Watch::Count => i64::from(scan.count),
            Watch::TimerValue(id) => (scan.timer_elapsed[id.index()].as_nanos() / 1_000_000) as i64,
        }
    }

    fn check_input(&self, device: &str, value: InputValue) -> Result<(), String> {
        parse_input(device)?;
        match value {
            InputValue::Int(0 | 1) => Ok(()),
            _ => Err(format!("{device} is a bit: its value is 0 or 1")),
        }
    }

    fn apply_input(&mut self, device: &str, value: InputValue) {
        let on = value == InputValue::Int(1);
        // check_input accepted the device; an unknown one is ignored here.
        let command = match parse_input(device) {
            Ok(Input::Terminal(n)) => Command::SetInput(n, on),
            Ok(Input::CountClearButton) => Command::CountClearButton(on),
            Err(_) => return,
        };
        let _ = self.apply(command);
    }

    fn run_before(&mut self, t: SimTime) {
        Machine::run_before(self, t);
    }

    fn run_until(&mut self, t: SimTime) {
        Machine::run_until(self, t);
    }
}
