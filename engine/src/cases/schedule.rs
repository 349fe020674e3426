//! When a case looks at its expectations: the instants, in order, and
//! which expectations each instant samples.
//!
//! Every expectation has a span `from..=to` (a single instant for
//! `… at TIME`). The *points* are every event time and every span's two
//! ends. A span is sampled at every point inside it and on its own grid,
//! every [`SAMPLE`] from its start. Keeping each span to its own grid (not
//! every other span's) makes the work a sum over the expectations, which
//! [`Schedule::work`] counts before anything runs.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use super::SAMPLE;
use crate::time::SimTime;

/// The instants of one case and the spans each one samples.
pub(super) struct Schedule {
    /// Every point, sorted, each once.
    points: Vec<SimTime>,
    /// The first point not yet passed.
    next_point: usize,
    /// Each expectation's span.
    spans: Vec<(SimTime, SimTime)>,
    /// Expectation indices by the start of their span.
    by_start: Vec<usize>,
    /// The first of `by_start` not yet started.
    next_start: usize,
    /// The next grid sample of each started span, earliest first.
    grid: BinaryHeap<Reverse<(SimTime, usize)>>,
    /// Started spans, pruned of ended ones at each point.
    active: Vec<usize>,
}

impl Schedule {
    /// The schedule of a case whose events happen at `events` and whose
    /// expectations span `spans` (in the expectations' order).
    pub(super) fn new(
        events: impl Iterator<Item = SimTime>,
        spans: Vec<(SimTime, SimTime)>,
    ) -> Self {
        let mut points: Vec<SimTime> = events.collect();
        points.extend(spans.iter().flat_map(|&(from, to)| [from, to]));
        crate::sort::all(&mut points);
        points.dedup();
        let mut by_start: Vec<usize> = (0..spans.len()).collect();
        crate::sort::by_key(&mut by_start, |&i| spans[i].0);
        Schedule {
            points,
            next_point: 0,
            spans,
            by_start,
            next_start: 0,
            grid: BinaryHeap::new(),
            active: Vec::new(),
        }
    }

    /// How many samples the case takes at most: one per instant (the
    /// machine runs to each) plus one per expectation looked at. Counted
    /// without running anything, in O(n log n).
    pub(super) fn work(&self) -> u64 {
        let points_within = |from: SimTime, to: SimTime| {
            (self.points.partition_point(|&p| p <= to) - self.points.partition_point(|&p| p < from))
                as u64
        };
        let grid = |from: SimTime, to: SimTime| (to - from).as_nanos() / SAMPLE.as_nanos();
        let mut work = self.points.len() as u64;
        for &(from, to) in &self.spans {
            // Each grid sample is an instant and a look; each point a look.
            work = work
                .saturating_add(grid(from, to).saturating_mul(2))
                .saturating_add(points_within(from, to));
        }
        work
    }

    /// The next instant, with the expectations looked at then put in
    /// `due`; `None` after the last.
    pub(super) fn next(&mut self, due: &mut Vec<usize>) -> Option<SimTime> {
        due.clear();
        let point = self.points.get(self.next_point).copied();
        let sample = self.grid.peek().map(|Reverse((t, _))| *t);
        let t = match (point, sample) {
            (Some(p), Some(s)) => p.min(s),
            (p, s) => p.or(s)?,
        };
        let at_point = point == Some(t);
        if at_point {
            self.next_point += 1;
        }
        while let Some(&i) = self.by_start.get(self.next_start) {
            let (from, to) = self.spans[i];
            if from > t {
                break;
            }
            self.next_start += 1;
            self.active.push(i);
            self.push_after(i, from, to);
        }
        while let Some(&Reverse((s, i))) = self.grid.peek() {
            if s != t {
                break;
            }
            self.grid.pop();
            let (_, to) = self.spans[i];
            self.push_after(i, s, to);
            if !at_point {
                due.push(i);
            }
        }
        if at_point {
            let spans = &self.spans;
            self.active.retain(|&i| spans[i].1 >= t);
            due.extend_from_slice(&self.active);
        }
        Some(t)
    }

    /// Queues span `i`'s grid sample after `t`, if it comes before its end
    /// `to` (the end is a point of its own).
    fn push_after(&mut self, i: usize, t: SimTime, to: SimTime) {
        let next = t.saturating_add(SAMPLE);
        if next < to {
            self.grid.push(Reverse((next, i)));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeSet;

    fn ms(x: f64) -> SimTime {
        SimTime::from_nanos((x * 1e6).round() as u64)
    }

    /// Each span's looks, built the obvious way: every point in it and its
    /// own grid.
    fn naive(events: &[SimTime], spans: &[(SimTime, SimTime)]) -> Vec<(SimTime, Vec<usize>)> {
        let mut points: BTreeSet<SimTime> = events.iter().copied().collect();
        points.extend(spans.iter().flat_map(|&(a, b)| [a, b]));
        let mut looks: std::collections::BTreeMap<SimTime, BTreeSet<usize>> = Default::default();
        for (i, &(from, to)) in spans.iter().enumerate() {
            for &p in points.range(from..=to) {
                looks.entry(p).or_default().insert(i);
            }
            let mut t = from;
            while t < to {
                looks.entry(t).or_default().insert(i);
                t = t.saturating_add(SAMPLE);
            }
        }
        for p in points {
            looks.entry(p).or_default();
        }
        looks
            .into_iter()
            .map(|(t, s)| (t, s.into_iter().collect()))
            .collect()
    }

    fn walk(events: &[SimTime], spans: &[(SimTime, SimTime)]) -> Vec<(SimTime, Vec<usize>)> {
        let mut schedule = Schedule::new(events.iter().copied(), spans.to_vec());
        let mut due = Vec::new();
        let mut out = Vec::new();
        while let Some(t) = schedule.next(&mut due) {
            let mut d = due.clone();
            d.sort_unstable();
            out.push((t, d));
        }
        out
    }

    #[test]
    fn instants_are_every_point_and_every_sample_once_in_order() {
        let events = [ms(0.5), ms(3.0), ms(7.25)];
        let spans = [
            (ms(2.5), ms(2.5)),
            (ms(0.3), ms(4.1)),
            (ms(2.0), ms(9.0)),
            (ms(8.7), ms(8.7)),
            (ms(2.0), ms(9.0)),
        ];
        let walked = walk(&events, &spans);
        assert_eq!(walked, naive(&events, &spans));
        assert!(walked.windows(2).all(|w| w[0].0 < w[1].0));
        let samples: u64 = walked.iter().map(|(_, d)| 1 + d.len() as u64).sum();
        let work = Schedule::new(events.iter().copied(), spans.to_vec()).work();
        assert!(samples <= work, "{samples} samples, {work} counted");
    }

    #[test]
    fn work_is_linear_in_the_expectations() {
        let long = (SimTime::ZERO, SimTime::from_millis(9_000_000));
        let one = Schedule::new(std::iter::empty(), vec![long]).work();
        let many = Schedule::new(std::iter::empty(), vec![long; 1000]).work();
        assert!(one > 9_000_000 && one < 20_000_000, "{one}");
        assert!(many > 1000 * 9_000_000, "{many}");
    }
}
