//! [`Planted`] as a [`Plc`]: the machine's interface, with the plant
//! stepped on its clock and the plant's names as devices.

use super::{Plant, Planted};
use crate::events::InputValue;
use crate::plc::{
    Command, Device, Front, Plc, PlcError, ScanTrace, SettingInfo, Terminals, TraceHistory, Value,
    Warning,
};
use crate::time::SimTime;
use crate::MachineId;

impl<M: Plc> Plc for Planted<M> {
    fn id(&self) -> MachineId {
        self.machine.id()
    }

    fn load_text(&mut self, text: &str) -> Result<(), PlcError> {
        self.machine.load_text(text)
    }

    fn listing(&self) -> String {
        self.machine.listing()
    }

    fn apply(&mut self, command: Command) -> Result<(), PlcError> {
        match command {
            Command::SetInput(device, _) | Command::ReleaseInput(device) => {
                self.check_free(device)?;
                self.machine.apply(command)
            }
            Command::Setting {
                ref name,
                ref value,
            } => {
                let prefix = self.plant.info().name;
                match name
                    .trim()
                    .strip_prefix(prefix)
                    .and_then(|k| k.strip_prefix('.'))
                {
                    Some(key) => self.set_param(key.trim(), value),
                    None => self.machine.apply(command),
                }
            }
            Command::PowerCycle => {
                self.machine.apply(Command::PowerCycle)?;
                self.reset_plant();
                Ok(())
            }
            other => self.machine.apply(other),
        }
    }

    fn device(&self, name: &str) -> Result<Device, PlcError> {
        let prefix = self.plant.info().name;
        match name.strip_prefix(prefix).and_then(|k| k.strip_prefix('.')) {
            Some(rest) => self.plant_device(rest),
            None => self.machine.device(name),
        }
    }

    fn check_input(&self, device: Device, value: InputValue) -> Result<(), PlcError> {
        self.check_free(device)?;
        self.machine.check_input(device, value)
    }

    fn read(&self, device: Device) -> Value {
        match self.plant_index(device) {
            Some(i) => self.plant_value(i),
            None => self.machine.read(device),
        }
    }

    fn now(&self) -> SimTime {
        self.machine.now()
    }

    fn scans(&self) -> u64 {
        self.machine.scans()
    }

    fn run_until(&mut self, t: SimTime) {
        self.advance(t, false);
    }

    fn run_before(&mut self, t: SimTime) {
        self.advance(t, true);
    }

    fn step_scan(&mut self) {
        // To the scan's end through the plant's steps where the machine
        // can tell when that is; else the machine's own step.
        let before = self.machine.scans();
        for _ in 0..1_000_000 {
            match self.machine.next_scan_end() {
                Some(end) => self.run_until(end),
                None => break,
            }
            if self.machine.scans() != before {
                return;
            }
        }
        self.machine.step_scan();
        self.catch_up();
    }

    fn next_scan_end(&self) -> Option<SimTime> {
        self.machine.next_scan_end()
    }

    fn nth_scan_end(&self, n: u64) -> Option<SimTime> {
        self.machine.nth_scan_end(n)
    }

    fn step_instruction(&mut self) -> Option<usize> {
        let step = self.machine.step_instruction();
        self.catch_up();
        step
    }

    fn step_clock(&mut self) -> bool {
        let stepped = self.machine.step_clock();
        self.catch_up();
        stepped
    }

    fn set_tracing(&mut self, on: bool) {
        self.machine.set_tracing(on);
    }

    fn trace(&self) -> Option<&ScanTrace> {
        self.machine.trace()
    }

    fn take_trace_history(&mut self) -> TraceHistory {
        self.machine.take_trace_history()
    }

    /// The machine's image, then the plant's devices (8 bytes each, little
    /// endian) at its end, so every recorded scan holds the plant's state.
    fn image_into(&self, image: &mut Vec<u8>) {
        self.machine.image_into(image);
        for i in 0..self.plant_devices() {
            image.extend_from_slice(&self.plant_value(i).as_i64().to_le_bytes());
        }
    }

    fn read_image(&self, image: &[u8], device: Device) -> Option<Value> {
        let n = self.plant_devices();
        let machine_part = image.len().checked_sub(8 * n)?;
        let Some(i) = self.plant_index(device) else {
            return self.machine.read_image(&image[..machine_part], device);
        };
        let at = machine_part + 8 * i;
        let value = i64::from_le_bytes(crate::plc::image_bytes(image, at)?);
        let info = self.plant.info();
        Some(match info.signals.get(i) {
            Some(s) if s.kind == super::Kind::Bit => Value::Bit(value != 0),
            _ => Value::Int(value),
        })
    }

    fn running(&self) -> bool {
        self.machine.running()
    }

    fn front_into(&self, front: &mut Front) {
        self.machine.front_into(front);
    }

    fn warnings(&self) -> Vec<Warning> {
        self.machine.warnings()
    }

    fn settings(&self) -> &'static [SettingInfo] {
        self.machine.settings()
    }

    fn terminals(&self) -> Terminals {
        self.machine.terminals()
    }

    fn time_for_steps(&self, steps: u64) -> Option<(SimTime, u64)> {
        self.machine.time_for_steps(steps)
    }

    fn serial_open(&mut self) -> Result<String, PlcError> {
        self.machine.serial_open()
    }

    fn serial_sent(&self, seen: u64, out: &mut String) -> u64 {
        self.machine.serial_sent(seen, out)
    }

    fn serial(&mut self, line: &str) -> Result<String, PlcError> {
        self.machine.serial(line)
    }
}
