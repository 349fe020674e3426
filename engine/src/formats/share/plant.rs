//! What version 5 links add (issue #50): the project's plant (its name,
//! wiring, parameters and faults), after a version 4 link's exercise. A
//! project without a plant keeps its version 1-4 link, which older
//! Hashigos open.

use super::{put_len, put_map, put_str, Reader, ShareError};
use crate::formats::project::{PlantSetup, Project, MAX_PLANT_LINES};

/// The plant: its name, a wiring flag and pairs, parameters, faults.
pub(super) fn put(w: &mut Vec<u8>, project: &Project) {
    let plant = project.plant.clone().unwrap_or_default();
    put_str(w, &plant.name);
    match &plant.wiring {
        None => w.push(0),
        Some(pairs) => {
            w.push(1);
            put_len(w, pairs.len());
            for [signal, device] in pairs {
                put_str(w, signal);
                put_str(w, device);
            }
        }
    }
    put_map(w, &plant.params);
    put_len(w, plant.faults.len());
    for fault in &plant.faults {
        put_str(w, fault);
    }
}

impl Reader<'_> {
    /// What [`put`] wrote.
    pub(super) fn plant(&mut self) -> Result<PlantSetup, ShareError> {
        let name = self.string()?;
        let wiring = match self.byte()? {
            0 => None,
            1 => {
                let n = self.count("plant wiring lines", MAX_PLANT_LINES)?;
                let mut pairs = Vec::with_capacity(n);
                for _ in 0..n {
                    pairs.push([self.string()?, self.string()?]);
                }
                Some(pairs)
            }
            _ => return Err(self.bad("the wiring flag is neither 0 nor 1")),
        };
        let params = self.map("plant parameters")?;
        if params.len() > MAX_PLANT_LINES {
            return Err(ShareError::TooMany {
                what: "plant parameters",
                count: params.len() as u64,
                limit: MAX_PLANT_LINES,
            });
        }
        let n = self.count("plant faults", MAX_PLANT_LINES)?;
        let mut faults = Vec::with_capacity(n);
        for _ in 0..n {
            faults.push(self.string()?);
        }
        Ok(PlantSetup {
            name,
            wiring,
            params,
            faults,
        })
    }
}
