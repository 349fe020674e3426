//! One IO86A scan, in three parts so that it can also be stepped one
//! instruction at a time: the inputs latched ([`Machine::begin_scan`]),
//! each instruction ([`Machine::execute`]), the outputs driven
//! ([`Machine::end_scan`]). A scan run whole and a scan stepped through
//! leave exactly the same state.

use super::isa::{Bit, Instruction};
use super::machine::{
    LinkWrite, Machine, Timer, M_1S, M_5HZ, M_EQ, M_FIRST, M_GT, M_LT, M_OFF, M_ON,
};
use super::peripherals::IrMode;
use crate::time::SimTime;

/// Where a scan under way stands, and its logic state.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ScanState {
    /// The next instruction's index.
    pub pc: usize,
    /// The running result.
    acc: bool,
    /// A rung has started since the last output.
    open: bool,
    /// The last instruction was an output (a following LD starts a rung).
    after_output: bool,
    /// Time since the previous scan (timers add it up).
    elapsed: SimTime,
}

impl Machine {
    /// One whole scan at the current time.
    pub(super) fn scan(&mut self) {
        let mut state = self.begin_scan();
        while self.execute(&mut state) {}
        self.end_scan();
    }

    /// Finishes a scan that was being stepped, at the time it started.
    pub(super) fn finish_scan(&mut self) {
        if let Some(mut state) = self.in_scan.take() {
            while self.execute(&mut state) {}
            self.end_scan();
        }
    }

    /// Runs one instruction: the first one starts the next scan at its
    /// time, the last one ends it. Returns the index of the instruction
    /// run, or `None` when the device is stopped (or has no program, when
    /// a whole, empty, scan runs instead).
    pub fn step_instruction(&mut self) -> Option<usize> {
        let mut state = match self.in_scan.take() {
            Some(state) => state,
            None => {
                if !self.running {
                    return None;
                }
                let next = self.clock.next();
                self.clock.fire_until(next);
                self.begin_scan()
            }
        };
        let index = state.pc;
        let more = self.execute(&mut state);
        if more {
            self.in_scan = Some(state);
        } else {
            self.end_scan();
        }
        // The step number, as the listing numbers it (MOV's operands are
        // steps of their own).
        (index < self.program.instructions().len()).then(|| self.program.first_step(index))
    }

    /// Runs to the end of the scan under way, or one whole next scan.
    pub fn step_scan(&mut self) {
        if self.in_scan.is_some() {
            self.finish_scan();
        } else if self.running {
            let next = self.clock.next();
            self.clock.fire_until(next);
            self.scan();
        }
    }

    /// The next instruction of a scan being stepped, if one is.
    pub fn scan_position(&self) -> Option<usize> {
        self.in_scan.map(|s| s.pc)
    }

    /// Latches the inputs (through the filter, analog and IR modes) and
    /// sets the system relays.
    fn begin_scan(&mut self) -> ScanState {
        let now = self.clock.now();
        let elapsed = now - self.last_scan_at;
        self.last_scan_at = now;
        // The input filter: a change counts once it has held long enough.
        let hold = self.settings.filter_time();
        for n in 0..8u8 {
            let changed = (self.input_terminals ^ self.filtered) >> n & 1 != 0;
            if changed && now.saturating_sub(self.changed_at[usize::from(n)]) >= hold {
                self.filtered ^= 1 << n;
            }
        }
        let d = &mut self.devices;
        d.x = self.filtered;
        for (i, mode) in self.settings.analog.iter().enumerate() {
            if let Some(value) = mode.convert(self.analog_mv[i]) {
                d.x &= !(1 << (4 + i)); // the pin is no digital input now
                d.d[6 + i] = value;
            }
        }
        if let IrMode::Ir { custom } = self.settings.ir {
            d.x &= !(1 << 7);
            d.d[3] = match self.ir_frame {
                Some(frame) if custom.is_none_or(|c| u32::from(c) == frame >> 16) => {
                    frame as u16 as i16
                }
                _ => 0,
            };
        }
        let now_ms = now.as_nanos() / 1_000_000;
        let specials = [
            (M_OFF, false),
            (M_ON, true),
            (M_5HZ, (now_ms / 100) % 2 == 1),
            (M_1S, (now_ms / 1000) % 2 == 1),
            (M_FIRST, self.first_scan),
        ];
        for (n, on) in specials {
            d.set_bit(Bit::M(n), on);
        }
        self.first_scan = false;
        self.stack.clear();
        ScanState {
            elapsed,
            ..ScanState::default()
        }
    }

    /// Drives the outputs from the scan's result.
    fn end_scan(&mut self) {
        self.output_terminals = self.devices.y;
        self.scans += 1;
        self.last_scan = self.devices;
        self.tracer.end_scan();
    }

    /// Runs the instruction at `state.pc`; false once the scan is over
    /// (END, or past the last instruction).
    pub(super) fn execute(&mut self, state: &mut ScanState) -> bool {
        let index = state.pc;
        let Some(&instruction) = self.program.instructions().get(index) else {
            return false;
        };
        state.pc += 1;
        let acc = state.acc;
        let d = &mut self.devices;
        let mut output = true;
        // The bit a contact step reads, for tracing.
        let read = match instruction {
            Instruction::Ld(b)
            | Instruction::Ldi(b)
            | Instruction::And(b)
            | Instruction::Ani(b)
            | Instruction::Or(b)
            | Instruction::Ori(b) => d.bit(b),
            _ => false,
        };
        match instruction {
            Instruction::Ld(_) | Instruction::Ldi(_) => {
                if state.open && !state.after_output {
                    self.stack.push(acc);
                } else {
                    self.stack.clear();
                }
                state.acc = read ^ matches!(instruction, Instruction::Ldi(_));
                state.open = true;
                state.after_output = false;
                self.trace_result(index, read, state.acc);
                return true;
            }
            Instruction::And(_) => (state.acc, output) = (acc && read, false),
            Instruction::Ani(_) => (state.acc, output) = (acc && !read, false),
            Instruction::Or(_) => (state.acc, output) = (acc || read, false),
            Instruction::Ori(_) => (state.acc, output) = (acc || !read, false),
            Instruction::Orb => {
                (state.acc, output) = (self.stack.pop().unwrap_or(false) || acc, false)
            }
            Instruction::Anb => {
                (state.acc, output) = (self.stack.pop().unwrap_or(false) && acc, false)
            }
            Instruction::Out(b) => d.set_bit(b, acc),
            Instruction::OutTimer(n, preset) => {
                let k = i64::from(d.word(preset));
                let t = &mut d.timers[usize::from(n)];
                if acc {
                    t.elapsed = if t.coil {
                        t.elapsed + state.elapsed
                    } else {
                        SimTime::ZERO
                    };
                    t.coil = true;
                    t.on = i64::from(t.current(n)) >= k;
                } else {
                    *t = Timer::default();
                }
            }
            Instruction::OutCounter(n, preset) => {
                let k = d.word(preset);
                let c = &mut d.counters[usize::from(n)];
                if acc && !self.edges[index] && c.count < k {
                    c.count += 1;
                }
                c.on = c.count >= k;
                self.edges[index] = acc;
            }
            Instruction::Pls(b) => {
                d.set_bit(b, acc && !self.edges[index]);
                self.edges[index] = acc;
            }
            Instruction::Plf(b) => {
                d.set_bit(b, !acc && self.edges[index]);
                self.edges[index] = acc;
            }
            Instruction::End => return false,
            other => self.act(other, acc),
        }
        if output {
            state.after_output = true;
        }
        self.trace_result(index, read, state.acc);
        true
    }

    /// Records instruction `index`'s step while tracing.
    // Inlined by force: the interpreter calls it per step, and the page is
    // built for size (opt-level z; docs/performance.md, "First visit").
    #[inline(always)]
    fn trace_result(&mut self, index: usize, read: bool, result: bool) {
        if self.tracer.on() {
            self.tracer
                .step(self.program.first_step(index), read, result);
        }
    }

    /// The instructions that act only while the rung is on.
    fn act(&mut self, instruction: Instruction, acc: bool) {
        if !acc {
            return;
        }
        let d = &mut self.devices;
        match instruction {
            Instruction::Set(b) => d.set_bit(b, true),
            Instruction::Rst(b) => d.set_bit(b, false),
            Instruction::Sets(b) => self.link_writes.push(LinkWrite { bit: b, on: true }),
            Instruction::Rsts(b) => self.link_writes.push(LinkWrite { bit: b, on: false }),
            Instruction::Cmp(a, b) => {
                let (a, b) = (d.word(a), d.word(b));
                d.set_bit(Bit::M(M_GT), a > b);
                d.set_bit(Bit::M(M_EQ), a == b);
                d.set_bit(Bit::M(M_LT), a < b);
            }
            Instruction::Mov(a, to) => d.d[usize::from(to)] = d.word(a),
            Instruction::Inc(r) => d.d[usize::from(r)] = d.d[usize::from(r)].wrapping_add(1),
            Instruction::Dec(r) => d.d[usize::from(r)] = d.d[usize::from(r)].wrapping_sub(1),
            _ => {}
        }
    }
}
