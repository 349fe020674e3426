//! Inside MINASEC-U (issue #33): the signals of the book's CPU and its
//! blocks at one instant, for a view that draws the circuit working —
//! never recomputed by the view. The book's names (its chapter "1bit
//! CPU"): the program counter (74HC590) addresses the program memory
//! (HM6116), whose byte on the instruction bus is decoded into the
//! logic unit's OP2 OP1 OP0 and the address bus; the address decoder
//! (74HC138) selects the device, its C input taken by WE, so that its
//! outputs Y0–Y3 strobe a device's write and Y4–Y7 select its read; the
//! accumulator (74HC74) takes `D = i·(!OP1 + Q) + OP2·Q` at the clock's
//! rise; `WE = !(OP1·OP2·CLK)`; the instruction changes at the fall; at
//! the PC's wrap the scan signal clocks the input and output D-FFs
//! (74HC273).

use super::control::Mode;
use super::isa::{Address, Device, Instruction};
use super::machine::Machine;

/// Where the clock stands: on an edge just taken, or between edges.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Phase {
    /// The rising edge just happened (the step executed), or was the
    /// last while the clock is stopped.
    Rising,
    /// High, the clock running, some time after the rise.
    High,
    /// The falling edge just happened (the PC advanced), or was the last
    /// while the clock is stopped.
    Falling,
    /// Low, the clock running, some time after the fall (or no edge since
    /// reset).
    #[default]
    Low,
}

impl Phase {
    /// The name the view's `data-value` carries.
    pub const fn name(self) -> &'static str {
        match self {
            Phase::Rising => "rising",
            Phase::High => "high",
            Phase::Falling => "falling",
            Phase::Low => "low",
        }
    }
}

/// The book's blocks, as the CPU view draws them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Block {
    /// The program counter, 74HC590.
    Pc,
    /// The program memory, HM6116.
    Memory,
    /// The instruction decoder and logic unit.
    Decoder,
    /// The address decoder, 74HC138.
    AddressDecoder,
    /// The accumulator, 74HC74.
    Accumulator,
    /// The digital inputs: 74HC273 image, 74HC251 multiplexer.
    Inputs,
    /// The digital outputs: 74HC259 latches, 74HC273 to the terminals.
    Outputs,
    /// The internal relays, 74HC259 + 74HC251.
    Relays,
    /// The RC timers (74HC132) between a latch and the multiplexer.
    Timers,
    /// The BCD counter: 74HC390, 74HC4511, 74HC688.
    Counter,
}

impl Block {
    /// Every block, in the order of [`CpuView::blocks`].
    pub const ALL: [Block; 10] = [
        Block::Pc,
        Block::Memory,
        Block::Decoder,
        Block::AddressDecoder,
        Block::Accumulator,
        Block::Inputs,
        Block::Outputs,
        Block::Relays,
        Block::Timers,
        Block::Counter,
    ];

    /// The test hook's name (`cpu-block-<name>`).
    pub const fn name(self) -> &'static str {
        match self {
            Block::Pc => "pc",
            Block::Memory => "memory",
            Block::Decoder => "decoder",
            Block::AddressDecoder => "address-decoder",
            Block::Accumulator => "accumulator",
            Block::Inputs => "inputs",
            Block::Outputs => "outputs",
            Block::Relays => "relays",
            Block::Timers => "timers",
            Block::Counter => "counter",
        }
    }

    /// Its bit in a set of blocks.
    const fn bit(self) -> u16 {
        1 << self as u16
    }

    /// The device block an address belongs to.
    pub const fn of(address: Address) -> Block {
        match address.device() {
            Device::Input(_) => Block::Inputs,
            Device::Output(_) => Block::Outputs,
            Device::Relay(_) => Block::Relays,
            Device::Timer(_) => Block::Timers,
            Device::Counter | Device::CounterClear => Block::Counter,
        }
    }
}

/// One block at an instant: its value and whether the current edge
/// involves it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BlockState {
    /// The PC, the instruction byte, the opcode (OP2 OP1 OP0), the
    /// decoder's active output (0–7), the accumulator, the input image,
    /// the Y latches, the M latches (M00–M07 bits 0–7, M10–M13 bits
    /// 8–11), the timers' outputs (T0 bit 0, T1 bit 1), the count.
    pub value: u32,
    /// Takes part in the edge just taken.
    pub active: bool,
}

/// Everything the CPU view shows, filled into the caller's copy.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CpuView {
    /// The program counter.
    pub pc: u8,
    /// The byte on the instruction bus (opcode bits 7–5, operand 4–0).
    pub instruction: u8,
    /// The address bus: the operand.
    pub address: u8,
    /// The input data bus: what the addressed device reads now.
    pub data_in: bool,
    /// The output data bus: the accumulator, inverted by OP0 (what a
    /// store writes).
    pub data_out: bool,
    /// The write strobe, active low: `!(OP1·OP2·CLK)`.
    pub we: bool,
    /// The scan signal: high at the falling edge that wraps the PC, when
    /// the input image and the output terminals are exchanged.
    pub scan: bool,
    /// The clear signal CLR: high while the switch is at RESET.
    pub clear: bool,
    /// The accumulator Q.
    pub acc: bool,
    /// The clock line.
    pub clk: bool,
    /// The clock's phase.
    pub phase: Phase,
    /// Each of [`Block::ALL`], in that order.
    pub blocks: [BlockState; 10],
}

impl CpuView {
    /// The opcode bits (OP2 OP1 OP0).
    pub const fn opcode(&self) -> u8 {
        self.instruction >> 5
    }

    /// The operand bits.
    pub const fn operand(&self) -> u8 {
        self.instruction & 0b1_1111
    }

    /// One block's state.
    pub fn block(&self, block: Block) -> BlockState {
        let i = Block::ALL.iter().position(|b| *b == block).unwrap_or(0);
        self.blocks[i]
    }
}

/// CLK, WE and the scan signal after one edge, for the timing strip.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EdgeLevels {
    pub clk: bool,
    pub we: bool,
    pub scan: bool,
}

/// Edges the timing strip shows.
pub const STRIP_EDGES: usize = 32;

impl Machine {
    /// Fills `view` with the CPU's signals and blocks now (dark when the
    /// board is off: everything zero).
    pub fn cpu_view_into(&self, view: &mut CpuView) {
        *view = CpuView::default();
        if !self.powered() {
            return;
        }
        let instruction = self.instruction();
        let Instruction { opcode, address } = instruction;
        let clk = self.clock_high();
        // The edge just taken: at this instant, or the last one while the
        // clock is stopped (HALT: the view steps edges; time still runs
        // for the timers).
        let clocked = self.powered() && self.mode() == Mode::Run;
        let edge_now =
            self.last_edge.at.is_some() && (self.last_edge.at == Some(self.now()) || !clocked);
        view.phase = match (clk, edge_now) {
            (true, true) => Phase::Rising,
            (true, false) => Phase::High,
            (false, true) => Phase::Falling,
            (false, false) => Phase::Low,
        };
        view.pc = self.pc();
        view.instruction = instruction.encode();
        view.address = address.index();
        view.data_in = self.read(address);
        view.acc = self.acc();
        view.data_out = view.acc ^ opcode.inverts();
        view.clk = clk;
        view.we = !(opcode.is_store() && clk);
        view.scan = view.phase == Phase::Falling && self.last_edge.wrapped;
        view.clear = self.mode() == Mode::Reset;
        let selected = (address.index() >> 3) + if view.we { 4 } else { 0 };
        let bus = self.bus();
        let counter = self.counter();
        let values = [
            u32::from(view.pc),
            u32::from(view.instruction),
            u32::from(view.opcode()),
            u32::from(selected),
            u32::from(view.acc),
            u32::from(self.input_image()),
            bus >> 8 & 0xFF,
            bus >> 16 & 0xFFF,
            bus >> 28 & 0b11,
            u32::from(counter.count()),
        ];
        let active = self.active_blocks(view.phase, Block::of(address));
        for ((state, value), block) in view.blocks.iter_mut().zip(values).zip(Block::ALL) {
            state.value = value;
            state.active = active & block.bit() != 0;
        }
    }

    /// The blocks the edge just taken involves (a set of [`Block::bit`]):
    /// at the rise, the decoder, the address decoder, the accumulator and
    /// the addressed `device` (read, or written by a store); at the fall,
    /// the PC and the memory with the next instruction, a store's device
    /// as WE rises and its latch closes, and at the wrap the inputs and
    /// outputs exchanged.
    fn active_blocks(&self, phase: Phase, device: Block) -> u16 {
        let set = |blocks: &[Block]| blocks.iter().fold(0, |m, b| m | b.bit());
        match phase {
            Phase::Rising => set(&[
                Block::Decoder,
                Block::AddressDecoder,
                Block::Accumulator,
                device,
            ]),
            Phase::Falling => {
                let mut blocks = set(&[Block::Pc, Block::Memory, Block::Decoder]);
                if self.last_edge.wrapped {
                    blocks |= set(&[Block::Inputs, Block::Outputs]);
                }
                // The step that just ended is the one before the PC.
                let ended = self.memory()[usize::from(self.pc().wrapping_sub(1))];
                let ended = Instruction::decode(ended);
                if ended.opcode.is_store() {
                    blocks |= set(&[Block::AddressDecoder, Block::of(ended.address)]);
                }
                blocks
            }
            Phase::High | Phase::Low => 0,
        }
    }

    /// CLK, WE and the scan signal after each of the last edges since
    /// reset (up to [`STRIP_EDGES`], the oldest first), from the program
    /// as it is in memory now.
    pub fn recent_edges_into(&self, out: &mut Vec<EdgeLevels>) {
        out.clear();
        if !self.powered() {
            return;
        }
        let taken = 2 * (self.clocks() - self.reset_clocks) - u64::from(self.clock_high());
        let shown = taken.min(STRIP_EDGES as u64) as usize;
        // Walk back from the last edge: its PC and level, then alternate.
        let (mut pc, mut high) = (self.pc(), self.clock_high());
        for _ in 0..shown {
            let store = Instruction::decode(self.memory()[usize::from(pc)])
                .opcode
                .is_store();
            out.push(EdgeLevels {
                clk: high,
                we: !(store && high),
                scan: !high && pc == 0,
            });
            if !high {
                pc = pc.wrapping_sub(1);
            }
            high = !high;
        }
        out.reverse();
    }
}
