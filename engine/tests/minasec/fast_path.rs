//! The fast path (whole scans, on the gate network or the step kernel) must
//! give exactly what the exact path (one clock edge at a time, straight from
//! the seed's truth table) gives: compared at every scan boundary over
//! random programs, inputs and panel settings.

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

/// How a machine runs its scans.
#[derive(Clone, Copy, Debug)]
enum Path {
    /// One clock edge at a time.
    Exact,
    /// Fast path, step kernel only.
    Steps,
    /// Fast path as shipped: the gate network, the step kernel when refused.
    Network,
}

fn machine(path: Path) -> Machine {
    let mut m = Machine::for_run();
    m.set_fast_path(!matches!(path, Path::Exact));
    m.set_gate_network(matches!(path, Path::Network));
    m
}

fn run(
    program: &Program,
    events: &[(u64, u64, u8, bool)],
    presets: (u8, u8, u64),
    path: Path,
) -> Vec<String> {
    let mut m = machine(path);
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
        let exact = run(&program, &events, (tens, ones, t0_ms), Path::Exact);
        for path in [Path::Steps, Path::Network] {
            let fast = run(&program, &events, (tens, ones, t0_ms), path);
            for (e, f) in exact.iter().zip(&fast) {
                prop_assert_eq!(e, f, "{:?}", path);
            }
        }
    }
}

#[test]
fn the_seed_program_agrees_over_a_whole_count() {
    let program = super::harness::program(engine::minasec::SEED_TEST_PROGRAM);
    let mut machines = [Path::Network, Path::Steps, Path::Exact].map(machine);
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
        for fast in &machines[..2] {
            assert_eq!(fast.last_scan(), machines[2].last_scan(), "scan {scan}");
        }
    }
    assert_eq!(machines[0].counter().count(), 10);
}

/// A program whose counter latch toggles on every scan (so the network is
/// refused every scan and backs off) and one whose timer coil follows an
/// input: both agree with the exact path scan by scan.
#[test]
fn devices_acting_every_scan_or_now_and_then_agree() {
    let programs = [
        // C0's latch takes the opposite of what it holds: a count every
        // other scan; X00 clears.
        "LDI Y00\nST Y00\nST C0\nLD X00\nST C0R\nLD C0\nST Y01\n",
        // T0 follows X00; its output drives Y00 and counts.
        "LD X00\nST T0\nLD T0\nST Y00\nST C0\n",
    ];
    for text in programs {
        let program = super::harness::program(text);
        let mut machines = [Path::Network, Path::Exact].map(machine);
        for m in &mut machines {
            m.load(&program);
            m.apply(Command::SetCounterPreset(2, 5)).unwrap();
            m.apply(Command::SetDelay(TimerId::T0, SimTime::from_millis(200)))
                .unwrap();
        }
        let mut counts = std::collections::BTreeSet::new();
        for scan in 1..=600u64 {
            let end = SimTime::from_nanos(scan * SCAN.as_nanos());
            for m in &mut machines {
                // X00 on for 40 scans (338 ms), off for 40.
                let on = (scan / 40) % 2 == 1;
                m.apply(Command::SetInput(0, on)).unwrap();
                m.run_until(end);
            }
            assert_eq!(
                machines[0].last_scan(),
                machines[1].last_scan(),
                "{text:?} scan {scan}"
            );
            counts.insert(machines[0].last_scan().count);
        }
        // The devices really acted: the counter went through many values.
        assert!(counts.len() > 5, "{text:?}: counts {counts:?}");
    }
}
