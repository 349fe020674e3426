//! What the frame loop knows of a plant (issue #52): the [`Rig`]
//! interface it calls and what a rig publishes for drawing ([`Shown`]).
//! A leaf of the page's modules (only the engine below it), so that the
//! simulator, the editor and the plant dock all reach it without a
//! circle; the rigs themselves are built in the `plants` part
//! (`crate::plant`).

use engine::formats::project::PlantSetup;
use engine::plc::Plc;
use engine::SimTime;

/// A plant coupled to a machine, as the frame loop drives it: the
/// machine runs to each plant step, the plant moves, its sensors are
/// written to the machine's inputs. Built inside the `plants` part.
pub trait Rig {
    /// The setup it was built from (a new setup builds a new rig).
    fn setup(&self) -> &PlantSetup;
    /// Advances the machine and the plant by `dt` of simulated time.
    fn advance(&mut self, machine: &mut dyn Plc, dt: SimTime);
    /// Manual mode, with the machine stopped: the plant moves `ms`
    /// milliseconds of its own clock, its actuators driven by `hand`
    /// (per signal, on or off) instead of the machine's outputs; its
    /// sensors are still written to the machine's inputs.
    fn jog(&mut self, machine: &mut dyn Plc, hand: &[bool], ms: u32);
    /// What the dock draws, now.
    fn show(&self, machine: &dyn Plc) -> Shown;
    /// What the dock draws while time travel shows the scan that ended
    /// at `at`: the plant as it was then.
    fn show_at(&self, at: SimTime) -> Shown;
    /// The plant device `name` (`tank.level`, `conveyor.motor`,
    /// `tank.alarms`: what `hashigo test` reads) at each of `times`, as
    /// the plant stood after its last step at or before it (`None`: not
    /// kept); `None` when the plant has no such device.
    fn series(&self, name: &str, times: &[SimTime]) -> Option<Vec<Option<i64>>>;
    /// The machine's power went off and on: the plant back at its start
    /// (as `hashigo`'s power cycle puts it), from the machine's time now.
    fn power_cycle(&mut self, machine: &mut dyn Plc);
    /// Unwires: the inputs the plant drove are released.
    fn detach(&mut self, machine: &mut dyn Plc);
}

/// Where a machine's plant is kept: none, or the rig coupled to it.
pub type RigSlot = Option<Box<dyn Rig>>;

/// Refusals of a setup, each at its wiring row (1-based; 0: not a row's).
pub type Refusals = Vec<(usize, Refusal)>;

/// Why a setup is refused, by kind, said in the page's language: a
/// wiring row's (`crate::i18n::plant_wiring`), or the plant's (a
/// parameter, a fault, its own check: `crate::i18n::plant_errors`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Refusal {
    /// A wiring row the plant and the machine do not take.
    Wire(engine::plant::wiring::WireError),
    /// A parameter, a fault or the plant's name the plant refuses.
    Plant(engine::plant::PlantError),
}

/// Couples a setup's plant to a machine, or refuses.
pub type Build = fn(&PlantSetup, &mut dyn Plc) -> Result<Box<dyn Rig>, Refusals>;

/// One signal as the dock draws it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SignalShown {
    /// Its name (`infeed`).
    pub name: &'static str,
    /// An actuator (the PLC drives it); else a sensor.
    pub output: bool,
    /// An analog signal (0..=100 000 is 0–100 %).
    pub analog: bool,
    /// Its value: what the PLC reads, or what acts on the plant.
    pub value: i64,
    /// The device it is wired to, if any.
    pub device: Option<String>,
}

/// What the plant dock draws, published by the rig once per frame.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Shown {
    /// The plant's engine name.
    pub plant: &'static str,
    /// Whether the machine runs (the plant stands still when not).
    pub running: bool,
    /// Its signals.
    pub signals: Vec<SignalShown>,
    /// Its quantities, by name.
    pub quantities: Vec<(&'static str, i64)>,
    /// The latest alarms: the machine's time in ms, the message.
    pub alarms: Vec<(i64, String)>,
    /// The plant's own figure: the conveyor's belt and part lengths and
    /// its parts' leading edges (µm); the tank's level (thousandths of
    /// a percent); empty for the others.
    pub figure: Vec<i64>,
}

/// What the shown workspace's rig last published, in the context (the
/// dock's `Plants::shown`), for the editor's Watch to offer the plant's
/// names without reaching the dock's module.
#[derive(Clone, Copy)]
pub struct ShownPlant(pub leptos::prelude::RwSignal<Option<Shown>>);

impl Shown {
    /// The plant's names as Watch and the chart take them (`hashigo
    /// test`'s): each quantity, `PLANT.alarms`, then each signal whose
    /// name is no quantity's (the tank's `level` is its quantity), so
    /// Watch offers them as the user types, beside the machine's devices.
    pub fn device_names(&self) -> Vec<String> {
        let quantities = self.quantities.iter().map(|(n, _)| *n);
        let signals = (self.signals.iter().map(|s| s.name))
            .filter(|s| !self.quantities.iter().any(|(q, _)| q == s));
        (quantities.chain(["alarms"]).chain(signals))
            .map(|n| format!("{}.{n}", self.plant))
            .collect()
    }
}
