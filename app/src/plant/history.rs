//! The plant's past, for time travel (part `plants`; docs/plants.md "In
//! the page"): a copy of the plant every [`SNAP`] of the machine's time
//! and each change of what drove its actuators. The plant at a past scan
//! is the copy before it stepped forward, 1 ms at a time, driven as it
//! was then: exact, since a plant's step depends only on its state, its
//! clock and its drive. Bounded: [`KEPT`] copies (ten minutes of the
//! machine's time); older scans show the oldest copy kept.

use std::collections::VecDeque;

use engine::plant::{AnyPlant, Plant, STEP};
use engine::SimTime;

/// A copy of the plant is kept this often (machine time).
pub(super) const SNAP: SimTime = SimTime::from_millis(250);
/// The most copies kept.
const KEPT: usize = 2400;

/// The plant as it stood after its step at `at`.
struct Snap {
    at: SimTime,
    /// The plant's own clock then (ms; manual mode moves it alone).
    clock: i64,
    plant: AnyPlant,
}

/// What a rig keeps of its plant's past.
#[derive(Default)]
pub(super) struct History {
    snaps: VecDeque<Snap>,
    /// From when each drive acted: per signal, the value acting.
    drives: VecDeque<(SimTime, Vec<i64>)>,
}

impl History {
    /// Notes the drive of the step at `at`, when it changed.
    pub(super) fn drive(&mut self, at: SimTime, drive: &[i64], outputs: &[usize]) {
        let same = self
            .drives
            .back()
            .is_some_and(|(_, d)| outputs.iter().all(|&s| d.get(s) == drive.get(s)));
        if !same {
            self.drives.push_back((at, drive.to_vec()));
        }
    }

    /// After the step at `at` (plant clock `clock`): keeps a copy when
    /// [`SNAP`] went by since the last (`force`: in any case).
    pub(super) fn step(&mut self, at: SimTime, clock: i64, plant: &AnyPlant, force: bool) {
        let due = self
            .snaps
            .back()
            .is_none_or(|s| at >= s.at.saturating_add(SNAP));
        if !(due || force) {
            return;
        }
        self.snaps.push_back(Snap {
            at,
            clock,
            plant: plant.clone(),
        });
        if self.snaps.len() > KEPT {
            self.snaps.pop_front();
            // Drives older than the oldest copy are not needed, but the
            // one acting at it is.
            let oldest = self.snaps.front().map_or(SimTime::ZERO, |s| s.at);
            while self.drives.len() > 1 && self.drives[1].0 <= oldest {
                self.drives.pop_front();
            }
        }
    }

    /// Forgets what came after `at` (the machine resumed from there).
    pub(super) fn cut(&mut self, at: SimTime) {
        while self.snaps.len() > 1 && self.snaps.back().is_some_and(|s| s.at > at) {
            self.snaps.pop_back();
        }
        while self.drives.back().is_some_and(|(t, _)| *t > at) {
            self.drives.pop_back();
        }
    }

    /// The plant after its step at `at`, its clock and the drive acting
    /// then; `None` before anything was kept.
    pub(super) fn at(&self, at: SimTime) -> Option<(AnyPlant, i64, Vec<i64>)> {
        // The last copy at or before `at` (the latest of equal times: a
        // manual jog's end), else the oldest kept.
        let i = self.snaps.iter().rposition(|s| s.at <= at).unwrap_or(0);
        let snap = self.snaps.get(i)?;
        let mut plant = snap.plant.clone();
        let mut clock = snap.clock;
        let mut t = snap.at;
        let mut alarms = Vec::new();
        let idle = vec![0; plant.info().signals.len()];
        while t.saturating_add(STEP) <= at {
            t = t.saturating_add(STEP);
            clock += 1;
            plant.step(clock, self.drive_at(t).unwrap_or(&idle), &mut alarms);
            alarms.clear();
        }
        let drive = self.drive_at(at).cloned().unwrap_or(idle);
        Some((plant, clock, drive))
    }

    /// The drive acting at `at`.
    fn drive_at(&self, at: SimTime) -> Option<&Vec<i64>> {
        self.drives
            .iter()
            .rev()
            .find(|(t, _)| *t <= at)
            .map(|(_, d)| d)
    }
}
