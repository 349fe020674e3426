//! The coupling of a plant to the page's machine (part `plants`): the
//! same stepping as the engine's `Planted` (docs/plants.md "How a plant
//! runs"), on the page's recorded machine, which the simulator owns: the
//! machine runs to the end of each 1 ms plant step, the plant moves
//! driven by the outputs as the machine last wrote them, and its sensors
//! that changed are written to the machine's inputs (recorded commands,
//! so time travel replays the machine as it ran).

use engine::error::Located;
use engine::events::InputValue;
use engine::formats::project::PlantSetup;
use engine::plant::wiring::{self, Wire, WireEntry, WireError};
use engine::plant::{fault, AnyPlant, Coupling, Direction, Fault, Kind, Plant, PlantError, STEP};
use engine::plc::{tick_end, Command, Plc};
use engine::SimTime;

use super::history::History;
use super::series::{self, Series};
use super::{Refusal, Refusals, Rig, Shown, SignalShown};

/// The alarms the dock keeps (the latest).
const ALARMS_KEPT: usize = 20;

/// A plant wired to the page's machine.
pub(super) struct PlantRig {
    setup: PlantSetup,
    plant: AnyPlant,
    wires: Vec<Wire>,
    faults: Vec<Fault>,
    /// The plant's start on the machine's clock.
    origin: SimTime,
    /// The milliseconds the plant moved by hand (manual mode): its own
    /// clock is the machine's since `origin` plus these.
    jogged: i64,
    /// Its past, for time travel.
    history: History,
    /// The end of the next plant step.
    next_step: SimTime,
    /// Per signal: what the PLC reads (`in`), what acts on the plant (`out`).
    values: Vec<i64>,
    /// Per signal: the input value last written to the machine.
    written: Vec<Option<InputValue>>,
    /// The latest alarms: the machine's time in ms, the message.
    alarms: Vec<(i64, String)>,
    /// The alarms raised since the start (`PLANT.alarms`).
    alarm_count: i64,
    raised: Vec<String>,
    /// Its signals and quantities over time (the chart, Watch).
    series: Series,
}

/// Couples `setup`'s plant to `machine`, or the refusals, each at its
/// wiring row (1-based; 0: the plant, its parameters or faults).
pub(super) fn build(setup: &PlantSetup, machine: &mut dyn Plc) -> Result<Box<dyn Rig>, Refusals> {
    let one = |e: PlantError| vec![(0, Refusal::Plant(e))];
    let mut plant = AnyPlant::new(&setup.name).ok_or_else(|| {
        one(PlantError::NoPlant {
            name: setup.name.clone(),
            known: AnyPlant::names(),
        })
    })?;
    plant.set_params(&setup.params).map_err(one)?;
    let info = plant.info();
    let faults = setup
        .faults
        .iter()
        .map(|f| Fault::parse(f, info).map_err(one))
        .collect::<Result<Vec<_>, _>>()?;
    let entries: Vec<WireEntry> = match &setup.wiring {
        Some(rows) => rows
            .iter()
            .enumerate()
            .filter(|(_, [signal, device])| !(signal.trim().is_empty() && device.trim().is_empty()))
            .map(|(i, [signal, device])| WireEntry {
                signal: signal.trim().to_string(),
                device: device.trim().to_string(),
                line: i + 1,
            })
            .collect(),
        None => super::wiring::default_entries(info, machine),
    };
    let wires = wiring::check(info, machine, &entries)
        .map_err(|errors| errors.into_iter().map(located).collect::<Vec<_>>())?;
    let n = info.signals.len();
    let now = machine.now();
    let mut rig = PlantRig {
        setup: setup.clone(),
        plant,
        wires,
        faults,
        origin: now,
        jogged: 0,
        history: History::default(),
        next_step: now.saturating_add(STEP),
        values: vec![0; n],
        written: vec![None; n],
        alarms: Vec::new(),
        alarm_count: 0,
        raised: Vec::new(),
        series: Series::default(),
    };
    rig.sense(machine, now);
    rig.note(now);
    rig.history.step(now, 0, &rig.plant, true);
    Ok(Box::new(rig))
}

fn located(e: Located<WireError>) -> (usize, Refusal) {
    (e.line, Refusal::Wire(e.error))
}

impl PlantRig {
    /// One plant step ending at `at`: driven by the outputs as the
    /// machine left them (or by `hand`, in manual mode), then its
    /// sensors written.
    fn step(&mut self, machine: &mut dyn Plc, at: SimTime, hand: Option<&[bool]>) {
        let now_ms = ms(at) - ms(self.origin) + self.jogged;
        // The engine's one step (as `Planted` steps): drive, move, sense.
        let mut raised = std::mem::take(&mut self.raised);
        self.coupling().step(machine, at, now_ms, hand, &mut raised);
        self.raised = raised;
        // What drove it, for time travel (only the actuators' entries
        // count: the sensors' are read from the plant when shown).
        let info = self.plant.info();
        let outputs: Vec<usize> = (info.signals.iter().enumerate())
            .filter(|(_, s)| s.direction == Direction::Out)
            .map(|(i, _)| i)
            .collect();
        self.history.drive(at, &self.values, &outputs);
        for message in self.raised.drain(..) {
            self.alarm_count += 1;
            if self.alarms.len() == ALARMS_KEPT {
                self.alarms.remove(0);
            }
            self.alarms.push((ms(at), message));
        }
        self.note(at);
        self.history.step(at, now_ms, &self.plant, false);
    }

    /// The plant and its wiring as the engine's step takes them.
    fn coupling(&mut self) -> Coupling<'_> {
        Coupling {
            plant: &mut self.plant,
            wires: &self.wires,
            faults: &self.faults,
            values: &mut self.values,
            written: &mut self.written,
        }
    }

    /// Notes the plant's devices as they stand after the step at `at`.
    fn note(&mut self, at: SimTime) {
        let now = series::values_of(&self.plant, &self.values, self.alarm_count);
        self.series.note(at, &now);
    }

    /// Back to the plant as it was at `at` (the machine resumed from a
    /// past scan): what came after is forgotten.
    fn rewind(&mut self, at: SimTime) {
        if let Some((plant, clock, _)) = self.history.at(at) {
            self.plant = plant;
            self.jogged = clock - (ms(at) - ms(self.origin));
            self.history.cut(at);
            self.series.cut(at);
            self.alarms.retain(|(t, _)| *t <= ms(at));
            let info = self.plant.info();
            let count = info.signals.len() + info.quantities.len();
            self.alarm_count = self.series.at(count, at).unwrap_or(0);
            // Written again from the plant as it was.
            self.written.iter_mut().for_each(|w| *w = None);
        }
    }

    /// What the dock draws of `plant` with the values `values`.
    fn shown_of(&self, plant: &AnyPlant, values: &[i64], running: bool, upto: i64) -> Shown {
        let info = plant.info();
        let signals = info
            .signals
            .iter()
            .enumerate()
            .map(|(s, signal)| SignalShown {
                name: signal.name,
                output: signal.direction == Direction::Out,
                analog: signal.kind == Kind::Analog,
                value: values.get(s).copied().unwrap_or(0),
                device: self
                    .wires
                    .iter()
                    .find(|w| w.signal == s)
                    .map(|w| w.name.clone()),
            })
            .collect();
        let quantities = info
            .quantities
            .iter()
            .enumerate()
            .map(|(q, quantity)| (quantity.name, plant.quantity(q)))
            .collect();
        Shown {
            plant: info.name,
            running,
            signals,
            quantities,
            alarms: self
                .alarms
                .iter()
                .filter(|(t, _)| *t <= upto)
                .cloned()
                .collect(),
            figure: figure(plant),
        }
    }

    /// Reads the sensors at `at` (after faults) and writes those that
    /// changed to the machine's inputs.
    fn sense(&mut self, machine: &mut dyn Plc, at: SimTime) {
        self.coupling().sense(machine, at);
    }
}

/// A time in whole milliseconds.
fn ms(t: SimTime) -> i64 {
    i64::try_from(t.as_nanos() / 1_000_000).unwrap_or(i64::MAX)
}

impl Rig for PlantRig {
    fn setup(&self) -> &PlantSetup {
        &self.setup
    }

    fn advance(&mut self, machine: &mut dyn Plc, dt: SimTime) {
        let end = tick_end(machine.now(), dt);
        // The machine went back in time (resumed from a past scan): the
        // plant goes on from there as it is.
        if self.next_step > machine.now().saturating_add(STEP) {
            self.rewind(machine.now());
            self.next_step = machine.now().saturating_add(STEP);
        }
        while self.next_step <= end {
            let at = self.next_step;
            machine.run_until(at);
            if machine.now() < at {
                // Stopped short: a break condition held.
                return;
            }
            self.step(machine, at, None);
            self.next_step = at.saturating_add(STEP);
        }
        machine.run_until(end);
    }

    fn jog(&mut self, machine: &mut dyn Plc, hand: &[bool], span: u32) {
        // The faults act as at the machine's time, which stands still.
        let at = machine.now();
        for _ in 0..span {
            self.jogged += 1;
            self.step(machine, at, Some(hand));
        }
        let clock = ms(at) - ms(self.origin) + self.jogged;
        self.history.step(at, clock, &self.plant, true);
    }

    fn show(&self, machine: &dyn Plc) -> Shown {
        self.shown_of(&self.plant, &self.values, machine.running(), i64::MAX)
    }

    fn show_at(&self, at: SimTime) -> Shown {
        let Some((plant, _, mut values)) = self.history.at(at) else {
            return self.shown_of(&self.plant, &self.values, false, ms(at));
        };
        // The outputs as they drove it then; the sensors as they read.
        for (s, signal) in plant.info().signals.iter().enumerate() {
            if signal.direction == Direction::In {
                if let Some(v) = values.get_mut(s) {
                    *v = fault::apply(fault::acting(&self.faults, s, at), plant.sensor(s));
                }
            }
        }
        self.shown_of(&plant, &values, false, ms(at))
    }

    fn power_cycle(&mut self, machine: &mut dyn Plc) {
        // The alarms said stay in the dock's list (they happened); their
        // count, `PLANT.alarms`, starts again as the engine's does.
        let now = machine.now();
        self.plant.reset();
        self.origin = now;
        self.jogged = 0;
        self.alarm_count = 0;
        self.next_step = now.saturating_add(STEP);
        self.written.iter_mut().for_each(|w| *w = None);
        self.sense(machine, now);
        self.note(now);
        self.history.step(now, 0, &self.plant, true);
    }

    fn series(&self, name: &str, times: &[SimTime]) -> Option<Vec<Option<i64>>> {
        let rest = name
            .strip_prefix(self.plant.info().name)?
            .strip_prefix('.')?;
        let index = series::index_of(&self.plant, rest)?;
        Some(self.series.sample(index, times))
    }

    fn detach(&mut self, machine: &mut dyn Plc) {
        for w in &self.wires {
            if self.plant.info().signals[w.signal].direction == Direction::In {
                let _ = machine.apply(Command::ReleaseInput(w.device));
            }
        }
    }
}

/// The plant's own figure for the drawing ([`Shown::figure`]).
fn figure(plant: &AnyPlant) -> Vec<i64> {
    match plant {
        AnyPlant::Conveyor(c) => {
            let (length, part) = c.lengths_um();
            [length, part].into_iter().chain(c.part_leads()).collect()
        }
        AnyPlant::Tank(t) => {
            let info = t.info();
            let level = info.signal("level").map_or(0, |s| t.sensor(s));
            let param = |key: &str| {
                let i = info.params.iter().position(|p| p.key == key);
                i.and_then(|i| t.params().get(i).copied()).unwrap_or(0)
            };
            vec![level, param("low_at"), param("high_at")]
        }
        _ => Vec::new(),
    }
}
