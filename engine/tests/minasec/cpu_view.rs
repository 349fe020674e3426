//! The CPU view's snapshot (issue #33) against an oracle written from the
//! book's equations, not from the machine's code: the logic unit
//! `D = i·(!OP1 + Q) + OP2·Q` latched on the clock's rise (a store writes
//! `Q ⊕ OP0`), `WE = !(OP1·OP2·CLK)`, the instruction changing at the
//! fall, the input image and the output terminals exchanged when the PC
//! wraps. Random programs over X, Y and M, stepped edge by edge at HALT
//! with the CLOCK button, compared at every edge.

use engine::minasec::cpu::{Block, CpuView, EdgeLevels, Phase, STRIP_EDGES};
use engine::minasec::{Command, Machine, Mode};

/// The book's CPU, from its equations.
struct Oracle {
    memory: [u8; 256],
    pc: u8,
    q: bool,
    clk: bool,
    terminals: u8,
    image: u8,
    /// Bit `a` = the latch at address `a` (Y 8–15, M 16–27).
    latches: u32,
    lamps: u8,
    /// CLK, WE, scan after each edge.
    strip: Vec<EdgeLevels>,
}

impl Oracle {
    fn new(memory: [u8; 256]) -> Oracle {
        Oracle {
            memory,
            pc: 0,
            q: false,
            clk: false,
            terminals: 0,
            image: 0,
            latches: 0,
            lamps: 0,
            strip: Vec::new(),
        }
    }

    fn bits(&self) -> (bool, bool, bool, u8) {
        let byte = self.memory[usize::from(self.pc)];
        (
            byte & 0x80 != 0,
            byte & 0x40 != 0,
            byte & 0x20 != 0,
            byte & 0x1F,
        )
    }

    fn read(&self, a: u8) -> bool {
        if a < 8 {
            self.image >> a & 1 != 0
        } else {
            self.latches >> a & 1 != 0
        }
    }

    fn we(&self) -> bool {
        let (op2, op1, _, _) = self.bits();
        !(op1 && op2 && self.clk)
    }

    fn rise(&mut self) {
        let (op2, op1, op0, a) = self.bits();
        let i = self.read(a) ^ op0;
        if op1 && op2 && a >= 8 {
            let bit = 1u32 << a;
            self.latches = if self.q ^ op0 {
                self.latches | bit
            } else {
                self.latches & !bit
            };
        }
        self.q = (i && (!op1 || self.q)) || (op2 && self.q);
        self.clk = true;
        self.strip.push(EdgeLevels {
            clk: true,
            we: self.we(),
            scan: false,
        });
    }

    fn fall(&mut self) {
        self.clk = false;
        self.pc = self.pc.wrapping_add(1);
        if self.pc == 0 {
            self.lamps = (self.latches >> 8) as u8;
            self.image = self.terminals;
        }
        self.strip.push(EdgeLevels {
            clk: false,
            we: true,
            scan: self.pc == 0,
        });
    }
}

/// A deterministic pseudo-random source (xorshift).
struct Random(u64);

impl Random {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    /// A step over X, Y and M (addresses 0–27), any opcode.
    fn step(&mut self) -> u8 {
        let opcode = (self.next() % 8) as u8;
        let address = (self.next() % 28) as u8;
        opcode << 5 | address
    }
}

/// Compares the view after one edge with the oracle, and with the
/// panel's LEDs.
fn compare(m: &Machine, o: &Oracle, phase: Phase, at: &str) {
    let mut v = CpuView::default();
    m.cpu_view_into(&mut v);
    let (op2, op1, op0, a) = o.bits();
    let byte = o.memory[usize::from(o.pc)];
    assert_eq!(v.phase, phase, "{at}");
    assert_eq!((v.pc, v.instruction, v.address), (o.pc, byte, a), "{at}");
    assert_eq!((v.opcode(), v.operand()), (byte >> 5, a), "{at}");
    assert_eq!(v.acc, o.q, "{at}: the accumulator");
    assert_eq!(v.data_in, o.read(a), "{at}: Din");
    assert_eq!(v.data_out, o.q ^ op0, "{at}: Dout");
    assert_eq!(v.clk, o.clk, "{at}");
    assert_eq!(v.we, !(op1 && op2 && o.clk), "{at}: WE");
    assert_eq!(v.scan, phase == Phase::Falling && o.pc == 0, "{at}: scan");
    let value = |b: Block| v.block(b).value;
    assert_eq!(value(Block::Pc), u32::from(o.pc), "{at}");
    assert_eq!(value(Block::Memory), u32::from(byte), "{at}");
    assert_eq!(value(Block::Decoder), u32::from(byte >> 5), "{at}");
    let selected = a >> 3 | if v.we { 4 } else { 0 };
    assert_eq!(value(Block::AddressDecoder), u32::from(selected), "{at}");
    assert_eq!(value(Block::Accumulator), u32::from(o.q), "{at}");
    assert_eq!(value(Block::Inputs), u32::from(o.image), "{at}");
    assert_eq!(value(Block::Outputs), o.latches >> 8 & 0xFF, "{at}");
    assert_eq!(value(Block::Relays), o.latches >> 16 & 0xFFF, "{at}");
    // The panel's LEDs say the same.
    let panel = m.panel();
    assert_eq!(panel.pc_leds, v.pc, "{at}: PC LEDs");
    assert_eq!(
        panel.instruction_leds, v.instruction,
        "{at}: instruction LEDs"
    );
    assert_eq!(panel.acc_led, v.acc, "{at}: A LED");
    assert_eq!(panel.lamps, o.lamps, "{at}: lamps");
    // The device the edge reads or writes is lit, and at the rise the
    // accumulator; at the fall the PC.
    // The rise lights the accumulator and the device read; the fall the
    // PC, and the inputs only when it wraps (unless a store to X ended).
    let active = |b: Block| v.block(b).active;
    let device = |a: u8| match a {
        0..=7 => Block::Inputs,
        8..=15 => Block::Outputs,
        _ => Block::Relays,
    };
    match phase {
        Phase::Rising => {
            assert!(active(Block::Accumulator) && !active(Block::Pc), "{at}");
            assert!(active(device(a)), "{at}: the device read");
        }
        _ => {
            assert!(active(Block::Pc) && !active(Block::Accumulator), "{at}");
            let ended = o.memory[usize::from(o.pc.wrapping_sub(1))];
            if !(ended >> 6 == 0b11 && ended & 0x1F < 8) {
                assert_eq!(active(Block::Inputs), o.pc == 0, "{at}: inputs at the wrap");
            }
        }
    }
}

#[test]
fn the_view_follows_the_books_equations_at_every_edge_of_random_programs() {
    let mut random = Random(0x9E37_79B9_7F4A_7C15);
    for program in 0..12 {
        let mut memory = [0u8; 256];
        for byte in memory.iter_mut() {
            *byte = random.step();
        }
        let mut m = Machine::new();
        m.load(&engine::minasec::Program::from_bytes(memory));
        let mut o = Oracle::new(memory);
        // Two scans and a bit, edge by edge.
        for edge in 0..(2 * 256 * 2 + 40) {
            if edge % 97 == 0 {
                let n = (random.next() % 8) as u8;
                let on = random.next() % 2 == 1;
                m.apply(Command::SetInput(n, on)).expect("an input");
                o.terminals = (o.terminals & !(1 << n)) | u8::from(on) << n;
            }
            let at = format!("program {program}, edge {edge}");
            if edge % 2 == 0 {
                m.apply(Command::ClockButton(true)).expect("press");
                o.rise();
                compare(&m, &o, Phase::Rising, &at);
            } else {
                m.apply(Command::ClockButton(false)).expect("release");
                o.fall();
                compare(&m, &o, Phase::Falling, &at);
            }
            let mut strip = Vec::new();
            m.recent_edges_into(&mut strip);
            let from = o.strip.len().saturating_sub(STRIP_EDGES);
            assert_eq!(strip, o.strip[from..], "{at}: the strip");
        }
    }
}

#[test]
fn the_phase_keeps_a_stepped_edge_at_halt_and_is_a_level_while_running() {
    let mut m = Machine::new();
    let mut v = CpuView::default();
    m.cpu_view_into(&mut v);
    assert_eq!(v.phase, Phase::Low, "no edge since reset");
    m.apply(Command::ClockButton(true)).expect("press");
    // At HALT time still runs (the timers), the edge stays the last.
    m.tick(engine::SimTime::from_millis(5));
    m.cpu_view_into(&mut v);
    assert_eq!((v.phase, v.clk), (Phase::Rising, true));
    m.apply(Command::ClockButton(false)).expect("release");
    m.apply(Command::SetMode(Mode::Run)).expect("run");
    m.tick(engine::SimTime::from_nanos(1));
    m.cpu_view_into(&mut v);
    assert_eq!(v.phase, Phase::Low, "running, between edges");
    assert!(v.blocks.iter().all(|b| !b.active), "no edge lights a block");
    m.tick(engine::SimTime::from_micros(20));
    m.cpu_view_into(&mut v);
    assert_eq!(v.phase, Phase::High, "running, after a rise");
    m.apply(Command::SetMode(Mode::Reset)).expect("reset");
    m.cpu_view_into(&mut v);
    assert!(v.clear && !v.clk && v.pc == 0);
    let mut strip = vec![EdgeLevels::default()];
    m.recent_edges_into(&mut strip);
    assert!(strip.is_empty(), "no edges since reset");
}
