//! The fast path (decoded, whole scans) must give exactly what the exact
//! path (one clock edge at a time, straight from the seed's truth table)
//! gives: compared at every scan boundary over random programs, inputs and
//! panel settings.

use engine::minasec::{Command, Machine, Program, TimerId};
use engine::SimTime;
use proptest::prelude::*;

use super::harness::SCAN;

/// A random program biased toward the devices with behaviour: timers,
/// counter, clear, and reads of what was just stored.
fn program_bytes() -> impl Strategy<Value = Vec<u8>> {
    let address = prop_oneof![
        3 => 0u8..8,   // X
        3 => 8u8..16,  // Y
        2 => 16u8..28, // M
        2 => 28u8..30, // T0, T1
        2 => 30u8..32, // C0, C0R
    ];
    let step = (0u8..8, address).prop_map(|(op, a)| op << 5 | a);
    prop::collection::vec(step, 1..=256)
}

/// Input changes: (scan number, clock within the scan, input, level).
fn timeline() -> impl Strategy<Value = Vec<(u64, u64, u8, bool)>> {
    prop::collection::vec((0u64..120, 0u64..256, 0u8..8, any::<bool>()), 0..30)
}

fn run(
    program: &Program,
    events: &[(u64, u64, u8, bool)],
    presets: (u8, u8, u64),
    fast: bool,
) -> Vec<String> {
    let mut m = Machine::for_run();
    m.set_fast_path(fast);
    m.load(program);
    let (tens, ones, t0_ms) = presets;
    m.apply(Command::SetCounterPreset(tens, ones)).unwrap();
    m.apply(Command::SetDelay(TimerId::T0, SimTime::from_millis(t0_ms)))
        .unwrap();
    let mut events = events.to_vec();
    events.sort();
    let mut trace = Vec::new();
    let mut pending = events.iter().peekable();
    for scan in 1..=130u64 {
        let end = SimTime::from_nanos(scan * SCAN.as_nanos());
        while let Some(&&(s, clock, n, on)) = pending.peek() {
            let at = SimTime::from_nanos(s * SCAN.as_nanos() + clock * 33_000 + 7);
            if at > end {
                break;
            }
            m.run_until(at);
            m.apply(Command::SetInput(n, on)).unwrap();
            pending.next();
        }
        m.run_until(end);
        let snap = m.last_scan();
        trace.push(format!(
            "scan {scan}: bus {:08x} count {} acc {} t {:?} clocks {}",
            snap.bus,
            snap.count,
            m.acc(),
            snap.timer_elapsed,
            m.clocks()
        ));
    }
    trace
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    #[test]
    fn fast_and_exact_paths_agree_at_every_scan(
        bytes in program_bytes(),
        events in timeline(),
        tens in 0u8..3,
        ones in 0u8..10,
        t0_ms in 100u64..=300,
    ) {
        let mut steps = [0u8; 256];
        steps[..bytes.len()].copy_from_slice(&bytes);
        let program = Program::from_bytes(steps);
        let exact = run(&program, &events, (tens, ones, t0_ms), false);
        let fast = run(&program, &events, (tens, ones, t0_ms), true);
        for (e, f) in exact.iter().zip(&fast) {
            prop_assert_eq!(e, f);
        }
    }
}

#[test]
fn the_seed_program_agrees_over_a_whole_count() {
    let program = super::harness::program(engine::minasec::SEED_TEST_PROGRAM);
    let mut machines = [Machine::for_run(), Machine::for_run()];
    machines[1].set_fast_path(false);
    for m in &mut machines {
        m.load(&program);
        m.apply(Command::SetDelay(TimerId::T0, SimTime::from_millis(1100)))
            .unwrap();
        m.apply(Command::SetCounterPreset(1, 0)).unwrap();
        m.apply(Command::SetInput(0, true)).unwrap();
    }
    for scan in 1..=2_600u64 {
        let end = SimTime::from_nanos(scan * SCAN.as_nanos());
        for m in &mut machines {
            m.run_until(end);
        }
        assert_eq!(
            machines[0].last_scan(),
            machines[1].last_scan(),
            "scan {scan}"
        );
    }
    assert_eq!(machines[0].counter().count(), 10);
}
