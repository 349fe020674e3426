//! The speculative kernel: a whole scan compiled to a network of lookup-table
//! gates.
//!
//! Inside a scan in which no timer or counter latch changes, every read of
//! `T0`, `T1` and `C0` gives the same value from the first step to the last
//! (the machine only runs a fast scan when no timer output can change by
//! itself), and `C0R` always reads 0. The scan is then a pure boolean
//! function of the input image, the Y and M latches and the accumulator,
//! and it can be compiled like a logic circuit, once for each state of the
//! timer and counter bits ([`Specials`]):
//!
//! - every value the scan computes gets a *slot* (one byte, 0 or 1): slots
//!   0..=30 are the bus bits at the start of the scan, slot 31 is the
//!   constant 0, slot 32 the accumulator carried in, and each gate adds one;
//! - reads of `T0`, `T1`, `C0` and `C0R` are constants, folded away;
//! - a run of `LD`/`AND`/`OR` steps becomes one gate of up to four inputs
//!   with a truth table; a longer run chains gates. A gate reads the gate
//!   just before it from a register, not from its slot, so a chain of gates
//!   (an accumulator carried from rung to rung) waits on no memory;
//! - `ST` to a Y or M latch costs nothing: later reads of that latch are
//!   wired to the stored value's slot (single assignment), and only the
//!   latch's last value is written back at the end of the scan;
//! - `ST` to `T0`, `T1`, `C0` or `C0R` becomes a *check*: the stored value
//!   must equal the latch as it is, or a device would act inside the scan.
//!   A check that fails, at compile time or at run time, refuses the scan;
//!   nothing has been written then, and the caller runs the exact step
//!   kernel instead.
//!
//! Running a network is one loop over its gates and one over its checks,
//! with no branch per step; docs/performance.md has the figures.

use crate::minasec::asm::STEPS;
use crate::minasec::isa::{Device, Instruction, Opcode};

/// Slot of the constant 0; also `C0R`'s bus bit.
const ZERO: u8 = 31;
/// Slot of the accumulator as the scan starts.
const ACC_IN: u8 = 32;
/// Slot of the first gate's output.
const FIRST_GATE: u8 = 33;
/// Slots are numbered by a byte, so indexing the slot array needs no bounds
/// check. A program of 256 steps makes at most 129 gates (a gate needs a
/// combining step and the store or the fifth input that settles it), so
/// they always fit; [`Network::compile`] still refuses a program that would
/// not.
const SLOTS: usize = 256;
const MAX_GATES: usize = SLOTS - FIRST_GATE as usize;

/// The truth-table column of gate input `n`: bit `i` of the table is the
/// gate's output when the inputs read `i` (input `n` is bit `n` of `i`).
const INPUT_COLUMN: [u16; 4] = [0xAAAA, 0xCCCC, 0xF0F0, 0xFF00];

/// Bus bits of the timer and counter: `T0`, `T1`, `C0`, `C0R`.
const SPECIAL_BITS: u32 = 0xF000_0000;

/// The timer and counter state a network is compiled for: what `T0`, `T1`
/// and `C0` read (bus bits 28..=30; `C0R` reads 0) and the four latches
/// their stores write (timer coils, count-up latch, clear latch: bits
/// 28..=31).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Specials {
    /// The bus word's special bits.
    pub reads: u32,
    /// The latches at their bus bits.
    pub latches: u32,
}

impl Specials {
    /// The number of different [`Specials::key`]s.
    pub(super) const KEYS: usize = 128;

    /// A dense number for the state: 3 read bits and 4 latch bits.
    pub(super) fn key(self) -> usize {
        (((self.reads & 0x7000_0000) >> 28) | ((self.latches & SPECIAL_BITS) >> 25)) as usize
    }
}

/// A computed value: a slot, possibly read inverted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Wire {
    slot: u8,
    inverted: bool,
}

impl Wire {
    const fn slot(slot: u8) -> Wire {
        Wire {
            slot,
            inverted: false,
        }
    }

    const fn constant(value: bool) -> Wire {
        Wire {
            slot: ZERO,
            inverted: value,
        }
    }

    const fn inverted_if(self, invert: bool) -> Wire {
        Wire {
            slot: self.slot,
            inverted: self.inverted ^ invert,
        }
    }

    /// The value, if the wire is a constant.
    fn constant_value(self) -> Option<bool> {
        (self.slot == ZERO).then_some(self.inverted)
    }
}

/// A gate: the previous gate's output and four input slots (unused ones
/// read [`ZERO`]), and the truth table indexed by their values: bit 0 of
/// the index is the previous gate's output, bit `n + 1` slot `inputs[n]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Gate {
    inputs: [u8; 4],
    table: u32,
    /// The checks on this gate's output, as a table of the inputs that
    /// refuse the scan (its value differs from a latch it is stored to).
    refuse: u32,
}

impl Gate {
    /// The gate for `table`, a function of `inputs[..len]` (bit `n` of its
    /// index is input `n`). An input that is the slot `previous` (the
    /// output of the gate before this one) is read from the register
    /// instead.
    fn new(inputs: [u8; 4], len: usize, table: u16, previous: u8) -> Gate {
        let from_register = inputs[..len].iter().position(|&s| s == previous);
        let mut slots = [ZERO; 4];
        // Where each of `inputs` is in the new index.
        let mut bit = [0usize; 4];
        let mut next = 0;
        for (n, &slot) in inputs[..len].iter().enumerate() {
            if Some(n) == from_register {
                bit[n] = 0;
            } else {
                slots[next] = slot;
                bit[n] = next + 1;
                next += 1;
            }
        }
        let mut spread = 0u32;
        for index in 0..32usize {
            let old: usize = (0..len).map(|n| (index >> bit[n] & 1) << n).sum();
            spread |= u32::from(table >> old & 1) << index;
        }
        Gate {
            inputs: slots,
            table: spread,
            refuse: 0,
        }
    }
}

/// A run-time check on a slot that is not a gate's (those are folded into
/// [`Gate::refuse`]): the scan stands only if slot `slot` holds `want`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
struct Check {
    slot: u8,
    want: u8,
}

/// A Y or M latch the scan leaves with a new value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Output {
    bit: u8,
    value: Wire,
}

/// The accumulator while the compiler reads a run of `LD`/`AND`/`OR`: a
/// truth table over up to four distinct input slots.
#[derive(Clone, Copy, Debug)]
struct Pending {
    inputs: [u8; 4],
    len: usize,
    table: u16,
}

impl Pending {
    /// The accumulator equal to `wire`.
    fn of(wire: Wire) -> Pending {
        let mut p = Pending {
            inputs: [ZERO; 4],
            len: 0,
            table: 0,
        };
        p.combine(wire, false);
        p
    }

    /// Where `slot` is among the inputs, adding it if there is room.
    fn position(&mut self, slot: u8) -> Option<usize> {
        if let Some(n) = self.inputs[..self.len].iter().position(|&s| s == slot) {
            return Some(n);
        }
        if self.len == self.inputs.len() {
            return None;
        }
        self.inputs[self.len] = slot;
        self.len += 1;
        Some(self.len - 1)
    }

    /// `AND`s or `OR`s `wire` in; `false` when a fifth input would be needed.
    fn combine(&mut self, wire: Wire, and: bool) -> bool {
        let column = match wire.constant_value() {
            Some(value) => {
                if value {
                    u16::MAX
                } else {
                    0
                }
            }
            None => {
                let Some(n) = self.position(wire.slot) else {
                    return false;
                };
                if wire.inverted {
                    !INPUT_COLUMN[n]
                } else {
                    INPUT_COLUMN[n]
                }
            }
        };
        self.table = if and {
            self.table & column
        } else {
            self.table | column
        };
        true
    }

    /// The table as a function of inputs 0..len only (the unused inputs
    /// read 0, so only the entries with their bits clear matter).
    fn used_table(&self) -> u16 {
        let entries = 1u32 << self.len;
        (u32::from(self.table) & ((1u32 << entries) - 1)) as u16
    }
}

#[derive(Clone, Copy, Debug)]
enum Accumulator {
    Wire(Wire),
    Pending(Pending),
}

/// Builds a network step by step.
struct Compiler {
    specials: Specials,
    gates: Vec<Gate>,
    checks: Vec<Check>,
    /// A check failed while compiling: no scan in this state can stand.
    refused: bool,
    /// What reading each address gives now.
    reads: [Wire; 32],
    acc: Accumulator,
}

impl Compiler {
    fn new(specials: Specials) -> Compiler {
        let reads = std::array::from_fn(|a| match Instruction::decode(a as u8).address.device() {
            Device::Timer(_) | Device::Counter | Device::CounterClear => {
                Wire::constant(specials.reads >> a & 1 != 0)
            }
            _ => Wire::slot(a as u8),
        });
        Compiler {
            specials,
            gates: Vec::new(),
            checks: Vec::new(),
            refused: false,
            reads,
            acc: Accumulator::Wire(Wire::slot(ACC_IN)),
        }
    }

    /// The accumulator as a wire, adding a gate if it is still a table.
    fn settle(&mut self) -> Wire {
        let wire = match self.acc {
            Accumulator::Wire(wire) => wire,
            Accumulator::Pending(p) => self.gate_for(p),
        };
        self.acc = Accumulator::Wire(wire);
        wire
    }

    /// A wire for a pending table: no gate when it is a constant or a
    /// single input read plainly or inverted.
    fn gate_for(&mut self, p: Pending) -> Wire {
        let table = p.used_table();
        let all_ones = ((1u32 << (1u32 << p.len)) - 1) as u16;
        match (p.len, table) {
            (_, 0) => return Wire::constant(false),
            _ if table == all_ones => return Wire::constant(true),
            (1, 0b10) => return Wire::slot(p.inputs[0]),
            (1, 0b01) => return Wire::slot(p.inputs[0]).inverted_if(true),
            _ => {}
        }
        let previous = FIRST_GATE
            .wrapping_add(self.gates.len() as u8)
            .wrapping_sub(1);
        self.gates.push(Gate::new(p.inputs, p.len, table, previous));
        // Past MAX_GATES the slot number wraps; compile() then refuses.
        Wire::slot(FIRST_GATE.wrapping_add(self.gates.len() as u8 - 1))
    }

    /// Requires `value` to equal `latch` for the scan to stand.
    fn check(&mut self, value: Wire, latch: bool) {
        // The value the slot itself must hold.
        let want = value.inverted ^ latch;
        if let Some(stored) = value.constant_value() {
            self.refused |= stored != latch;
        } else if let Some(gate) = value
            .slot
            .checked_sub(FIRST_GATE)
            .and_then(|n| self.gates.get_mut(usize::from(n)))
        {
            gate.refuse |= if want { !gate.table } else { gate.table };
        } else {
            self.checks.push(Check {
                slot: value.slot,
                want: u8::from(want),
            });
        }
    }

    fn step(&mut self, instruction: Instruction) {
        let address = usize::from(instruction.address.index());
        let invert = instruction.opcode.inverts();
        let read = self.reads[address].inverted_if(invert);
        match instruction.opcode {
            Opcode::Ld | Opcode::Ldi => self.acc = Accumulator::Pending(Pending::of(read)),
            Opcode::And | Opcode::Andi | Opcode::Or | Opcode::Ori => {
                let and = matches!(instruction.opcode, Opcode::And | Opcode::Andi);
                let mut p = match self.acc {
                    Accumulator::Pending(p) => p,
                    Accumulator::Wire(wire) => Pending::of(wire),
                };
                if !p.combine(read, and) {
                    // A fifth input: the run so far becomes a gate, which is
                    // the first input of the next table.
                    p = Pending::of(self.gate_for(p));
                    let fits = p.combine(read, and);
                    debug_assert!(fits, "a second input always fits");
                }
                self.acc = Accumulator::Pending(p);
            }
            Opcode::St | Opcode::Sti => {
                let value = self.settle().inverted_if(invert);
                match instruction.address.device() {
                    Device::Output(_) | Device::Relay(_) => self.reads[address] = value,
                    Device::Input(_) => {}
                    Device::Timer(_) | Device::Counter | Device::CounterClear => {
                        let latch = self.specials.latches >> address & 1 != 0;
                        self.check(value, latch);
                    }
                }
            }
        }
    }
}

/// Each byte spread to eight slot values: byte `i` of `SPREAD[b]` is bit `i`
/// of `b`. Loads the bus into the first 32 slots with four lookups.
const SPREAD: [u64; 256] = {
    let mut table = [0u64; 256];
    let mut b = 0;
    while b < 256 {
        let mut i = 0;
        while i < 8 {
            table[b] |= ((b as u64 >> i) & 1) << (8 * i);
            i += 1;
        }
        b += 1;
    }
    table
};

/// The values of one scan, one byte a slot; kept by the caller so that a
/// scan allocates nothing.
#[derive(Clone, Debug)]
pub(super) struct Slots(Box<[u8; SLOTS]>);

impl Default for Slots {
    fn default() -> Slots {
        Slots(Box::new([0; SLOTS]))
    }
}

/// A program compiled for one [`Specials`] state.
#[derive(Clone, Debug)]
pub(super) struct Network {
    gates: Box<[Gate]>,
    /// Without repeats: a check made twice is made once.
    checks: Box<[Check]>,
    outputs: Box<[Output]>,
    acc: Wire,
    /// A store changes a latch whatever the inputs (or the program is too
    /// big): every scan is refused.
    refused: bool,
}

impl Network {
    /// Compiles program memory for the timer and counter state `specials`.
    /// A program that needs more gates than there are slots (no 256-step
    /// program does, see [`SLOTS`]) gets a network that refuses every scan.
    pub(super) fn compile(memory: &[u8; STEPS], specials: Specials) -> Network {
        let mut c = Compiler::new(specials);
        for &byte in memory {
            c.step(Instruction::decode(byte));
        }
        let acc = c.settle();
        if c.gates.len() > MAX_GATES {
            c.refused = true;
            c.gates.clear();
        }
        let outputs = (0..32u8)
            .filter(|&a| {
                matches!(
                    Instruction::decode(a).address.device(),
                    Device::Output(_) | Device::Relay(_)
                )
            })
            .filter(|&a| c.reads[usize::from(a)] != Wire::slot(a))
            .map(|a| Output {
                bit: a,
                value: c.reads[usize::from(a)],
            })
            .collect();
        crate::sort::all(&mut c.checks);
        c.checks.dedup();
        Network {
            gates: c.gates.into_boxed_slice(),
            checks: c.checks.into_boxed_slice(),
            outputs,
            acc,
            refused: c.refused,
        }
    }

    /// Runs one scan from `bus` (bit `a` = what address `a` reads, in the
    /// state the network was compiled for) and `acc`. Returns the
    /// accumulator and the bus after the scan, or `None` if a store would
    /// change a timer or counter latch.
    pub(super) fn run(&self, slots: &mut Slots, bus: u32, acc: bool) -> Option<(bool, u32)> {
        if self.refused {
            return None;
        }
        let s = &mut *slots.0;
        for (n, chunk) in s[..32].chunks_exact_mut(8).enumerate() {
            let byte = (bus >> (8 * n)) as u8;
            chunk.copy_from_slice(&SPREAD[usize::from(byte)].to_le_bytes());
        }
        s[usize::from(ZERO)] = 0;
        s[usize::from(ACC_IN)] = u8::from(acc);
        // Bit 0 of `refuse` collects every check; the bits above it are
        // whatever the shifts leave and are never looked at.
        let mut refuse = 0u32;
        // The first gate's "previous gate" is slot FIRST_GATE - 1: ACC_IN.
        let mut last = u32::from(acc);
        let mut out = FIRST_GATE;
        for gate in self.gates.iter() {
            let input = |n: usize| u32::from(s[usize::from(gate.inputs[n])]);
            // Values are 0 or 1, so the sum is the table index (0..32).
            let index = last + 2 * input(0) + 4 * input(1) + 8 * input(2) + 16 * input(3);
            last = gate.table.wrapping_shr(index) & 1;
            s[usize::from(out)] = last as u8;
            refuse |= gate.refuse.wrapping_shr(index);
            out = out.wrapping_add(1);
        }
        for check in self.checks.iter() {
            refuse |= u32::from(s[usize::from(check.slot)] ^ check.want);
        }
        if refuse & 1 != 0 {
            return None;
        }
        let value = |w: Wire| s[usize::from(w.slot)] ^ u8::from(w.inverted);
        let mut bus = bus;
        for output in self.outputs.iter() {
            let mask = 1u32 << output.bit;
            bus = (bus & !mask) | u32::from(value(output.value)) << output.bit;
        }
        Some((value(self.acc) != 0, bus))
    }
}

#[cfg(test)]
mod tests;
