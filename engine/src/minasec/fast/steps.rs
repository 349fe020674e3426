//! The exact step kernel: program memory decoded once into micro-steps, and
//! a whole scan run over a 32-bit image of the read bus.
//!
//! Bit `a` of the bus word is what reading address `a` gives. Inside one
//! scan only stores change it, so loads are a shift and a mask. Stores to
//! the timers and the counter are rare and go out of line; they keep the
//! board's semantics by calling the same [`RcTimer`] and [`BcdCounter`] the
//! exact path uses. The machine only takes this path for a scan in which no
//! timer output can change by itself (see `Machine::fast_scan_fits`).

use crate::minasec::asm::STEPS;
use crate::minasec::counter::BcdCounter;
use crate::minasec::isa::{Device, Instruction, Opcode};
use crate::minasec::timer::RcTimer;
use crate::time::SimTime;

/// The number of [`Kind`]s.
const KINDS: u8 = 6;

/// What a micro-step does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
enum Kind {
    /// `LD`/`LDI`: acc = bus bit ^ inv.
    Load,
    /// `AND`/`ANDI`.
    And,
    /// `OR`/`ORI`.
    Or,
    /// `ST`/`STI` to a Y or M latch: a bus bit.
    StoreLatch,
    /// `ST`/`STI` to an input: no effect.
    StoreNowhere,
    /// `ST`/`STI` to `T0`/`T1`, `C0` or `C0R`.
    StoreSpecial,
}

/// One decoded step. Fields are words, not bytes: the kernel reads them
/// with plain aligned loads instead of unpacking bytes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Micro {
    kind: Kind,
    bit: u32,
    inv: u32,
}

impl Micro {
    fn decode(byte: u8) -> Micro {
        let Instruction { opcode, address } = Instruction::decode(byte);
        let kind = match opcode {
            Opcode::Ld | Opcode::Ldi => Kind::Load,
            Opcode::And | Opcode::Andi => Kind::And,
            Opcode::Or | Opcode::Ori => Kind::Or,
            Opcode::St | Opcode::Sti => match address.device() {
                Device::Output(_) | Device::Relay(_) => Kind::StoreLatch,
                Device::Input(_) => Kind::StoreNowhere,
                Device::Timer(_) | Device::Counter | Device::CounterClear => Kind::StoreSpecial,
            },
        };
        Micro {
            kind,
            bit: u32::from(address.index()),
            inv: u32::from(opcode.inverts()),
        }
    }
}

/// Program memory decoded into pairs of micro-steps. Dispatching once per
/// pair halves the branches per step, which is what bounds an interpreter
/// whose steps are one or two ALU operations.
#[derive(Clone, Debug)]
pub(super) struct DecodedProgram {
    pairs: Box<[Pair; STEPS / 2]>,
}

/// Two consecutive steps and the code of their kinds (`6·first + second`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Pair {
    code: u32,
    first: Micro,
    second: Micro,
}

impl DecodedProgram {
    pub(super) fn decode(memory: &[u8; STEPS]) -> DecodedProgram {
        let erased = Micro::decode(0);
        let mut pairs = Box::new(
            [Pair {
                code: 0,
                first: erased,
                second: erased,
            }; STEPS / 2],
        );
        for (pair, bytes) in pairs.iter_mut().zip(memory.chunks_exact(2)) {
            let (first, second) = (Micro::decode(bytes[0]), Micro::decode(bytes[1]));
            *pair = Pair {
                code: u32::from(first.kind as u8 * KINDS + second.kind as u8),
                first,
                second,
            };
        }
        DecodedProgram { pairs }
    }
}

/// The out-of-line devices a fast scan can store to, and when each step's
/// rising edge happens.
pub(in crate::minasec) struct ScanDevices<'a> {
    pub timers: &'a mut [RcTimer; 2],
    pub counter: &'a mut BcdCounter,
    /// The rising edge of step 0.
    pub first_rise: SimTime,
    pub period: SimTime,
}

impl ScanDevices<'_> {
    /// A store to `T0`, `T1`, `C0` or `C0R` at step `k`; returns the bus
    /// with that address's read bit brought up to date.
    #[cold]
    #[inline(never)]
    fn store(&mut self, k: usize, bit: u8, value: bool, bus: u32) -> u32 {
        let now =
            SimTime::from_nanos(self.first_rise.as_nanos() + k as u64 * self.period.as_nanos());
        let read = match bit {
            28 | 29 => {
                let timer = &mut self.timers[usize::from(bit - 28)];
                timer.set_coil(value, now);
                timer.output(now)
            }
            30 => {
                self.counter.set_up_latch(value);
                self.counter.matched()
            }
            _ => {
                self.counter.set_clear_latch(value);
                // C0 is the bit that a clear can change; C0R always reads 0.
                let matched = self.counter.matched();
                return (bus & !(1 << 30)) | (u32::from(matched) << 30);
            }
        };
        (bus & !(1 << bit)) | (u32::from(read) << bit)
    }
}

/// The special latches as a word at their bus positions: timer coils
/// (bits 28, 29), the count-up latch (30) and the clear latch (31).
pub(super) fn special_latches(timers: &[RcTimer; 2], counter: &BcdCounter) -> u32 {
    u32::from(timers[0].coil()) << 28
        | u32::from(timers[1].coil()) << 29
        | u32::from(counter.up_latch()) << 30
        | u32::from(counter.clear_latch()) << 31
}

/// The values a scan threads through its steps.
struct Regs {
    acc: u32,
    bus: u32,
    /// The special latches at their bus bits (see [`special_latches`]).
    special: u32,
}

/// Executes one micro-step of kind `KIND` (a [`Kind`] as `u8`) at step `k`.
/// Callers pass constant kinds, so each use compiles to its one arm.
#[inline(always)]
fn step<const KIND: u8>(m: Micro, k: usize, r: &mut Regs, devices: &mut ScanDevices<'_>) {
    let inv = m.inv;
    match KIND {
        0 => r.acc = ((r.bus >> m.bit) ^ inv) & 1,
        // acc holds only bit 0, so the AND needs no mask.
        1 => r.acc &= (r.bus >> m.bit) ^ inv,
        2 => r.acc |= ((r.bus >> m.bit) ^ inv) & 1,
        3 => {
            let mask = 1u32 << m.bit;
            r.bus = (r.bus & !mask) | ((r.acc ^ inv) << m.bit);
        }
        4 => {}
        _ => {
            // Programs write the same value to a timer or counter latch on
            // most scans; only a change needs the devices.
            let value = r.acc ^ inv;
            if (r.special >> m.bit) & 1 != value {
                r.special ^= 1 << m.bit;
                r.bus = devices.store(k, m.bit as u8, value != 0, r.bus);
            }
        }
    }
}

/// Runs all 256 steps from PC 0 over the bus word; returns the accumulator
/// and the bus after the last step.
pub(super) fn run_scan(
    program: &DecodedProgram,
    bus: u32,
    acc: bool,
    devices: &mut ScanDevices<'_>,
) -> (bool, u32) {
    let mut r = Regs {
        acc: u32::from(acc),
        bus,
        special: special_latches(devices.timers, devices.counter),
    };
    let d = devices;
    for (n, p) in program.pairs.iter().enumerate() {
        let (a, b, k) = (p.first, p.second, 2 * n);
        // One arm per (first kind, second kind); the kinds' numbers are
        // Load 0, And 1, Or 2, StoreLatch 3, StoreNowhere 4, StoreSpecial 5.
        #[rustfmt::skip]
        match p.code {
            0 => { step::<0>(a, k, &mut r, d); step::<0>(b, k + 1, &mut r, d) }
            1 => { step::<0>(a, k, &mut r, d); step::<1>(b, k + 1, &mut r, d) }
            2 => { step::<0>(a, k, &mut r, d); step::<2>(b, k + 1, &mut r, d) }
            3 => { step::<0>(a, k, &mut r, d); step::<3>(b, k + 1, &mut r, d) }
            4 => { step::<0>(a, k, &mut r, d); step::<4>(b, k + 1, &mut r, d) }
            5 => { step::<0>(a, k, &mut r, d); step::<5>(b, k + 1, &mut r, d) }
            6 => { step::<1>(a, k, &mut r, d); step::<0>(b, k + 1, &mut r, d) }
            7 => { step::<1>(a, k, &mut r, d); step::<1>(b, k + 1, &mut r, d) }
            8 => { step::<1>(a, k, &mut r, d); step::<2>(b, k + 1, &mut r, d) }
            9 => { step::<1>(a, k, &mut r, d); step::<3>(b, k + 1, &mut r, d) }
            10 => { step::<1>(a, k, &mut r, d); step::<4>(b, k + 1, &mut r, d) }
            11 => { step::<1>(a, k, &mut r, d); step::<5>(b, k + 1, &mut r, d) }
            12 => { step::<2>(a, k, &mut r, d); step::<0>(b, k + 1, &mut r, d) }
            13 => { step::<2>(a, k, &mut r, d); step::<1>(b, k + 1, &mut r, d) }
            14 => { step::<2>(a, k, &mut r, d); step::<2>(b, k + 1, &mut r, d) }
            15 => { step::<2>(a, k, &mut r, d); step::<3>(b, k + 1, &mut r, d) }
            16 => { step::<2>(a, k, &mut r, d); step::<4>(b, k + 1, &mut r, d) }
            17 => { step::<2>(a, k, &mut r, d); step::<5>(b, k + 1, &mut r, d) }
            18 => { step::<3>(a, k, &mut r, d); step::<0>(b, k + 1, &mut r, d) }
            19 => { step::<3>(a, k, &mut r, d); step::<1>(b, k + 1, &mut r, d) }
            20 => { step::<3>(a, k, &mut r, d); step::<2>(b, k + 1, &mut r, d) }
            21 => { step::<3>(a, k, &mut r, d); step::<3>(b, k + 1, &mut r, d) }
            22 => { step::<3>(a, k, &mut r, d); step::<4>(b, k + 1, &mut r, d) }
            23 => { step::<3>(a, k, &mut r, d); step::<5>(b, k + 1, &mut r, d) }
            24 => { step::<4>(a, k, &mut r, d); step::<0>(b, k + 1, &mut r, d) }
            25 => { step::<4>(a, k, &mut r, d); step::<1>(b, k + 1, &mut r, d) }
            26 => { step::<4>(a, k, &mut r, d); step::<2>(b, k + 1, &mut r, d) }
            27 => { step::<4>(a, k, &mut r, d); step::<3>(b, k + 1, &mut r, d) }
            28 => { step::<4>(a, k, &mut r, d); step::<4>(b, k + 1, &mut r, d) }
            29 => { step::<4>(a, k, &mut r, d); step::<5>(b, k + 1, &mut r, d) }
            30 => { step::<5>(a, k, &mut r, d); step::<0>(b, k + 1, &mut r, d) }
            31 => { step::<5>(a, k, &mut r, d); step::<1>(b, k + 1, &mut r, d) }
            32 => { step::<5>(a, k, &mut r, d); step::<2>(b, k + 1, &mut r, d) }
            33 => { step::<5>(a, k, &mut r, d); step::<3>(b, k + 1, &mut r, d) }
            34 => { step::<5>(a, k, &mut r, d); step::<4>(b, k + 1, &mut r, d) }
            _ => { step::<5>(a, k, &mut r, d); step::<5>(b, k + 1, &mut r, d) }
        };
    }
    (r.acc != 0, r.bus)
}
