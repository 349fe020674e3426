//! The seed book's test program, run as the book describes (動作確認).

use engine::minasec::Machine;
use engine::SimTime;

use super::harness::{input, lamp, seed_machine};

/// Runs in 1 ms steps until `until`, returning the times at which the
/// count shown on the digits changed, with the new count.
fn count_changes(m: &mut Machine, until: SimTime) -> Vec<(SimTime, u8)> {
    let mut changes = Vec::new();
    let mut last = m.counter().count();
    while m.now() < until {
        m.tick(SimTime::from_millis(1));
        let count = m.counter().count();
        if count != last {
            changes.push((m.now(), count));
            last = count;
        }
    }
    changes
}

#[test]
fn start_counts_every_2_1_s_to_10_then_lights_y01() {
    let mut m = seed_machine();
    m.run_until(SimTime::from_millis(100));
    input(&mut m, 0, true); // press start
    m.run_until(SimTime::from_millis(300));
    input(&mut m, 0, false);
    assert!(lamp(&m, 0), "the running lamp Y00 holds itself on");
    assert!(!lamp(&m, 1));

    let changes = count_changes(&mut m, SimTime::from_secs(30));
    let counts: Vec<u8> = changes.iter().map(|c| c.1).collect();
    assert_eq!(
        counts,
        (1..=10).collect::<Vec<u8>>(),
        "counts 1..10, then stops"
    );

    // The first count comes T0's delay after start; then one per flicker
    // period: T0 (1.1 s) + T1 (1 s) + about a scan to restart T0.
    let first = changes[0].0.as_secs_f64() - 0.1;
    assert!((1.1..1.13).contains(&first), "first count after {first} s");
    for pair in changes.windows(2) {
        let gap = (pair[1].0 - pair[0].0).as_secs_f64();
        assert!((2.1..2.13).contains(&gap), "counts {gap} s apart");
    }
    assert!(lamp(&m, 1), "Y01 lights at the match");
    assert!(lamp(&m, 0), "still running");
}

#[test]
fn stop_keeps_the_count_and_x02_clears_it() {
    let mut m = seed_machine();
    input(&mut m, 0, true);
    m.run_until(SimTime::from_millis(100));
    input(&mut m, 0, false);
    m.run_until(SimTime::from_millis(5_500)); // counts at ~1.1, 3.2, 5.3 s
    assert_eq!(m.counter().count(), 3);

    input(&mut m, 1, true); // stop
    m.run_until(SimTime::from_millis(5_600));
    input(&mut m, 1, false);
    m.run_until(SimTime::from_secs(12));
    assert!(!lamp(&m, 0), "stop drops Y00");
    assert_eq!(m.counter().count(), 3, "stop keeps the count");

    input(&mut m, 2, true); // clear
    m.run_until(SimTime::from_millis(12_100));
    assert_eq!(m.counter().count(), 0);
    input(&mut m, 2, false);
    m.run_until(SimTime::from_secs(15));
    assert_eq!(m.counter().count(), 0, "no counting while stopped");
}

#[test]
fn clear_while_running_restarts_the_count() {
    let mut m = seed_machine();
    input(&mut m, 0, true);
    m.run_until(SimTime::from_secs(25));
    assert_eq!(m.counter().count(), 10);
    assert!(lamp(&m, 1));
    input(&mut m, 2, true);
    m.run_until(SimTime::from_millis(25_050));
    assert_eq!(m.counter().count(), 0);
    assert!(!lamp(&m, 1), "no match after clear");
    input(&mut m, 2, false);
    m.run_until(SimTime::from_secs(30));
    assert!(
        m.counter().count() >= 2,
        "counting again: {}",
        m.counter().count()
    );
}
