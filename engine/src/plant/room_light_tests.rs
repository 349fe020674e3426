use super::*;

fn run(r: &mut RoomLight, ms: i64, lamp: bool) {
    let mut alarms = Vec::new();
    for now in 1..=ms {
        r.step(now, &[0, 0, i64::from(lamp)], &mut alarms);
    }
    assert!(alarms.is_empty(), "the room raises no alarm: {alarms:?}");
}

#[test]
fn daylight_follows_the_table_with_straight_lines_between_the_hours() {
    let mut r = RoomLight::new();
    // A 60 s day: an hour is 2.5 s.
    assert_eq!((r.quantity(3), r.sensor(LIGHT), r.sensor(DARK)), (0, 0, 1));
    run(&mut r, 6 * 2500, false);
    assert_eq!((r.quantity(3), r.quantity(2)), (6, 20));
    // Half past six: halfway from 20 % to 40 %.
    run(&mut r, 1250, false);
    assert_eq!(r.sensor(LIGHT), 30 * PER_PERCENT);
    assert_eq!(r.sensor(DARK), 0, "30 % is not below dark_below = 30");
    run(&mut r, 1, false);
    assert_eq!(r.sensor(LIGHT), 30 * PER_PERCENT + 8, "rises every ms");
    run(&mut r, 5 * 2500 + 1249, false);
    assert_eq!((r.quantity(3), r.quantity(2)), (12, 100));
    assert_eq!(r.sensor(LIGHT), ANALOG_FULL);
    // Midnight again after a whole day.
    run(&mut r, 12 * 2500, false);
    assert_eq!((r.quantity(3), r.sensor(LIGHT)), (0, 0));
}

#[test]
fn the_lamp_on_while_light_is_wasted_and_off_while_dark_is_unlit() {
    let mut r = RoomLight::new();
    // Dark below 30 %: before 6.5 h and after 17.5 h, 16 250 ms each of
    // the 60 s day; light from 6.5 h to 17.5 h, both ends included.
    run(&mut r, 60_000, true);
    assert_eq!((r.quantity(0), r.quantity(1)), (27_501, 0));
    r.reset();
    run(&mut r, 60_000, false);
    assert_eq!((r.quantity(0), r.quantity(1)), (0, 32_499));
}

#[test]
fn the_start_hour_and_the_threshold_are_parameters() {
    let mut r = RoomLight::new();
    r.set_param(START, 12);
    assert_eq!((r.quantity(3), r.sensor(DARK)), (12, 0));
    r.set_param(DARK_BELOW, 100);
    assert_eq!(r.sensor(DARK), 0, "noon is 100 %");
    run(&mut r, 1, false);
    assert_eq!(r.sensor(DARK), 1);
    r.set_param(DAY, 86_400_000);
    assert_eq!((r.quantity(3), r.quantity(2)), (12, 100));
    run(&mut r, 3_600_000, false);
    assert_eq!((r.quantity(3), r.quantity(2)), (13, 95));
    r.reset();
    assert_eq!((r.quantity(0), r.quantity(1), r.quantity(3)), (0, 0, 12));
}
