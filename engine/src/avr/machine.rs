//! The simplified PLC's scan: inputs driven into their register bits, the
//! records run from the first to `End_PLC` with one accumulator, once every
//! scan period.

use super::program::{BitRef, Instruction, Program};
use crate::clock::PeriodicClock;
use crate::plc::SettingError;
pub use crate::scan_timer::ScanTimer as TimerWord;
use crate::time::SimTime;

/// The value of the assembler's `Scan` symbol for a scan period: whole
/// milliseconds, 1 ms to 10 s. The source computes presets as integers
/// (`LOW(1000/Scan)`), so a period of 1.5 ms or 0.5 ms would silently give
/// timers of the wrong length (or a division by zero): it is refused.
pub fn scan_ms(period: SimTime) -> Result<u32, SettingError> {
    let nanos = period.as_nanos();
    if nanos == 0 || nanos > 10_000_000_000 || !nanos.is_multiple_of(1_000_000) {
        return Err(SettingError::AvrScan(period));
    }
    Ok((nanos / 1_000_000) as u32)
}

/// The default scan period.
pub const DEFAULT_SCAN: SimTime = SimTime::from_millis(10);

/// One AVR running the simplified PLC.
#[derive(Clone, Debug)]
pub struct Machine {
    program: Program,
    clock: PeriodicClock,
    registers: [u8; 32],
    timers: Vec<TimerWord>,
    /// Input bits and their levels, written into the registers each scan.
    driven: Vec<(BitRef, bool)>,
    scans: u64,
    last_scan: [u8; 32],
    /// The scan under way when stepping one record at a time: the next
    /// record and the running result.
    in_scan: Option<(usize, bool)>,
    /// Per-step tracing, when on.
    pub(crate) tracer: crate::plc::Tracer,
}

impl Machine {
    /// A powered-up AVR with `program` (RAM cleared: every timer word 0).
    pub fn new(program: Program) -> Machine {
        let timers = vec![TimerWord::default(); program.timer_count()];
        Machine {
            program,
            clock: PeriodicClock::new(DEFAULT_SCAN),
            registers: [0; 32],
            timers,
            driven: Vec::new(),
            scans: 0,
            last_scan: [0; 32],
            in_scan: None,
            tracer: crate::plc::Tracer::default(),
        }
    }

    /// Power off and on: registers and timer RAM cleared (so a TOF is on
    /// for its set time again); the program and the driven inputs stay.
    /// The next scan comes one period from now.
    pub fn power_cycle(&mut self) {
        self.in_scan = None;
        self.registers = [0; 32];
        self.last_scan = [0; 32];
        self.timers
            .iter_mut()
            .for_each(|t| *t = TimerWord::default());
        self.clock.restart();
    }

    /// Replaces the program, as flashing the AVR does: the device starts
    /// again from power-up; the scan period and the driven inputs stay.
    pub fn load(&mut self, program: Program) {
        self.timers = vec![TimerWord::default(); program.timer_count()];
        self.program = program;
        self.power_cycle();
    }

    /// The program.
    pub fn program(&self) -> &Program {
        &self.program
    }

    /// The scan period.
    pub fn scan_period(&self) -> SimTime {
        self.clock.period()
    }

    /// Sets the scan period (the program's presets count scans); it must
    /// pass [`scan_ms`]. Nothing changes on error.
    pub fn set_scan_period(&mut self, period: SimTime) -> Result<(), SettingError> {
        scan_ms(period)?;
        let now = self.clock.now();
        self.clock
            .set_period(period, now, SimTime::from_secs(10), "scan period")
    }

    /// Stops driving `bit`: from the next scan on, only the program writes it.
    pub fn release_input(&mut self, bit: BitRef) {
        self.driven.retain(|(b, _)| *b != bit);
    }

    /// Drives an input bit: from the next scan on, the bit reads `on`.
    pub fn set_input(&mut self, bit: BitRef, on: bool) {
        match self.driven.iter_mut().find(|(b, _)| *b == bit) {
            Some(entry) => entry.1 = on,
            None => self.driven.push((bit, on)),
        }
    }

    /// A bit as the last completed scan left it.
    pub fn bit(&self, bit: BitRef) -> bool {
        self.last_scan[usize::from(bit.register)] >> bit.bit & 1 != 0
    }

    /// The registers as the last completed scan left them.
    pub fn last_scan_registers(&self) -> &[u8; 32] {
        &self.last_scan
    }

    /// A timer's RAM word.
    pub fn timer(&self, index: usize) -> Option<&TimerWord> {
        self.timers.get(index)
    }

    /// The simulated time.
    pub fn now(&self) -> SimTime {
        self.clock.now()
    }

    /// Scans run.
    pub fn scans(&self) -> u64 {
        self.scans
    }

    /// Runs every scan due at or before `t` (first finishing one that was
    /// being stepped).
    pub fn run_until(&mut self, t: SimTime) {
        self.finish_scan();
        while self.clock.fire_until(t).is_some() {
            self.scan();
        }
        self.clock.settle(t);
    }

    /// Runs every scan due strictly before `t`; the time becomes `t`.
    pub fn run_before(&mut self, t: SimTime) {
        self.run_until(PeriodicClock::just_before(t));
        self.clock.settle(t);
    }

    // The interpreter's inner loop: inlined by force, since the page's
    // size-first build (opt-level z) would otherwise call each of these
    // per record and run the AVR PLC at half speed (docs/performance.md).
    #[inline(always)]
    fn read(&self, b: BitRef) -> bool {
        self.registers[usize::from(b.register)] >> b.bit & 1 != 0
    }

    #[inline(always)]
    fn write(&mut self, b: BitRef, on: bool) {
        let r = &mut self.registers[usize::from(b.register)];
        *r = (*r & !(1 << b.bit)) | (u8::from(on) << b.bit);
    }

    fn scan(&mut self) {
        let mut state = self.begin_scan();
        while self.execute(&mut state) {}
        self.end_scan();
    }

    /// Finishes a scan that was being stepped.
    fn finish_scan(&mut self) {
        if let Some(mut state) = self.in_scan.take() {
            while self.execute(&mut state) {}
            self.end_scan();
        }
    }

    /// Runs one record: the first starts the next scan at its time, the
    /// last ends it. Returns the index of the record run (`None` for an
    /// empty program, when a whole empty scan runs instead).
    pub fn step_instruction(&mut self) -> Option<usize> {
        let mut state = match self.in_scan.take() {
            Some(state) => state,
            None => {
                let next = self.clock.next();
                self.clock.fire_until(next);
                self.begin_scan()
            }
        };
        let index = state.0;
        if self.execute(&mut state) {
            self.in_scan = Some(state);
        } else {
            self.end_scan();
        }
        (index < self.program.instructions().len()).then_some(index)
    }

    /// When the scan being stepped ends (now) or the next one runs.
    pub fn next_scan_end(&self) -> SimTime {
        if self.in_scan.is_some() {
            self.now()
        } else {
            self.clock.next()
        }
    }

    /// When the `n`-th scan from now ends (`n` ≥ 1).
    pub fn nth_scan_end(&self, n: u64) -> Option<SimTime> {
        match (n, self.in_scan.is_some()) {
            (0, _) => None,
            (1, true) => Some(self.now()),
            (_, true) => self.clock.nth(n - 1),
            (_, false) => self.clock.nth(n),
        }
    }

    /// Runs to the end of the scan under way, or one whole next scan.
    pub fn step_scan(&mut self) {
        if self.in_scan.is_some() {
            self.finish_scan();
        } else {
            let next = self.clock.next();
            self.clock.fire_until(next);
            self.scan();
        }
    }

    /// The next record of a scan being stepped, if one is.
    pub fn scan_position(&self) -> Option<usize> {
        self.in_scan.map(|(pc, _)| pc)
    }

    /// Writes the driven input bits into their registers.
    fn begin_scan(&mut self) -> (usize, bool) {
        for i in 0..self.driven.len() {
            let (b, on) = self.driven[i];
            self.write(b, on);
        }
        (0, false)
    }

    fn end_scan(&mut self) {
        self.scans += 1;
        self.last_scan = self.registers;
        self.tracer.end_scan();
    }

    /// Runs the record at `pc` with the running result `acc`; false once
    /// the scan is over.
    #[inline(always)]
    fn execute(&mut self, (pc, acc): &mut (usize, bool)) -> bool {
        let Some(&instruction) = self.program.instructions().get(*pc) else {
            return false;
        };
        let step = *pc;
        *pc += 1;
        let mut read = false;
        match instruction {
            Instruction::Load(b, inv) => {
                read = self.read(b);
                *acc = read ^ inv;
            }
            Instruction::And(b, inv) => {
                read = self.read(b);
                *acc &= read ^ inv;
            }
            Instruction::Or(b, inv) => {
                read = self.read(b);
                *acc |= read ^ inv;
            }
            Instruction::Coil(b, inv) => self.write(b, *acc ^ inv),
            Instruction::Set(b) if *acc => self.write(b, true),
            Instruction::Reset(b) if *acc => self.write(b, false),
            Instruction::Set(_) | Instruction::Reset(_) => {}
            Instruction::Timer {
                kind,
                index,
                preset,
            } => {
                if let Some(t) = self.timers.get_mut(index) {
                    *acc = t.run(kind, *acc, preset);
                }
            }
            Instruction::Not => *acc = !*acc,
            Instruction::Pulse(memory, falling) => {
                let before = self.read(memory);
                self.write(memory, *acc);
                *acc = if falling {
                    !*acc && before
                } else {
                    *acc && !before
                };
            }
            Instruction::End => return false,
        }
        self.tracer.step(step, read, *acc);
        true
    }
}
