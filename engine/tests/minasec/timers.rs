//! The RC on-delay timers: delay at clock resolution, immediate off, the
//! potentiometers' ranges.

use engine::minasec::control::SLOW_PERIOD;
use engine::minasec::{ClockSpeed, Command, SettingError, TimerId};
use engine::SimTime;

use super::harness::{addr, apply, input, lamp, rise, running, SCAN};

const DELAY: &str = "LD X00\nST T0\nLD T0\nST Y00\n";

fn machine(t0: SimTime) -> engine::minasec::Machine {
    let mut m = running(DELAY);
    apply(&mut m, Command::SetDelay(TimerId::T0, t0));
    input(&mut m, 0, true);
    m
}

#[test]
fn the_delay_runs_from_the_st_clock_to_the_nanosecond() {
    let mut m = machine(SimTime::from_millis(100));
    // X00 is latched at the end of scan 0; scan 1 step 1 sets the coil.
    let t_on = rise(1, 1);
    let expiry = t_on + SimTime::from_millis(100);
    m.run_until(SimTime::from_nanos(expiry.as_nanos() - 1));
    assert!(!m.read(addr("T0")));
    m.run_until(expiry);
    assert!(m.read(addr("T0")), "on exactly one delay after the ST");
}

#[test]
fn the_program_sees_the_timer_at_its_next_read_step() {
    for fast in [true, false] {
        let mut m = machine(SimTime::from_millis(100));
        m.set_fast_path(fast);
        let expiry = rise(1, 1) + SimTime::from_millis(100);
        // The first scan whose step 2 (LD T0) comes at or after expiry.
        let s = (0..).find(|&s| rise(s, 2) >= expiry).unwrap();
        let boundary = SimTime::from_nanos((s + 1) * SCAN.as_nanos());
        m.run_until(SimTime::from_nanos(boundary.as_nanos() - 1));
        assert!(!lamp(&m, 0), "fast={fast}: not before the scan ends");
        m.run_until(boundary);
        assert!(lamp(&m, 0), "fast={fast}: Y00 at the end of scan {s}");
    }
}

#[test]
fn off_is_immediate() {
    let mut m = machine(SimTime::from_millis(100));
    m.run_until(SimTime::from_millis(200));
    assert!(lamp(&m, 0));
    // Drop X00 mid-scan: the next scan's ST T0 writes 0 and its LD T0 reads
    // 0 at once, so Y00 falls at the end of that very scan.
    let change = SimTime::from_nanos(24 * SCAN.as_nanos() + 5_000);
    m.run_until(change);
    input(&mut m, 0, false);
    m.run_until(SimTime::from_nanos(26 * SCAN.as_nanos() - 1));
    assert!(lamp(&m, 0), "the change is latched at the end of scan 24");
    m.run_until(SimTime::from_nanos(26 * SCAN.as_nanos()));
    assert!(!lamp(&m, 0), "off at the end of scan 25, no delay");
}

#[test]
fn the_timer_runs_in_time_even_with_the_slow_clock() {
    let mut m = machine(SimTime::from_millis(1100));
    apply(&mut m, Command::SetClock(ClockSpeed::Slow));
    // At ≈ 1.08 s a clock, the delay is shorter than two clocks.
    m.run_until(SimTime::from_nanos(
        SLOW_PERIOD.as_nanos() * 256 + SLOW_PERIOD.as_nanos() * 3,
    ));
    assert!(m.read(addr("T0")));
}

#[test]
fn potentiometer_ranges_are_enforced() {
    let mut m = running(DELAY);
    let ok = [
        (TimerId::T0, SimTime::from_millis(100)),
        (TimerId::T0, SimTime::from_millis(1100)),
        (TimerId::T1, SimTime::from_secs(1)),
        (TimerId::T1, SimTime::from_secs(11)),
    ];
    for (id, delay) in ok {
        assert_eq!(m.apply(Command::SetDelay(id, delay)), Ok(()));
        assert_eq!(m.timer(id).delay(), delay);
    }
    let bad = [
        (TimerId::T0, SimTime::from_nanos(99_999_999)),
        (TimerId::T0, SimTime::from_nanos(1_100_000_001)),
        (TimerId::T1, SimTime::from_millis(999)),
        (TimerId::T1, SimTime::from_millis(11_001)),
    ];
    for (id, delay) in bad {
        let before = m.timer(id).delay();
        assert_eq!(
            m.apply(Command::SetDelay(id, delay)),
            Err(SettingError::DelayOutOfRange { timer: id, delay })
        );
        assert_eq!(
            m.timer(id).delay(),
            before,
            "a rejected setting changes nothing"
        );
    }
    assert!(m
        .apply_setting("T0", "1.2s")
        .unwrap_err()
        .to_string()
        .contains("out of range"));
    assert!(m
        .apply_setting("T1", "0.5s")
        .unwrap_err()
        .to_string()
        .contains("out of range"));
    assert!(m
        .apply_setting("T1", "soon")
        .unwrap_err()
        .to_string()
        .contains("bad time"));
    assert_eq!(m.apply_setting("T1", "11s"), Ok(()));
}
