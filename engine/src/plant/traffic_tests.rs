use super::*;

const CAR_RED: usize = 1;

/// Runs `t` from `from` for `ms` steps with the lights given as
/// (car_red, car_yellow, car_green, walk, dont_walk); the alarms raised.
fn run(t: &mut Traffic, from: i64, ms: i64, lights: [i64; 5]) -> Vec<String> {
    let mut drive = [0; 6];
    drive[CAR_RED..].copy_from_slice(&lights);
    let mut alarms = Vec::new();
    for now in from + 1..=from + ms {
        t.step(now, &drive, &mut alarms);
    }
    alarms
}

const CARS_GO: [i64; 5] = [0, 0, 1, 0, 1];
const PEOPLE_GO: [i64; 5] = [1, 0, 0, 1, 0];

#[test]
fn a_pedestrian_arrives_presses_the_button_and_waits_for_walk() {
    let mut t = Traffic::new();
    let first = t.next_arrival;
    assert!((0..=10_000).contains(&first), "within the first spread");
    run(&mut t, 0, first, CARS_GO);
    assert_eq!((t.sensor(BUTTON), t.quantity(2)), (1, 1));
    run(&mut t, first, 299, CARS_GO);
    assert_eq!(t.sensor(BUTTON), 1, "held for press = 300 ms");
    run(&mut t, first + 299, 1, CARS_GO);
    assert_eq!(t.sensor(BUTTON), 0);
    // Waits 5 s more, then walk: crossed, and the wait is the longest.
    run(&mut t, first + 300, 4700, CARS_GO);
    assert_eq!(t.quantity(1), 5000, "waits still going count");
    run(&mut t, first + 5000, 1, PEOPLE_GO);
    assert_eq!((t.quantity(0), t.quantity(1), t.quantity(2)), (1, 5001, 0));
    // A shorter wait later does not lower the longest.
    let alarms = run(&mut t, first + 5001, 60_000, PEOPLE_GO);
    assert!(alarms.is_empty(), "{alarms:?}");
    assert!(t.quantity(0) >= 3, "people crossing on walk at once");
    assert_eq!(t.quantity(1), 5001);
}

#[test]
fn walk_with_dont_walk_also_lit_lets_nobody_cross() {
    let mut t = Traffic::new();
    run(&mut t, 0, 11_000, [1, 0, 0, 1, 1]);
    assert_eq!((t.quantity(0), t.quantity(2)), (0, 1));
}

#[test]
fn green_or_yellow_with_walk_is_one_alarm_while_it_lasts() {
    let mut t = Traffic::new();
    let alarms = run(&mut t, 0, 1000, [0, 0, 1, 1, 0]);
    assert_eq!(alarms.len(), 1, "{alarms:?}");
    assert!(alarms[0].contains("green while pedestrians have walk"));
    // Yellow follows green with walk still on: the same conflict goes on.
    assert!(run(&mut t, 1000, 1000, [0, 1, 0, 1, 0]).is_empty());
    assert!(run(&mut t, 2000, 1000, PEOPLE_GO).is_empty());
    let again = run(&mut t, 3000, 10, [0, 1, 0, 1, 0]);
    assert!(again[0].contains("yellow"), "{again:?}");
}

#[test]
fn the_schedule_follows_the_seed_and_a_power_cycle_starts_it_over() {
    let mut t = Traffic::new();
    run(&mut t, 0, 120_000, CARS_GO);
    let (waiting, waited) = (t.quantity(2), t.quantity(1));
    assert!(waiting >= 4, "about one each 20-30 s: {waiting}");
    t.reset();
    assert_eq!((t.quantity(0), t.quantity(1), t.quantity(2)), (0, 0, 0));
    run(&mut t, 0, 120_000, CARS_GO);
    assert_eq!((t.quantity(2), t.quantity(1)), (waiting, waited));
    t.set_param(SEED, 2);
    run(&mut t, 0, 120_000, CARS_GO);
    assert_ne!(t.quantity(1), waited, "another seed, other arrivals");
}

#[test]
fn waiting_pedestrians_are_bounded() {
    let mut t = Traffic::new();
    t.set_param(INTERVAL, 100);
    t.set_param(SPREAD, 0);
    run(&mut t, 0, 200_000, CARS_GO);
    assert_eq!(t.quantity(2), MAX_WAITING as i64);
}
