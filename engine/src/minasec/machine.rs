//! MINASEC-U's state and how it steps: one instruction per clock, the PC
//! wrapping every 256 clocks, I/O exchanged at the wrap.
//!
//! Each clock has two edges. The rising edge executes the step at PC (the
//! accumulator is latched, a store's WE strobes low); the falling edge
//! advances the PC and, when it wraps, is the scan boundary: the output
//! terminals take the output latches and the input image takes the input
//! terminals. After the clock starts, the first rising edge comes half a
//! period later, so one scan is exactly 256 periods.

use super::asm::{Program, STEPS};
use super::control::{ClockSpeed, Command, Mode, SettingError, TimerId};
use super::counter::BcdCounter;
use super::fast::{FastCode, ScanDevices};
use super::isa::{logic_unit, Address, Device, Instruction};
use super::timer::RcTimer;
use crate::time::SimTime;

mod run;

/// Bits of the bus word that hold the Y and M latches (addresses 8..=27).
const LATCH_BITS: u32 = 0x0FFF_FF00;

/// The state a scan left behind, as the CLI's output rows report it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ScanSnapshot {
    /// When the scan ended (its last falling edge), or the reset instant.
    pub time: SimTime,
    /// Bit `a` = what address `a` read at the boundary; X bits are the input
    /// image just latched, Y bits the output terminals.
    pub bus: u32,
    /// The counter's count.
    pub count: u8,
    /// Each timer's current value (time its coil has been on, capped).
    pub timer_elapsed: [SimTime; 2],
}

impl ScanSnapshot {
    /// What reading `address` gave at the boundary.
    pub const fn bit(&self, address: Address) -> bool {
        self.bus >> address.index() & 1 != 0
    }
}

/// The last edge the clock took: when, and whether it was a fall that
/// wrapped the PC.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct LastEdge {
    pub(super) at: Option<SimTime>,
    pub(super) wrapped: bool,
}

/// One MINASEC-U board: CPU, memory, I/O, timers, counter and front panel.
#[derive(Clone, Debug)]
pub struct Machine {
    // Battery-backed: survive power-off.
    pub(super) memory: [u8; STEPS],
    pub(super) counter: BcdCounter,
    // The panel's physical controls.
    pub(super) powered: bool,
    pub(super) mode: Mode,
    pub(super) speed: ClockSpeed,
    pub(super) dip: u8,
    pub(super) write_held: bool,
    pub(super) clock_held: bool,
    pub(super) input_terminals: u8,
    /// Coil latches are volatile; the delays are the potentiometers.
    pub(super) timers: [RcTimer; 2],
    // Volatile CPU and I/O state.
    pub(super) pc: u8,
    pub(super) acc: bool,
    pub(super) clk_high: bool,
    /// Y latches (bits 8..=15) and M latches (16..=27), as on the bus.
    pub(super) latches: u32,
    pub(super) input_image: u8,
    pub(super) output_terminals: u8,
    // Simulated time.
    now: SimTime,
    /// The next clock edge while running.
    next_edge: SimTime,
    clocks: u64,
    scans: u64,
    /// What the last scan left; `None` until a scan completes after reset,
    /// when the reset state (with the panel as it is now) stands instead.
    last_scan: Option<ScanSnapshot>,
    reset_at: SimTime,
    // The fast path's decoded memory, rebuilt after any write.
    decoded: FastCache,
    fast_path: bool,
    gate_network: bool,
    /// Per-step tracing, when on (the exact path runs meanwhile).
    pub(crate) tracer: crate::plc::Tracer,
    /// The last clock edge (the CPU view's phase and scan signal).
    pub(super) last_edge: LastEdge,
    /// [`Machine::clocks`] at the last reset (the edges the strip has).
    pub(super) reset_clocks: u64,
}

impl Default for Machine {
    fn default() -> Self {
        Machine::new()
    }
}

impl Machine {
    /// A board with erased memory, powered on, switch at HALT, FAST clock,
    /// potentiometers at their minimum and the counter set to 00.
    pub fn new() -> Machine {
        let mut m = Machine {
            memory: [0; STEPS],
            counter: BcdCounter::default(),
            powered: true,
            mode: Mode::Halt,
            speed: ClockSpeed::Fast,
            dip: 0,
            write_held: false,
            clock_held: false,
            input_terminals: 0,
            timers: [
                RcTimer::new(TimerId::T0.range().0),
                RcTimer::new(TimerId::T1.range().0),
            ],
            pc: 0,
            acc: false,
            clk_high: false,
            latches: 0,
            input_image: 0,
            output_terminals: 0,
            now: SimTime::ZERO,
            next_edge: SimTime::ZERO,
            clocks: 0,
            scans: 0,
            last_scan: None,
            reset_at: SimTime::ZERO,
            decoded: FastCache(None),
            fast_path: true,
            tracer: crate::plc::Tracer::default(),
            gate_network: true,
            last_edge: LastEdge::default(),
            reset_clocks: 0,
        };
        m.clear_volatile();
        m
    }

    // ----- reading the state -------------------------------------------

    /// The simulated time.
    pub const fn now(&self) -> SimTime {
        self.now
    }
    /// Clocks executed since the machine was made.
    pub const fn clocks(&self) -> u64 {
        self.clocks
    }
    /// Scans completed since the machine was made.
    pub const fn scans(&self) -> u64 {
        self.scans
    }
    /// The program counter.
    pub const fn pc(&self) -> u8 {
        self.pc
    }
    /// The accumulator.
    pub const fn acc(&self) -> bool {
        self.acc
    }
    /// Whether the CPU clock is high (between a rising and a falling edge).
    pub const fn clock_high(&self) -> bool {
        self.clk_high
    }
    /// Whether the 5 V supply is on.
    pub const fn powered(&self) -> bool {
        self.powered
    }
    /// The RUN-HALT-RESET switch.
    pub const fn mode(&self) -> Mode {
        self.mode
    }
    /// The clock speed.
    pub const fn speed(&self) -> ClockSpeed {
        self.speed
    }
    /// The DIP switches.
    pub const fn dip(&self) -> u8 {
        self.dip
    }
    /// Program memory.
    pub const fn memory(&self) -> &[u8; STEPS] {
        &self.memory
    }
    /// The counter.
    pub const fn counter(&self) -> &BcdCounter {
        &self.counter
    }
    /// A timer.
    pub const fn timer(&self, id: TimerId) -> &RcTimer {
        &self.timers[id.index()]
    }
    /// The input terminals (switch positions), bit n = `X0n`.
    pub const fn input_terminals(&self) -> u8 {
        self.input_terminals
    }
    /// The input image the program reads this scan.
    pub const fn input_image(&self) -> u8 {
        self.input_image
    }
    /// The output terminals (lamps), bit n = `Y0n`.
    pub const fn output_terminals(&self) -> u8 {
        self.output_terminals
    }
    /// The state the last completed scan left, or before the first scan
    /// after reset, the reset state: latches clear, the counter as it is.
    pub fn last_scan(&self) -> ScanSnapshot {
        self.last_scan.unwrap_or(ScanSnapshot {
            time: self.reset_at,
            bus: u32::from(self.counter.matched()) << 30,
            count: self.counter.count(),
            timer_elapsed: [SimTime::ZERO; 2],
        })
    }
    /// The instruction on the instruction bus (the byte at PC).
    pub const fn instruction(&self) -> Instruction {
        Instruction::decode(self.memory[self.pc as usize])
    }

    /// What reading `address` gives now (the CPU's Din for it).
    pub fn read(&self, address: Address) -> bool {
        let a = address.index();
        match address.device() {
            Device::Input(n) => self.input_image >> n & 1 != 0,
            Device::Output(_) | Device::Relay(_) => self.latches >> a & 1 != 0,
            Device::Timer(n) => self.timers[usize::from(n)].output(self.now),
            Device::Counter => self.counter.matched(),
            Device::CounterClear => false,
        }
    }

    /// The bus word: bit `a` = [`Machine::read`] of address `a`.
    pub fn bus(&self) -> u32 {
        u32::from(self.input_image)
            | (self.latches & LATCH_BITS)
            | u32::from(self.timers[0].output(self.now)) << 28
            | u32::from(self.timers[1].output(self.now)) << 29
            | u32::from(self.counter.matched()) << 30
    }

    // ----- operating the board ------------------------------------------

    /// Loads a whole program into memory (the DIP + WRITE route gives the
    /// same memory). Steps the program does not define are erased.
    pub fn load(&mut self, program: &Program) {
        self.memory = *program.bytes();
        self.decoded = FastCache(None);
    }

    /// Turns the fast path off (every clock through the exact path) or on.
    /// Results are the same either way; tests and benchmarks compare them.
    pub fn set_fast_path(&mut self, enabled: bool) {
        self.fast_path = enabled;
    }

    /// Lets the fast path try the compiled gate network before the step
    /// kernel (the default), or keeps it to the step kernel. Results are the
    /// same either way; tests and benchmarks compare them.
    pub fn set_gate_network(&mut self, enabled: bool) {
        self.gate_network = enabled;
    }

    /// Operates one control. A rejected command changes nothing.
    pub fn apply(&mut self, command: Command) -> Result<(), SettingError> {
        match command {
            Command::Power(on) => self.set_power(on),
            Command::SetMode(mode) => self.set_mode(mode),
            Command::SetClock(speed) => self.set_speed(speed),
            Command::ClockButton(pressed) => self.clock_button(pressed),
            Command::SetInput(n, on) => {
                if n > 7 {
                    return Err(SettingError::NoSuchInput(n));
                }
                self.input_terminals = (self.input_terminals & !(1 << n)) | (u8::from(on) << n);
            }
            Command::SetDip(value) => {
                self.dip = value;
                self.write_through();
            }
            Command::WriteButton(pressed) => {
                self.write_held = pressed;
                self.write_through();
            }
            Command::CountClearButton(pressed) => self.counter.set_clear_button(pressed),
            Command::SetDelay(id, delay) => {
                let (lo, hi) = id.range();
                if delay < lo || delay > hi {
                    return Err(SettingError::DelayOutOfRange { timer: id, delay });
                }
                self.timers[id.index()].set_delay(delay);
            }
            Command::SetCounterPreset(tens, ones) => {
                if tens > 9 || ones > 9 {
                    return Err(SettingError::PresetOutOfRange(u32::from(tens.max(ones))));
                }
                self.counter.set_set_value(tens * 10 + ones);
            }
        }
        Ok(())
    }

    fn set_power(&mut self, on: bool) {
        if on == self.powered {
            return;
        }
        self.stop_clock();
        self.powered = on;
        // Power-off loses everything but memory and count; power-on resets.
        self.clear_volatile();
        self.start_clock();
    }

    fn set_mode(&mut self, mode: Mode) {
        if mode == self.mode {
            return;
        }
        self.stop_clock();
        self.mode = mode;
        if mode == Mode::Reset {
            self.clear_volatile();
        }
        self.start_clock();
    }

    fn set_speed(&mut self, speed: ClockSpeed) {
        self.speed = speed;
        // The oscillator restarts at the new rate from its low half.
        if self.clk_high {
            self.fall();
        }
        self.start_clock();
    }

    fn clock_button(&mut self, pressed: bool) {
        self.clock_held = pressed;
        // The CLOCK button drives the clock only while the oscillator is held
        // stopped (HALT); in RUN and RESET it has no visible effect.
        if !self.powered || self.mode != Mode::Halt {
            return;
        }
        if pressed && !self.clk_high {
            self.rise();
        } else if !pressed && self.clk_high {
            self.fall();
        }
    }

    /// While WRITE is held, the SRAM takes the DIP value at the PC.
    fn write_through(&mut self) {
        if self.write_held && self.powered {
            self.memory[usize::from(self.pc)] = self.dip;
            self.decoded = FastCache(None);
        }
    }

    /// What RESET and power-on clear: PC, accumulator, Y/M latches, timer
    /// coils, counter latches, input and output images. Not memory, count.
    fn clear_volatile(&mut self) {
        self.pc = 0;
        self.acc = false;
        self.clk_high = false;
        self.latches = 0;
        self.input_image = 0;
        self.output_terminals = 0;
        for timer in &mut self.timers {
            timer.set_coil(false, self.now);
        }
        self.counter.clear_latches();
        self.last_scan = None;
        self.reset_at = self.now;
        self.reset_clocks = self.clocks;
        self.last_edge = LastEdge::default();
    }

    /// Ends a clock that is high (the oscillator is being stopped).
    fn stop_clock(&mut self) {
        if self.clk_high {
            self.fall();
        }
    }

    /// Starts the oscillator if the board is powered and in RUN.
    fn start_clock(&mut self) {
        if self.powered && self.mode == Mode::Run {
            self.next_edge = self.now + self.low_time();
        }
    }

    fn running(&self) -> bool {
        self.powered && self.mode == Mode::Run
    }

    fn high_time(&self) -> SimTime {
        SimTime::from_nanos(self.speed.period().as_nanos() / 2)
    }

    fn low_time(&self) -> SimTime {
        self.speed.period() - self.high_time()
    }

    // ----- the exact path: one edge at a time ---------------------------

    /// The rising edge: execute the step at PC.
    fn rise(&mut self) {
        let Instruction { opcode, address } = self.instruction();
        let data_in = self.read(address);
        if opcode.is_store() {
            self.write(address, self.acc ^ opcode.inverts());
        }
        self.acc = logic_unit(opcode, data_in, self.acc);
        self.tracer.step(usize::from(self.pc), data_in, self.acc);
        self.clk_high = true;
        self.clocks += 1;
        self.last_edge = LastEdge {
            at: Some(self.now),
            wrapped: false,
        };
    }

    /// The falling edge: advance the PC; at the wrap, exchange I/O.
    fn fall(&mut self) {
        self.clk_high = false;
        self.pc = self.pc.wrapping_add(1);
        self.last_edge = LastEdge {
            at: Some(self.now),
            wrapped: self.pc == 0,
        };
        if self.pc == 0 {
            self.scan_boundary();
        }
        self.write_through();
    }

    fn write(&mut self, address: Address, value: bool) {
        let a = address.index();
        match address.device() {
            Device::Input(_) => {}
            Device::Output(_) | Device::Relay(_) => {
                self.latches = (self.latches & !(1 << a)) | (u32::from(value) << a);
            }
            Device::Timer(n) => self.timers[usize::from(n)].set_coil(value, self.now),
            Device::Counter => self.counter.set_up_latch(value),
            Device::CounterClear => self.counter.set_clear_latch(value),
        }
    }

    fn scan_boundary(&mut self) {
        self.output_terminals = (self.latches >> 8) as u8;
        self.input_image = self.input_terminals;
        self.scans += 1;
        self.last_scan = Some(self.snapshot());
        self.tracer.end_scan();
    }

    fn snapshot(&self) -> ScanSnapshot {
        ScanSnapshot {
            time: self.now,
            bus: (self.bus() & !0xFF00) | u32::from(self.output_terminals) << 8,
            count: self.counter.count(),
            timer_elapsed: [
                self.timers[0].elapsed(self.now),
                self.timers[1].elapsed(self.now),
            ],
        }
    }
}

/// The fast path's code: a cache, derived from program memory, that a
/// copy of the machine does not take along (it is rebuilt on first use).
/// Recording copies the machine every few hundred scans; the compiled
/// networks would make each copy cost more than the scans between.
#[derive(Debug, Default)]
struct FastCache(Option<FastCode>);

impl Clone for FastCache {
    fn clone(&self) -> Self {
        FastCache(None)
    }
}
