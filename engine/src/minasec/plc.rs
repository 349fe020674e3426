//! MINASEC-U behind the [`Plc`] interface: settings by name, devices by
//! handle, the panel's commands.

use super::control::{ClockSpeed, Command, Mode, TimerId};
use super::isa::Address;
use super::machine::Machine;
use super::Program;
use crate::events::InputValue;
use crate::plc::SettingInfo;
use crate::plc::{self, Device, DeviceError, Drives, Plc, PlcError, SettingError, Value};
use crate::time::SimTime;
use crate::MachineId;

/// The settings `--set` and projects give MINASEC-U.
const SETTINGS: &[SettingInfo] = &[
    SettingInfo {
        name: "T0",
        range: "0.1s..1.1s (RV1)",
        default: "0.1s",
    },
    SettingInfo {
        name: "T1",
        range: "1s..11s (RV2)",
        default: "1s",
    },
    SettingInfo {
        name: "C0",
        range: "0..99 (the rotary switches)",
        default: "0",
    },
    SettingInfo {
        name: "clock",
        range: "fast, slow or a frequency in Hz",
        default: "fast",
    },
];

// Device handles: an address read as a bit, the count, a timer's value,
// the CNTCLR button.
const COUNT: u32 = 0x100;
const TIMER_VALUE: u32 = 0x200;
const COUNT_CLEAR_BUTTON: u32 = 0x300;

impl Machine {
    /// A machine as `hashigo run` starts it: powered, switch at RUN, FAST.
    pub fn for_run() -> Machine {
        let mut m = Machine::new();
        // SetMode cannot fail; the result is only for value-carrying commands.
        let _ = m.apply(Command::SetMode(Mode::Run));
        m
    }

    /// Applies one `--set NAME=VALUE`: `T0=<delay>`, `T1=<delay>`,
    /// `C0=<0..99>`, `clock=fast|slow|<Hz>`. Nothing changes on error.
    pub fn apply_setting(&mut self, name: &str, value: &str) -> Result<(), SettingError> {
        let command = match name.to_ascii_uppercase().as_str() {
            "T0" | "T00" | "T1" | "T01" => {
                let id = if name.ends_with('0') {
                    TimerId::T0
                } else {
                    TimerId::T1
                };
                Command::SetDelay(id, SimTime::parse(value)?)
            }
            "C0" | "C00" => {
                let preset: u32 = value
                    .trim()
                    .parse()
                    .map_err(|_| SettingError::CounterPreset(value.to_string()))?;
                if preset > 99 {
                    return Err(SettingError::own(super::SettingError::PresetOutOfRange(
                        preset,
                    )));
                }
                Command::SetCounterPreset((preset / 10) as u8, (preset % 10) as u8)
            }
            "CLOCK" => Command::SetClock(ClockSpeed::parse(value).map_err(SettingError::own)?),
            _ => {
                return Err(SettingError::Unknown {
                    machine: MachineId::MinasecU,
                    name: name.to_string(),
                    takes: "T0, T1, C0 and clock",
                })
            }
        };
        self.apply(command).map_err(SettingError::own)
    }
}

/// MINASEC-U as a [`Plc`]: the board, switch at RUN, and the program last
/// loaded (for its programming sheet).
#[derive(Clone, Debug)]
pub struct MinasecPlc {
    machine: Machine,
    program: Program,
}

impl Default for MinasecPlc {
    fn default() -> Self {
        MinasecPlc::new()
    }
}

impl MinasecPlc {
    /// A board with erased memory, powered, switch at RUN, FAST clock.
    pub fn new() -> MinasecPlc {
        MinasecPlc {
            machine: Machine::for_run(),
            program: Program::erased(),
        }
    }

    /// `machine` (as it is: switch, knobs, memory) as a [`Plc`].
    pub fn with(machine: Machine) -> MinasecPlc {
        MinasecPlc {
            machine,
            program: Program::erased(),
        }
    }

    /// The board.
    pub fn machine(&self) -> &Machine {
        &self.machine
    }

    /// The board, to operate it directly.
    pub fn machine_mut(&mut self) -> &mut Machine {
        &mut self.machine
    }

    fn input(&self, device: Device) -> Result<u32, PlcError> {
        match device.0 {
            a @ 0..=7 => Ok(a),
            COUNT_CLEAR_BUTTON => Ok(COUNT_CLEAR_BUTTON),
            other => Err(DeviceError::NotAnInput {
                device: self.name(other),
                drives: Drives::TerminalsAndButton("X00-X07", "CNTCLR"),
            }
            .into()),
        }
    }

    fn name(&self, handle: u32) -> String {
        match handle {
            COUNT => "C0.v".into(),
            COUNT_CLEAR_BUTTON => "CNTCLR".into(),
            h if h & !1 == TIMER_VALUE => format!("T{}.v", h & 1),
            a => Address::new(a as u8).map_or_else(String::new, |a| a.to_string()),
        }
    }
}

impl Plc for MinasecPlc {
    fn id(&self) -> MachineId {
        MachineId::MinasecU
    }

    fn load_text(&mut self, text: &str) -> Result<(), PlcError> {
        let program =
            Program::parse(text).map_err(|errors| PlcError::Program(plc::problems(errors)))?;
        self.machine.load(&program);
        self.program = program;
        Ok(())
    }

    fn listing(&self) -> String {
        self.program.sheet().to_string()
    }

    fn apply(&mut self, command: plc::Command) -> Result<(), PlcError> {
        match command {
            plc::Command::SetInput(device, value) => {
                self.check_input(device, value)?;
                let on = value == InputValue::Int(1);
                let command = match self.input(device)? {
                    COUNT_CLEAR_BUTTON => Command::CountClearButton(on),
                    n => Command::SetInput(n as u8, on),
                };
                self.machine.apply(command).map_err(PlcError::own)
            }
            plc::Command::ReleaseInput(device) => {
                self.apply(plc::Command::SetInput(device, InputValue::Int(0)))
            }
            plc::Command::Setting { name, value } => {
                Ok(self.machine.apply_setting(name.trim(), value.trim())?)
            }
            plc::Command::PowerCycle => {
                let mode = self.machine.mode();
                self.machine
                    .apply(Command::Power(false))
                    .map_err(PlcError::own)?;
                self.machine
                    .apply(Command::Power(true))
                    .map_err(PlcError::own)?;
                self.machine
                    .apply(Command::SetMode(mode))
                    .map_err(PlcError::own)
            }
            plc::Command::Run(on) => {
                let mode = if on { Mode::Run } else { Mode::Halt };
                self.machine
                    .apply(Command::SetMode(mode))
                    .map_err(PlcError::own)
            }
            plc::Command::Own(own) => match own.get::<Command>() {
                Some(&c) => self.machine.apply(c).map_err(PlcError::own),
                None => Err(PlcError::NotItsOwn {
                    machine: MachineId::MinasecU,
                    command: own,
                }),
            },
        }
    }

    fn device(&self, name: &str) -> Result<Device, PlcError> {
        let upper = name.to_ascii_uppercase();
        let handle = match upper.as_str() {
            "C0.V" | "C00.V" => COUNT,
            "T0.V" | "T00.V" => TIMER_VALUE,
            "T1.V" | "T01.V" => TIMER_VALUE | 1,
            "CNTCLR" => COUNT_CLEAR_BUTTON,
            _ => u32::from(Address::parse(name).map_err(DeviceError::own)?.index()),
        };
        Ok(Device(handle))
    }

    fn check_input(&self, device: Device, value: InputValue) -> Result<(), PlcError> {
        self.input(device)?;
        match value {
            InputValue::Int(0 | 1) => Ok(()),
            _ => Err(DeviceError::BitValue(self.name(device.0)).into()),
        }
    }

    fn read(&self, device: Device) -> Value {
        let scan = self.machine.last_scan();
        match device.0 {
            COUNT => Value::Int(i64::from(scan.count)),
            COUNT_CLEAR_BUTTON => Value::Bit(self.machine.counter().clear_button()),
            h if h & !1 == TIMER_VALUE => {
                Value::Int((scan.timer_elapsed[(h & 1) as usize].as_nanos() / 1_000_000) as i64)
            }
            a => Value::Bit(scan.bus >> a & 1 != 0),
        }
    }

    fn read_image(&self, image: &[u8], device: Device) -> Option<Value> {
        let byte = |at: usize| image.get(at).copied();
        match device.0 {
            COUNT => byte(4).map(|c| Value::Int(i64::from(c))),
            COUNT_CLEAR_BUTTON => None,
            h if h & !1 == TIMER_VALUE => {
                let at = 5 + 4 * (h & 1) as usize;
                plc::image_bytes(image, at).map(|b| Value::Int(i64::from(u32::from_le_bytes(b))))
            }
            a => {
                plc::image_bytes(image, 0).map(|b| Value::Bit(u32::from_le_bytes(b) >> a & 1 != 0))
            }
        }
    }

    fn next_scan_end(&self) -> Option<SimTime> {
        self.machine.next_scan_end()
    }

    /// Every scan after the one under way is 256 whole clocks.
    fn nth_scan_end(&self, n: u64) -> Option<SimTime> {
        let first = self.machine.next_scan_end()?;
        let rest = n
            .checked_sub(1)?
            .checked_mul(self.machine.scan_period().as_nanos())?;
        first.checked_add(SimTime::from_nanos(rest))
    }

    plc::forward_time!(machine);

    fn scans(&self) -> u64 {
        self.machine.scans()
    }

    fn step_instruction(&mut self) -> Option<usize> {
        self.machine.step_instruction().map(usize::from)
    }

    fn step_clock(&mut self) -> bool {
        self.machine.step_clock()
    }

    // Address `n` is step `n`; the scan ends at the wrap to address 0.
    plc::forward_tracing!(machine.tracer);

    /// The bus word the last scan left (4 bytes, little-endian: bit `a` =
    /// address `a`), the count, and each timer's value in ms (4 bytes each).
    fn image_into(&self, image: &mut Vec<u8>) {
        let scan = self.machine.last_scan();
        image.clear();
        image.extend_from_slice(&scan.bus.to_le_bytes());
        image.push(scan.count);
        for t in scan.timer_elapsed {
            let ms = u32::try_from(t.as_nanos() / 1_000_000).unwrap_or(u32::MAX);
            image.extend_from_slice(&ms.to_le_bytes());
        }
    }

    fn running(&self) -> bool {
        self.machine.powered() && self.machine.mode() == Mode::Run
    }

    /// The front panel, copied in place.
    fn front_into(&self, front: &mut plc::Front) {
        front.fill(|panel: &mut super::Panel| self.machine.panel_into(panel));
    }

    fn settings(&self) -> &'static [SettingInfo] {
        SETTINGS
    }

    /// Plants wire to the eight switches and lamps (no analog input).
    fn terminals(&self) -> crate::plc::Terminals {
        use crate::plc::Terminals;
        Terminals {
            inputs: Terminals::numbered(8, |i| format!("X{i:02}")),
            outputs: Terminals::numbered(8, |i| format!("Y{i:02}")),
            ..Terminals::default()
        }
    }

    /// One step is one clock: `steps` periods of the clock.
    fn time_for_steps(&self, steps: u64) -> Option<(SimTime, u64)> {
        let t = steps.checked_mul(self.machine.speed().period().as_nanos())?;
        Some((SimTime::from_nanos(t), steps))
    }
}
