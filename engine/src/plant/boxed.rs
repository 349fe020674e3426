//! A boxed machine is a machine: so the command line's `Box<dyn Plc>`
//! can carry a plant ([`super::Planted`]) like any machine type.

use crate::events::InputValue;
use crate::plc::{
    Command, Device, Front, Plc, PlcError, ScanTrace, SettingInfo, Terminals, TraceHistory, Value,
    Warning,
};
use crate::time::SimTime;
use crate::MachineId;

impl<P: Plc + ?Sized> Plc for Box<P> {
    fn id(&self) -> MachineId {
        (**self).id()
    }
    fn load_text(&mut self, text: &str) -> Result<(), PlcError> {
        (**self).load_text(text)
    }
    fn listing(&self) -> String {
        (**self).listing()
    }
    fn apply(&mut self, command: Command) -> Result<(), PlcError> {
        (**self).apply(command)
    }
    fn device(&self, name: &str) -> Result<Device, PlcError> {
        (**self).device(name)
    }
    fn check_input(&self, device: Device, value: InputValue) -> Result<(), PlcError> {
        (**self).check_input(device, value)
    }
    fn read(&self, device: Device) -> Value {
        (**self).read(device)
    }
    fn now(&self) -> SimTime {
        (**self).now()
    }
    fn scans(&self) -> u64 {
        (**self).scans()
    }
    fn run_until(&mut self, t: SimTime) {
        (**self).run_until(t)
    }
    fn run_before(&mut self, t: SimTime) {
        (**self).run_before(t)
    }
    fn tick(&mut self, dt: SimTime) {
        (**self).tick(dt)
    }
    fn step_scan(&mut self) {
        (**self).step_scan()
    }
    fn next_scan_end(&self) -> Option<SimTime> {
        (**self).next_scan_end()
    }
    fn nth_scan_end(&self, n: u64) -> Option<SimTime> {
        (**self).nth_scan_end(n)
    }
    fn step_instruction(&mut self) -> Option<usize> {
        (**self).step_instruction()
    }
    fn step_clock(&mut self) -> bool {
        (**self).step_clock()
    }
    fn set_tracing(&mut self, on: bool) {
        (**self).set_tracing(on)
    }
    fn trace(&self) -> Option<&ScanTrace> {
        (**self).trace()
    }
    fn take_trace_history(&mut self) -> TraceHistory {
        (**self).take_trace_history()
    }
    fn image_into(&self, image: &mut Vec<u8>) {
        (**self).image_into(image)
    }
    fn read_image(&self, image: &[u8], device: Device) -> Option<Value> {
        (**self).read_image(image, device)
    }
    fn running(&self) -> bool {
        (**self).running()
    }
    fn front_into(&self, front: &mut Front) {
        (**self).front_into(front)
    }
    fn warnings(&self) -> Vec<Warning> {
        (**self).warnings()
    }
    fn settings(&self) -> &'static [SettingInfo] {
        (**self).settings()
    }
    fn terminals(&self) -> Terminals {
        (**self).terminals()
    }
    fn time_for_steps(&self, steps: u64) -> Option<(SimTime, u64)> {
        (**self).time_for_steps(steps)
    }
    fn serial_open(&mut self) -> Result<String, PlcError> {
        (**self).serial_open()
    }
    fn serial_sent(&self, seen: u64, out: &mut String) -> u64 {
        (**self).serial_sent(seen, out)
    }
    fn serial(&mut self, line: &str) -> Result<String, PlcError> {
        (**self).serial(line)
    }
}
