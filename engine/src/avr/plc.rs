//! The AVR simplified PLC behind the [`Plc`] interface: `--set scan=`,
//! bits by name or `R4.2`, timer words by label.

use super::machine::Machine;
use super::program::{BitRef, Instruction, TimerKind};
use super::Program;
use crate::events::InputValue;
use crate::plc::{self, Device, DeviceError, Drives, Plc, PlcError, SettingError, Value};
use crate::plc::{SettingInfo, Warning};
use crate::time::SimTime;
use crate::MachineId;

const SETTINGS: &[SettingInfo] = &[SettingInfo {
    name: "scan",
    range: "whole milliseconds, 1ms..10s",
    default: "10ms",
}];

// Handles: a bit (register × 8 + bit), a timer word's count (0x1000 + index).
const TIMER: u32 = 0x1000;

impl Machine {
    /// Applies one `--set NAME=VALUE`: `scan=<time>`.
    pub fn apply_setting(&mut self, name: &str, value: &str) -> Result<(), SettingError> {
        match name.to_ascii_lowercase().as_str() {
            "scan" => self.set_scan_period(SimTime::parse(value)?),
            _ => Err(SettingError::Unknown {
                machine: MachineId::AvrPlc,
                name: name.to_string(),
                takes: "scan",
            }),
        }
    }
}

/// The warnings a program earns: a TOF is on for its set time after
/// power-up (the seed's warning).
pub fn warnings(program: &Program) -> Vec<Warning> {
    let tof = program.instructions().iter().any(|i| {
        matches!(
            i,
            Instruction::Timer {
                kind: TimerKind::Tof,
                ..
            }
        )
    });
    if tof {
        vec![Warning::TofOnAtPowerUp]
    } else {
        Vec::new()
    }
}

/// The AVR PLC as a [`Plc`].
#[derive(Clone, Debug)]
pub struct AvrPlc {
    machine: Machine,
}

impl Default for AvrPlc {
    fn default() -> Self {
        AvrPlc::new()
    }
}

impl AvrPlc {
    /// An AVR with no program, at a 10 ms scan.
    pub fn new() -> AvrPlc {
        AvrPlc {
            machine: Machine::new(Program::default()),
        }
    }

    /// The AVR.
    pub fn machine(&self) -> &Machine {
        &self.machine
    }

    fn bit(h: u32) -> BitRef {
        BitRef {
            register: (h >> 3) as u8,
            bit: (h & 7) as u8,
        }
    }
}

impl Plc for AvrPlc {
    fn id(&self) -> MachineId {
        MachineId::AvrPlc
    }

    /// Assembles with `Scan` = this machine's scan period in ms.
    fn load_text(&mut self, text: &str) -> Result<(), PlcError> {
        let scan = super::scan_ms(self.machine.scan_period())?;
        let program = Program::parse(text, i64::from(scan))
            .map_err(|errors| PlcError::Program(plc::problems(errors)))?;
        self.machine.load(program);
        Ok(())
    }

    fn listing(&self) -> String {
        self.machine.program().listing()
    }

    fn apply(&mut self, command: plc::Command) -> Result<(), PlcError> {
        match command {
            plc::Command::SetInput(device, value) => {
                self.check_input(device, value)?;
                self.machine
                    .set_input(AvrPlc::bit(device.0), value == InputValue::Int(1));
                Ok(())
            }
            plc::Command::ReleaseInput(device) => {
                self.check_input(device, InputValue::Int(0))?;
                self.machine.release_input(AvrPlc::bit(device.0));
                Ok(())
            }
            plc::Command::Setting { name, value } => {
                Ok(self.machine.apply_setting(name.trim(), value.trim())?)
            }
            plc::Command::PowerCycle => {
                self.machine.power_cycle();
                Ok(())
            }
            plc::Command::Run(_) => Err(PlcError::NotThisMachine {
                machine: MachineId::AvrPlc,
                lacks: "RUN/STOP switch: it runs whenever it is powered",
            }),
            plc::Command::Own(command) => Err(PlcError::NotItsOwn {
                machine: MachineId::AvrPlc,
                command,
            }),
        }
    }

    fn device(&self, name: &str) -> Result<Device, PlcError> {
        if let Some(base) = name.strip_suffix(".v").or_else(|| name.strip_suffix(".V")) {
            let index = self
                .machine
                .program()
                .timer(base)
                .ok_or_else(|| DeviceError::AvrTimer(base.to_string()))?;
            return Ok(Device(TIMER | index as u32));
        }
        let b = self
            .machine
            .program()
            .bit(name)
            .ok_or_else(|| DeviceError::AvrBit(name.to_string()))?;
        Ok(Device(u32::from(b.register) << 3 | u32::from(b.bit)))
    }

    fn check_input(&self, device: Device, value: InputValue) -> Result<(), PlcError> {
        if device.0 >= TIMER {
            // Named as the user writes it (`T1.v`), in every language.
            let index = (device.0 - TIMER) as usize;
            let name = self.machine.program().timer_name(index);
            return Err(DeviceError::NotAnInput {
                device: name.map_or_else(|| format!("T{index}"), |n| format!("{n}.v")),
                drives: Drives::Bits,
            }
            .into());
        }
        match value {
            InputValue::Int(0 | 1) => Ok(()),
            _ => Err(DeviceError::BitValue(AvrPlc::bit(device.0).to_string()).into()),
        }
    }

    fn read(&self, device: Device) -> Value {
        match device.0 {
            h if h >= TIMER => Value::Int(
                self.machine
                    .timer((h - TIMER) as usize)
                    .map_or(0, |t| i64::from(t.count)),
            ),
            h => Value::Bit(self.machine.bit(AvrPlc::bit(h))),
        }
    }

    fn read_image(&self, image: &[u8], device: Device) -> Option<Value> {
        let registers = self.machine.last_scan_registers().len();
        match device.0 {
            h if h >= TIMER => {
                let at = registers + 2 * (h - TIMER) as usize;
                plc::image_bytes(image, at).map(|b| Value::Int(i64::from(u16::from_le_bytes(b))))
            }
            h => {
                let bit = AvrPlc::bit(h);
                let r = image.get(usize::from(bit.register))?;
                Some(Value::Bit(r >> bit.bit & 1 != 0))
            }
        }
    }

    fn next_scan_end(&self) -> Option<SimTime> {
        Some(self.machine.next_scan_end())
    }

    plc::forward_time!(machine);

    plc::forward_scans!(machine);

    // Record `n` is step `n`: a load, and, or reads its bit.
    plc::forward_tracing!(machine.tracer);

    /// R0-R31 as the last scan left them, then each timer word's count
    /// (2 bytes, little-endian).
    fn image_into(&self, image: &mut Vec<u8>) {
        image.clear();
        image.extend_from_slice(self.machine.last_scan_registers());
        for i in 0..self.machine.program().timer_count() {
            let count = self.machine.timer(i).map_or(0, |t| t.count);
            image.extend_from_slice(&count.to_le_bytes());
        }
    }

    fn running(&self) -> bool {
        true
    }

    fn warnings(&self) -> Vec<Warning> {
        warnings(self.machine.program())
    }

    fn settings(&self) -> &'static [SettingInfo] {
        SETTINGS
    }

    /// No fixed terminals: a plant wires to the program's named bits.
    fn terminals(&self) -> crate::plc::Terminals {
        crate::plc::Terminals {
            by_name: true,
            ..crate::plc::Terminals::default()
        }
    }

    /// Whole scans of every record.
    fn time_for_steps(&self, steps: u64) -> Option<(SimTime, u64)> {
        plc::whole_scans(
            steps,
            self.machine.program().instructions().len() as u64,
            self.machine.scan_period(),
        )
    }
}
