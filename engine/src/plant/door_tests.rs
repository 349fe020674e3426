use super::*;

/// Runs `d` from `from` for `ms` steps with up and down as given; the
/// alarms raised.
fn run(d: &mut Door, from: i64, ms: i64, up: bool, down: bool) -> Vec<String> {
    let drive = [0, 0, 0, 0, i64::from(up), i64::from(down)];
    let mut alarms = Vec::new();
    for now in from + 1..=from + ms {
        d.step(now, &drive, &mut alarms);
    }
    alarms
}

/// A door whose remote and eye come only after an hour.
fn quiet() -> Door {
    let mut d = Door::new();
    d.set_param(REMOTE_EVERY, 3_600_000);
    d.set_param(EYE_EVERY, 3_600_000);
    d.set_param(SEED, 1);
    d
}

#[test]
fn the_door_travels_between_its_limit_switches_in_the_travel_time() {
    let mut d = quiet();
    assert_eq!((d.sensor(BOTTOM), d.sensor(TOP), d.quantity(0)), (1, 0, 0));
    run(&mut d, 0, 1, true, false);
    assert_eq!(d.sensor(BOTTOM), 0, "off the bottom switch at once");
    run(&mut d, 1, 4999, true, false);
    assert_eq!(d.quantity(0), 50);
    run(&mut d, 5000, 4999, true, false);
    assert_eq!((d.sensor(TOP), d.quantity(0)), (0, 99));
    let alarms = run(&mut d, 9999, 1, true, false);
    assert_eq!((d.sensor(TOP), d.quantity(0)), (1, 100), "10 s to open");
    assert!(alarms.is_empty(), "{alarms:?}");
    run(&mut d, 10_000, 2500, false, true);
    assert_eq!((d.sensor(TOP), d.quantity(0)), (0, 75));
    // Neither or both: it stays.
    run(&mut d, 12_500, 1000, false, false);
    run(&mut d, 13_500, 1000, true, true);
    assert_eq!(d.quantity(0), 75);
}

#[test]
fn driving_on_against_a_limit_is_an_alarm_after_the_grace() {
    let mut d = quiet();
    assert!(run(&mut d, 0, 200, false, true).is_empty(), "within grace");
    let alarms = run(&mut d, 200, 1000, false, true);
    assert_eq!(alarms.len(), 1, "{alarms:?}");
    assert!(alarms[0].contains("down against the bottom limit switch"));
    run(&mut d, 1200, 10_000, true, false);
    let alarms = run(&mut d, 11_200, 500, true, false);
    assert!(alarms[0].contains("up against the top"), "{alarms:?}");
}

#[test]
fn both_directions_at_once_is_an_alarm_at_once() {
    let mut d = quiet();
    d.set_param(START, 50);
    let alarms = run(&mut d, 0, 100, true, true);
    assert_eq!(alarms, ["the motor is driven up and down at once"]);
}

#[test]
fn the_remote_and_the_eye_follow_the_seeded_schedule() {
    let mut d = Door::new();
    let (press, block) = (d.next_press, d.next_block);
    assert!((30_000..=40_000).contains(&press), "{press}");
    assert!((45_000..=60_000).contains(&block), "{block}");
    run(&mut d, 0, press, false, false);
    assert_eq!(d.sensor(REMOTE), 1);
    run(&mut d, press, 300, false, false);
    assert_eq!(d.sensor(REMOTE), 0, "held for press = 300 ms");
    d.reset();
    assert_eq!((d.next_press, d.next_block), (press, block), "same seed");
    run(&mut d, 0, block, false, false);
    assert_eq!(d.sensor(EYE), 1);
    run(&mut d, block, 2000, false, false);
    assert_eq!(d.sensor(EYE), 0, "blocked for 2 s");
}

#[test]
fn closing_on_the_blocked_eye_is_an_alarm_after_the_grace() {
    let mut d = Door::new();
    d.set_param(START, 100);
    let block = d.next_block;
    run(&mut d, 0, block - 1, false, false);
    let alarms = run(&mut d, block - 1, 150, false, true);
    assert!(alarms.is_empty(), "within grace: {alarms:?}");
    let alarms = run(&mut d, block + 149, 100, false, true);
    assert_eq!(alarms.len(), 1, "{alarms:?}");
    assert!(alarms[0].contains("photo-eye is blocked"));
}
