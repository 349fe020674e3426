use super::*;

/// Runs `c` for `ms` steps from `from` with the motor as given; the
/// alarms raised.
fn run(c: &mut Conveyor, from: i64, ms: i64, motor: bool) -> Vec<String> {
    let mut alarms = Vec::new();
    for t in from + 1..=from + ms {
        c.step(t, &[0, 0, i64::from(motor)], &mut alarms);
    }
    alarms
}

#[test]
fn a_part_arrives_within_the_spread_and_waits_at_the_infeed_while_the_belt_stands() {
    let mut c = Conveyor::new();
    assert_eq!(c.sensor(INFEED), 0);
    run(&mut c, 0, 1001, false);
    assert_eq!(c.quantity(0), 1, "placed within the first spread");
    assert_eq!(c.sensor(INFEED), 1);
    assert_eq!(c.sensor(OUTFEED), 0);
    // The infeed is not clear: no second part, however long it waits.
    run(&mut c, 1001, 60_000, false);
    assert_eq!(c.quantity(0), 1);
    assert_eq!((c.quantity(1), c.quantity(2)), (0, 1));
}

#[test]
fn a_part_rides_the_belt_past_the_outfeed_and_is_delivered() {
    let mut c = Conveyor::new();
    run(&mut c, 0, 2001, false);
    // Belt 2000 mm, part 200 mm, 250 mm/s: 8 s until its tail is off the end.
    let alarms = run(&mut c, 2001, 7500, true);
    assert!(alarms.is_empty(), "{alarms:?}");
    assert_eq!(
        c.sensor(OUTFEED),
        1,
        "7.5 s on, its lead is past the outfeed eye at the end"
    );
    assert!(
        c.quantity(2) >= 2,
        "the next parts arrived meanwhile and ride along"
    );
    assert_eq!(c.quantity(1), 0);
    run(&mut c, 9501, 500, true);
    assert_eq!(c.quantity(1), 1, "delivered after 8 s of belt");
    assert!(c.quantity(0) >= 2);
}

#[test]
fn starting_the_belt_sooner_than_the_guard_after_an_arrival_is_one_alarm() {
    let mut c = Conveyor::new();
    let mut alarms = Vec::new();
    let mut t = 0;
    while c.quantity(0) == 0 {
        t += 1;
        c.step(t, &[0, 0, 0], &mut alarms);
    }
    let arrived = t;
    run(&mut c, t, 300, false);
    let alarms = run(&mut c, arrived + 300, 2000, true);
    assert_eq!(alarms.len(), 1, "counted once, when the belt starts");
    assert!(alarms[0].contains("301 ms"), "{}", alarms[0]);
    // A start a full guard after the arrival raises none.
    let mut c = Conveyor::new();
    run(&mut c, 0, 2001, false);
    let later = run(&mut c, 2001, 100, true);
    assert!(later.is_empty(), "{later:?}");
}

#[test]
fn the_seed_fixes_the_schedule_and_reset_starts_it_over() {
    let arrivals = |seed: i64| {
        let mut c = Conveyor::new();
        c.set_param(SEED, seed);
        let mut placed = Vec::new();
        let mut alarms = Vec::new();
        for t in 1..=120_000 {
            let before = c.quantity(0);
            c.step(t, &[0, 0, 1], &mut alarms);
            if c.quantity(0) != before {
                placed.push(t);
            }
        }
        placed
    };
    assert_eq!(arrivals(1), arrivals(1));
    assert_ne!(arrivals(1), arrivals(2));
    let first = arrivals(3);
    assert!(
        first
            .windows(2)
            .all(|w| (4000..=5000).contains(&(w[1] - w[0]))),
        "{first:?}"
    );
    let mut c = Conveyor::new();
    let fresh = c.clone();
    run(&mut c, 0, 30_000, true);
    c.reset();
    assert_eq!(c, fresh);
}

#[test]
fn a_part_longer_than_half_the_belt_is_refused() {
    let mut c = Conveyor::new();
    c.set_param(LENGTH, 300);
    let e = c.check().unwrap_err();
    assert_eq!(
        e,
        Misfit::PartOverHalfBelt {
            part: 200,
            length: 300
        }
    );
    assert!(e.to_string().contains("half the belt"), "{e}");
    c.set_param(PART, 150);
    assert!(c.check().is_ok());
}

#[test]
fn a_part_still_on_the_landing_place_is_seen_so_the_belt_is_never_left_waiting() {
    let mut c = Conveyor::new();
    run(&mut c, 0, 2001, false);
    // 150 mm on: the tail (at 150 mm) is past the landing place's middle
    // but still on it, so no new part can land there.
    run(&mut c, 2001, 600, true);
    assert_eq!(c.parts.front().map(|lead| lead - c.um(PART)), Some(150_000));
    assert_eq!(c.sensor(INFEED), 1, "a part on the landing place is seen");
    let placed = c.quantity(0);
    run(&mut c, 2601, 60_000, false);
    assert_eq!(c.quantity(0), placed, "and no part lands on it");
    // 50 mm more and the place is clear: the eye goes off, a part lands.
    run(&mut c, 62_601, 200, true);
    run(&mut c, 62_801, 10, false);
    assert_eq!(c.quantity(0), placed + 1);
}
