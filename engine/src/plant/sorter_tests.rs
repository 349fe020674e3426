use super::*;

/// Runs `s` from `from` for `ms` steps with the belt and the pusher's
/// valve as given; the alarms raised.
fn run(s: &mut Sorter, from: i64, ms: i64, belt: bool, push: bool) -> Vec<String> {
    let drive = [0, 0, 0, 0, i64::from(belt), i64::from(push)];
    let mut alarms = Vec::new();
    for now in from + 1..=from + ms {
        s.step(now, &drive, &mut alarms);
    }
    alarms
}

/// A sorter whose parts all have the given height, one part at a time.
fn sorter(tall: bool) -> Sorter {
    let mut s = Sorter::new();
    s.set_param(TALL_PCT, if tall { 100 } else { 0 });
    s.set_param(INTERVAL, 3_600_000);
    s.set_param(SPREAD, 0);
    s.set_param(SEED, 1);
    s
}

#[test]
fn a_part_arrives_passes_the_height_sensor_and_reaches_the_pusher() {
    let mut s = sorter(true);
    run(&mut s, 0, 1, false, false);
    assert_eq!(s.quantity(2), 1, "the first part at once (spread 0)");
    // Lead at 50 mm; 100 mm/s: lead at 400 mm after 3.5 s.
    run(&mut s, 1, 3500, true, false);
    assert_eq!(s.sensor(TALL), 0);
    run(&mut s, 3501, 1, true, false);
    assert_eq!(s.sensor(TALL), 1);
    // Fully in front once the tail passes 500 mm: lead 550 mm, 5 s in.
    run(&mut s, 3502, 1498, true, false);
    assert_eq!((s.sensor(TALL), s.sensor(PART)), (0, 0));
    run(&mut s, 5000, 1, true, false);
    assert_eq!(s.sensor(PART), 1);
    // ... until its lead passes the face's end at 580 mm, 300 ms on.
    run(&mut s, 5001, 300, true, false);
    assert_eq!(s.sensor(PART), 1);
    run(&mut s, 5301, 1, true, false);
    assert_eq!(s.sensor(PART), 0);
}

#[test]
fn a_tall_part_pushed_from_in_front_lands_right_and_the_end_switches_follow() {
    let mut s = sorter(true);
    run(&mut s, 0, 5101, true, false);
    assert_eq!((s.sensor(PART), s.sensor(PUSHER_IN)), (1, 1));
    let alarms = run(&mut s, 5101, 499, true, true);
    assert!(alarms.is_empty(), "{alarms:?}");
    assert_eq!((s.sensor(PUSHER_IN), s.sensor(PUSHER_OUT)), (0, 0));
    assert_eq!(s.sensor(PART), 1, "held by the face, not riding on");
    run(&mut s, 5600, 1, true, true);
    assert_eq!((s.sensor(PUSHER_OUT), s.sensor(PART)), (1, 0));
    assert_eq!((s.quantity(0), s.quantity(1), s.quantity(2)), (1, 0, 0));
    run(&mut s, 5601, 500, true, false);
    assert_eq!(s.sensor(PUSHER_IN), 1);
}

#[test]
fn parts_at_the_end_of_the_belt_are_right_when_short_and_wrong_when_tall() {
    for (tall, right, wrong) in [(false, 1, 0), (true, 0, 1)] {
        let mut s = sorter(tall);
        // Tail past 1000 mm: lead 1050 mm, 10 s from 50 mm.
        run(&mut s, 0, 10_000, true, false);
        assert_eq!(s.quantity(2), 1);
        run(&mut s, 10_000, 1, true, false);
        assert_eq!(
            (s.quantity(0), s.quantity(1), s.quantity(2)),
            (right, wrong, 0)
        );
    }
}

#[test]
fn pushing_a_part_not_fully_in_front_is_a_hit_alarm_and_the_part_is_lost() {
    let mut s = sorter(false);
    // Lead at 520 mm: partly in front.
    run(&mut s, 0, 4701, true, false);
    let alarms = run(&mut s, 4701, 10, true, true);
    assert_eq!(alarms.len(), 1, "{alarms:?}");
    assert!(alarms[0].contains("hit a short part mid-stroke"));
    assert_eq!((s.quantity(1), s.quantity(2)), (1, 0));
}

#[test]
fn a_part_running_into_the_pusher_left_out_is_a_hit() {
    let mut s = sorter(true);
    run(&mut s, 0, 600, true, true);
    assert_eq!(s.sensor(PUSHER_OUT), 1);
    let alarms = run(&mut s, 600, 5000, true, true);
    assert_eq!(alarms.len(), 1, "{alarms:?}");
    assert_eq!((s.quantity(0), s.quantity(1)), (0, 1));
}

#[test]
fn heights_follow_the_seed_and_the_share_of_tall_parts() {
    let mut s = Sorter::new();
    s.set_param(INTERVAL, 100);
    s.set_param(SPREAD, 0);
    s.set_param(SPEED, 10_000);
    s.reset();
    run(&mut s, 0, 100_000, true, false);
    let (right, wrong) = (s.quantity(0), s.quantity(1));
    assert!(right + wrong > 900, "{right} + {wrong}");
    assert!(
        (right - wrong).abs() < (right + wrong) / 5,
        "about half tall"
    );
    s.reset();
    run(&mut s, 0, 100_000, true, false);
    assert_eq!((s.quantity(0), s.quantity(1)), (right, wrong), "same seed");
}

#[test]
fn parameters_that_do_not_fit_together_are_refused() {
    let mut s = Sorter::new();
    s.set_param(SIZE, 100);
    let e = s.check().unwrap_err();
    assert!(matches!(e, Misfit::PartOverFace { part: 100, .. }), "{e:?}");
    assert!(
        e.to_string().contains("longer than the pusher's face"),
        "{e}"
    );
    s.set_param(SIZE, 50);
    s.set_param(PUSHER_AT, 990);
    let e = s.check().unwrap_err();
    assert!(matches!(e, Misfit::BeltTooShort { from: 990, .. }), "{e:?}");
    assert!(e.to_string().contains("too short"), "{e}");
}
