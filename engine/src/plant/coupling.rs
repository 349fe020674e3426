//! One plant step on a machine, as every coupling does it (issue #52):
//! [`super::Planted`] (headless runs, `hashigo test`, the page's grading)
//! and the page's rig (the live plant, manual mode) both call
//! [`Coupling::step`], so the two cannot drift apart. The step drives the
//! plant's actuators from the machine's outputs as it last wrote them
//! (or by hand), after faults; moves the plant one [`super::STEP`]; and
//! writes its sensors, after faults, to the machine's inputs, only those
//! that changed (recorded machines keep each as a command).

use super::fault::{self, Fault};
use super::wiring::{self, Wire};
use super::{AnyPlant, Direction, Kind, Plant};
use crate::events::InputValue;
use crate::plc::{Command, Plc};
use crate::time::SimTime;

/// A plant and its wiring to a machine, borrowed from the coupling that
/// keeps them (the machine is passed to each call).
pub struct Coupling<'a> {
    /// The plant.
    pub plant: &'a mut AnyPlant,
    /// Its signals' devices.
    pub wires: &'a [Wire],
    /// Its faults.
    pub faults: &'a [Fault],
    /// Per signal: what the PLC reads (`in`), what acts on the plant (`out`).
    pub values: &'a mut [i64],
    /// Per signal: the input value last written to the machine.
    pub written: &'a mut [Option<InputValue>],
}

impl Coupling<'_> {
    /// One plant step ending at `at` (the plant's clock then: `now_ms`),
    /// driven by `machine`'s outputs, or by `hand` (per signal, on or
    /// off; an analog actuator by hand is full on or off); its sensors
    /// written after. The alarms that begin are pushed to `raised`.
    pub fn step<P: Plc + ?Sized>(
        &mut self,
        machine: &mut P,
        at: SimTime,
        now_ms: i64,
        hand: Option<&[bool]>,
        raised: &mut Vec<String>,
    ) {
        let info = self.plant.info();
        for (s, signal) in info.signals.iter().enumerate() {
            if signal.direction != Direction::Out {
                continue;
            }
            let driven = match hand {
                Some(hand) => match (hand.get(s).copied().unwrap_or(false), signal.kind) {
                    (false, _) => 0,
                    (true, Kind::Analog) => super::ANALOG_FULL,
                    (true, _) => 1,
                },
                None => self
                    .wires
                    .iter()
                    .find(|w| w.signal == s)
                    .map_or(0, |w| i64::from(machine.read(w.device).is_on())),
            };
            self.values[s] = fault::apply(fault::acting(self.faults, s, at), driven);
        }
        self.plant.step(now_ms, self.values, raised);
        self.sense(machine, at);
    }

    /// Reads the plant's sensors at `at` (after faults) and writes those
    /// that changed to `machine`'s inputs.
    pub fn sense<P: Plc + ?Sized>(&mut self, machine: &mut P, at: SimTime) {
        let info = self.plant.info();
        for (s, signal) in info.signals.iter().enumerate() {
            if signal.direction != Direction::In {
                continue;
            }
            let value = fault::apply(fault::acting(self.faults, s, at), self.plant.sensor(s));
            self.values[s] = value;
            let Some(w) = self.wires.iter().find(|w| w.signal == s) else {
                continue;
            };
            let input = match w.scale {
                Some(scale) => wiring::scaled(scale, value),
                None => InputValue::Int(value),
            };
            // Checked when wired: the input takes it (kept unwritten if
            // not, so the next step tries again).
            if self.written[s] != Some(input)
                && machine.apply(Command::SetInput(w.device, input)).is_ok()
            {
                self.written[s] = Some(input);
            }
        }
    }
}
