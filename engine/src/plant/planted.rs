//! A machine with a plant attached: itself a [`Plc`], so headless runs,
//! test cases, Why? and recording drive it as any machine, and the plant
//! is hooked in once, here. Every [`STEP`] on the simulated clock the
//! machine runs to the step's end, the plant moves one step driven by the
//! outputs the machine last wrote, and its sensors are written to the
//! machine's inputs, which the machine samples when its scan samples them.
//! Plant names (`conveyor.delivered`) are devices of this machine.

use super::fault::Fault;
use super::wiring::{self, Wire, WireEntry};
use super::{Alarm, AnyPlant, Coupling, Direction, Kind, Plant, ALARMS, ANALOG_FULL, STEP};
use crate::error::{shown, Located};
use crate::events::InputValue;
use crate::plc::{Device, DeviceError, Plc, PlcError, SettingError, Value};
use crate::time::SimTime;

/// Plant devices: `PLANT_BASE` + index (signals, quantities, `alarms`).
const PLANT_BASE: u32 = 0xFFFF_0000;

/// The alarms kept for printing (all are counted).
pub const MAX_ALARM_LOG: usize = 10_000;

/// A request the plant refuses.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PlantedError {
    /// An input event on a device the plant drives.
    Driven {
        /// The device.
        device: String,
        /// The plant signal on it (`conveyor.infeed`).
        signal: String,
    },
    /// An input event on a plant name.
    PlantName(String),
    /// A name after `PLANT.` the plant does not have.
    Unknown {
        /// The plant.
        plant: &'static str,
        /// The name as written.
        name: String,
    },
    /// A parameter refused.
    Param(super::PlantError),
}

impl std::fmt::Display for PlantedError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            PlantedError::Driven { device, signal } => write!(
                f,
                "{device} is driven by the plant's signal {signal}: an input event cannot drive it"
            ),
            PlantedError::PlantName(name) => {
                write!(f, "{name} is the plant's, not an input an event can drive")
            }
            PlantedError::Unknown { plant, name } => write!(
                f,
                "the plant {plant} has no signal or quantity {} (hashigo plants lists them)",
                shown(name)
            ),
            PlantedError::Param(e) => e.fmt(f),
        }
    }
}

/// A machine `M` with a plant wired to it.
#[derive(Clone, Debug)]
pub struct Planted<M> {
    machine: M,
    plant: AnyPlant,
    wires: Vec<Wire>,
    faults: Vec<Fault>,
    /// The plant's start (power-on, or the last power cycle).
    origin: SimTime,
    /// The end of the next plant step.
    next_step: SimTime,
    /// Per signal: what the PLC reads (`in`), what acts on the plant (`out`).
    values: Vec<i64>,
    /// Per signal: the input value last written to the machine.
    written: Vec<Option<InputValue>>,
    alarms: i64,
    log: Vec<Alarm>,
    /// Scratch for one step's new alarms.
    raised: Vec<String>,
}

impl<M: Plc> Planted<M> {
    /// Attaches `plant` to `machine` (powered on, program loaded) with
    /// `wiring` (`None`: the default for the machine) and `faults`.
    /// Errors are located at the wiring's lines (line 0: the default).
    pub fn new(
        machine: M,
        plant: AnyPlant,
        wiring: Option<&[WireEntry]>,
        faults: Vec<Fault>,
    ) -> Result<Planted<M>, Vec<Located<String>>> {
        let info = plant.info();
        let entries = match wiring {
            Some(w) => w.to_vec(),
            // A default terminal the program does not have (the soft
            // PLC knows only the addresses its program uses) is left
            // unconnected.
            None => {
                let mut entries = wiring::default_wiring(info, &machine).0;
                entries.retain(|e| machine.device(&e.device).is_ok());
                entries
            }
        };
        let wires = wiring::check(info, &machine, &entries).map_err(|errors| {
            let said = |e: Located<wiring::WireError>| Located::new(e.line, e.error.to_string());
            errors.into_iter().map(said).collect::<Vec<_>>()
        })?;
        let n = info.signals.len();
        let now = machine.now();
        let mut planted = Planted {
            machine,
            plant,
            wires,
            faults,
            origin: now,
            next_step: now.saturating_add(STEP),
            values: vec![0; n],
            written: vec![None; n],
            alarms: 0,
            log: Vec::new(),
            raised: Vec::new(),
        };
        planted.sense(now);
        Ok(planted)
    }

    /// The machine.
    pub fn machine(&self) -> &M {
        &self.machine
    }

    /// The plant.
    pub fn plant(&self) -> &AnyPlant {
        &self.plant
    }

    /// The wiring in use.
    pub fn wires(&self) -> &[Wire] {
        &self.wires
    }

    /// The alarms raised so far, oldest first (at most [`MAX_ALARM_LOG`]).
    pub fn alarm_log(&self) -> &[Alarm] {
        &self.log
    }

    /// The plant signal wired to `device` (`conveyor.infeed`), if any.
    pub fn signal_on(&self, device: Device) -> Option<String> {
        let w = self.wires.iter().find(|w| w.device == device)?;
        let info = self.plant.info();
        Some(format!("{}.{}", info.name, info.signals[w.signal].name))
    }

    /// Runs the plant steps due by `t` (`before`: strictly before), each
    /// with the machine run to its end first, then the machine to `t`.
    fn advance(&mut self, t: SimTime, before: bool) {
        while if before {
            self.next_step < t
        } else {
            self.next_step <= t
        } {
            let at = self.next_step;
            self.machine.run_until(at);
            self.step_plant(at);
            self.next_step = at.saturating_add(STEP);
        }
        if before {
            self.machine.run_before(t);
        } else {
            self.machine.run_until(t);
        }
    }

    /// The plant steps due by the machine's time, after the machine
    /// moved by itself (a single instruction or clock edge).
    fn catch_up(&mut self) {
        while self.next_step <= self.machine.now() {
            let at = self.next_step;
            self.step_plant(at);
            self.next_step = at.saturating_add(STEP);
        }
    }

    /// The plant's coupling (the engine's one step, [`Coupling`]) and
    /// the machine it drives.
    fn coupling(&mut self) -> (Coupling<'_>, &mut M) {
        let coupling = Coupling {
            plant: &mut self.plant,
            wires: &self.wires,
            faults: &self.faults,
            values: &mut self.values,
            written: &mut self.written,
        };
        (coupling, &mut self.machine)
    }

    /// One plant step ending at `at`: driven by the outputs as the
    /// machine left them, then its sensors written.
    fn step_plant(&mut self, at: SimTime) {
        let now_ms = ((at.as_nanos() - self.origin.as_nanos()) / 1_000_000) as i64;
        let mut raised = std::mem::take(&mut self.raised);
        let (mut coupling, machine) = self.coupling();
        coupling.step(machine, at, now_ms, None, &mut raised);
        for message in raised.drain(..) {
            self.alarms += 1;
            if self.log.len() < MAX_ALARM_LOG {
                self.log.push(Alarm { at, message });
            }
        }
        self.raised = raised;
    }

    /// Reads the plant's sensors at `at` (after faults) and writes those
    /// that changed to the machine's inputs.
    fn sense(&mut self, at: SimTime) {
        let (mut coupling, machine) = self.coupling();
        coupling.sense(machine, at);
    }

    /// The plant device `device` names, by index, if it is one.
    fn plant_index(&self, device: Device) -> Option<usize> {
        device.0.checked_sub(PLANT_BASE).map(|i| i as usize)
    }

    /// The number of plant devices: signals, quantities, `alarms`.
    fn plant_devices(&self) -> usize {
        let info = self.plant.info();
        info.signals.len() + info.quantities.len() + 1
    }

    /// The plant device `index`'s value now.
    fn plant_value(&self, index: usize) -> Value {
        let info = self.plant.info();
        let signals = info.signals.len();
        if let Some(s) = info.signals.get(index) {
            return match s.kind {
                Kind::Bit => Value::Bit(self.values[index] != 0),
                Kind::Analog => Value::Int(self.values[index] * 100 / ANALOG_FULL),
            };
        }
        match index - signals {
            q if q < info.quantities.len() => Value::Int(self.plant.quantity(q)),
            _ => Value::Int(self.alarms),
        }
    }

    /// Resolves `rest` in `PLANT.rest`: a quantity (or `alarms`) first,
    /// then a signal (the tank's `level` is its quantity, in percent).
    fn plant_device(&self, rest: &str) -> Result<Device, PlcError> {
        let info = self.plant.info();
        let signals = info.signals.len();
        let index = if rest == ALARMS.name {
            Some(signals + info.quantities.len())
        } else if let Some(q) = info.quantities.iter().position(|q| q.name == rest) {
            Some(signals + q)
        } else {
            info.signal(rest)
        };
        match index {
            Some(i) => Ok(Device(PLANT_BASE + i as u32)),
            None => Err(DeviceError::own(PlantedError::Unknown {
                plant: info.name,
                name: rest.to_string(),
            })
            .into()),
        }
    }

    /// Refuses an input event on a plant name or a plant-driven device.
    fn check_free(&self, device: Device) -> Result<(), PlcError> {
        if let Some(i) = self.plant_index(device) {
            let name = self.plant_name(i);
            return Err(DeviceError::own(PlantedError::PlantName(name)).into());
        }
        let info = self.plant.info();
        let driven = self
            .wires
            .iter()
            .find(|w| w.device == device && info.signals[w.signal].direction == Direction::In);
        match driven {
            Some(w) => Err(DeviceError::own(PlantedError::Driven {
                device: w.name.clone(),
                signal: format!("{}.{}", info.name, info.signals[w.signal].name),
            })
            .into()),
            None => Ok(()),
        }
    }

    /// A plant device's name (`conveyor.delivered`).
    fn plant_name(&self, index: usize) -> String {
        let info = self.plant.info();
        let signals = info.signals.len();
        let short = match info.signals.get(index) {
            Some(s) => s.name,
            None => info
                .quantities
                .get(index - signals)
                .map_or(ALARMS.name, |q| q.name),
        };
        format!("{}.{short}", info.name)
    }

    /// Sets the parameter `key` to `value`; the plant's parameters
    /// together must still make sense, or nothing changes.
    fn set_param(&mut self, key: &str, value: &str) -> Result<(), PlcError> {
        let info = self.plant.info();
        let refuse = |e| PlcError::from(SettingError::own(PlantedError::Param(e)));
        let Some(index) = info.params.iter().position(|p| p.key == key) else {
            let keys: Vec<_> = info.params.iter().map(|p| p.key).collect();
            return Err(refuse(super::PlantError::UnknownParam {
                plant: info.name,
                key: key.to_string(),
                known: keys.join(", "),
            }));
        };
        let v = super::parse_param(&info.params[index], value).map_err(refuse)?;
        let old = self.plant.params()[index];
        self.plant.set_param(index, v);
        if let Err(e) = self.plant.check() {
            self.plant.set_param(index, old);
            return Err(refuse(super::PlantError::Together(e)));
        }
        // The start level (and the schedule's seed) act at once.
        self.sense(self.machine.now());
        Ok(())
    }

    /// The plant back at its start, with the machine's power cycle.
    fn reset_plant(&mut self) {
        let now = self.machine.now();
        self.plant.reset();
        self.alarms = 0;
        self.origin = now;
        self.next_step = now.saturating_add(STEP);
        self.written.iter_mut().for_each(|w| *w = None);
        self.sense(now);
    }
}

#[path = "planted_plc.rs"]
mod plc_impl;

#[cfg(test)]
#[path = "planted_tests.rs"]
mod tests;
