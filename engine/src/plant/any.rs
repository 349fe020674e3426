//! The registry of plants: the one place that names every plant.

use super::conveyor::{self, Conveyor};
use super::door::{self, Door};
use super::room_light::{self, RoomLight};
use super::sorter::{self, Sorter};
use super::tank::{self, Tank};
use super::traffic::{self, Traffic};
use super::{Plant, PlantInfo};

/// Every plant's description, in `hashigo plants` order.
pub static ALL: [&PlantInfo; 6] = [
    &conveyor::INFO,
    &tank::INFO,
    &traffic::INFO,
    &door::INFO,
    &sorter::INFO,
    &room_light::INFO,
];

/// One of the plants, as a value (so a machine with its plant can be
/// copied for recording).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum AnyPlant {
    /// The book's conveyor.
    Conveyor(Conveyor),
    /// The tank.
    Tank(Tank),
    /// The pedestrian crossing.
    Traffic(Traffic),
    /// The garage door.
    Door(Door),
    /// The sorter.
    Sorter(Sorter),
    /// The Arduino sketch's room light.
    RoomLight(RoomLight),
}

impl AnyPlant {
    /// A new plant called `name`, if there is one.
    pub fn new(name: &str) -> Option<AnyPlant> {
        match name {
            "conveyor" => Some(AnyPlant::Conveyor(Conveyor::new())),
            "tank" => Some(AnyPlant::Tank(Tank::new())),
            "traffic" => Some(AnyPlant::Traffic(Traffic::new())),
            "door" => Some(AnyPlant::Door(Door::new())),
            "sorter" => Some(AnyPlant::Sorter(Sorter::new())),
            "room-light" => Some(AnyPlant::RoomLight(RoomLight::new())),
            _ => None,
        }
    }

    /// Sets parameters given by key and value as written (a project's
    /// `plant.params`, `--set conveyor.length=…`), then checks them
    /// together; the first refusal, typed. Shared by everything that sets
    /// a plant up from a project, for one set of refusals.
    pub fn set_params<'a>(
        &mut self,
        params: impl IntoIterator<Item = (&'a String, &'a String)>,
    ) -> Result<(), super::PlantError> {
        let info = self.info();
        for (key, value) in params {
            let Some(index) = info.params.iter().position(|p| p.key == key) else {
                let known: Vec<_> = info.params.iter().map(|p| p.key).collect();
                return Err(super::PlantError::UnknownParam {
                    plant: info.name,
                    key: key.clone(),
                    known: known.join(", "),
                });
            };
            let v = super::parse_param(&info.params[index], value)?;
            self.set_param(index, v);
        }
        self.check().map_err(super::PlantError::Together)
    }

    /// The plants' names, for messages.
    pub fn names() -> String {
        ALL.map(|p| p.name).join(", ")
    }

    fn inner(&self) -> &dyn Plant {
        match self {
            AnyPlant::Conveyor(p) => p,
            AnyPlant::Tank(p) => p,
            AnyPlant::Traffic(p) => p,
            AnyPlant::Door(p) => p,
            AnyPlant::Sorter(p) => p,
            AnyPlant::RoomLight(p) => p,
        }
    }

    fn inner_mut(&mut self) -> &mut dyn Plant {
        match self {
            AnyPlant::Conveyor(p) => p,
            AnyPlant::Tank(p) => p,
            AnyPlant::Traffic(p) => p,
            AnyPlant::Door(p) => p,
            AnyPlant::Sorter(p) => p,
            AnyPlant::RoomLight(p) => p,
        }
    }
}

impl Plant for AnyPlant {
    fn info(&self) -> &'static PlantInfo {
        self.inner().info()
    }

    fn params(&self) -> &[i64] {
        self.inner().params()
    }

    fn set_param(&mut self, index: usize, value: i64) {
        self.inner_mut().set_param(index, value);
    }

    fn check(&self) -> Result<(), super::Misfit> {
        self.inner().check()
    }

    fn reset(&mut self) {
        self.inner_mut().reset();
    }

    fn step(&mut self, now_ms: i64, drive: &[i64], alarms: &mut Vec<String>) {
        self.inner_mut().step(now_ms, drive, alarms);
    }

    fn sensor(&self, signal: usize) -> i64 {
        self.inner().sensor(signal)
    }

    fn quantity(&self, index: usize) -> i64 {
        self.inner().quantity(index)
    }
}
