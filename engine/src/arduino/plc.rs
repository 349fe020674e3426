//! The Arduino PLC sketch behind the [`Plc`] interface: `--set` settings,
//! pins by handle, the serial monitor.

use super::isa::{io_name, parse_io, Op, ERASED};
use super::machine::{Chip, Machine, PopOrder};
use super::Program;
use crate::events::InputValue;
use crate::plc::{self, Device, DeviceError, Drives, Plc, PlcError, SettingError, Value};
use crate::plc::{SettingInfo, Warning};
use crate::time::SimTime;
use crate::MachineId;

const SETTINGS: &[SettingInfo] = &[
    SettingInfo {
        name: "step",
        range: "above 0, at most 1s a word",
        default: "10us",
    },
    SettingInfo {
        name: "quirk",
        range: "none, or sketch (the seed's pop order)",
        default: "none",
    },
    SettingInfo {
        name: "chip",
        range: "328 (512 steps) or 168 (256 steps)",
        default: "328",
    },
];

/// What events can drive.
const INPUTS: &str = "X000-X005";

impl Machine {
    /// Applies one `--set NAME=VALUE`: `step=<time>`, `quirk=sketch`
    /// (or `none`), `chip=168|328`.
    pub fn apply_setting(&mut self, name: &str, value: &str) -> Result<(), SettingError> {
        match name.to_ascii_lowercase().as_str() {
            "step" => self.set_step_time(SimTime::parse(value)?),
            "quirk" => {
                let order = match value.to_ascii_lowercase().as_str() {
                    "sketch" => PopOrder::Sketch,
                    "none" => PopOrder::Intended,
                    _ => return Err(choice("quirk", value, "sketch or none")),
                };
                self.set_pop_order(order);
                Ok(())
            }
            "chip" => {
                let chip = match value {
                    "168" | "atmega168" => Chip::Atmega168,
                    "328" | "atmega328" => Chip::Atmega328,
                    _ => return Err(choice("chip", value, "168 or 328")),
                };
                self.set_chip(chip)
            }
            _ => Err(SettingError::Unknown {
                machine: MachineId::ArduinoPlc,
                name: name.to_string(),
                takes: "step, quirk, chip",
            }),
        }
    }
}

fn choice(setting: &'static str, value: &str, choices: &'static str) -> SettingError {
    SettingError::Choice {
        setting,
        value: value.to_string(),
        choices,
    }
}

/// The warnings a program (its EEPROM words) earns: with neither END nor
/// JUMP the PLC runs on through erased EEPROM and spins at its last step.
pub fn warnings(words: &[u16]) -> Vec<Warning> {
    let stops = words
        .iter()
        .any(|&w| w != ERASED && matches!(Op::decode(w), Some(Op::End | Op::Jump)));
    if stops {
        Vec::new()
    } else {
        vec![Warning::RunsIntoErasedEeprom]
    }
}

/// The Arduino PLC as a [`Plc`]: an ATmega328 with the PLC enabled (the
/// sketch waits for `e` after power-up; `hashigo run` and the page start
/// it at once). Inputs and outputs are pins, read as they are now.
#[derive(Clone, Debug)]
pub struct ArduinoPlc {
    machine: Machine,
}

impl Default for ArduinoPlc {
    fn default() -> Self {
        ArduinoPlc::new()
    }
}

impl ArduinoPlc {
    /// An ATmega328 with erased EEPROM and the PLC enabled.
    pub fn new() -> ArduinoPlc {
        let mut machine = Machine::new(&Program::default(), Chip::Atmega328);
        machine.set_enabled(true);
        ArduinoPlc { machine }
    }

    /// The Arduino.
    pub fn machine(&self) -> &Machine {
        &self.machine
    }

    fn pin(name: &str) -> Result<u8, DeviceError> {
        parse_io(name).ok_or_else(|| DeviceError::ArduinoPin(name.to_string()))
    }
}

impl Plc for ArduinoPlc {
    fn id(&self) -> MachineId {
        MachineId::ArduinoPlc
    }

    fn load_text(&mut self, text: &str) -> Result<(), PlcError> {
        let program = Program::parse(text, self.machine.chip().capacity())
            .map_err(|errors| PlcError::Program(plc::problems(errors)))?;
        self.machine.load(&program);
        Ok(())
    }

    fn listing(&self) -> String {
        super::monitor::hex_dump(self.machine.eeprom())
    }

    fn apply(&mut self, command: plc::Command) -> Result<(), PlcError> {
        match command {
            plc::Command::SetInput(device, value) => {
                self.check_input(device, value)?;
                self.machine
                    .set_input(device.0 as u8, value == InputValue::Int(1));
                Ok(())
            }
            plc::Command::ReleaseInput(device) => {
                self.apply(plc::Command::SetInput(device, InputValue::Int(0)))
            }
            plc::Command::Setting { name, value } => {
                Ok(self.machine.apply_setting(name.trim(), value.trim())?)
            }
            plc::Command::PowerCycle => {
                let enabled = self.machine.enabled();
                self.machine.power_cycle();
                self.machine.set_enabled(enabled);
                Ok(())
            }
            plc::Command::Run(on) => {
                self.machine.set_enabled(on);
                Ok(())
            }
            plc::Command::Own(command) => Err(PlcError::NotItsOwn {
                machine: MachineId::ArduinoPlc,
                command,
            }),
        }
    }

    fn device(&self, name: &str) -> Result<Device, PlcError> {
        Ok(Device(u32::from(ArduinoPlc::pin(name)?)))
    }

    fn check_input(&self, device: Device, value: InputValue) -> Result<(), PlcError> {
        let n = device.0 as u8;
        if n > 5 {
            return Err(DeviceError::IsAnOutput {
                device: io_name(n),
                drives: Drives::Terminals(INPUTS),
            }
            .into());
        }
        match value {
            InputValue::Int(0 | 1) => Ok(()),
            _ => Err(DeviceError::BitValue(io_name(n)).into()),
        }
    }

    /// The pins now: the sketch has no scan, every step drives its pin.
    fn read(&self, device: Device) -> Value {
        let n = device.0 as u8;
        let pins = if n >= 8 {
            self.machine.outputs() >> (n - 8)
        } else {
            self.machine.inputs() >> n
        };
        Value::Bit(pins & 1 != 0)
    }

    fn read_image(&self, image: &[u8], device: Device) -> Option<Value> {
        let n = device.0 as u8;
        let pins = if n >= 8 {
            image.get(1)? >> (n - 8)
        } else {
            image.first()? >> n
        };
        Some(Value::Bit(pins & 1 != 0))
    }

    /// A pass ends where the program returns to step 0.
    fn next_scan_end(&self) -> Option<SimTime> {
        self.machine.next_pass_end()
    }

    fn nth_scan_end(&self, n: u64) -> Option<SimTime> {
        self.machine.nth_pass_end(n)
    }

    plc::forward_time!(machine);

    fn scans(&self) -> u64 {
        self.machine.passes()
    }

    fn step_instruction(&mut self) -> Option<usize> {
        self.machine.step_instruction().map(usize::from)
    }

    // Word `n` of the EEPROM is step `n`; a pass back to word 0 ends a scan.
    plc::forward_tracing!(machine.tracer);

    /// The input pins (X000-X005 in bits 0-5), the output port (Y000-Y005
    /// in bits 0-5), the program counter and the bit stack (2 bytes each,
    /// little-endian).
    fn image_into(&self, image: &mut Vec<u8>) {
        image.clear();
        image.push(self.machine.inputs());
        image.push(self.machine.outputs());
        image.extend_from_slice(&self.machine.pc().to_le_bytes());
        image.extend_from_slice(&self.machine.stack().to_le_bytes());
    }

    fn running(&self) -> bool {
        self.machine.enabled()
    }

    fn warnings(&self) -> Vec<Warning> {
        warnings(self.machine.eeprom())
    }

    fn settings(&self) -> &'static [SettingInfo] {
        SETTINGS
    }

    /// Plants wire to the six input and six output pins.
    fn terminals(&self) -> crate::plc::Terminals {
        use crate::plc::Terminals;
        Terminals {
            inputs: Terminals::numbered(6, |i| format!("X{i:03}")),
            outputs: Terminals::numbered(6, |i| format!("Y{i:03}")),
            ..Terminals::default()
        }
    }

    /// One word a step, back to back.
    fn time_for_steps(&self, steps: u64) -> Option<(SimTime, u64)> {
        let t = steps.checked_mul(self.machine.step_time().as_nanos())?;
        Some((SimTime::from_nanos(t), steps))
    }

    /// The sketch prints nothing until it is typed at.
    fn serial_open(&mut self) -> Result<String, PlcError> {
        Ok(String::new())
    }

    fn serial(&mut self, line: &str) -> Result<String, PlcError> {
        Ok(super::monitor::type_line(&mut self.machine, line))
    }
}
