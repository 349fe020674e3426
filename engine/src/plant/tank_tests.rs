use super::*;

fn run(t: &mut Tank, ms: i64, fill: bool, drain: bool) -> Vec<String> {
    let mut alarms = Vec::new();
    let drive = [0, 0, 0, i64::from(fill), i64::from(drain)];
    for now in 1..=ms {
        t.step(now, &drive, &mut alarms);
    }
    alarms
}

#[test]
fn the_level_moves_by_inflow_less_demand_and_the_switches_follow_it() {
    let mut t = Tank::new();
    assert_eq!(t.quantity(0), 50);
    assert_eq!((t.sensor(LOW), t.sensor(HIGH)), (1, 0));
    // Fill 8 %/s less demand 2 %/s: +6 %/s, 5 s to 80 %.
    run(&mut t, 4999, true, false);
    assert_eq!(t.sensor(HIGH), 0);
    run(&mut t, 1, true, false);
    assert_eq!(t.sensor(HIGH), 1);
    assert_eq!(t.quantity(0), 80);
    assert_eq!(t.sensor(LEVEL), 80 * PER_PERCENT);
    // Drain 6 %/s plus demand 2 %/s: -8 %/s, 7.5 s to 20 %.
    run(&mut t, 7500, false, true);
    assert_eq!((t.quantity(0), t.sensor(LOW)), (20, 1));
    run(&mut t, 1, false, true);
    assert_eq!(t.sensor(LOW), 0);
    run(&mut t, 60_000, false, true);
    assert_eq!(t.quantity(0), 0, "never below empty");
}

#[test]
fn filling_a_full_tank_is_one_overflow_alarm_while_it_lasts() {
    let mut t = Tank::new();
    let alarms = run(&mut t, 20_000, true, false);
    assert_eq!(alarms.len(), 1, "{alarms:?}");
    assert!(alarms[0].contains("overflow"));
    assert_eq!(t.quantity(0), 100);
    assert!(t.quantity(1) > 10_000, "overflowed for most of the run");
    // Closed, then opened again: a second overflow.
    run(&mut t, 100, false, false);
    assert_eq!(run(&mut t, 100, true, false).len(), 1);
}

#[test]
fn parameters_set_the_start_and_the_switches_must_not_cross() {
    let mut t = Tank::new();
    t.set_param(START, 10);
    assert_eq!((t.quantity(0), t.sensor(LOW)), (10, 0));
    t.set_param(LOW_AT, 90);
    let e = t.check().unwrap_err();
    assert!(matches!(e, Misfit::LowAboveHigh { low: 90, .. }), "{e:?}");
    assert!(e.to_string().contains("above the high switch"), "{e}");
    t.set_param(LOW_AT, 20);
    run(&mut t, 1000, true, false);
    t.reset();
    assert_eq!((t.quantity(0), t.quantity(1)), (10, 0));
}
