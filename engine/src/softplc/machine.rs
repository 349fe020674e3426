//! The soft PLC as a machine in time: its cyclic task runs one scan every
//! period (read inputs, solve, write outputs), RUN / STOP, the values the
//! last completed scan left, and scans stepped an instruction at a time.

use super::program::Program;
use super::scan::Cursor;
use crate::clock::PeriodicClock;
use crate::iec::data::Data;
use crate::plc::{SettingError, Tracer};
use crate::time::SimTime;

/// The cyclic task's period on a new machine.
pub const DEFAULT_SCAN: SimTime = SimTime::from_millis(10);

/// The longest period the task takes.
pub const MAX_SCAN: SimTime = SimTime::from_secs(10);

/// One soft PLC with its program.
#[derive(Clone, Debug)]
pub struct Machine {
    program: Program,
    clock: PeriodicClock,
    /// Every value as the last completed scan left it, kept while a scan
    /// is stepped an instruction at a time (between scans the program's
    /// own values are that; copying them after every scan would cost the
    /// scan a third of its speed).
    last: Vec<Data>,
    /// The scan under way when stepping one instruction at a time.
    cursor: Cursor,
    in_scan: bool,
    scans: u64,
    running: bool,
    /// Per-step tracing, when on.
    pub(crate) tracer: Tracer,
}

impl Machine {
    /// A powered-up machine running `program` every 10 ms.
    pub fn new(program: Program) -> Machine {
        Machine {
            last: Vec::new(),
            program,
            clock: PeriodicClock::new(DEFAULT_SCAN),
            cursor: Cursor::default(),
            in_scan: false,
            scans: 0,
            running: true,
            tracer: Tracer::default(),
        }
    }

    /// The program with its values as they are now.
    pub fn program(&self) -> &Program {
        &self.program
    }

    /// Every value as the last completed scan left it, by slot.
    pub fn last_scan(&self) -> &[Data] {
        if self.in_scan {
            &self.last
        } else {
            &self.program.values
        }
    }

    /// Replaces the program, as a download does: values and blocks start
    /// from their declarations (the terminals' inputs carried over by
    /// address); the period and RUN / STOP stay.
    pub fn load(&mut self, mut program: Program) {
        for (address, value) in self.program.input_values() {
            program.set_input(address, value);
        }
        // The terminal keeps what was sent before the download.
        let mut uart = std::mem::take(&mut self.program.uart);
        uart.power_cycle();
        program.uart = uart;
        self.program = program;
        self.start_over();
    }

    /// Power off and on: every value but the `VAR_RETAIN` ones back to
    /// its start, every block anew; the next scan one period from now.
    pub fn power_cycle(&mut self) {
        self.program.power_cycle();
        self.start_over();
    }

    fn start_over(&mut self) {
        self.in_scan = false;
        self.clock.restart();
    }

    /// The task's period.
    pub fn scan_period(&self) -> SimTime {
        self.clock.period()
    }

    /// Sets the task's period (above zero, at most 10 s); the next scan
    /// comes one new period from now. Nothing changes on error.
    pub fn set_scan_period(&mut self, period: SimTime) -> Result<(), SettingError> {
        let now = self.clock.now();
        self.clock.set_period(period, now, MAX_SCAN, "scan period")
    }

    /// The serial port (LDmicro's UART blocks).
    pub fn uart(&self) -> &crate::runtime::uart::Uart {
        &self.program.uart
    }

    /// The serial port, to type at it.
    pub fn uart_mut(&mut self) -> &mut crate::runtime::uart::Uart {
        &mut self.program.uart
    }

    /// The program's values, to drive inputs and write variables.
    pub fn program_mut(&mut self) -> &mut Program {
        &mut self.program
    }

    /// Writes `value` into slot `slot` now, and into what the last scan
    /// shows (a write from the monitor: the program may overwrite it).
    pub fn write(&mut self, slot: usize, value: Data) {
        if let Some(last) = self.last.get_mut(slot).filter(|_| self.in_scan) {
            *last = value.clone();
        }
        if let Some(now) = self.program.values.get_mut(slot) {
            *now = value;
        }
    }

    /// The simulated time.
    pub fn now(&self) -> SimTime {
        self.clock.now()
    }

    /// Scans completed.
    pub fn scans(&self) -> u64 {
        self.scans
    }

    /// Whether the task runs (RUN) or not (STOP).
    pub fn running(&self) -> bool {
        self.running
    }

    /// RUN (`true`) or STOP: stopped, no scan runs and every value holds;
    /// a scan being stepped is finished first. RUN starts the next scan
    /// one period from now.
    pub fn set_running(&mut self, on: bool) {
        if on == self.running {
            return;
        }
        self.finish_scan();
        self.running = on;
        self.clock.restart();
    }

    /// Runs every scan due at or before `t` (first finishing one that was
    /// being stepped); stopped, only the time moves.
    pub fn run_until(&mut self, t: SimTime) {
        self.finish_scan();
        if !self.running {
            self.clock.settle(t);
            self.clock.restart();
            return;
        }
        while let Some(at) = self.clock.fire_until(t) {
            self.scan(at);
        }
        self.clock.settle(t);
    }

    /// Runs every scan due strictly before `t`; the time becomes `t`.
    pub fn run_before(&mut self, t: SimTime) {
        self.run_until(PeriodicClock::just_before(t));
        self.clock.settle(t);
    }

    /// When the scan being stepped ends (now) or the next one runs;
    /// `None` while stopped.
    pub fn next_scan_end(&self) -> Option<SimTime> {
        match (self.running, self.in_scan) {
            (false, _) => None,
            (true, true) => Some(self.now()),
            (true, false) => Some(self.clock.next()),
        }
    }

    /// When the `n`-th scan from now ends (`n` ≥ 1); `None` while stopped.
    pub fn nth_scan_end(&self, n: u64) -> Option<SimTime> {
        match (n, self.running, self.in_scan) {
            (0, _, _) | (_, false, _) => None,
            (1, _, true) => Some(self.now()),
            (_, _, true) => self.clock.nth(n - 1),
            (_, _, false) => self.clock.nth(n),
        }
    }

    /// Runs to the end of the scan under way, or one whole next scan.
    pub fn step_scan(&mut self) {
        if self.in_scan {
            self.finish_scan();
        } else if self.running {
            let next = self.clock.next();
            self.clock.fire_until(next);
            self.scan(next);
        }
    }

    /// Runs one instruction: the first starts the next scan at its time,
    /// the last ends it. Its step number, or `None` while stopped.
    pub fn step_instruction(&mut self) -> Option<usize> {
        if !self.running {
            return None;
        }
        if !self.in_scan {
            let next = self.clock.next();
            self.clock.fire_until(next);
            self.last.clone_from(&self.program.values);
            self.program.begin_scan(&mut self.cursor);
            self.in_scan = true;
        }
        let step = self.cursor.position();
        let now = time_ns(self.now());
        if !self
            .program
            .execute(&mut self.cursor, now, &mut self.tracer)
        {
            self.end_scan();
        }
        (step < self.program.len()).then_some(step)
    }

    /// The next step of a scan being stepped, if one is.
    pub fn scan_position(&self) -> Option<usize> {
        self.in_scan.then(|| self.cursor.position())
    }

    fn scan(&mut self, at: SimTime) {
        let now = time_ns(at);
        self.program.begin_scan(&mut self.cursor);
        while self
            .program
            .execute(&mut self.cursor, now, &mut self.tracer)
        {}
        self.end_scan();
    }

    fn finish_scan(&mut self) {
        if self.in_scan {
            let now = time_ns(self.now());
            while self
                .program
                .execute(&mut self.cursor, now, &mut self.tracer)
            {}
            self.end_scan();
        }
    }

    fn end_scan(&mut self) {
        self.in_scan = false;
        self.scans += 1;
        self.tracer.end_scan();
    }
}

/// A time as the blocks count it: nanoseconds, signed (simulated time
/// never reaches 292 years).
fn time_ns(t: SimTime) -> i64 {
    i64::try_from(t.as_nanos()).unwrap_or(i64::MAX)
}
