//! The plant's signals and quantities over time, for the timing chart
//! and Watch (part `plants`; docs/plants.md "In the page"): per plant
//! device (its signals, its quantities, then `alarms`, as `hashigo test`
//! numbers them) the value after each 1 ms plant step, kept as its
//! changes only. Exact (every step is noted, so a scan's end reads the
//! plant as it stood then) and cheap (a still belt notes nothing; a
//! scan's value is a binary search). Bounded: [`KEPT`] changes a device
//! (a quantity that changes every millisecond keeps its last 65 s);
//! before its oldest change kept a device has no value (drawn as none).

use std::collections::VecDeque;

use engine::plant::{AnyPlant, Kind, Plant, ALARMS, ANALOG_FULL};
use engine::SimTime;

/// The most changes kept per device.
pub(super) const KEPT: usize = 65_536;

/// Each plant device's changes: (from when, value).
#[derive(Default)]
pub(super) struct Series {
    logs: Vec<VecDeque<(SimTime, i64)>>,
}

/// The plant device `rest` names in `PLANT.rest`, as the engine's
/// `Planted` resolves it: a quantity (or `alarms`) first, then a signal
/// (the tank's `level` is its quantity, in percent).
pub(super) fn index_of(plant: &AnyPlant, rest: &str) -> Option<usize> {
    let info = plant.info();
    let signals = info.signals.len();
    if rest == ALARMS.name {
        Some(signals + info.quantities.len())
    } else if let Some(q) = info.quantities.iter().position(|q| q.name == rest) {
        Some(signals + q)
    } else {
        info.signal(rest)
    }
}

/// Every plant device's value now: the signals as `values` has them
/// (an analog one in whole percent), the quantities, the alarms raised.
pub(super) fn values_of(plant: &AnyPlant, values: &[i64], alarms: i64) -> Vec<i64> {
    let info = plant.info();
    let signals = info.signals.iter().enumerate().map(|(s, signal)| {
        let v = values.get(s).copied().unwrap_or(0);
        match signal.kind {
            Kind::Analog => v * 100 / ANALOG_FULL,
            _ => v,
        }
    });
    let quantities = (0..info.quantities.len()).map(|q| plant.quantity(q));
    signals
        .chain(quantities)
        .chain(std::iter::once(alarms))
        .collect()
}

impl Series {
    /// Notes the devices' values from `at` on (a change at the same time
    /// as the last replaces it: manual mode steps while time stands).
    pub(super) fn note(&mut self, at: SimTime, values: &[i64]) {
        if self.logs.len() != values.len() {
            self.logs = vec![VecDeque::new(); values.len()];
        }
        for (log, &v) in self.logs.iter_mut().zip(values) {
            match log.back_mut() {
                Some((_, last)) if *last == v => {}
                Some((t, last)) if *t == at => *last = v,
                _ => {
                    log.push_back((at, v));
                    if log.len() > KEPT {
                        log.pop_front();
                    }
                }
            }
        }
    }

    /// Forgets what came after `at` (the machine resumed from there).
    pub(super) fn cut(&mut self, at: SimTime) {
        for log in &mut self.logs {
            while log.back().is_some_and(|(t, _)| *t > at) {
                log.pop_back();
            }
        }
    }

    /// Device `index`'s value at `at`; `None` before its oldest change kept.
    pub(super) fn at(&self, index: usize, at: SimTime) -> Option<i64> {
        let log = self.logs.get(index)?;
        let after = log.partition_point(|(t, _)| *t <= at);
        after.checked_sub(1).map(|i| log[i].1)
    }

    /// Device `index`'s value at each of `times`.
    pub(super) fn sample(&self, index: usize, times: &[SimTime]) -> Vec<Option<i64>> {
        times.iter().map(|&t| self.at(index, t)).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ms(n: u64) -> SimTime {
        SimTime::from_millis(n)
    }

    #[test]
    fn a_value_is_the_last_change_at_or_before_the_time() {
        let mut s = Series::default();
        s.note(ms(0), &[0, 5]);
        s.note(ms(1), &[0, 5]);
        s.note(ms(2), &[1, 5]);
        s.note(ms(3), &[1, 6]);
        assert_eq!(
            s.sample(0, &[ms(0), ms(1), ms(2), ms(9)]),
            [Some(0), Some(0), Some(1), Some(1)]
        );
        assert_eq!(s.at(1, ms(2)), Some(5));
        assert_eq!(s.at(1, ms(3)), Some(6));
        // Only the changes are kept.
        assert_eq!(s.logs[0].len(), 2);
        assert_eq!(s.at(2, ms(3)), None, "no such device");
    }

    #[test]
    fn a_change_at_the_same_time_replaces_and_cut_forgets_the_later() {
        let mut s = Series::default();
        s.note(ms(5), &[1]);
        s.note(ms(7), &[2]);
        s.note(ms(7), &[3]);
        assert_eq!(s.at(0, ms(7)), Some(3));
        assert_eq!(s.logs[0].len(), 2);
        s.cut(ms(6));
        assert_eq!(s.at(0, ms(9)), Some(1));
        assert_eq!(s.at(0, ms(4)), None, "before the first change noted");
    }

    #[test]
    fn at_most_kept_changes_a_device() {
        let mut s = Series::default();
        for i in 0..(KEPT as u64 + 10) {
            s.note(ms(i), &[i as i64]);
        }
        assert_eq!(s.logs[0].len(), KEPT);
        assert_eq!(s.at(0, ms(9)), None, "forgotten");
        assert_eq!(s.at(0, ms(10)), Some(10));
    }
}
