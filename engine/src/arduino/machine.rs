//! The Arduino PLC sketch running: one word per step, inputs read as each
//! step runs, outputs driven at once, a 16-bit shift register as the stack.

use super::isa::{Op, Program, ERASED};
use crate::clock::PeriodicClock;
use crate::plc::SettingError;
use crate::time::SimTime;

/// Which ATmega the sketch runs on: its EEPROM holds 256 or 512 words.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Chip {
    /// ATmega168: 512-byte EEPROM, 256 steps.
    Atmega168,
    /// ATmega328 (Arduino Uno): 1 KB EEPROM, 512 steps.
    #[default]
    Atmega328,
}

impl Chip {
    /// Steps the EEPROM holds.
    pub const fn capacity(self) -> usize {
        match self {
            Chip::Atmega168 => 256,
            Chip::Atmega328 => 512,
        }
    }
}

/// How the bit stack pops.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum PopOrder {
    /// Decided (machines.md): take the top, then shift.
    #[default]
    Intended,
    /// The sketch as written: shift, then take the bit that was under the top.
    Sketch,
}

/// The default time one step takes.
pub const DEFAULT_STEP: SimTime = SimTime::from_micros(10);

/// One Arduino running the PLC sketch.
#[derive(Clone, Debug)]
pub struct Machine {
    eeprom: Vec<u16>,
    chip: Chip,
    pop_order: PopOrder,
    /// Fires once per step.
    clock: PeriodicClock,
    enabled: bool,
    pc: u16,
    stack: u16,
    /// X000..X005 = PD2..PD7, bit n = X00n.
    inputs: u8,
    /// PORTB: bit n = Y00n.
    port_b: u8,
    steps: u64,
    /// Times the run came back to step 0 (END, JUMP 0).
    passes: u64,
    /// Per-step tracing, when on (a pass is a scan).
    pub(crate) tracer: crate::plc::Tracer,
}

impl Machine {
    /// An Arduino with `program` in EEPROM (the rest erased), as after
    /// power-up: the PLC is disabled until `e`.
    pub fn new(program: &Program, chip: Chip) -> Machine {
        let mut eeprom = vec![ERASED; chip.capacity()];
        for (slot, &word) in eeprom.iter_mut().zip(program.words()) {
            *slot = word;
        }
        Machine {
            eeprom,
            chip,
            pop_order: PopOrder::Intended,
            clock: PeriodicClock::new(DEFAULT_STEP),
            enabled: false,
            pc: 0,
            stack: 0,
            inputs: 0,
            port_b: 0,
            steps: 0,
            passes: 0,
            tracer: crate::plc::Tracer::default(),
        }
    }

    /// Power off and on: the program counter, the bit stack and the
    /// outputs cleared, the PLC disabled until `e` (as after power-up);
    /// the EEPROM stays.
    pub fn power_cycle(&mut self) {
        self.pc = 0;
        self.stack = 0;
        self.port_b = 0;
        self.enabled = false;
        self.clock.restart();
    }

    /// Writes `program` into EEPROM (the rest erased), as uploading it
    /// does; the run starts again from step 0 with an empty stack.
    pub fn load(&mut self, program: &Program) {
        self.eeprom.iter_mut().for_each(|w| *w = ERASED);
        for (slot, &word) in self.eeprom.iter_mut().zip(program.words()) {
            *slot = word;
        }
        self.pc = 0;
        self.stack = 0;
    }

    /// The EEPROM, one word per step.
    pub fn eeprom(&self) -> &[u16] {
        &self.eeprom
    }

    /// Writes one EEPROM word (the monitor's `s`); false beyond the EEPROM.
    pub fn write_word(&mut self, step: usize, word: u16) -> bool {
        match self.eeprom.get_mut(step) {
            Some(slot) => {
                *slot = word;
                true
            }
            None => false,
        }
    }

    /// The chip.
    pub fn chip(&self) -> Chip {
        self.chip
    }

    /// Changes the chip: the EEPROM grows (erased) or shrinks, refusing to
    /// drop a programmed word.
    pub fn set_chip(&mut self, chip: Chip) -> Result<(), SettingError> {
        let capacity = chip.capacity();
        if let Some(step) = self.eeprom.iter().skip(capacity).position(|&w| w != ERASED) {
            return Err(SettingError::ChipTooSmall {
                step: capacity + step,
                capacity,
            });
        }
        self.eeprom.resize(capacity, ERASED);
        self.chip = chip;
        Ok(())
    }

    /// Chooses how the stack pops.
    pub fn set_pop_order(&mut self, order: PopOrder) {
        self.pop_order = order;
    }

    /// Sets the time a step takes (above zero).
    pub fn set_step_time(&mut self, t: SimTime) -> Result<(), SettingError> {
        let now = self.clock.now();
        self.clock
            .set_period(t, now, SimTime::from_secs(1), "step time")
    }

    /// `e` (true) or `d`: the PLC runs from step 0 when enabled.
    pub fn set_enabled(&mut self, on: bool) {
        if on && !self.enabled {
            self.pc = 0;
            self.clock.restart();
        }
        self.enabled = on;
    }

    /// Whether the PLC runs.
    pub fn enabled(&self) -> bool {
        self.enabled
    }

    /// The step that runs next.
    pub fn pc(&self) -> u16 {
        self.pc
    }

    /// The bit stack (bit 0 = top).
    pub fn stack(&self) -> u16 {
        self.stack
    }

    /// Sets input X00n (pin PD(n+2)).
    pub fn set_input(&mut self, n: u8, on: bool) {
        if n < 6 {
            self.inputs = (self.inputs & !(1 << n)) | (u8::from(on) << n);
        }
    }

    /// The input pins (bit n = X00n).
    pub fn inputs(&self) -> u8 {
        self.inputs
    }

    /// The output pins (bit n = Y00n).
    pub fn outputs(&self) -> u8 {
        self.port_b & 0x3F
    }

    /// The simulated time.
    pub fn now(&self) -> SimTime {
        self.clock.now()
    }

    /// The time one step takes.
    pub fn step_time(&self) -> SimTime {
        self.clock.period()
    }

    /// Times the run came back to step 0 (END or JUMP 0): the sketch's
    /// nearest thing to completed scans.
    pub fn passes(&self) -> u64 {
        self.passes
    }

    /// Steps executed.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// Runs the next step at its time; returns its address (`None` while
    /// the PLC is not enabled).
    pub fn step_instruction(&mut self) -> Option<u16> {
        if !self.enabled {
            return None;
        }
        let pc = self.pc;
        self.run_until(self.clock.next());
        Some(pc)
    }

    /// Runs steps until the program returns to step 0 (END or JUMP 0):
    /// the sketch's nearest thing to a scan.
    pub fn step_scan(&mut self) {
        for _ in 0..=self.eeprom.len() {
            match self.step_instruction() {
                Some(_) if self.pc != 0 => {}
                _ => break,
            }
        }
    }

    /// When the pass under way ends (the step that returns to step 0), if
    /// nothing is written meanwhile; `None` while disabled or when the
    /// program never returns to 0 from here. The sketch has no
    /// conditional jump, so where each step goes is fixed by the EEPROM.
    pub fn next_pass_end(&self) -> Option<SimTime> {
        self.nth_pass_end(1)
    }

    /// When the `n`-th pass from now ends (`n` ≥ 1): the rest of this
    /// one, then whole passes from step 0.
    pub fn nth_pass_end(&self, n: u64) -> Option<SimTime> {
        if !self.enabled || n == 0 {
            return None;
        }
        let rest = self.steps_to_zero(self.pc)?;
        let whole = match n {
            1 => 0,
            _ => self.steps_to_zero(0)?.checked_mul(n - 1)?,
        };
        let steps = rest
            .checked_add(whole)?
            .checked_sub(1)?
            .checked_mul(self.step_time().as_nanos())?;
        self.clock.next().checked_add(SimTime::from_nanos(steps))
    }

    /// How many steps from `pc` until the program is back at step 0.
    fn steps_to_zero(&self, mut pc: u16) -> Option<u64> {
        // Past that many steps a pc repeats: the program loops elsewhere.
        let limit = self.eeprom.len().max(256) + 2;
        for k in 1..=limit as u64 {
            let word = self.eeprom.get(usize::from(pc)).copied().unwrap_or(ERASED);
            pc = match Op::decode(word) {
                Some(Op::End) => 0,
                Some(Op::Jump) => word & 0xFF,
                _ => pc.wrapping_add(1),
            };
            if pc == 0 {
                return Some(k);
            }
        }
        None
    }

    /// Runs every step due at or before `t`.
    pub fn run_until(&mut self, t: SimTime) {
        while self.enabled && self.clock.fire_until(t).is_some() {
            self.step();
        }
        self.clock.settle(t);
    }

    /// Runs every step due strictly before `t`; the time becomes `t`.
    pub fn run_before(&mut self, t: SimTime) {
        self.run_until(PeriodicClock::just_before(t));
        self.clock.settle(t);
    }

    // Inlined by force: the interpreter calls it per step, and the page is
    // built for size (opt-level z; docs/performance.md, "First visit").
    #[inline(always)]
    fn push(&mut self, bit: bool) {
        self.stack = self.stack << 1 | u16::from(bit);
    }

    // Inlined by force: the interpreter calls it per step, and the page is
    // built for size (opt-level z; docs/performance.md, "First visit").
    #[inline(always)]
    fn pop(&mut self) -> bool {
        match self.pop_order {
            PopOrder::Intended => {
                let bit = self.stack & 1 != 0;
                self.stack >>= 1;
                bit
            }
            PopOrder::Sketch => {
                self.stack >>= 1;
                self.stack & 1 != 0
            }
        }
    }

    /// What an operand reads: bits 0-7 the inputs, 8-15 port B (the sketch
    /// takes the operand's low four bits).
    fn read(&self, bit: u8) -> bool {
        if bit > 7 {
            self.port_b >> (bit - 8) & 1 != 0
        } else {
            self.inputs >> bit & 1 != 0
        }
    }

    /// One step: fetch, decode, execute. Every pop happens whatever the
    /// operand reads (no short-circuit): the stack must move as the sketch's.
    fn step(&mut self) {
        let word = self
            .eeprom
            .get(usize::from(self.pc))
            .copied()
            .unwrap_or(ERASED);
        let step = usize::from(self.pc);
        self.pc += 1;
        self.steps += 1;
        let bit = (word & 0x0F) as u8;
        // What the step read and left on top, for tracing.
        let (mut read, mut result) = (false, false);
        let mut operand = |m: &Self| {
            read = m.read(bit);
            read
        };
        match Op::decode(word) {
            Some(Op::End) => self.pc = 0,
            Some(Op::Ld) => {
                result = operand(self);
                self.push(result);
            }
            Some(Op::Ldn) => {
                result = !operand(self);
                self.push(result);
            }
            Some(Op::And) => {
                let top = self.pop();
                result = operand(self) && top;
                self.push(result);
            }
            Some(Op::Andn) => {
                let top = self.pop();
                result = !operand(self) && top;
                self.push(result);
            }
            Some(Op::Or) => {
                let top = self.pop();
                result = operand(self) || top;
                self.push(result);
            }
            Some(Op::Orn) => {
                let top = self.pop();
                result = !operand(self) || top;
                self.push(result);
            }
            Some(Op::Andb) => {
                let (a, b) = (self.pop(), self.pop());
                result = a && b;
                self.push(result);
            }
            Some(Op::Orb) => {
                let (a, b) = (self.pop(), self.pop());
                result = a || b;
                self.push(result);
            }
            Some(Op::Out) => {
                result = self.pop();
                // Port B bit (operand - 8): the intent of the sketch, whose
                // own code shifts by the raw operand (see docs/arduino-plc.md).
                if let Some(n) = bit.checked_sub(8) {
                    self.port_b = (self.port_b & !(1 << n)) | (u8::from(result) << n);
                }
            }
            Some(Op::Jump) => self.pc = word & 0xFF,
            None => {} // opcodes 10-14: the sketch does nothing
        }
        self.tracer.step(step, read, result);
        if self.pc == 0 {
            self.tracer.end_scan();
        }
        if self.pc == 0 {
            self.passes += 1;
        }
    }
}
