//! `--ignored` property tests (`cargo test -p engine --test plants --
//! --ignored`): each plant driven by random outputs and parameters for
//! simulated hours never panics, and every quantity stays in its
//! documented range.

use engine::plant::{AnyPlant, Direction, Plant};
use proptest::prelude::*;

/// Two simulated hours, in 1 ms steps.
const HOURS_MS: i64 = 2 * 3600 * 1000;

/// Drives `plant` for [`HOURS_MS`] with the outputs of `segments` (each:
/// how long, in ms, and the bits of the `out` signals), repeated; checks
/// every quantity and sensor after each segment.
fn drive(mut plant: AnyPlant, params: &[u64], segments: &[(u16, u8)]) {
    let info = plant.info();
    for (i, p) in info.params.iter().enumerate() {
        let span = (p.max - p.min) as u64 + 1;
        let value = p.min + (params[i % params.len()] % span) as i64;
        let old = plant.params()[i];
        plant.set_param(i, value);
        if plant.check().is_err() {
            plant.set_param(i, old);
        }
    }
    let outs: Vec<usize> = (0..info.signals.len())
        .filter(|&s| info.signals[s].direction == Direction::Out)
        .collect();
    let mut drive = vec![0i64; info.signals.len()];
    let (mut now, mut alarms) = (0i64, Vec::new());
    'run: for &(ms, bits) in segments.iter().cycle() {
        for (k, &s) in outs.iter().enumerate() {
            drive[s] = i64::from(bits >> k & 1);
        }
        for _ in 0..=ms {
            now += 1;
            plant.step(now, &drive, &mut alarms);
            if now >= HOURS_MS {
                break 'run;
            }
        }
        check(&plant);
    }
    check(&plant);
}

fn check(plant: &AnyPlant) {
    let info = plant.info();
    for (q, quantity) in info.quantities.iter().enumerate() {
        let v = plant.quantity(q);
        let (lo, hi) = quantity.range;
        assert!(
            (lo..=hi).contains(&v),
            "{}.{} = {v}",
            info.name,
            quantity.name
        );
    }
    for (s, signal) in info.signals.iter().enumerate() {
        if signal.direction == Direction::In {
            let v = plant.sensor(s);
            assert!(
                (0..=engine::plant::ANALOG_FULL).contains(&v),
                "{}.{} = {v}",
                info.name,
                signal.name
            );
        }
    }
    match info.name {
        "conveyor" => assert_eq!(plant.quantity(0) - plant.quantity(1), plant.quantity(2)),
        // The door's limit switches follow its position.
        "door" => {
            let position = plant.quantity(0);
            assert_eq!(plant.sensor(0), i64::from(position == 100), "top");
            if position > 0 {
                assert_eq!(plant.sensor(1), 0, "bottom at {position} %");
            }
        }
        // One end switch at most, and never both.
        "sorter" => assert!(plant.sensor(2) + plant.sensor(3) <= 1),
        // The bit and the analog value of one sensor agree.
        "room-light" => {
            let light = plant.sensor(1);
            assert_eq!(plant.sensor(0) == 1, light < plant.params()[2] * 1000);
        }
        _ => {}
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 12, ..ProptestConfig::default() })]

    #[test]
    #[ignore = "simulated hours: run with --ignored"]
    fn the_conveyor_stays_in_range_under_random_outputs(
        params in prop::collection::vec(any::<u64>(), 7),
        segments in prop::collection::vec((0u16..20_000, any::<u8>()), 1..40),
    ) {
        drive(AnyPlant::new("conveyor").unwrap(), &params, &segments);
    }

    #[test]
    #[ignore = "simulated hours: run with --ignored"]
    fn the_tank_stays_in_range_under_random_outputs(
        params in prop::collection::vec(any::<u64>(), 6),
        segments in prop::collection::vec((0u16..20_000, any::<u8>()), 1..40),
    ) {
        drive(AnyPlant::new("tank").unwrap(), &params, &segments);
    }

    #[test]
    #[ignore = "simulated hours: run with --ignored"]
    fn the_crossing_stays_in_range_under_random_outputs(
        params in prop::collection::vec(any::<u64>(), 4),
        segments in prop::collection::vec((0u16..20_000, any::<u8>()), 1..40),
    ) {
        drive(AnyPlant::new("traffic").unwrap(), &params, &segments);
    }

    #[test]
    #[ignore = "simulated hours: run with --ignored"]
    fn the_door_stays_in_range_under_random_outputs(
        params in prop::collection::vec(any::<u64>(), 10),
        segments in prop::collection::vec((0u16..20_000, any::<u8>()), 1..40),
    ) {
        drive(AnyPlant::new("door").unwrap(), &params, &segments);
    }

    #[test]
    #[ignore = "simulated hours: run with --ignored"]
    fn the_sorter_stays_in_range_under_random_outputs(
        params in prop::collection::vec(any::<u64>(), 11),
        segments in prop::collection::vec((0u16..20_000, any::<u8>()), 1..40),
    ) {
        drive(AnyPlant::new("sorter").unwrap(), &params, &segments);
    }

    #[test]
    #[ignore = "simulated hours: run with --ignored"]
    fn the_room_light_stays_in_range_under_random_outputs(
        params in prop::collection::vec(any::<u64>(), 3),
        segments in prop::collection::vec((0u16..20_000, any::<u8>()), 1..40),
    ) {
        drive(AnyPlant::new("room-light").unwrap(), &params, &segments);
    }
}
