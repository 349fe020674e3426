//! Advancing MINASEC-U's simulated time: edge by edge on the exact path,
//! whole scans at once on the fast one where nothing time-dependent acts.

use super::*;

impl Machine {
    /// Advances simulated time by `dt`, running every clock edge due.
    pub fn tick(&mut self, dt: SimTime) {
        self.run_until(self.now.saturating_add(dt));
    }

    /// Runs every clock edge at or before `t`, then sets the time to `t`.
    /// While halted, reset or off, only time passes (the timers still run).
    pub fn run_until(&mut self, t: SimTime) {
        if t < self.now {
            return;
        }
        while self.running() && self.next_edge <= t {
            // Tracing needs each step: the exact path then.
            if self.fast_path
                && !self.tracer.on()
                && !self.clk_high
                && self.pc == 0
                && !self.write_held
            {
                if let Some(end) = self.fast_scan_fits(t) {
                    self.fast_scan(end);
                    continue;
                }
            }
            self.now = self.next_edge;
            if self.clk_high {
                self.fall();
                self.next_edge = self.now + self.low_time();
            } else {
                self.rise();
                self.next_edge = self.now + self.high_time();
            }
        }
        self.now = t;
    }

    /// Runs the next clock edge, if the CPU is clocked (RUN, powered).
    /// Returns whether an edge ran.
    pub fn step_clock(&mut self) -> bool {
        if !self.running() {
            return false;
        }
        self.run_until(self.next_edge);
        true
    }

    /// Runs one whole clock (the rising and the falling edge): one step.
    /// Returns the address of the step executed.
    pub fn step_instruction(&mut self) -> Option<u8> {
        let pc = self.pc;
        if !self.step_clock() {
            return None;
        }
        if self.clk_high {
            self.step_clock();
        }
        Some(pc)
    }

    /// When the scan under way ends (the falling edge that wraps the PC
    /// to 0), if the clock runs and no setting changes meanwhile.
    pub fn next_scan_end(&self) -> Option<SimTime> {
        if !self.running() {
            return None;
        }
        // Falling edges until the PC wraps: 256 from PC 0.
        let falls = STEPS as u64 - u64::from(self.pc);
        let period = self.speed.period().as_nanos();
        let first_fall = if self.clk_high {
            self.next_edge
        } else {
            self.next_edge + self.high_time()
        };
        let rest = (falls - 1).checked_mul(period)?;
        first_fall
            .as_nanos()
            .checked_add(rest)
            .map(SimTime::from_nanos)
    }

    /// One whole scan's length: 256 clocks.
    pub fn scan_period(&self) -> SimTime {
        SimTime::from_nanos(self.speed.period().as_nanos() * STEPS as u64)
    }

    /// Runs to the end of the scan (the next PC wrap).
    pub fn step_scan(&mut self) {
        let scans = self.scans;
        // 256 steps a scan; one more clock covers a half-clock start.
        for _ in 0..=STEPS {
            if self.scans != scans || self.step_instruction().is_none() {
                break;
            }
        }
    }

    /// Runs edges strictly before `t` (so that events at `t` come first).
    pub fn run_before(&mut self, t: SimTime) {
        if t > self.now {
            self.run_until(SimTime::from_nanos(t.as_nanos() - 1));
            self.now = t;
        }
    }

    /// If a whole scan from PC 0 ends by `t` and no timer output can change
    /// on its own inside it, the time of its last falling edge.
    fn fast_scan_fits(&self, t: SimTime) -> Option<SimTime> {
        let period = self.speed.period().as_nanos();
        let first_rise = self.next_edge;
        let last_rise = first_rise.as_nanos().checked_add(255 * period)?;
        let end = SimTime::from_nanos(last_rise.checked_add(self.high_time().as_nanos())?);
        if end > t {
            return None;
        }
        let last_rise = SimTime::from_nanos(last_rise);
        for timer in &self.timers {
            // A coil started during the scan must not expire within it.
            if timer.delay().as_nanos() <= 255 * period {
                return None;
            }
            if timer.output(first_rise) != timer.output(last_rise) {
                return None;
            }
        }
        Some(end)
    }

    /// One whole scan on the fast path, ending at `end`.
    fn fast_scan(&mut self, end: SimTime) {
        let first_rise = self.next_edge;
        let period = self.speed.period();
        let decoded = self
            .decoded
            .0
            .get_or_insert_with(|| FastCode::decode(&self.memory));
        self.now = first_rise;
        let bus = u32::from(self.input_image)
            | (self.latches & LATCH_BITS)
            | u32::from(self.timers[0].output(first_rise)) << 28
            | u32::from(self.timers[1].output(first_rise)) << 29
            | u32::from(self.counter.matched()) << 30;
        let mut devices = ScanDevices {
            timers: &mut self.timers,
            counter: &mut self.counter,
            first_rise,
            period,
        };
        let (acc, bus) = decoded.run_scan(bus, self.acc, &mut devices, self.gate_network);
        self.acc = acc;
        self.latches = bus & LATCH_BITS;
        self.clocks += STEPS as u64;
        self.now = end;
        self.next_edge = end + self.low_time();
        // The last falling edge wraps the PC: the scan boundary.
        self.pc = 0;
        self.last_edge = LastEdge {
            at: Some(end),
            wrapped: true,
        };
        self.scan_boundary();
    }
}
