//! PLC-IO86A's scan: inputs latched, the program run to END, outputs driven,
//! once every scan period (machines.md §2, FX semantics where decided).

use super::asm::Program;
use super::isa::{Bit, Instruction, Word};
use super::peripherals::{OutputSignal, Settings};
use super::scan::ScanState;
use crate::clock::PeriodicClock;
use crate::plc::SettingError;
use crate::time::SimTime;

/// The default scan period.
pub const DEFAULT_SCAN: SimTime = SimTime::from_millis(1);
/// 100 ms timers are T00-T23; T24-T31 count 10 ms.
pub const FIRST_10MS_TIMER: u8 = 24;
const CURRENT_MAX: u64 = 32767;

/// An on-delay timer (FX): while its coil stays on it adds up the elapsed
/// scan time; the contact is on when whole base units ≥ the set value.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Timer {
    /// The coil as the last scan left it.
    pub coil: bool,
    /// Time accumulated since the coil turned on.
    pub elapsed: SimTime,
    /// The contact.
    pub on: bool,
}

impl Timer {
    /// The timer's base unit.
    pub const fn base(n: u8) -> SimTime {
        if n < FIRST_10MS_TIMER {
            SimTime::from_millis(100)
        } else {
            SimTime::from_millis(10)
        }
    }

    /// The current value in base units, capped at 32767.
    pub fn current(&self, n: u8) -> i16 {
        // Most timers never run: no division for them.
        if self.elapsed == SimTime::ZERO {
            return 0;
        }
        (self.elapsed.as_nanos() / Timer::base(n).as_nanos()).min(CURRENT_MAX) as i16
    }
}

/// A counter (FX): counts OFF→ON of its OUT rung up to the set value.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Counter {
    /// The count, 0..=set value.
    pub count: i16,
    /// The contact: count ≥ set value.
    pub on: bool,
}

/// Every device's state: what contacts read and what a scan leaves.
/// `Copy`: the scan keeps a copy at every end, one block copy.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Devices {
    /// The input image (bit n = X0n).
    pub x: u8,
    /// Output latches (bit n = Y0n).
    pub y: u8,
    /// Relays M00-M63.
    pub m: u64,
    /// Relays S00-S07.
    pub s: u8,
    pub timers: [Timer; 32],
    pub counters: [Counter; 8],
    /// Data registers D00-D07.
    pub d: [i16; 8],
}

impl Devices {
    /// What a contact on `bit` reads.
    // Inlined by force: the interpreter calls it per step, and the page is
    // built for size (opt-level z; docs/performance.md, "First visit").
    #[inline(always)]
    pub fn bit(&self, bit: Bit) -> bool {
        match bit {
            Bit::X(n) => self.x >> n & 1 != 0,
            Bit::Y(n) => self.y >> n & 1 != 0,
            Bit::M(n) => self.m >> n & 1 != 0,
            Bit::S(n) => self.s >> n & 1 != 0,
            Bit::T(n) => self.timers[usize::from(n)].on,
            Bit::C(n) => self.counters[usize::from(n)].on,
        }
    }

    /// A word operand's value.
    pub fn word(&self, word: Word) -> i16 {
        match word {
            Word::K(k) => k,
            Word::D(n) => self.d[usize::from(n)],
            Word::T(n) => self.timers[usize::from(n)].current(n),
            Word::C(n) => self.counters[usize::from(n)].count,
        }
    }

    // Inlined by force: the interpreter calls it per step, and the page is
    // built for size (opt-level z; docs/performance.md, "First visit").
    #[inline(always)]
    pub(super) fn set_bit(&mut self, bit: Bit, on: bool) {
        fn put8(v: &mut u8, n: u8, on: bool) {
            *v = (*v & !(1 << n)) | (u8::from(on) << n);
        }
        match bit {
            Bit::X(_) | Bit::T(_) => {} // the assembler refuses these
            Bit::Y(n) => put8(&mut self.y, n, on),
            Bit::S(n) => put8(&mut self.s, n, on),
            Bit::M(n) => self.m = (self.m & !(1 << n)) | (u64::from(on) << n),
            Bit::C(n) => {
                let c = &mut self.counters[usize::from(n)];
                c.on = on;
                if !on {
                    c.count = 0;
                }
            }
        }
    }
}

/// A write that `SETS`/`RSTS` sends to the linked device.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LinkWrite {
    /// The linked device's Y or M.
    pub bit: Bit,
    /// ON for SETS, OFF for RSTS.
    pub on: bool,
}

/// One PLC-IO86A.
#[derive(Clone, Debug)]
pub struct Machine {
    pub(super) program: Program,
    pub(super) clock: PeriodicClock,
    pub(super) running: bool,
    pub(super) settings: Settings,
    /// The input pins as driven (bit n = X0n on).
    pub(super) input_terminals: u8,
    /// The inputs after the filter, and when each pin last changed.
    pub(super) filtered: u8,
    pub(super) changed_at: [SimTime; 8],
    /// Volts on X04 / X05, in millivolts.
    pub(super) analog_mv: [i64; 2],
    /// The IR frame being received (a button held), and the last one seen.
    pub(super) ir_frame: Option<u32>,
    pub(super) last_ir: Option<u32>,
    pub(super) devices: Devices,
    pub(super) output_terminals: u8,
    /// The previous rung state of each instruction (PLS, PLF, OUT C).
    pub(super) edges: Vec<bool>,
    pub(super) stack: Vec<bool>,
    pub(super) first_scan: bool,
    pub(super) last_scan_at: SimTime,
    pub(super) scans: u64,
    pub(super) last_scan: Devices,
    /// Per-step tracing, when on.
    pub(crate) tracer: crate::plc::Tracer,
    pub(super) link_writes: Vec<LinkWrite>,
    /// The scan under way when stepping one instruction at a time.
    pub(super) in_scan: Option<ScanState>,
}

/// The system relays.
pub(super) const M_OFF: u8 = 56;
pub(super) const M_ON: u8 = 57;
pub(super) const M_5HZ: u8 = 58;
pub(super) const M_1S: u8 = 59;
pub(super) const M_GT: u8 = 60;
pub(super) const M_EQ: u8 = 61;
pub(super) const M_LT: u8 = 62;
pub(super) const M_FIRST: u8 = 63;

impl Machine {
    /// A device with `program`, powered on and in RUN (as after power-up).
    pub fn new(program: Program) -> Machine {
        let edges = vec![false; program.instructions().len()];
        Machine {
            program,
            clock: PeriodicClock::new(DEFAULT_SCAN),
            running: true,
            settings: Settings::default(),
            input_terminals: 0,
            filtered: 0,
            changed_at: [SimTime::ZERO; 8],
            analog_mv: [0; 2],
            ir_frame: None,
            last_ir: None,
            devices: Devices::default(),
            output_terminals: 0,
            edges,
            stack: Vec::with_capacity(8),
            first_scan: true,
            last_scan_at: SimTime::ZERO,
            scans: 0,
            last_scan: Devices::default(),
            tracer: crate::plc::Tracer::default(),
            link_writes: Vec::new(),
            in_scan: None,
        }
    }

    /// The scan period.
    pub fn scan_period(&self) -> SimTime {
        self.clock.period()
    }

    /// Sets the scan period (must be above zero); the next scan comes one
    /// new period after the last.
    pub fn set_scan_period(&mut self, period: SimTime) -> Result<(), SettingError> {
        self.clock.set_period(
            period,
            self.last_scan_at,
            SimTime::from_secs(10),
            "scan period",
        )
    }

    /// The simulated time.
    pub fn now(&self) -> SimTime {
        self.clock.now()
    }

    /// Scans run since power-on.
    pub fn scans(&self) -> u64 {
        self.scans
    }

    /// The devices now.
    pub fn devices(&self) -> &Devices {
        &self.devices
    }

    /// The devices as the last completed scan left them.
    pub fn last_scan(&self) -> &Devices {
        &self.last_scan
    }

    /// The output terminals (bit n = Y0n).
    pub fn output_terminals(&self) -> u8 {
        self.output_terminals
    }

    /// Sets input terminal `X0n`.
    pub fn set_input(&mut self, n: u8, on: bool) {
        if n < 8 && (self.input_terminals >> n & 1 != 0) != on {
            self.input_terminals ^= 1 << n;
            self.changed_at[usize::from(n)] = self.clock.now();
        }
    }

    /// The input terminals (bit n = X0n driven on).
    pub fn input_terminals(&self) -> u8 {
        self.input_terminals
    }

    /// Sets the voltage on X04 (`index` 0) or X05 (1), in millivolts.
    pub fn set_analog(&mut self, index: usize, millivolts: i64) {
        if let Some(v) = self.analog_mv.get_mut(index) {
            *v = millivolts;
        }
    }

    /// The voltage on X04 / X05.
    pub fn analog(&self, index: usize) -> i64 {
        self.analog_mv.get(index).copied().unwrap_or(0)
    }

    /// An IR remote frame (NEC: custom code in the high 16 bits) arriving
    /// while a button is held; `None` when it is released.
    pub fn set_ir(&mut self, frame: Option<u32>) {
        self.ir_frame = frame;
        if frame.is_some() {
            self.last_ir = frame;
        }
    }

    /// The last IR frame received (the `.` command).
    pub fn last_ir(&self) -> Option<u32> {
        self.last_ir
    }

    /// The pin settings.
    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// The pin settings, to change them (the terminal's setting commands).
    pub fn settings_mut(&mut self) -> &mut Settings {
        &mut self.settings
    }

    /// What Y03 (`index` 0) or Y04 (1) puts out after the last scan.
    pub fn output_signal(&self, index: usize) -> OutputSignal {
        let on = self.output_terminals >> (3 + index) & 1 != 0;
        let command = self.last_scan.d[4 + index];
        self.settings.outputs[index.min(1)].signal(on, command)
    }

    /// Whether the program is running (the terminal's `R`; Ctrl-C stops).
    pub fn running(&self) -> bool {
        self.running
    }

    /// Runs (`R`) or stops (Ctrl-C) the program. Running again starts from
    /// the first scan (M63 pulses), with the devices as they are.
    pub fn set_running(&mut self, run: bool) {
        if !run {
            self.finish_scan();
        }
        if run && !self.running {
            self.first_scan = true;
            self.last_scan_at = self.clock.now();
            self.clock.restart();
        }
        self.running = run;
    }

    /// Power off and on: every device, timer, counter and edge cleared,
    /// the outputs off, the first-scan relay set again; the program, the
    /// pin settings and the driven inputs stay. The next scan comes one
    /// period from now.
    pub fn power_cycle(&mut self) {
        self.in_scan = None;
        self.devices = Devices::default();
        self.last_scan = Devices::default();
        self.output_terminals = 0;
        self.edges.iter_mut().for_each(|e| *e = false);
        self.stack.clear();
        self.link_writes.clear();
        self.first_scan = true;
        self.running = true;
        self.last_scan_at = self.clock.now();
        self.clock.restart();
    }

    /// Replaces the program (edited at the terminal); the edge memory of
    /// PLS/PLF/counters starts again.
    pub fn load(&mut self, program: Program) {
        // A scan being stepped ends with the program it started with.
        self.finish_scan();
        self.edges = vec![false; program.instructions().len()];
        self.program = program;
    }

    /// The program.
    pub fn program(&self) -> &Program {
        &self.program
    }

    /// Resets every Y (the terminal's `@`).
    pub fn reset_outputs(&mut self) {
        self.devices.y = 0;
        self.output_terminals = 0;
        self.last_scan.y = 0;
    }

    /// Takes the SETS/RSTS writes of the scans so far, oldest first.
    pub fn take_link_writes(&mut self) -> Vec<LinkWrite> {
        std::mem::take(&mut self.link_writes)
    }

    /// Writes a bit as a linked device's SETS/RSTS (or the terminal's
    /// `Ynn=1`) does: at once, between scans; a Y drives its pin at once.
    pub fn write_bit(&mut self, bit: Bit, on: bool) {
        self.devices.set_bit(bit, on);
        self.last_scan.set_bit(bit, on);
        if let Bit::Y(_) = bit {
            self.output_terminals = self.devices.y;
        }
    }

    /// Writes a D register (the terminal's `Dnn=`), between scans.
    pub fn write_word(&mut self, n: u8, value: i16) {
        if let Some(d) = self.devices.d.get_mut(usize::from(n)) {
            *d = value;
            self.last_scan.d[usize::from(n)] = value;
        }
    }

    /// Instructions one scan executes (up to and including the first END).
    pub fn steps_per_scan(&self) -> usize {
        let all = self.program.instructions();
        all.iter()
            .position(|i| *i == Instruction::End)
            .map_or(all.len(), |end| end + 1)
    }

    /// When the `n`-th scan from now runs (`n` ≥ 1); `None` while stopped.
    pub fn nth_scan_at(&self, n: u64) -> Option<SimTime> {
        self.running.then(|| self.clock.nth(n)).flatten()
    }

    /// When the next scan runs; `None` while stopped.
    pub fn next_scan_at(&self) -> Option<SimTime> {
        self.running.then_some(self.clock.next())
    }

    /// Runs every scan due at or before `t` (first finishing one that
    /// was being stepped).
    pub fn run_until(&mut self, t: SimTime) {
        self.finish_scan();
        while self.running && self.clock.fire_until(t).is_some() {
            self.scan();
        }
        self.clock.settle(t);
    }

    /// Runs every scan due strictly before `t`; the time becomes `t`.
    pub fn run_before(&mut self, t: SimTime) {
        self.run_until(PeriodicClock::just_before(t));
        self.clock.settle(t);
    }
}
