//! The gate network against a step-at-a-time scan.

use super::*;
use proptest::prelude::*;

/// What a straightforward scan gives: the accumulator and the bus after
/// it, whether a store changed a timer or counter latch, and the first
/// value stored to each of those latches (at its bus bit).
struct Straightforward {
    acc: bool,
    bus: u32,
    device_acts: bool,
    first_stores: u32,
}

/// The scan run from the seed's definitions, one step at a time.
fn straightforward(
    memory: &[u8; STEPS],
    bus: u32,
    acc: bool,
    specials: Specials,
) -> Straightforward {
    let mut r = Straightforward {
        acc,
        bus,
        device_acts: false,
        first_stores: 0,
    };
    let mut stored = 0u32;
    for &byte in memory {
        let Instruction { opcode, address } = Instruction::decode(byte);
        let a = address.index();
        let read = (r.bus >> a & 1 != 0) ^ opcode.inverts();
        match opcode {
            Opcode::Ld | Opcode::Ldi => r.acc = read,
            Opcode::And | Opcode::Andi => r.acc &= read,
            Opcode::Or | Opcode::Ori => r.acc |= read,
            Opcode::St | Opcode::Sti => {
                let value = r.acc ^ opcode.inverts();
                match address.device() {
                    Device::Output(_) | Device::Relay(_) => {
                        r.bus = (r.bus & !(1 << a)) | u32::from(value) << a;
                    }
                    Device::Input(_) => {}
                    _ => {
                        r.device_acts |= value != (specials.latches >> a & 1 != 0);
                        if stored >> a & 1 == 0 {
                            stored |= 1 << a;
                            r.first_stores |= u32::from(value) << a;
                        }
                    }
                }
            }
        }
    }
    r
}

/// The bus as the machine builds it: the special bits are what the
/// timers and counter read, bit 31 (`C0R`) is 0.
fn bus_for(bus: u32, specials: Specials) -> u32 {
    (bus & !SPECIAL_BITS) | (specials.reads & 0x7000_0000)
}

/// Runs the network and the straightforward scan; returns whether the
/// network's scan stood.
fn agree(
    memory: &[u8; STEPS],
    bus: u32,
    acc: bool,
    specials: Specials,
) -> Result<bool, TestCaseError> {
    let bus = bus_for(bus, specials);
    let network = Network::compile(memory, specials);
    let got = network.run(&mut Slots::default(), bus, acc);
    let want = straightforward(memory, bus, acc, specials);
    if want.device_acts {
        prop_assert_eq!(got, None);
    } else {
        prop_assert_eq!(got, Some((want.acc, want.bus)));
    }
    Ok(got.is_some())
}

/// Steps biased toward what the compiler treats apart: reads of what was
/// just stored, the constants (T, C, C0R), long runs of AND/OR.
fn memory() -> impl Strategy<Value = [u8; STEPS]> {
    let address = prop_oneof![3 => 0u8..8, 3 => 8u8..12, 2 => 16u8..20, 2 => 28u8..32];
    let step = (0u8..8, address).prop_map(|(op, a)| op << 5 | a);
    prop::collection::vec(step, 1..=STEPS).prop_map(|steps| {
        let mut memory = [0u8; STEPS];
        memory[..steps.len()].copy_from_slice(&steps);
        memory
    })
}

fn specials() -> impl Strategy<Value = Specials> {
    (0u32..8, 0u32..16).prop_map(|(reads, latches)| Specials {
        reads: reads << 28,
        latches: latches << 28,
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 1000, ..ProptestConfig::default() })]

    #[test]
    fn a_network_scan_equals_the_straightforward_scan(
        memory in memory(),
        bus in any::<u32>(),
        acc in any::<bool>(),
        specials in specials(),
    ) {
        agree(&memory, bus, acc, specials)?;
    }

    /// Quiet devices (every special store writes what its latch holds)
    /// are the case the network is for, and random latches rarely give
    /// them: here the latches are set to what the scan first stores.
    #[test]
    fn quiet_scans_stand_and_equal_the_straightforward_scan(
        memory in memory(),
        bus in any::<u32>(),
        acc in any::<bool>(),
        specials in specials(),
    ) {
        let first = straightforward(&memory, bus_for(bus, specials), acc, specials);
        let quiet = Specials { latches: first.first_stores, ..specials };
        let stood = agree(&memory, bus, acc, quiet)?;
        let acts = straightforward(&memory, bus_for(bus, quiet), acc, quiet).device_acts;
        prop_assert_eq!(stood, !acts);
    }
}

#[test]
fn the_seed_program_repeated_makes_one_gate_per_copy_when_quiet() {
    let program =
        crate::minasec::Program::parse(include_str!("../../../../programs/minasec-u/bench-256.il"))
            .expect("the bench program parses");
    // Timers and counter quiet, T0/T1/C0 reading 0: per 13-step copy
    // only `LD X00 / OR Y00 / ANDI X01` is a gate; `ANDI T1` folds away.
    let quiet = Specials {
        reads: 0,
        latches: 0,
    };
    let network = Network::compile(program.bytes(), quiet);
    assert!(!network.refused);
    assert_eq!(network.gates.len(), 20);
    // Each copy's gate must stay what T0's coil holds (a check folded
    // into the gate), and X02 what C0R's latch holds (a check of its
    // own); `LD T0 / ST T1 / ST C0` store the constant 0, which matches
    // their latches: no check.
    assert!(network.gates.iter().all(|g| g.refuse == g.table));
    // Each copy's gate reads Y00, which the previous copy's gate (the
    // gate just before it) stored: read from the register.
    for (n, g) in network.gates.iter().enumerate().skip(1) {
        let previous = FIRST_GATE + n as u8 - 1;
        assert!(!g.inputs.contains(&previous));
        assert_ne!(g.table & 0x5555_5555, g.table >> 1 & 0x5555_5555);
    }
    assert_eq!(network.checks.len(), 1);
    // With T0 reading 1 but T1's coil off, `LD T0 / ST T1` turns the
    // coil on in every scan: refused without running.
    let t1_starts = Specials {
        reads: 1 << 28,
        latches: 0,
    };
    assert!(Network::compile(program.bytes(), t1_starts).refused);
}

#[test]
fn the_most_gates_a_program_can_make_fit() {
    // `AND Xn / ST Yn` over and over: a gate every two steps, each
    // reading the one before.
    let mut memory = [0u8; STEPS];
    for (n, pair) in memory.chunks_exact_mut(2).enumerate() {
        pair[0] = 0b010 << 5 | (n % 8) as u8;
        pair[1] = 0b110 << 5 | (8 + n % 20) as u8;
    }
    let quiet = Specials {
        reads: 0,
        latches: 0,
    };
    let network = Network::compile(&memory, quiet);
    assert_eq!(network.gates.len(), STEPS / 2);
    assert!(!network.refused);
    for bus in [0, 0xFF, 0x5A, 0x0FFF_FFFF] {
        for acc in [false, true] {
            agree(&memory, bus, acc, quiet).expect("agrees");
        }
    }
}
